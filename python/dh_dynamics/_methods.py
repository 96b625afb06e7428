"""One method of the robot on NumPy arrays: its inputs checked and made contiguous
(``_inputs``), its results allocated, and one call of the C batch function over every state,
with the robot's parameters first where it has any.

A method takes each input as one state, shape ``(n,)``, or a batch, shape ``(N, n)`` (a 1-D
input beside batches is used for every state, as NumPy broadcasts; ``N`` may be 0), in
``float64``, or ``float32`` when every input is ``float32``. Its result has the shape of one
state's result with ``(N,)`` before it for a batch.
"""

from __future__ import annotations

import ctypes
from typing import Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from . import _inputs
from ._errors import NonFiniteInput, NotPositiveDefinite


# The results the Rust trait returns as structs (`dynamics-runtime/src/derivatives.rs`): the
# same fields, in the same order, as named tuples.
class InverseDynamicsDerivatives(NamedTuple):
    """``inverse_dynamics_derivatives``: ∂τ/∂q and ∂τ/∂q̇, row i the derivatives of τ_i."""

    dtau_dq: NDArray[np.floating[Any]]
    dtau_dqd: NDArray[np.floating[Any]]


class ForwardDynamicsDerivatives(NamedTuple):
    """``forward_dynamics_derivatives``: q̈, ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = M⁻¹."""

    qdd: NDArray[np.floating[Any]]
    dqdd_dq: NDArray[np.floating[Any]]
    dqdd_dqd: NDArray[np.floating[Any]]
    dqdd_dtau: NDArray[np.floating[Any]]


_STRUCTS = {
    "inverse_dynamics_derivatives": InverseDynamicsDerivatives,
    "forward_dynamics_derivatives": ForwardDynamicsDerivatives,
}

_DTYPES = {"float64": np.float64, "float32": np.float32}


class Method:
    """A method of the robot: ``robot.inverse_dynamics(q, qd, qdd)``."""

    def __init__(self, robot, library, signatures, parameters):
        first = signatures[0]
        self._robot = robot
        self._parameters = parameters
        self.__name__ = first["method"]
        self._where = f"{robot.name}.{self.__name__}"
        self._arguments = first["arguments"]
        self._signature = f"{self.__name__}({', '.join(name for name, _ in self._arguments)})"
        self.__doc__ = (
            f"{self._signature}: {first['summary']}\n\n"
            "Each input one state, shape (n,), or a batch, shape (N, n); float64, or float32 "
            "when every input is float32."
        )
        self._by_dtype = {}
        for signature in signatures:
            # The C functions take the parameters first: one array, the same for every state.
            if signature["parameters"] != len(parameters):
                raise RuntimeError(f"{self._where}: the header's function takes "
                                   f"{signature['parameters']} parameters, the robot has "
                                   f"{len(parameters)}")
            function = getattr(library, signature["name"] + "_batch")
            arrays = len(signature["arguments"]) + len(signature["outputs"])
            arrays += (signature["returns"] != "nothing") + (signature["parameters"] > 0)
            function.argtypes = [ctypes.c_size_t] + [ctypes.c_void_p] * arrays
            function.restype = ctypes.c_size_t if signature["returns"] == "status" else None
            self._by_dtype[np.dtype(_DTYPES[signature["dtype"]])] = (function, signature)

    def __repr__(self):
        return f"<method {self._where}>"

    def __call__(self, *inputs, **named):
        inputs = self._ordered(inputs, named)
        given, dtype = _inputs.arrays(self._where, self._arguments, inputs)
        count, batch = _inputs.batch(self._where, self._arguments, given)
        function, signature = self._by_dtype[dtype]
        pointers = []
        if signature["parameters"]:
            params = self._parameters.arrays(self.__name__)[dtype.type]
            if params is None:
                raise ValueError(f"{self._where}: a parameter is beyond float32's range "
                                 f"({self._parameters!r}); call it with float64 arrays")
            pointers.append(params.ctypes.data)
        arrays = _inputs.contiguous(given, count)
        outputs = [np.empty((count, *dims), dtype) for _, dims in signature["outputs"]]
        extra = None
        if signature["returns"] == "value":
            extra = np.empty(count, dtype)
        elif signature["returns"] == "status":
            extra = np.zeros(count, np.intc)
        pointers += [a.ctypes.data for a in arrays + outputs]
        if extra is not None:
            pointers.append(extra.ctypes.data)
        # No call for an empty batch: there is nothing to read or write.
        failures = function(count, *pointers) if count else 0
        result = self._result(outputs, extra, signature, batch)
        states, problems = _inputs.not_finite(self._arguments, given, count)
        singular = np.flatnonzero(extra).tolist() if failures else []
        if problems:
            singular = sorted(set(singular) - set(states))
            raise NonFiniteInput(self._where, problems, states, count if batch else None,
                                 result, singular)
        if failures:
            raise NotPositiveDefinite(self._where, singular, count, result)
        return result

    def _ordered(self, inputs, named):
        """The inputs in the arguments' order, from positions and names."""
        if not named and len(inputs) == len(self._arguments):
            return inputs
        names = [name for name, _ in self._arguments]
        unknown = [name for name in named if name not in names]
        twice = [name for name in names[:len(inputs)] if name in named]
        missing = [name for name in names[len(inputs):] if name not in named]
        if len(inputs) > len(names) or unknown or twice or missing:
            given = len(inputs) + len(named)
            problems = [f"{len(names)} arrays, {given} given"]
            problems += [f"no argument `{name}`" for name in unknown]
            problems += [f"`{name}` given twice" for name in twice]
            problems += [f"`{name}` missing" for name in missing]
            raise TypeError(f"{self._robot.name}.{self._signature} takes "
                            f"{'; '.join(problems)}")
        return list(inputs) + [named[name] for name in names[len(inputs):]]

    def _result(self, outputs, extra, signature, batch):
        """The outputs as the method returns them: one array (or a named tuple of the Rust
        struct's fields), without the batch's axis for one state."""
        if signature["returns"] == "value":
            return extra if batch else extra[0].item()
        parts = []
        struct = _STRUCTS.get(self.__name__)
        for (_, dims), out in zip(signature["outputs"], outputs):
            # A struct's blocks are stacked on the axis after the batch's.
            if struct is not None and len(dims) == 3:
                parts.extend(out[:, k] for k in range(dims[0]))
            else:
                parts.append(out)
        if not batch:
            parts = [p[0] for p in parts]
        if struct is not None:
            return struct(*parts)
        return parts[0] if len(parts) == 1 else tuple(parts)

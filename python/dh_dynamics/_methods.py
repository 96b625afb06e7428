"""One method of the robot on NumPy arrays: its inputs checked and made contiguous, its
results allocated, and one call of the C batch function over every state.

A method takes each input as one state, shape ``(n,)``, or a batch, shape ``(N, n)`` (a 1-D
input beside batches is used for every state, as NumPy broadcasts), in ``float64``, or
``float32`` when every input is ``float32``. Its result has the shape of one state's result with
``(N,)`` before it for a batch.
"""

import ctypes
from collections import namedtuple

import numpy as np

from ._errors import NotPositiveDefinite

# The results the Rust trait returns as structs (`dynamics-runtime/src/derivatives.rs`): the
# same fields, in the same order, as named tuples.
_STRUCTS = {
    "inverse_dynamics_derivatives": namedtuple(
        "InverseDynamicsDerivatives", ["dtau_dq", "dtau_dqd"]
    ),
    "forward_dynamics_derivatives": namedtuple(
        "ForwardDynamicsDerivatives", ["qdd", "dqdd_dq", "dqdd_dqd", "dqdd_dtau"]
    ),
}

_DTYPES = {"float64": np.float64, "float32": np.float32}


class Method:
    """A method of the robot: ``robot.inverse_dynamics(q, qd, qdd)``."""

    def __init__(self, robot, library, signatures):
        first = signatures[0]
        self._robot = robot
        self.__name__ = first["method"]
        self._arguments = first["arguments"]
        names = ", ".join(name for name, _ in self._arguments)
        self.__doc__ = (
            f"{self.__name__}({names}): {first['summary']}\n\n"
            "Each input one state, shape (n,), or a batch, shape (N, n); float64, or float32 "
            "when every input is float32."
        )
        self._by_dtype = {}
        for signature in signatures:
            # Only a derive's struct fields are parameters; a description file has none.
            assert signature["parameters"] == 0, "a description file's robot has no parameters"
            function = getattr(library, signature["name"] + "_batch")
            arrays = 1 + len(signature["arguments"]) + len(signature["outputs"])
            arrays += signature["returns"] != "nothing"
            function.argtypes = [ctypes.c_size_t] + [ctypes.c_void_p] * (arrays - 1)
            function.restype = ctypes.c_size_t if signature["returns"] == "status" else None
            self._by_dtype[_DTYPES[signature["dtype"]]] = (function, signature)

    def __repr__(self):
        return f"<method {self._robot.name}.{self.__name__}>"

    def __call__(self, *inputs):
        if len(inputs) != len(self._arguments):
            names = ", ".join(name for name, _ in self._arguments)
            raise TypeError(f"{self.__name__}({names}) takes {len(self._arguments)} arrays, "
                            f"{len(inputs)} given")
        float32 = all(getattr(x, "dtype", None) == np.float32 for x in inputs)
        dtype = np.float32 if inputs and float32 else np.float64
        function, signature = self._by_dtype[dtype]
        arrays, count, batch = self._inputs(inputs, dtype)
        outputs = [np.empty((count, *dims), dtype) for _, dims in signature["outputs"]]
        pointers = [a.ctypes.data for a in arrays + outputs]
        extra = None
        if signature["returns"] == "value":
            extra = np.empty(count, dtype)
        elif signature["returns"] == "status":
            extra = np.empty(count, np.intc)
        if extra is not None:
            pointers.append(extra.ctypes.data)
        failures = function(count, *pointers)
        result = self._result(outputs, extra, signature, batch)
        if failures:
            states = np.flatnonzero(extra).tolist()
            raise NotPositiveDefinite(self.__name__, states, count, result)
        return result

    def _inputs(self, inputs, dtype):
        """The inputs as contiguous ``(N, len)`` arrays of ``dtype``, ``N``, and whether any
        was a batch."""
        arrays = []
        for (name, length), x in zip(self._arguments, inputs):
            a = np.asarray(x, dtype=dtype)
            if a.ndim not in (1, 2) or a.shape[-1] != length:
                raise ValueError(f"{self.__name__}: `{name}` has shape {a.shape}; expected "
                                 f"({length},) for one state or (N, {length}) for N states")
            arrays.append(a)
        counts = {a.shape[0] for a in arrays if a.ndim == 2}
        if len(counts) > 1:
            shapes = ", ".join(f"{name} {a.shape}" for (name, _), a in zip(self._arguments, arrays))
            raise ValueError(f"{self.__name__}: batches of different lengths: {shapes}")
        batch = bool(counts)
        count = counts.pop() if counts else 1
        arrays = [
            np.ascontiguousarray(a if a.ndim == 2 or count == 1 else np.broadcast_to(a, (count, a.shape[-1])))
            for a in arrays
        ]
        return arrays, count, batch

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

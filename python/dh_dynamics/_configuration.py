"""A floating base's configuration space on NumPy arrays: Pinocchio's ``integrate(q, v)`` and
``difference(q0, q1)``, the Rust runtime's (``dynamics-runtime/src/configuration.rs``, through
``_native``), state by state over a batch, in ``float64``.

Inputs as a method's (``_inputs``): one state, shape ``(n,)``, or a batch ``(N, n)``, a 1-D
input used for every state of a batch.
"""

import numpy as np

from . import _inputs


class ConfigurationMethod:
    """``robot.integrate(q, v)`` or ``robot.difference(q0, q1)`` of a floating base."""

    def __init__(self, robot, name, arguments, result, function, summary):
        self._where = f"{robot.name}.{name}"
        self.__name__ = name
        self._arguments = arguments
        self._result = result
        self._function = function
        self._nv = robot.dof
        self.__doc__ = (f"{name}({', '.join(n for n, _ in arguments)}): {summary}\n\n"
                        "Each input one state, shape (n,), or a batch, shape (N, n); float64.")

    def __repr__(self):
        return f"<method {self._where}>"

    def __call__(self, first, second):
        given, _ = _inputs.arrays(self._where, self._arguments, [first, second])
        count, batch = _inputs.batch(self._where, self._arguments, given)
        arrays = _inputs.contiguous([a.astype(np.float64, copy=False) for a in given], count)
        states, problems = _inputs.not_finite(self._arguments, arrays, count)
        if problems:
            where = "; ".join(f"`{name}` at states {s}: {at}" for name, s, at in problems)
            raise ValueError(f"{self._where}: not finite: {where}")
        raw = self._function(*(np.ascontiguousarray(a).tobytes() for a in arrays), count,
                             self._nv)
        out = np.frombuffer(raw, np.float64).reshape(count, self._result).copy()
        return out if batch else out[0]


def methods(robot, native):
    """The configuration space's methods of the floating-base robot ``robot``, computed by
    ``native`` (the extension ``_native``, which ``robot.py`` imports: mypy reads it through
    ``robot.pyi``)."""
    nq, nv = robot.dof + 1, robot.dof
    return {
        "integrate": ConfigurationMethod(
            robot, "integrate", [("q", nq), ("v", nv)], nq, native.integrate,
            "Pinocchio's integrate: the configuration reached from q by the velocity v held "
            "for unit time (the base moved by SE(3)'s exponential of its twist)."),
        "difference": ConfigurationMethod(
            robot, "difference", [("q0", nq), ("q1", nq)], nv, native.difference,
            "Pinocchio's difference: the velocity v with integrate(q0, v) = q1 (the base's "
            "the logarithm of M0^-1 M1)."),
    }

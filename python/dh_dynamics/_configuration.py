"""A floating base's configuration space on NumPy arrays: Pinocchio's ``integrate(q, v)`` and
``difference(q0, q1)`` and their Jacobians (``dIntegrate``, ``dDifference``), the Rust
runtime's (``dynamics-runtime/src/configuration.rs``, through ``_native``), state by state over
a batch, in ``float64``.

Inputs as a method's (``_inputs``): one state, shape ``(n,)``, or a batch ``(N, n)``, a 1-D
input used for every state of a batch.
"""

import numpy as np

from . import _inputs


class ConfigurationMethod:
    """``robot.integrate(q, v)``, ``robot.difference(q0, q1)`` or a Jacobian of theirs, of a
    floating base."""

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
        shape = self._result if isinstance(self._result, tuple) else (self._result,)
        out = np.frombuffer(raw, np.float64).reshape((count,) + shape).copy()
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
        "integrate_jacobian_v": ConfigurationMethod(
            robot, "integrate_jacobian_v", [("q", nq), ("v", nv)], (nv, nv),
            native.integrate_jacobian_v,
            "Pinocchio's dIntegrate(q, v, ARG1): d integrate(q, v) / dv, (nv, nv)."),
        "integrate_jacobian_q": ConfigurationMethod(
            robot, "integrate_jacobian_q", [("q", nq), ("v", nv)], (nv, nv),
            native.integrate_jacobian_q,
            "Pinocchio's dIntegrate(q, v, ARG0): d integrate(q, v) / dq, (nv, nv)."),
        "difference_jacobian_q0": ConfigurationMethod(
            robot, "difference_jacobian_q0", [("q0", nq), ("q1", nq)], (nv, nv),
            native.difference_jacobian_q0,
            "Pinocchio's dDifference(q0, q1, ARG0): d difference(q0, q1) / dq0, (nv, nv)."),
        "difference_jacobian_q1": ConfigurationMethod(
            robot, "difference_jacobian_q1", [("q0", nq), ("q1", nq)], (nv, nv),
            native.difference_jacobian_q1,
            "Pinocchio's dDifference(q0, q1, ARG1): d difference(q0, q1) / dq1, (nv, nv)."),
    }

"""A floating base's kinematics and contacts on NumPy arrays: the C header's functions beyond
the method table's (``dynamics emit --lang c --floating --kinematics --contacts``), called state
through ctypes in ``float64`` (their batch twins: one foreign call a batch), the frames by name
(``robot.frames``), the robot's parameters first where it has any (``robot.parameters``).

A frame's results are a dict by frame name; a wrench ``[f, m]`` or force ``f`` is what the
environment exerts on the robot at the frame's origin, in world axes (Pinocchio's
LOCAL_WORLD_ALIGNED). Inputs as a method's (``_inputs``): one state, shape ``(n,)``, or a batch
``(N, n)``, a 1-D input used for every state of a batch.
"""

import ctypes

import numpy as np

from . import _inputs
from ._errors import NotPositiveDefinite

_DOUBLE = ctypes.POINTER(ctypes.c_double)


def _pointer(a):
    return a.ctypes.data_as(_DOUBLE)


class FloatingMethod:
    """One of the kinematics' or contacts' functions of a floating base."""

    def __init__(self, robot, library, prefix, spec):
        name, arguments, result, summary = spec
        self._robot = robot
        self._where = f"{robot.name}.{name}"
        self.__name__ = name
        self._arguments = arguments
        self._result = result
        self._frames = robot.frames
        self._function = getattr(library, f"{prefix}_{name}_batch")
        self._status = name in _STATUS
        self._parameters = robot.parameters
        self._function.restype = ctypes.c_size_t if self._status else None
        self.__doc__ = (f"{name}({', '.join(n for n, _ in arguments)}): {summary}\n\n"
                        "Each input one state, shape (n,), or a batch, shape (N, n); float64.")

    def __repr__(self):
        return f"<method {self._where}>"

    def _states(self, inputs):
        given, _ = _inputs.arrays(self._where, self._arguments, inputs)
        count, batch = _inputs.batch(self._where, self._arguments, given)
        arrays = _inputs.contiguous([a.astype(np.float64, copy=False) for a in given], count)
        _, problems = _inputs.not_finite(self._arguments, arrays, count)
        if problems:
            where = "; ".join(f"`{name}` at states {s}: {at}" for name, s, at in problems)
            raise ValueError(f"{self._where}: not finite: {where}")
        return arrays, count, batch

    def _call(self, arrays, count, extra=(), outputs=None):
        """The batch function over the ``count`` states of ``arrays``, ``extra`` its arguments
        after them: its outputs (each ``(count, ...)``) and the states whose status is not 0."""
        outputs = [np.zeros((count, *self._result))] if outputs is None else outputs
        # A robot with parameters (`mass = "m1"`): their values first, as the table's methods.
        params = []
        if len(self._parameters):
            params = [_pointer(self._parameters.arrays(self.__name__)[np.float64])]
        arguments = [ctypes.c_size_t(count), *params, *(_pointer(a) for a in arrays), *extra,
                     *(_pointer(o) for o in outputs)]
        status = np.zeros(count, np.intc)
        if self._status:
            arguments.append(status.ctypes.data_as(ctypes.POINTER(ctypes.c_int)))
        self._function(*arguments)
        return outputs, status

    def _by_frame(self, out, batch):
        return {name: (out[:, f] if batch else out[0, f]).copy()
                for f, name in enumerate(self._frames)}

    def __call__(self, *inputs):
        arrays, count, batch = self._states(inputs)
        (out,), _ = self._call(arrays, count)
        if self.__name__.startswith("frame_"):
            return self._by_frame(out, batch)
        return out if batch else out[0]


class WrenchMethod(FloatingMethod):
    """``inverse_dynamics_with_wrenches(q, v, a, wrenches)`` and
    ``forward_dynamics_with_wrenches(q, v, tau, wrenches)``: ``wrenches`` a dict by frame name
    of ``[f, m]`` (6) or, with ``forces``, ``f`` (3), the frames left out exerting none."""

    def __call__(self, first, second, third, wrenches):
        arrays, count, batch = self._states([first, second, third])
        frames = len(self._frames)
        packed = np.zeros((count, frames, 6))
        for name, w in dict(wrenches).items():
            if name not in self._frames:
                raise ValueError(f"{self._where}: no frame {name!r}; the frames are "
                                 f"{', '.join(self._frames)}")
            w = np.asarray(w, np.float64)
            if w.shape[-1] not in (3, 6) or w.ndim > 2:
                raise ValueError(f"{self._where}: the wrench at {name!r} has shape {w.shape}; "
                                 "expected (6,) [f, m] or (3,) f, or (N, 6), (N, 3)")
            packed[:, self._frames.index(name), :w.shape[-1]] = w
        if not np.isfinite(packed).all():
            raise ValueError(f"{self._where}: a wrench is not finite")
        (out,), status = self._call(arrays, count, [_pointer(packed)])
        if status.any():
            raise NotPositiveDefinite(self._where, np.flatnonzero(status).tolist(), count,
                                      out if batch else out[0])
        return out if batch else out[0]


class ContactDynamics(FloatingMethod):
    """``contact_dynamics(q, v, tau, in_contact)``: the forward dynamics with the origins of the
    frames named in ``in_contact`` held; ``(qdd, forces)``, ``forces`` a dict by frame name of
    the force on the robot in world axes (zero where not held)."""

    def __call__(self, q, v, tau, in_contact):
        arrays, count, batch = self._states([q, v, tau])
        # One frame's name alone is that frame, not its letters.
        held = [in_contact] if isinstance(in_contact, str) else list(in_contact)
        for name in held:
            if name not in self._frames:
                raise ValueError(f"{self._where}: no frame {name!r}; the frames are "
                                 f"{', '.join(self._frames)}")
        mask = np.array([[int(f in held) for f in self._frames]] * count, np.intc)
        out = np.zeros((count, *self._result))
        forces = np.zeros((count, len(self._frames), 3))
        _, status = self._call(arrays, count, [mask.ctypes.data_as(ctypes.POINTER(ctypes.c_int))],
                               [out, forces])
        if (status == 1).any():
            raise NotPositiveDefinite(self._where, np.flatnonzero(status == 1).tolist(), count,
                                      out if batch else out[0])
        if status.any():
            raise ValueError(f"{self._where}: the contacts {held} are not independent at "
                             f"states {np.flatnonzero(status).tolist()}")
        qdd = out if batch else out[0]
        return qdd, self._by_frame(forces, batch)


# The functions that return a status (0, or 1 where M is not positive definite; 2 where the
# contacts are not independent).
_STATUS = {"forward_dynamics_with_wrenches", "contact_dynamics"}


def methods(robot, library, prefix):
    """The kinematics' and contacts' methods of the floating-base robot ``robot`` whose compiled
    header is ``library``, its functions ``{prefix}_*``."""
    nq, nv, frames = robot.dof + 1, robot.dof, len(robot.frames)
    q, v = ("q", nq), ("v", nv)
    kinematic = [
        ("center_of_mass", [q], (3,), "the centre of mass in the world (centerOfMass)"),
        ("center_of_mass_jacobian", [q], (3, nv), "its Jacobian (jacobianCenterOfMass)"),
        ("centroidal_momentum_matrix", [q], (6, nv),
         "A_G, linear rows first, about the centre of mass in world axes (computeCentroidalMap)"),
        ("centroidal_momentum_bias", [q, v], (6,), "dA_G/dt v"),
        ("frame_poses", [q], (frames, 3, 4), "each frame's pose [R | p] in the world (oMf)"),
        ("frame_jacobians_world_aligned", [q], (frames, 6, nv),
         "each frame's Jacobian in LOCAL_WORLD_ALIGNED"),
        ("frame_jacobians_local", [q], (frames, 6, nv), "each frame's Jacobian in LOCAL"),
        ("frame_acceleration_biases_world_aligned", [q, v], (frames, 6),
         "each frame origin's classical acceleration at a = 0, world axes"),
        ("frame_acceleration_biases_local", [q, v], (frames, 6), "the same in the frame's axes"),
    ]
    out = {spec[0]: FloatingMethod(robot, library, prefix, spec) for spec in kinematic}
    if not hasattr(library, f"{prefix}_contact_dynamics_batch"):
        return out
    out["inverse_dynamics_with_wrenches"] = WrenchMethod(robot, library, prefix, (
        "inverse_dynamics_with_wrenches", [q, v, ("a", nv)], (nv,),
        "tau = M a + h - sum_f J_f^T w_f (rnea with fext)"))
    out["forward_dynamics_with_wrenches"] = WrenchMethod(robot, library, prefix, (
        "forward_dynamics_with_wrenches", [q, v, ("tau", nv)], (nv,),
        "a = M^-1 (tau - h + sum_f J_f^T w_f) (aba with fext)"))
    out["contact_dynamics"] = ContactDynamics(robot, library, prefix, (
        "contact_dynamics", [q, v, ("tau", nv)], (nv,),
        "the forward dynamics with the named frames' origins held (constraintDynamics, "
        "CONTACT_3D in LOCAL_WORLD_ALIGNED)"))
    return out

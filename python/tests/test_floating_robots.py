"""ANYmal B and the Unitree G1 on a free-flying base (``floating=True``), beyond Solo 12
(``test_floating.py``): the dynamics, the kinematics by frame name, the configuration space and
(``contacts=True``, ANYmal B) the contacts against Pinocchio's bindings, their URDFs read by
Pinocchio's loader with its free flyer.

Pinocchio's parser takes a link's child joints in the order of their names, the package in the
file's: ANYmal B's legs, LF, RF, LH, RH in its file and in the package's ``q``, are LF, LH, RF,
RH in Pinocchio's. The states are drawn in the package's order and taken to Pinocchio's for its
calls, its results back (``Order``), as ``tests/data/floating/make.py`` does. The G1's joints are
in the same order in both."""

import importlib.util

import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

import dh_dynamics  # noqa: E402
from conftest import DATA, ROOT, scaled_error  # noqa: E402

URDF = ROOT / "robots" / "urdf" / "floating"
TOLERANCE = 1e-12
FRAMES = {
    "anymal_b": ("LF_FOOT", "RF_FOOT", "LH_FOOT", "RH_FOOT"),
    "g1_29dof": ("left_ankle_roll_link", "right_ankle_roll_link", "logo_link", "head_link",
                 "imu_in_torso", "d435_link", "mid360_link", "left_rubber_hand",
                 "right_rubber_hand"),
}


def make_script():
    """`tests/data/floating/make.py` (imported by path: it is a script), for `file_order`."""
    spec = importlib.util.spec_from_file_location("floating_make", DATA / "floating" / "make.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


class Order:
    """Pinocchio's model of a URDF and the permutation between its joint order and the file's
    (the package's)."""

    def __init__(self, name):
        path = str(URDF / f"{name}.urdf")
        self.model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
        self.data = self.model.createData()
        _, order = make_script().file_order(path)
        names = list(self.model.names)[2:]
        pick = [names.index(j) for j in order]
        # Entry k of the file's vector is entry iq[k] (iv[k]) of Pinocchio's.
        self.iq = np.array(list(range(7)) + [7 + k for k in pick])
        self.iv = np.array(list(range(6)) + [6 + k for k in pick])

    def q(self, q_file):
        out = np.empty(len(self.iq))
        out[self.iq] = q_file
        return out

    def v(self, v_file):
        out = np.empty(len(self.iv))
        out[self.iv] = v_file
        return out

    def back(self, x, rows=True, columns=False):
        """Pinocchio's vector or matrix `x` in the file's order: its rows (a vector's entries)
        and, with `columns`, its columns."""
        x = np.asarray(x)
        if rows:
            x = x[self.iv]
        return x[..., self.iv] if columns else x

    def frame_id(self, name):
        return self.model.getFrameId(name)


def random_states(order, count, seed):
    """Random states in the file's order: the base in [-1, 1]³, a unit quaternion, the joints in
    [-π, π]; v, a in [-2, 2]; tau in [-20, 20]."""
    rng = np.random.default_rng(seed)
    nv = order.model.nv
    quaternion = rng.normal(size=(count, 4))
    quaternion /= np.linalg.norm(quaternion, axis=1, keepdims=True)
    q = np.hstack([rng.uniform(-1, 1, (count, 3)), quaternion,
                   rng.uniform(-np.pi, np.pi, (count, nv - 6))])
    v, a = rng.uniform(-2, 2, (2, count, nv))
    return q, v, a, rng.uniform(-20, 20, (count, nv))


@pytest.fixture(scope="module", params=["anymal_b", "g1_29dof"])
def robot(request):
    """The robot and its `Order`. ANYmal B with its contacts (gcc -O2 -march=native: 17 s of
    CPU); the G1 without them, built unoptimized: its header with the kinematics (3.2 MB) took
    77 s of gcc's CPU at the package's flags, with the contacts (4.8 MB) longer still, and the C
    tests check both headers' functions (dynamics-cli/tests/it/c_floating.rs)."""
    name = request.param
    with pytest.MonkeyPatch.context() as patch:
        if name == "g1_29dof":
            patch.setenv("DH_DYNAMICS_CFLAGS", "-O0")
        built = dh_dynamics.Robot.from_urdf(URDF / f"{name}.urdf", floating=True,
                                            contacts=name == "anymal_b")
    return name, built, Order(name)


def test_the_dynamics_match_pinocchio(robot):
    name, robot, order = robot
    model, data = order.model, order.data
    q, v, a, tau = random_states(order, 4, 60)
    got = {"M": robot.mass_matrix(q), "h": robot.bias_forces(q, v),
           "tau": robot.inverse_dynamics(q, v, a), "g": robot.generalized_gravity(q),
           "a": robot.forward_dynamics(q, v, tau)}
    for s in range(4):
        qp, vp = order.q(q[s]), order.v(v[s])
        m = pin.crba(model, data, qp).copy()
        want = {"M": order.back(np.triu(m) + np.triu(m, 1).T, columns=True),
                "h": order.back(pin.nonLinearEffects(model, data, qp, vp)),
                "tau": order.back(pin.rnea(model, data, qp, vp, order.v(a[s]))),
                "g": order.back(pin.computeGeneralizedGravity(model, data, qp)),
                "a": order.back(pin.aba(model, data, qp, vp, order.v(tau[s])))}
        for key, w in want.items():
            # The G1's M has a condition number up to 3.5e5: Pinocchio's aba is itself 4e-12
            # off M a + h = tau (docs/floating-base.md).
            tolerance = 1e-10 if key == "a" and name == "g1_29dof" else TOLERANCE
            e = scaled_error(got[key][s], w)
            assert e <= tolerance, f"{name}: {key} at state {s}: off by {e:.3g}"


def test_the_kinematics_match_pinocchio(robot):
    """centerOfMass, jacobianCenterOfMass, computeCentroidalMap (and its time variation times
    v), oMf, getFrameJacobian and getFrameClassicalAcceleration (LOCAL_WORLD_ALIGNED, LOCAL)
    at every frame of FloatingKinematics (the leaf links below a moving joint)."""
    name, robot, order = robot
    assert robot.frames == FRAMES[name]
    model, data = order.model, order.data
    q, v, _, _ = random_states(order, 3, 61)
    com, jcom = robot.center_of_mass(q), robot.center_of_mass_jacobian(q)
    ag, bias = robot.centroidal_momentum_matrix(q), robot.centroidal_momentum_bias(q, v)
    poses = robot.frame_poses(q)
    jacobians = {pin.LOCAL_WORLD_ALIGNED: robot.frame_jacobians_world_aligned(q),
                 pin.LOCAL: robot.frame_jacobians_local(q)}
    drifts = {pin.LOCAL_WORLD_ALIGNED: robot.frame_acceleration_biases_world_aligned(q, v),
              pin.LOCAL: robot.frame_acceleration_biases_local(q, v)}
    for s in range(3):
        qp, vp = order.q(q[s]), order.v(v[s])
        checks = [("com", com[s], pin.centerOfMass(model, data, qp)),
                  ("Jcom", jcom[s], order.back(pin.jacobianCenterOfMass(model, data, qp),
                                               rows=False, columns=True)),
                  ("A_G", ag[s], order.back(pin.computeCentroidalMap(model, data, qp),
                                            rows=False, columns=True)),
                  ("dA_G v", bias[s],
                   pin.computeCentroidalMapTimeVariation(model, data, qp, vp) @ vp)]
        pin.forwardKinematics(model, data, qp, vp, np.zeros(model.nv))
        pin.updateFramePlacements(model, data)
        pin.computeJointJacobians(model, data, qp)
        for frame in robot.frames:
            i = order.frame_id(frame)
            checks.append((f"{frame} pose", poses[frame][s], data.oMf[i].homogeneous[:3]))
            for ref in (pin.LOCAL_WORLD_ALIGNED, pin.LOCAL):
                want = pin.getFrameJacobian(model, data, i, ref)
                checks.append((f"{frame} J {ref}", jacobians[ref][frame][s],
                               order.back(want, rows=False, columns=True)))
                want = pin.getFrameClassicalAcceleration(model, data, i, ref).vector
                checks.append((f"{frame} dJ v {ref}", drifts[ref][frame][s], want))
        for key, got, want in checks:
            e = scaled_error(got, want)
            assert e <= TOLERANCE, f"{name}: {key} at state {s}: off by {e:.3g}"


def test_the_configuration_space_matches_pinocchio(robot):
    """integrate, difference and their Jacobians (dIntegrate, dDifference) with the joints in
    the file's order."""
    name, robot, order = robot
    model = order.model
    q, v, _, _ = random_states(order, 3, 62)
    q1, _, _, _ = random_states(order, 3, 63)
    v[0, 3:6] *= 1e-9
    results = {"integrate": robot.integrate(q, v), "difference": robot.difference(q, q1),
               "dv": robot.integrate_jacobian_v(q, v), "dq": robot.integrate_jacobian_q(q, v),
               "d0": robot.difference_jacobian_q0(q, q1),
               "d1": robot.difference_jacobian_q1(q, q1)}
    for s in range(3):
        qp, vp, q1p = order.q(q[s]), order.v(v[s]), order.q(q1[s])
        want = {"integrate": pin.integrate(model, qp, vp)[order.iq],
                "difference": order.back(pin.difference(model, qp, q1p)),
                "dv": order.back(pin.dIntegrate(model, qp, vp, pin.ARG1), columns=True),
                "dq": order.back(pin.dIntegrate(model, qp, vp, pin.ARG0), columns=True),
                "d0": order.back(pin.dDifference(model, qp, q1p, pin.ARG0), columns=True),
                "d1": order.back(pin.dDifference(model, qp, q1p, pin.ARG1), columns=True)}
        for key, w in want.items():
            e = scaled_error(results[key][s], w)
            assert e <= TOLERANCE, f"{name}: {key} at state {s}: off by {e:.3g}"


def local_force(model, data, frame, wrench):
    """A wrench [f, m] at the frame's origin in world axes as Pinocchio's fext on its joint."""
    placement = model.frames[frame].placement
    rotation = data.oMf[frame].rotation
    return placement.act(pin.Force(rotation.T @ wrench[:3], rotation.T @ wrench[3:]))


def test_anymal_b_contacts_match_pinocchio(robot):
    """rnea and aba with fext at the feet, and constraintDynamics with some feet held (CONTACT_3D
    in LOCAL_WORLD_ALIGNED), on ANYmal B (whose legs Pinocchio orders otherwise)."""
    name, robot, order = robot
    if name != "anymal_b":
        assert not hasattr(robot, "contact_dynamics"), "no contacts=True"
        return
    model, data = order.model, order.data
    q, v, a, tau = random_states(order, 3, 64)
    rng = np.random.default_rng(65)
    feet = FRAMES[name]
    held_sets = [("LF_FOOT", "RH_FOOT"), feet, ("RF_FOOT", "LH_FOOT", "RH_FOOT")]
    for s in range(3):
        qp, vp, ap, taup = order.q(q[s]), order.v(v[s]), order.v(a[s]), order.v(tau[s])
        wrenches = {f: rng.uniform(-10, 10, 6) for f in feet[1:]}
        wrenches[feet[0]] = rng.uniform(-10, 10, 3)
        pin.framesForwardKinematics(model, data, qp)
        fext = [pin.Force.Zero() for _ in range(model.njoints)]
        for frame, w in wrenches.items():
            i = order.frame_id(frame)
            # A 3-vector is a force: a wrench with a zero moment.
            wrench = np.concatenate([w, np.zeros(6 - len(w))])
            fext[model.frames[i].parentJoint] += local_force(model, data, i, wrench)
        got = robot.inverse_dynamics_with_wrenches(q[s], v[s], a[s], wrenches)
        e = scaled_error(got, order.back(pin.rnea(model, data, qp, vp, ap, fext)))
        assert e <= TOLERANCE, (s, e)
        got = robot.forward_dynamics_with_wrenches(q[s], v[s], tau[s], wrenches)
        e = scaled_error(got, order.back(pin.aba(model, data, qp, vp, taup, fext)))
        assert e <= TOLERANCE, (s, e)
        held = held_sets[s]
        ids = [order.frame_id(f) for f in held]
        models = [pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model,
                                           model.frames[i].parentJoint, model.frames[i].placement,
                                           pin.LOCAL_WORLD_ALIGNED) for i in ids]
        datas = [c.createData() for c in models]
        pin.initConstraintDynamics(model, data, models, datas)
        want = order.back(pin.constraintDynamics(model, data, qp, vp, taup, models, datas))
        forces = data.lambda_c.reshape(-1, 3)
        qdd, got = robot.contact_dynamics(q[s], v[s], tau[s], held)
        assert scaled_error(qdd, want) <= TOLERANCE, s
        for k, frame in enumerate(held):
            assert scaled_error(got[frame], forces[k]) <= TOLERANCE, (s, frame)
        assert all(not got[f].any() for f in feet if f not in held)
    # One frame's name alone is that frame.
    alone = robot.contact_dynamics(q[0], v[0], tau[0], "LF_FOOT")
    listed = robot.contact_dynamics(q[0], v[0], tau[0], ["LF_FOOT"])
    assert np.array_equal(alone[0], listed[0]) and np.array_equal(alone[1]["LF_FOOT"],
                                                                  listed[1]["LF_FOOT"])

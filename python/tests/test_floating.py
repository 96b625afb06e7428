"""A robot on a free-flying base (``floating=True``): Solo 12's URDF read by the package and by
Pinocchio's own loader with its free flyer (``buildModelFromUrdf(path, JointModelFreeFlyer())``;
Solo 12's joints are in the same order in both, its legs' names sorted as the file has them),
``mass_matrix``, ``bias_forces``, ``inverse_dynamics``, ``generalized_gravity``,
``forward_dynamics``, ``mass_matrix_inverse``, ``integrate`` and ``difference`` on a batch of
random states and unit quaternions against Pinocchio's ``crba``, ``nonLinearEffects``,
``rnea``, ``computeGeneralizedGravity``, ``aba``, ``computeMinverse``, ``integrate`` and
``difference``; then the batch against each state alone, ``float32``, the errors, and the
readable equations."""

import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

import dh_dynamics  # noqa: E402
from conftest import ROOT, scaled_error  # noqa: E402

SOLO = ROOT / "robots" / "urdf" / "floating" / "solo12.urdf"
TOLERANCE = 1e-12
COUNT = 16


@pytest.fixture(scope="module")
def solo():
    return dh_dynamics.Robot.from_urdf(SOLO, floating=True)


@pytest.fixture(scope="module")
def solo_contacts():
    return dh_dynamics.Robot.from_urdf(SOLO, floating=True, contacts=True)


@pytest.fixture(scope="module")
def model():
    return pin.buildModelFromUrdf(str(SOLO), pin.JointModelFreeFlyer())


def random_states(model, count, seed):
    """Random configurations (the base in [-1, 1]³, a unit quaternion, the joints in [-π, π]),
    velocities, accelerations and generalized forces."""
    rng = np.random.default_rng(seed)
    n = model.nv - 6
    quaternion = rng.normal(size=(count, 4))
    quaternion /= np.linalg.norm(quaternion, axis=1, keepdims=True)
    q = np.hstack([rng.uniform(-1, 1, (count, 3)), quaternion,
                   rng.uniform(-np.pi, np.pi, (count, n))])
    v, a = rng.uniform(-2, 2, (2, count, model.nv))
    tau = rng.uniform(-20, 20, (count, model.nv))
    return q, v, a, tau


def test_the_robot_is_read_on_a_floating_base(solo, model):
    assert solo.floating and solo.dof == model.nv == 18
    for name in ["mass_matrix", "bias_forces", "inverse_dynamics", "generalized_gravity",
                 "forward_dynamics", "mass_matrix_inverse", "integrate", "difference"]:
        assert name in solo.methods, name
    assert "_inverse_dynamics(const double q[19]" in solo.header
    assert "floating base" in repr(solo)
    names = [model.names[j] for j in range(2, model.njoints)]
    assert names[:3] == ["FL_HAA", "FL_HFE", "FL_KFE"], names


def test_the_dynamics_match_pinocchio(solo, model):
    data = model.createData()
    q, v, a, tau = random_states(model, COUNT, 43)
    got = {
        "M": solo.mass_matrix(q),
        "h": solo.bias_forces(q, v),
        "tau": solo.inverse_dynamics(q, v, a),
        "g": solo.generalized_gravity(q),
        "a": solo.forward_dynamics(q, v, tau),
        "Minv": solo.mass_matrix_inverse(q),
    }
    for s in range(COUNT):
        m = pin.crba(model, data, q[s]).copy()
        m = np.triu(m) + np.triu(m, 1).T
        minv = pin.computeMinverse(model, data, q[s]).copy()
        minv = np.triu(minv) + np.triu(minv, 1).T
        want = {
            "M": m,
            "h": pin.nonLinearEffects(model, data, q[s], v[s]),
            "tau": pin.rnea(model, data, q[s], v[s], a[s]),
            "g": pin.computeGeneralizedGravity(model, data, q[s]),
            "a": pin.aba(model, data, q[s], v[s], tau[s]),
            "Minv": minv,
        }
        for key, w in want.items():
            e = scaled_error(got[key][s], w)
            assert e <= TOLERANCE, f"{key} at state {s}: off by {e:.3g}"


def test_integrate_and_difference_match_pinocchio(solo, model):
    q, v, _, _ = random_states(model, COUNT, 44)
    q1, _, _, _ = random_states(model, COUNT, 45)
    # A small step too, where the runtime takes its Taylor series.
    v[0] *= 1e-9
    reached = solo.integrate(q, v)
    velocity = solo.difference(q, q1)
    assert reached.shape == (COUNT, 19) and velocity.shape == (COUNT, 18)
    for s in range(COUNT):
        assert scaled_error(reached[s], pin.integrate(model, q[s], v[s])) <= TOLERANCE, s
        assert scaled_error(velocity[s], pin.difference(model, q[s], q1[s])) <= TOLERANCE, s
    assert np.array_equal(solo.integrate(q[3], v[3]), reached[3])
    # One configuration beside a batch is used for every state.
    assert np.array_equal(solo.difference(q[0], q1)[2], solo.difference(q[0], q1[2]))


def test_the_configuration_jacobians_match_pinocchio(solo, model):
    q, v, _, _ = random_states(model, COUNT, 47)
    q1, _, _, _ = random_states(model, COUNT, 48)
    # A small step too, where the runtime takes its Taylor series.
    v[0] *= 1e-9
    q1[1] = pin.integrate(model, q[1], 1e-9 * v[1])
    got = {
        (pin.dIntegrate, pin.ARG1): solo.integrate_jacobian_v(q, v),
        (pin.dIntegrate, pin.ARG0): solo.integrate_jacobian_q(q, v),
        (pin.dDifference, pin.ARG0): solo.difference_jacobian_q0(q, q1),
        (pin.dDifference, pin.ARG1): solo.difference_jacobian_q1(q, q1),
    }
    for (function, argument), jacobian in got.items():
        assert jacobian.shape == (COUNT, 18, 18)
        second = v if function is pin.dIntegrate else q1
        for s in range(COUNT):
            want = function(model, q[s], second[s], argument)
            e = scaled_error(jacobian[s], want)
            assert e <= TOLERANCE, f"{function.__name__} {argument} at state {s}: off by {e:.3g}"
    alone = solo.difference_jacobian_q0(q[2], q1[2])
    assert np.array_equal(alone, got[pin.dDifference, pin.ARG0][2])


def test_a_batch_is_each_state_alone_and_float32_follows(solo, model):
    q, v, a, _ = random_states(model, 5, 46)
    batch = solo.inverse_dynamics(q, v, a)
    for s in range(5):
        assert np.array_equal(batch[s], solo.inverse_dynamics(q[s], v[s], a[s]))
    single = solo.inverse_dynamics(*(x.astype(np.float32) for x in (q, v, a)))
    assert single.dtype == np.float32
    assert scaled_error(single, batch) <= 1e-4


def test_wrong_inputs_are_refused(solo):
    with pytest.raises(ValueError, match=r"`q` has shape \(18,\)"):
        solo.mass_matrix(np.zeros(18))
    with pytest.raises(ValueError, match="`v` has shape"):
        solo.integrate(np.zeros(19), np.zeros(19))
    with pytest.raises(ValueError, match="not finite"):
        solo.integrate(np.full(19, np.nan), np.zeros(18))


def test_the_equations_name_pinocchios_coordinates(solo):
    text = solo.equations()
    assert "configuration q = [x, y, z, qx, qy, qz, qw, θ1" in text
    assert "  M[vx, vx] = " in text and "  τ[ωz] = " in text
    assert "M_{v_x v_x} &= " in solo.equations(latex=True)
    with pytest.raises(ValueError, match="kinematics"):
        solo.equations(kinematics=True)


FEET = ("FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT")


def test_kinematics_match_pinocchio(solo, model):
    """The header's kinematics (frames by name) against centerOfMass, jacobianCenterOfMass,
    computeCentroidalMap (and its time variation times v), oMf, getFrameJacobian and
    getFrameClassicalAcceleration, in LOCAL_WORLD_ALIGNED and LOCAL."""
    assert solo.frames == FEET
    data = model.createData()
    q, v, _, _ = random_states(model, 4, 47)
    com, jcom = solo.center_of_mass(q), solo.center_of_mass_jacobian(q)
    ag, bias = solo.centroidal_momentum_matrix(q), solo.centroidal_momentum_bias(q, v)
    poses = solo.frame_poses(q)
    jacobians = {"world": solo.frame_jacobians_world_aligned(q),
                 "local": solo.frame_jacobians_local(q)}
    drifts = {"world": solo.frame_acceleration_biases_world_aligned(q, v),
              "local": solo.frame_acceleration_biases_local(q, v)}
    assert com.shape == (4, 3) and ag.shape == (4, 6, 18) and poses["FL_FOOT"].shape == (4, 3, 4)
    references = {"world": pin.LOCAL_WORLD_ALIGNED, "local": pin.LOCAL}
    for s in range(4):
        checks = [(com[s], pin.centerOfMass(model, data, q[s])),
                  (jcom[s], pin.jacobianCenterOfMass(model, data, q[s])),
                  (ag[s], pin.computeCentroidalMap(model, data, q[s])),
                  (bias[s], pin.computeCentroidalMapTimeVariation(model, data, q[s], v[s]) @ v[s])]
        pin.forwardKinematics(model, data, q[s], v[s], np.zeros(model.nv))
        pin.updateFramePlacements(model, data)
        pin.computeJointJacobians(model, data, q[s])
        for name in FEET:
            i = model.getFrameId(name)
            checks.append((poses[name][s], data.oMf[i].homogeneous[:3]))
            for key, ref in references.items():
                checks.append((jacobians[key][name][s], pin.getFrameJacobian(model, data, i, ref)))
                checks.append((drifts[key][name][s],
                               pin.getFrameClassicalAcceleration(model, data, i, ref).vector))
        for k, (got, want) in enumerate(checks):
            assert scaled_error(got, want) <= TOLERANCE, (s, k)
    # One state alone is the batch's.
    assert np.array_equal(solo.frame_poses(q[2])["HR_FOOT"], poses["HR_FOOT"][2])


def local_force(model, data, frame, wrench):
    """A wrench [f, m] at the frame's origin in world axes as Pinocchio's fext on its joint."""
    placement = model.frames[frame].placement
    rotation = data.oMf[frame].rotation
    return placement.act(pin.Force(rotation.T @ wrench[:3], rotation.T @ wrench[3:]))


def test_contacts_match_pinocchio(solo, solo_contacts, model):
    """rnea and aba with fext at the feet, and constraintDynamics with some feet held
    (CONTACT_3D in LOCAL_WORLD_ALIGNED), against the header's contacts."""
    assert not hasattr(solo, "contact_dynamics"), "contacts=True asks for them"
    solo = solo_contacts
    data = model.createData()
    q, v, a, tau = random_states(model, 3, 48)
    rng = np.random.default_rng(49)
    held_sets = [("FL_FOOT", "HR_FOOT"), FEET, ("FR_FOOT",)]
    for s in range(3):
        wrenches = {name: rng.uniform(-10, 10, 6) for name in FEET[:3]}
        pin.framesForwardKinematics(model, data, q[s])
        fext = [pin.Force.Zero() for _ in range(model.njoints)]
        for name, w in wrenches.items():
            i = model.getFrameId(name)
            fext[model.frames[i].parentJoint] += local_force(model, data, i, w)
        want = pin.rnea(model, data, q[s], v[s], a[s], fext)
        got = solo.inverse_dynamics_with_wrenches(q[s], v[s], a[s], wrenches)
        assert scaled_error(got, want) <= TOLERANCE, s
        want = pin.aba(model, data, q[s], v[s], tau[s], fext)
        got = solo.forward_dynamics_with_wrenches(q[s], v[s], tau[s], wrenches)
        assert scaled_error(got, want) <= TOLERANCE, s
        held = held_sets[s]
        models = [pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model,
                                           model.frames[model.getFrameId(f)].parentJoint,
                                           model.frames[model.getFrameId(f)].placement,
                                           pin.LOCAL_WORLD_ALIGNED) for f in held]
        datas = [c.createData() for c in models]
        pin.initConstraintDynamics(model, data, models, datas)
        want = pin.constraintDynamics(model, data, q[s], v[s], tau[s], models, datas)
        forces = data.lambda_c.reshape(-1, 3)
        qdd, got = solo.contact_dynamics(q[s], v[s], tau[s], held)
        assert scaled_error(qdd, want) <= TOLERANCE, s
        for k, name in enumerate(held):
            assert scaled_error(got[name], forces[k]) <= TOLERANCE, (s, name)
        assert all(not got[name].any() for name in FEET if name not in held)
    with pytest.raises(ValueError, match="no frame 'HAND'"):
        solo.contact_dynamics(q[0], v[0], tau[0], ["HAND"])

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

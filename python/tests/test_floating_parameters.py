"""A floating base with parameters (``mass = "mb"``): Solo 12's description file
(``robots/floating/solo12.toml``, its body the ``[floating]`` table) with the body's mass and a
hip's mass named, its kinematics and contacts, which the C functions take the parameters
first for, as the table's methods do. At the file's values they are Pinocchio's for Solo 12's
URDF (the file's frames are the leaf links of its joints list, the lower legs, whose frames are
Pinocchio's ``*_LOWER_LEG`` bodies' frames); at other values Pinocchio's with the same masses
changed (the centres of mass and the inertias about them kept)."""

import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

import dh_dynamics  # noqa: E402
from conftest import ROOT, scaled_error  # noqa: E402

SOLO_FILE = ROOT / "robots" / "floating" / "solo12.toml"
SOLO_URDF = ROOT / "robots" / "urdf" / "floating" / "solo12.urdf"
TOLERANCE = 1e-12
# The file's masses named: the floating body's and the first hip's (FL_HAA's link).
BODY, HIP = "mass = 1.16115091", "mass = 0.14853845"
VALUES = {"mb": 1.16115091, "m1": 0.14853845}
LEGS = ("FL_LOWER_LEG", "FR_LOWER_LEG", "HL_LOWER_LEG", "HR_LOWER_LEG")


@pytest.fixture(scope="module")
def solo_file(tmp_path_factory):
    """The description file with the two masses named."""
    text = SOLO_FILE.read_text(encoding="utf-8")
    named = text.replace(BODY, 'mass = "mb"', 1).replace(HIP, 'mass = "m1"', 1)
    assert named.count('"mb"') == 1 and named.count('"m1"') == 1
    path = tmp_path_factory.mktemp("floating") / "solo12_parameters.toml"
    path.write_text(named, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def solo(solo_file):
    return dh_dynamics.Robot.from_file(solo_file, floating=True, contacts=True)


def model_with(masses):
    """Pinocchio's Solo 12 with the floating body's and FL_HAA's link's masses set."""
    model = pin.buildModelFromUrdf(str(SOLO_URDF), pin.JointModelFreeFlyer())
    for joint, mass in [(1, masses["mb"]), (model.getJointId("FL_HAA"), masses["m1"])]:
        old = model.inertias[joint]
        model.inertias[joint] = pin.Inertia(mass, old.lever, old.inertia)
    return model


def random_states(count, seed):
    rng = np.random.default_rng(seed)
    quaternion = rng.normal(size=(count, 4))
    quaternion /= np.linalg.norm(quaternion, axis=1, keepdims=True)
    q = np.hstack([rng.uniform(-1, 1, (count, 3)), quaternion,
                   rng.uniform(-np.pi, np.pi, (count, 12))])
    v, a = rng.uniform(-2, 2, (2, count, 18))
    return q, v, a, rng.uniform(-20, 20, (count, 18))


def check_against(solo, model, seed):
    """The kinematics and contacts of `solo` against `model`'s at 3 random states."""
    data = model.createData()
    q, v, a, tau = random_states(3, seed)
    frames = dict(zip(solo.frames, LEGS))
    com, ag = solo.center_of_mass(q), solo.centroidal_momentum_matrix(q)
    jacobians = solo.frame_jacobians_world_aligned(q)
    drifts = solo.frame_acceleration_biases_local(q, v)
    rng = np.random.default_rng(seed + 1)
    for s in range(3):
        checks = [("com", com[s], pin.centerOfMass(model, data, q[s])),
                  ("A_G", ag[s], pin.computeCentroidalMap(model, data, q[s]))]
        pin.forwardKinematics(model, data, q[s], v[s], np.zeros(18))
        pin.updateFramePlacements(model, data)
        pin.computeJointJacobians(model, data, q[s])
        fext = [pin.Force.Zero() for _ in range(model.njoints)]
        wrenches = {}
        for mine, theirs in frames.items():
            i = model.getFrameId(theirs)
            checks.append((f"{mine} J", jacobians[mine][s],
                           pin.getFrameJacobian(model, data, i, pin.LOCAL_WORLD_ALIGNED)))
            checks.append((f"{mine} dJ v", drifts[mine][s],
                           pin.getFrameClassicalAcceleration(model, data, i, pin.LOCAL).vector))
            wrenches[mine] = rng.uniform(-10, 10, 6)
            rotation = data.oMf[i].rotation
            local = pin.Force(rotation.T @ wrenches[mine][:3], rotation.T @ wrenches[mine][3:])
            fext[model.frames[i].parentJoint] += model.frames[i].placement.act(local)
        checks.append(("tau with wrenches",
                       solo.inverse_dynamics_with_wrenches(q[s], v[s], a[s], wrenches),
                       pin.rnea(model, data, q[s], v[s], a[s], fext)))
        checks.append(("a with wrenches",
                       solo.forward_dynamics_with_wrenches(q[s], v[s], tau[s], wrenches),
                       pin.aba(model, data, q[s], v[s], tau[s], fext)))
        held = list(solo.frames)[s:s + 2]
        ids = [model.getFrameId(frames[f]) for f in held]
        models = [pin.RigidConstraintModel(pin.ContactType.CONTACT_3D, model,
                                           model.frames[i].parentJoint, model.frames[i].placement,
                                           pin.LOCAL_WORLD_ALIGNED) for i in ids]
        datas = [c.createData() for c in models]
        pin.initConstraintDynamics(model, data, models, datas)
        want = pin.constraintDynamics(model, data, q[s], v[s], tau[s], models, datas).copy()
        qdd, forces = solo.contact_dynamics(q[s], v[s], tau[s], held)
        checks.append(("contact a", qdd, want))
        checks.append(("contact forces", np.array([forces[f] for f in held]),
                       data.lambda_c.reshape(-1, 3)))
        for key, got, want in checks:
            e = scaled_error(got, want)
            assert e <= TOLERANCE, f"{key} at state {s}: off by {e:.3g}"


def test_the_extras_take_the_parameters(solo_file):
    # A robot of its own (its library from the cache): the others give the values.
    solo = dh_dynamics.Robot.from_file(solo_file, floating=True, contacts=True)
    assert solo.parameters.names == ("m1", "mb")
    assert "const double params[2]" in solo.header
    assert "center_of_mass" in solo.methods and "contact_dynamics" in solo.methods
    with pytest.raises(ValueError, match="have no value"):
        solo.center_of_mass(np.r_[0, 0, 0, 0, 0, 0, 1, np.zeros(12)])


def test_at_the_files_values_they_are_pinocchios(solo):
    solo.parameters = VALUES
    check_against(solo, model_with(VALUES), 70)


def test_at_other_values_they_follow_the_masses(solo):
    masses = {"mb": 3.5, "m1": 0.6}
    solo.parameters = masses
    check_against(solo, model_with(masses), 71)
    # The centre of mass moves with the masses: not the file's.
    q = np.r_[0, 0, 0.3, 0, 0, 0, 1, np.full(12, 0.4)]
    moved = solo.center_of_mass(q)
    solo.parameters.update(VALUES)
    assert scaled_error(moved, solo.center_of_mass(q)) > 1e-4

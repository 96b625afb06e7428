"""Every family of methods against Pinocchio's Python bindings, on batches of random states:
the D-H robots (their Pinocchio models built from the same tables as the reference data's),
the UR5 and UR10 URDF files (Pinocchio's own URDF loader), and the Panda, Z1 and SO-101 URDF
files against the Pinocchio data recorded in `tests/data/urdf/` (their chains cut off moving
fingers and jaws, which Pinocchio's loader keeps)."""

import json

import numpy as np
import pytest

pin = pytest.importorskip("pinocchio")

import dh_dynamics  # noqa: E402
from conftest import DATA, ROOT, reference_script, scaled_error, states  # noqa: E402

TOLERANCE = 1e-10
# The URDF front end snaps every angle within 1e-5 rad of a multiple of π/2 to it; Pinocchio's
# loader keeps the file's (the UR files' 1.570796327 is 3.2e-10 rad off π/2), which moves the
# values by up to about 1e-10 (`snapping` in `tests/data/urdf/ur10.json`).
UNSNAPPED_TOLERANCE = 1e-9
COUNT = 12

# (the file the package reads, the D-H table Pinocchio's model is built from). PUMA 560 and the
# Stanford arm are read from `robots/`, whose files keep their published inertias with
# `check_inertia = false`; the others from the reference robots themselves.
DH_ROBOTS = [
    ("robots/puma560.toml", "reference/robots/puma560.json"),
    ("robots/stanford.toml", "reference/robots/stanford.json"),
    ("tests/data/reference/robots/random5.json", "reference/robots/random5.json"),
    ("tests/data/reference/robots/random2.json", "reference/robots/random2.json"),
    ("tests/data/reference/robots/niku_polar.json", "reference/robots/niku_polar.json"),
    ("tests/data/panda/robot.json", "panda/robot.json"),
]


def hand_frame(model, desc):
    """A frame at the D-H hand: the last joint's frame, then (standard table) its a and α."""
    last = desc["joints"][-1]
    script = reference_script()
    if desc.get("convention", "standard") == "modified":
        placement = pin.SE3.Identity()
    else:
        placement = script.se3("x", 0.0, [last["a"], 0, 0]) * script.se3("x", last["alpha"], [0, 0, 0])
    joint = model.njoints - 1
    return model.addFrame(pin.Frame("hand", joint, placement, pin.FrameType.OP_FRAME))


def pinocchio_values(model, frame, q, qd, qdd):
    """Pinocchio's quantities at one state."""
    data = model.createData()
    M = pin.crba(model, data, q)
    M = np.triu(M) + np.triu(M, 1).T
    minv = pin.computeMinverse(model, data, q)
    minv = np.triu(minv) + np.triu(minv, 1).T
    dtau_dq, dtau_dqd, _ = pin.computeRNEADerivatives(model, data, q, qd, qdd)
    out = dict(
        tau=pin.rnea(model, data, q, qd, qdd).copy(),
        M=M,
        Minv=minv,
        g=pin.computeGeneralizedGravity(model, data, q).copy(),
        h=pin.nonLinearEffects(model, data, q, qd).copy(),
        C=pin.computeCoriolisMatrix(model, data, q, qd).copy(),
        kinetic=pin.computeKineticEnergy(model, data, q, qd),
        potential=pin.computePotentialEnergy(model, data, q),
        dtau_dq=dtau_dq.copy(),
        dtau_dqd=dtau_dqd.copy(),
    )
    pin.forwardKinematics(model, data, q)
    pin.updateFramePlacements(model, data)
    pin.computeJointJacobians(model, data, q)
    out["pose"] = data.oMf[frame].homogeneous[:3].copy()
    out["jacobian"] = pin.getFrameJacobian(
        model, data, frame, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    ).copy()
    return out


def check_batch(robot, model, frame, stiffness=None, rest=None, tolerance=TOLERANCE):
    """Every method of the robot's families against Pinocchio, one batch call per method.
    Pinocchio has no joint springs: their torque k (q - rest), energy and slope are added to
    its values; nor friction, which is taken off the robot's τ (the robots here have none that
    depends on more than q̇)."""
    stiffness = np.zeros(robot.dof) if stiffness is None else stiffness
    rest = np.zeros(robot.dof) if rest is None else rest
    q, qd, qdd = states(robot.dof, COUNT, seed=7)
    friction = robot.friction_torques(qd)
    derivatives = robot.inverse_dynamics_derivatives(q, qd, qdd)
    got = dict(
        tau=robot.inverse_dynamics(q, qd, qdd) - friction,
        M=robot.mass_matrix(q),
        Minv=robot.mass_matrix_inverse(q),
        g=robot.gravity_torques(q),
        h=robot.bias_torques(q, qd),
        C=robot.coriolis_matrix(q, qd),
        kinetic=robot.kinetic_energy(q, qd),
        potential=robot.potential_energy(q),
        pose=robot.hand_pose(q),
        jacobian=robot.hand_jacobian_in_base(q),
        dtau_dq=derivatives.dtau_dq,
        dtau_dqd=derivatives.dtau_dqd,
    )
    qdd_back = robot.forward_dynamics(q, qd, got["tau"] + friction)
    for i in range(COUNT):
        want = pinocchio_values(model, frame, q[i], qd[i], qdd[i])
        spring = stiffness * (q[i] - rest)
        for name in ("tau", "g", "h"):
            want[name] = want[name] + spring
        want["potential"] += 0.5 * float(stiffness @ (q[i] - rest) ** 2)
        want["dtau_dq"] = want["dtau_dq"] + np.diag(stiffness)
        for name, value in want.items():
            error = scaled_error(got[name][i], value)
            assert error < tolerance, f"{robot.name} {name} at state {i}: {error:e}"
        error = scaled_error(qdd_back[i], qdd[i])
        assert error < 1e-8, f"{robot.name} forward dynamics at state {i}: {error:e}"


@pytest.mark.parametrize("file,table", DH_ROBOTS, ids=lambda x: x.split("/")[-1])
def test_dh_robots_match_pinocchio(file, table):
    script = reference_script()
    desc = json.loads((DATA / table).read_text())
    model = script.model_from_dh(desc)
    frame = hand_frame(model, desc)
    robot = dh_dynamics.Robot.from_file(ROOT / file, families=["derivatives"])
    stiffness = np.array([j.get("spring_stiffness", 0.0) for j in desc["joints"]])
    rest = np.array([j.get("spring_rest", 0.0) for j in desc["joints"]])
    check_batch(robot, model, frame, stiffness, rest)


def articulated_3r(p):
    """`robots/articulated_3r.toml`'s table with its parameters' values: point masses at the
    link frames' origins."""
    point = dict(type="revolute", theta=0.0, d=0.0, com=[0, 0, 0], inertia=[0] * 6)
    return dict(gravity=[0, 0, -p["g"]], joints=[
        dict(point, a=0.0, alpha=np.pi / 2, mass=p["m1"]),
        dict(point, a=p["a2"], alpha=0.0, mass=p["m2"]),
        dict(point, a=p["a3"], alpha=0.0, mass=p["m3"]),
    ])


def niku_example_6_4(p):
    """`robots/niku_example_6_4.toml`'s table with its parameters' values: uniform rods."""
    def rod(m, l):
        return dict(type="revolute", theta=0.0, d=0.0, a=l, alpha=0.0, mass=m,
                    com=[-l / 2, 0, 0], inertia=[0, m * l * l / 12, m * l * l / 12, 0, 0, 0])
    return dict(gravity=[0, -p["g"], 0], joints=[rod(p["m1"], p["l1"]), rod(p["m2"], p["l2"])])


@pytest.mark.parametrize("table", [articulated_3r, niku_example_6_4], ids=lambda f: f.__name__)
def test_robots_with_parameters_match_pinocchio(table):
    """A description's symbols given values from Python, against Pinocchio's model of the
    table with those values."""
    robot = dh_dynamics.Robot.from_file(ROOT / "robots" / f"{table.__name__}.toml",
                                        families=["derivatives"])
    rng = np.random.default_rng(11)
    for _ in range(2):
        robot.parameters = {name: float(rng.uniform(0.5, 2.0)) for name in robot.parameters}
        desc = table(robot.parameters)
        model = reference_script().model_from_dh(desc)
        check_batch(robot, model, hand_frame(model, desc))


@pytest.mark.parametrize("name", ["ur5", "ur10"])
def test_urdf_robots_match_pinocchios_urdf_loader(name):
    path = ROOT / "robots" / "urdf" / f"{name}.urdf"
    model = pin.buildModelFromUrdf(str(path))
    frame = model.getFrameId("tool0")
    robot = dh_dynamics.Robot.from_urdf(path, base="base_link", tip="tool0",
                                        families=["derivatives"])
    check_batch(robot, model, frame, tolerance=UNSNAPPED_TOLERANCE)


@pytest.mark.parametrize("name", ["panda", "z1", "so101"])
def test_urdf_robots_match_pinocchios_recorded_data(name):
    """The robots whose chains are not Pinocchio's whole model, against the values Pinocchio
    gave for the chain (`tests/data/urdf/make.py`), every sample in one batch."""
    data = json.loads((DATA / "urdf" / f"{name}.json").read_text())
    robot = dh_dynamics.Robot.from_urdf(ROOT / data["urdf"], base=data["base"], tip=data["tip"])
    samples = data["samples"]
    q, qd, qdd = (np.array([s[k] for s in samples]) for k in ("q", "qd", "qdd"))
    got = dict(
        tau=robot.inverse_dynamics(q, qd, qdd),
        M=robot.mass_matrix(q),
        g=robot.gravity_torques(q),
        C=robot.coriolis_matrix(q, qd),
        kinetic_energy=robot.kinetic_energy(q, qd),
        potential_energy=robot.potential_energy(q),
        ee_pose=robot.hand_pose(q),
        jacobian=robot.hand_jacobian_in_base(q),
    )
    for i, sample in enumerate(samples):
        # The recorded τ is Pinocchio's, without the joints' friction the robot adds.
        want = dict(sample, tau=np.add(sample["tau"], sample["friction"]))
        want["ee_pose"] = np.asarray(sample["ee_pose"])[:3]
        for key, value in got.items():
            error = scaled_error(value[i], want[key])
            assert error < TOLERANCE, f"{name} {key} at sample {i}: {error:e}"

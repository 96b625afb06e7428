"""Kinematic reference data from Pinocchio for the reference robots.

Run: bench/.venv/bin/python tests/data/kinematics/make.py  (Pinocchio 4.1.0, numpy)

For each robot of tests/data/reference/robots/ and tests/data/panda/robot.json, a Pinocchio
model is built from its D-H table, as tests/data/panda/make.py builds the Panda: one RZ (PZ for a
prismatic joint) per row, placed by Rotx(alpha) Transx(a) Rotz(theta) Transz(d) (modified) or,
for a standard table, by the previous row's Transx(a) Rotx(alpha) followed by Rotz(theta)
Transz(d), with the last row's Transx(a) Rotx(alpha) as the placement of the hand frame (an
OP_FRAME, "hand"). At 10 seeded samples of (q, qd) it records the hand's placement
(framesForwardKinematics), its Jacobian (computeJointJacobians, getFrameJacobian) in LOCAL and
LOCAL_WORLD_ALIGNED, and its classical acceleration at qdd = 0
(getFrameClassicalAcceleration, LOCAL and LOCAL_WORLD_ALIGNED): J̇ q̇.

External load: each sample also has a wrench F = [fx, fy, fz, mx, my, mz] ("wrench", in the hand
frame's axes, moment about its origin; from a second seeded generator, so that q and qd are those
drawn without it) and qdd, and records tau_external = rnea(q, qd, qdd) - rnea(q, qd, qdd, fext),
fext applying F (expressed in the last joint's frame, frame.placement.act) to the last joint:
Pinocchio's fext are what the environment applies on the robot, so the difference is the torque
that holds F. The bodies get seeded random inertias (the D-H model has none), which cancel in the
difference. The script asserts tau_external = Jᵀ F with getFrameJacobian(LOCAL) to 1e-12.
Writes <robot>.json here.
"""

import json
import pathlib

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE.parent
ROBOTS = sorted((DATA / "reference" / "robots").glob("*.json")) + [DATA / "panda" / "robot.json"]


def se3(rotation_axis, angle, translation):
    return pin.SE3(pin.utils.rotate(rotation_axis, angle), np.array(translation, dtype=float))


def model_from_dh(desc):
    model = pin.Model()
    parent, previous = 0, pin.SE3.Identity()
    modified = desc.get("convention", "standard") == "modified"
    for i, j in enumerate(desc["joints"]):
        twist = se3("x", j["alpha"], [0, 0, 0])
        shift = se3("x", 0.0, [j["a"], 0, 0])
        turn = se3("z", j["theta"], [0, 0, 0]) * se3("z", 0.0, [0, 0, j["d"]])
        placement = twist * shift * turn if modified else previous * turn
        joint = pin.JointModelRZ() if j["type"] == "revolute" else pin.JointModelPZ()
        parent = model.addJoint(parent, joint, placement, f"joint{i + 1}")
        previous = pin.SE3.Identity() if modified else shift * twist
    model.addFrame(pin.Frame("hand", parent, 0, previous, pin.FrameType.OP_FRAME))
    return model


def rows(m):
    return [[float(x) for x in row] for row in np.asarray(m)]


def sample(model, data, fid, q, qd):
    pin.framesForwardKinematics(model, data, q)
    pin.computeJointJacobians(model, data, q)
    placement = data.oMf[fid]
    world = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    local = pin.ReferenceFrame.LOCAL
    out = {
        "q": q.tolist(),
        "qd": qd.tolist(),
        "rotation": rows(placement.rotation),
        "translation": placement.translation.tolist(),
        "jacobian_world_aligned": rows(pin.getFrameJacobian(model, data, fid, world)),
        "jacobian_local": rows(pin.getFrameJacobian(model, data, fid, local)),
    }
    pin.forwardKinematics(model, data, q, qd, np.zeros(model.nv))
    pin.updateFramePlacements(model, data)
    for key, frame in [("bias_world_aligned", world), ("bias_local", local)]:
        a = pin.getFrameClassicalAcceleration(model, data, fid, frame)
        out[key] = a.linear.tolist() + a.angular.tolist()
    return out


def give_inertias(model, rng):
    """Seeded random bodies: RNEA then has real work to do; they cancel in tau_external."""
    for i in range(1, model.njoints):
        root = rng.uniform(-1, 1, (3, 3))
        rotational = root @ root.T + 0.1 * np.eye(3)
        model.inertias[i] = pin.Inertia(rng.uniform(0.5, 5), rng.uniform(-0.2, 0.2, 3), rotational)


def external_load(model, data, fid, q, qd, rng):
    """The wrench F in the hand frame and the joint torques that hold it, by RNEA with fext."""
    wrench = rng.uniform(-5, 5, 6)
    qdd = rng.uniform(-2, 2, model.nv)
    frame = model.frames[fid]
    fext = [pin.Force.Zero() for _ in range(model.njoints)]
    fext[frame.parentJoint] = frame.placement.act(pin.Force(wrench))
    free = pin.rnea(model, data, q, qd, qdd).copy()
    loaded = pin.rnea(model, data, q, qd, qdd, fext).copy()
    tau_external = free - loaded
    pin.computeJointJacobians(model, data, q)
    pin.updateFramePlacements(model, data)
    by_jacobian = pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL).T @ wrench
    gap = np.max(np.abs(tau_external - by_jacobian))
    assert gap <= 1e-12 * max(1.0, np.max(np.abs(by_jacobian))), gap
    fields = {"wrench": wrench.tolist(), "qdd": qdd.tolist(), "tau_external": tau_external.tolist()}
    return fields, gap


def main():
    rng = np.random.default_rng(17)
    load_rng = np.random.default_rng(1717)
    for path in ROBOTS:
        desc = json.loads(path.read_text())
        model = model_from_dh(desc)
        give_inertias(model, load_rng)
        data = model.createData()
        fid = model.getFrameId("hand")
        samples, worst_gap = [], 0.0
        for _ in range(10):
            q, qd = rng.uniform(-3, 3, model.nq), rng.uniform(-2, 2, model.nv)
            samples.append(sample(model, data, fid, q, qd))
            fields, gap = external_load(model, data, fid, q, qd, load_rng)
            samples[-1].update(fields)
            worst_gap = max(worst_gap, gap)
        name = path.stem if path.parent.name == "robots" else path.parent.name
        out = {
            "robot": str(path.relative_to(DATA)),
            "generator": f"tests/data/kinematics/make.py with pinocchio {pin.__version__}",
            "samples": samples,
        }
        (HERE / f"{name}.json").write_text(json.dumps(out, indent=1) + "\n")
        print(name, len(samples), f"samples; worst |tau_external - J^T F| {worst_gap:.1e}")


if __name__ == "__main__":
    main()

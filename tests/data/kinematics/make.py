"""Kinematic reference data from Pinocchio for the reference robots.

Run: /work/venv/bin/python tests/data/kinematics/make.py  (Pinocchio 4.1.0, numpy)

For each robot of tests/data/reference/robots/ and tests/data/panda/robot.json, a Pinocchio
model is built from its D-H table, as tests/data/panda/make.py builds the Panda: one RZ (PZ for a
prismatic joint) per row, placed by Rotx(alpha) Transx(a) Rotz(theta) Transz(d) (modified) or,
for a standard table, by the previous row's Transx(a) Rotx(alpha) followed by Rotz(theta)
Transz(d), with the last row's Transx(a) Rotx(alpha) as the placement of the hand frame (an
OP_FRAME, "hand"). At 10 seeded samples of (q, qd) it records the hand's placement
(framesForwardKinematics), its Jacobian (computeJointJacobians, getFrameJacobian) in LOCAL and
LOCAL_WORLD_ALIGNED, and its classical acceleration at qdd = 0
(getFrameClassicalAcceleration, LOCAL and LOCAL_WORLD_ALIGNED): J̇ q̇. Writes <robot>.json here.
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


def main():
    rng = np.random.default_rng(17)
    for path in ROBOTS:
        desc = json.loads(path.read_text())
        model = model_from_dh(desc)
        data = model.createData()
        fid = model.getFrameId("hand")
        samples = [
            sample(model, data, fid, rng.uniform(-3, 3, model.nq), rng.uniform(-2, 2, model.nv))
            for _ in range(10)
        ]
        name = path.stem if path.parent.name == "robots" else path.parent.name
        out = {
            "robot": str(path.relative_to(DATA)),
            "generator": f"tests/data/kinematics/make.py with pinocchio {pin.__version__}",
            "samples": samples,
        }
        (HERE / f"{name}.json").write_text(json.dumps(out, indent=1) + "\n")
        print(name, len(samples))


if __name__ == "__main__":
    main()

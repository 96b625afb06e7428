"""Forward-dynamics reference data from Pinocchio for the reference robots.

Run: bench/.venv/bin/python tests/data/forward/make.py  (Pinocchio 4.1.0, numpy)

For each robot of tests/data/reference/robots/ (but ur5, whose M is singular: its last link has
no inertia about its axis, and the reference M has M66 = 0) and tests/data/panda/robot.json, a
Pinocchio model is built from its D-H table as tests/data/kinematics/make.py builds it (one RZ or
PZ per row, placed by Rotx(alpha) Transx(a) Rotz(theta) Transz(d) for a modified table, by the
previous row's Transx(a) Rotx(alpha) then Rotz(theta) Transz(d) for a standard one), with each
link's body (mass, com, inertia about the com, in link frame i: for a standard table, joint
frame i followed by Transx(a) Rotx(alpha)), the actuator inertia as the joint's armature and the
description's gravity. At 10 seeded samples of (q, qd, tau) it records qdd = aba(q, qd, tau) and
computeMinverse(q) (Pinocchio fills its upper triangle; the lower is mirrored). Pinocchio has no
joint springs: for a robot with springs (the Panda), aba is given tau - k (q - q0), which is what
tau leaves once the springs are held.

Before writing, the script asserts, per robot, that crba(q) equals M of the robot's data file in
tests/data/reference/data/ (or tests/data/panda/data.json) at its first sample to 1e-12 (the
model is the one those files were made from), and per sample that M Minv = I and
aba(q, qd, rnea(q, qd, qdd)) = qdd to 1e-10. Writes <robot>.json here.
"""

import json
import pathlib

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE.parent
ROBOTS = [
    p for p in sorted((DATA / "reference" / "robots").glob("*.json")) if p.stem != "ur5"
] + [DATA / "panda" / "robot.json"]


def se3(rotation_axis, angle, translation):
    return pin.SE3(pin.utils.rotate(rotation_axis, angle), np.array(translation, dtype=float))


def model_from_dh(desc):
    model = pin.Model()
    model.gravity = pin.Motion(np.array(desc["gravity"], dtype=float), np.zeros(3))
    parent, previous = 0, pin.SE3.Identity()
    modified = desc.get("convention", "standard") == "modified"
    armature = []
    for i, j in enumerate(desc["joints"]):
        twist = se3("x", j["alpha"], [0, 0, 0])
        shift = se3("x", 0.0, [j["a"], 0, 0])
        turn = se3("z", j["theta"], [0, 0, 0]) * se3("z", 0.0, [0, 0, j["d"]])
        placement = twist * shift * turn if modified else previous * turn
        joint = pin.JointModelRZ() if j["type"] == "revolute" else pin.JointModelPZ()
        parent = model.addJoint(parent, joint, placement, f"joint{i + 1}")
        ixx, iyy, izz, ixy, ixz, iyz = j["inertia"]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        link = pin.SE3.Identity() if modified else shift * twist
        body = pin.Inertia(j["mass"], np.array(j["com"], dtype=float), inertia)
        model.appendBodyToJoint(parent, body, link)
        armature.append(j.get("actuator_inertia", 0.0))
        previous = pin.SE3.Identity() if modified else shift * twist
    model.armature = np.array(armature)
    return model


def springs(desc, q):
    return np.array(
        [j.get("spring_stiffness", 0.0) * (qi - j.get("spring_rest", 0.0)) for j, qi in zip(desc["joints"], q)]
    )


def symmetric(upper):
    return np.triu(upper) + np.triu(upper, 1).T


def reference_file(path):
    if path.parent.name == "robots":
        return DATA / "reference" / "data" / path.name
    return DATA / "panda" / "data.json"


def scaled(a, b):
    return np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(1.0, np.max(np.abs(b)))


def main():
    rng = np.random.default_rng(18)
    for path in ROBOTS:
        desc = json.loads(path.read_text())
        model = model_from_dh(desc)
        data = model.createData()
        first = json.loads(reference_file(path).read_text())["samples"][0]
        m = pin.crba(model, data, np.array(first["q"]))
        gap = scaled(symmetric(m), first["M"])
        assert gap < 1e-12, (path.stem, gap)
        samples = []
        for _ in range(10):
            q, qd = rng.uniform(-3, 3, model.nq), rng.uniform(-2, 2, model.nv)
            tau = rng.uniform(-20, 20, model.nv)
            qdd = pin.aba(model, data, q, qd, tau - springs(desc, q)).copy()
            minv = symmetric(pin.computeMinverse(model, data, q))
            m = symmetric(pin.crba(model, data, q))
            assert scaled(m @ minv, np.eye(model.nv)) < 1e-10
            back = pin.aba(model, data, q, qd, pin.rnea(model, data, q, qd, qdd))
            assert scaled(back, qdd) < 1e-10
            samples.append(
                {
                    "q": q.tolist(),
                    "qd": qd.tolist(),
                    "tau": tau.tolist(),
                    "qdd": qdd.tolist(),
                    "Minv": [row.tolist() for row in minv],
                }
            )
        name = path.stem if path.parent.name == "robots" else path.parent.name
        out = {
            "robot": str(path.relative_to(DATA)),
            "generator": f"tests/data/forward/make.py with pinocchio {pin.__version__}",
            "samples": samples,
        }
        (HERE / f"{name}.json").write_text(json.dumps(out, indent=1) + "\n")
        print(name, len(samples), f"samples; crba vs the data file's M {gap:.1e}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Reference data for robots whose joints are given URDF style (placement xyz/rpy, then a unit
axis), as the description files' `origin = { xyz, rpy }` and `axis` write them.

Writes, beside this script, `<robot>.toml` (the description) and `<robot>.json` (20 samples in
the format of `../reference/data`, see its README) for each robot below. The Pinocchio 4.1.0
model is built joint by joint from the placements and axes, independently of the project's
lowering to a D-H table: `JointModelRX/RY/RZ` (or `PX/PY/PZ`) for an axis along +x, +y, +z,
`JointModelRevoluteUnaligned` (or `PrismaticUnaligned`) otherwise, each placed by
`SE3(rpyToMatrix(r, p, y), xyz)`, with its link's inertia in the joint frame.

Angles within 1e-5 rad of a multiple of pi/2 are snapped to it before Pinocchio sees them, as
the project does (URDF files write 1.5708 and 3.14159); the script builds a second model with
the angles as written and reports the largest change snapping makes to tau, M, C, g and both
energies, scaled as max|a - b| / max(1, max|b|). It also checks tau = M qdd + h, h = C qd + g,
KE = qd^T M qd / 2.

Usage: bench/.venv/bin/python tests/data/frames/make.py
"""

import json
import math
import os
import sys

import numpy as np
import pinocchio as pin

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from pinocchio_data import TOLERANCE, identities, quantities, rounded, samples, scaled_error  # noqa: E402

SEED = 20261216
QUARTER_TURN_TOLERANCE = 1e-5

# UR5 as example-robot-data 6.0.0's ur5.urdf gives its six joints and link inertials (the base's
# yaw of -pi folded into joint 1), with pi/2 written 1.5708 and pi written 3.14159, as many URDFs do.
UR5 = {
    "name": "ur5_urdf",
    "description": "UR5: the joints and link inertials of example-robot-data 6.0.0 ur5.urdf, "
    "the base link's yaw folded into joint 1, pi/2 written 1.5708 and pi 3.14159",
    "gravity": [0.0, 0.0, -9.81],
    "joints": [
        ("revolute", [0, 0, 0.089159], [0, 0, -3.14159], [0, 0, 1],
         3.7, [0, 0, 0], [0.010267495893, 0.010267495893, 0.00666, 0, 0, 0]),
        ("revolute", [0, 0.13585, 0], [0, 1.5708, 0], [0, 1, 0],
         8.393, [0, 0, 0.28], [0.22689067591, 0.22689067591, 0.0151074, 0, 0, 0]),
        ("revolute", [0, -0.1197, 0.425], [0, 0, 0], [0, 1, 0],
         2.275, [0, 0, 0.25], [0.049443313556, 0.049443313556, 0.004095, 0, 0, 0]),
        ("revolute", [0, 0, 0.39225], [0, 1.5708, 0], [0, 1, 0],
         1.219, [0, 0, 0], [0.111172755531, 0.111172755531, 0.21942, 0, 0, 0]),
        ("revolute", [0, 0.093, 0], [0, 0, 0], [0, 0, 1],
         1.219, [0, 0, 0], [0.111172755531, 0.111172755531, 0.21942, 0, 0, 0]),
        ("revolute", [0, 0, 0.09465], [0, 0, 0], [0, 1, 0],
         0.1879, [0, 0, 0], [0.0171364731454, 0.0171364731454, 0.033822, 0, 0, 0]),
    ],
}

# A small robot with exact quarter turns written as 3.14159 and -1.5708, a prismatic joint and
# a negative axis, gravity off the axes.
TILTED = {
    "name": "tilted",
    "description": "three joints (R P R): quarter turns written 3.14159 and -1.5708, a "
    "prismatic joint along -y, gravity off the axes",
    "gravity": [0.0, -6.0, -7.5],
    "joints": [
        ("revolute", [0.1, 0, 0.2], [3.14159, 0, 0], [1, 0, 0],
         1.5, [0.05, 0.01, -0.02], [0.02, 0.03, 0.025, 0.001, 0, -0.002]),
        ("prismatic", [0, 0.3, 0], [0, -1.5708, 0], [0, -1, 0],
         0.8, [0, -0.1, 0.03], [0.01, 0.004, 0.011, 0, 0.0005, 0]),
        ("revolute", [0.05, 0, -0.15], [0, 0, 1.5708], [0, 0, 1],
         0.6, [0.02, 0, 0.01], [0.003, 0.004, 0.005, 0, 0, 0.0002]),
    ],
}


def random_robot(rng):
    """Six joints R P R R P R: generic rpy and axes, some quarter turns, lengths to 4 digits."""
    kinds = ["revolute", "prismatic", "revolute", "revolute", "prismatic", "revolute"]
    joints = []
    for k, kind in enumerate(kinds):
        xyz = [round(float(x), 4) for x in rng.uniform(-0.3, 0.3, 3)]
        rpy = [round(float(x), 4) for x in rng.uniform(-3.0, 3.0, 3)]
        if k in (2, 4):
            rpy[k % 3] = 1.5708 if k == 2 else 0.0
        if k in (1, 3):
            axis = [0.0, 0.0, 0.0]
            axis[k % 3] = -1.0 if k == 3 else 1.0
        else:
            v = rng.normal(size=3)
            axis = [round(float(x), 6) for x in v / np.linalg.norm(v)]
        mass = round(float(rng.uniform(0.5, 3.0)), 3)
        com = [round(float(x), 4) for x in rng.uniform(-0.1, 0.1, 3)]
        principal = rng.uniform(0.01, 0.02, 3)
        rotation = pin.rpy.rpyToMatrix(*rng.uniform(-3.0, 3.0, 3))
        tensor = rotation @ np.diag(principal) @ rotation.T
        inertia = [round(float(tensor[i, j]), 7) for i, j in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))]
        joints.append((kind, xyz, rpy, axis, mass, com, inertia))
    return {
        "name": "general",
        "description": f"six joints R P R R P R, generic placements and axes, seed {SEED}",
        "gravity": [0.5, -0.3, -9.78],
        "joints": joints,
    }


def snap(angle):
    k = round(angle / (math.pi / 2))
    return k * math.pi / 2 if abs(angle - k * math.pi / 2) <= QUARTER_TURN_TOLERANCE else angle


def joint_model(kind, axis):
    axis = np.array(axis, float)
    axis = axis / np.linalg.norm(axis)
    aligned = {(1.0, 0.0, 0.0): "X", (0.0, 1.0, 0.0): "Y", (0.0, 0.0, 1.0): "Z"}.get(tuple(axis))
    if kind == "revolute":
        return getattr(pin, f"JointModelR{aligned}")() if aligned else pin.JointModelRevoluteUnaligned(axis)
    return getattr(pin, f"JointModelP{aligned}")() if aligned else pin.JointModelPrismaticUnaligned(axis)


def model(robot, snapped):
    m = pin.Model()
    m.gravity = pin.Motion(np.array(robot["gravity"], float), np.zeros(3))
    parent = 0
    for i, (kind, xyz, rpy, axis, mass, com, inertia) in enumerate(robot["joints"]):
        angles = [snap(a) if snapped else a for a in rpy]
        placement = pin.SE3(pin.rpy.rpyToMatrix(*angles), np.array(xyz, float))
        jid = m.addJoint(parent, joint_model(kind, axis), placement, f"joint{i + 1}")
        ixx, iyy, izz, ixy, ixz, iyz = inertia
        tensor = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], float)
        m.appendBodyToJoint(jid, pin.Inertia(mass, np.array(com, float), tensor), pin.SE3.Identity())
        m.addFrame(pin.Frame(f"link_{i + 1}", jid, 0, pin.SE3.Identity(), pin.FrameType.OP_FRAME))
        parent = jid
    return m


def number(x):
    return repr(float(x)) if float(x) != int(x) else str(int(x))


def toml(robot):
    lines = [
        f"# {robot['description']}.",
        "# Written by tests/data/frames/make.py (see README.md there): each joint's frame is placed",
        "# in the previous link's frame by origin (xyz in m, rpy in rad, URDF's <origin>), then",
        "# turns about or slides along its unit axis; mass in kg, com and inertia (about the com,",
        "# [Ixx, Iyy, Izz, Ixy, Ixz, Iyz], kg m^2) in the joint frame.",
        f'name = "{robot["name"]}"',
        f"gravity = [{', '.join(number(x) for x in robot['gravity'])}]",
    ]
    for i, (kind, xyz, rpy, axis, mass, com, inertia) in enumerate(robot["joints"]):
        vec = lambda v: "[" + ", ".join(number(x) for x in v) + "]"
        lines += [
            "",
            f"[[joints]]  # joint {i + 1}",
            f'type = "{kind}"',
            f"origin = {{ xyz = {vec(xyz)}, rpy = {vec(rpy)} }}",
            f"axis = {vec(axis)}",
            f"mass = {number(mass)}",
            f"com = {vec(com)}",
            f"inertia = {vec(inertia)}",
        ]
    return "\n".join(lines) + "\n"


def write(robot, rng, here):
    snapped, as_written = model(robot, True), model(robot, False)
    out, snapping, worst = [], 0.0, 0.0
    frame = f"link_{snapped.nq}"
    for q, qd, qdd in samples(snapped.nq, rng):
        x = quantities(snapped, frame, q, qd, qdd)
        y = quantities(as_written, frame, q, qd, qdd)
        for key in ("tau", "M", "C", "g", "kinetic_energy", "potential_energy"):
            snapping = max(snapping, scaled_error(y[key], x[key]))
        worst = max(worst, identities(x, qd, qdd))
        sample = {"q": q, "qd": qd, "qdd": qdd}
        sample.update(x)
        out.append({k: rounded(v) for k, v in sample.items()})
    name = robot["name"]
    data = {
        "robot": name,
        "generator": f"tests/data/frames/make.py with pinocchio {pin.__version__}",
        "seed": SEED,
        "n": snapped.nq,
        "units": "SI: m, rad, kg, kg m^2, s; tau in N m (revolute) or N (prismatic)",
        "notes": "tau = M qdd + h; h = C qd + g; ee_pose and jacobian ([v; w], base axes) of the "
        "user's link frame n; numbers rounded to 15 significant digits; angles snapped to "
        f"quarter turns within {QUARTER_TURN_TOLERANCE} rad; largest change snapping makes "
        f"(tau, M, C, g, energies, scaled): {snapping:.1e}; identities {worst:.1e}",
        "description": f"{name}.toml",
        "samples": out,
    }
    with open(os.path.join(here, f"{name}.toml"), "w") as f:
        f.write(toml(robot))
    with open(os.path.join(here, f"{name}.json"), "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print(f"{name}: {snapped.nq} joints, snapping changes outputs by {snapping:.1e}, "
          f"identities {worst:.1e}")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    rng = np.random.default_rng(SEED)
    for robot in (UR5, TILTED, random_robot(rng)):
        write(robot, rng, here)


if __name__ == "__main__":
    main()

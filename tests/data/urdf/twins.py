#!/usr/bin/env python3
"""The D-H twins of two URDF robots, checked against Pinocchio's URDF loader.

A twin is the robot of a URDF file written as a D-H table: the same joints, their axes along
the z axes of modified (Craig) D-H frames, each link's mass, centre of mass and inertia
re-expressed in its D-H frame. The URDF robots are compared with their twins in value (the test
`tests/tests/it/urdf_robots.rs`) and in operation count (the issue asks for counts within 5 %).

* `ur5`: the table below, derived by hand from the URDF's joint origins and axes (D-H frame 0 is
  the URDF's base_link frame).
* `panda`: Franka's modified D-H table (that of `tests/data/panda/make.py`; the URDF's link
  frames are its D-H frames). Not the robot of `tests/data/panda/robot.json`: the URDF chain to
  panda_link8 carries the hand, fixed to the flange (0.73 kg, merged into link 7), which that
  hand-less arm leaves out.

The link parameters are not copied: for each joint, the pose of the URDF link frame in the D-H
frame, X_i = (0_T_i^DH)^-1 0_T_i^URDF at q = 0 (checked constant at random q), maps
Pinocchio's inertia of the URDF link (fixed links merged) to the D-H frame (X_i.act). Written to
`robots/<robot>_urdf_dh.toml` (the description file a user would write) and `<robot>_dh.json`
(the same description and the 20 samples of make.py computed from the D-H model, for the
benchmark).

For each twin: a Pinocchio model built joint by joint from the D-H table (as
`tests/data/panda/make.py` builds it) must give the URDF model's tau, M, C, g and both energies
to 1e-12 (scaled) on the 20 samples of `make.py`, with the angles snapped as make.py snaps them.

Usage, from the repository root: bench/.venv/bin/python tests/data/urdf/twins.py
"""

import importlib.util
import math
import os

import numpy as np
import pinocchio as pin

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))


spec = importlib.util.spec_from_file_location("urdf_make", os.path.join(HERE, "make.py"))
make = importlib.util.module_from_spec(spec)
spec.loader.exec_module(make)
panda = make.panda

# The UR5's modified D-H table (Craig): row i holds a_{i-1}, alpha_{i-1}, d_i; theta offsets 0.
# Axes 2, 3 and 4 are parallel (the URDF's y): their common normals are put where d_2 = d_3 = 0,
# so the URDF's offsets along them (0.13585 - 0.1197 + 0.093) add up in d_4 = 0.10915.
UR5_DH = [
    (0.0, 0.0, 0.089159),
    (0.0, -math.pi / 2, 0.0),
    (0.425, 0.0, 0.0),
    (0.39225, 0.0, 0.10915),
    (0.0, -math.pi / 2, 0.09465),
    (0.0, math.pi / 2, 0.0),
]
TOLERANCE = 1e-12


def clean(x):
    """15 significant digits (the URDF's values have at most 12), -0 and 1e-17 noise to 0."""
    return 0.0 if abs(x) < 1e-15 else float(f"{x:.15g}")


def urdf_model(name):
    """The snapped chain of make.py, as Pinocchio's URDF loader builds it."""
    file, base, tip = make.ROBOTS[name]
    root = make.ET.parse(os.path.join(ROOT, "robots", "urdf", file)).getroot()
    make.prune(root, make.rigid_chain(root, base, tip)[1])
    make.snap(root)
    return make.load(root)


def re_expressed(urdf, table):
    """The D-H description with each URDF link's inertia mapped into its D-H frame."""
    geometry = {"gravity": make.GRAVITY, "joints": [
        {"type": "revolute", "theta": 0.0, "d": d, "a": a, "alpha": alpha, "mass": 0.0,
         "com": [0.0, 0.0, 0.0], "inertia": [0.0] * 6} for a, alpha, d in table]}
    dh = panda.model_from_dh(geometry)
    poses = link_poses(urdf, dh, np.zeros(urdf.nq))
    rng = np.random.default_rng(1)
    for _ in range(5):
        other = link_poses(urdf, dh, rng.uniform(-math.pi, math.pi, urdf.nq))
        assert all(np.allclose(x.homogeneous, y.homogeneous, atol=1e-14) for x, y in zip(poses, other)), \
            "a URDF link frame moves in its D-H frame: wrong table"
    for joint, pose, i in zip(geometry["joints"], poses, range(1, urdf.njoints)):
        inertia = pose.act(urdf.inertias[i])
        I = inertia.inertia
        joint["mass"] = clean(inertia.mass)
        joint["com"] = [clean(c) for c in inertia.lever]
        joint["inertia"] = [clean(v) for v in (I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2])]
        joint.update(actuator_inertia=0.0, spring_stiffness=0.0, spring_rest=0.0)
    return geometry


def link_poses(urdf, dh, q):
    """X_i: the URDF link frame i in D-H frame i, at q."""
    a, b = urdf.createData(), dh.createData()
    pin.forwardKinematics(urdf, a, q)
    pin.forwardKinematics(dh, b, q)
    return [b.oMi[i].actInv(a.oMi[i]) for i in range(1, urdf.njoints)]


def compare(name, desc):
    """The D-H model against the URDF model on make.py's samples; returns the worst scaled error."""
    urdf, dh = urdf_model(name), panda.model_from_dh(desc)
    tip = make.ROBOTS[name][2]
    worst, out = 0.0, []
    for q, qd, qdd in make.samples(urdf, make.SEED):
        x = make.quantities(urdf, tip, q, qd, qdd)
        y = make.quantities(dh, f"link_{dh.nv}", q, qd, qdd)
        for k in ("tau", "M", "C", "h", "g", "kinetic_energy", "potential_energy"):
            worst = max(worst, make.scaled_error(y[k], x[k]))
        y.pop("ee_pose"), y.pop("jacobian")  # frame n of the D-H table, not the URDF's tip
        sample = {"q": q, "qd": qd, "qdd": qdd}
        sample.update(y)
        out.append({k: make.rounded(v) for k, v in sample.items()})
    assert worst < TOLERANCE, f"{name}: D-H twin against the URDF: {worst:e}"
    return worst, out


def angle(x):
    """A multiple of 90 degrees as the description files write it, else radians."""
    k = round(x / (math.pi / 2))
    return f'"{90 * k} deg"' if k != 0 and x == k * (math.pi / 2) else repr(x)


HEADERS = {
    "ur5": ["UR5", "D-H frame 0 = the URDF's base_link",
            "Not the UR5 of robots/ur5.toml (the Robotics Toolbox's point masses)."],
    "panda": ["Franka Emika Panda", "Franka's table; D-H frame 0 = panda_link0",
              "Link 7 carries the hand (fixed to panda_link8): not the hand-less robots/panda.toml."],
}


def toml(name, desc, worst, friction):
    """The twin as a description file; `friction` is the URDF's (damping, friction) per joint."""
    robot, frames, note = HEADERS[name]
    lines = [
        f"# {robot} from its URDF (robots/urdf/{name}.urdf, example-robot-data 6.0.0), written as a D-H",
        f"# table: its D-H twin. Modified (Craig) D-H frames ({frames}); the URDF's link",
        "# masses, centres of mass and inertias (fixed links merged) re-expressed in the D-H frames.",
        f"# Made and checked by tests/data/urdf/twins.py: a Pinocchio model of this table matches the",
        f"# URDF's to {worst:.0e}. {note}",
        "# Lengths in m, masses in kg, inertia in kg m² about the centre of mass in link frame i",
        "# ([Ixx, Iyy, Izz, Ixy, Ixz, Iyz]).",
        f'name = "{name}_urdf_dh"',
        'convention = "modified"',
        "gravity = [0, 0, -9.81]",
    ]
    for i, j in enumerate(desc["joints"]):
        lines += ["", f"[[joints]]  # joint {i + 1}", 'type = "revolute"']
        lines += [f"{k} = {repr(j[k])}" for k in ("d", "a") if j[k] != 0.0]
        if j["alpha"] != 0.0:
            lines.append(f"alpha = {angle(j['alpha'])}")
        lines.append(f"mass = {j['mass']!r}")
        lines.append(f"com = [{', '.join(repr(c) for c in j['com'])}]")
        lines.append(f"inertia = [{', '.join(repr(c) for c in j['inertia'])}]")
        viscous, coulomb = friction[i]
        lines += [f"friction_{k} = {v!r}" for k, v in (("viscous", viscous), ("coulomb", coulomb)) if v]
    return "\n".join(lines) + "\n"


def main():
    for name, table in (("ur5", UR5_DH), ("panda", panda.DH)):
        urdf = urdf_model(name)
        desc = re_expressed(urdf, table)
        friction = [(float(v), float(c)) for v, c in zip(urdf.damping, urdf.friction)]
        desc = {"name": f"{name}_urdf_dh",
                "description": f"{name}.urdf of example-robot-data 6.0.0 as a modified D-H table, link "
                "inertials re-expressed in the D-H frames (tests/data/urdf/twins.py)",
                "convention": "modified", **desc}
        worst, samples = compare(name, desc)
        with open(os.path.join(ROOT, "robots", f"{name}_urdf_dh.toml"), "w") as f:
            f.write(toml(name, desc, worst, friction))
        data = {
            "robot": f"{name}_dh",
            "generator": f"tests/data/urdf/twins.py with pinocchio {pin.__version__}",
            "seed": make.SEED,
            "n": len(table),
            "units": "SI: m, rad, kg, kg m^2, s; tau in N m",
            "notes": f"the samples of {name}.json (make.py), computed from the D-H model of `description`; "
            f"D-H model against the URDF model: {worst:.1e} (scaled); no ee_pose or jacobian",
            "description": desc,
            "samples": samples,
        }
        make.write_json(os.path.join(HERE, f"{name}_dh.json"), data)
        print(f"{name}: D-H twin against the URDF {worst:.1e}: wrote robots/{name}_urdf_dh.toml, "
              f"tests/data/urdf/{name}_dh.json")


if __name__ == "__main__":
    main()

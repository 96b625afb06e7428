#!/usr/bin/env python3
"""Reference data for a 7-joint robot: the Franka Emika Panda arm, without its hand.

Writes, beside this script, `robot.json` (the description) and `data.json` (the description and
20 samples), in the formats of `../reference/robots` and `../reference/data` (see its README),
computed the same way: Pinocchio 4.1.0, the model built joint by
joint from the D-H table. Before writing, it checks:

* the D-H table and the link parameters against a second Pinocchio model read from the URDF they
  come from (example-robot-data 6.0.0, `panda_description/urdf/panda.urdf`, the hand and fingers
  removed): tau, M and the last frame's pose agree on every sample;
* the identities tau = M qdd + h, h = C qd + g, KE = qd^T M qd / 2 and, by central differences,
  Mdot = C + C^T and g = dP/dq.

Usage (Pinocchio from bench/run's virtual environment; the URDF from PyPI):

    pip download --no-deps example-robot-data==6.0.0 -d /tmp/erd
    unzip -q -o /tmp/erd/example_robot_data-6.0.0-*.whl -d /tmp/erd/x
    bench/.venv/bin/python tests/data/panda/make.py \
        /tmp/erd/x/cmeel.prefix/share/example-robot-data/robots/panda_description/urdf/panda.urdf
"""

import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from pinocchio_data import TOLERANCE, identities, quantities, rounded, samples, scaled_error  # noqa: E402

SEED = 20261124
N = 7
GRAVITY = [0.0, 0.0, -9.81]
# Franka's modified D-H table (Craig): row i holds a_{i-1}, alpha_{i-1}, d_i.
DH = [
    # a,      alpha,         d
    (0.0, 0.0, 0.333),
    (0.0, -math.pi / 2, 0.0),
    (0.0, math.pi / 2, 0.316),
    (0.0825, math.pi / 2, 0.0),
    (-0.0825, -math.pi / 2, 0.384),
    (0.0, math.pi / 2, 0.0),
    (0.088, math.pi / 2, 0.0),
]


def links_from_urdf(path):
    """Mass, centre of mass and inertia [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] of panda_link1..7."""
    root = ET.parse(path).getroot()
    links = {l.get("name"): l for l in root.findall("link")}
    out = []
    for i in range(1, N + 1):
        inertial = links[f"panda_link{i}"].find("inertial")
        origin = inertial.find("origin")
        assert [float(x) for x in origin.get("rpy").split()] == [0.0, 0.0, 0.0]
        com = [float(x) for x in origin.get("xyz").split()]
        mass = float(inertial.find("mass").get("value"))
        t = inertial.find("inertia")
        inertia = [float(t.get(k)) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")]
        out.append((mass, com, inertia))
    return out


def description(links):
    joints = []
    for (a, alpha, d), (mass, com, inertia) in zip(DH, links):
        joints.append({
            "type": "revolute", "theta": 0.0, "d": d, "a": a, "alpha": alpha,
            "mass": mass, "com": com, "inertia": inertia,
            "actuator_inertia": 0.0, "spring_stiffness": 0.0, "spring_rest": 0.0,
        })
    return {
        "name": "panda",
        "description": "Franka Emika Panda arm without its hand: Franka's modified D-H table; "
        "link inertials from example-robot-data 6.0.0 panda.urdf (whose link frames are the D-H frames)",
        "convention": "modified",
        "gravity": GRAVITY,
        "joints": joints,
    }


def model_from_dh(desc):
    """One JointModelRZ per joint, placed by Rotx(alpha) Transx(a) Rotz(theta) Transz(d)."""
    model = pin.Model()
    model.gravity = pin.Motion(np.array(desc["gravity"]), np.zeros(3))
    parent = 0
    for i, j in enumerate(desc["joints"]):
        rotx = pin.SE3(pin.utils.rotate("x", j["alpha"]), np.zeros(3))
        transx = pin.SE3(np.eye(3), np.array([j["a"], 0.0, 0.0]))
        rotz = pin.SE3(pin.utils.rotate("z", j["theta"]), np.zeros(3))
        transz = pin.SE3(np.eye(3), np.array([0.0, 0.0, j["d"]]))
        jid = model.addJoint(parent, pin.JointModelRZ(), rotx * transx * rotz * transz, f"joint{i + 1}")
        ixx, iyy, izz, ixy, ixz, iyz = j["inertia"]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        model.appendBodyToJoint(jid, pin.Inertia(j["mass"], np.array(j["com"]), inertia), pin.SE3.Identity())
        model.addFrame(pin.Frame(f"link_{i + 1}", jid, 0, pin.SE3.Identity(), pin.FrameType.OP_FRAME))
        parent = jid
    return model


def model_from_urdf(path):
    """The URDF's arm alone: the hand, the fingers and their joints removed."""
    root = ET.parse(path).getroot()
    arm = {f"panda_link{i}" for i in range(N + 1)}
    for l in list(root.findall("link")):
        if l.get("name") not in arm:
            root.remove(l)
    for j in list(root.findall("joint")):
        if j.find("child").get("link") not in arm:
            root.remove(j)
    model = pin.buildModelFromXML(ET.tostring(root, encoding="unicode"))
    model.gravity = pin.Motion(np.array(GRAVITY), np.zeros(3))
    assert model.nq == N, model.nq
    return model


def check_identities(model, q, qd, qdd, x):
    worst = identities(x, qd, qdd)
    # Central differences: Mdot = C + C^T, g = dP/dq.
    eps = 1e-6
    data = model.createData()
    crba = lambda q: (lambda M: np.triu(M) + np.triu(M, 1).T)(pin.crba(model, data, q).copy())
    mdot = (crba(q + eps * qd) - crba(q - eps * qd)) / (2 * eps)
    fd = scaled_error(mdot, x["C"] + x["C"].T)
    grad = np.array([
        (pin.computePotentialEnergy(model, data, q + eps * e) - pin.computePotentialEnergy(model, data, q - eps * e))
        / (2 * eps) for e in np.eye(model.nv)])
    fd = max(fd, scaled_error(grad, x["g"]))
    assert fd < 1e-7, f"finite differences: {fd:e}"
    return worst, fd


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    urdf = sys.argv[1]
    desc = description(links_from_urdf(urdf))
    model = model_from_dh(desc)
    urdf_model = model_from_urdf(urdf)
    urdf_data = urdf_model.createData()
    urdf_frame = urdf_model.getFrameId("panda_link7")
    out, worst_urdf, worst_id, worst_fd = [], 0.0, 0.0, 0.0
    for q, qd, qdd in samples(N, np.random.default_rng(SEED)):
        x = quantities(model, f"link_{N}", q, qd, qdd)
        # The same robot read from the URDF.
        worst_urdf = max(worst_urdf, scaled_error(pin.rnea(urdf_model, urdf_data, q, qd, qdd), x["tau"]))
        M = pin.crba(urdf_model, urdf_data, q)
        worst_urdf = max(worst_urdf, scaled_error(np.triu(M) + np.triu(M, 1).T, x["M"]))
        pin.framesForwardKinematics(urdf_model, urdf_data, q)
        worst_urdf = max(worst_urdf, scaled_error(urdf_data.oMf[urdf_frame].homogeneous, x["ee_pose"]))
        ident, fd = check_identities(model, q, qd, qdd, x)
        worst_id, worst_fd = max(worst_id, ident), max(worst_fd, fd)
        sample = {"q": q, "qd": qd, "qdd": qdd}
        sample.update(x)
        out.append({k: rounded(v) for k, v in sample.items()})
    assert worst_urdf < TOLERANCE, f"D-H model against the URDF: {worst_urdf:e}"
    data = {
        "robot": "panda",
        "generator": f"tests/data/panda/make.py with pinocchio {pin.__version__}",
        "seed": SEED,
        "n": N,
        "units": "SI: m, rad, kg, kg m^2, s; tau in N m",
        "notes": "tau = M qdd + h; h = C qd + g; jacobian rows = [v; w] of frame n in base axes; "
        "numbers rounded to 15 significant digits; "
        f"D-H model against the URDF model: {worst_urdf:.1e}; identities {worst_id:.1e}; "
        f"finite differences {worst_fd:.1e} (scaled errors)",
        "description": desc,
        "samples": out,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    for name, value in (("robot.json", desc), ("data.json", data)):
        with open(os.path.join(here, name), "w") as f:
            json.dump(value, f, indent=1)
            f.write("\n")
    print(f"wrote {here}/robot.json and data.json: D-H against URDF {worst_urdf:.1e}, "
          f"identities {worst_id:.1e}, finite differences {worst_fd:.1e}")


if __name__ == "__main__":
    main()

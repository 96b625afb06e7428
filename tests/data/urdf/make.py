#!/usr/bin/env python3
"""Reference data for the URDF robots of `robots/urdf/`, from Pinocchio's own URDF loader.

For each robot of ROBOTS (file, base link, tip link) this script

1. reads the URDF and keeps the serial chain from the base link to the tip link as the project's
   URDF front end takes it: the links on that path, and every link fixed to one of them
   (Pinocchio merges a fixed joint's child into its parent's body, as the front end does). What
   hangs off by a moving joint (the Panda's fingers, the Z1's and SO-101's jaws) and the links
   above the base are dropped; the Panda's hand and the Z1's gripper stator, fixed to the tip,
   stay;
2. snaps every `rpy` angle within SNAP_TOLERANCE (1e-5 rad) of a multiple of pi/2 to that
   multiple, exactly as the project's front end does (URDFs write 1.57079632679, 1.5708,
   3.14159 or 1e-15), and records each change;
3. loads the snapped chain with `pin.buildModelFromXML` (the text of `buildModelFromUrdf`'s
   file) with gravity [0, 0, -9.81] in the base frame, and computes 20 samples of tau (rnea),
   M (crba, symmetrised), C (computeCoriolisMatrix), h (nonLinearEffects), g
   (computeGeneralizedGravity), both energies, the tip's pose and its geometric Jacobian;
4. checks tau = M qdd + h, h = C qd + g, KE = qd^T M qd / 2 and, by central differences,
   Mdot = C + C^T and g = dP/dq;
5. measures what the snapping changed: the same quantities from the unsnapped chain, the largest
   scaled difference (max|a - b| / max(1, max|b|)) per quantity;
6. writes `<robot>.json` beside this script: the samples in the format of
   `../reference/data/` (see its README), the chain (base, tip, joint names), the joints'
   `<dynamics damping friction>` as Pinocchio read them (`model.damping`, `model.friction`;
   Pinocchio's tau does not include them), the friction torque of each sample, the Pinocchio
   model itself (joint types, placements and inertias, for `bench/pinocchio/bench.cpp`, which
   cannot link Pinocchio's URDF parser header-only) and the provenance.

Usage, from the repository root (Pinocchio 4.1.0, the `pin` wheel):

    bench/.venv/bin/python tests/data/urdf/make.py
"""

import copy
import hashlib
import importlib.util
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

# name: (file in robots/urdf/, base link, tip link)
ROBOTS = {
    "ur5": ("ur5.urdf", "base_link", "tool0"),
    "ur10": ("ur10.urdf", "base_link", "tool0"),
    "panda": ("panda.urdf", "panda_link0", "panda_link8"),
    "z1": ("z1.urdf", "link00", "link06"),
    "so101": ("so101.urdf", "base_link", "gripper_link"),
}
SEED = 20261125
GRAVITY = [0.0, 0.0, -9.81]
SNAP_TOLERANCE = 1e-5
TOLERANCE = 1e-12
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))


def module(path, name):
    """A script of the repository, imported by path."""
    spec = importlib.util.spec_from_file_location(name, path)
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


# The D-H Panda's script: its identity checks (with finite differences) serve here too.
panda = module(os.path.join(ROOT, "tests", "data", "panda", "make.py"), "panda_make")
check_identities = panda.check_identities
sys.path.insert(0, os.path.join(ROOT, "tests", "data"))
from pinocchio_data import quantities, rounded, samples, scaled_error, symmetric  # noqa: E402


def write_json(path, value):
    with open(path, "w") as f:
        json.dump(value, f, indent=1)
        f.write("\n")


def chain(root, base, tip):
    """The link names from base to tip, following each link's parent joint up from the tip."""
    parent_joint = {j.find("child").get("link"): j for j in root.findall("joint")}
    path, link = [tip], tip
    while link != base:
        if link not in parent_joint:
            sys.exit(f"{tip} does not descend from {base}")
        link = parent_joint[link].find("parent").get("link")
        path.append(link)
    return path[::-1]


def rigid_chain(root, base, tip):
    """The links that move with the chain from base to tip, as the project's URDF front end takes
    them: the path's links and every link fixed to one of them (a fixed joint's child is part of
    its parent's rigid body); below a joint that moves off the path, nothing (such a joint may
    only hang off the tip's rigid body: before the tip the chain would branch)."""
    path = chain(root, base, tip)
    children = {}
    for j in root.findall("joint"):
        children.setdefault(j.find("parent").get("link"), []).append(j)
    keep, todo = set(), [base]
    while todo:
        link = todo.pop()
        keep.add(link)
        for j in children.get(link, []):
            child = j.find("child").get("link")
            if child in path or j.get("type") == "fixed":
                todo.append(child)
            else:
                assert link not in path[:-1], f"{j.get('name')} branches off the chain at {link}"
    return path, keep


def prune(root, links):
    """Removes every link not in `links` and every joint not between two of them."""
    for l in list(root.findall("link")):
        if l.get("name") not in links:
            root.remove(l)
    for j in list(root.findall("joint")):
        if j.find("parent").get("link") not in links or j.find("child").get("link") not in links:
            root.remove(j)


def snap(root):
    """Snaps the rpy angles (of joints and inertials) near a multiple of pi/2 in place; returns
    the changes made."""
    changes = []
    for element in [e for e in root.iter() if e.tag in ("joint", "inertial")]:
        origin = element.find("origin")
        if origin is None or origin.get("rpy") is None:
            continue
        angles = [float(x) for x in origin.get("rpy").split()]
        snapped = []
        for x in angles:
            k = round(x / (math.pi / 2))
            exact = k * (math.pi / 2)
            snapped.append(exact if abs(x - exact) <= SNAP_TOLERANCE else x)
        if snapped != angles:
            owner = f"{element.tag} {element.get('name')}" if element.get("name") else element.tag
            changes.append({"element": owner, "rpy": angles, "snapped": snapped})
            origin.set("rpy", " ".join(repr(x) for x in snapped))
    return changes


def owners(root):
    """Gives each <inertial> the name of its link, so that snap() can name it."""
    for l in root.findall("link"):
        inertial = l.find("inertial")
        if inertial is not None:
            inertial.set("name", l.get("name"))


def load(root):
    xml = ET.tostring(root, encoding="unicode")
    model = pin.buildModelFromXML(xml)
    model.gravity = pin.Motion(np.array(GRAVITY), np.zeros(3))
    return model


def friction_torque(model, qd):
    """Viscous damping qd plus Coulomb friction sign(qd), sign(0) = 0."""
    return np.asarray(model.damping) * qd + np.asarray(model.friction) * np.sign(qd)


def pinocchio_model(model):
    """The model as the URDF loader built it: enough to rebuild it joint by joint."""
    joints = []
    for i in range(1, model.njoints):
        joint, inertia, placement = model.joints[i], model.inertias[i], model.jointPlacements[i]
        entry = {"name": model.names[i], "parent": int(model.parents[i]), "type": joint.shortname(),
                 "rotation": placement.rotation.tolist(), "translation": placement.translation.tolist(),
                 "mass": inertia.mass, "lever": inertia.lever.tolist(), "inertia": inertia.inertia.tolist()}
        if "Unaligned" in joint.shortname():
            entry["axis"] = joint.extract().axis.tolist()
        joints.append(entry)
    return {"gravity": GRAVITY, "joints": joints}


def rebuild(description):
    """The model of pinocchio_model(), built again as bench/pinocchio/bench.cpp builds it."""
    model = pin.Model()
    model.gravity = pin.Motion(np.array(description["gravity"]), np.zeros(3))
    kinds = {"JointModelRX": pin.JointModelRX, "JointModelRY": pin.JointModelRY,
             "JointModelRZ": pin.JointModelRZ, "JointModelPX": pin.JointModelPX,
             "JointModelPY": pin.JointModelPY, "JointModelPZ": pin.JointModelPZ}
    for j in description["joints"]:
        if j["type"] == "JointModelRevoluteUnaligned":
            kind = pin.JointModelRevoluteUnaligned(np.array(j["axis"]))
        elif j["type"] == "JointModelPrismaticUnaligned":
            kind = pin.JointModelPrismaticUnaligned(np.array(j["axis"]))
        else:
            kind = kinds[j["type"]]()
        placement = pin.SE3(np.array(j["rotation"]), np.array(j["translation"]))
        jid = model.addJoint(j["parent"], kind, placement, j["name"])
        inertia = pin.Inertia(j["mass"], np.array(j["lever"]), np.array(j["inertia"]))
        model.appendBodyToJoint(jid, inertia, pin.SE3.Identity())
    return model


def make(name, file, base, tip):
    path = os.path.join(ROOT, "robots", "urdf", file)
    with open(path, "rb") as f:
        sha256 = hashlib.sha256(f.read()).hexdigest()
    raw = ET.parse(path).getroot()
    links, rigid = rigid_chain(raw, base, tip)
    prune(raw, rigid)
    owners(raw)
    snapped = copy.deepcopy(raw)
    changes = snap(snapped)
    model, unsnapped = load(snapped), load(raw)
    n = model.nv
    assert model.nq == n, f"{name}: nq {model.nq} != nv {n} (a continuous joint?)"
    twin = rebuild(pinocchio_model(model))
    worst_id = worst_fd = worst_rebuild = 0.0
    change = {k: 0.0 for k in ("tau", "M", "C", "g", "kinetic_energy", "potential_energy")}
    out = []
    for q, qd, qdd in samples(model.nv, np.random.default_rng(SEED)):
        x = quantities(model, tip, q, qd, qdd)
        ident, fd = check_identities(model, q, qd, qdd, x)
        worst_id, worst_fd = max(worst_id, ident), max(worst_fd, fd)
        y = quantities(unsnapped, tip, q, qd, qdd)
        for k in change:
            change[k] = max(change[k], scaled_error(y[k], x[k]))
        data = twin.createData()
        worst_rebuild = max(worst_rebuild, scaled_error(pin.rnea(twin, data, q, qd, qdd), x["tau"]),
                            scaled_error(symmetric(pin.crba(twin, data, q)), x["M"]))
        sample = {"q": q, "qd": qd, "qdd": qdd}
        sample.update(x)
        sample["friction"] = friction_torque(model, qd)
        out.append({k: rounded(v) for k, v in sample.items()})
    assert worst_rebuild < TOLERANCE, f"{name}: the rebuilt model differs by {worst_rebuild:e}"
    joints = [model.names[i] for i in range(1, model.njoints)]
    types = [model.joints[i].shortname() for i in range(1, model.njoints)]
    return {
        "robot": f"{name}_urdf",
        "generator": f"tests/data/urdf/make.py with pinocchio {pin.__version__} (buildModelFromXML)",
        "urdf": f"robots/urdf/{file}",
        "urdf_sha256": sha256,
        "base": base,
        "tip": tip,
        "links": links,
        "fixed_to_the_chain": sorted(rigid - set(links)),
        "joints": joints,
        "joint_types": types,
        "damping": rounded(np.asarray(model.damping)),
        "friction": rounded(np.asarray(model.friction)),
        "seed": SEED,
        "n": n,
        "units": "SI: m, rad, kg, kg m^2, s; tau in N m",
        "notes": "tau = M qdd + h (Pinocchio's rnea: no joint friction); h = C qd + g; "
        "friction = damping * qd + friction * sign(qd) (sign(0) = 0), the URDF <dynamics> "
        "per joint, not in tau; jacobian rows = [v; w] of the tip in base axes; "
        "numbers rounded to 15 significant digits; "
        f"identities {worst_id:.1e}; finite differences {worst_fd:.1e} (scaled errors)",
        "snapping": {
            "tolerance": SNAP_TOLERANCE,
            "changes": changes,
            "largest_change": {k: float(f"{v:.2e}") for k, v in change.items()},
            "measure": "max over the samples of max|unsnapped - snapped| / max(1, max|snapped|)",
        },
        "pinocchio_model": pinocchio_model(model),
        "samples": out,
    }, (worst_id, worst_fd, change)


def main():
    names = sys.argv[1:] or list(ROBOTS)
    for name in names:
        data, (ident, fd, change) = make(name, *ROBOTS[name])
        write_json(os.path.join(HERE, f"{name}.json"), data)
        shown = ", ".join(f"{k} {v:.1e}" for k, v in change.items())
        print(f"{name}: n = {data['n']}, {data['base']} -> {data['tip']}, "
              f"{len(data['snapping']['changes'])} origins snapped (change: {shown}); "
              f"identities {ident:.1e}, finite differences {fd:.1e}")


if __name__ == "__main__":
    main()

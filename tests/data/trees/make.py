#!/usr/bin/env python3
"""Reference data for robots that branch (kinematic trees) and for mimic joints, from Pinocchio's
own URDF loader, for the tests of the tree front end (issue 41).

For each robot of ROBOTS (file, tips, other frames) this script

1. reads the URDF and walks its tree from the root link (the base, fixed): every moving joint of
   every branch, in the order the project's front end takes them: depth first, a link's child
   joints in the file's order of their `<joint>` elements, fixed joints walked through (their
   child is part of the parent's rigid body). Each joint's parent is its nearest moving
   ancestor (None: the base). It checks that Pinocchio's order is that same walk with a link's
   child joints sorted by name (urdfdom keeps joints in a name-sorted map), and writes the data
   in the front end's order, Pinocchio's order recorded beside it;
2. snaps every `rpy` within 1e-5 rad of a multiple of pi/2 as `../urdf/make.py` does;
3. loads the snapped file with `pin.buildModelFromXML` (gravity [0, 0, -9.81] in the base frame)
   and rebuilds the model joint by joint in the front end's order (`pinocchio_model`, for
   `bench/pinocchio/bench.cpp`), checking both agree;
4. computes 20 samples (the seed scheme of `../pinocchio_data.py`; a joint with URDF limits
   has its q in [-pi, pi] mapped linearly onto [lower, upper], sample #0 stays at q = 0) of tau,
   M, C, h, g, both energies, each tip's pose and Jacobian (LOCAL_WORLD_ALIGNED), the friction
   torque of the `<dynamics>` elements, and forward dynamics: qdd = aba(q, qd, tau_fd) for a
   torque tau_fd drawn uniformly in [-20, 20] (the hand: [-0.05, 0.05]; seed + 1);
5. checks tau = M qdd + h, h = C qd + g, KE = qd^T M qd / 2, by central differences Mdot = C + C^T,
   g = dP/dq and each tip's J qd = its pose's rate, aba(q, qd, tau) = qdd, and that M(i, j) and C(i, j) are exactly 0 whenever
   neither of joints i, j is an ancestor of the other;
6. for a robot with `<mimic>` joints writes two files: `<robot>.json`, the reduced coordinates
   (every joint but the mimicking ones; see mimic.py), and `<robot>_no_mimic.json`, every joint
   free. The reduced data are projections of the full model's, cross-checked against
   Pinocchio's own mimic model (`buildModelFromXML(..., mimic=True)`).

Usage, from the repository root (Pinocchio 4.1.0, the `pin` wheel):

    bench/.venv/bin/python tests/data/trees/make.py [robot ...]
"""

import copy
import hashlib
import importlib.metadata
import importlib.util
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "data"))
sys.path.insert(0, HERE)
from pinocchio_data import (TOLERANCE, central_differences, dynamics, frame_kinematics,  # noqa: E402
                            identities, rounded, samples, scaled_error)
import mimic  # noqa: E402
from urdf_tree import Tree, pinocchio_rule_order  # noqa: E402

# name: (URDF from the repository root, tips: one link on each leaf body of the moving tree,
#        other frames whose pose and Jacobian are wanted too, the bound of the forward dynamics'
#        torques: 20 N m, but the hand's 0.05 N m, the size of its gravity torques)
ROBOTS = {
    "baxter": ("robots/urdf/trees/baxter.urdf",
               ["head", "l_gripper_l_finger_tip", "l_gripper_r_finger_tip",
                "r_gripper_l_finger_tip", "r_gripper_r_finger_tip"],
               ["left_gripper", "right_gripper"], 20.0),
    "allegro_right_hand": ("robots/urdf/trees/allegro_right_hand.urdf",
                           ["link_3.0_tip", "link_7.0_tip", "link_11.0_tip", "link_15.0_tip"], [], 0.05),
    "panda_fingers": ("robots/urdf/panda.urdf", ["panda_leftfinger", "panda_rightfinger"],
                      ["panda_hand_tcp"], 20.0),
}
SEED = 20261125  # as ../urdf/
GRAVITY = [0.0, 0.0, -9.81]
QUANTITIES = ("tau", "M", "C", "h", "g", "kinetic_energy", "potential_energy")


def module(path, name):
    """A script of the repository, imported by path."""
    spec = importlib.util.spec_from_file_location(name, path)
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


# The serial URDF data's script: its snapping, model record and rebuild serve here too.
urdf = module(os.path.join(ROOT, "tests", "data", "urdf", "make.py"), "urdf_make")


def load(root, with_mimic=False):
    model = pin.buildModelFromXML(ET.tostring(root, encoding="unicode"), with_mimic)
    model.gravity = pin.Motion(np.array(GRAVITY), np.zeros(3))
    return model


class Full:
    """Pinocchio's quantities of a URDF model in the front end's joint order: `perm[i]` is the
    Pinocchio velocity index of the front end's joint i."""

    def __init__(self, model, names, frames):
        self.model, self.frames = model, frames
        self.perm = np.array([model.idx_vs[model.getJointId(n)] for n in names])
        assert all(model.nvs[model.getJointId(n)] == 1 for n in names)
        assert model.nq == model.nv == len(names), f"nq {model.nq}, nv {model.nv}, {len(names)} joints"

    def pin(self, v):
        out = np.empty(len(self.perm))
        out[self.perm] = v
        return out

    def quantities(self, q, qd, qdd):
        x = dynamics(self.model, self.pin(q), self.pin(qd), self.pin(qdd))
        p = self.perm
        x = {k: (v if np.ndim(v) == 0 else v[np.ix_(p, p)] if np.ndim(v) == 2 else v[p]) for k, v in x.items()}
        kin = frame_kinematics(self.model, self.frames, self.pin(q))
        x["tips"] = {f: dict(pose=k["pose"], jacobian=k["jacobian"][:, p]) for f, k in kin.items()}
        return x

    def mass(self, q):
        return dynamics(self.model, self.pin(q), 0 * q, 0 * q)["M"][np.ix_(self.perm, self.perm)]

    def potential(self, q):
        return pin.computePotentialEnergy(self.model, self.model.createData(), self.pin(q))

    def forward(self, q, qd, tau):
        data = self.model.createData()
        return pin.aba(self.model, data, self.pin(q), self.pin(qd), self.pin(tau))[self.perm]

    def friction_coefficients(self):
        """Each joint's `<dynamics damping friction>` as Pinocchio read them."""
        return tuple(np.asarray(a)[self.perm] for a in (self.model.damping, self.model.friction))

    def friction(self, qd):
        damping, friction = self.friction_coefficients()
        return damping * qd + friction * np.sign(qd)

    def structure(self, tree):
        return tree.structure()


def twin(model, names, frames):
    """The loaded model rebuilt joint by joint in the front end's order, with the tips' frames;
    and its record (`pinocchio_model`, parents as indices of that order, 0 = the base)."""
    record = urdf.pinocchio_model(model)
    by_name = {j["name"]: j for j in record["joints"]}
    new_id = {model.getJointId(n): k + 1 for k, n in enumerate(names)}
    new_id[0] = 0
    joints = []
    for n in names:
        j = dict(by_name[n])
        j["parent"] = new_id[j["parent"]]
        joints.append(j)
    record = {"gravity": record["gravity"], "joints": joints}
    rebuilt = urdf.rebuild(record)
    record["frames"] = []
    for f in frames:
        frame = model.frames[model.getFrameId(f, pin.FrameType.BODY)]
        placement = frame.placement
        rebuilt.addFrame(pin.Frame(f, new_id[frame.parentJoint], placement, pin.FrameType.BODY))
        record["frames"].append({"name": f, "parent": new_id[frame.parentJoint],
                                 "rotation": placement.rotation.tolist(),
                                 "translation": placement.translation.tolist()})
    return rebuilt, record


def check_twin(full, rebuilt, states):
    """The rebuilt model (already in the front end's order) against the loaded one, permuted."""
    worst = 0.0
    for q, qd, qdd in states:
        x = full.quantities(q, qd, qdd)
        y = dynamics(rebuilt, q, qd, qdd)
        kin = frame_kinematics(rebuilt, full.frames, q)
        for k in QUANTITIES:
            worst = max(worst, scaled_error(y[k], x[k]))
        for f in full.frames:
            worst = max(worst, scaled_error(kin[f]["pose"], x["tips"][f]["pose"]),
                        scaled_error(kin[f]["jacobian"], x["tips"][f]["jacobian"]))
    assert worst < TOLERANCE, f"the rebuilt model differs by {worst:e}"
    return worst


def states(n, limits, bound):
    """The 20 states of pinocchio_data.samples; q of a joint with limits mapped from [-pi, pi]
    onto them (but sample #0, all zero), and a torque in [-bound, bound] (drawn with SEED + 1)
    for the forward dynamics."""
    torques = np.random.default_rng(SEED + 1)
    out = []
    for k, (q, qd, qdd) in enumerate(samples(n, np.random.default_rng(SEED))):
        if k > 0:
            q = np.array([x if lim is None else lim[0] + (x + math.pi) / (2 * math.pi) * (lim[1] - lim[0])
                          for x, lim in zip(q, limits)])
        out.append((q, qd, qdd, torques.uniform(-bound, bound, n)))
    return out


def zero_blocks(x, related):
    """M(i, j) and C(i, j) where joints i and j lie on different branches: all must be 0."""
    pairs = [(i, j) for i in range(len(related)) for j in range(i + 1, len(related)) if not related[i][j]]
    largest = max([abs(x[m][i, j]) for m in ("M", "C") for a, b in pairs for i, j in ((a, b), (b, a))],
                  default=0.0)
    assert largest == 0.0, f"M or C nonzero between branches: {largest:e}"
    return len(pairs)


def relative_identities(x, qd, qdd):
    """The identities as pinocchio_data.identities checks them, but relative to each side's
    size (max|a - b| / max|b|): the hand's quantities are far below 1, where the scaled measure
    is an absolute one."""
    pairs = [(x["M"] @ qdd + x["h"], x["tau"]), (x["C"] @ qd + x["g"], x["h"]),
             (0.5 * qd @ x["M"] @ qd, x["kinetic_energy"])]
    return max([float(np.max(np.abs(a - b)) / np.max(np.abs(b))) for a, b in pairs if np.max(np.abs(b)) > 0],
               default=0.0)


def jacobian_differences(system, q, qd, tips):
    """Each tip's Jacobian against its pose's central difference along qd: v = dp/dt and
    [w]x = dR/dt R^T. The worst scaled error."""
    eps, worst = 1e-6, 0.0
    ahead, behind = (system.quantities(q + s * eps * qd, 0 * qd, 0 * qd)["tips"] for s in (1, -1))
    for f, t in tips.items():
        rate = (ahead[f]["pose"] - behind[f]["pose"]) / (2 * eps)
        spin = rate[:3, :3] @ t["pose"][:3, :3].T
        twist = np.concatenate([rate[:3, 3], [spin[2, 1], spin[0, 2], spin[1, 0]]])
        worst = max(worst, scaled_error(t["jacobian"] @ qd, twist))
    assert worst < 1e-7, f"tip Jacobians against finite differences: {worst:e}"
    return worst


def sample_set(system, names, limits, related, bound):
    """The samples of `system` (Full or mimic.Reduced) and the worst residuals of the checks."""
    worst = dict(identities=0.0, identities_relative=0.0, finite_differences=0.0, forward_round_trip=0.0)
    out = []
    for q, qd, qdd, tau_fd in states(len(names), limits, bound):
        x = system.quantities(q, qd, qdd)
        worst["identities"] = max(worst["identities"], identities(x, qd, qdd))
        worst["identities_relative"] = max(worst["identities_relative"], relative_identities(x, qd, qdd))
        fd = central_differences(system.mass, system.potential, q, qd, x["C"], x["g"])
        fd = max(fd, jacobian_differences(system, q, qd, x["tips"]))
        worst["finite_differences"] = max(worst["finite_differences"], fd)
        back = scaled_error(system.forward(q, qd, x["tau"]), qdd)
        assert back < 1e-10, f"forward dynamics round trip {back:e}"
        worst["forward_round_trip"] = max(worst["forward_round_trip"], back)
        pairs = zero_blocks(x, related)
        sample = {"q": q, "qd": qd, "qdd": qdd}
        sample.update({k: x[k] for k in QUANTITIES})
        sample["friction"] = system.friction(qd)
        damping, friction = system.friction_coefficients()
        assert scaled_error(damping * qd + friction * np.sign(qd), sample["friction"]) < TOLERANCE
        sample = {k: rounded(v) for k, v in sample.items()}
        sample["tips"] = {f: {k: rounded(v) for k, v in t.items()} for f, t in x["tips"].items()}
        sample["forward"] = {"tau": rounded(tau_fd), "qdd": rounded(system.forward(q, qd, tau_fd))}
        out.append(sample)
    return out, worst, pairs


def snapping_change(system, unsnapped, limits, bound):
    """The largest scaled change snapping made to each output, over the samples."""
    change = {k: 0.0 for k in QUANTITIES}
    for q, qd, qdd, _ in states(len(limits), limits, bound):
        x, y = system.quantities(q, qd, qdd), unsnapped.quantities(q, qd, qdd)
        for k in change:
            change[k] = max(change[k], scaled_error(y[k], x[k]))
    return {k: float(f"{v:.2e}") for k, v in change.items()}


def provenance(path):
    with open(path, "rb") as f:
        sha256 = hashlib.sha256(f.read()).hexdigest()
    return {
        "generator": f"tests/data/trees/make.py with pinocchio {pin.__version__} (buildModelFromXML)",
        "urdf_source": f"example-robot-data {importlib.metadata.version('example-robot-data')} (PyPI)",
        "urdf_sha256": sha256,
    }


def make(name, file, tips, others, bound):
    path = os.path.join(ROOT, file)
    raw = ET.parse(path).getroot()
    urdf.owners(raw)
    snapped = copy.deepcopy(raw)
    changes = urdf.snap(snapped)
    t = Tree(snapped)
    frames = tips + others
    model = load(snapped)
    pinocchio_order = [model.names[i] for i in range(1, model.njoints)]
    assert pinocchio_order == pinocchio_rule_order(snapped), "Pinocchio's order is not the name-sorted walk"
    full = Full(model, t.names, frames)
    rebuilt, record = twin(model, t.names, frames)
    twin_error = check_twin(full, rebuilt, [s[:3] for s in states(len(t.names), t.limits, bound)])
    tip_records = []
    for f in frames:
        owner = t.body[f]
        leaf = owner is not None and not any(p == owner for p in t.parents)
        assert leaf == (f in tips), f"{name}: {f} is {'' if leaf else 'not '}on a leaf body"
        tip_records.append({"link": f, "joint": None if owner is None else t.names[owner], "leaf": leaf})
    leaves = {i for i in range(len(t.names)) if i not in t.parents}
    assert leaves == {t.body[f] for f in tips} and len(tips) == len(leaves), f"{name}: one tip per leaf body"
    common = {
        "robot": name,
        **provenance(path),
        "urdf": file,
        "base": t.root,
        "order_rule": "depth first from the base link; a link's child joints in the file's order of "
                      "their <joint> elements; fixed joints walked through",
        "pinocchio_order": pinocchio_order,
        "order_matches_pinocchio": pinocchio_order == t.names,
        "tips": tip_records,
        "seed": SEED,
        "forward_torque_bound": bound,
        "units": "SI: m, rad, kg, kg m^2, s; tau in N m (N on a prismatic joint)",
        "snapping": {"tolerance": urdf.SNAP_TOLERANCE, "changes": changes},
    }
    unsnapped = Full(load(raw), t.names, frames)
    files = {}
    systems = [("", full, unsnapped)]
    if t.mimic:
        reduced = mimic.Reduced(full, t)
        systems = [("", reduced, mimic.Reduced(unsnapped, t)), ("_no_mimic", full, unsnapped)]
    for suffix, system, unsnapped_system in systems:
        names, parents, limits, related = system.structure(t)
        out, worst, pairs = sample_set(system, names, limits, related, bound)
        data = dict(common)
        data["robot"] = name + suffix
        data.update({"n": len(names), "joints": names, "parents": parents,
                     "joint_types": [t.types[t.names.index(n)] for n in names],
                     "limits": [None if lim is None else list(lim) for lim in limits]})
        data["damping"], data["friction"] = (rounded(a) for a in system.friction_coefficients())
        if system is full:
            data["pinocchio_model"] = record
        else:
            data.update(system.record(t, load(snapped, True), states(len(names), limits, bound)))
        data["zero_blocks_checked"] = {
            "rule": "M(i, j) = C(i, j) = 0 exactly, in every sample, for every pair of joints (for "
                    "reduced coordinates: of the joints each moves) neither of which is an ancestor "
                    "of the other", "pairs": pairs, "matrices": ["M", "C"], "largest": 0.0}
        data["residuals"] = {k: float(f"{v:.1e}") for k, v in worst.items()}
        data["residuals"]["rebuilt_model"] = float(f"{twin_error:.1e}")
        data["snapping"] = dict(data["snapping"], largest_change=snapping_change(
            system, unsnapped_system, limits, bound))
        data["notes"] = NOTES + (REDUCED_NOTES if system is not full else "")
        data["samples"] = out
        files[name + suffix] = data
    return files


def write_json(path, value):
    """As the other data (indent 1), but a row of numbers on one line (a third smaller)."""
    text = json.dumps(value, indent=1)
    row = re.compile(r"\[\s+([-+0-9.eE,\s]+?)\s+\]")
    text = row.sub(lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)
    with open(path, "w") as f:
        f.write(text + "\n")


NOTES = ("tau = M qdd + h (Pinocchio's rnea: no joint friction); h = C qd + g; friction = "
         "damping * qd + friction * sign(qd) per joint (sign(0) = 0), not in tau; tips: pose "
         "(4x4 in the base frame) and Jacobian (rows [v; w] in base axes) per link; forward: "
         "qdd = M^-1 (tau - h) for the torque given (Pinocchio's aba); numbers rounded to 15 "
         "significant digits; residuals are scaled errors max|a - b| / max(1, max|b|)")
REDUCED_NOTES = ("; reduced coordinates (mimic joints): every quantity is the full model's "
                 "projected with G (see `reduction`), forward dynamics by solving M qdd = tau - h "
                 "(Pinocchio 4.1's aba refuses mimic joints)")


def main():
    names = sys.argv[1:] or list(ROBOTS)
    for name in names:
        for out, data in make(name, *ROBOTS[name]).items():
            write_json(os.path.join(HERE, f"{out}.json"), data)
            r = data["residuals"]
            mimics = data.get("mimic_cross_check")
            print(f"{out}: n = {data['n']}, order {'=' if data['order_matches_pinocchio'] else '!='} "
                  f"Pinocchio's, {data['zero_blocks_checked']['pairs']} zero pairs, identities "
                  f"{r['identities']:.1e} (relative {r['identities_relative']:.1e}), finite differences "
                  f"{r['finite_differences']:.1e}, forward round trip {r['forward_round_trip']:.1e}, "
                  f"rebuilt {r['rebuilt_model']:.1e}" + (f", Pinocchio's mimic model {mimics['largest']:.1e}"
                                                        f" (but C)" if mimics else ""))


if __name__ == "__main__":
    main()

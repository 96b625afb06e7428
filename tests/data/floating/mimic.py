"""Mimic joints on a free-flying base (issue 43, helper floatmimic), for `make.py`: PAL's Talos
with its grippers (`talos_full_v2.urdf`, 44 moving joints of which 12 follow a gripper joint),
written to `<name>_mimic.json`.

The mimicking joint m follows q_m = k q_j + o (URDF `multiplier` k, `offset` o) and is not a
coordinate: the coordinates are the base's six, then every joint but the mimic ones in the front
end's order. With G the (n_full x n_red) map of the joints and S = diag(1_6, G):
q_full = [q_base, G q_joints + o], v_full = S v, a_full = S a, and

    M = S^T M_full S,  h = S^T h_full,  tau = S^T (rnea_full + friction_full(S v)),  g = S^T g_full,
    a_fd = M^-1 (tau_in - h - S^T friction_full(S v)),  M_inv = M^-1,
    J = J_full S (frames, centre of mass, A_G),  dJ v = that of the full model at (q_full, S v),
    dtau/dq = S^T dtau_full/dq S (along the tangent, S constant), dtau/dv = S^T dtau_full/dv S
    (+ S^T diag(0_6, damping) S), da/dx = -M^-1 dtau/dx at a = a_fd, da/dtau = M^-1,

every full quantity Pinocchio 4.1's, its URDF loaded with `JointModelFreeFlyer` and every joint
free, its rpy angles near a quarter turn snapped as the front end reads them (`snapped_model`;
`snapping_change` records what that moves). Pinocchio's own mimic joints cannot
load this file (`buildModelFromUrdf(.., mimic=True)`: "The parent joint of the mimic joint is
not in the kinematic tree": its parser takes a link's child joints by name, and the fingertips
come before `gripper_left_joint`), so the cross-check against its `JointModelMimic` builds the
mimic model from the full one with `transformJointIntoMimic` and compares crba, rnea,
nonLinearEffects, computeGeneralizedGravity and the frames' Jacobians (`mimic_cross_check`).
"""

import hashlib
import importlib.metadata
import os

import numpy as np
import pinocchio as pin

import make
from make import HERE, ROOT, SAMPLES, SEED, TOLERANCE, file_order, joint_friction, scaled, symmetric, write_json

# name: URDF from the repository root, the frames of the kinematics.
MIMIC = {"talos_full_v2": ("robots/urdf/floating/talos_full_v2.urdf",
                           ["left_sole_link", "gripper_left_fingertip_3_link", "gripper_right_fingertip_1_link"])}


# The front end takes an angle within 1e-5 rad of a multiple of pi/2 as that quarter turn
# (`tests/data/urdf/make.py`'s `snap`, the same rule).
SNAP_TOLERANCE = 1e-5


def snapped_model(path):
    """The full model of the URDF at `path` with its rpy angles (of joints and inertials) near a
    multiple of pi/2 snapped, as the front end reads them (Talos's `1.57079632679`, 4.9e-12
    from pi/2, turns its gripper's frames by 1e-11 otherwise); and the number of origins
    snapped."""
    import math
    import xml.etree.ElementTree as ET
    root = ET.parse(path).getroot()
    changed = 0
    for element in [e for e in root.iter() if e.tag in ("joint", "inertial")]:
        origin = element.find("origin")
        if origin is None or origin.get("rpy") is None:
            continue
        angles = [float(x) for x in origin.get("rpy").split()]
        snapped = [k * (math.pi / 2) if abs(x - k * (math.pi / 2)) <= SNAP_TOLERANCE else x
                   for x, k in ((x, round(x / (math.pi / 2))) for x in angles)]
        if snapped != angles:
            changed += 1
            origin.set("rpy", " ".join(repr(x) for x in snapped))
    xml = ET.tostring(root, encoding="unicode")
    return pin.buildModelFromXML(xml, pin.JointModelFreeFlyer()), changed


def mimic_rules(path, order):
    """Per joint of the file's `order` that has `<mimic>`: (the joint it follows, k, o)."""
    import xml.etree.ElementTree as ET
    rules = {}
    for j in ET.parse(path).getroot().findall("joint"):
        m = j.find("mimic")
        if m is not None and j.get("name") in order:
            rules[j.get("name")] = (m.get("joint"), float(m.get("multiplier", "1")), float(m.get("offset", "0")))
    return rules


class Reduction:
    """The map S from the coordinates (file order, mimic joints left out) to Pinocchio's full
    model (its own joint order), and back."""

    def __init__(self, model, path):
        _, order = file_order(path)
        names = list(model.names)[2:]
        self.rules = mimic_rules(path, order)
        self.coordinates = [j for j in order if j not in self.rules]
        column = {j: c for c, j in enumerate(self.coordinates)}
        n_red = len(self.coordinates)
        self.S = np.zeros((model.nv, 6 + n_red))
        self.S[:6, :6] = np.eye(6)
        self.offset = np.zeros(model.nq)
        for j in order:
            row = model.idx_vs[model.getJointId(j)]
            follows, k, o = self.rules.get(j, (j, 1.0, 0.0))
            self.S[row, 6 + column[follows]] = k
            self.offset[model.idx_qs[model.getJointId(j)]] = o
        assert sorted(names) == sorted(order)
        self.nq, self.nv = 7 + n_red, 6 + n_red

    def q_full(self, q):
        """The full model's configuration of the coordinates' q: the base's 7 as they are."""
        out = np.zeros(len(self.offset))
        out[:7] = q[:7]
        out[7:] = self.S[6:, 6:] @ q[7:] + self.offset[7:]
        return out

    def sample(self, rng, k):
        """State k in the coordinates, as `make.sample` draws a robot's."""
        if k == 0:
            q = np.zeros(self.nq)
            q[6] = 1.0
            return q, np.zeros(self.nv), np.zeros(self.nv)
        quaternion = rng.normal(size=4)
        quaternion /= np.linalg.norm(quaternion)
        q = np.concatenate([rng.uniform(-1, 1, 3), quaternion, rng.uniform(-np.pi, np.pi, self.nv - 6)])
        return q, rng.uniform(-2, 2, self.nv), rng.uniform(-2, 2, self.nv)


def dynamics(model, data, r, q, v, a, tau_in):
    """M, h, tau, g, the friction, a_fd and M^-1 in the coordinates."""
    S = r.S
    qf, vf, af = r.q_full(q), S @ v, S @ a
    m_full = symmetric(pin.crba(model, data, qf).copy())
    friction_full = joint_friction(vf, model.damping, model.friction)
    m = S.T @ m_full @ S
    h = S.T @ pin.nonLinearEffects(model, data, qf, vf)
    tau = S.T @ (pin.rnea(model, data, qf, vf, af) + friction_full)
    g = S.T @ pin.computeGeneralizedGravity(model, data, qf)
    friction = S.T @ friction_full
    assert scaled(m @ a + h + friction, tau) < TOLERANCE
    m_inv = np.linalg.inv(m)
    a_fd = np.linalg.solve(m, tau_in - h - friction)
    return {"q": q.tolist(), "v": v.tolist(), "a": a.tolist(), "M": m.tolist(), "h": h.tolist(),
            "tau": tau.tolist(), "g": g.tolist(), "friction": friction.tolist(), "tau_in": tau_in.tolist(),
            "a_fd": a_fd.tolist(), "M_inv": symmetric(m_inv).tolist()}, (qf, vf, m, m_inv, a_fd)


def kinematics(model, data, r, frames, qf, vf):
    """Centre of mass, its Jacobian, A_G, dA_G v and each frame's pose, Jacobian and classical
    dJ v in LOCAL and LOCAL_WORLD_ALIGNED, the Jacobians times S."""
    S = r.S
    out = {"com": pin.centerOfMass(model, data, qf).tolist(),
           "Jcom": (pin.jacobianCenterOfMass(model, data, qf) @ S).tolist(),
           "Ag": (pin.computeCentroidalMap(model, data, qf) @ S).tolist(),
           "dAg_v": (pin.computeCentroidalMapTimeVariation(model, data, qf, vf) @ vf).tolist(), "frames": {}}
    pin.forwardKinematics(model, data, qf, vf, np.zeros(model.nv))
    pin.updateFramePlacements(model, data)
    pin.computeJointJacobians(model, data, qf)
    for frame in frames:
        i = model.getFrameId(frame)
        assert i < len(model.frames), frame
        entry = {"rotation": data.oMf[i].rotation.tolist(), "translation": data.oMf[i].translation.tolist()}
        for key, ref in [("local", pin.LOCAL), ("world_aligned", pin.LOCAL_WORLD_ALIGNED)]:
            jac = pin.getFrameJacobian(model, data, i, ref)
            assert scaled(jac @ vf, pin.getFrameVelocity(model, data, i, ref).vector) < TOLERANCE
            entry["J_" + key] = (jac @ S).tolist()
            entry["dJv_" + key] = pin.getFrameClassicalAcceleration(model, data, i, ref).vector.tolist()
        out["frames"][frame] = entry
    return out


def derivatives(model, data, r, qf, vf, af, m_inv, a_fd):
    """dtau/dq, dtau/dv at (q, v, a); a_fd's da/dq, da/dv, da/dtau, all in the coordinates."""
    S = r.S
    damping = np.diag(np.concatenate([np.zeros(6), model.damping[6:]]))
    dq, dv, _ = pin.computeRNEADerivatives(model, data, qf, vf, af)
    out = {"dtau_dq": S.T @ dq @ S, "dtau_dv": S.T @ (dv + damping) @ S}
    dq, dv, _ = pin.computeRNEADerivatives(model, data, qf, vf, S @ a_fd)
    out.update({"ddq_dq": -m_inv @ S.T @ dq @ S, "ddq_dv": -m_inv @ S.T @ (dv + damping) @ S,
                "ddq_dtau": symmetric(m_inv)})
    check_derivatives(model, data, r, (qf, vf, af), out, a_fd)
    return {k: x.tolist() for k, x in out.items()}


def check_derivatives(model, data, r, state, out, a_fd):
    """dtau/dq, dtau/dv, da/dq and da/dv against central differences in the coordinates (1e-5
    scaled: a wrong projection is off by O(1)); q moved along the tangent, the full model's
    `integrate` along S dq (the joints' map being linear), Coulomb's friction held."""
    S, (qf, vf, af) = r.S, state
    # Coulomb's term held at v (its sign is flat away from 0; sample 0 is at rest).
    coulomb = joint_friction(vf, 0 * model.damping, model.friction)
    friction = lambda v: joint_friction(v, model.damping, 0 * model.friction) + coulomb
    tau = lambda q, v: S.T @ (pin.rnea(model, data, q, v, af) + friction(v))
    tau_in = S.T @ (pin.rnea(model, data, qf, vf, S @ a_fd) + friction(vf))

    def fd(q, v):
        m = S.T @ pin.crba(model, data, q) @ S
        return np.linalg.solve(symmetric(m), tau_in - S.T @ (pin.nonLinearEffects(model, data, q, v) + friction(v)))

    step = 1e-6
    for key, f in [("dtau", tau), ("ddq", fd)]:
        by_q = np.array([(f(pin.integrate(model, qf, S @ e), vf) - f(pin.integrate(model, qf, -S @ e), vf)) / (2 * step)
                         for e in np.eye(r.nv) * step]).T
        by_v = np.array([(f(qf, vf + S @ e) - f(qf, vf - S @ e)) / (2 * step) for e in np.eye(r.nv) * step]).T
        assert scaled(by_q, out[key + "_dq"]) < 1e-5, (key, scaled(by_q, out[key + "_dq"]))
        assert scaled(by_v, out[key + "_dv"]) < 1e-5, (key, scaled(by_v, out[key + "_dv"]))


def cross_check(model, r, samples, path):
    """Pinocchio's own mimic joints: the full model rebuilt joint by joint in the file's order
    (`make.pinocchio_model`, `make.rebuild`: there each gripper joint comes before the joints
    that follow it, as `transformJointIntoMimic` needs), each mimic joint then made a
    `JointModelMimic` of the joint it follows; its crba, rnea, nonLinearEffects and
    computeGeneralizedGravity against the data (without the friction, which Pinocchio's
    algorithms leave out); the largest scaled difference each."""
    _, order = file_order(path)
    mm = make.rebuild(make.pinocchio_model(model, list(model.names)[2:], order))
    for j, (follows, k, o) in r.rules.items():
        mm = pin.transformJointIntoMimic(mm, mm.getJointId(follows), mm.getJointId(j), k, o)
    assert mm.nv == r.nv, (mm.nv, r.nv)
    perm = np.array([0, 1, 2, 3, 4, 5] + [mm.idx_vs[mm.getJointId(n)] for n in r.coordinates])
    qperm = [0, 1, 2, 3, 4, 5, 6] + [mm.idx_qs[mm.getJointId(n)] for n in r.coordinates]
    d = mm.createData()
    largest = {}

    def record(key, mine, theirs):
        largest[key] = max(largest.get(key, 0.0), scaled(theirs, mine))

    for s in samples:
        q, v, a = (np.array(s[k]) for k in ("q", "v", "a"))
        qm, vm, am = np.zeros(mm.nq), np.zeros(mm.nv), np.zeros(mm.nv)
        qm[qperm], vm[perm], am[perm] = q, v, a
        friction = np.array(s["friction"])
        record("M", np.array(s["M"]), symmetric(pin.crba(mm, d, qm))[np.ix_(perm, perm)])
        record("tau", np.array(s["tau"]) - friction, pin.rnea(mm, d, qm, vm, am)[perm])
        record("h", np.array(s["h"]), pin.nonLinearEffects(mm, d, qm, vm)[perm])
        record("g", np.array(s["g"]), pin.computeGeneralizedGravity(mm, d, qm)[perm])
    return {"model": "transformJointIntoMimic, mimic joint by mimic joint, on make.rebuild(make.pinocchio_model("
                     "buildModelFromUrdf(path, JointModelFreeFlyer()))), the joints in the file's order",
            "per_quantity": {k: float(f"{x:.1e}") for k, x in largest.items()}}


def snapping_change(unsnapped, r, samples, frames):
    """How far the URDF's own angles are from the snapped ones the data use: the largest scaled
    change of M, tau (without friction) and the frames' rotations over the samples."""
    data = unsnapped.createData()
    largest = {"M": 0.0, "tau": 0.0, "frame rotation": 0.0}
    for s in samples:
        q, v, a = (np.array(s[k]) for k in ("q", "v", "a"))
        qf, vf, af = r.q_full(q), r.S @ v, r.S @ a
        m = r.S.T @ symmetric(pin.crba(unsnapped, data, qf)) @ r.S
        tau = r.S.T @ pin.rnea(unsnapped, data, qf, vf, af)
        largest["M"] = max(largest["M"], scaled(m, s["M"]))
        largest["tau"] = max(largest["tau"], scaled(tau, np.array(s["tau"]) - np.array(s["friction"])))
        pin.framesForwardKinematics(unsnapped, data, qf)
        for f in frames:
            rotation = data.oMf[unsnapped.getFrameId(f)].rotation
            change = scaled(rotation, s["kinematics"]["frames"][f]["rotation"])
            largest["frame rotation"] = max(largest["frame rotation"], change)
    return {k: float(f"{x:.1e}") for k, x in largest.items()}


def mimic_data(name):
    urdf, frames = MIMIC[name]
    path = os.path.join(ROOT, urdf)
    model, snapped = snapped_model(path)
    unsnapped = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    data = model.createData()
    r = Reduction(model, path)
    rng, extra = np.random.default_rng(SEED), np.random.default_rng(SEED + 1)
    samples = []
    for k in range(SAMPLES):
        q, v, a = r.sample(rng, k)
        tau_in = extra.uniform(-20, 20, r.nv)
        state, (qf, vf, m, m_inv, a_fd) = dynamics(model, data, r, q, v, a, tau_in)
        state["kinematics"] = kinematics(model, data, r, frames, qf, vf)
        state["derivatives"] = derivatives(model, data, r, qf, vf, r.S @ a, m_inv, a_fd)
        samples.append(state)
    check = cross_check(model, r, samples, path)
    snapping = snapping_change(unsnapped, r, samples, frames)
    snapping["origins_snapped"] = snapped
    assert max(check["per_quantity"].values()) < TOLERANCE, check
    with open(path, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    out = {
        "robot": name,
        "generator": "tests/data/floating/mimic.py (mimic_data, run by make.py) with pinocchio %s "
                     "(buildModelFromXML of the URDF with its rpy angles within 1e-5 of a quarter turn snapped, "
                     "with JointModelFreeFlyer, every joint free, projected)"
                     % importlib.metadata.version("pin"),
        "urdf_source": "example-robot-data 6.0.0 (PyPI)",
        "urdf_sha256": sha,
        "urdf": urdf,
        "coordinates": r.coordinates,
        "mimic": [{"joint": j, "follows": f, "multiplier": k, "offset": o} for j, (f, k, o) in r.rules.items()],
        "nq": r.nq,
        "nv": r.nv,
        "frames": frames,
        "gravity": [0.0, 0.0, -9.81],
        "conventions": "q = [x, y, z, qx, qy, qz, qw, coordinates]; v, a = [linear, angular (base frame), "
                       "coordinates]; S = diag(1_6, G) the map to every joint (q_full = G q + offset); M, h, tau "
                       "(with the joints' friction), g, a_fd = M^-1 (tau_in - h - friction), M_inv and the "
                       "derivatives as make.py's for the reduced system, S^T (full) S; kinematics as make.py's "
                       "kinematics, Jacobians J_full S",
        "seed": SEED,
        "mimic_cross_check": check,
        "snapping": snapping,
        "samples": samples,
    }
    write_json(name + "_mimic.json", out)
    print(name, "mimic:", r.nq, r.nv, "of", model.nq, model.nv, check["per_quantity"], snapping)


if __name__ == "__main__":
    for robot in MIMIC:
        mimic_data(robot)

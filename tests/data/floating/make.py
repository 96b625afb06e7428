#!/usr/bin/env python3
"""Reference data for a robot on a free-flying base (issue 43), from Pinocchio's own URDF
loader with its free-flyer root joint.

For each robot of ROBOTS this script

1. loads the URDF with `pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())` (gravity
   [0, 0, -9.81] in the world frame): the root link, and every link fixed to it, is the
   floating body;
2. takes Pinocchio's joints after the free flyer to the order the project's front end takes
   them (depth first from the root link, a link's child joints in the file's order; Pinocchio's
   URDF parser orders a link's child joints by name, so ANYmal's LF, RF, LH, RH legs are LF, LH,
   RF, RH there): every joint's q, v, a and row and column of M, h, tau, g are written in the
   front end's order (`to_file_order`), the same numbers;
3. draws SAMPLES states: the base position uniform in [-1, 1]^3, the base orientation a uniform
   random unit quaternion (a normalised Gaussian 4-vector, stored [qx, qy, qz, qw] as Pinocchio's
   q), each joint in [-pi, pi], v and a uniform in [-2, 2] (the base's twist in its own frame,
   then the joint rates, as Pinocchio's v); sample #0 is the base at rest, upright, joints at 0;
4. writes M (`crba`, its upper triangle mirrored), h (`nonLinearEffects`), tau (`rnea`) and
   g (`computeGeneralizedGravity`), and checks tau = M a + h and g = rnea(q, 0, 0) to 1e-12;
5. writes the model as "pinocchio_model" (`pinocchio_model`), the free flyer first, then the
   joints in the file's order, for `bench/pinocchio/bench.cpp` (header-only Pinocchio, no URDF
   parser), and checks that the model rebuilt from it (`rebuild`, as bench.cpp builds it) gives
   every sample's M and tau to 1e-12;
6. for the robots of CONFIGURATION_SPACE (Solo 12), draws, from a second generator
   (seeded SEED + 1, so that the states above stay as they were), per state a generalized
   force `tau_in` uniform in [-20, 20], a velocity step `dv` uniform in [-1.5, 1.5] (its base
   rotation up to 2.6 rad) and a second configuration `q1` as q is drawn; on sample #1 the
   step's rotation is tiny (1e-9 rad), for the Taylor branch; and writes the forward dynamics
   `a_fd = aba(q, v, tau_in)`, `M_inv` (`computeMinverse`, its upper triangle mirrored),
   `q_next = integrate(q, dv)`, `dq = difference(q, q1)`, and the Jacobians `dIntegrate` by q
   and by v at (q, dv) and `dDifference` by q0 and by q1 at (q, q1); it checks
   M a_fd + h = tau_in, M M_inv = 1 and integrate(q, dq) = q1.

Usage, from the repository root (Pinocchio 4.1, the `pin` wheel):

    target/python-venv/bin/python tests/data/floating/make.py
"""

import hashlib
import importlib.metadata
import json
import os
import xml.etree.ElementTree as ET

import numpy as np
import pinocchio as pin

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))

# name: URDF from the repository root
ROBOTS = {
    "solo12": "robots/urdf/floating/solo12.urdf",
    "anymal_b": "robots/urdf/floating/anymal_b.urdf",
    "g1_29dof": "robots/urdf/floating/g1_29dof.urdf",
}
# The robots whose forward dynamics, M^-1 and configuration space are written (step 6). Not the
# G1: its M's condition (light wrists beside a heavy trunk) puts aba's M a + h - tau above 1e-12.
CONFIGURATION_SPACE = ["solo12"]
SEED = 20261129
SAMPLES = 12
TOLERANCE = 1e-12


def file_order(path):
    """The moving joints depth first from the root link, a link's child joints in file order."""
    robot = ET.parse(path).getroot()
    joints = robot.findall("joint")
    children = {}
    for j in joints:
        children.setdefault(j.find("parent").get("link"), []).append(j)
    child_links = {j.find("child").get("link") for j in joints}
    roots = [link.get("name") for link in robot.findall("link") if link.get("name") not in child_links]
    assert len(roots) == 1, roots
    order = []

    def walk(link):
        for j in children.get(link, []):
            if j.get("type") not in ("fixed",):
                order.append(j.get("name"))
            walk(j.find("child").get("link"))

    walk(roots[0])
    return roots[0], order


def load(name, urdf):
    """Pinocchio's model of `urdf` on its free flyer, its data, the samples of `<name>.json`, and
    the moving joints in the file's order and in Pinocchio's."""
    path = os.path.join(ROOT, urdf)
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    with open(os.path.join(HERE, name + ".json")) as f:
        states = json.load(f)["samples"]
    _, order = file_order(path)
    return model, model.createData(), states, order, list(model.names)[2:]


def write_json(file, record):
    """`record` as `file` in this directory, one space of indent, a newline at the end."""
    with open(os.path.join(HERE, file), "w") as f:
        json.dump(record, f, indent=1)
        f.write("\n")


def file_indices(names, order):
    """The indices that take Pinocchio's q (`iq`) and v (`iv`) to the file's joint `order`:
    `q[iq]`, `v[iv]`; the free flyer's 7 and 6 first coordinates stay."""
    pick = [names.index(j) for j in order]
    return list(range(7)) + [7 + k for k in pick], list(range(6)) + [6 + k for k in pick]


def to_file_order(model, names, order, q, v, a, m, h, tau, g):
    """Pinocchio's joint coordinates (its `names` order) permuted into the file's `order`; the
    free flyer's 7 (q) and 6 (v) first coordinates stay."""
    assert sorted(names) == sorted(order), (names, order)
    iq, iv = file_indices(names, order)
    assert model.nq == len(iq) and model.nv == len(iv)
    return q[iq], v[iv], a[iv], m[np.ix_(iv, iv)], h[iv], tau[iv], g[iv]


def pinocchio_model(model, names, order):
    """The model, joint by joint in the file's `order`, the free flyer first: each joint's type,
    parent (an index into this list, 0 the universe), placement and body inertia."""
    index = [1] + [2 + names.index(j) for j in order]
    new = {old: k + 1 for k, old in enumerate(index)}
    new[0] = 0
    joints = []
    for i in index:
        joint, inertia, placement = model.joints[i], model.inertias[i], model.jointPlacements[i]
        joints.append({"name": model.names[i], "parent": new[int(model.parents[i])], "type": joint.shortname(),
                       "rotation": placement.rotation.tolist(), "translation": placement.translation.tolist(),
                       "mass": inertia.mass, "lever": inertia.lever.tolist(), "inertia": inertia.inertia.tolist()})
    assert all(j["type"] in ("JointModelFreeFlyer", "JointModelRX", "JointModelRY", "JointModelRZ")
               for j in joints), [j["type"] for j in joints]
    return {"gravity": [0.0, 0.0, -9.81], "joints": joints}


def rebuild(record):
    """The model of `pinocchio_model`, built again as bench/pinocchio/bench.cpp builds it."""
    model = pin.Model()
    model.gravity = pin.Motion(np.array(record["gravity"]), np.zeros(3))
    kinds = {"JointModelFreeFlyer": pin.JointModelFreeFlyer, "JointModelRX": pin.JointModelRX,
             "JointModelRY": pin.JointModelRY, "JointModelRZ": pin.JointModelRZ}
    for j in record["joints"]:
        kind = kinds[j["type"]]()
        jid = model.addJoint(j["parent"], kind, pin.SE3(np.array(j["rotation"]), np.array(j["translation"])), j["name"])
        model.appendBodyToJoint(jid, pin.Inertia(j["mass"], np.array(j["lever"]), np.array(j["inertia"])),
                                pin.SE3.Identity())
    return model


def check_rebuilt(record, samples):
    """The rebuilt model's M and tau at every sample (in the file's order) to 1e-12."""
    model = rebuild(record)
    data = model.createData()
    for s in samples:
        q, v, a = (np.array(s[k]) for k in ("q", "v", "a"))
        m = pin.crba(model, data, q)
        assert scaled(symmetric(m), s["M"]) < TOLERANCE
        assert scaled(pin.rnea(model, data, q, v, a), s["tau"]) < TOLERANCE


def scaled(a, b):
    """max |a - b| / max(1, max |b|)."""
    a, b = np.asarray(a), np.asarray(b)
    return float(np.max(np.abs(a - b)) / max(1.0, float(np.max(np.abs(b)))))


def symmetric(m):
    """`m`'s upper triangle mirrored (Pinocchio's crba and computeMinverse fill only that)."""
    return np.triu(m) + np.triu(m, 1).T


def dynamics_at(model, data, q, v, a):
    """M (crba), h (nonLinearEffects), rnea(q, v, a) and g (computeGeneralizedGravity) at one
    state, Pinocchio's joint order; checks rnea = M a + h to 1e-12."""
    m = symmetric(pin.crba(model, data, q))
    h = pin.nonLinearEffects(model, data, q, v).copy()
    tau = pin.rnea(model, data, q, v, a).copy()
    g = pin.computeGeneralizedGravity(model, data, q).copy()
    assert scaled(m @ a + h, tau) < TOLERANCE
    return m, h, tau, g


def sample(rng, model, k):
    """State k: q (nq), v and a (nv)."""
    n = model.nv - 6
    if k == 0:
        q = pin.neutral(model)
        return q, np.zeros(model.nv), np.zeros(model.nv)
    quaternion = rng.normal(size=4)
    quaternion /= np.linalg.norm(quaternion)
    q = np.concatenate([rng.uniform(-1, 1, 3), quaternion, rng.uniform(-np.pi, np.pi, n)])
    return q, rng.uniform(-2, 2, model.nv), rng.uniform(-2, 2, model.nv)


def configuration_step(rng, model, k):
    """The configuration space's inputs at state k: a velocity step `dv` uniform in [-1.5, 1.5]
    (on state 1 its rotation 1e-9 rad, for the Taylor branch) and a second configuration `q1`."""
    dv = rng.uniform(-1.5, 1.5, model.nv)
    if k == 1:
        dv[3:6] *= 1e-9
    q1, _, _ = sample(rng, model, 2)
    return dv, q1


def configuration_at(model, q, dv, q1):
    """`q_next = integrate(q, dv)`, `dq = difference(q, q1)` and the Jacobians of both by each
    argument (Pinocchio's joint order); checks integrate(q, dq) = q1."""
    q_next = pin.integrate(model, q, dv)
    dq = pin.difference(model, q, q1)
    back = pin.integrate(model, q, dq)
    assert scaled(back[7:], q1[7:]) < TOLERANCE and scaled(back[:3], q1[:3]) < TOLERANCE
    # The same rotation: the quaternions equal up to sign.
    assert min(scaled(back[3:7], q1[3:7]), scaled(back[3:7], -q1[3:7])) < TOLERANCE
    jacobians = {
        "dintegrate_dq": pin.dIntegrate(model, q, dv, pin.ARG0),
        "dintegrate_dv": pin.dIntegrate(model, q, dv, pin.ARG1),
        "ddifference_dq0": pin.dDifference(model, q, q1, pin.ARG0),
        "ddifference_dq1": pin.dDifference(model, q, q1, pin.ARG1),
    }
    return q_next, dq, {key: np.asarray(j) for key, j in jacobians.items()}


def configuration_space(rng, model, data, k, q, v, m, h):
    """Forward dynamics, M^-1, integrate, difference and their Jacobians at state k."""
    tau_in = rng.uniform(-20, 20, model.nv)
    dv, q1 = configuration_step(rng, model, k)
    a_fd = pin.aba(model, data, q, v, tau_in).copy()
    m_inv = symmetric(pin.computeMinverse(model, data, q))
    assert scaled(m @ a_fd + h, tau_in) < TOLERANCE
    assert scaled(m @ m_inv, np.eye(model.nv)) < TOLERANCE
    q_next, dq, jacobians = configuration_at(model, q, dv, q1)
    out = {"tau_in": tau_in.tolist(), "a_fd": a_fd.tolist(), "M_inv": m_inv.tolist(),
           "dv": dv.tolist(), "q_next": q_next.tolist(), "q1": q1.tolist(), "dq": dq.tolist()}
    out.update({key: j.tolist() for key, j in jacobians.items()})
    return out


def make(name, urdf):
    path = os.path.join(ROOT, urdf)
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    data = model.createData()
    root, order = file_order(path)
    names = list(model.names)[2:]
    assert model.joints[1].shortname() == "JointModelFreeFlyer"
    rng = np.random.default_rng(SEED)
    extra = np.random.default_rng(SEED + 1)
    samples = []
    for k in range(SAMPLES):
        q, v, a = sample(rng, model, k)
        m, h, tau, g = dynamics_at(model, data, q, v, a)
        assert scaled(pin.rnea(model, data, q, np.zeros(model.nv), np.zeros(model.nv)), g) < TOLERANCE
        q, v, a, m, h, tau, g = to_file_order(model, names, order, q, v, a, m, h, tau, g)
        state = {"q": q.tolist(), "v": v.tolist(), "a": a.tolist(), "M": m.tolist(),
                 "h": h.tolist(), "tau": tau.tolist(), "g": g.tolist()}
        if name in CONFIGURATION_SPACE:
            assert names == order, "computed in Pinocchio's joint order"
            state.update(configuration_space(extra, model, data, k, q, v, m, h))
        samples.append(state)
    record = pinocchio_model(model, names, order)
    check_rebuilt(record, samples)
    with open(path, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    out = {
        "robot": name,
        "generator": "tests/data/floating/make.py with pinocchio %s (buildModelFromUrdf with JointModelFreeFlyer)"
                     % importlib.metadata.version("pin"),
        "urdf_source": "example-robot-data 6.0.0 (PyPI)",
        "urdf_sha256": sha,
        "urdf": urdf,
        "floating_body": root,
        "joints": order,
        "nq": model.nq,
        "nv": model.nv,
        "gravity": [0.0, 0.0, -9.81],
        "conventions": "q = [x, y, z, qx, qy, qz, qw, joints]; v, a = [linear, angular (base frame), joints]; "
                       "tau[0:6] = base wrench [force, moment] in the base frame",
        "seed": SEED,
        "pinocchio_model": record,
        "samples": samples,
    }
    write_json(name + ".json", out)
    print(name, model.nq, model.nv, "mass %.4f" % sum(i.mass for i in model.inertias))


# Frames of KINEMATICS[name] (the feet of Solo 12: its leaf links), read by `kinematics`.
KINEMATICS = {"solo12": ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"]}


def kinematics_at(model, data, q, v, ids, frames, mass, columns=np.asarray):
    """`kinematics`' outputs at one state (Pinocchio's joint order), checked as it checks them;
    `columns` takes a matrix's columns to the file's order."""
    com = pin.centerOfMass(model, data, q).copy()
    jcom = pin.jacobianCenterOfMass(model, data, q).copy()
    ag = pin.computeCentroidalMap(model, data, q).copy()
    dag = pin.computeCentroidalMapTimeVariation(model, data, q, v).copy()
    assert scaled(ag[:3], mass * jcom) < TOLERANCE
    # A_G v: each body's momentum about the CoM, in world axes (body velocities in world).
    pin.forwardKinematics(model, data, q, v)
    momentum = pin.Force.Zero()
    for k in range(1, model.njoints):
        momentum += data.oMi[k].act(model.inertias[k] * data.v[k])
    assert scaled(ag @ v, pin.SE3(np.eye(3), com).actInv(momentum).vector) < TOLERANCE
    step = 1e-6
    diff = (pin.computeCentroidalMap(model, data, pin.integrate(model, q, v * step))
            - pin.computeCentroidalMap(model, data, pin.integrate(model, q, -v * step))) / (2 * step)
    assert scaled(diff @ v, dag @ v) < 1e-6
    pin.forwardKinematics(model, data, q, v, np.zeros(model.nv))
    pin.updateFramePlacements(model, data)
    pin.computeJointJacobians(model, data, q)
    out = {"com": com.tolist(), "Jcom": columns(jcom).tolist(), "Ag": columns(ag).tolist(),
           "dAg_v": (dag @ v).tolist(), "frames": {}}
    for frame, i in zip(frames, ids):
        placement = data.oMf[i]
        entry = {"rotation": placement.rotation.tolist(), "translation": placement.translation.tolist()}
        for key, ref in [("local", pin.LOCAL), ("world_aligned", pin.LOCAL_WORLD_ALIGNED)]:
            jac = pin.getFrameJacobian(model, data, i, ref)
            assert scaled(jac @ v, pin.getFrameVelocity(model, data, i, ref).vector) < TOLERANCE
            entry["J_" + key] = columns(jac).tolist()
            entry["dJv_" + key] = pin.getFrameClassicalAcceleration(model, data, i, ref).vector.tolist()
        out["frames"][frame] = entry
    return out


def kinematics(name, urdf):
    """The kinematic outputs at the states of `<name>.json` (issue 43, item 2), written to
    `<name>_kinematics.json`: the centre of mass (`centerOfMass`) and its Jacobian
    (`jacobianCenterOfMass`), the centroidal momentum matrix A_G (`computeCentroidalMap`) and
    dA_G v (`computeCentroidalMapTimeVariation`, times v), and for each frame its placement in
    the world, its Jacobian (`getFrameJacobian`) and its classical acceleration at a = 0
    (`getFrameClassicalAcceleration`: the origin's acceleration in the world, dJ v) in LOCAL
    and LOCAL_WORLD_ALIGNED. Checks A_G's linear rows = m Jcom, A_G v = the momentum about the
    CoM computed body by body, and dA_G v against a central difference of A_G along the motion."""
    model, data, states, _, _ = load(name, urdf)
    frames = KINEMATICS[name]
    ids = [model.getFrameId(f) for f in frames]
    mass = sum(i.mass for i in model.inertias)
    samples = [kinematics_at(model, data, np.array(s["q"]), np.array(s["v"]), ids, frames, mass) for s in states]
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (kinematics) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v of its samples, in order)",
        "frames": frames,
        "mass": mass,
        "conventions": "com and Jcom in the world frame; Ag, dAg_v: [linear; angular] momentum about the CoM in "
                       "world axes; frame rotation and translation in the world; J_local, dJv_local in the frame's "
                       "axes, J_world_aligned, dJv_world_aligned in world axes at the frame's origin; dJv = "
                       "getFrameClassicalAcceleration at a = 0 ([origin's acceleration; angular acceleration])",
        "samples": samples,
    }
    write_json(name + "_kinematics.json", result)
    print(name, "kinematics:", len(samples), "samples,", len(frames), "frames")


# Contacts at the feet of Solo 12 (issue 43, item 3), read by `contacts`: the sets of feet in
# contact, one per sample in turn, from two diagonal feet (a trot's stance) to none.
CONTACT_MASKS = [[True, False, False, True], [True, True, True, True], [False, True, True, False],
                 [True, True, True, False], [False, False, True, False], [False, False, False, False]]


def rigid_contacts(model, data, held):
    """Pinocchio's constraints holding the frames of `held` (frame id, "surface" or "point") in
    LOCAL_WORLD_ALIGNED, CONTACT_6D or CONTACT_3D (no Baumgarte), with their data, initialised."""
    types = {"surface": pin.ContactType.CONTACT_6D, "point": pin.ContactType.CONTACT_3D}
    models = [pin.RigidConstraintModel(types[kind], model, model.frames[i].parentJoint,
                                       model.frames[i].placement, pin.LOCAL_WORLD_ALIGNED) for i, kind in held]
    datas = [c.createData() for c in models]
    pin.initConstraintDynamics(model, data, models, datas)
    return models, datas


def kkt_gap(model, data, q, v, tau, held, ddq, lambda_c):
    """How far constraintDynamics' `ddq` and `lambda_c` (flat) at the frames `held` (as
    `rigid_contacts`') are from numpy's solve of the KKT system [M J^T; J 0] [a; -lambda] =
    [tau - h; -gamma] (scaled, the larger gap): J the frames' LOCAL_WORLD_ALIGNED Jacobians (6
    rows at a surface, the 3 linear at a point), gamma a surface's spatial acceleration at a = 0
    (getFrameAcceleration: the classical one less w x v in the linear part) and a point's
    classical acceleration."""
    m = symmetric(pin.crba(model, data, q))
    h = pin.nonLinearEffects(model, data, q, v).copy()
    pin.forwardKinematics(model, data, q, v, np.zeros(model.nv))
    pin.computeJointJacobians(model, data, q)
    pin.updateFramePlacements(model, data)
    rows, gammas = [np.zeros((0, model.nv))], [np.zeros(0)]
    for i, kind in held:
        jac = pin.getFrameJacobian(model, data, i, pin.LOCAL_WORLD_ALIGNED)
        if kind == "surface":
            rows.append(jac)
            gammas.append(pin.getFrameAcceleration(model, data, i, pin.LOCAL_WORLD_ALIGNED).vector)
        else:
            rows.append(jac[:3])
            gammas.append(pin.getFrameClassicalAcceleration(model, data, i, pin.LOCAL_WORLD_ALIGNED).linear)
    jc, gamma = np.vstack(rows), np.concatenate(gammas)
    c = len(gamma)
    kkt = np.block([[m, jc.T], [jc, np.zeros((c, c))]])
    solution = np.linalg.solve(kkt, np.concatenate([tau - h, -gamma]))
    return max(scaled(ddq, solution[:model.nv]), scaled(lambda_c, -solution[model.nv:]) if c else 0.0)


def contacts_at(model, data, state, ids, mask, rng, tolerance, iv=slice(None)):
    """`contacts`' outputs at one state (Pinocchio's joint order), the frames `ids`, those of
    `mask` held; the vectors in the file's order (`iv`). The accelerations with wrenches are
    checked against rnea and numpy's solve to 1e-9, the constrained ones against the KKT
    system's solve to `tolerance`."""
    q, v, a, tau = state
    wrenches = rng.uniform(-10, 10, (len(ids), 6))
    forces = rng.uniform(-10, 10, (len(ids), 3))
    pin.computeJointJacobians(model, data, q)
    pin.updateFramePlacements(model, data)
    jac = [pin.getFrameJacobian(model, data, i, pin.LOCAL_WORLD_ALIGNED).copy() for i in ids]
    m = symmetric(pin.crba(model, data, q))
    out = {}
    for key, w in [("wrenches", wrenches), ("forces", np.hstack([forces, np.zeros_like(forces)]))]:
        # fext: each wrench turned into its frame's axes and carried to the frame's joint.
        fext = [pin.Force.Zero() for _ in range(model.njoints)]
        for i, wrench in zip(ids, w):
            frame = model.frames[i]
            rotation = data.oMf[i].rotation
            fext[frame.parentJoint] += frame.placement.act(pin.Force(rotation.T @ wrench[:3], rotation.T @ wrench[3:]))
        generalized = sum(j.T @ wrench for j, wrench in zip(jac, w))
        tau_ext = pin.rnea(model, data, q, v, a, fext).copy()
        assert scaled(tau_ext, tau - generalized) < TOLERANCE
        acc_ext = pin.aba(model, data, q, v, tau, fext).copy()
        assert scaled(pin.rnea(model, data, q, v, acc_ext) - generalized, tau) < 1e-9
        h = pin.nonLinearEffects(model, data, q, v)
        assert scaled(acc_ext, np.linalg.solve(m, tau - h + generalized)) < 1e-9
        out[key] = (w if key == "wrenches" else forces).tolist()
        out["tau_" + key] = tau_ext[iv].tolist()
        out["a_" + key] = acc_ext[iv].tolist()
    held = [(i, "point") for i, flag in zip(ids, mask) if flag]
    models, datas = rigid_contacts(model, data, held)
    ddq = pin.constraintDynamics(model, data, q, v, tau, models, datas).copy()
    lambda_c = data.lambda_c.copy()
    assert kkt_gap(model, data, q, v, tau, held, ddq, lambda_c) < tolerance
    full = np.zeros((len(ids), 3))
    full[np.array(mask, dtype=bool)] = lambda_c.reshape(-1, 3)
    out.update({"in_contact": mask, "a_contact": ddq[iv].tolist(), "lambda": full.tolist()})
    return out


def contacts(name, urdf):
    """Contacts at the frames KINEMATICS[name], at the states of `<name>.json`, written to
    `<name>_contacts.json`: for random wrenches [f, m] and point forces f exerted on the robot at
    each frame's origin in LOCAL_WORLD_ALIGNED, tau = rnea(q, v, a, fext) and
    a = aba(q, v, tau, fext) (fext: each wrench carried to its frame's joint, in the joint's
    frame), each checked against tau -/+ sum J^T w with getFrameJacobian in LOCAL_WORLD_ALIGNED;
    and constraintDynamics with a RigidConstraintModel CONTACT_3D in LOCAL_WORLD_ALIGNED at each
    frame of CONTACT_MASKS (no Baumgarte), its ddq and lambda_c checked against the KKT system
    [M J^T; J 0] [a; -lambda] = [tau - h; -gamma] solved with numpy."""
    model, data, states, _, _ = load(name, urdf)
    frames = KINEMATICS[name]
    ids = [model.getFrameId(f) for f in frames]
    rng = np.random.default_rng(SEED + 2)
    samples = []
    for k, s in enumerate(states):
        state = tuple(np.array(s[key]) for key in ("q", "v", "a", "tau"))
        mask = CONTACT_MASKS[k % len(CONTACT_MASKS)]
        samples.append(contacts_at(model, data, state, ids, mask, rng, 1e-10))
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (contacts) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, a, tau of its samples, in order)",
        "frames": frames,
        "seed": SEED + 2,
        "conventions": "wrenches [f, m] and forces f exerted on the robot at each frame's origin in world axes "
                       "(LOCAL_WORLD_ALIGNED); tau_X = rnea(q, v, a, fext), a_X = aba(q, v, tau, fext); "
                       "a_contact, lambda = constraintDynamics(q, v, tau) with CONTACT_3D in LOCAL_WORLD_ALIGNED "
                       "at the frames in_contact (no Baumgarte), lambda the force on the robot in world axes, "
                       "zero at a frame not in contact",
        "samples": samples,
    }
    write_json(name + "_contacts.json", result)
    print(name, "contacts:", len(samples), "samples,", len(frames), "frames")


# The feet held by `contact_fd` (bench/run's `contact_fd` row), in the front end's frame order
# (the leaf links below a moving joint, in the file's order).
CONTACT_FD = {"solo12": ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"],
              "anymal_b": ["LF_FOOT", "RF_FOOT", "LH_FOOT", "RH_FOOT"]}


def contact_fd(name, urdf):
    """Every foot of CONTACT_FD[name] held (CONTACT_3D in LOCAL_WORLD_ALIGNED, no Baumgarte) at
    the states of `<name>.json` (its q, v, tau), written to `<name>_contact_fd.json`:
    constraintDynamics' ddq and lambda_c, each checked against numpy's solve of the KKT system;
    and each foot's frame (its parent joint's name, its placement in the joint's frame) for
    bench/pinocchio/floating.hpp, which holds the same feet of the rebuilt model. Joints in the
    file's order, as `<name>.json`'s."""
    model, data, states, order, names = load(name, urdf)
    frames = CONTACT_FD[name]
    ids = [model.getFrameId(f) for f in frames]
    held = [(i, "point") for i in ids]
    models, datas = rigid_contacts(model, data, held)
    _, iv = file_indices(names, order)
    samples = []
    for s in states:
        q = from_file_order(names, order, np.array(s["q"]), 7)
        v = from_file_order(names, order, np.array(s["v"]), 6)
        tau = from_file_order(names, order, np.array(s["tau"]), 6)
        ddq = pin.constraintDynamics(model, data, q, v, tau, models, datas).copy()
        lambda_c = data.lambda_c.copy()
        assert kkt_gap(model, data, q, v, tau, held, ddq, lambda_c) < 1e-10
        samples.append({"a_contact": ddq[iv].tolist(), "lambda": lambda_c.reshape(-1, 3).tolist()})
    feet = [{"name": model.frames[i].name, "joint": model.names[model.frames[i].parentJoint],
             "rotation": model.frames[i].placement.rotation.tolist(),
             "translation": model.frames[i].placement.translation.tolist()} for i in ids]
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (contact_fd) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, tau of its samples, in order)",
        "frames": feet,
        "conventions": "every frame held: a_contact, lambda = constraintDynamics(q, v, tau) with CONTACT_3D in "
                       "LOCAL_WORLD_ALIGNED at each frame (no Baumgarte), a_contact's joints in the file's order, "
                       "lambda the force on the robot in world axes, a row per frame; a frame's placement in its "
                       "parent joint's frame",
        "samples": samples,
    }
    write_json(name + "_contact_fd.json", result)
    print(name, "contact_fd:", len(samples), "samples,", len(frames), "frames")


# Robots whose first derivatives are written by `derivatives` (all three).
DERIVATIVES = ["solo12", "anymal_b", "g1_29dof"]


def from_file_order(names, order, x, offset):
    """A vector in the file's joint `order` back in Pinocchio's (`names`), its first `offset`
    (the free flyer's 7 of q, 6 of v) kept."""
    pick = [names.index(j) for j in order]
    index = list(range(offset)) + [offset + k for k in pick]
    out = np.empty(len(index))
    out[index] = x
    return out


def central(f, model, q, step=1e-6):
    """The columns d f(q (+) dq) / d dq by central differences along `integrate`."""
    columns = []
    for j in range(model.nv):
        e = np.zeros(model.nv)
        e[j] = step
        columns.append((f(pin.integrate(model, q, e)) - f(pin.integrate(model, q, -e))) / (2 * step))
    return np.array(columns).T


def derivatives(name, urdf):
    """The first derivatives (issue 43, item 2) at the states of `<name>.json`, written to
    `<name>_derivatives.json`: `computeRNEADerivatives(q, v, a)`'s dtau_dq and dtau_dv, and, at
    a generalized force `tau_in` uniform in [-20, 20] drawn from a third generator (seeded SEED
    + 2), `aba(q, v, tau_in)` and `computeABADerivatives`' ddq_dq, ddq_dv and Minv (ddq_dtau,
    its upper triangle mirrored). The derivatives by q are along the tangent,
    q (+) dq = integrate(q, dq): the base moved in its own frame. Rows and columns in the
    file's joint order (the states are read in it, taken to Pinocchio's for the calls, and the
    results back). Checks dtau_dq, dtau_dv, ddq_dq and ddq_dv against central differences
    (1e-5 scaled: a wrong convention is off by O(1)), Minv M = 1 and ddq_dq = -Minv dtau_dq at a = ddq (1e-10 scaled)."""
    model, data, states, order, names = load(name, urdf)
    rng = np.random.default_rng(SEED + 2)
    _, iv = file_indices(names, order)
    to_file = lambda m: m[np.ix_(iv, iv)]
    samples = []
    for s in states:
        q = from_file_order(names, order, np.array(s["q"]), 7)
        v, a = (from_file_order(names, order, np.array(s[k]), 6) for k in ("v", "a"))
        tau_in = rng.uniform(-20, 20, model.nv)
        dtau_dq, dtau_dv, _ = (x.copy() for x in pin.computeRNEADerivatives(model, data, q, v, a))
        fd_q = central(lambda x: pin.rnea(model, data, x, v, a), model, q)
        assert scaled(fd_q, dtau_dq) < 1e-5, scaled(fd_q, dtau_dq)
        fd_v = np.array([(pin.rnea(model, data, q, v + e, a) - pin.rnea(model, data, q, v - e, a)) / 2e-6
                         for e in np.eye(model.nv) * 1e-6]).T
        assert scaled(fd_v, dtau_dv) < 1e-5, scaled(fd_v, dtau_dv)
        ddq = pin.aba(model, data, q, v, tau_in).copy()
        ddq_dq, ddq_dv, m_inv = (x.copy() for x in pin.computeABADerivatives(model, data, q, v, tau_in))
        m_inv = symmetric(m_inv)
        m = symmetric(pin.crba(model, data, q))
        assert scaled(m_inv @ m, np.eye(model.nv)) < 1e-10
        at_ddq, _, _ = pin.computeRNEADerivatives(model, data, q, v, ddq)
        assert scaled(-m_inv @ at_ddq, ddq_dq) < 1e-10, scaled(-m_inv @ at_ddq, ddq_dq)
        fd_q = central(lambda x: pin.aba(model, data, x, v, tau_in), model, q)
        assert scaled(fd_q, ddq_dq) < 1e-5, scaled(fd_q, ddq_dq)
        fd_v = np.array([(pin.aba(model, data, q, v + e, tau_in) - pin.aba(model, data, q, v - e, tau_in)) / 2e-6
                         for e in np.eye(model.nv) * 1e-6]).T
        assert scaled(fd_v, ddq_dv) < 1e-5, scaled(fd_v, ddq_dv)
        samples.append({"tau_in": tau_in[iv].tolist(), "dtau_dq": to_file(dtau_dq).tolist(),
                        "dtau_dv": to_file(dtau_dv).tolist(), "ddq": ddq[iv].tolist(),
                        "ddq_dq": to_file(ddq_dq).tolist(), "ddq_dv": to_file(ddq_dv).tolist(),
                        "ddq_dtau": to_file(m_inv).tolist()})
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (derivatives) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, a of its samples, in order)",
        "joints": order,
        "conventions": "row i, column j: d y_i / d x_j; by q along the tangent, q (+) dq = integrate(q, dq) (the base "
                       "perturbed in its own frame, [linear, angular]), by v and tau as the vectors; "
                       "dtau_* = computeRNEADerivatives(q, v, a); ddq = aba(q, v, tau_in), ddq_* = "
                       "computeABADerivatives(q, v, tau_in), ddq_dtau = Minv",
        "seed": SEED + 2,
        "samples": samples,
    }
    write_json(name + "_derivatives.json", result)
    print(name, "derivatives:", len(samples), "samples")


# The robots whose regressor is written (`regressor`).
REGRESSOR = ["solo12", "anymal_b", "g1_29dof"]
# States stacked for the regressor's numerical rank, and the relative tolerance on the singular
# values that decides it.
RANK_STATES = 40
RANK_TOLERANCE = 1e-9


def regressor(name, urdf):
    """The joint torque regressor (issue 43, item 2) at the states of `<name>.json`, written to
    `<name>_regressor.json`: `computeJointTorqueRegressor(q, v, a)` (nv x 10 (n + 1)), the column
    blocks body by body, the free flyer's first, then the joints' in the file's order, each
    block the body's `[m, m c, I(6)]` (`Inertia::toDynamicParameters`: about the joint frame's
    origin, in its axes; a URDF's joint frame is its child link's frame), rows in the file's
    joint order; and the standard parameters `pi` in the same layout. Checks Y pi = rnea(q, v, a)
    to 1e-12 scaled. Also the numerical rank of Y stacked at RANK_STATES random states (seed
    SEED + 3: joints in [-pi, pi], unit quaternions, v and a in [-2, 2]), by the SVD with
    singular values below RANK_TOLERANCE times the largest taken as zero, and the gap there."""
    model, data, states, order, names = load(name, urdf)
    pick = [names.index(j) for j in order]
    iv = list(range(6)) + [6 + k for k in pick]
    # Body blocks: the free flyer's (Pinocchio's joint 1), then the file's joints.
    bodies = [1] + [2 + k for k in pick]
    columns = [10 * (b - 1) + k for b in bodies for k in range(10)]
    pi = np.concatenate([model.inertias[b].toDynamicParameters() for b in bodies])
    samples = []
    for s in states:
        q = from_file_order(names, order, np.array(s["q"]), 7)
        v, a = (from_file_order(names, order, np.array(s[k]), 6) for k in ("v", "a"))
        y = pin.computeJointTorqueRegressor(model, data, q, v, a).copy()[np.ix_(iv, columns)]
        tau = pin.rnea(model, data, q, v, a)[iv]
        assert scaled(y @ pi, tau) < TOLERANCE, scaled(y @ pi, tau)
        assert scaled(tau, s["tau"]) < TOLERANCE
        samples.append({"Y": y.tolist()})
    rng = np.random.default_rng(SEED + 3)
    stacked = []
    for _ in range(RANK_STATES):
        q, v, a = sample(rng, model, 1)
        stacked.append(pin.computeJointTorqueRegressor(model, data, q, v, a).copy())
    singular = np.linalg.svd(np.vstack(stacked), compute_uv=False)
    rank = int(np.sum(singular > RANK_TOLERANCE * singular[0]))
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (regressor) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, a of its samples, in order)",
        "joints": order,
        "conventions": "Y[i][10 j + k] = d tau_i / d pi_jk; body 0 the floating body (about the base origin, base "
                       "axes), body j the link of joint j in the file's order (about its joint frame's origin, in "
                       "its axes); pi_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]",
        "pi": pi.tolist(),
        "rank": rank,
        "rank_gap": [float(singular[rank - 1] / singular[0]), float(singular[rank] / singular[0])
                     if rank < len(singular) else 0.0],
        "rank_states": RANK_STATES,
        "seed": SEED + 3,
        "samples": samples,
    }
    write_json(name + "_regressor.json", result)
    print(name, "regressor:", len(samples), "samples, rank", rank, "of", len(columns), result["rank_gap"])



# Joint friction and actuator inertia on a floating base (issue 43; helper contactforms). The
# URDF robots with `<dynamics damping friction>`: name -> URDF, their frames held by `surface`.
FRICTION = {"talos_reduced": "robots/urdf/floating/talos_reduced.urdf"}
# Solo 12 given again as a description file with joint terms of its own (`joint_terms`): per
# joint (the file's order) its actuator inertia, viscous and Coulomb coefficients.
JOINT_TERMS_TOML = "robots/floating/solo12.toml"


def joint_friction(v, damping, friction):
    """The joints' friction torque, `damping v + friction sign(v)` (sign(0) = 0), as the
    front end reads `<dynamics damping friction>`; zero in the base's six rows. Pinocchio
    parses both into `model.damping` and `model.friction` but its `rnea`, `nonLinearEffects`
    and `aba` leave them out (checked in `friction_data`), so they are added here by hand."""
    out = damping * v + friction * np.sign(v)
    out[:6] = 0.0
    return out


def friction_states(name, model, order, names, rng, damping, friction, extra):
    """12 states as `make` draws them, with tau = rnea + friction (Pinocchio's armature in its
    crba and rnea) and, at tau_in, a_fd = aba(q, v, tau_in - friction), in the file's order."""
    data = model.createData()
    samples = []
    for k in range(SAMPLES):
        q, v, a = sample(rng, model, k)
        m, h, rigid, g = dynamics_at(model, data, q, v, a)
        f = joint_friction(v, damping, friction)
        tau = rigid + f
        tau_in = extra.uniform(-20, 20, model.nv)
        a_fd = pin.aba(model, data, q, v, tau_in - f).copy()
        assert scaled(m @ a_fd + h + f, tau_in) < 1e-10
        _, iv = file_indices(names, order)
        q, v, a, m, h, tau, g = to_file_order(model, names, order, q, v, a, m, h, tau, g)
        samples.append({"q": q.tolist(), "v": v.tolist(), "a": a.tolist(), "M": m.tolist(),
                        "h": h.tolist(), "tau": tau.tolist(), "g": g.tolist(),
                        "friction": f[iv].tolist(), "tau_in": tau_in[iv].tolist(), "a_fd": a_fd[iv].tolist()})
    return samples


def friction_data(name, urdf):
    """`<name>.json` for a URDF robot whose joints have `<dynamics damping friction>` (Talos):
    `make`'s samples (M, h = nonLinearEffects, g) with tau = rnea + friction and, at a force
    tau_in uniform in [-20, 20] (generator SEED + 1), a_fd = aba(q, v, tau_in - friction)."""
    path = os.path.join(ROOT, urdf)
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    data = model.createData()
    _, order = file_order(path)
    names = list(model.names)[2:]
    # Pinocchio reads the coefficients but its algorithms do not: the same numbers without them.
    bare = model.copy()
    bare.damping[:] = 0.0
    bare.friction[:] = 0.0
    q, v, a = sample(np.random.default_rng(SEED), model, 3)
    assert pin.rnea(model, data, q, v, a).tolist() == pin.rnea(bare, bare.createData(), q, v, a).tolist()
    assert np.count_nonzero(model.damping) > 0
    samples = friction_states(name, model, order, names, np.random.default_rng(SEED), model.damping,
                              model.friction, np.random.default_rng(SEED + 1))
    with open(path, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    out = {
        "robot": name,
        "generator": "tests/data/floating/make.py (friction_data) with pinocchio %s (buildModelFromUrdf with "
                     "JointModelFreeFlyer)" % importlib.metadata.version("pin"),
        "urdf_source": "example-robot-data 6.0.0 (PyPI)",
        "urdf_sha256": sha,
        "urdf": urdf,
        "joints": order,
        "nq": model.nq,
        "nv": model.nv,
        "gravity": [0.0, 0.0, -9.81],
        "conventions": "as make's; tau = rnea(q, v, a) + friction, friction = damping v + friction sign(v) of each "
                       "joint's <dynamics> (Pinocchio's rnea leaves it out); h = nonLinearEffects (no friction); "
                       "a_fd = aba(q, v, tau_in - friction)",
        "seed": SEED,
        "samples": samples,
    }
    write_json(name + ".json", out)
    print(name, model.nq, model.nv, "friction:", int(np.count_nonzero(model.damping)), "joints with damping")


def joint_terms_values(n):
    """Per joint k of n: actuator inertia, viscous and Coulomb coefficients, distinct and exact
    in decimal (so that the TOML and Pinocchio read the same doubles)."""
    return [(0.001 * (k + 1), 0.01 * (k + 2), 0.02 * (k + 1)) for k in range(n)]


def joint_terms(name="solo12"):
    """Solo 12 with actuator inertia, viscous and Coulomb friction at every joint:
    `<name>_joint_terms.toml` (JOINT_TERMS_TOML with the three keys added to each joint) and
    `<name>_joint_terms.json`, Pinocchio's model of the URDF with `armature`, `damping` and
    `friction` set to the same numbers, at `<name>.json`'s states: M (crba, armature on the
    diagonal), h (nonLinearEffects), tau = rnea (armature in it) + friction by hand, g, and at
    tau_in, a_fd = aba(q, v, tau_in - friction), in the file's order (Solo's is Pinocchio's)."""
    path = os.path.join(ROOT, ROBOTS[name])
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    _, order = file_order(path)
    names = list(model.names)[2:]
    assert names == order
    values = joint_terms_values(len(order))
    for k, (armature, viscous, coulomb) in enumerate(values):
        model.armature[6 + k] = armature
        model.damping[6 + k] = viscous
        model.friction[6 + k] = coulomb
    with open(os.path.join(ROOT, JOINT_TERMS_TOML)) as f:
        lines = f.read().split("\n")
    out, k = [], 0
    for line in lines:
        out.append(line)
        if line.startswith("inertia = ") and k < len(values) and any(o.startswith("[[joints]]") for o in out):
            armature, viscous, coulomb = values[k]
            out += ["actuator_inertia = %r" % armature, "friction_viscous = %r" % viscous,
                    "friction_coulomb = %r" % coulomb]
            k += 1
    assert k == len(values)
    out[0:2] = ["# Solo 12 with joint terms, written by tests/data/floating/make.py (joint_terms) from",
                "# %s: each joint's actuator_inertia, friction_viscous, friction_coulomb added. Do not edit." % JOINT_TERMS_TOML]
    with open(os.path.join(HERE, name + "_joint_terms.toml"), "w") as f:
        f.write("\n".join(out))
    samples = friction_states(name, model, order, names, np.random.default_rng(SEED), model.damping,
                              model.friction, np.random.default_rng(SEED + 1))
    # The armature is Pinocchio's: on crba's diagonal and in rnea.
    bare = model.copy()
    bare.armature[:] = 0.0
    q, a = np.array(samples[3]["q"]), np.array(samples[3]["a"])
    assert scaled(np.diag(pin.crba(model, model.createData(), q) - pin.crba(bare, bare.createData(), q))[6:],
                  model.armature[6:]) < 1e-15
    result = {
        "robot": name + " with joint terms",
        "generator": "tests/data/floating/make.py (joint_terms) with pinocchio %s" % importlib.metadata.version("pin"),
        "description": name + "_joint_terms.toml",
        "joints": order,
        "armature": model.armature[6:].tolist(),
        "damping": model.damping[6:].tolist(),
        "friction": model.friction[6:].tolist(),
        "nq": model.nq,
        "nv": model.nv,
        "conventions": "as friction_data's; Pinocchio's armature on crba's diagonal and in rnea and aba",
        "samples": samples,
    }
    write_json(name + "_joint_terms.json", result)
    print(name, "joint terms:", len(samples), "samples")


def joint_terms_derivatives(name="solo12"):
    """The first derivatives of Solo 12 with joint terms (`joint_terms`' model: armature, damping,
    friction) at the states of `<name>_joint_terms.json`, written to
    `<name>_joint_terms_derivatives.json`. Pinocchio's derivatives model the armature (in M) but
    not the friction, which is added by hand: tau = rnea + f_v v + f_c sign(v), so dtau_dq is
    `computeRNEADerivatives`' and dtau_dv gains diag(0_6, f_v) (Coulomb's sign is flat away from
    v = 0: its derivative is taken as 0); at tau_in, ddq = aba(q, v, tau_in - friction),
    ddq_dq = `computeABADerivatives(q, v, tau_in - friction)`' (friction does not depend on q),
    ddq_dv its less Minv diag(0_6, f_v), ddq_dtau = Minv (armature in it). Checks the armature is
    in Pinocchio's derivatives (Minv M = 1 with M = crba), and dtau_dq, dtau_dv, ddq_dq, ddq_dv
    against central differences of rnea + the viscous term and of aba(q, v, tau_in - viscous)
    (1e-5 scaled; the Coulomb term, constant near each state but the one at rest, left out of
    the differences). Solo's joint order is Pinocchio's."""
    path = os.path.join(ROOT, ROBOTS[name])
    model = pin.buildModelFromUrdf(path, pin.JointModelFreeFlyer())
    with open(os.path.join(HERE, name + "_joint_terms.json")) as f:
        terms = json.load(f)
    model.armature[6:] = terms["armature"]
    damping = np.concatenate([np.zeros(6), terms["damping"]])
    coulomb = np.concatenate([np.zeros(6), terms["friction"]])
    data = model.createData()
    viscous = lambda x, v, a: pin.rnea(model, data, x, v, a) + damping * v
    samples = []
    for s in terms["samples"]:
        q, v, a, tau_in = (np.array(s[k]) for k in ("q", "v", "a", "tau_in"))
        dtau_dq, dtau_dv, _ = (x.copy() for x in pin.computeRNEADerivatives(model, data, q, v, a))
        dtau_dv += np.diag(damping)
        assert scaled(central(lambda x: viscous(x, v, a), model, q), dtau_dq) < 1e-5
        fd_v = np.array([(viscous(q, v + e, a) - viscous(q, v - e, a)) / 2e-6 for e in np.eye(model.nv) * 1e-6]).T
        assert scaled(fd_v, dtau_dv) < 1e-5, scaled(fd_v, dtau_dv)
        friction = joint_friction(v, damping, coulomb)
        assert scaled(friction, np.array(s["friction"])) < 1e-15
        ddq = pin.aba(model, data, q, v, tau_in - friction).copy()
        assert scaled(ddq, np.array(s["a_fd"])) < 1e-15
        ddq_dq, ddq_dv, m_inv = (x.copy() for x in pin.computeABADerivatives(model, data, q, v, tau_in - friction))
        m_inv = symmetric(m_inv)
        assert scaled(m_inv @ np.array(s["M"]), np.eye(model.nv)) < 1e-10
        ddq_dv -= m_inv @ np.diag(damping)
        forward = lambda x, v: pin.aba(model, data, x, v, tau_in - coulomb * np.sign(s["v"]) - damping * v)
        assert scaled(central(lambda x: forward(x, v), model, q), ddq_dq) < 1e-5
        fd_v = np.array([(forward(q, v + e) - forward(q, v - e)) / 2e-6 for e in np.eye(model.nv) * 1e-6]).T
        assert scaled(fd_v, ddq_dv) < 1e-5, scaled(fd_v, ddq_dv)
        samples.append({"tau_in": tau_in.tolist(), "dtau_dq": dtau_dq.tolist(), "dtau_dv": dtau_dv.tolist(), "ddq": ddq.tolist(),
                        "ddq_dq": ddq_dq.tolist(), "ddq_dv": ddq_dv.tolist(), "ddq_dtau": m_inv.tolist()})
    result = {
        "robot": name + " with joint terms",
        "generator": "tests/data/floating/make.py (joint_terms_derivatives) with pinocchio %s"
                     % importlib.metadata.version("pin"),
        "states": name + "_joint_terms.json (q, v, a, tau_in of its samples, in order)",
        "conventions": "as derivatives'; dtau_* = computeRNEADerivatives(q, v, a) (armature in the model) with "
                       "dtau_dv + diag(0_6, damping); ddq = aba(q, v, tau_in - friction), ddq_dq = "
                       "computeABADerivatives(q, v, tau_in - friction)'s, ddq_dv its - Minv diag(0_6, damping), "
                       "ddq_dtau = Minv; Coulomb friction's derivative taken as 0 (flat away from v = 0)",
        "samples": samples,
    }
    write_json(name + "_joint_terms_derivatives.json", result)
    print(name, "joint terms derivatives:", len(samples), "samples")


# 6-D (surface) contacts, CONTACT_6D in LOCAL_WORLD_ALIGNED, read by `surface`: per robot its
# frames (those of FloatingKinematics, the leaf links in the file's order) and the contacts of
# each sample in turn, "surface" (CONTACT_6D), "point" (CONTACT_3D) or "none" per frame.
SURFACE = {
    "g1_29dof": {
        "frames": ["left_ankle_roll_link", "right_ankle_roll_link", "logo_link", "head_link", "imu_in_torso",
                   "d435_link", "mid360_link", "left_rubber_hand", "right_rubber_hand"],
        "contacts": [["surface", "surface"], ["surface", "point"], ["point", "surface"], ["surface", "none"],
                     ["point", "point"], ["surface", "surface", "none", "none", "none", "none", "none", "point"]],
    },
    "solo12": {
        "frames": ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT"],
        "contacts": [["surface", "point", "point", "point"], ["point", "surface", "none", "point"],
                     ["none", "none", "surface"], ["point", "none", "none", "surface"]],
    },
}


def surface(name, urdf):
    """Forward dynamics with contacts held at the states of `<name>.json` (its q, v, tau),
    written to `<name>_surface_contacts.json`: Pinocchio's `constraintDynamics` with a
    RigidConstraintModel CONTACT_6D (a foot held flat: its pose fixed) or CONTACT_3D (its origin
    fixed) in LOCAL_WORLD_ALIGNED at each frame of SURFACE[name] (no Baumgarte), ddq and
    lambda_c (a wrench [f, m] on the robot at the frame's origin in world axes per 6-D contact,
    a force per 3-D one), each checked against numpy's solve of the full KKT system
    [M J^T; J 0] [a; -lambda] = [tau - h; -gamma], with J the frames' LOCAL_WORLD_ALIGNED
    Jacobians (6 rows, or the 3 linear), gamma a 6-D contact's spatial acceleration at a = 0
    (getFrameAcceleration: the classical one less w x v in the linear part) and a 3-D contact's
    classical acceleration. Joints in the file's order."""
    model, data, states, order, names = load(name, urdf)
    _, iv = file_indices(names, order)
    frames = SURFACE[name]["frames"]
    ids = [model.getFrameId(f) for f in frames]
    samples = []
    worst = 0.0
    for k, s in enumerate(states):
        q = from_file_order(names, order, np.array(s["q"]), 7)
        v = from_file_order(names, order, np.array(s["v"]), 6)
        tau = from_file_order(names, order, np.array(s["tau"]), 6)
        kinds = SURFACE[name]["contacts"][k % len(SURFACE[name]["contacts"])]
        kinds = kinds + ["none"] * (len(frames) - len(kinds))
        held = [(i, kind) for i, kind in zip(ids, kinds) if kind != "none"]
        models, datas = rigid_contacts(model, data, held)
        ddq = pin.constraintDynamics(model, data, q, v, tau, models, datas).copy()
        lambda_c = data.lambda_c.copy()
        gap = kkt_gap(model, data, q, v, tau, held, ddq, lambda_c)
        worst = max(worst, gap)
        assert gap < 1e-9
        wrenches = np.zeros((len(frames), 6))
        at = 0
        for f, kind in enumerate(kinds):
            size = {"surface": 6, "point": 3, "none": 0}[kind]
            wrenches[f, :size] = lambda_c[at:at + size]
            at += size
        samples.append({"contacts": kinds, "a_contact": ddq[iv].tolist(),
                        "wrenches": wrenches.tolist()})
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (surface) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, tau of its samples, in order)",
        "frames": frames,
        "kkt_gap": worst,
        "conventions": "a_contact, wrenches = constraintDynamics(q, v, tau) with CONTACT_6D (surface) or CONTACT_3D "
                       "(point) in LOCAL_WORLD_ALIGNED at each frame (no Baumgarte); a wrench [f, m] on the robot at "
                       "the frame's origin in world axes per frame, its moment zero at a point, all zero at none; "
                       "a_contact's joints in the file's order",
        "samples": samples,
    }
    write_json(name + "_surface_contacts.json", result)
    print(name, "surface contacts:", len(samples), "samples, KKT gap %.1e" % worst)


# The C header's and the Python package's extras (`--kinematics --contacts --configuration`)
# beyond Solo 12, read by `extras`: per robot its frames (FloatingKinematics': the leaf links
# below a moving joint, in the file's order) and the point contacts held at each sample in turn.
EXTRAS = {
    "anymal_b": {
        "frames": ["LF_FOOT", "RF_FOOT", "LH_FOOT", "RH_FOOT"],
        "held": CONTACT_MASKS,
    },
    "g1_29dof": {
        "frames": SURFACE["g1_29dof"]["frames"],
        # Both feet, one, both and a hand, none, one foot and the other hand, the feet and the head.
        "held": [[True, True] + [False] * 7, [True] + [False] * 8,
                 [True, True] + [False] * 5 + [True, False], [False] * 9,
                 [False, True] + [False] * 5 + [True, False], [True, True, False, True] + [False] * 5],
    },
}


def extras(name, urdf):
    """The extras of the C header and the Python package beyond the table's methods at the 12
    states of `<name>.json`, in one file, `<name>_extras.json`, as Solo 12's three files
    (`kinematics`, `contacts` and step 6 of `make`) hold them: the kinematics (centre of mass,
    its Jacobian, A_G, dA_G v, each frame of EXTRAS[name]'s placement, Jacobian and classical
    acceleration at a = 0 in LOCAL and LOCAL_WORLD_ALIGNED), the contacts (rnea and aba with
    random wrenches and forces at the frames, constraintDynamics with CONTACT_3D in
    LOCAL_WORLD_ALIGNED at the frames `held`, no Baumgarte) and the configuration space
    (integrate, difference, dIntegrate and dDifference by both arguments at a random step `dv`
    and second configuration `q1`, sample 1's step's rotation 1e-9 rad). The states are read in
    the file's joint order, taken to Pinocchio's for the calls, and every result back (rows and
    columns). Checks as `kinematics`, `contacts` and `configuration_space` do; the constrained
    and external-force accelerations against numpy's solves to 1e-9 (the G1's M has a
    condition number up to 3.5e5)."""
    model, data, states, order, names = load(name, urdf)
    iq, iv = file_indices(names, order)
    columns = lambda m: np.asarray(m)[..., iv]
    frames = EXTRAS[name]["frames"]
    ids = [model.getFrameId(f) for f in frames]
    assert all(model.frames[i].name == f for i, f in zip(ids, frames)), frames
    mass = sum(i.mass for i in model.inertias)
    rng = np.random.default_rng(SEED + 4)
    samples = []
    for k, s in enumerate(states):
        q = from_file_order(names, order, np.array(s["q"]), 7)
        v, a, tau = (from_file_order(names, order, np.array(s[key]), 6) for key in ("v", "a", "tau"))
        out = {"tau": s["tau"]}
        out.update(kinematics_at(model, data, q, v, ids, frames, mass, columns))
        out.update(contacts_at(model, data, (q, v, a, tau), ids, EXTRAS[name]["held"][k % 6], rng, 1e-9, iv))
        # The configuration space, its inputs drawn in the file's order.
        dv, q1 = configuration_step(rng, model, k)
        q_next, dq, jacobians = configuration_at(model, q, from_file_order(names, order, dv, 6),
                                                 from_file_order(names, order, q1, 7))
        out.update({"dv": dv.tolist(), "q1": q1.tolist(), "q_next": q_next[iq].tolist(), "dq": dq[iv].tolist()})
        out.update({key: j[np.ix_(iv, iv)].tolist() for key, j in jacobians.items()})
        samples.append(out)
    result = {
        "robot": name,
        "generator": "tests/data/floating/make.py (extras) with pinocchio %s" % importlib.metadata.version("pin"),
        "states": name + ".json (q, v, a, tau of its samples, in order)",
        "frames": frames,
        "mass": mass,
        "seed": SEED + 4,
        "conventions": "as solo12_kinematics.json, solo12_contacts.json and solo12.json's configuration space, "
                       "joints (rows, columns) in the file's order",
        "samples": samples,
    }
    write_json(name + "_extras.json", result)
    print(name, "extras:", len(samples), "samples,", len(frames), "frames")


if __name__ == "__main__":
    for name, urdf in ROBOTS.items():
        make(name, urdf)
    for name, urdf in ROBOTS.items():
        if name in KINEMATICS:
            kinematics(name, urdf)
    contacts("solo12", ROBOTS["solo12"])
    for name in CONTACT_FD:
        contact_fd(name, ROBOTS[name])
    for name, urdf in ROBOTS.items():
        if name in DERIVATIVES:
            derivatives(name, urdf)
    for name in REGRESSOR:
        regressor(name, ROBOTS[name])
    for name, urdf in FRICTION.items():
        friction_data(name, urdf)
    joint_terms("solo12")
    joint_terms_derivatives("solo12")
    for name in SURFACE:
        surface(name, ROBOTS[name])
    for name in EXTRAS:
        extras(name, ROBOTS[name])

    # Mimic joints on the free flyer (Talos with its grippers): `mimic.py`, which reads this one.
    from mimic import MIMIC, mimic_data
    for name in MIMIC:
        mimic_data(name)

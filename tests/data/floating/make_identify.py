#!/usr/bin/env python3
"""Measurements of Solo 12 on its free-flying base for `dynamics identify --floating` (issue
43), from Pinocchio 4.1's `rnea` with the URDF's own parameters (the known ones).

Along a smooth motion given in closed form, sampled at RATE Hz for DURATION s:

* the base origin p(t) (world) and the base orientation R(t) = Rz(yaw) Ry(pitch) Rx(roll), and
  each joint angle, each a constant plus three sines of their own frequency and phase;
* v = [R^T p', w_b] (the base's twist in its frame, Pinocchio's free-flyer v; the body rates of
  Z-Y-X angles written out) and a = v' (its time derivative in the same coordinates,
  R^T p'' - w_b x R^T p' and w_b' by the chain rule), then the joint rates; the script checks v
  and a against central differences of `pin.difference` along the samples of q and of v at
  +-1e-5 s (1e-6 scaled: a wrong frame or a sign is off by O(1));
* tau = rnea(q, v, a), every row: the base's six (the wrench on it, in its frame) then the joint
  torques.

It writes `solo12_identify.csv` (`t, q1..q19, v1..v18, a1..a18, tau1..tau18`, the joints in the
file's order, as `make.py` writes them; 17 significant digits) and `solo12_identify.json`: the
numerical ranks of Pinocchio's regressor `computeJointTorqueRegressor` stacked over the samples,
all 18 rows and the joints' 12 alone (SVD; singular values below RANK_TOLERANCE of the largest
are zero), which are the counts of base parameters identifiable from these data.

Usage, from the repository root (Pinocchio 4.1, the `pin` wheel; imports `make.py`'s helpers):

    target/python-venv/bin/python tests/data/floating/make_identify.py
"""

import importlib.metadata
import os

import numpy as np
import pinocchio as pin

from make import HERE, ROBOTS, ROOT, file_indices, file_order, from_file_order, scaled, write_json

NAME = "solo12"
SEED = 20261130
RATE = 500.0
DURATION = 2.0
RANK_TOLERANCE = 1e-9
CHECK_STEP = 1e-5


def sines(rng, count, amplitude, frequencies):
    """`count` signals, each a constant plus three sines: (values, first, second) at time t."""
    offset = rng.uniform(-amplitude, amplitude, count)
    amp = rng.uniform(0.2, 1.0, (count, 3)) * amplitude / 2
    omega = 2 * np.pi * rng.uniform(*frequencies, (count, 3))
    phase = rng.uniform(0, 2 * np.pi, (count, 3))

    def at(t):
        s, c = np.sin(omega * t + phase), np.cos(omega * t + phase)
        return (offset + np.sum(amp * s, axis=1), np.sum(amp * omega * c, axis=1),
                -np.sum(amp * omega ** 2 * s, axis=1))
    return at


def base_motion(position, angles, t):
    """The base's quaternion [x, y, z, w], origin, twist in its frame and its derivative at t."""
    p, dp, ddp = position(t)
    (yaw, pitch, roll), (dy, dp_, dr), (ddy, ddp_, ddr) = angles(t)
    rot = pin.utils.rotate("z", yaw) @ pin.utils.rotate("y", pitch) @ pin.utils.rotate("x", roll)
    sb, cb, sg, cg = np.sin(pitch), np.cos(pitch), np.sin(roll), np.cos(roll)
    # Body rates of Z-Y-X angles, and their time derivative by the chain rule.
    w = np.array([dr - dy * sb, dp_ * cg + dy * cb * sg, -dp_ * sg + dy * cb * cg])
    dw = np.array([
        ddr - ddy * sb - dy * cb * dp_,
        ddp_ * cg - dp_ * sg * dr + ddy * cb * sg - dy * sb * dp_ * sg + dy * cb * cg * dr,
        -ddp_ * sg - dp_ * cg * dr + ddy * cb * cg - dy * sb * dp_ * cg - dy * cb * sg * dr,
    ])
    linear = rot.T @ dp
    dlinear = rot.T @ ddp - np.cross(w, linear)
    quaternion = pin.Quaternion(rot).coeffs()
    return quaternion, p, np.concatenate([linear, w]), np.concatenate([dlinear, dw])


def state(motion, t):
    """q (Pinocchio's order: nq), v and a (nv) at t, the joints from `motion`."""
    position, angles, joints = motion
    quaternion, p, vb, ab = base_motion(position, angles, t)
    qj, vj, aj = joints(t)
    return np.concatenate([p, quaternion, qj]), np.concatenate([vb, vj]), np.concatenate([ab, aj])


def check_derivatives(model, motion, times):
    """v and a against central differences along the configuration space, 1e-6 scaled."""
    worst = 0.0
    for t in times:
        q, v, a = state(motion, t)
        (q0, v0, _), (q1, v1, _) = state(motion, t - CHECK_STEP), state(motion, t + CHECK_STEP)
        # The tangent at q to q0 and q1: v by the central difference of the two.
        dv = (pin.difference(model, q, q1) - pin.difference(model, q, q0)) / (2 * CHECK_STEP)
        da = (v1 - v0) / (2 * CHECK_STEP)
        worst = max(worst, scaled(dv, v), scaled(da, a))
    assert worst < 1e-6, worst
    return worst


def main():
    urdf = os.path.join(ROOT, ROBOTS[NAME])
    model = pin.buildModelFromUrdf(urdf, pin.JointModelFreeFlyer())
    data = model.createData()
    _, order = file_order(urdf)
    names = list(model.names)[2:]
    n = model.nv - 6
    rng = np.random.default_rng(SEED)
    position = sines(rng, 3, 0.3, (0.3, 1.5))
    angles = sines(rng, 3, 1.2, (0.2, 1.0))
    pinocchio_joints = sines(rng, n, 1.5, (0.3, 2.0))
    motion = (position, angles, pinocchio_joints)
    count = int(round(RATE * DURATION)) + 1
    times = [k / RATE for k in range(count)]
    worst = check_derivatives(model, motion, times)
    iq, iv = file_indices(names, order)
    rows, stacked = [], []
    previous = None
    for t in times:
        q, v, a = state(motion, t)
        # The quaternion's sign kept continuous along the motion (either is the rotation).
        if previous is not None and np.dot(previous, q[3:7]) < 0:
            q[3:7] = -q[3:7]
        previous = q[3:7].copy()
        tau = pin.rnea(model, data, q, v, a)
        y = pin.computeJointTorqueRegressor(model, data, q, v, a).copy()
        stacked.append(y)
        assert np.allclose(from_file_order(names, order, q[iq], 7), q)
        rows.append([t] + list(q[iq]) + list(v[iv]) + list(a[iv]) + list(tau[iv]))
    stacked = np.array(stacked)

    def rank(y):
        singular = np.linalg.svd(y, compute_uv=False)
        r = int(np.sum(singular > RANK_TOLERANCE * singular[0]))
        gap = [float(singular[r - 1] / singular[0]), float(singular[r] / singular[0]) if r < len(singular) else 0.0]
        return r, gap
    rank_all, gap_all = rank(stacked.reshape(-1, stacked.shape[2]))
    rank_joints, gap_joints = rank(stacked[:, 6:, :].reshape(-1, stacked.shape[2]))
    header = (["t"] + ["q%d" % (i + 1) for i in range(n + 7)] + ["v%d" % (i + 1) for i in range(n + 6)]
              + ["a%d" % (i + 1) for i in range(n + 6)] + ["tau%d" % (i + 1) for i in range(n + 6)])
    with open(os.path.join(HERE, NAME + "_identify.csv"), "w") as f:
        f.write("# Solo 12 on its free-flying base: Pinocchio %s rnea along a smooth motion "
                "(tests/data/floating/make_identify.py)\n" % importlib.metadata.version("pin"))
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(repr(float(x)) for x in r) + "\n")
    result = {
        "robot": NAME,
        "generator": "tests/data/floating/make_identify.py with pinocchio %s" % importlib.metadata.version("pin"),
        "csv": NAME + "_identify.csv",
        "samples": count,
        "rate_hz": RATE,
        "joints": order,
        "rank_all_rows": rank_all,
        "rank_all_rows_gap": gap_all,
        "rank_joint_rows": rank_joints,
        "rank_joint_rows_gap": gap_joints,
        "rank_tolerance": RANK_TOLERANCE,
        "derivatives_check": worst,
    }
    write_json(NAME + "_identify.json", result)
    print(NAME, "identify:", count, "samples, rank", rank_all, gap_all, "joint rows", rank_joints, gap_joints,
          "derivatives %.1e" % worst)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""The joint torque regressor of the Panda with its mimic finger, from Pinocchio 4.1's regressor
of the free model (`robots/urdf/trees/panda_free_fingers.urdf`: the same URDF without
`<mimic>`, made by `free_fingers.py`), projected onto the reduced coordinates.

`panda_finger_joint2` follows `panda_finger_joint1` (k = 1, o = 0): with G the 9 x 8 map,
q_full = G q + o, qd_full = G qd, qdd_full = G qdd, and the reduced regressor is
Y = G^T Y_full(q_full, qd_full, qdd_full), 8 rows and still 10 columns per link (90): each
link keeps its own parameters. `pi` is every body's `toDynamicParameters()` (about the origin of
the joint frame, the URDF link frame, in its axes; the hand merged into link 7), and
`tau = G^T rnea(q_full, qd_full, qdd_full)` (no friction: the rigid bodies' part), so that
Y pi = tau (the script checks it, `residual`).

Pinocchio's joint order is the front end's for the Panda (one chain, then the two fingers).
16 states: seed 20261129, q in [-pi, pi] (the fingers' in [0, 0.04]), qd in [-2, 2], qdd in
[-5, 5]. Usage, from the repository root, with Pinocchio 4.1.0 and numpy:

    /work/main/target/python-venv/bin/python tests/data/trees/mimic_regressor.py

writes `tests/data/trees/panda_fingers_regressor.json`, byte for byte the same on every run.
"""

import json
import os

import numpy as np
import pinocchio as pin

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
URDF = "robots/urdf/trees/panda_free_fingers.urdf"
OUT = os.path.join(ROOT, "tests/data/trees/panda_fingers_regressor.json")
FOLLOWER, FOLLOWED, K, O = "panda_finger_joint2", "panda_finger_joint1", 1.0, 0.0
SAMPLES = 16


def main():
    model = pin.buildModelFromUrdf(os.path.join(ROOT, URDF))
    data = model.createData()
    names = list(model.names)[1:]
    assert model.nq == model.nv == len(names) == 9, names
    full, reduced = len(names), len(names) - 1
    follower, followed = names.index(FOLLOWER), names.index(FOLLOWED)
    coordinates = [i for i in range(full) if i != follower]
    G = np.zeros((full, reduced))
    for a, i in enumerate(coordinates):
        G[i, a] = 1.0
    G[follower, coordinates.index(followed)] = K
    offset = np.zeros(full)
    offset[follower] = O
    pi = np.concatenate([model.inertias[i + 1].toDynamicParameters() for i in range(full)])
    rng = np.random.default_rng(20261129)
    samples, residual = [], 0.0
    for _ in range(SAMPLES):
        q = rng.uniform(-np.pi, np.pi, reduced)
        q[-1] = rng.uniform(0.0, 0.04)
        qd, qdd = rng.uniform(-2, 2, reduced), rng.uniform(-5, 5, reduced)
        x = (G @ q + offset, G @ qd, G @ qdd)
        Y = G.T @ pin.computeJointTorqueRegressor(model, data, *x)
        tau = G.T @ pin.rnea(model, data, *x)
        residual = max(residual, float(np.max(np.abs(Y @ pi - tau)) / max(1.0, np.max(np.abs(tau)))))
        samples.append({"q": q.tolist(), "qd": qd.tolist(), "qdd": qdd.tolist(),
                        "Y": Y.tolist(), "tau": tau.tolist()})
    assert residual < 1e-12, residual
    out = {
        "robot": "robots/urdf/panda.urdf (base panda_link0)",
        "generator": f"tests/data/trees/mimic_regressor.py with pinocchio {pin.__version__} "
                     f"(computeJointTorqueRegressor on {URDF}, projected)",
        "joints": names,
        "coordinates": [names[i] for i in coordinates],
        "mimic": {"joint": FOLLOWER, "follows": FOLLOWED, "multiplier": K, "offset": O},
        "G": G.tolist(),
        "rule": "q_full = G q + offset; Y = G^T Y_full(q_full, G qd, G qdd); tau = G^T rnea = Y pi",
        "pi": pi.tolist(),
        "residual": residual,
        "samples": samples,
    }
    # One line per entry, a sample per line: diffs stay readable.
    samples = out.pop("samples")
    lines = [f" {json.dumps(k)}: {json.dumps(v)}" for k, v in out.items()]
    lines.append(' "samples": [\n' + ",\n".join("  " + json.dumps(x) for x in samples) + "\n ]")
    with open(OUT, "w", encoding="utf-8") as f:
        f.write("{\n" + ",\n".join(lines) + "\n}\n")


if __name__ == "__main__":
    main()

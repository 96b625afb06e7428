"""What the reference-data scripts share (`panda/`, `frames/`, `urdf/` make.py): the 20 states
of a sample set, Pinocchio's quantities at a state, the identities they must satisfy, the
scaled error measure and the rounding of the numbers written.

Imported by path: `sys.path.insert(0, <this folder>)` then `import pinocchio_data`.
"""

import math

import numpy as np
import pinocchio as pin

TOLERANCE = 1e-12


def scaled_error(a, b):
    """max |a - b| / max(1, max |b|)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    return float(np.max(np.abs(a - b)) / max(1.0, float(np.max(np.abs(b)))))


def rounded(x):
    """Numbers, arrays and lists rounded to 15 significant digits for the JSON files."""
    if isinstance(x, np.ndarray):
        return rounded(x.tolist())
    if isinstance(x, list):
        return [rounded(v) for v in x]
    return float(f"{float(x):.15g}")


def symmetric(M):
    """The full matrix of the upper triangle Pinocchio fills."""
    return np.triu(M) + np.triu(M, 1).T


def samples(n, rng):
    """20 states of n joints: all zero, q only, q and qd, then 17 random ones."""
    out = []
    for k in range(20):
        q = rng.uniform(-math.pi, math.pi, n)
        qd = rng.uniform(-2.0, 2.0, n)
        qdd = rng.uniform(-5.0, 5.0, n)
        if k == 0:
            q, qd, qdd = np.zeros(n), np.zeros(n), np.zeros(n)
        elif k == 1:
            qd, qdd = np.zeros(n), np.zeros(n)
        elif k == 2:
            qdd = np.zeros(n)
        out.append((q, qd, qdd))
    return out


def quantities(model, frame, q, qd, qdd):
    """tau, M, h, g, C, both energies, and the pose and base-axes Jacobian of `frame`."""
    data = model.createData()
    tau = pin.rnea(model, data, q, qd, qdd).copy()
    M = symmetric(pin.crba(model, data, q))
    h = pin.nonLinearEffects(model, data, q, qd).copy()
    g = pin.computeGeneralizedGravity(model, data, q).copy()
    C = pin.computeCoriolisMatrix(model, data, q, qd).copy()
    ke = pin.computeKineticEnergy(model, data, q, qd)
    pe = pin.computePotentialEnergy(model, data, q)
    pin.forwardKinematics(model, data, q)
    pin.updateFramePlacements(model, data)
    pin.computeJointJacobians(model, data, q)
    fid = model.getFrameId(frame)
    pose = data.oMf[fid].homogeneous.copy()
    jac = pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED).copy()
    return dict(tau=tau, M=M, h=h, g=g, C=C, kinetic_energy=ke, potential_energy=pe,
                ee_pose=pose, jacobian=jac)


def identities(x, qd, qdd):
    """tau = M qdd + h, h = C qd + g, KE = qd^T M qd / 2: the worst scaled error."""
    worst = scaled_error(x["M"] @ qdd + x["h"], x["tau"])
    worst = max(worst, scaled_error(x["C"] @ qd + x["g"], x["h"]))
    worst = max(worst, scaled_error(0.5 * qd @ x["M"] @ qd, x["kinetic_energy"]))
    assert worst < TOLERANCE, f"identities: {worst:e}"
    return worst

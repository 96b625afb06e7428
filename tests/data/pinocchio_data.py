"""What the reference-data scripts share (`panda/`, `frames/`, `urdf/`, `trees/` make.py): the 20 states
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


def dynamics(model, q, qd, qdd):
    """tau, M, h, g, C and both energies at a state."""
    data = model.createData()
    tau = pin.rnea(model, data, q, qd, qdd).copy()
    M = symmetric(pin.crba(model, data, q))
    h = pin.nonLinearEffects(model, data, q, qd).copy()
    g = pin.computeGeneralizedGravity(model, data, q).copy()
    C = pin.computeCoriolisMatrix(model, data, q, qd).copy()
    ke = pin.computeKineticEnergy(model, data, q, qd)
    pe = pin.computePotentialEnergy(model, data, q)
    return dict(tau=tau, M=M, h=h, g=g, C=C, kinetic_energy=ke, potential_energy=pe)


def frame_kinematics(model, frames, q):
    """Each frame's pose (4x4, in the base frame) and geometric Jacobian (rows [v; w] in base
    axes: LOCAL_WORLD_ALIGNED), by frame name (a link's BODY frame when names repeat)."""
    data = model.createData()
    pin.forwardKinematics(model, data, q)
    pin.updateFramePlacements(model, data)
    pin.computeJointJacobians(model, data, q)
    out = {}
    for frame in frames:
        fid = model.getFrameId(frame, pin.FrameType.BODY)
        if fid >= model.nframes:
            fid = model.getFrameId(frame)
        out[frame] = dict(
            pose=data.oMf[fid].homogeneous.copy(),
            jacobian=pin.getFrameJacobian(model, data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED).copy())
    return out


def quantities(model, frame, q, qd, qdd):
    """tau, M, h, g, C, both energies, and the pose and base-axes Jacobian of `frame`."""
    x = dynamics(model, q, qd, qdd)
    tip = frame_kinematics(model, [frame], q)[frame]
    x.update(ee_pose=tip["pose"], jacobian=tip["jacobian"])
    return x


def identities(x, qd, qdd):
    """tau = M qdd + h, h = C qd + g, KE = qd^T M qd / 2: the worst scaled error."""
    worst = scaled_error(x["M"] @ qdd + x["h"], x["tau"])
    worst = max(worst, scaled_error(x["C"] @ qd + x["g"], x["h"]))
    worst = max(worst, scaled_error(0.5 * qd @ x["M"] @ qd, x["kinetic_energy"]))
    assert worst < TOLERANCE, f"identities: {worst:e}"
    return worst


def central_differences(mass, potential, q, qd, C, g, eps=1e-6):
    """Mdot = C + C^T along qd and g = dP/dq by central differences, for any coordinates:
    `mass(q)` and `potential(q)` are M and P as functions of them. The worst scaled error."""
    mdot = (mass(q + eps * qd) - mass(q - eps * qd)) / (2 * eps)
    grad = np.array([(potential(q + eps * e) - potential(q - eps * e)) / (2 * eps) for e in np.eye(len(q))])
    worst = max(scaled_error(mdot, C + C.T), scaled_error(grad, g))
    assert worst < 1e-7, f"finite differences: {worst:e}"
    return worst

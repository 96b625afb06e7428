"""Reference data for identification: the joint torque regressor and base-parameter counts.

Run: bench/.venv/bin/python tests/data/regressor/make.py  (Pinocchio 4.1.0, numpy: bench/run
creates that environment with the `pin` wheel; any with `pip install pin==4.1.0 numpy` works
too). About 10 s.

1. Per robot, <robot>.json: 10 seeded samples of (q, qd, qdd) with Pinocchio's
   computeJointTorqueRegressor. The robots: those of tests/data/forward/make.py (imported from it,
   with its model_from_dh: the reference robots and the hand-less Panda), plus ur5, which
   forward/ leaves out only because its M is singular (the regressor needs no inverse), and the
   URDF robots of tests/data/urdf/ (their model rebuilt from the `pinocchio_model` record of
   <robot>.json by urdf/make.py's rebuild, which that script checks against the URDF loader).

   Pinocchio's columns of joint i are the dynamic parameters of body i about the origin of
   *Pinocchio's joint frame i*, in its axes (Inertia::toDynamicParameters, [m, m cx, m cy, m cz,
   Ixx, Ixy, Iyy, Ixz, Iyz, Izz], inertia about the frame's origin). For a modified (Craig) D-H
   table and for a URDF, that frame is the project's link frame i. For a standard D-H table it
   is not: forward/make.py places joint i at Rotz(theta) Transz(d) after the previous link frame
   and puts the body at jMl = Transx(a) Rotx(alpha) in it, so the link frame i is jMl from the
   joint frame. The parameters move linearly, pi_joint = T pi_link (T per link, from jMl), so
   the project's regressor is Y = Y_pinocchio T (block diagonal T). Both are written.

   Beside Y (n x 10n), per joint i four more columns Y_extra (n x 4n, in the order [actuator
   inertia, viscous, Coulomb, offset] of joint i): e_i qdd_i, e_i qd_i, e_i sign(qd_i) (sign(0)
   = 0) and e_i, with pi_extra = [actuator_inertia, friction_viscous, friction_coulomb,
   friction_offset] of the description (0 where absent; for the URDF robots model.armature,
   <dynamics damping> and <dynamics friction>, offset 0). Springs k (q - q0) are linear in (k,
   k q0) but not in the inertial parameters: they are left out, and `tau` is the project's
   inverse dynamics minus the spring torque (none of these robots has a spring).

   Checks before writing, per sample (scaled as max|a - b| / max(1, max|b|), to 1e-12):
   Y_pinocchio pi_pinocchio = rnea of the model without armature; T pi_link = pi_pinocchio (the
   description's parameters, moved); Y pi_link = the same rnea; [Y | Y_extra] [pi; pi_extra] =
   rnea with armature + friction = tau. Per robot, tau at the samples of the robot's existing
   data file (reference/data, panda/data.json, urdf/<robot>.json: their tau includes the actuator
   inertia; the URDF files' friction is added) equals that file's tau (rounded there to 15
   digits).

2. base_counts.json: per robot, the numerical rank of the regressor stacked over 1000 seeded
   samples (q in [-pi, pi], qd in [-2, 2], qdd in [-5, 5]), by SVD of the nonzero columns scaled
   to unit norm: rigid body only; with the actuator (rotor) inertia columns; with viscous and
   Coulomb friction on every joint too; and with the offsets too. A column is zero if its norm is
   below ZERO times the largest column norm; the rank counts singular values above RANK times
   the largest; the gap is the ratio of the last one kept to the first one dropped. PUMA 560 is
   the robot of robots/puma560.toml, checked to be the reference puma560.json.

3. In base_counts.json, for PUMA 560 (and the Panda), the numerical grouping of the 52-column
   set, in link-frame parameters: the zero columns; the basis chosen greedily in a fixed order (a
   column joins it if it is not in the span of those before it: its residual after projection,
   scaled, is above RANK); and for every other nonzero column its coefficients on the basis
   (least squares on the stacked columns; the fit's residual is checked, and Y_b pi_b = Y pi).
   The order: link by link, each link's columns from Izz back to m, then per joint the actuator
   inertia, viscous, Coulomb columns. It keeps a link's inertias before its first moments and mass, as the
   classical grouping rules (Gautier and Khalil) do, and gives coefficients of at most 1 in
   magnitude, products of the D-H lengths (toDynamicParameters' own order gives 1 / a3^2 on the
   PUMA 560). The basis is a choice; the relations (the null space) are not.
"""

import importlib.util
import json
import math
import pathlib
import tomllib

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE.parent
ROOT = DATA.parent.parent


def module(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


forward = module(DATA / "forward" / "make.py", "forward_make")
urdf = module(DATA / "urdf" / "make.py", "urdf_make")

DH_ROBOTS = sorted((DATA / "reference" / "robots").glob("*.json")) + [DATA / "panda" / "robot.json"]
URDF_ROBOTS = ["ur5", "ur10", "panda", "z1", "so101"]
PARAMETERS = ["m", "mx", "my", "mz", "Ixx", "Ixy", "Iyy", "Ixz", "Iyz", "Izz"]
EXTRA = ["Ia", "fv", "fc", "f0"]
SAMPLES = 10
STACK = 1000
TOLERANCE = 1e-12
ZERO = 1e-10
RANK = 1e-8
GROUPED = ["puma560", "panda"]


def skew(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def moved(pi, placement):
    """Dynamic parameters about frame l to those about frame j, where jMl = placement: linear in
    pi (m, h = m c, I about the origin). c_j = R c_l + p, so h_j = R h + m p and
    I_j = R I R^T - S(R h) S(p) - S(p) S(R h) - m S(p)^2."""
    m, h = pi[0], np.asarray(pi[1:4])
    xx, xy, yy, xz, yz, zz = pi[4:]
    inertia = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    r, p = placement.rotation, placement.translation
    rh = r @ h
    out = r @ inertia @ r.T - skew(rh) @ skew(p) - skew(p) @ skew(rh) - m * skew(p) @ skew(p)
    return np.array([m, *(rh + m * p), out[0, 0], out[0, 1], out[1, 1], out[0, 2], out[1, 2], out[2, 2]])


def link_to_joint(placement):
    """T with pi_joint = T pi_link (10 x 10)."""
    return np.array([moved(e, placement) for e in np.eye(10)]).T


class Robot:
    """A Pinocchio model, the project's link-frame parameters and the extra coefficients."""

    def __init__(self, name, source, model, placements, pi_link, extra, reference):
        self.name, self.source, self.model = name, source, model
        self.n = model.nv
        self.T = np.zeros((10 * self.n, 10 * self.n))
        for i, placement in enumerate(placements):
            self.T[10 * i : 10 * i + 10, 10 * i : 10 * i + 10] = link_to_joint(placement)
        self.pi_link, self.extra, self.reference = pi_link, extra, reference
        self.rigid = model.copy()
        self.rigid.armature = np.zeros(self.n)
        self.pi_pinocchio = np.concatenate([model.inertias[i].toDynamicParameters() for i in range(1, model.njoints)])
        gap = forward.scaled(self.T @ pi_link, self.pi_pinocchio)
        assert gap < TOLERANCE, (name, "T pi_link", gap)
        self.standard = any(not np.allclose(p.homogeneous, np.eye(4)) for p in placements)

    def regressor(self, q, qd, qdd):
        """Pinocchio's Y, the link-frame Y and Y_extra."""
        y = pin.computeJointTorqueRegressor(self.rigid, self.rigid.createData(), q, qd, qdd).copy()
        extra = np.zeros((self.n, 4 * self.n))
        for i in range(self.n):
            extra[i, 4 * i : 4 * i + 4] = [qdd[i], qd[i], np.sign(qd[i]), 1.0]
        return y, y @ self.T, extra

    def tau(self, q, qd, qdd):
        """The project's inverse dynamics (actuator inertia, friction; springs left out)."""
        tau = pin.rnea(self.model, self.model.createData(), q, qd, qdd).copy()
        fv, fc, f0 = self.extra[1::4], self.extra[2::4], self.extra[3::4]
        return tau + fv * qd + fc * np.sign(qd) + f0


def dh_robot(path):
    desc = json.loads(path.read_text())
    name = path.stem if path.parent.name == "robots" else path.parent.name
    model = forward.model_from_dh(desc)
    modified = desc.get("convention", "standard") == "modified"
    placements, pi_link, extra = [], [], []
    for j in desc["joints"]:
        shift, twist = forward.se3("x", 0.0, [j["a"], 0, 0]), forward.se3("x", j["alpha"], [0, 0, 0])
        placements.append(pin.SE3.Identity() if modified else shift * twist)
        ixx, iyy, izz, ixy, ixz, iyz = j["inertia"]
        inertia = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        pi_link.append(pin.Inertia(j["mass"], np.array(j["com"], dtype=float), inertia).toDynamicParameters())
        assert j.get("spring_stiffness", 0.0) == 0.0, (name, "springs")
        keys = ["actuator_inertia", "friction_viscous", "friction_coulomb", "friction_offset"]
        extra += [j.get(k, 0.0) for k in keys]
    reference = json.loads(forward.reference_file(path).read_text())["samples"]
    return Robot(name, str(path.relative_to(DATA)), model, placements, np.concatenate(pi_link), np.array(extra),
                 [(s["q"], s["qd"], s["qdd"], s["tau"]) for s in reference])


def urdf_robot(name):
    record = json.loads((DATA / "urdf" / f"{name}.json").read_text())
    model = urdf.rebuild(record["pinocchio_model"])
    n = model.nv
    pi_link = np.concatenate([model.inertias[i].toDynamicParameters() for i in range(1, model.njoints)])
    extra = np.zeros(4 * n)
    extra[0::4], extra[1::4], extra[2::4] = model.armature, record["damping"], record["friction"]
    reference = [(s["q"], s["qd"], s["qdd"], np.add(s["tau"], s["friction"])) for s in record["samples"]]
    return Robot(f"{name}_urdf", f"urdf/{name}.json", model, [pin.SE3.Identity()] * n, pi_link, extra, reference)


def compact(value, indent=0):
    """JSON with one line per list of numbers (a vector or a matrix row)."""
    pad = " " * (indent + 1)
    if isinstance(value, dict):
        items = [f"{pad}{json.dumps(k)}: {compact(v, indent + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    if isinstance(value, list) and value and isinstance(value[0], (dict, list)):
        return "[\n" + ",\n".join(pad + compact(v, indent + 1) for v in value) + "\n" + " " * indent + "]"
    return json.dumps(value)


def matrix(a):
    return [row.tolist() for row in np.asarray(a)]


def names(n, extras=EXTRA):
    return [f"{p}{i + 1}" for i in range(n) for p in PARAMETERS], [f"{p}{i + 1}" for i in range(n) for p in extras]


def samples(robot, rng):
    out = []
    worst = 0.0
    for k in range(SAMPLES):
        q, qd = rng.uniform(-math.pi, math.pi, robot.n), rng.uniform(-2, 2, robot.n)
        qdd = rng.uniform(-5, 5, robot.n)
        if k == 0:
            qd[::2] = 0.0  # sign(0) = 0: no Coulomb torque at rest
        y_pin, y, extra = robot.regressor(q, qd, qdd)
        rigid = pin.rnea(robot.rigid, robot.rigid.createData(), q, qd, qdd)
        tau = robot.tau(q, qd, qdd)
        errors = [
            forward.scaled(y_pin @ robot.pi_pinocchio, rigid),
            forward.scaled(y @ robot.pi_link, rigid),
            forward.scaled(y @ robot.pi_link + extra @ robot.extra, tau),
        ]
        assert max(errors) < TOLERANCE, (robot.name, k, errors)
        worst = max(worst, *errors)
        sample = {"q": q.tolist(), "qd": qd.tolist(), "qdd": qdd.tolist(), "tau": tau.tolist(), "Y": matrix(y)}
        if robot.standard:
            sample["Y_pinocchio"] = matrix(y_pin)
        sample["Y_extra"] = matrix(extra)
        out.append(sample)
    for q, qd, qdd, tau in robot.reference:
        gap = forward.scaled(robot.tau(np.array(q), np.array(qd), np.array(qdd)), tau)
        assert gap < 1e-12, (robot.name, "reference tau", gap)
    return out, worst


def write(robot, rng):
    out, worst = samples(robot, rng)
    rigid, extra = names(robot.n)
    doc = {
        "robot": robot.source,
        "generator": f"tests/data/regressor/make.py with pinocchio {pin.__version__}",
        "n": robot.n,
        "parameters": rigid,
        "pi": robot.pi_link.tolist(),
        "extra_parameters": extra,
        "pi_extra": robot.extra.tolist(),
    }
    if robot.standard:
        doc["pi_pinocchio"] = robot.pi_pinocchio.tolist()
        doc["link_to_joint"] = [matrix(robot.T[10 * i : 10 * i + 10, 10 * i : 10 * i + 10]) for i in range(robot.n)]
    doc["notes"] = (
        "Y pi = rnea without actuator inertia; [Y | Y_extra] [pi; pi_extra] = tau (actuator inertia and "
        "friction, sign(0) = 0; no springs); pi about the link frame's origin, in its axes"
        + ("; Y_pinocchio = computeJointTorqueRegressor, about Pinocchio's joint frames: "
           "pi_pinocchio = T pi and Y = Y_pinocchio T, T block diagonal of link_to_joint" if robot.standard else
           "; the link frames are Pinocchio's joint frames: Y = computeJointTorqueRegressor")
        + f"; largest scaled error {worst:.1e}"
    )
    doc["samples"] = out
    (HERE / f"{robot.name}.json").write_text(compact(doc) + "\n")
    return worst


def stacked(robot, rng, count=STACK):
    """The stacked [Y | Y_extra] over count samples, link frames."""
    rows = []
    for _ in range(count):
        q, qd = rng.uniform(-math.pi, math.pi, robot.n), rng.uniform(-2, 2, robot.n)
        qdd = rng.uniform(-5, 5, robot.n)
        _, y, extra = robot.regressor(q, qd, qdd)
        rows.append(np.hstack([y, extra]))
    return np.vstack(rows)


def rank(w):
    """Zero columns, rank and the singular values at the gap, of w's columns scaled to unit norm."""
    norms = np.linalg.norm(w, axis=0)
    zero = norms <= ZERO * norms.max()
    s = np.linalg.svd(w[:, ~zero] / norms[~zero], compute_uv=False)
    r = int(np.sum(s > RANK * s[0]))
    last, next_ = s[r - 1], (s[r] if r < len(s) else 0.0)
    return {
        "columns": int(w.shape[1]),
        "zero_columns": int(zero.sum()),
        "rank": r,
        "sigma_max": float(s[0]),
        "sigma_last_kept": float(last),
        "sigma_first_dropped": float(next_),
        "gap": float(last / next_) if next_ > 0 else None,
    }


def selections(n):
    """Column sets of [Y | Y_extra]: rigid body, + actuator inertia, + viscous and Coulomb, + offset."""
    rigid = list(range(10 * n))
    extra = lambda kinds: [10 * n + 4 * i + k for i in range(n) for k in kinds]
    return {
        "rigid_body": rigid,
        "with_actuator_inertia": rigid + extra([0]),
        "with_viscous_and_coulomb": rigid + extra([0, 1, 2]),
        "with_offset": rigid + extra([0, 1, 2, 3]),
    }


def grouping(w, labels, pi):
    """Zero columns, the greedy basis in column order, and each dependent column's coefficients."""
    norms = np.linalg.norm(w, axis=0)
    zero = norms <= ZERO * norms.max()
    basis, q = [], np.zeros((w.shape[0], 0))
    for j in np.flatnonzero(~zero):
        v = w[:, j] / norms[j]
        for _ in range(2):  # Gram-Schmidt, twice
            v = v - q @ (q.T @ v)
        residual = np.linalg.norm(v)
        if residual > RANK:
            basis.append(j)
            q = np.hstack([q, (v / residual)[:, None]])
    dependent = [j for j in np.flatnonzero(~zero) if j not in basis]
    b = w[:, basis]
    coefficients, *_ = np.linalg.lstsq(b, w[:, dependent], rcond=None)
    fit = np.max(np.abs(b @ coefficients - w[:, dependent])) / np.max(np.abs(w))
    assert fit < 1e-10, ("grouping fit", fit)
    base = pi[basis] + coefficients @ pi[dependent] if dependent else pi[basis]
    same = np.max(np.abs(b @ base - w @ pi)) / np.max(np.abs(w @ pi))
    assert same < 1e-10, ("Y_b pi_b = Y pi", same)
    return {
        "order": "link by link, each link's columns in the reverse of toDynamicParameters' order (Izz, Iyz, Ixz, Iyy, "
        "Ixy, Ixx, mz, my, mx, m: about link i's origin, in its axes), then per joint Ia, fv, fc; a column joins "
        f"the basis if its residual after projection on the basis so far (columns scaled to unit norm) exceeds {RANK}",
        "zero": [labels[j] for j in np.flatnonzero(zero)],
        "basis": [labels[j] for j in basis],
        "dependent": [labels[j] for j in dependent],
        "coefficients": matrix(coefficients.T),
        "coefficients_note": "row d, column k: column dependent[d] = sum_k coefficients[d][k] column basis[k]; "
        "so base parameter k = pi[basis[k]] + sum_d coefficients[d][k] pi[dependent[d]]",
        "fit_residual": float(fit),
        "base_parameters": base.tolist(),
    }


def puma_toml():
    """robots/puma560.toml, checked to be tests/data/reference/robots/puma560.json."""
    toml = tomllib.loads((ROOT / "robots" / "puma560.toml").read_text())
    ref = json.loads((DATA / "reference" / "robots" / "puma560.json").read_text())
    angle = lambda x: math.radians(float(x.split()[0])) if isinstance(x, str) else float(x)
    assert toml["gravity"] == ref["gravity"] and len(toml["joints"]) == len(ref["joints"])
    for t, r in zip(toml["joints"], ref["joints"]):
        assert t["type"] == r["type"]
        for key in ["theta", "d", "a", "alpha", "mass", "actuator_inertia"]:
            assert abs(angle(t.get(key, 0.0)) - r[key]) < 1e-15, (key, t, r)
        for key in ["com", "inertia"]:
            assert np.max(np.abs(np.subtract(t.get(key, [0.0] * 3), r[key]))) < 1e-15, (key, t, r)
    return "robots/puma560.toml = reference/robots/puma560.json (every D-H value, mass, com, inertia to 1e-15)"


def main():
    robots = [dh_robot(p) for p in DH_ROBOTS] + [urdf_robot(n) for n in URDF_ROBOTS]
    rng = np.random.default_rng(2027)
    for robot in robots:
        worst = write(robot, rng)
        print(f"{robot.name}: n = {robot.n}, {SAMPLES} samples, largest scaled error {worst:.1e}")
    counts = {
        "generator": f"tests/data/regressor/make.py with pinocchio {pin.__version__}",
        "samples": STACK,
        "sampling": "q in [-pi, pi], qd in [-2, 2], qdd in [-5, 5], uniform, seeded; gravity of the description",
        "method": f"SVD of the nonzero columns scaled to unit norm; zero column: norm <= {ZERO} x the largest; "
        f"rank: singular values > {RANK} x the largest; gap = last kept / first dropped",
        "puma560_source": puma_toml(),
        "issue_27": {"puma560": [36, 40, 52], "panda": [43, 48, 62]},
        "robots": {},
        "grouping": {},
    }
    for robot in robots:
        w = stacked(robot, np.random.default_rng(27))
        entry = {"n": robot.n}
        for label, columns in selections(robot.n).items():
            entry[label] = rank(w[:, columns])
        counts["robots"][robot.name] = entry
        shown = ", ".join(f"{k} {v['rank']} (gap {v['gap']:.0e})" for k, v in entry.items() if k != "n")
        print(f"{robot.name}: {shown}")
        if robot.name in GROUPED:
            columns = selections(robot.n)["with_viscous_and_coulomb"]
            rigid, extra = names(robot.n, ["Ia", "fv", "fc"])
            pi = np.concatenate([robot.pi_link, np.delete(robot.extra, np.s_[3::4])])
            order = [10 * i + k for i in range(robot.n) for k in range(9, -1, -1)]
            order += list(range(10 * robot.n, 13 * robot.n))
            labels = [(rigid + extra)[j] for j in order]
            group = grouping(w[:, columns][:, order], labels, pi[order])
            assert len(group["basis"]) == entry["with_viscous_and_coulomb"]["rank"], robot.name
            counts["grouping"][robot.name] = group
    (HERE / "base_counts.json").write_text(compact(counts) + "\n")


if __name__ == "__main__":
    main()

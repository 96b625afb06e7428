"""Reference data for the derivatives of the dynamics, from Pinocchio, for the reference robots.

Run: bench/.venv/bin/python tests/data/derivatives/make.py  (Pinocchio 4.1.0, numpy; bench/run
creates that virtual environment)

The robots and their Pinocchio models are those of tests/data/forward/make.py (imported from it:
the reference robots but ur5, whose M is singular, and the Panda; bodies, actuator inertia as
armature, gravity). At 10 seeded samples of (q, qd, qdd, tau) it records

* computeRNEADerivatives(q, qd, qdd): dtau_dq, dtau_dqd;
* computeABADerivatives(q, qd, tau): qdd_of_tau (aba), dqdd_dq, dqdd_dqd, dqdd_dtau.

Pinocchio has no joint springs. For a robot with springs (the Panda), tau gains k (q - q0), so
dtau_dq gains diag(k); aba is given tau - k (q - q0), and by the chain rule dqdd_dq gains
-Minv diag(k). Both are added here, by hand, and written in the files.

Before writing, each sample is checked: dqdd_dtau = Minv (computeMinverse); dqdd_dq and dqdd_dqd
equal -Minv times computeRNEADerivatives at aba's qdd; every derivative equals central
differences of rnea (step 1e-6, to 1e-6 scaled) or aba (to 1e-4: its differences lose what M's
condition number says). Writes <robot>.json here.
"""

import importlib.util
import json
import pathlib

import numpy as np
import pinocchio as pin

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE.parent
SPEC = importlib.util.spec_from_file_location("forward_make", DATA / "forward" / "make.py")
forward = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(forward)

STEP = 1e-6


def central(f, x, n):
    """Columns j: (f(x + h e_j) - f(x - h e_j)) / 2h."""
    columns = []
    for j in range(n):
        e = np.zeros(n)
        e[j] = STEP
        columns.append((f(x + e) - f(x - e)) / (2 * STEP))
    return np.array(columns).T


def stiffness(desc):
    return np.array([j.get("spring_stiffness", 0.0) for j in desc["joints"]])


def sample(model, data, desc, q, qd, qdd, tau):
    k = np.diag(stiffness(desc))
    dq, dv, _ = pin.computeRNEADerivatives(model, data, q, qd, qdd)
    dtau_dq, dtau_dqd = dq + k, dv.copy()
    rnea = lambda q_, v_: pin.rnea(model, data, q_, v_, qdd) + forward.springs(desc, q_)
    assert forward.scaled(central(lambda x: rnea(x, qd), q, model.nv), dtau_dq) < 1e-6
    assert forward.scaled(central(lambda x: rnea(q, x), qd, model.nv), dtau_dqd) < 1e-6

    aba = lambda q_, v_, t_: pin.aba(model, data, q_, v_, t_ - forward.springs(desc, q_)).copy()
    acceleration = aba(q, qd, tau)
    aq, av, at = pin.computeABADerivatives(model, data, q, qd, tau - forward.springs(desc, q))
    minv = forward.symmetric(pin.computeMinverse(model, data, q))
    dqdd_dq, dqdd_dqd, dqdd_dtau = aq - minv @ k, av.copy(), forward.symmetric(at)
    assert forward.scaled(dqdd_dtau, minv) < 1e-10
    dq, dv, _ = pin.computeRNEADerivatives(model, data, q, qd, acceleration)
    assert forward.scaled(dqdd_dq, -minv @ (dq + k)) < 1e-10
    assert forward.scaled(dqdd_dqd, -minv @ dv) < 1e-10
    # aba's differences lose what M's condition number says (up to 1e5 here).
    assert forward.scaled(central(lambda x: aba(x, qd, tau), q, model.nv), dqdd_dq) < 1e-4
    assert forward.scaled(central(lambda x: aba(q, x, tau), qd, model.nv), dqdd_dqd) < 1e-4
    assert forward.scaled(central(lambda x: aba(q, qd, x), tau, model.nv), dqdd_dtau) < 1e-4
    matrix = lambda m: [row.tolist() for row in np.asarray(m)]
    return {
        "q": q.tolist(),
        "qd": qd.tolist(),
        "qdd": qdd.tolist(),
        "tau": tau.tolist(),
        "dtau_dq": matrix(dtau_dq),
        "dtau_dqd": matrix(dtau_dqd),
        "qdd_of_tau": acceleration.tolist(),
        "dqdd_dq": matrix(dqdd_dq),
        "dqdd_dqd": matrix(dqdd_dqd),
        "dqdd_dtau": matrix(dqdd_dtau),
    }


def main():
    rng = np.random.default_rng(1818)
    for path in forward.ROBOTS:
        desc = json.loads(path.read_text())
        model = forward.model_from_dh(desc)
        data = model.createData()
        samples = []
        for _ in range(10):
            q, qd = rng.uniform(-3, 3, model.nq), rng.uniform(-2, 2, model.nv)
            qdd, tau = rng.uniform(-5, 5, model.nv), rng.uniform(-20, 20, model.nv)
            samples.append(sample(model, data, desc, q, qd, qdd, tau))
        name = path.stem if path.parent.name == "robots" else path.parent.name
        out = {
            "robot": str(path.relative_to(DATA)),
            "generator": f"tests/data/derivatives/make.py with pinocchio {pin.__version__}",
            "samples": samples,
        }
        (HERE / f"{name}.json").write_text(json.dumps(out, indent=1) + "\n")
        print(name, len(samples), "samples")


if __name__ == "__main__":
    main()

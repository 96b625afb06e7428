"""Speed from Python: N states of the Panda, the package's batch call against a Python loop over
Pinocchio's bindings, per state; and the cost of one call (a batch of one state).

Run from the repository: python python/examples/speed.py [N]  (needs `pin`)
Prints a markdown table; each figure is the fastest of 5 runs.
"""

import json
import sys
import time
from pathlib import Path

import numpy as np
import pinocchio as pin

import dh_dynamics

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "python" / "tests"))
from conftest import reference_script  # noqa: E402


def fastest(f, runs=5):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return best


def main():
    n_states = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
    robot = dh_dynamics.Robot.from_file(ROOT / "tests/data/panda/robot.json",
                                        families=["derivatives"])
    description = json.loads((ROOT / "tests/data/panda/robot.json").read_text())
    model = reference_script().model_from_dh(description)
    data = model.createData()
    rng = np.random.default_rng(0)
    q, qd, qdd = (rng.uniform(-1, 1, (n_states, 7)) for _ in range(3))

    def loop(f):
        return lambda: [f(model, data, q[i], qd[i], qdd[i]) for i in range(n_states)]

    rows = [
        ("inverse_dynamics", lambda: robot.inverse_dynamics(q, qd, qdd), loop(pin.rnea)),
        ("inverse_dynamics_derivatives",
         lambda: robot.inverse_dynamics_derivatives(q, qd, qdd),
         loop(pin.computeRNEADerivatives)),
    ]
    print(f"Panda, {n_states} states, ns per state (fastest of 5)\n")
    print("| method | dh_dynamics, one batch call | Python loop over Pinocchio | ratio |")
    print("|---|--:|--:|--:|")
    for name, ours, theirs in rows:
        a = fastest(ours) / n_states * 1e9
        b = fastest(theirs, runs=3) / n_states * 1e9
        print(f"| {name} | {a:.0f} | {b:.0f} | {b / a:.0f}x |")
    one = q[:1], qd[:1], qdd[:1]
    call = fastest(lambda: [robot.inverse_dynamics(*one) for _ in range(10_000)]) / 10_000
    print(f"\nOne call with one state (the overhead of a batch call): {call * 1e6:.1f} us")


if __name__ == "__main__":
    main()

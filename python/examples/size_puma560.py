"""Actuator sizing from Python: PUMA 560 along a two-second point-to-point move, the torque of
each joint split into its terms (inertia M q̈, Coriolis and centripetal C q̇, gravity g), the
peak and RMS torque of each joint, and a figure.

Run from the repository: python python/examples/size_puma560.py [figure.png]  (needs matplotlib)
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import dh_dynamics  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def minimum_jerk(start, end, duration, samples):
    """q, q̇, q̈ of the minimum-jerk move from `start` to `end`: (samples, n) arrays."""
    t = np.linspace(0.0, duration, samples)[:, None]
    s = t / duration
    shape = 10 * s**3 - 15 * s**4 + 6 * s**5
    rate = (30 * s**2 - 60 * s**3 + 30 * s**4) / duration
    accel = (60 * s - 180 * s**2 + 120 * s**3) / duration**2
    span = end - start
    return t[:, 0], start + shape * span, rate * span, accel * span


def main():
    figure = sys.argv[1] if len(sys.argv) > 1 else "size_puma560.png"
    robot = dh_dynamics.Robot.from_file(ROOT / "robots" / "puma560.toml")
    start = np.zeros(6)
    end = np.array([1.5, -1.0, 1.2, 0.8, -0.9, 1.4])
    t, q, qd, qdd = minimum_jerk(start, end, duration=2.0, samples=2001)

    # One call per term over the whole trajectory.
    tau = robot.inverse_dynamics(q, qd, qdd)
    gravity = robot.gravity_torques(q)
    coriolis = robot.coriolis_torques(q, qd)
    inertia = np.einsum("sij,sj->si", robot.mass_matrix(q), qdd)
    friction = robot.friction_torques(qd)
    worst = np.max(np.abs(inertia + coriolis + gravity + friction - tau))
    assert worst < 1e-9 * max(1.0, np.max(np.abs(tau))), f"the terms do not add up: {worst:e}"

    print("| joint | peak torque (N m) | RMS torque (N m) | peak power (W) |")
    print("|--:|--:|--:|--:|")
    for j in range(robot.dof):
        peak = np.max(np.abs(tau[:, j]))
        rms = np.sqrt(np.mean(tau[:, j] ** 2))
        power = np.max(np.abs(tau[:, j] * qd[:, j]))
        print(f"| {j + 1} | {peak:.2f} | {rms:.2f} | {power:.1f} |")

    fig, axes = plt.subplots(2, 3, figsize=(12, 6), sharex=True)
    for j, ax in enumerate(axes.flat):
        ax.plot(t, tau[:, j], "k", label="τ")
        ax.plot(t, inertia[:, j], label="M q̈")
        ax.plot(t, coriolis[:, j], label="C q̇")
        ax.plot(t, gravity[:, j], label="g")
        ax.set_title(f"joint {j + 1}")
        ax.set_ylabel("N m")
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("time (s)")
    axes[0, 0].legend()
    fig.suptitle(f"{robot.name}: the torque of each joint and its terms along a 2 s move")
    fig.tight_layout()
    fig.savefig(figure, dpi=100)
    print(f"\nfigure: {figure}")


if __name__ == "__main__":
    main()

"""The simplified models a description file asks for (its ``[simplify]`` table): the package
has them as the derive and the C header do, and at random states inside the file's envelope
they are within the proven bounds the header states above them of the exact methods, and not
the exact methods themselves (terms dropped)."""

import numpy as np
import pytest

import dh_dynamics
from conftest import DATA

TWO_LINK = DATA / "simplify" / "two_link.toml"


def stated_bounds(header, function):
    """The bounds the comment above ``function`` states (``|T1 - T1,simplified| <= 4.2e-1``),
    in its order."""
    at = header.index(f" {function}(const")
    comment = header[header.rindex("/*", 0, at):at]
    marker = ",simplified| <= "
    return np.array([float(line.split(marker)[1].split()[0])
                     for line in comment.splitlines() if marker in line])


@pytest.fixture(scope="module")
def two_link():
    return dh_dynamics.Robot.from_file(TWO_LINK)


def test_the_files_simplified_models_within_their_stated_bounds(two_link):
    # The file's envelope: q1 in [-1, 1], q2 in [-2, 2], |qd| <= 3, |qdd| <= 5.
    rng = np.random.default_rng(30)
    count = 2000
    q = rng.uniform([-1.0, -2.0], [1.0, 2.0], (count, 2))
    qd = rng.uniform(-3.0, 3.0, (count, 2))
    qdd = rng.uniform(-5.0, 5.0, (count, 2))
    upper = np.triu_indices(2)
    pairs = {
        "inverse_dynamics": (two_link.inverse_dynamics(q, qd, qdd),
                             two_link.inverse_dynamics_simplified(q, qd, qdd)),
        "gravity_torques": (two_link.gravity_torques(q), two_link.gravity_torques_simplified(q)),
        "coriolis_torques": (two_link.coriolis_torques(q, qd),
                             two_link.coriolis_torques_simplified(q, qd)),
        # The bounds of M are its upper triangle's, row by row.
        "mass_matrix": (two_link.mass_matrix(q)[:, upper[0], upper[1]],
                        two_link.mass_matrix_simplified(q)[:, upper[0], upper[1]]),
    }
    for method, (exact, simplified) in pairs.items():
        bounds = stated_bounds(two_link.header, f"two_link_{method}_simplified")
        off = np.max(np.abs(exact - simplified), axis=0)
        assert off.shape == bounds.shape, method
        assert np.all(off <= bounds * (1 + 1e-9) + 1e-12), (method, off, bounds)
        assert np.max(off) > 0, f"{method}_simplified is the exact {method}"


def test_a_mimic_robots_simplified_models_within_their_stated_bounds():
    """The mimic arm (its third joint follows the second: three coordinates of four joints):
    its simplified models take and give one value per coordinate, and within the file's
    envelope stay within the header's bounds of the exact methods."""
    arm = dh_dynamics.Robot.from_file(DATA / "trees" / "mimic_arm.toml")
    assert arm.dof == 3
    # The file's envelope: q in [-1, 1.5], |qd| <= 2, |qdd| <= 5 for every coordinate.
    rng = np.random.default_rng(41)
    count = 2000
    q = rng.uniform(-1.0, 1.5, (count, 3))
    qd = rng.uniform(-2.0, 2.0, (count, 3))
    qdd = rng.uniform(-5.0, 5.0, (count, 3))
    upper = np.triu_indices(3)
    pairs = {
        "inverse_dynamics": (arm.inverse_dynamics(q, qd, qdd),
                             arm.inverse_dynamics_simplified(q, qd, qdd)),
        "mass_matrix": (arm.mass_matrix(q)[:, upper[0], upper[1]],
                        arm.mass_matrix_simplified(q)[:, upper[0], upper[1]]),
    }
    for method, (exact, simplified) in pairs.items():
        assert simplified.shape == exact.shape, method
        bounds = stated_bounds(arm.header, f"mimic_arm_{method}_simplified")
        off = np.max(np.abs(exact - simplified), axis=0)
        assert off.shape == bounds.shape, method
        assert np.all(off <= bounds * (1 + 1e-9) + 1e-12), (method, off, bounds)
        assert np.max(off) > 0, f"{method}_simplified is the exact {method}"


def test_a_file_without_the_table_has_no_simplified_models():
    plain = dh_dynamics.Robot.from_file(DATA.parent.parent / "robots" / "puma560.toml")
    assert "inverse_dynamics_simplified" not in plain.methods

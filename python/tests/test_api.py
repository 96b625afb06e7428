"""The package's behaviour apart from the numbers' source: one state against a batch, float32,
broadcasting, the errors of a bad description or bad arrays, a failed solve, the equations."""

import numpy as np
import pytest

import dh_dynamics
from conftest import ROOT, states

PUMA = ROOT / "robots" / "puma560.toml"


@pytest.fixture(scope="module")
def puma():
    return dh_dynamics.Robot.from_file(PUMA, families=["derivatives"])


def test_every_method_of_the_trait_is_there(puma):
    for name in ["mass_matrix", "coriolis_matrix", "coriolis_torques", "gravity_torques",
                 "bias_torques", "inverse_dynamics", "friction_torques", "kinetic_energy",
                 "potential_energy", "hand_pose", "hand_jacobian_in_base", "forward_dynamics",
                 "mass_matrix_inverse", "inverse_dynamics_derivatives",
                 "forward_dynamics_derivatives", "joint_torques_for_hand_wrench"]:
        assert name in puma.methods
        assert callable(getattr(puma, name))
    assert "M(q)" in puma.mass_matrix.__doc__


def test_a_batch_is_each_state_alone_bit_for_bit(puma):
    q, qd, qdd = states(6, 9, seed=1)
    batch = puma.inverse_dynamics(q, qd, qdd)
    assert batch.shape == (9, 6) and batch.dtype == np.float64
    for i in range(9):
        assert np.array_equal(puma.inverse_dynamics(q[i], qd[i], qdd[i]), batch[i])
    d = puma.forward_dynamics_derivatives(q, qd, batch)
    assert d.dqdd_dq.shape == (9, 6, 6) and d.qdd.shape == (9, 6)
    one = puma.forward_dynamics_derivatives(q[4], qd[4], batch[4])
    assert all(np.array_equal(a, b[4]) for a, b in zip(one, d))
    assert np.allclose(d.qdd, qdd, atol=1e-9)
    assert isinstance(puma.kinetic_energy(q[0], qd[0]), float)
    assert puma.kinetic_energy(q, qd).shape == (9,)


def test_float32_in_gives_float32_out(puma):
    q, qd, qdd = states(6, 5, seed=2)
    tau = puma.inverse_dynamics(q, qd, qdd)
    tau32 = puma.inverse_dynamics(*(x.astype(np.float32) for x in (q, qd, qdd)))
    assert tau32.dtype == np.float32
    assert np.max(np.abs(tau32 - tau)) < 1e-4 * max(1.0, np.max(np.abs(tau)))
    # One float64 input makes the call float64.
    mixed = puma.inverse_dynamics(q.astype(np.float32), qd, qdd.astype(np.float32))
    assert mixed.dtype == np.float64


def test_one_state_is_used_for_every_state_of_a_batch(puma):
    q, qd, qdd = states(6, 4, seed=3)
    tau = puma.inverse_dynamics(q[0], qd, qdd)
    for i in range(4):
        assert np.array_equal(tau[i], puma.inverse_dynamics(q[0], qd[i], qdd[i]))
    wrench = np.array([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    assert puma.joint_torques_for_hand_wrench(q, wrench).shape == (4, 6)


def test_bad_arrays_are_refused_with_their_names(puma):
    q, qd, qdd = states(6, 4, seed=4)
    with pytest.raises(ValueError, match="`qd` has shape \\(5,\\)"):
        puma.inverse_dynamics(q[0], np.zeros(5), qdd[0])
    with pytest.raises(ValueError, match="batches of different lengths"):
        puma.inverse_dynamics(q, qd[:3], qdd)
    with pytest.raises(TypeError, match="takes 3 arrays, 2 given"):
        puma.inverse_dynamics(q, qd)


def test_a_failed_solve_names_its_states(puma):
    q, qd, qdd = states(6, 6, seed=5)
    # M does not depend on q1: NaN in q2 and q3.
    q[2, 1] = q[4, 2] = np.nan
    with pytest.raises(dh_dynamics.NotPositiveDefinite) as failed:
        puma.forward_dynamics(q, qd, qdd)
    assert failed.value.states == [2, 4]
    assert failed.value.result.shape == (6, 6)
    assert np.isfinite(failed.value.result[0]).all()
    assert isinstance(failed.value, np.linalg.LinAlgError)


def test_a_bad_description_is_an_exception_at_its_line_and_column(tmp_path):
    text = PUMA.read_text().replace("mass = 17.4", "mass = -17.4", 1)
    assert text != PUMA.read_text()
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    with pytest.raises(dh_dynamics.DescriptionError) as error:
        dh_dynamics.Robot.from_file(bad)
    line = next(i for i, l in enumerate(text.splitlines(), 1) if "mass = -17.4" in l)
    assert (error.value.file, error.value.line) == (str(bad), line)
    assert error.value.column >= 1 and "mass" in error.value.message
    with pytest.raises(dh_dynamics.DescriptionError) as missing:
        dh_dynamics.Robot.from_file(tmp_path / "missing.toml")
    assert missing.value.line is None and missing.value.file.endswith("missing.toml")
    with pytest.raises(ValueError, match="not an opt-in family"):
        dh_dynamics.Robot.from_file(PUMA, families=["everything"])


def test_the_equations_read_as_the_book_writes_them(puma):
    text = puma.equations()
    assert "D11 = " in text and "eq. 6.43" in text
    latex = puma._repr_latex_()
    assert "\\begin{align*}" in latex and not latex.lstrip().startswith("%")
    kinematics = puma.equations(kinematics=True)
    assert "hand pose and Jacobians" in kinematics and "D11 = " not in kinematics


def test_a_tool_and_a_urdf_chain():
    tool = dh_dynamics.Robot.from_file(PUMA, tool=[0, 0, 0.1, 0, 0, 0])
    plain = dh_dynamics.Robot.from_file(PUMA)
    q = states(6, 1, seed=6)[0][0]
    pose, tool_pose = plain.hand_pose(q), tool.hand_pose(q)
    assert np.allclose(tool_pose[:, 3], pose[:, 3] + 0.1 * pose[:, 2])
    ur10 = dh_dynamics.Robot.from_urdf(ROOT / "robots/urdf/ur10.urdf", base="base_link",
                                       tip="tool0")
    assert (ur10.name, ur10.dof) == ("ur10", 6)


def test_the_regressor_and_base_parameters_give_tau():
    """τ = Y π + the joints' columns times their parameters = Y_B π_B (τ itself is checked
    against Pinocchio in test_pinocchio.py)."""
    robot = dh_dynamics.Robot.from_file(PUMA, families=["regressor", "base_parameters"])
    q, qd, qdd = states(6, 5, seed=8)
    tau = robot.inverse_dynamics(q, qd, qdd)
    links = np.einsum("sijk,jk->si", robot.regressor(q, qd, qdd), robot.standard_parameters())
    joints = np.einsum("sik,ik->si", robot.joint_regressor(qd, qdd), robot.joint_parameters())
    assert np.max(np.abs(links + joints - tau)) < 1e-10 * np.max(np.abs(tau))
    base = robot.base_regressor(q, qd, qdd) @ robot.base_parameters()
    assert np.max(np.abs(base - tau)) < 1e-10 * np.max(np.abs(tau))
    assert robot.base_parameters().shape == (36,)

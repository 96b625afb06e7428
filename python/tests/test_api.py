"""The package's behaviour apart from the numbers' source: one state against a batch, float32,
broadcasting, the errors of a bad description or bad arrays, a failed solve, the equations."""

import numpy as np
import pytest

import dh_dynamics
from conftest import DATA, ROOT, states
from dh_dynamics import _native

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


def test_a_failed_solve_names_its_states():
    """A cart of no mass (Niku's Example 6.1 with m = 0): M = [m] is singular at every
    state."""
    cart = dh_dynamics.Robot.from_file(ROOT / "robots" / "niku_example_6_1.toml",
                                       parameters={"m": 1.0, "k": 2.0, "g": 9.81})
    x = np.array([[0.1], [0.2], [0.3]])
    assert np.array_equal(cart.forward_dynamics(x, 0 * x, 2 * x), np.zeros((3, 1)))
    cart.parameters["m"] = 0.0
    with pytest.raises(dh_dynamics.NotPositiveDefinite) as failed:
        cart.forward_dynamics(x, 0 * x, 2 * x)
    assert failed.value.states == [0, 1, 2]
    assert "niku_example_6_1.forward_dynamics: M(q) is not positive definite at 3 of 3" in \
        str(failed.value)
    assert failed.value.result.shape == (3, 1)
    assert isinstance(failed.value, np.linalg.LinAlgError)


def test_a_state_that_is_not_finite_is_named_not_blamed_on_m(puma):
    q, qd, qdd = states(6, 6, seed=5)
    # M does not depend on q1: NaN in q2 and q3, where the solve fails, and in q1, where not.
    q[2, 1] = q[4, 2] = q[5, 0] = np.nan
    qd[3, 5] = np.inf
    with pytest.raises(dh_dynamics.NonFiniteInput) as failed:
        puma.forward_dynamics(q, qd, qdd)
    message = str(failed.value)
    assert message.startswith("puma560.forward_dynamics: `q` is not finite at 3 of 6 states "
                              "(2, 4, 5): q[2, 1] = nan; `qd` is not finite at 1 of 6 states "
                              "(3): qd[3, 5] = inf; expected finite numbers"), message
    assert "positive definite" not in message
    assert failed.value.states == [2, 3, 4, 5] and failed.value.arguments == ["q", "qd"]
    assert isinstance(failed.value, ValueError)
    assert failed.value.result.shape == (6, 6)
    assert np.isfinite(failed.value.result[[0, 1]]).all()
    # Every method, one state or a batch: not only the solves.
    with pytest.raises(dh_dynamics.NonFiniteInput, match=r"puma560\.inverse_dynamics: `qdd` "
                                                          r"is not finite: qdd\[0\] = -inf"):
        puma.inverse_dynamics(q[0], qd[0], np.r_[-np.inf, qdd[0, 1:]])
    # One state used for every state of a batch.
    with pytest.raises(dh_dynamics.NonFiniteInput, match=r"`q` is not finite at 2 of 2 states "
                                                          r"\(0, 1\): q\[3\] = nan"):
        puma.inverse_dynamics(np.r_[q[0, :3], np.nan, q[0, 4:]], qd[:2], qdd[:2])


def test_a_method_the_robot_was_built_without_names_its_family(puma):
    plain = dh_dynamics.Robot.from_file(PUMA)
    with pytest.raises(AttributeError, match=r"puma560 has no method `regressor`: it belongs to "
                                             r"the opt-in family `regressor`.*families=\["
                                             r"'regressor'\]"):
        plain.regressor
    with pytest.raises(AttributeError, match="`forward_dynamics_derivatives`: .* family "
                                             "`derivatives`"):
        plain.forward_dynamics_derivatives
    with pytest.raises(AttributeError, match=r"`gravity_torques_simplified`: .*\[simplify\]"):
        plain.gravity_torques_simplified
    with pytest.raises(AttributeError, match="no method `inverse_dynamic`; its methods: "
                                             "mass_matrix, "):
        plain.inverse_dynamic
    arm = dh_dynamics.Robot.from_file(ROOT / "robots" / "articulated_3r.toml",
                                      families=["base_parameters"])
    with pytest.raises(AttributeError, match="need the robot's lengths and angles as numbers"):
        arm.base_regressor
    assert not hasattr(plain, "regressor") and hasattr(puma, "inverse_dynamics_derivatives")


def test_an_unwritable_cache_falls_back_to_a_temporary_directory(tmp_path, monkeypatch):
    from dh_dynamics import _compiled
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    # Under a file, not a read-only directory: root writes those anyway.
    monkeypatch.setenv("DH_DYNAMICS_CACHE", str(blocker / "cache"))
    monkeypatch.setattr(_compiled, "_SCRATCH", [])
    with pytest.warns(RuntimeWarning, match=f"the cache directory {blocker / 'cache'} cannot "
                                            "be written .*DH_DYNAMICS_CACHE"):
        robot = dh_dynamics.Robot.from_file(ROOT / "robots" / "niku_example_6_3.toml")
    scratch = _compiled._SCRATCH[0]
    assert scratch.is_dir() and any(scratch.glob("*.so"))
    robot.parameters = dict(l1=1.0, l2=1.0, m1=1.0, m2=1.0, g=1.0)
    assert robot.mass_matrix([0.0, 0.0])[1, 1] == 1.0   # m2 l2²
    # Nowhere to write: the error names both places and the variable.
    monkeypatch.setattr(_compiled, "_SCRATCH", [])
    monkeypatch.setattr(_compiled.tempfile, "tempdir", str(blocker / "tmp"))
    with pytest.raises(OSError, match="cannot be written .* nor a temporary directory .*: set "
                                      "DH_DYNAMICS_CACHE to a writable directory"):
        dh_dynamics.Robot.from_file(ROOT / "robots" / "niku_example_6_2.toml")


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


def test_errors_are_the_generators_diagnostics_as_data(tmp_path):
    """Each problem is a ``Diagnostic`` of the generator's fields, no text parsed back; a
    mistake in the arguments (no file) is a ``ValueError`` with the hint."""
    two_link = (DATA / "simplify" / "two_link.toml").read_text()
    text = two_link.replace("qd_max = 3", "qd_max = -3", 1)
    assert text != two_link
    bad = tmp_path / "bad simplify.toml"
    bad.write_text(text)
    with pytest.raises(dh_dynamics.DescriptionError) as error:
        dh_dynamics.Robot.from_file(bad)
    line = text.splitlines().index("qd_max = -3") + 1
    first = error.value.diagnostics[0]
    assert isinstance(first, dh_dynamics.Diagnostic)
    assert (first.file, first.line, first.column) == (str(bad), line, len("qd_max = ") + 1)
    assert first.message.startswith("simplify: ") and first.help is None
    assert error.value.problems[0] == f"{bad}:{line}:10: {first.message}"
    assert str(error.value) == "\n".join(error.value.problems)
    # The generator's own message, line for line what the package prints from the fields.
    with pytest.raises(_native.GeneratorError) as native:
        _native.c_header(str(bad))
    fields = [dh_dynamics.Diagnostic(**d) for d in native.value.diagnostics]
    assert fields == error.value.diagnostics
    assert str(native.value) == str(error.value)
    with pytest.raises(ValueError) as families:
        dh_dynamics.Robot.from_file(PUMA, families=["derivatives", "everything"])
    assert not isinstance(families.value, dh_dynamics.DescriptionError)
    assert str(families.value) == ("families: `everything` is not an opt-in family of methods\n"
                                   "help: the opt-in families: derivatives, regressor, "
                                   "base_parameters, tip_kinematics")
    with pytest.raises(ValueError, match=r"^families: `simplify` needs an envelope .*\nhelp: "
                                         r".*`\[simplify\]` table"):
        dh_dynamics.Robot.from_file(PUMA, families="simplify")
    with pytest.raises(ValueError, match=r"^base, tip and tips name links of a URDF file; "
                                         r"`.*puma560\.toml` is not one"):
        dh_dynamics.Robot.from_urdf(PUMA, tip="link6")
    with pytest.raises(ValueError, match=r"^tool: `.*two_link\.toml` declares a `tool` already"):
        tooled = tmp_path / "two_link.toml"
        tooled.write_text(two_link.replace("[[joints]]", "tool = [0, 0, 0.1, 0, 0, 0]\n\n"
                                                         "[[joints]]", 1))
        dh_dynamics.Robot.from_file(tooled, tool=[0, 0, 0.1, 0, 0, 0])
    with pytest.raises(ValueError, match=r"is its tip link\nhelp: choose the hand with `tip`"):
        dh_dynamics.Robot(ROOT / "robots/urdf/ur5.urdf", tool=[0, 0, 0.1, 0, 0, 0])


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


def test_a_tree_from_a_urdf_with_its_published_inertias():
    """Two fingers of the Allegro hand: a tree off the palm, whose inertias break the triangle
    inequality (refused, then kept with ``check_inertia=False``). Fingers on different branches
    do not couple: M's block between them is exactly zero."""
    hand = ROOT / "robots/urdf/trees/allegro_right_hand.urdf"
    index_and_middle = ["link_3.0_tip", "link_7.0_tip"]
    with pytest.raises(dh_dynamics.DescriptionError, match="triangle inequality"):
        dh_dynamics.Robot.from_urdf(hand, tips=index_and_middle)
    fingers = dh_dynamics.Robot.from_urdf(hand, tips=index_and_middle, check_inertia=False)
    assert fingers.dof == 8
    m = fingers.mass_matrix(states(8, 1, seed=8)[0][0])
    assert np.array_equal(m[:4, 4:], np.zeros((4, 4)))
    assert np.all(np.linalg.eigvalsh(m) > 0)
    assert "joints 5-8 from the base" in fingers.equations()


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


def test_the_regressor_of_a_robot_with_mimic_joints():
    """The Panda's second finger follows the first: 8 coordinates (rows), 9 links (blocks);
    each joint's columns add to its row of τ (``joint_rows``)."""
    panda = ROOT / "robots" / "urdf" / "panda.urdf"
    robot = dh_dynamics.Robot.from_urdf(panda, base="panda_link0",
                                        families=["regressor", "base_parameters"])
    assert robot.dof == 8 and robot.joint_rows == (0, 1, 2, 3, 4, 5, 6, 7, 7)
    q, qd, qdd = states(8, 5, seed=9)
    tau = robot.inverse_dynamics(q, qd, qdd)
    y = robot.regressor(q, qd, qdd)
    assert y.shape == (5, 8, 9, 10)
    links = np.einsum("sijk,jk->si", y, robot.standard_parameters())
    per_joint = np.einsum("smk,mk->sm", robot.joint_regressor(qd, qdd), robot.joint_parameters())
    joints = np.zeros_like(tau)
    for m, row in enumerate(robot.joint_rows):
        joints[:, row] += per_joint[:, m]
    assert np.max(np.abs(links + joints - tau)) < 1e-10 * np.max(np.abs(tau))
    base = robot.base_regressor(q, qd, qdd) @ robot.base_parameters()
    assert np.max(np.abs(base - tau)) < 1e-10 * np.max(np.abs(tau))

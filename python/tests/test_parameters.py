"""The robots whose descriptions have symbols (``mass = "m1"``): every robot file of
``robots/`` loads and every method runs; the book's worked examples give the book's printed
equations of motion (typed in below from Niku, ch. 6, as ``tests/tests/niku_*.rs`` has them);
a robot with parameters gives what the same robot with the numbers written into its file gives;
and the parameters' errors."""

import json
import re
import subprocess
import sys

import numpy as np
import pytest

import dh_dynamics
from dh_dynamics import _native
from conftest import ROOT, scaled_error, states

tomllib = pytest.importorskip("tomllib")

ROBOT_FILES = sorted((ROOT / "robots").glob("*.toml"))
ARM = ROOT / "robots" / "articulated_3r.toml"
ALL_FAMILIES = ["derivatives", "regressor", "base_parameters"]


def some_values(names, seed):
    """A value in [0.5, 2] for each parameter: masses, lengths, stiffnesses, g, inertias."""
    rng = np.random.default_rng(seed)
    return {name: float(rng.uniform(0.5, 2.0)) for name in names}


def method_inputs(method, count, seed):
    """Random inputs of ``count`` states for each of the method's arguments."""
    rng = np.random.default_rng(seed)
    return [rng.uniform(-1.5, 1.5, (count, length)) for _, length in method._arguments]


@pytest.mark.parametrize("path", ROBOT_FILES, ids=lambda p: p.stem)
def test_every_robot_file_loads_and_every_method_runs(path):
    # The names without compiling a header: the generator's list of the C functions' params.
    names = _native.c_header(str(path))["fields"]
    families = ALL_FAMILIES if names else []
    robot = dh_dynamics.Robot.from_file(path, families=families,
                                        parameters=some_values(names, seed=1))
    assert list(robot.parameters) == list(names)
    assert all(isinstance(v, float) for v in robot.parameters.values())
    if names:
        assert {"inverse_dynamics_derivatives", "regressor"} <= set(robot.methods)
    for name in robot.methods:
        method = getattr(robot, name)
        inputs = method_inputs(method, 3, seed=2)
        batch, solved = call(robot, method, inputs)
        one, _ = call(robot, method, [x[1] for x in inputs])
        assert all(np.isfinite(p).all() for p in batch + one) or not solved, (path.stem, name)
        if method._arguments:
            assert all(np.array_equal(b[1], o, equal_nan=True) for b, o in zip(batch, one)), \
                (path.stem, name)
        single, _ = call(robot, method, [x.astype(np.float32) for x in inputs])
        if method._arguments:
            assert all(p.dtype == np.float32 for p in single), (path.stem, name)


def call(robot, method, inputs):
    """The method's result as a list of arrays, and whether M was positive definite: a solve
    may fail only where M(q) is singular (the UR5 file's links have no inertia, so the wrist's
    last joint moves nothing)."""
    try:
        return parts(method(*inputs)), True
    except dh_dynamics.NotPositiveDefinite as failed:
        q = np.atleast_2d(inputs[0])
        for i in failed.states:
            eigenvalues = np.linalg.eigvalsh(robot.mass_matrix(q[i]))
            assert eigenvalues[0] <= 1e-12 * eigenvalues[-1], (robot.name, method, i)
        return parts(failed.result), False


def parts(result):
    """A method's result as a list of arrays (a named tuple's fields, or the one result)."""
    return [np.asarray(p) for p in result] if isinstance(result, tuple) else [np.asarray(result)]


# The book's printed τ, M and g (Niku, ch. 6; docs/errata.md applied as the Rust tests do),
# each a function of the parameters and one state.
def example_6_1(p, q, qd, qdd):
    m, k = p["m"], p["k"]
    return [m * qdd[0] + k * q[0]], [[m]], [k * q[0]]


def example_6_2(p, q, qd, qdd):
    m1, m2, l, k, g = p["m1"], p["m2"], p["l"], p["k"], p["g"]
    x, th = q
    s, c = np.sin(th), np.cos(th)
    tau = [(m1 + m2) * qdd[0] + m2 * l * c * qdd[1] - m2 * l * s * qd[1] ** 2 + k * x,
           m2 * l * l * qdd[1] + m2 * l * qdd[0] * c + m2 * g * l * s]
    return tau, [[m1 + m2, m2 * l * c], [m2 * l * c, m2 * l * l]], [k * x, m2 * g * l * s]


def example_6_3(p, q, qd, qdd):
    l1, l2, m1, m2, g = p["l1"], p["l2"], p["m1"], p["m2"], p["g"]
    s1, c2, s2, s12 = np.sin(q[0]), np.cos(q[1]), np.sin(q[1]), np.sin(q[0] + q[1])
    m12 = m2 * l2 * l2 + m2 * l1 * l2 * c2
    mass = [[(m1 + m2) * l1 * l1 + m2 * l2 * l2 + 2 * m2 * l1 * l2 * c2, m12], [m12, m2 * l2 * l2]]
    grav = [(m1 + m2) * g * l1 * s1 + m2 * g * l2 * s12, m2 * g * l2 * s12]
    h = m2 * l1 * l2 * s2
    velocity = [-2 * h * qd[0] * qd[1] - h * qd[1] ** 2, h * qd[0] ** 2]
    return np.array(mass) @ qdd + velocity + np.array(grav), mass, grav


def example_6_4(p, q, qd, qdd):
    l1, l2, m1, m2, g = p["l1"], p["l2"], p["m1"], p["m2"], p["g"]
    c1, c2, s2, c12 = np.cos(q[0]), np.cos(q[1]), np.sin(q[1]), np.cos(q[0] + q[1])
    m12 = m2 * l2 * l2 / 3 + m2 * l1 * l2 * c2 / 2
    mass = [[m1 * l1 * l1 / 3 + m2 * l1 * l1 + m2 * l2 * l2 / 3 + m2 * l1 * l2 * c2, m12],
            [m12, m2 * l2 * l2 / 3]]
    grav = [(m1 / 2 + m2) * g * l1 * c1 + m2 * g * l2 * c12 / 2, m2 * g * l2 * c12 / 2]
    h = m2 * l1 * l2 * s2
    velocity = [-h * qd[0] * qd[1] - h * qd[1] ** 2 / 2, h * qd[0] ** 2 / 2]   # (6.11), (6.12)
    return np.array(mass) @ qdd + velocity + np.array(grav), mass, grav


def example_6_5(p, q, qd, qdd):
    l1, l2, m1, m2, g = p["l1"], p["l2"], p["m1"], p["m2"], p["g"]
    (th, r), (thd, rd) = q, qd
    mass = [[m1 * l1 * l1 / 3 + m2 * l2 * l2 / 12 + m2 * r * r, 0], [0, m2]]
    grav = [(m1 * g * l1 / 2 + m2 * g * r) * np.cos(th), m2 * g * np.sin(th)]
    velocity = [2 * m2 * r * rd * thd, -m2 * r * thd ** 2]       # (6.14), (6.15)
    return np.array(mass) @ qdd + velocity + np.array(grav), mass, grav


def example_6_8(p, q, qd, qdd):
    l, m1, m2, g, i1, i2 = p["l"], p["m1"], p["m2"], p["g"], p["I1act"], p["I2act"]
    ll = l * l
    c1, c2, s2, c12 = np.cos(q[0]), np.cos(q[1]), np.sin(q[1]), np.cos(q[0] + q[1])
    d12 = m2 * ll / 3 + m2 * ll * c2 / 2
    mass = [[m1 * ll / 3 + 4 * m2 * ll / 3 + m2 * ll * c2 + i1, d12], [d12, m2 * ll / 3 + i2]]
    grav = [m1 * g * l * c1 / 2 + m2 * g * l * c12 / 2 + m2 * g * l * c1, m2 * g * l * c12 / 2]
    h = m2 * ll * s2 / 2
    velocity = [-h * qd[1] ** 2 - 2 * h * qd[0] * qd[1], h * qd[0] ** 2]   # T2: erratum 1
    return np.array(mass) @ qdd + velocity + np.array(grav), mass, grav


BOOK = {"6_1": example_6_1, "6_2": example_6_2, "6_3": example_6_3, "6_4": example_6_4,
        "6_5": example_6_5, "6_8": example_6_8}


@pytest.mark.parametrize("example", sorted(BOOK))
def test_the_books_examples_give_the_books_equations(example):
    # The header of the test above (compiled once in the session's cache).
    robot = dh_dynamics.Robot.from_file(ROOT / "robots" / f"niku_example_{example}.toml",
                                        families=ALL_FAMILIES)
    for trial in range(3):
        values = some_values(robot.parameters.names, seed=10 * trial)
        robot.parameters = values
        q, qd, qdd = states(robot.dof, 20, seed=trial)
        tau, mass, grav = robot.inverse_dynamics(q, qd, qdd), robot.mass_matrix(q), \
            robot.gravity_torques(q)
        for i in range(len(q)):
            want = BOOK[example](values, q[i], qd[i], qdd[i])
            for name, got, book in zip(("tau", "M", "g"), (tau[i], mass[i], grav[i]), want):
                error = scaled_error(got, book)
                assert error < 1e-12, f"Example {example} {name} at state {i}: {error:e}"
        assert scaled_error(robot.forward_dynamics(q, qd, tau), qdd) < 1e-9


def with_numbers(path, values, out):
    """The description file ``path`` with each parameter's value written in its place, as
    JSON at ``out``."""
    text = tomllib.loads(path.read_text())
    symbol = re.compile(r"\b(" + "|".join(map(re.escape, values)) + r")\b")

    def substitute(node, key=None):
        if isinstance(node, dict):
            return {k: substitute(v, k) for k, v in node.items()}
        if isinstance(node, list):
            return [substitute(v) for v in node]
        if isinstance(node, str) and key not in ("name", "type"):
            return symbol.sub(lambda m: f"({values[m.group(1)]!r})", node)
        return node

    out.write_text(json.dumps(substitute(text)))
    return out


@pytest.mark.parametrize("path", [p for p in ROBOT_FILES if "niku" in p.stem or p == ARM],
                         ids=lambda p: p.stem)
def test_a_robot_with_parameters_is_the_robot_with_the_numbers_written_in(path, tmp_path):
    robot = dh_dynamics.Robot.from_file(path, families=ALL_FAMILIES)
    values = some_values(robot.parameters.names, seed=3)
    robot.parameters.update(values)
    numbers = dh_dynamics.Robot.from_file(with_numbers(path, values, tmp_path / "robot.json"),
                                          families=ALL_FAMILIES)
    assert len(numbers.parameters) == 0 and len(robot.parameters) > 0
    # The numbers give the base parameters too, where the symbols are lengths or angles.
    assert set(robot.methods) <= set(numbers.methods)
    for name in robot.methods:
        inputs = method_inputs(getattr(robot, name), 7, seed=4)
        got, want = getattr(robot, name)(*inputs), getattr(numbers, name)(*inputs)
        for a, b in zip(parts(got), parts(want)):
            assert scaled_error(a, b) < 1e-12, (path.stem, name)


def test_the_parameters_can_change_after_loading():
    arm = dh_dynamics.Robot.from_file(ARM, parameters=some_values(
        ["m1", "m2", "m3", "a2", "a3", "g"], seed=5))
    q = states(3, 4, seed=5)[0]
    before = arm.gravity_torques(q)
    arm.parameters["g"] *= 2
    # g(q) is linear in g.
    assert scaled_error(arm.gravity_torques(q), 2 * before) < 1e-14
    arm.parameters.update(m2=0.0, m3=0.0)
    assert np.array_equal(arm.gravity_torques(q), np.zeros((4, 3)))


def test_a_robot_with_parameters_runs_under_python_O():
    """``python -O`` took out the check that stood for the parameters, and the C functions
    read the robot's `params` from the first input array's place (a segmentation fault)."""
    script = (
        "import dh_dynamics, numpy as np\n"
        f"arm = dh_dynamics.Robot.from_file({str(ARM)!r}, parameters=dict(m1=1.0, m2=2.0, "
        "m3=3.0, a2=0.5, a3=0.4, g=9.81))\n"
        "q = np.array([0.1, 0.2, 0.3])\n"
        "print(repr(float(arm.mass_matrix(q)[0, 0])))\n"
    )
    run = subprocess.run([sys.executable, "-O", "-c", script], capture_output=True, text=True,
                         check=False)
    assert run.returncode == 0, run.stderr
    # M11 = m2 (a2 C2)² + m3 (a2 C2 + a3 C23)²: the point masses' distances from z0.
    c2, c23 = np.cos(0.2), np.cos(0.5)
    want = 2.0 * (0.5 * c2) ** 2 + 3.0 * (0.5 * c2 + 0.4 * c23) ** 2
    assert abs(float(run.stdout) - want) < 1e-14


def test_the_parameters_errors_name_what_is_wrong():
    arm = dh_dynamics.Robot.from_file(ARM)
    assert arm.parameters.names == ("a2", "a3", "g", "m1", "m2", "m3")
    assert dict(arm.parameters) == dict.fromkeys(arm.parameters.names)
    with pytest.raises(ValueError, match=r"articulated_3r\.mass_matrix: the robot's parameters "
                                         r"`a2`, `a3`, `g`, `m1`, `m2`, `m3` have no value"):
        arm.mass_matrix(np.zeros(3))
    good = some_values(arm.parameters.names, seed=6)
    expected = "its parameters: a2, a3, g, m1, m2, m3"
    with pytest.raises(ValueError, match=f"no value for `g`, `m3`; {expected}"):
        dh_dynamics.Robot.from_file(ARM, parameters={k: v for k, v in good.items()
                                                     if k not in ("g", "m3")})
    with pytest.raises(ValueError, match=f"no parameter `l1`; {expected}"):
        dh_dynamics.Robot.from_file(ARM, parameters=dict(good, l1=1.0))
    with pytest.raises(ValueError, match=f"has no parameter `mass`; {expected}"):
        arm.parameters["mass"] = 1.0
    with pytest.raises(KeyError, match="has no parameter `mass`"):
        arm.parameters["mass"]
    for bad in (np.nan, np.inf, -np.inf, 10 ** 400):
        with pytest.raises(ValueError, match="parameter `m1` = .*: expected a finite number"):
            arm.parameters["m1"] = bad
    for bad in ("2.0", None, True, 1 + 2j, [1.0], np.ones(2)):
        with pytest.raises(TypeError, match="parameter `m1` = .*: expected a real number"):
            arm.parameters["m1"] = bad
    # Checked before any is changed.
    with pytest.raises(ValueError):
        arm.parameters.update(m1=1.0, m2=np.nan)
    assert arm.parameters["m1"] is None
    arm.parameters = good
    with pytest.raises(TypeError, match="cannot be removed"):
        del arm.parameters["m1"]
    with pytest.raises(ValueError, match="no value for `a3`"):
        arm.parameters = {k: v for k, v in good.items() if k != "a3"}
    assert dict(arm.parameters) == good
    # Numbers of any real type; a float32 call with a value beyond float32's range is refused.
    arm.parameters.update(m1=np.float32(1.5), m2=np.int64(2), m3=np.array(3.0))
    assert (arm.parameters["m1"], arm.parameters["m2"], arm.parameters["m3"]) == (1.5, 2.0, 3.0)
    arm.parameters["m3"] = 1e39
    with pytest.raises(ValueError, match="beyond float32's range"):
        arm.mass_matrix(np.zeros(3, np.float32))
    assert np.isfinite(arm.mass_matrix(np.zeros(3))).all()
    puma = dh_dynamics.Robot.from_file(ROOT / "robots" / "puma560.toml", parameters={})
    assert len(puma.parameters) == 0
    with pytest.raises(ValueError, match="no parameter `g`; the robot has no parameters"):
        dh_dynamics.Robot.from_file(ROOT / "robots" / "puma560.toml", parameters={"g": 9.81})

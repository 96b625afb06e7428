"""The package's type information (``py.typed``, ``dh_dynamics/robot.pyi``, whose methods
``tests/tests/it/python_stubs.rs`` generates from the method table): the stub against the methods a
robot has at run time, and mypy on calls against the installed package, where a correct call
type-checks and a missing argument or a misspelt method is an error (skipped without mypy)."""

import ast
import importlib.util
import pathlib
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import dh_dynamics
from dh_dynamics import _native
from dh_dynamics._methods import _STRUCTS
from conftest import DATA

STUB = pathlib.Path(dh_dynamics.__file__).with_name("robot.pyi")


def stub_methods():
    """The stub's `Robot` functions by name: their arguments after `self` and their result."""
    tree = ast.parse(STUB.read_text(encoding="utf-8"))
    robot = next(node for node in tree.body if getattr(node, "name", None) == "Robot")
    return {
        f.name: ([a.arg for a in f.args.args[1:]], ast.unparse(f.returns))
        for f in robot.body
        if isinstance(f, ast.FunctionDef)
    }


def test_the_package_is_typed():
    assert STUB.with_name("py.typed").is_file()


def test_the_stub_declares_each_method_as_a_robot_has_it():
    # Every family: the opt-in ones, and the simplified models of the file's `[simplify]`.
    robot = dh_dynamics.Robot.from_file(DATA / "simplify" / "two_link.toml",
                                        families=["derivatives", "regressor", "base_parameters",
                                                  "tip_kinematics"])
    declared = stub_methods()
    table = [name for name, _, _ in _native.methods()]
    assert set(robot.methods) == set(table)
    for name in robot.methods:
        method = getattr(robot, name)
        assert name in declared, f"robot.pyi does not declare {name}"
        arguments, returns = declared[name]
        assert arguments == [a for a, _ in method._arguments], name
        result = method(*[np.full(length, 0.1) for _, length in method._arguments])
        if name in _STRUCTS:
            assert returns == _STRUCTS[name].__name__
        elif isinstance(result, float):
            assert returns == "float | NDArray[np.floating[Any]]", name
        else:
            assert isinstance(result, np.ndarray), name
            assert returns == "NDArray[np.floating[Any]]", name


SNIPPETS = {
    "correct.py": """
        from typing import Any, Union

        import numpy as np
        from numpy.typing import NDArray
        from typing_extensions import assert_type

        import dh_dynamics

        robot = dh_dynamics.Robot.from_file("puma560.toml", families=["derivatives"])
        q = np.zeros((10, robot.dof))
        tau = robot.inverse_dynamics(q, [0.0] * 6, qdd=q)
        assert_type(tau, NDArray[np.floating[Any]])
        energy = robot.kinetic_energy(q, q)
        assert_type(energy, Union[float, NDArray[np.floating[Any]]])
        assert_type(robot.forward_dynamics_derivatives(q, q, tau).dqdd_dq,
                    NDArray[np.floating[Any]])
        robot.parameters["m1"] = 2.0
        assert_type(robot.methods, tuple[str, ...])
    """,
    "missing.py": """
        import dh_dynamics

        robot = dh_dynamics.Robot.from_urdf("ur5.urdf", tip="tool0")
        robot.inverse_dynamics([0.0] * 6, [0.0] * 6)
    """,
    "misspelt.py": """
        import dh_dynamics

        robot = dh_dynamics.Robot.from_file("puma560.toml")
        robot.inverse_dynamic([0.0] * 6, [0.0] * 6, [0.0] * 6)
    """,
}


def mypy(tmp_path, *arguments):
    """mypy's report on `arguments`, run in `tmp_path`, so that it reads the installed package
    and not a source tree."""
    if importlib.util.find_spec("mypy") is None:
        pytest.skip("mypy is not installed")
    run = subprocess.run([sys.executable, "-m", *arguments], cwd=tmp_path, capture_output=True,
                         text=True, check=False)
    return run.stdout + run.stderr


def test_mypy_checks_calls_against_the_stub(tmp_path):
    for name, text in SNIPPETS.items():
        (tmp_path / name).write_text(textwrap.dedent(text))
    report = mypy(tmp_path, "mypy", "--no-incremental", "--cache-dir", str(tmp_path / "cache"),
                  *SNIPPETS)
    errors = {name: [line for line in report.splitlines()
                     if line.startswith(f"{name}:") and ": error:" in line]
              for name in SNIPPETS}
    assert errors["correct.py"] == [], report
    assert len(errors["missing.py"]) == 1, report
    assert 'Missing positional argument "qdd" in call to "inverse_dynamics"' in report
    assert len(errors["misspelt.py"]) == 1, report
    assert '"Robot" has no attribute "inverse_dynamic"' in report


def test_the_stub_matches_the_runtime(tmp_path):
    # stubtest compares the stub's constructors and attributes with `robot.py`; the generated
    # methods, attached per robot at run time, are checked above.
    allowed = tmp_path / "generated.txt"
    # A floating base's, attached the same way (`floating=True`; `test_floating.py`).
    floating = ["bias_forces", "generalized_gravity", "integrate", "difference",
                "integrate_jacobian_v", "integrate_jacobian_q", "difference_jacobian_q0",
                "difference_jacobian_q1",
                "center_of_mass", "center_of_mass_jacobian", "centroidal_momentum_matrix",
                "centroidal_momentum_bias", "frame_poses", "frame_jacobians_world_aligned",
                "frame_jacobians_local", "frame_acceleration_biases_world_aligned",
                "frame_acceleration_biases_local", "inverse_dynamics_with_wrenches",
                "forward_dynamics_with_wrenches", "contact_dynamics"]
    names = [name for name, _, _ in _native.methods()] + floating
    allowed.write_text("".join(f"dh_dynamics.robot.Robot.{name}\n" for name in names))
    report = mypy(tmp_path, "mypy.stubtest", "dh_dynamics", "--allowlist", str(allowed))
    assert "Success" in report, report

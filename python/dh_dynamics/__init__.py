"""dh_dynamics: a serial robot's closed-form equations of motion on NumPy arrays.

The generator reads the robot's description (a D-H table or joint frames in a TOML or JSON
file, or a URDF file) and writes the robot's equations as straight-line C, the same closed
forms as ``#[derive(Dynamics)]`` generates in Rust; the package compiles them once for this
machine (cached) and calls them over whole batches of states::

    import numpy as np
    import dh_dynamics

    robot = dh_dynamics.Robot.from_file("robots/puma560.toml")
    q, qd, qdd = np.random.default_rng(0).uniform(-1, 1, (3, 1000, 6))
    tau = robot.inverse_dynamics(q, qd, qdd)        # (1000, 6), one call
    print(robot.equations())                        # M, C, g in the book's notation
"""

from ._compiled import CompilerError
from ._errors import DescriptionError, NotPositiveDefinite
from .robot import Robot

__all__ = ["Robot", "DescriptionError", "NotPositiveDefinite", "CompilerError"]

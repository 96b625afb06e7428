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

A description whose quantities are symbols (``mass = "m1"``) takes their values::

    arm = dh_dynamics.Robot.from_file("robots/articulated_3r.toml",
                                      parameters={"m1": 1, "m2": 2, "m3": 1, "a2": 0.4,
                                                  "a3": 0.3, "g": 9.81})
    arm.parameters["m3"] = 1.5                      # a payload, say
"""

from ._compiled import CompilerError
from ._errors import DescriptionError, Diagnostic, NonFiniteInput, NotPositiveDefinite
from ._methods import ForwardDynamicsDerivatives, InverseDynamicsDerivatives
from ._parameters import Parameters
from .robot import Robot

__all__ = [
    "Robot",
    "Parameters",
    "InverseDynamicsDerivatives",
    "ForwardDynamicsDerivatives",
    "DescriptionError",
    "Diagnostic",
    "NonFiniteInput",
    "NotPositiveDefinite",
    "CompilerError",
]

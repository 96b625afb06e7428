"""The types of :class:`Robot`, for editors and type checkers. Its methods are attached at run
time, one per function of the robot's C header; they are declared here, one per row of the
method table, so that a method of a family a robot was built without type-checks and raises
``AttributeError`` when called."""

import os
from collections.abc import Iterable, Mapping
from typing import Any, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._methods import ForwardDynamicsDerivatives, InverseDynamicsDerivatives
from ._parameters import Parameters

_Path = Union[str, bytes, os.PathLike[str], os.PathLike[bytes]]

class Robot:
    name: str
    dof: int
    floating: bool
    frames: tuple[str, ...]
    joint_rows: tuple[int, ...]
    header: str
    methods: tuple[str, ...]

    def __init__(
        self,
        path: _Path,
        *,
        base: str | None = None,
        tip: str | None = None,
        tips: str | Iterable[str] = (),
        tool: Iterable[float] | None = None,
        families: str | Iterable[str] = (),
        parameters: Mapping[str, float] | None = None,
        check_inertia: bool = True,
        floating: bool = False,
        contacts: bool = False,
    ) -> None: ...
    @classmethod
    def from_file(
        cls,
        path: _Path,
        *,
        families: str | Iterable[str] = (),
        tool: Iterable[float] | None = None,
        parameters: Mapping[str, float] | None = None,
        floating: bool = False,
        contacts: bool = False,
    ) -> Robot: ...
    @classmethod
    def from_urdf(
        cls,
        path: _Path,
        base: str | None = None,
        tip: str | None = None,
        *,
        tips: str | Iterable[str] = (),
        families: str | Iterable[str] = (),
        check_inertia: bool = True,
        floating: bool = False,
        contacts: bool = False,
    ) -> Robot: ...
    @property
    def parameters(self) -> Parameters: ...
    @parameters.setter
    def parameters(self, values: Mapping[str, float]) -> None: ...
    def equations(self, latex: bool = False, kinematics: bool = False) -> str: ...
    def _repr_latex_(self) -> str: ...

    # The methods, generated from the method table (`dynamics-runtime/src/methods.rs`) by
    # `tests/tests/it/python_stubs.rs`: `DYNAMICS_BLESS=1 cargo test -p dynamics-tests
    # --test it python_stubs` rewrites them to the end marker. Each input is one state, shape
    # (n,), or a batch, shape (N, n); the result has (N,) before one state's shape for a batch.
    def mass_matrix(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """M(q), with the actuator inertia on the diagonal."""
    def coriolis_matrix(self, q: ArrayLike, qd: ArrayLike) -> NDArray[np.floating[Any]]:
        """C(q, q̇), with C_ij = Σ_k D_ijk q̇_k."""
    def coriolis_torques(self, q: ArrayLike, qd: ArrayLike) -> NDArray[np.floating[Any]]:
        """C(q, q̇) q̇."""
    def gravity_torques(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """g(q), with joint springs."""
    def bias_torques(self, q: ArrayLike, qd: ArrayLike) -> NDArray[np.floating[Any]]:
        """C(q, q̇) q̇ + g(q)."""
    def inverse_dynamics(
        self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """τ = M(q) q̈ + C(q, q̇) q̇ + g(q)."""
    def friction_torques(self, qd: ArrayLike) -> NDArray[np.floating[Any]]:
        """Joint friction: f_v q̇ + f_c sign(q̇) + f_0."""
    def kinetic_energy(self, q: ArrayLike, qd: ArrayLike) -> float | NDArray[np.floating[Any]]:
        """The kinetic energy."""
    def potential_energy(self, q: ArrayLike) -> float | NDArray[np.floating[Any]]:
        """The potential energy."""
    def hand_pose(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The hand frame's pose, A1 ⋯ An (and the tool)."""
    def link_poses(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The pose of every link frame, A1 ⋯ Ai."""
    def hand_jacobian_in_base(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The hand's Jacobian in the base frame."""
    def hand_jacobian_in_hand(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The book's ᴴJ, the hand's Jacobian in the hand frame."""
    def hand_acceleration_bias_in_base(
        self, q: ArrayLike, qd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """J̇ q̇ of the hand, in the base frame."""
    def hand_acceleration_bias_in_hand(
        self, q: ArrayLike, qd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """J̇ q̇ of the hand, in the hand's axes."""
    def joint_torques_for_hand_wrench(
        self, q: ArrayLike, wrench: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """T = ᴴJᵀ ᴴF for a wrench in the hand frame."""
    def joint_torques_for_base_wrench(
        self, q: ArrayLike, wrench: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """T = Jᵀ F for a wrench in base axes."""
    def mass_matrix_inverse(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """M(q)⁻¹, through the LDLᵀ of M."""
    def forward_dynamics(
        self, q: ArrayLike, qd: ArrayLike, tau: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """q̈ = M(q)⁻¹ (τ − C(q, q̇) q̇ − g(q) − f(q̇))."""
    def inverse_dynamics_derivatives(
        self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike
    ) -> InverseDynamicsDerivatives:
        """∂τ/∂q and ∂τ/∂q̇ at (q, q̇, q̈).

        Opt-in: ``families=['derivatives']``.
        """
    def forward_dynamics_derivatives(
        self, q: ArrayLike, qd: ArrayLike, tau: ArrayLike
    ) -> ForwardDynamicsDerivatives:
        """q̈, ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = M⁻¹ at (q, q̇, τ).

        Opt-in: ``families=['derivatives']``.
        """
    def regressor(self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike) -> NDArray[np.floating[Any]]:
        """Y(q, q̇, q̈), with τ = Y π for the rigid bodies.

        Opt-in: ``families=['regressor']``.
        """
    def joint_regressor(self, qd: ArrayLike, qdd: ArrayLike) -> NDArray[np.floating[Any]]:
        """The actuator inertia's and friction's columns, per joint.

        Opt-in: ``families=['regressor']``.
        """
    def joint_parameters(self) -> NDArray[np.floating[Any]]:
        """The actuator inertia and friction coefficients, per joint.

        Opt-in: ``families=['regressor']``.
        """
    def standard_parameters(self) -> NDArray[np.floating[Any]]:
        """The standard parameters π of each link.

        Opt-in: ``families=['regressor']``.
        """
    def inverse_dynamics_simplified(
        self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """τ pruned within the tolerance over the envelope.

        Only for a description file with a ``[simplify]`` table.
        """
    def mass_matrix_simplified(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """M(q) pruned within the tolerance over the envelope.

        Only for a description file with a ``[simplify]`` table.
        """
    def coriolis_torques_simplified(
        self, q: ArrayLike, qd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """C(q, q̇) q̇ pruned within the tolerance over the envelope.

        Only for a description file with a ``[simplify]`` table.
        """
    def gravity_torques_simplified(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """g(q) pruned within the tolerance over the envelope.

        Only for a description file with a ``[simplify]`` table.
        """
    def base_regressor(
        self, q: ArrayLike, qd: ArrayLike, qdd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """Y_B(q, q̇, q̈), with τ = Y_B π_B.

        Opt-in: ``families=['base_parameters']``.
        """
    def base_parameters(self) -> NDArray[np.floating[Any]]:
        """The base parameters π_B of the description.

        Opt-in: ``families=['base_parameters']``.
        """
    def base_from_standard(self) -> NDArray[np.floating[Any]]:
        """The map P from the links' standard parameters π to π_B.

        Opt-in: ``families=['base_parameters']``.
        """
    def base_from_joints(self) -> NDArray[np.floating[Any]]:
        """The map P_J from the joints' parameters to π_B.

        Opt-in: ``families=['base_parameters']``.
        """
    def tip_poses(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The pose of every tip frame.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def tip_jacobians_in_base(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """Every tip's Jacobian in the base frame.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def tip_jacobians_in_tip(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """Every tip's Jacobian in its own frame.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def tip_acceleration_biases_in_base(
        self, q: ArrayLike, qd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """J̇ q̇ of every tip, in the base frame.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def tip_acceleration_biases_in_tip(
        self, q: ArrayLike, qd: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """J̇ q̇ of every tip, in its own axes.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def joint_torques_for_tip_wrenches(
        self, q: ArrayLike, wrenches: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """T = Σ J_tᵀ F_t for a wrench at each tip, in its frame.

        Opt-in: ``families=['tip_kinematics']``.
        """
    def joint_torques_for_tip_wrenches_in_base(
        self, q: ArrayLike, wrenches: ArrayLike
    ) -> NDArray[np.floating[Any]]:
        """T = Σ J_tᵀ F_t for a wrench at each tip, in base axes.

        Opt-in: ``families=['tip_kinematics']``.
        """
    # End of the generated methods.

    # A floating base's (`floating=True`): `FloatingDynamics`' methods that a fixed base has not
    # (its others share their names and arguments), and the configuration space's.
    def bias_forces(self, q: ArrayLike, qd: ArrayLike) -> NDArray[np.floating[Any]]:
        """h(q, v) = C(q, v) v + g(q) of a floating base."""
    def generalized_gravity(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """g(q) of a floating base."""
    def integrate(self, q: ArrayLike, v: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's integrate: the configuration reached from q by the velocity v."""
    def difference(self, q0: ArrayLike, q1: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's difference: the velocity v with integrate(q0, v) = q1."""
    def integrate_jacobian_v(self, q: ArrayLike, v: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's dIntegrate(q, v, ARG1): d integrate(q, v) / dv."""
    def integrate_jacobian_q(self, q: ArrayLike, v: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's dIntegrate(q, v, ARG0): d integrate(q, v) / dq."""
    def difference_jacobian_q0(self, q0: ArrayLike, q1: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's dDifference(q0, q1, ARG0): d difference(q0, q1) / dq0."""
    def difference_jacobian_q1(self, q0: ArrayLike, q1: ArrayLike) -> NDArray[np.floating[Any]]:
        """Pinocchio's dDifference(q0, q1, ARG1): d difference(q0, q1) / dq1."""
    # A floating base's kinematics and contacts (the header's, `_floating.py`), frames by name.
    def center_of_mass(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """The centre of mass in the world (centerOfMass)."""
    def center_of_mass_jacobian(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """Its Jacobian, 3 x nv (jacobianCenterOfMass)."""
    def centroidal_momentum_matrix(self, q: ArrayLike) -> NDArray[np.floating[Any]]:
        """A_G, 6 x nv (computeCentroidalMap)."""
    def centroidal_momentum_bias(self, q: ArrayLike, v: ArrayLike) -> NDArray[np.floating[Any]]:
        """dA_G/dt v."""
    def frame_poses(self, q: ArrayLike) -> dict[str, NDArray[np.floating[Any]]]:
        """Each frame's pose [R | p] in the world, 3 x 4 (oMf)."""
    def frame_jacobians_world_aligned(self, q: ArrayLike) -> dict[str, NDArray[np.floating[Any]]]:
        """Each frame's Jacobian in LOCAL_WORLD_ALIGNED, 6 x nv."""
    def frame_jacobians_local(self, q: ArrayLike) -> dict[str, NDArray[np.floating[Any]]]:
        """Each frame's Jacobian in LOCAL, 6 x nv."""
    def frame_acceleration_biases_world_aligned(
        self, q: ArrayLike, v: ArrayLike
    ) -> dict[str, NDArray[np.floating[Any]]]:
        """Each frame origin's classical acceleration at a = 0, world axes: Jd v."""
    def frame_acceleration_biases_local(
        self, q: ArrayLike, v: ArrayLike
    ) -> dict[str, NDArray[np.floating[Any]]]:
        """The same in the frame's own axes."""
    def inverse_dynamics_with_wrenches(
        self, q: ArrayLike, v: ArrayLike, a: ArrayLike, wrenches: Mapping[str, ArrayLike]
    ) -> NDArray[np.floating[Any]]:
        """tau = M a + h - sum_f J_f^T w_f, wrenches [f, m] (or forces f) by frame name."""
    def forward_dynamics_with_wrenches(
        self, q: ArrayLike, v: ArrayLike, tau: ArrayLike, wrenches: Mapping[str, ArrayLike]
    ) -> NDArray[np.floating[Any]]:
        """a = M^-1 (tau - h + sum_f J_f^T w_f)."""
    def contact_dynamics(
        self, q: ArrayLike, v: ArrayLike, tau: ArrayLike, in_contact: Iterable[str]
    ) -> tuple[NDArray[np.floating[Any]], dict[str, NDArray[np.floating[Any]]]]:
        """The forward dynamics with the named frames' origins held: (a, forces by frame)."""

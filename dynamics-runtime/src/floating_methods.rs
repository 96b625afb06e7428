// The method table's rows of a robot on a free-flying base (`base = floating`), apart from
// `methods.rs` for its length: `for_each_tip_method!` hands every other row to
// `for_each_floating_method!`, which adds these and calls the callback with all of them (the
// same `include!`d symlink in `dynamics-codegen`). The trait's first const parameter, `Q`, is
// the configuration's length (`n + 7`), `N` the velocity's (`n + 6`): `q` is `&[T; Q]`, `v`, `a`
// and `tau` are `&[T; N]`, and the results' `N` is the velocity's.

/// Calls `$callback!` with the rows given and the floating base's trait row after them.
macro_rules! for_each_floating_method {
    ($callback:ident { $($rows:tt)* }) => {
        $callback! {
            $($rows)*
            /// Closed-form dynamics of a kinematic tree on a free-flying base, Pinocchio's free
            /// flyer: `τ = M(q) a + h(q, v)`, and its forward dynamics. Implemented by `#[derive(Dynamics)]` for a robot
            /// with `base = floating` (see `docs/floating-base.md`).
            ///
            /// The configuration `q` has `Q = NQ = n + 7` entries,
            /// `[x, y, z, qx, qy, qz, qw, q_1 … q_n]`: the base origin in the world, the base
            /// orientation as a unit quaternion, then the joints. The velocity `v` and
            /// acceleration `a` have `N = NV = n + 6`, `[v_x, v_y, v_z, ω_x, ω_y, ω_z, q̇_1 …]`:
            /// the base origin's velocity and the base's angular velocity, both in the base
            /// frame, then the joint rates. The first six rows of a generalized force are the
            /// wrench on the base, `[f_x, f_y, f_z, m_x, m_y, m_z]` in the base frame, its moment
            /// about the base origin.
            ///
            /// The quaternion is read as given: its rotation matrix is the polynomial of its
            /// components, a rotation only if it is unit (as in Pinocchio). Only gravity reads
            /// it; nothing reads the base position.
            trait FloatingDynamics<Q, N>, nalgebra FloatingDynamicsNalgebra, batch FloatingDynamicsBatch {
                items {
                    /// The configuration's length, `n + 7`.
                    const NQ: usize = Q;
                    /// The velocity's length, `n + 6`.
                    const NV: usize = N;
                    /// Pinocchio's `integrate(q, v)`: the configuration reached from `q` by the
                    /// velocity `v` held for unit time, the base moved by SE(3)'s exponential of
                    /// its twist (in its own frame), the quaternion renormalised to first order,
                    /// the joints `q_i + v_i`. The same function for every robot (in the runtime,
                    /// not generated); `f32` and `f64`.
                    #[inline]
                    fn integrate<T: crate::RealScalar>(&self, q: &[T; Q], v: &[T; N]) -> [T; Q] {
                        crate::configuration::integrate(q, v)
                    }
                    /// Pinocchio's `difference(q0, q1)`: the velocity `v` with
                    /// `integrate(q0, v) = q1`, the base's the logarithm of `M0⁻¹ M1` (the shorter
                    /// rotation), the joints `q1_i − q0_i`.
                    #[inline]
                    fn difference<T: crate::RealScalar>(&self, q0: &[T; Q], q1: &[T; Q]) -> [T; N] {
                        crate::configuration::difference(q0, q1)
                    }
                    /// Pinocchio's `dIntegrate(q, v, ARG1)`: `∂ integrate(q, v) / ∂v`, in the
                    /// tangent space at the result (the base's block SE(3)'s right Jacobian of
                    /// `v`'s twist, the joints' the identity); it does not depend on `q`.
                    #[inline]
                    fn integrate_jacobian_v<T: crate::RealScalar>(&self, q: &[T; Q], v: &[T; N]) -> [[T; N]; N] {
                        let _ = q;
                        crate::configuration::integrate_jacobian(v)
                    }
                    /// Pinocchio's `dIntegrate(q, v, ARG0)`: `∂ integrate(q, v) / ∂q`, from the
                    /// tangent space at `q` to the one at the result (the base's block
                    /// `Ad(exp6(v_b)⁻¹)`, the joints' the identity); it does not depend on `q`.
                    #[inline]
                    fn integrate_jacobian_q<T: crate::RealScalar>(&self, q: &[T; Q], v: &[T; N]) -> [[T; N]; N] {
                        let _ = q;
                        crate::configuration::integrate_jacobian_q(v)
                    }
                    /// Pinocchio's `dDifference(q0, q1, ARG0)`: `∂ difference(q0, q1) / ∂q0` in
                    /// the tangent space at `q0` (the base's block `−Jlog6(M) Ad(M⁻¹)`,
                    /// `M = M0⁻¹ M1`, the joints' `−1`).
                    #[inline]
                    fn difference_jacobian_q0<T: crate::RealScalar>(&self, q0: &[T; Q], q1: &[T; Q]) -> [[T; N]; N] {
                        crate::configuration::difference_jacobian_q0(q0, q1)
                    }
                    /// Pinocchio's `dDifference(q0, q1, ARG1)`: `∂ difference(q0, q1) / ∂q1` in
                    /// the tangent space at `q1` (the base's block `Jlog6(M0⁻¹ M1)`, the
                    /// joints' the identity).
                    #[inline]
                    fn difference_jacobian_q1<T: crate::RealScalar>(&self, q0: &[T; Q], q1: &[T; Q]) -> [[T; N]; N] {
                        crate::configuration::difference_jacobian_q1(q0, q1)
                    }
                }
                /// M, h, τ and g of a floating base.
                family Floating {
                    name: floating,
                    module: "__floating",
                    opt_in: false,
                    adjective: "floating ",
                }
                methods {
                    /// The mass matrix `M(q)`, base rows and columns first (Pinocchio's `crba`,
                    /// symmetric).
                    fn mass_matrix(q) -> matrix, nalgebra mass_matrix_na, batch mass_matrix_batch {
                        variant: FloatingMassMatrix,
                        equation: None,
                        prefix: "m",
                        summary: "M(q) of a floating base, its rows first.",
                        element: "M{i}{j} = M{j}{i}",
                        diagonal: "M{i}{i}",
                        into: mass_matrix_into,
                    }
                    /// The bias `h(q, v) = C(q, v) v + g(q)` (Pinocchio's `nonLinearEffects`).
                    fn bias_forces(q, v) -> vector, nalgebra bias_forces_na, batch bias_forces_batch {
                        variant: FloatingBiasForces,
                        equation: None,
                        prefix: "h",
                        summary: "h(q, v) = C(q, v) v + g(q) of a floating base.",
                        element: "centripetal, Coriolis and gravity force {i}",
                    }
                    /// Inverse dynamics `τ = M(q) a + h(q, v)` (Pinocchio's `rnea`): the base's six
                    /// rows are the wrench the base needs (from contacts), the others the joint
                    /// torques.
                    fn inverse_dynamics(q, v, a) -> vector, nalgebra inverse_dynamics_na, batch inverse_dynamics_batch {
                        variant: FloatingInverseDynamics,
                        equation: None,
                        prefix: "tau",
                        summary: "τ = M(q) a + h(q, v) of a floating base, the base's wrench first.",
                        element: "generalized force {i}",
                    }
                    /// The generalized gravity `g(q)` (Pinocchio's `computeGeneralizedGravity`).
                    fn generalized_gravity(q) -> vector, nalgebra generalized_gravity_na, batch generalized_gravity_batch {
                        variant: FloatingGravity,
                        equation: None,
                        prefix: "g",
                        summary: "g(q) of a floating base.",
                        element: "gravity force {i}",
                    }
                }
                /// Forward dynamics and `M⁻¹` of a floating base, through the LDLᵀ of `M`.
                family FloatingForward {
                    name: floating_forward,
                    module: "__floating_forward",
                    opt_in: false,
                    adjective: "floating forward ",
                }
                methods {
                    /// The inverse of the mass matrix, `M(q)⁻¹` (Pinocchio's `computeMinverse`),
                    /// through the LDLᵀ of `M` factored from the tips (Featherstone's `Lᵀ D L`,
                    /// the base last); `Err(NotPositiveDefinite)` where a pivot is not positive
                    /// (on lane types, where at least one lane's is not).
                    fn mass_matrix_inverse(q) -> solved_matrix, nalgebra mass_matrix_inverse_na, batch mass_matrix_inverse_batch {
                        variant: FloatingMassMatrixInverse,
                        equation: None,
                        prefix: "mi",
                        summary: "M(q)⁻¹ of a floating base, through the LDLᵀ of M.",
                        element: "(M^-1){i}{j}",
                    }
                    /// Forward dynamics without contact, `a = M(q)⁻¹ (tau − h(q, v))` (Pinocchio's
                    /// `aba`), through the same factors: the inverse of `inverse_dynamics`, the
                    /// base's six entries of `tau` a wrench on the base in its frame.
                    /// `Err(NotPositiveDefinite)` where a pivot is not positive.
                    fn forward_dynamics(q, v, tau) -> solved_vector, nalgebra forward_dynamics_na, batch forward_dynamics_batch {
                        variant: FloatingForwardDynamics,
                        equation: None,
                        prefix: "acc",
                        summary: "a = M(q)⁻¹ (τ − h(q, v)) of a floating base.",
                        element: "acceleration {i}",
                    }
                }
            }
            /// The first derivatives of a floating base's dynamics (Pinocchio's
            /// `computeRNEADerivatives` and `computeABADerivatives` on the free flyer), for
            /// model-predictive control: implemented by `#[derive(Dynamics)]` for a robot with
            /// `base = floating` and `derivatives = true`.
            ///
            /// A derivative by `q` is along the tangent, `N = n + 6` columns: column j is
            /// `d/dε f(integrate(q, ε e_j))` at 0, the base moved in its own frame (its
            /// position, then its rotation `δω`), then the joints. Only gravity reads the base
            /// pose, as `g_b = Rᵀ g`, which turns as `g_b × δω`: the position's three columns are
            /// zero and the rotation's `−M[:, 0..3] [g_b]×`. By `v`, `a` and `tau`, the vectors'
            /// own entries. The quaternion is taken to be unit (its rotation a rotation).
            trait FloatingDynamicsDerivatives<Q, N>: FloatingDynamics<Q, N>, nalgebra FloatingDynamicsDerivativesNalgebra, batch FloatingDynamicsDerivativesBatch {
                items {}
                /// The derivatives of a floating base's inverse and forward dynamics.
                family FloatingDerivatives {
                    name: derivatives,
                    module: "__floating_derivatives",
                    opt_in: true,
                    adjective: "floating derivatives' ",
                }
                methods {
                    /// `∂τ/∂q` (along the tangent, `N × N`) and `∂τ/∂v` at `(q, v, a)`, row i the
                    /// derivatives of `τ_i` (Pinocchio's `computeRNEADerivatives`; `∂τ/∂a` is
                    /// `mass_matrix(q)`). The fields are named as a fixed base's: `dtau_dq`,
                    /// `dtau_dqd` (by `v`).
                    fn inverse_dynamics_derivatives(q, v, a) -> inverse_derivatives, nalgebra inverse_dynamics_derivatives_na, batch inverse_dynamics_derivatives_batch {
                        variant: FloatingInverseDynamicsDerivatives,
                        equation: None,
                        prefix: "dtau",
                        summary: "∂τ/∂q (along the tangent) and ∂τ/∂v of a floating base at (q, v, a).",
                        element: "d tau{i} / d {x}{j}",
                    }
                    /// Forward dynamics and its derivatives at `(q, v, tau)` (Pinocchio's
                    /// `computeABADerivatives`): `a`, `∂a/∂q` (along the tangent), `∂a/∂v` and
                    /// `∂a/∂tau = M⁻¹`, the first two `−M⁻¹ ∂τ/∂x` at that `a`, solved with the
                    /// LDLᵀ of `M`; the base rotation's columns are exact, `[g_b]×` in the base's
                    /// linear rows and zero elsewhere. `Err(NotPositiveDefinite)` where a pivot is
                    /// not positive.
                    fn forward_dynamics_derivatives(q, v, tau) -> forward_derivatives, nalgebra forward_dynamics_derivatives_na, batch forward_dynamics_derivatives_batch {
                        variant: FloatingForwardDynamicsDerivatives,
                        equation: None,
                        prefix: "dacc",
                        summary: "a, ∂a/∂q (along the tangent), ∂a/∂v and ∂a/∂τ = M⁻¹ of a floating base at (q, v, τ).",
                        element: "d acc{i} / d {x}{j}",
                        compiled_apart: true,
                    }
                }
            }
            /// The joint torque regressor of a floating base (Pinocchio's
            /// `computeJointTorqueRegressor` on the free flyer), for identifying its inertial
            /// parameters: implemented by `#[derive(Dynamics)]` for a robot with
            /// `base = floating` and `regressor = true`.
            ///
            /// `τ = Σ_j Y_j(q, v, a) π_j` over the `LINKS = n + 1` bodies, the floating body
            /// first (`π_0` about the base origin in base axes), then link j of joint j about the
            /// origin of its link frame (a URDF's link frame), each
            /// `π_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]` (Pinocchio's
            /// `Inertia::toDynamicParameters`); the `N = n + 6` rows are `inverse_dynamics`'.
            trait FloatingDynamicsRegressor<Q, N; LINKS>: FloatingDynamics<Q, N>, nalgebra FloatingDynamicsRegressorNalgebra, batch FloatingDynamicsRegressorBatch {
                items {
                    /// Number of bodies, the floating one first: of column blocks of
                    /// `regressor`.
                    const LINK_COUNT: usize = LINKS;
                }
                /// The joint torque regressor and the standard parameters of a floating base.
                family FloatingRegressor {
                    name: regressor,
                    module: "__floating_regressor",
                    opt_in: true,
                    adjective: "floating regressor's ",
                }
                methods {
                    /// The regressor `Y(q, v, a)`: element `[i][j][k]` is `∂τ_i/∂π_jk`, body 0
                    /// the floating one, so that `Σ_j Σ_k Y[i][j][k] π_jk` is
                    /// `inverse_dynamics(q, v, a)`.
                    fn regressor(q, v, a) -> link_columns, nalgebra regressor_na, batch regressor_batch {
                        variant: FloatingRegressor,
                        equation: None,
                        prefix: "y",
                        summary: "Y(q, v, a) of a floating base, with τ = Y π.",
                        element: "d tau{k} / d pi{i}_{j}",
                        into: regressor_into,
                    }
                    /// The standard parameters `π_j` as the description gives them, the floating
                    /// body's first (about the base origin, in base axes), then each link's about
                    /// the origin of its link frame, per body
                    /// `[m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]`.
                    fn standard_parameters() -> link_parameters, nalgebra standard_parameters_na {
                        variant: FloatingStandardParameters,
                        equation: None,
                        prefix: "pi",
                        summary: "The standard parameters π of each body, the floating one first.",
                        element: "pi{i}_{j}",
                    }
                }
            }
            /// The base parameters of a floating base: the `B` combinations of the standard
            /// parameters (`FloatingDynamicsRegressor`'s, the floating body's first) that the
            /// generalized forces determine, and the reduced regressor `Y_B` of full column
            /// rank, `Y_B(q, v, a) π_B = inverse_dynamics(q, v, a)`. Found exactly from the
            /// closed form, as a fixed base's. `LINKS` is `FloatingDynamicsRegressor`'s.
            trait FloatingDynamicsBaseParameters<Q, N; B, LINKS>: FloatingDynamics<Q, N>, nalgebra FloatingDynamicsBaseParametersNalgebra, batch FloatingDynamicsBaseParametersBatch {
                items {}
                /// The base parameters of a floating base and their reduced regressor.
                family FloatingBaseParameters {
                    name: base_parameters,
                    module: "__floating_base_parameters",
                    opt_in: true,
                    adjective: "floating base parameters' ",
                }
                methods {
                    /// The reduced regressor `Y_B(q, v, a)`: element `[i][b]` is the derivative
                    /// of `τ_i` by base parameter b, in the order of `base_parameters`.
                    fn base_regressor(q, v, a) -> base_columns, nalgebra base_regressor_na, batch base_regressor_batch {
                        variant: FloatingBaseRegressor,
                        equation: None,
                        prefix: "yb",
                        summary: "Y_B(q, v, a) of a floating base, with τ = Y_B π_B.",
                        element: "d tau{i} / d base parameter {j}",
                        into: base_regressor_into,
                    }
                    /// The base parameters `π_B` of the description.
                    fn base_parameters() -> base_vector, nalgebra base_parameters_na {
                        variant: FloatingBaseParameters,
                        equation: None,
                        prefix: "pib",
                        summary: "The base parameters π_B of the description.",
                        element: "base parameter {i}",
                    }
                    /// The map from the bodies' standard parameters (`standard_parameters`'
                    /// layout, the floating body first) to the base parameters:
                    /// `π_B[b] = Σ_j Σ_k P[b][j][k] π_jk`. Constants.
                    fn base_from_standard() -> base_link_map, nalgebra base_from_standard_na {
                        variant: FloatingBaseFromStandard,
                        equation: None,
                        prefix: "pbs",
                        summary: "The map P from the bodies' standard parameters π to π_B.",
                        element: "base parameter {k}: coefficient of pi{i}_{j}",
                    }
                }
            }
        }
    };
}

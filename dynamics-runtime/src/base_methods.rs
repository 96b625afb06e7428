// The method table's row of the base parameters, apart from `methods.rs` for its length:
// `for_each_method!` hands its rows to `for_each_base_method!`, which adds this one after them
// and hands all to `for_each_tip_method!` (the same `include!`d symlink in `dynamics-codegen`).

/// Calls `for_each_tip_method!` with the rows given and the base parameters' trait row after
/// them.
macro_rules! for_each_base_method {
    ($callback:ident { $($rows:tt)* }) => {
        for_each_tip_method! { $callback {
            $($rows)*
            /// The base parameters `π_B`: the combinations of the standard parameters that the
            /// joint torques determine, and the reduced regressor `Y_B` of full column rank, with
            /// `Y_B(q, q̇, q̈) π_B` the rigid bodies' part of `inverse_dynamics` plus the terms of
            /// the joint parameters the description gives (actuator inertia, friction); `B` is
            /// their number. Found exactly from the closed form; `dynamics inspect ROBOT
            /// --base-parameters` prints each as its grouping of standard parameters
            /// (`ZZR1 = ZZ1 + YY2 + …`). `LINKS` is `DynamicsRegressor`'s.
            trait DynamicsBaseParameters<N; B, LINKS = N>: Dynamics<N>, nalgebra DynamicsBaseParametersNalgebra, batch DynamicsBaseParametersBatch {
                items {}
                /// The base parameters and their reduced regressor.
                family BaseParameters {
                    name: base_parameters,
                    module: "__base_parameters",
                    opt_in: true,
                    adjective: "base parameters' ",
                }
                methods {
                    /// The reduced regressor `Y_B(q, q̇, q̈)`: element `[i][b]` is the derivative
                    /// of joint i's torque by base parameter b, in the order of
                    /// `base_parameters` (and of `dynamics inspect --base-parameters`).
                    fn base_regressor(q, qd, qdd) -> base_columns, nalgebra base_regressor_na, batch base_regressor_batch {
                        variant: BaseRegressor,
                        equation: None,
                        prefix: "yb",
                        summary: "Y_B(q, q̇, q̈), with τ = Y_B π_B.",
                        element: "d tau{i} / d base parameter {j}",
                        into: base_regressor_into,
                    }
                    /// The base parameters `π_B` of the description.
                    fn base_parameters() -> base_vector, nalgebra base_parameters_na {
                        variant: BaseParameters,
                        equation: None,
                        prefix: "pib",
                        summary: "The base parameters π_B of the description.",
                        element: "base parameter {i}",
                    }
                    /// The map from the links' standard parameters to the base parameters:
                    /// `π_B[b] = Σ_j Σ_k P[b][j][k] π_jk + Σ_i Σ_k P_J[b][i][k] p_ik`, with `π`
                    /// in `standard_parameters`' layout and `P_J` from `base_from_joints` on the
                    /// joints' parameters in `joint_parameters`' layout: for identified or
                    /// edited standard parameters. Constants, Khalil's grouping.
                    fn base_from_standard() -> base_link_map, nalgebra base_from_standard_na {
                        variant: BaseFromStandard,
                        equation: None,
                        prefix: "pbs",
                        summary: "The map P from the links' standard parameters π to π_B.",
                        element: "base parameter {k}: coefficient of pi{i}_{j}",
                    }
                    /// The map from the joints' parameters (`joint_parameters`' layout) to the
                    /// base parameters: `P_J` of `base_from_standard`.
                    fn base_from_joints() -> base_joint_map, nalgebra base_from_joints_na {
                        variant: BaseFromJoints,
                        equation: None,
                        prefix: "pbj",
                        summary: "The map P_J from the joints' parameters to π_B.",
                        element: "base parameter {k}: coefficient of joint {i} parameter {j}",
                    }
                }
            }
        }}
    };
}

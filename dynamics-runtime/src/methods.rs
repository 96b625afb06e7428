// The table of the generated methods: the one place that lists them, by trait and family.
//
// `for_each_method!(callback)` calls `callback! { rows }`. The runtime reads it to declare its
// traits (`dynamics.rs`), their nalgebra wrappers (`nalgebra.rs`) and their forms over many
// states (`batch/traits.rs`: a trait row's `batch` trait, a method row's `_batch` method, for the
// methods with joint inputs); `dynamics-codegen` reads
// the same file (a symlink, `include!`d, hence no inner doc comment here) to build its
// `enum Family` and `enum Method`. The rows nest:
//
//     /// Rustdoc of the trait.
//     trait DynamicsDerivatives<N>: Dynamics<N>, nalgebra DynamicsDerivativesNalgebra,
//             batch DynamicsDerivativesBatch {
//         items {}                         // the trait's other items (`const DOF`)
//         /// Doc of the family.
//         family Derivatives {             // the codegen enum's variant
//             name: derivatives,           // its name: `derivatives = true` in the attribute,
//                                          // `--with derivatives` on the command line
//             module: "__derivatives",     // the generated module holding its functions
//             opt_in: true,                // generated only for a robot that asks for it
//             adjective: "derivatives' ",  // `dynamics stats`: (derivatives' configuration)
//         }
//         methods {
//             /// Rustdoc of the trait method.
//             fn name(q, qd) -> vector, nalgebra name_na, batch name_batch {
//                 variant: Name,                 // the codegen enum's variant
//                 equation: Some("6.46"),        // the book's equation (Niku, ch. 6), if any
//                 prefix: "tau",                 // generated element names: tau3, m1_2, p
//                 summary: "…",                  // one-line doc of `dynamics emit`
//                 element: "T{i} ({equation})",  // doc of a generated element; {i}, {j} from
//                                                // 1, {x} the argument a derivative is taken by
//                 diagonal: "…",                 // optional: a matrix's diagonal, if different
//                 default: zeros,                // optional: the trait's body for robots whose
//                                                // description gives no such term (friction)
//                 compiled_apart: true,          // optional: compiled once, apart from its
//                                                // callers (below)
//                 into: name_into,               // optional: also a method writing the
//                                                // result into the caller's `&mut` (below)
//             }
//         }
//     }
//
// A trait's const parameters: first the configuration's length (`q: &[T; _]`), then, for a
// floating base only, `N`; then, after a `;`, counts of its own (`LINKS`, `TIPS`). `N` is always
// the velocity's length (of `qd`, `qdd`, `tau`, and the results' `N`): the joints of a fixed
// base, whose configuration is as long (`Dynamics<N>`), or `n + 6` on a floating base, whose
// configuration has `n + 7` (`FloatingDynamics<Q, N>`, in `floating_methods.rs`).
//
// A method's arguments are among `q`, `qd`, `qdd`, `wrench`, `tau` (and a floating base's `v`,
// `a`, the velocity's length as `qd`'s); its result is a keyword of
// the result table (`results.rs`). A family is emitted in a module of its own. `compiled_apart`
// (the forward dynamics' derivatives) and `into` (the regressors, whose hundreds of values
// outnumber the registers) are explained, with the checklists for adding a method and a
// family, in `docs/design/families.md`.

/// Calls `$callback!` with the rows of the method table (see the comment at the top of
/// `methods.rs`).
macro_rules! for_each_method {
    ($callback:ident) => {
        for_each_base_method! { $callback {
            /// Closed-form equations of motion of a serial robot with `N` joints,
            /// `tau = M(q) qdd + C(q, qd) qd + g(q)` (Niku eq. 6.46).
            ///
            /// Every method is straight-line code generated from the robot's D-H table: no
            /// loops, no heap. Each is generic over the scalar, so one robot evaluates in `f32`
            /// or `f64`; the robot's parameters (struct fields) are converted to that scalar on
            /// each call.
            trait Dynamics<N>, nalgebra DynamicsNalgebra, batch DynamicsBatch {
                items {
                    /// Number of joints.
                    const DOF: usize = N;
                }
                /// M, C, g, τ, friction, energies.
                family Dynamics {
                    name: dynamics,
                    module: "__dynamics",
                    opt_in: false,
                    adjective: "",
                }
                methods {
                    /// Mass matrix `M(q)`: the book's D_ij (eq. 6.43) plus actuator inertia
                    /// I_i(act) on the diagonal. Symmetric positive definite.
                    fn mass_matrix(q) -> matrix, nalgebra mass_matrix_na, batch mass_matrix_batch {
                        variant: MassMatrix,
                        equation: Some("6.43"),
                        prefix: "m",
                        summary: "M(q), with the actuator inertia on the diagonal.",
                        element: "D{i}{j} = D{j}{i} ({equation})",
                        diagonal: "D{i}{i} ({equation}) + actuator inertia",
                        into: mass_matrix_into,
                    }
                    /// Coriolis matrix `C(q, qd)` with `C_ij = Σ_k D_ijk qd_k`, where the book's
                    /// D_ijk (eq. 6.44) are the Christoffel symbols of `M`. `Ṁ − 2C` is
                    /// skew-symmetric.
                    fn coriolis_matrix(q, qd) -> matrix, nalgebra coriolis_matrix_na, batch coriolis_matrix_batch {
                        variant: CoriolisMatrix,
                        equation: Some("6.44"),
                        prefix: "cor",
                        summary: "C(q, q̇), with C_ij = Σ_k D_ijk q̇_k.",
                        element: "C{i}{j} = sum of D{i}{j}k qd_k ({equation})",
                    }
                    /// Coriolis and centripetal torques `C(q, qd) qd = Σ_j Σ_k D_ijk qd_j qd_k`.
                    fn coriolis_torques(q, qd) -> vector, nalgebra coriolis_torques_na, batch coriolis_torques_batch {
                        variant: CoriolisTorques,
                        equation: None,
                        prefix: "cqd",
                        summary: "C(q, q̇) q̇.",
                        element: "centripetal and Coriolis torque {i}",
                    }
                    /// Gravity torques `g(q)`: the book's D_i (eq. 6.45), plus joint spring torques
                    /// `k_i (q_i − q0_i)`.
                    fn gravity_torques(q) -> vector, nalgebra gravity_torques_na, batch gravity_torques_batch {
                        variant: GravityTorques,
                        equation: Some("6.45"),
                        prefix: "g",
                        summary: "g(q), with joint springs.",
                        element: "D{i} ({equation}), gravity and spring",
                    }
                    /// Bias torques `C(q, qd) qd + g(q)` (Pinocchio's "non-linear effects").
                    fn bias_torques(q, qd) -> vector, nalgebra bias_torques_na, batch bias_torques_batch {
                        variant: BiasTorques,
                        equation: None,
                        prefix: "h",
                        summary: "C(q, q̇) q̇ + g(q).",
                        element: "centripetal, Coriolis and gravity torque {i}",
                    }
                    /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (eq. 6.46), actuator
                    /// inertia and springs included, and joint friction where the robot declares
                    /// it.
                    fn inverse_dynamics(q, qd, qdd) -> vector, nalgebra inverse_dynamics_na, batch inverse_dynamics_batch {
                        variant: InverseDynamics,
                        equation: Some("6.46"),
                        prefix: "tau",
                        summary: "τ = M(q) q̈ + C(q, q̇) q̇ + g(q).",
                        element: "T{i} ({equation})",
                    }
                    /// Joint friction torques `f_v qd + f_c sign(qd) + f_0`, per joint, with
                    /// `sign(0) = 0` (`f_c tanh(qd / ε)` where a smoothing velocity ε is given).
                    /// Zero for a robot without friction; `inverse_dynamics` includes them.
                    fn friction_torques(qd) -> vector, nalgebra friction_torques_na, batch friction_torques_batch {
                        variant: FrictionTorques,
                        equation: None,
                        prefix: "f",
                        summary: "Joint friction: f_v q̇ + f_c sign(q̇) + f_0.",
                        element: "friction torque {i}",
                        default: zeros,
                    }
                    /// Kinetic energy `½ qdᵀ M(q) qd` (eq. 6.39), actuators included.
                    fn kinetic_energy(q, qd) -> scalar, nalgebra kinetic_energy_na, batch kinetic_energy_batch {
                        variant: KineticEnergy,
                        equation: Some("6.39"),
                        prefix: "k",
                        summary: "The kinetic energy.",
                        element: "kinetic energy",
                    }
                    /// Potential energy `−Σ m_i gᵀ p_i + Σ ½ k_i (q_i − q0_i)²`, zero with every
                    /// centre of mass at the base origin and every spring at rest.
                    fn potential_energy(q) -> scalar, nalgebra potential_energy_na, batch potential_energy_batch {
                        variant: PotentialEnergy,
                        equation: None,
                        prefix: "p",
                        summary: "The potential energy.",
                        element: "potential energy",
                    }
                }
                /// Poses, Jacobians, acceleration bias, statics.
                family Kinematics {
                    name: kinematics,
                    module: "__kinematics",
                    opt_in: false,
                    adjective: "kinematic ",
                }
                methods {
                    /// The hand frame in the base frame, the book's `A_1 ⋯ A_n` followed by the
                    /// tool transform if the robot declares one: rotation and position
                    /// (`Pose::homogeneous` gives the 4×4 form).
                    fn hand_pose(q) -> pose, nalgebra hand_pose_na, batch hand_pose_batch {
                        variant: HandPose,
                        equation: None,
                        prefix: "hand",
                        summary: "The hand frame's pose, A1 ⋯ An (and the tool).",
                        element: "hand pose [R | p], row {i} column {j}",
                    }
                    /// The pose of every link frame in the base frame: link i at `A_1 ⋯ A_i`.
                    fn link_poses(q) -> poses, nalgebra link_poses_na, batch link_poses_batch {
                        variant: LinkPoses,
                        equation: None,
                        prefix: "link",
                        summary: "The pose of every link frame, A1 ⋯ Ai.",
                        element: "link {k} pose [R | p], row {i} column {j}",
                    }
                    /// The hand's geometric Jacobian in the base frame: rows `[dx, dy, dz, δx, δy,
                    /// δz]`, the velocity of the hand's origin and the hand's angular velocity per
                    /// joint velocity, in base axes.
                    fn hand_jacobian_in_base(q) -> jacobian, nalgebra hand_jacobian_in_base_na, batch hand_jacobian_in_base_batch {
                        variant: HandJacobianInBase,
                        equation: None,
                        prefix: "jb",
                        summary: "The hand's Jacobian in the base frame.",
                        element: "J{i}{j}, base frame (rows dx dy dz rx ry rz)",
                    }
                    /// The hand's Jacobian in the hand frame, the book's ᴴJ: rows `[dx, dy, dz, δx,
                    /// δy, δz]` along and about the hand frame's axes.
                    fn hand_jacobian_in_hand(q) -> jacobian, nalgebra hand_jacobian_in_hand_na, batch hand_jacobian_in_hand_batch {
                        variant: HandJacobianInHand,
                        equation: None,
                        prefix: "jh",
                        summary: "The book's ᴴJ, the hand's Jacobian in the hand frame.",
                        element: "HJ{i}{j}, hand frame (rows dx dy dz rx ry rz)",
                    }
                    /// `J̇ q̇` of `hand_jacobian_in_base`: the hand's
                    /// linear and angular acceleration at `qdd = 0`, in base axes.
                    fn hand_acceleration_bias_in_base(q, qd) -> spatial, nalgebra hand_acceleration_bias_in_base_na, batch hand_acceleration_bias_in_base_batch {
                        variant: HandAccelerationBiasInBase,
                        equation: None,
                        prefix: "ab",
                        summary: "J̇ q̇ of the hand, in the base frame.",
                        element: "row {i} of J qd' in the base frame",
                    }
                    /// The same acceleration as `hand_acceleration_bias_in_base` in the hand's axes
                    /// (Pinocchio's classical acceleration in `LOCAL`; not `d(ᴴJ)/dt q̇`, which
                    /// also has the terms of the hand frame's own turning).
                    fn hand_acceleration_bias_in_hand(q, qd) -> spatial, nalgebra hand_acceleration_bias_in_hand_na, batch hand_acceleration_bias_in_hand_batch {
                        variant: HandAccelerationBiasInHand,
                        equation: None,
                        prefix: "ah",
                        summary: "J̇ q̇ of the hand, in the hand's axes.",
                        element: "row {i} of J qd' in the hand frame",
                    }
                    /// The joint torques and forces that hold a wrench `[fx, fy, fz, mx, my, mz]`
                    /// given in the hand frame, `T = ᴴJᵀ ᴴF` (eq. 6.64).
                    fn joint_torques_for_hand_wrench(q, wrench) -> vector, nalgebra joint_torques_for_hand_wrench_na, batch joint_torques_for_hand_wrench_batch {
                        variant: JointTorquesForHandWrench,
                        equation: Some("6.64"),
                        prefix: "tf",
                        summary: "T = ᴴJᵀ ᴴF for a wrench in the hand frame.",
                        element: "T{i} ({equation})",
                    }
                    /// The joint torques and forces that hold a wrench `[fx, fy, fz, mx, my, mz]`
                    /// given in base axes, its moment about the hand's origin: `T = Jᵀ F` with the
                    /// base-frame Jacobian.
                    fn joint_torques_for_base_wrench(q, wrench) -> vector, nalgebra joint_torques_for_base_wrench_na, batch joint_torques_for_base_wrench_batch {
                        variant: JointTorquesForBaseWrench,
                        equation: Some("6.64"),
                        prefix: "tb",
                        summary: "T = Jᵀ F for a wrench in base axes.",
                        element: "T{i} ({equation}), wrench in base axes",
                    }
                }
                /// What solves with M through its LDLᵀ: forward dynamics, `M⁻¹`.
                family Forward {
                    name: forward,
                    module: "__forward",
                    opt_in: false,
                    adjective: "forward ",
                }
                methods {
                    /// The inverse of the mass matrix, `M(q)⁻¹`, through the LDLᵀ factorization of
                    /// `M`; `Err(NotPositiveDefinite)` where a pivot of the factorization is not
                    /// positive (a robot whose parameters leave a joint without inertia); on lane
                    /// types, where at least one lane's is not.
                    fn mass_matrix_inverse(q) -> solved_matrix, nalgebra mass_matrix_inverse_na, batch mass_matrix_inverse_batch {
                        variant: MassMatrixInverse,
                        equation: None,
                        prefix: "mi",
                        summary: "M(q)⁻¹, through the LDLᵀ of M.",
                        element: "(M^-1){i}{j}",
                    }
                    /// Forward dynamics `qdd = M(q)⁻¹ (tau − C(q, qd) qd − g(q))`, minus joint
                    /// friction where the robot declares it, through the LDLᵀ factorization of `M`:
                    /// the inverse of `inverse_dynamics`. `Err(NotPositiveDefinite)` where a pivot
                    /// is not positive (on lane types, where at least one lane's is not).
                    fn forward_dynamics(q, qd, tau) -> solved_vector, nalgebra forward_dynamics_na, batch forward_dynamics_batch {
                        variant: ForwardDynamics,
                        equation: None,
                        prefix: "qdd",
                        summary: "q̈ = M(q)⁻¹ (τ − C(q, q̇) q̇ − g(q) − f(q̇)).",
                        element: "joint acceleration {i}",
                    }
                }
            }
            /// The derivatives of the equations of motion, for model-predictive and optimal
            /// control: implemented by `#[derive(Dynamics)]` for a robot that asks for them
            /// with `#[dynamics(..., derivatives = true)]`, since their code is several times
            /// the size of the rest, and a robot that does not call them should not compile
            /// them.
            ///
            /// Straight-line code from the same expression graph as [`Dynamics`]: the
            /// derivatives of its traced `τ` (forward differentiation at compile time, no finite
            /// differences, no automatic differentiation at run time), and `∂q̈/∂x = −M⁻¹ ∂τ/∂x`
            /// solved with the LDLᵀ of `M` (Carpentier and Mansard, RSS 2018).
            trait DynamicsDerivatives<N>: Dynamics<N>, nalgebra DynamicsDerivativesNalgebra, batch DynamicsDerivativesBatch {
                items {}
                /// The derivatives of inverse and forward dynamics.
                family Derivatives {
                    name: derivatives,
                    module: "__derivatives",
                    opt_in: true,
                    adjective: "derivatives' ",
                }
                methods {
                    /// The derivatives of inverse dynamics at `(q, qd, qdd)`: `∂τ/∂q` and `∂τ/∂q̇`,
                    /// each `[[T; N]; N]` with row i the derivatives of `τ_i` (`∂τ/∂q̈` is
                    /// `mass_matrix(q)`). Friction's Coulomb term is taken as flat (`∂ sign(q̇)/∂q̇
                    /// = 0`), its smooth form differentiated.
                    fn inverse_dynamics_derivatives(q, qd, qdd) -> inverse_derivatives, nalgebra inverse_dynamics_derivatives_na, batch inverse_dynamics_derivatives_batch {
                        variant: InverseDynamicsDerivatives,
                        equation: None,
                        prefix: "dtau",
                        summary: "∂τ/∂q and ∂τ/∂q̇ at (q, q̇, q̈).",
                        element: "d tau{i} / d {x}{j}",
                    }
                    /// Forward dynamics and its derivatives at `(q, qd, tau)`: `q̈`, `∂q̈/∂q`,
                    /// `∂q̈/∂q̇` and `∂q̈/∂τ = M⁻¹`, the first two as `−M⁻¹ ∂τ/∂x` at that `q̈`,
                    /// solved with the LDLᵀ of `M`. `Err(NotPositiveDefinite)` where a pivot is not
                    /// positive (on lane types, where at least one lane's is not).
                    fn forward_dynamics_derivatives(q, qd, tau) -> forward_derivatives, nalgebra forward_dynamics_derivatives_na, batch forward_dynamics_derivatives_batch {
                        variant: ForwardDynamicsDerivatives,
                        equation: None,
                        prefix: "dqdd",
                        summary: "q̈, ∂q̈/∂q, ∂q̈/∂q̇ and ∂q̈/∂τ = M⁻¹ at (q, q̇, τ).",
                        element: "d qdd{i} / d {x}{j}",
                        compiled_apart: true,
                    }
                }
            }
            /// The joint torque regressor, for identifying a robot's inertial parameters:
            /// implemented by `#[derive(Dynamics)]` for a robot that asks for it with
            /// `#[dynamics(..., regressor = true)]`.
            ///
            /// The rigid bodies' part of inverse dynamics is linear in each link's 10 standard
            /// parameters `π_j = [m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]` (Pinocchio's
            /// `Inertia::toDynamicParameters` order), the first moment and the inertia tensor
            /// (off-diagonal entries `−∫xy dm`) about the origin of link frame j (the D-H frame,
            /// or a URDF's link frame), in its axes:
            /// `τ = Σ_j Y_j(q, q̇, q̈) π_j`, plus the actuator inertia's and friction's terms, linear
            /// in their coefficients (`joint_regressor`, `joint_parameters`), and the springs.
            ///
            /// `LINKS` is the number of links, `N` by default: a robot with mimic joints (each
            /// following `q_m = k q_j + o`, not a coordinate) has a row per coordinate (`N`) and
            /// still a column block per link (`LINKS`, one per joint).
            trait DynamicsRegressor<N; LINKS = N>: Dynamics<N>, nalgebra DynamicsRegressorNalgebra, batch DynamicsRegressorBatch {
                items {
                    /// Number of links: of column blocks of `regressor`, of rows of
                    /// `joint_regressor`.
                    const LINK_COUNT: usize = LINKS;
                    /// Per joint, the row of τ (its coordinate) that its columns of
                    /// `joint_regressor` add to: joint i's own row i, but that a mimic joint's
                    /// add to the row of the joint it follows.
                    const JOINT_ROWS: [usize; LINKS] = crate::identity_rows::<LINKS>();
                }
                /// The joint torque regressor and the standard parameters.
                family Regressor {
                    name: regressor,
                    module: "__regressor",
                    opt_in: true,
                    adjective: "regressor's ",
                }
                methods {
                    /// The regressor `Y(q, q̇, q̈)`: element `[i][j][k]` is `∂τ_i/∂π_jk`, the
                    /// derivative of joint i's torque by parameter k of link j, so that
                    /// `Σ_j Σ_k Y[i][j][k] π_jk` is the rigid bodies' part of
                    /// `inverse_dynamics` (without actuator inertia, friction and springs).
                    fn regressor(q, qd, qdd) -> link_columns, nalgebra regressor_na, batch regressor_batch {
                        variant: Regressor,
                        equation: None,
                        prefix: "y",
                        summary: "Y(q, q̇, q̈), with τ = Y π for the rigid bodies.",
                        element: "d tau{k} / d pi{i}_{j}",
                        into: regressor_into,
                    }
                    /// The joints' columns: row i is `[q̈_i, q̇_i, sign(q̇_i), 1]` (`tanh(q̇_i / ε)`
                    /// in place of the sign where the robot smooths joint i's Coulomb friction),
                    /// the columns of joint i's actuator inertia, viscous, Coulomb and offset
                    /// friction (`joint_parameters`), which add to τ's row `JOINT_ROWS[i]`: with
                    /// `regressor`, `inverse_dynamics` minus the spring torques. A mimic joint's
                    /// row is that of `k q̇_j` (and `k q̈_j`), times k.
                    fn joint_regressor(qd, qdd) -> joint_columns, nalgebra joint_regressor_na, batch joint_regressor_batch {
                        variant: JointRegressor,
                        equation: None,
                        prefix: "yj",
                        summary: "The actuator inertia's and friction's columns, per joint.",
                        element: "joint {i}: column {j} of [qdd, qd, sign(qd), 1]",
                    }
                    /// Per joint, `[I_act, f_v, f_c, f_0]`: the actuator inertia and the
                    /// friction coefficients, as the description gives them (zeros where it gives
                    /// none).
                    fn joint_parameters() -> joint_columns, nalgebra joint_parameters_na {
                        variant: JointParameters,
                        equation: None,
                        prefix: "pj",
                        summary: "The actuator inertia and friction coefficients, per joint.",
                        element: "joint {i}: [I_act, f_v, f_c, f_0] {j}",
                    }
                    /// The robot's standard parameters `π_j` as its description gives them, per
                    /// link `[m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]` about the origin
                    /// of link frame j (the D-H frame of a D-H table; a URDF's link frame), in its
                    /// axes.
                    fn standard_parameters() -> link_parameters, nalgebra standard_parameters_na {
                        variant: StandardParameters,
                        equation: None,
                        prefix: "pi",
                        summary: "The standard parameters π of each link.",
                        element: "pi{i}_{j}",
                    }
                }
            }
            /// Pruned equations of motion with a proven error bound (opt-in, `simplify(...)`): the
            /// terms dropped whose summed interval bound over the envelope stays within the
            /// tolerance. Each method's rustdoc on the robot states its bounds and the envelope.
            trait DynamicsSimplified<N>: Dynamics<N>, nalgebra DynamicsSimplifiedNalgebra, batch DynamicsSimplifiedBatch {
                items {}
                /// The pruned τ, M, C q̇ and g; an output too large to prune is the exact one.
                family Simplified {
                    name: simplify,
                    module: "__simplified",
                    opt_in: true,
                    adjective: "simplified ",
                }
                methods {
                    /// The joint torques `τ` of `inverse_dynamics` with the terms dropped whose
                    /// summed bound over the envelope stays within each joint's tolerance:
                    /// `|τ_i − τ_i,simplified| ≤ b_i` for every state of the envelope.
                    fn inverse_dynamics_simplified(q, qd, qdd) -> vector, nalgebra inverse_dynamics_simplified_na, batch inverse_dynamics_simplified_batch {
                        variant: InverseDynamicsSimplified,
                        equation: Some("6.46"),
                        prefix: "tau",
                        summary: "τ pruned within the tolerance over the envelope.",
                        element: "T{i} pruned ({equation})",
                    }
                    /// The mass matrix `M(q)` pruned: element `[i][j]` within
                    /// `min(t_i, t_j) / Σ_k a_k`, `t` the joints' tolerances and `a` the envelope's
                    /// accelerations, so that `|((M − M_simplified) q̈)_i| ≤ t_i` over the envelope.
                    fn mass_matrix_simplified(q) -> matrix, nalgebra mass_matrix_simplified_na, batch mass_matrix_simplified_batch {
                        variant: MassMatrixSimplified,
                        equation: Some("6.43"),
                        prefix: "m",
                        summary: "M(q) pruned within the tolerance over the envelope.",
                        element: "D{i}{j} = D{j}{i} pruned ({equation})",
                        diagonal: "D{i}{i} pruned ({equation})",
                    }
                    /// The centripetal and Coriolis torques `C(q, q̇) q̇` pruned within each joint's tolerance.
                    fn coriolis_torques_simplified(q, qd) -> vector, nalgebra coriolis_torques_simplified_na, batch coriolis_torques_simplified_batch {
                        variant: CoriolisTorquesSimplified,
                        equation: None,
                        prefix: "cqd",
                        summary: "C(q, q̇) q̇ pruned within the tolerance over the envelope.",
                        element: "centripetal and Coriolis torque {i} pruned",
                    }
                    /// The gravity torques `g(q)` pruned within each joint's tolerance.
                    fn gravity_torques_simplified(q) -> vector, nalgebra gravity_torques_simplified_na, batch gravity_torques_simplified_batch {
                        variant: GravityTorquesSimplified,
                        equation: Some("6.45"),
                        prefix: "g",
                        summary: "g(q) pruned within the tolerance over the envelope.",
                        element: "D{i} pruned ({equation})",
                    }
                }
            }
        }}
    };
}

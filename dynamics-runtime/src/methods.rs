// The table of the generated methods: the one place that lists them.
//
// `for_each_method!(callback)` calls `callback! { rows }`, one row per method of the
// `Dynamics` trait, in the trait's order. The runtime reads it to declare the trait
// (`dynamics.rs`) and its nalgebra wrappers (`nalgebra.rs`); `dynamics-codegen` reads the same
// file (a symlink, `include!`d, hence no inner doc comment here) to build its `enum Method`.
//
// A row: the method's arguments (among `q`, `qd`, `qdd`), its result (`matrix`, `vector` or
// `scalar`) and the name of its nalgebra wrapper, then
//
//     /// Rustdoc of the trait method.
//     fn name(q, qd) -> vector, nalgebra name_na {
//         variant: Name,                 // the codegen enum's variant
//         equation: Some("6.46"),        // the book's equation (Niku, ch. 6), if it has one
//         prefix: "tau",                 // generated element names: tau3, m1_2, p
//         summary: "…",                  // one-line doc of `dynamics emit`
//         element: "T{i} ({equation})",  // doc of a generated element; {i}, {j} from 1
//         diagonal: "…",                 // optional: a matrix's diagonal elements, if different
//         default: zeros,                // optional: the trait's body for robots whose
//                                        // description gives no such term (friction)
//     }
//
// Adding a method: a row here, its `Equations` output in `dynamics-codegen/src/method.rs`,
// the algorithm, and their tests.

/// Calls `$callback!` with the rows of the method table (see the comment at the top of
/// `methods.rs`).
macro_rules! for_each_method {
    ($callback:ident) => {
        $callback! {
            /// Mass matrix `M(q)`: the book's D_ij (eq. 6.43) plus actuator inertia I_i(act) on the
            /// diagonal. Symmetric positive definite.
            fn mass_matrix(q) -> matrix, nalgebra mass_matrix_na {
                variant: MassMatrix,
                equation: Some("6.43"),
                prefix: "m",
                summary: "M(q), with the actuator inertia on the diagonal.",
                element: "D{i}{j} = D{j}{i} ({equation})",
                diagonal: "D{i}{i} ({equation}) + actuator inertia",
            }
            /// Coriolis matrix `C(q, qd)` with `C_ij = Σ_k D_ijk qd_k`, where the book's D_ijk (eq. 6.44)
            /// are the Christoffel symbols of `M`. `Ṁ − 2C` is skew-symmetric.
            fn coriolis_matrix(q, qd) -> matrix, nalgebra coriolis_matrix_na {
                variant: CoriolisMatrix,
                equation: Some("6.44"),
                prefix: "cor",
                summary: "C(q, q̇), with C_ij = Σ_k D_ijk q̇_k.",
                element: "C{i}{j} = sum of D{i}{j}k qd_k ({equation})",
            }
            /// Coriolis and centripetal torques `C(q, qd) qd = Σ_j Σ_k D_ijk qd_j qd_k`.
            fn coriolis_torques(q, qd) -> vector, nalgebra coriolis_torques_na {
                variant: CoriolisTorques,
                equation: None,
                prefix: "cqd",
                summary: "C(q, q̇) q̇.",
                element: "centripetal and Coriolis torque {i}",
            }
            /// Gravity torques `g(q)`: the book's D_i (eq. 6.45), plus joint spring torques
            /// `k_i (q_i − q0_i)`.
            fn gravity_torques(q) -> vector, nalgebra gravity_torques_na {
                variant: GravityTorques,
                equation: Some("6.45"),
                prefix: "g",
                summary: "g(q), with joint springs.",
                element: "D{i} ({equation}), gravity and spring",
            }
            /// Bias torques `C(q, qd) qd + g(q)` (Pinocchio's "non-linear effects").
            fn bias_torques(q, qd) -> vector, nalgebra bias_torques_na {
                variant: BiasTorques,
                equation: None,
                prefix: "h",
                summary: "C(q, q̇) q̇ + g(q).",
                element: "centripetal, Coriolis and gravity torque {i}",
            }
            /// Inverse dynamics `tau = M(q) qdd + C(q, qd) qd + g(q)` (eq. 6.46), actuator inertia and
            /// springs included, and joint friction where the robot declares it.
            fn inverse_dynamics(q, qd, qdd) -> vector, nalgebra inverse_dynamics_na {
                variant: InverseDynamics,
                equation: Some("6.46"),
                prefix: "tau",
                summary: "τ = M(q) q̈ + C(q, q̇) q̇ + g(q).",
                element: "T{i} ({equation})",
            }
            /// Joint friction torques `f_v qd + f_c sign(qd) + f_0`, per joint, with `sign(0) = 0`
            /// (`f_c tanh(qd / ε)` where a smoothing velocity ε is given). Zero for a robot
            /// without friction; `inverse_dynamics` includes them.
            fn friction_torques(qd) -> vector, nalgebra friction_torques_na {
                variant: FrictionTorques,
                equation: None,
                prefix: "f",
                summary: "Joint friction: f_v q̇ + f_c sign(q̇) + f_0.",
                element: "friction torque {i}",
                default: zeros,
            }
            /// Kinetic energy `½ qdᵀ M(q) qd` (eq. 6.39), actuators included.
            fn kinetic_energy(q, qd) -> scalar, nalgebra kinetic_energy_na {
                variant: KineticEnergy,
                equation: Some("6.39"),
                prefix: "k",
                summary: "The kinetic energy.",
                element: "kinetic energy",
            }
            /// Potential energy `−Σ m_i gᵀ p_i + Σ ½ k_i (q_i − q0_i)²`, zero with every centre of mass
            /// at the base origin and every spring at rest.
            fn potential_energy(q) -> scalar, nalgebra potential_energy_na {
                variant: PotentialEnergy,
                equation: None,
                prefix: "p",
                summary: "The potential energy.",
                element: "potential energy",
            }
        }
    };
}

// The method table's rows of the tips' kinematics, apart from `methods.rs` for its length:
// `for_each_method!` hands its rows to `for_each_tip_method!`, which adds these and hands all to
// `for_each_floating_method!` (the same `include!`d symlink in `dynamics-codegen`).

/// Calls `for_each_floating_method!` with the rows given and the tips' trait row after them.
macro_rules! for_each_tip_method {
    ($callback:ident { $($rows:tt)* }) => {
        for_each_floating_method! { $callback {
            $($rows)*
            /// The kinematics of every tip of a robot that branches, all at once: `TIPS` tips,
            /// the leaves of its tree in joint order (a URDF's `tips = [..]` in their order),
            /// each tip's frame its link frame (a URDF tip link's own frame, fixed to the link
            /// it is part of). Implemented by `#[derive(Dynamics)]` for every tree, and for a
            /// serial robot that asks with `tip_kinematics = true` (one tip, its last link).
            /// The derive names the tips: `Robot::TIP_NAMES` and an index per tip
            /// (`Robot::TIP_LEFT_HAND`).
            ///
            /// One straight-line function computes every tip, so the links they share are
            /// computed once: a dual arm's or a hand's controller wants them all. The serial
            /// robots' `hand_*` methods stay those of the last joint's link.
            trait TipKinematics<N; TIPS>: Dynamics<N>, nalgebra TipKinematicsNalgebra, batch TipKinematicsBatch {
                items {
                    /// Number of tips.
                    const TIP_COUNT: usize = TIPS;
                }
                /// Every tip's pose, Jacobians, acceleration bias and statics.
                family Tips {
                    name: tip_kinematics,
                    module: "__tips",
                    opt_in: true,
                    adjective: "tips' ",
                }
                methods {
                    /// Each tip's frame in the base frame: rotation and position.
                    fn tip_poses(q) -> tip_poses, nalgebra tip_poses_na, batch tip_poses_batch {
                        variant: TipPoses,
                        equation: None,
                        prefix: "tip",
                        summary: "The pose of every tip frame.",
                        element: "tip {k} pose [R | p], row {i} column {j}",
                    }
                    /// Each tip's geometric Jacobian in the base frame (Pinocchio's
                    /// `LOCAL_WORLD_ALIGNED`): rows `[dx, dy, dz, δx, δy, δz]`, the velocity of
                    /// the tip's origin and its angular velocity, in base axes; zero in the
                    /// columns of the joints that do not carry it.
                    fn tip_jacobians_in_base(q) -> tip_jacobians, nalgebra tip_jacobians_in_base_na, batch tip_jacobians_in_base_batch {
                        variant: TipJacobiansInBase,
                        equation: None,
                        prefix: "tjb",
                        summary: "Every tip's Jacobian in the base frame.",
                        element: "tip {k}: J{i}{j}, base frame (rows dx dy dz rx ry rz)",
                    }
                    /// Each tip's Jacobian in its own frame (Pinocchio's `LOCAL`; the book's ᴴJ
                    /// with the tip for the hand).
                    fn tip_jacobians_in_tip(q) -> tip_jacobians, nalgebra tip_jacobians_in_tip_na, batch tip_jacobians_in_tip_batch {
                        variant: TipJacobiansInTip,
                        equation: None,
                        prefix: "tjt",
                        summary: "Every tip's Jacobian in its own frame.",
                        element: "tip {k}: J{i}{j}, tip frame (rows dx dy dz rx ry rz)",
                    }
                    /// `J̇ q̇` of each tip's `tip_jacobians_in_base`: its linear and angular
                    /// acceleration at `qdd = 0`, in base axes.
                    fn tip_acceleration_biases_in_base(q, qd) -> tip_spatials, nalgebra tip_acceleration_biases_in_base_na, batch tip_acceleration_biases_in_base_batch {
                        variant: TipAccelerationBiasesInBase,
                        equation: None,
                        prefix: "tab",
                        summary: "J̇ q̇ of every tip, in the base frame.",
                        element: "tip {i}: row {j} of J qd' in the base frame",
                    }
                    /// The same accelerations in each tip's axes (Pinocchio's classical
                    /// acceleration in `LOCAL`).
                    fn tip_acceleration_biases_in_tip(q, qd) -> tip_spatials, nalgebra tip_acceleration_biases_in_tip_na, batch tip_acceleration_biases_in_tip_batch {
                        variant: TipAccelerationBiasesInTip,
                        equation: None,
                        prefix: "tat",
                        summary: "J̇ q̇ of every tip, in its own axes.",
                        element: "tip {i}: row {j} of J qd' in the tip frame",
                    }
                    /// The joint torques and forces that hold a wrench `[fx, fy, fz, mx, my, mz]`
                    /// at each tip, each given in its tip's frame: `T = Σ_t J_tᵀ F_t` with the
                    /// tips' Jacobians in their own frames (eq. 6.64).
                    fn joint_torques_for_tip_wrenches(q, wrenches) -> vector, nalgebra joint_torques_for_tip_wrenches_na {
                        variant: JointTorquesForTipWrenches,
                        equation: Some("6.64"),
                        prefix: "ttf",
                        summary: "T = Σ J_tᵀ F_t for a wrench at each tip, in its frame.",
                        element: "T{i} ({equation}), a wrench at each tip",
                    }
                    /// The same with each wrench in base axes, its moment about its tip's
                    /// origin: `T = Σ_t J_tᵀ F_t` with the base-frame Jacobians.
                    fn joint_torques_for_tip_wrenches_in_base(q, wrenches) -> vector, nalgebra joint_torques_for_tip_wrenches_in_base_na {
                        variant: JointTorquesForTipWrenchesInBase,
                        equation: Some("6.64"),
                        prefix: "ttb",
                        summary: "T = Σ J_tᵀ F_t for a wrench at each tip, in base axes.",
                        element: "T{i} ({equation}), a wrench at each tip in base axes",
                    }
                }
            }
        }}
    };
}

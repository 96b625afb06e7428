//! The robots of the reference data (`data/reference/`, `data/panda/`, `data/frames/`), the
//! D-H twins of two URDF robots (`robots/*_urdf_dh.toml`, made by `data/urdf/twins.py`) and a
//! two-link arm with friction, derived once for the tests that use them; those with derivatives'
//! reference data (`data/derivatives/`) and the friction arm implement `DynamicsDerivatives`.
//! The reference robots carry every family a test file asks of them (the regressor everywhere,
//! the base parameters of the PUMA 560 and the Panda) rather than each file deriving its own copy:
//! a derive's code is compiled once per copy, the test binaries' largest compile cost.
//! The URDF chains of `robots/urdf/` are in [`urdf`]. Paths are relative to this crate's
//! `Cargo.toml`.

use dynamics_runtime::Dynamics;

/// A unit struct deriving the robot of a description file.
macro_rules! robot {
    ($(#[doc = $doc:literal])* $name:ident, $file:literal $(, $key:ident = $value:tt)*) => {
        $(#[doc = $doc])*
        #[derive(Dynamics)]
        #[dynamics(file = $file $(, $key = $value)*)]
        pub struct $name;
    };
}

// PUMA 560 links 1 and 3 and Stanford link 5, as published, break the triangle inequality of
// principal moments of inertia; the reference data keep them.
robot!(
    /// PUMA 560 (6 joints).
    Puma560,
    "data/reference/robots/puma560.json",
    check_inertia = false,
    derivatives = true,
    regressor = true,
    base_parameters = true
);
robot!(
    /// The Stanford arm (6 joints, one prismatic).
    Stanford,
    "data/reference/robots/stanford.json",
    check_inertia = false,
    derivatives = true,
    regressor = true
);
robot!(
    /// The Robotics Toolbox's UR5 (point masses).
    Ur5,
    "data/reference/robots/ur5.json",
    regressor = true
);
robot!(
    /// The book's two-link arm.
    NikuTwoLink,
    "data/reference/robots/niku_2link.json",
    derivatives = true,
    regressor = true
);
robot!(
    /// The book's polar arm (revolute, prismatic).
    NikuPolar,
    "data/reference/robots/niku_polar.json",
    derivatives = true,
    regressor = true
);
robot!(
    /// A random 2-joint robot.
    Random1,
    "data/reference/robots/random1.json",
    derivatives = true,
    regressor = true
);
robot!(
    /// A random 3-joint robot.
    Random2,
    "data/reference/robots/random2.json",
    derivatives = true,
    regressor = true
);
robot!(
    /// A random 6-joint robot.
    Random5,
    "data/reference/robots/random5.json",
    derivatives = true,
    regressor = true
);
robot!(
    /// The Franka Emika Panda (7 joints).
    Panda,
    "data/panda/robot.json",
    derivatives = true,
    regressor = true,
    base_parameters = true
);
robot!(
    /// A UR5 transcribed from its URDF as placements and axes.
    Ur5Urdf,
    "data/frames/ur5_urdf.toml"
);
robot!(
    /// Three joints with tilted axes.
    Tilted,
    "data/frames/tilted.toml"
);
robot!(
    /// Six joints with generic placements and axes.
    General,
    "data/frames/general.toml"
);
robot!(
    /// The UR5 of `robots/urdf/ur5.urdf` as a modified D-H table.
    Ur5Twin,
    "../robots/ur5_urdf_dh.toml"
);
robot!(
    /// The Panda of `robots/urdf/panda.urdf` (to panda_link8, the hand fixed to it) as Franka's
    /// modified D-H table.
    PandaTwin,
    "../robots/panda_urdf_dh.toml"
);

/// A planar two-link arm (Niku Example 6.4's shape) with friction on both joints; joint 2's
/// Coulomb term smoothed with a run-time ε.
#[derive(Dynamics)]
#[dynamics(
    derivatives = true,
    gravity = [0, -9.81, 0],
    dh = [[q, 0, 0.7, 0], [q, 0, 0.5, 0]],
    link(mass = 2, com = [-0.35, 0, 0], inertia = [0, 0.08, 0.08, 0, 0, 0],
         friction = (viscous = 0.3, coulomb = 1.5, offset = -0.2)),
    link(mass = 1, com = [-0.25, 0, 0], inertia = [0, 0.02, 0.02, 0, 0, 0],
         friction = (viscous = fv2, coulomb = 0.8, smoothing = eps)),
)]
pub struct Rubbing {
    /// Joint 2's viscous coefficient.
    pub fv2: f64,
    /// Joint 2's smoothing velocity.
    pub eps: f64,
}

/// Calls `$check(&robot, "name")` for each robot with forward-dynamics and derivatives'
/// reference data (`data/forward/<name>.json`, `data/derivatives/<name>.json`): the reference
/// robots whose M is positive definite, and the Panda.
#[macro_export]
macro_rules! for_each_robot_with_forward_data {
    ($check:expr) => {{
        use $crate::robots::{
            NikuPolar, NikuTwoLink, Panda, Puma560, Random1, Random2, Random5, Stanford,
        };
        $check(&Puma560, "puma560");
        $check(&Stanford, "stanford");
        $check(&NikuTwoLink, "niku_2link");
        $check(&NikuPolar, "niku_polar");
        $check(&Random1, "random1");
        $check(&Random2, "random2");
        $check(&Random5, "random5");
        $check(&Panda, "panda");
    }};
}

/// The serial chains of `robots/urdf/` (example-robot-data 6.0.0), base to tip, each derived once
/// with its regressor: `urdf_robots.rs` checks them against Pinocchio, `regressor.rs` their
/// regressors, `lanes.rs` the Panda's methods in lanes.
pub mod urdf {
    use dynamics_runtime::Dynamics;

    /// A unit struct deriving a URDF robot's chain, with its regressor.
    macro_rules! urdf_robot {
        ($(#[doc = $doc:literal])* $name:ident, $file:literal, $base:literal, $tip:literal) => {
            $(#[doc = $doc])*
            #[derive(Dynamics)]
            #[dynamics(urdf = $file, base = $base, tip = $tip, regressor = true)]
            pub struct $name;
        };
    }

    urdf_robot!(
        /// Universal Robots' UR5.
        Ur5,
        "../robots/urdf/ur5.urdf",
        "base_link",
        "tool0"
    );
    urdf_robot!(
        /// Universal Robots' UR10.
        Ur10,
        "../robots/urdf/ur10.urdf",
        "base_link",
        "tool0"
    );
    urdf_robot!(
        /// The Franka Emika Panda to its flange, with its joints' friction.
        Panda,
        "../robots/urdf/panda.urdf",
        "panda_link0",
        "panda_link8"
    );
    urdf_robot!(
        /// Unitree's Z1.
        Z1,
        "../robots/urdf/z1.urdf",
        "link00",
        "link06"
    );
    urdf_robot!(
        /// The SO-101 arm to its gripper.
        So101,
        "../robots/urdf/so101.urdf",
        "base_link",
        "gripper_link"
    );
}

//! The options of `excite`.

use super::trajectory::Limits;
use super::values::{file, positive, whole, Numbers, Setting};
use super::{JointTerms, RobotFile};
use clap::Args;

#[derive(Args, Debug)]
pub struct Excite {
    #[command(flatten)]
    pub robot: RobotFile,
    /// The joint terms whose base parameters the motion is to excite, as `identify` takes them
    #[command(flatten)]
    pub joint_terms: JointTerms,
    /// The period T of the motion, s (its base frequency is 1/T)
    #[arg(long, value_name = "SECONDS", default_value = "10", value_parser = positive, allow_hyphen_values = true)]
    pub period: f64,
    /// The harmonics L of each joint's Fourier series (at least 2: the motion starts at rest)
    #[arg(long, value_name = "L", default_value = "5", value_parser = whole::<2, 50>, allow_hyphen_values = true)]
    pub harmonics: u64,
    /// The periods written
    #[arg(long, value_name = "N", default_value = "1", value_parser = whole::<1, { u64::MAX }>, allow_hyphen_values = true)]
    pub periods: u64,
    /// Samples per second written, rounded to a whole number of samples per period
    #[arg(long, value_name = "HZ", default_value = "100", value_parser = positive, allow_hyphen_values = true)]
    pub rate: f64,
    /// The joints' lower limits (rad or m): one for every joint, or one per joint [default:
    /// a URDF's <limit lower>, else -π/2 rad or -0.1 m]
    #[arg(long, value_name = "Q1,Q2,..", allow_hyphen_values = true)]
    pub q_min: Option<Numbers>,
    /// The joints' upper limits [default: a URDF's <limit upper>, else π/2 rad or 0.1 m]
    #[arg(long, value_name = "Q1,Q2,..", allow_hyphen_values = true)]
    pub q_max: Option<Numbers>,
    /// The joints' speed limits (rad/s or m/s) [default: a URDF's <limit velocity>, else 1
    /// rad/s or 0.2 m/s]
    #[arg(long, value_name = "V1,V2,..", allow_hyphen_values = true)]
    pub qd_max: Option<Numbers>,
    /// The joints' acceleration limits (rad/s² or m/s²) [default: 5 rad/s² or 1 m/s²]
    #[arg(long, value_name = "A1,A2,..", allow_hyphen_values = true)]
    pub qdd_max: Option<Numbers>,
    /// The seed of the search's random restarts: the same seed, the same trajectory
    #[arg(long, default_value = "1", value_parser = whole::<0, { u64::MAX }>, allow_hyphen_values = true)]
    pub seed: u64,
    /// The condition numbers the search evaluates: a quarter on random restarts, the rest on
    /// a compass search from the best
    #[arg(long, value_name = "N", default_value = "3000", value_parser = whole::<1, { u64::MAX }>, allow_hyphen_values = true)]
    pub evaluations: u64,
    /// The value of a parameter of the robot (a struct field of the description); once for
    /// each of them
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<Setting>,
    /// Write the trajectory (t,q..,qd..,qdd..) to FILE and print the report [default: the
    /// trajectory on stdout, the report on stderr]
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub csv: Option<String>,
    /// The report as JSON
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub limits: Limits,
}

//! The options of `inspect`, with those of `--simplified`.

use super::{JointTerms, Numbers, RobotFile};
use clap::Args;

#[derive(Args, Debug)]
pub struct Inspect {
    #[command(flatten)]
    pub robot: RobotFile,
    /// LaTeX instead of plain text
    #[arg(long)]
    pub latex: bool,
    /// The hand pose [n o a p] and the hand's Jacobians instead of the equations of motion
    #[arg(long, conflicts_with_all = ["base_parameters", "simplified"])]
    pub kinematics: bool,
    /// The base parameters instead of the equations of motion: the combinations of the
    /// standard parameters that the joint torques determine
    #[arg(long, conflicts_with = "simplified")]
    pub base_parameters: bool,
    /// The robot on a free-flying base (the derive's `base = floating`): M, h, g and τ in
    /// Pinocchio's coordinates (base position, quaternion, base twist, joints). A URDF's root
    /// link (or --base) flies, a description file's `[floating]` table is the body
    #[arg(long, conflicts_with_all = ["kinematics", "base_parameters", "simplified", "tip", "tips", "tool"])]
    pub floating: bool,
    #[command(flatten)]
    pub joint_terms: JointTerms,
    #[command(flatten)]
    pub simplified: Simplified,
}

/// `inspect --simplified` and `stats --simplified`: the equations pruned within a proven bound
/// over an envelope.
#[derive(Args, Debug)]
pub struct Simplified {
    /// The equations with their smallest terms dropped, within --tolerance over the envelope
    /// (--q-min, --q-max, --qd-max, --qdd-max): `inspect` prints the joint torques and what was
    /// dropped, `stats` the operations of the generated `*_simplified` methods and their bounds.
    /// The description file's `[simplify]` gives what these options do not (the options win,
    /// --tolerance over `rated` and `tolerance_percent` too; `stats` reads the table without
    /// --simplified, as the derive does); a URDF's <limit>s give the default range, speed and
    /// `rated` (efforts)
    #[arg(long)]
    pub simplified: bool,
    /// The largest error allowed in each joint torque, N·m or N: one for every joint, or one
    /// per joint
    #[arg(
        long,
        value_name = "T1,T2,..",
        requires = "simplified",
        allow_hyphen_values = true
    )]
    pub tolerance: Option<Numbers>,
    /// The tolerance as this percentage of each joint's rated torque, in place of --tolerance
    #[arg(
        long,
        value_name = "P",
        requires = "simplified",
        conflicts_with = "tolerance",
        allow_hyphen_values = true
    )]
    pub tolerance_percent: Option<Numbers>,
    /// The joints' rated torques (N·m or N) for --tolerance-percent [default: the file's
    /// `rated`, else a URDF's efforts]
    #[arg(
        long,
        value_name = "R1,R2,..",
        requires = "simplified",
        allow_hyphen_values = true
    )]
    pub rated: Option<Numbers>,
    /// The joints' lower limits (rad or m): one for every joint, or one per joint [default:
    /// the file's, else -π rad or -1 m]
    #[arg(
        long,
        value_name = "Q1,Q2,..",
        allow_hyphen_values = true,
        requires = "simplified"
    )]
    pub q_min: Option<Numbers>,
    /// The joints' upper limits [default: the file's, else π rad or 1 m]
    #[arg(
        long,
        value_name = "Q1,Q2,..",
        allow_hyphen_values = true,
        requires = "simplified"
    )]
    pub q_max: Option<Numbers>,
    /// The joints' speed limits (rad/s or m/s) [default: the file's, else 2]
    #[arg(
        long,
        value_name = "V1,V2,..",
        requires = "simplified",
        allow_hyphen_values = true
    )]
    pub qd_max: Option<Numbers>,
    /// The joints' acceleration limits (rad/s² or m/s²) [default: the file's, else 5]
    #[arg(
        long,
        value_name = "A1,A2,..",
        requires = "simplified",
        allow_hyphen_values = true
    )]
    pub qdd_max: Option<Numbers>,
}

//! The command line, declared for clap: every subcommand, option and help text.

use clap::{Args, Parser, Subcommand};
use dynamics_codegen::model::Robot;
use dynamics_codegen::{asked_by_name, Family, FamilySet, JointColumns};
use std::str::FromStr;

mod emit;
mod excite;
mod inspect;
mod trajectory;
mod values;
pub use emit::{Emit, Lang};
pub use excite::Excite;
pub use inspect::{Inspect, Simplified};
pub use trajectory::{Simulate, Size};
use values::{file, fraction, path, positive, whole};
pub use values::{Numbers, Setting};

/// The closed-form equations of motion of a robot arm, hand or other tree of joints, from its
/// description file.
#[derive(Parser, Debug)]
#[command(
    name = "dynamics",
    version,
    subcommand_required = true,
    arg_required_else_help = true
)]
#[command(after_help = "ROBOT is a description file (.json or .toml), as \
                        `#[dynamics(file = \"...\")]` reads it, or a URDF file (.urdf), as \
                        `#[dynamics(urdf = \"...\")]` reads it, with --base and --tip.")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Print the equations of motion in the book's notation (Niku, chapter 6)
    Inspect(Inspect),
    /// Print a standalone Rust module with the code `#[derive(Dynamics)]` generates
    Emit(Emit),
    /// Print expansion time, operation counts, depth and code size per method
    Stats(Stats),
    /// Print τ, M, C and g at one state
    Eval(Eval),
    /// Size the actuators along a trajectory: peak and RMS torque, peak power, and the terms of
    /// the torque at its peak, per joint
    Size(Size),
    /// Integrate the forward dynamics (RK4) from an initial state, under constant torques
    Simulate(Simulate),
    /// Estimate the robot's inertial (and joint) parameters from measured motions and torques,
    /// by weighted least squares, with their standard deviations
    Identify(Identify),
    /// Write a periodic exciting trajectory (a Fourier series per joint, within the joints'
    /// limits) that keeps the condition number of the base parameters' regressor low
    Excite(Excite),
}

#[derive(Args, Debug)]
pub struct RobotFile {
    /// The robot's description file (.json, .toml or .urdf)
    #[arg(value_name = "ROBOT", value_parser = path)]
    pub path: String,
    /// URDF only: the link the chain starts at, fixed to the ground [default: the root link]
    #[arg(long, value_name = "LINK", allow_hyphen_values = true)]
    pub base: Option<String>,
    /// URDF only: the link the serial chain ends at (what branches off the path is refused)
    /// [default: every moving joint below the base, a tree if they branch]
    #[arg(
        long,
        value_name = "LINK",
        allow_hyphen_values = true,
        conflicts_with = "tips"
    )]
    pub tip: Option<String>,
    /// URDF only: the links the branches kept lead to, comma-separated (what moves off them
    /// is cut off) [default: every branch]
    #[arg(
        long,
        value_name = "LINK,..",
        value_delimiter = ',',
        allow_hyphen_values = true
    )]
    pub tips: Vec<String>,
    /// A tool frame on the hand, as a description file's `tool` (m, rad): the kinematic
    /// methods then give the tool's pose, Jacobians and statics
    #[arg(long, value_name = "X,Y,Z,ROLL,PITCH,YAW", allow_hyphen_values = true)]
    pub tool: Option<Tool>,
    /// Keep every link's inertia as given, unchecked (the derive's `check_inertia = false`):
    /// for published data whose principal moments break the triangle inequality
    #[arg(long)]
    pub no_check_inertia: bool,
}

/// `--tool x,y,z,roll,pitch,yaw`: six finite numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Tool(pub [f64; 6]);

impl FromStr for Tool {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let Numbers(values) = text.parse()?;
        let count = values.len();
        values.try_into().map(Tool).map_err(|_| {
            format!("a tool takes 6 numbers, x,y,z,roll,pitch,yaw; `{text}` has {count}")
        })
    }
}

/// The opt-in families of methods a command generates, as the attribute asks for them.
#[derive(Args, Debug)]
pub struct Families {
    #[arg(long = "with", value_name = "FAMILY", value_delimiter = ',', value_parser = opt_in_family, help = with_help(), allow_hyphen_values = true)]
    pub with: Vec<Family>,
    /// The same as `--with derivatives`
    #[arg(long)]
    pub derivatives: bool,
}

impl Families {
    /// The families asked for, and every family that is not opt-in.
    pub fn set(&self) -> FamilySet {
        let with = self.with.iter().copied();
        let shorthand = self.derivatives.then_some(Family::Derivatives);
        with.chain(shorthand)
            .fold(FamilySet::default(), FamilySet::with)
    }
}

/// The help of `--with`, naming the opt-in families of the method table.
fn with_help() -> String {
    let names = asked_by_name().join(", ");
    format!(
        "Also these opt-in families of methods, as `#[dynamics(..., FAMILY = true)]` asks for them (comma-separated or repeated): {names}"
    )
}

/// An opt-in family's name, as the front door reads it; the simplified models' with where
/// this command line takes their envelope and tolerances.
fn opt_in_family(name: &str) -> Result<Family, String> {
    dynamics_codegen::pipeline::opt_in_family(name).map_err(|d| match Family::from_name(name) {
        Some(Family::Simplified) => format!(
            "{}: `[simplify]` in the description file (emit, stats), `--simplified \
             --tolerance T` (stats, inspect), `simplify(...)`",
            d.message
        ),
        _ => match d.help {
            Some(help) => format!("{}; {help}", d.message),
            None => d.message,
        },
    })
}

#[derive(Args, Debug)]
pub struct Stats {
    #[command(flatten)]
    pub robot: RobotFile,
    #[command(flatten)]
    pub families: Families,
    #[command(flatten)]
    pub simplified: Simplified,
    /// Times the whole derive this many times and prints the fastest run, the one least slowed
    /// by the machine's other work
    #[arg(long, value_name = "N", default_value = "5", value_parser = whole::<1, 1000>, allow_hyphen_values = true)]
    pub runs: u64,
    /// The robot on a free-flying base (the derive's `base = floating`): a URDF's root link
    /// (or `--base`) flies, a description file's `[floating]` table is the body
    #[arg(long, conflicts_with_all = ["tip", "tips", "tool", "simplified"])]
    pub floating: bool,
}

/// Which of the joints' own parameters take part in the base parameters, beside the links'.
#[derive(Args, Debug)]
pub struct JointTerms {
    /// Every joint's actuator (rotor) inertia [default: the joints whose description gives one]
    #[arg(long)]
    pub rotors: bool,
    /// These friction coefficients of every joint: viscous, coulomb, offset (comma-separated)
    /// [default: those of the joints whose description has friction]
    #[arg(long, value_name = "TERM", value_delimiter = ',', value_parser = ["viscous", "coulomb", "offset"], allow_hyphen_values = true)]
    pub friction: Vec<String>,
}

impl JointTerms {
    /// Per joint, its description's parameters and those asked for.
    pub fn columns(&self, robot: &Robot) -> Vec<JointColumns> {
        let asked = |name: &str| self.friction.iter().any(|f| f == name);
        robot
            .joints
            .iter()
            .map(|joint| {
                let described = JointColumns::described(joint);
                JointColumns {
                    actuator_inertia: described.actuator_inertia || self.rotors,
                    viscous: described.viscous || asked("viscous"),
                    coulomb: described.coulomb || asked("coulomb"),
                    offset: described.offset || asked("offset"),
                }
            })
            .collect()
    }
}

#[derive(Args, Debug)]
pub struct Eval {
    #[command(flatten)]
    pub robot: RobotFile,
    /// Joint positions, one per joint (rad or m)
    // Hyphen values: `--q -0.5,1` is a list, not a flag.
    #[arg(long, value_name = "Q1,Q2,..", allow_hyphen_values = true)]
    pub q: Numbers,
    /// Joint velocities, one per joint [default: 0]
    #[arg(long, value_name = "QD1,QD2,..", allow_hyphen_values = true)]
    pub qd: Option<Numbers>,
    /// Joint accelerations, one per joint [default: 0]
    #[arg(long, value_name = "QDD1,QDD2,..", allow_hyphen_values = true)]
    pub qdd: Option<Numbers>,
    /// The value of a parameter of the robot; once for each of them
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<Setting>,
    /// Print JSON: {"tau": [..], "M": [[..]..], "C": [[..]..], "g": [..]}
    #[arg(long)]
    pub json: bool,
}

#[derive(Args, Debug)]
pub struct Identify {
    #[command(flatten)]
    pub robot: RobotFile,
    /// The measurements: a header `t,q1,..,qn` (then optionally `qd1,..,qdn`, then optionally
    /// `qdd1,..,qddn`), then `tau1,..,taun`; then one sample per line, t strictly increasing
    /// (s; rad or m; N m or N). Missing q̇ and q̈ come from central differences
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub csv: String,
    /// The robot on a free-flying base (the derive's `base = floating`, Pinocchio's free
    /// flyer): q1..q{n+7} (x, y, z, qx, qy, qz, qw, then the joints), optionally v1..v{n+6} and
    /// a1..a{n+6} (the base's twist in its frame, then the joint rates), then tau1..tau{n+6}
    /// (the wrench on the base in its frame, then the joint torques), every row fitted
    #[arg(long)]
    pub floating: bool,
    /// With --floating: fit the joints' rows of τ alone (no wrench on the base measured); the
    /// file's torques tau7..tau{n+6}, or all n + 6 (the base's six then not read)
    #[arg(long, requires = "floating")]
    pub joint_rows: bool,
    #[command(flatten)]
    pub joint_terms: JointTerms,
    /// Low-pass q at this frequency before q̇ and q̈ are taken (a 4th-order Butterworth filter
    /// run forward and backward: zero phase), then τ and the regressor's columns alike, keeping
    /// one sample in ⌊0.4 f_s / HZ⌋. Samples must be evenly spaced
    #[arg(long, value_name = "HZ", value_parser = positive, allow_hyphen_values = true)]
    pub cutoff: Option<f64>,
    /// A parameter whose column of the regressor is, to this fraction of its norm, a
    /// combination of the columns before it is named as not identifiable and not estimated
    /// (estimated, noise in its estimate would be amplified about 1/FRACTION times)
    #[arg(long, value_name = "FRACTION", default_value = "1e-4", value_parser = fraction, allow_hyphen_values = true)]
    pub tolerance: f64,
    /// The value of a parameter of the robot (a struct field of the description); once for
    /// each of them
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<Setting>,
    /// Write a plot of the measured and the predicted torque per joint, as SVG
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub plot: Option<String>,
    /// Other measurements, as --csv, not used in the fit: their torques are predicted by the
    /// estimate, and the error's RMS per joint printed (a validation)
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub validate: Option<String>,
    /// Write a plot of the measured and the predicted torque of the --validate file, as SVG
    #[arg(long, value_name = "FILE", value_parser = file, requires = "validate", allow_hyphen_values = true)]
    pub validate_plot: Option<String>,
    /// Re-estimate each joint's σ_i from the weighted fit's residuals and fit again, until no
    /// σ_i changes by 1 % (at most 10 times), instead of taking σ_i from the ordinary fit only
    #[arg(long)]
    pub iterate_weights: bool,
    /// Also estimate physically consistent parameters: every link's pseudo-inertia positive
    /// semidefinite (a mass distribution could have them), actuator inertia, viscous and Coulomb
    /// friction nonnegative, fitting the measurements as well as such parameters can
    #[arg(long)]
    pub consistent: bool,
    /// With --consistent and a TOML ROBOT: write the description with the consistent estimate's
    /// masses, centres of mass, inertias and joint terms in place of its own, as TOML
    #[arg(long, value_name = "FILE", value_parser = file, requires = "consistent", allow_hyphen_values = true)]
    pub description_out: Option<String>,
    /// Print JSON instead of a table
    #[arg(long)]
    pub json: bool,
}

impl Identify {
    /// How many times the weights may be re-estimated (`--iterate-weights`).
    #[must_use]
    pub fn weight_iterations(&self) -> usize {
        dynamics_identification::identify::estimate::ITERATIONS * usize::from(self.iterate_weights)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_declaration_is_consistent() {
        Cli::command().debug_assert();
    }

    /// A value that starts with `-` reaches the option's parser (which says what is wrong with
    /// it), not clap's "unexpected argument" with its misleading tip.
    #[test]
    fn every_value_may_start_with_a_hyphen() {
        for command in Cli::command().get_subcommands() {
            for arg in command.get_arguments() {
                let takes = arg.get_num_args().is_some_and(|n| n.takes_values());
                if takes && !arg.is_positional() && arg.get_id() != "help" {
                    assert!(
                        arg.is_allow_hyphen_values_set(),
                        "{} --{}",
                        command.get_name(),
                        arg.get_id()
                    );
                }
            }
        }
    }
}

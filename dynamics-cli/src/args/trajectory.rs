//! The options of `size` and `simulate`, and `--no-limits`, which they share with `excite`.

use super::values::{file, positive, whole, Numbers, Setting};
use super::RobotFile;
use clap::Args;

/// `--no-limits`: a run past the limits on its length and its output.
#[derive(Args, Debug)]
pub struct Limits {
    /// Run however long it takes and write however much it writes: without it, a run past the
    /// command's limits (the steps, samples or evaluations its options ask for; 1 GB of
    /// output) is refused with what it would cost. A run longer than a few seconds shows its
    /// progress on stderr
    #[arg(long)]
    pub no_limits: bool,
}

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("trajectory").required(true).args(["csv", "from"])))]
pub struct Size {
    #[command(flatten)]
    pub robot: RobotFile,
    /// The trajectory: a header `t,q1,..,qn` (then optionally `qd1,..,qdn`, then optionally
    /// `qdd1,..,qddn`), then one sample per line, t strictly increasing (s; rad or m). Missing
    /// q̇ and q̈ come from central differences on the (uneven) time steps
    #[arg(long, value_name = "FILE", value_parser = file, conflicts_with_all = ["from", "to"], allow_hyphen_values = true)]
    pub csv: Option<String>,
    /// The start pose of a quintic rest-to-rest move (with --to and --duration)
    #[arg(
        long,
        value_name = "Q1,Q2,..",
        allow_hyphen_values = true,
        requires = "to"
    )]
    pub from: Option<Numbers>,
    /// The end pose of the move
    #[arg(
        long,
        value_name = "Q1,Q2,..",
        allow_hyphen_values = true,
        requires = "from"
    )]
    pub to: Option<Numbers>,
    /// The duration of the move, s
    #[arg(long, value_name = "SECONDS", default_value = "2", value_parser = positive, allow_hyphen_values = true)]
    pub duration: f64,
    /// The samples of the move, both ends included
    #[arg(long, value_name = "N", default_value = "1001", value_parser = whole::<2, { u64::MAX }>, allow_hyphen_values = true)]
    pub samples: u64,
    /// The value of a parameter of the robot; once for each of them
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<Setting>,
    /// Write a plot of τ per joint, split into its terms, and of the power, as SVG
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub svg: Option<String>,
    /// Print JSON instead of a table
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub limits: Limits,
}

#[derive(Args, Debug)]
pub struct Simulate {
    #[command(flatten)]
    pub robot: RobotFile,
    /// Initial joint positions [default: 0]
    #[arg(long, value_name = "Q1,Q2,..", allow_hyphen_values = true)]
    pub q0: Option<Numbers>,
    /// Many initial states: every line (q, and q̇ or 0) of a trajectory file in the format
    /// `size --csv` reads; prints each state's end (t0,q..,qd..,energy_start,energy_end), four
    /// states at a time in vector lanes
    #[arg(long, value_name = "FILE", value_parser = file, conflicts_with_all = ["q0", "qd0", "svg"], allow_hyphen_values = true)]
    pub batch: Option<String>,
    /// Initial joint velocities [default: 0]
    #[arg(long, value_name = "QD1,QD2,..", allow_hyphen_values = true)]
    pub qd0: Option<Numbers>,
    /// Constant joint torques (N m) or forces (N) [default: 0]
    #[arg(long, value_name = "TAU1,TAU2,..", allow_hyphen_values = true)]
    pub tau: Option<Numbers>,
    /// The simulated time, s
    #[arg(long, value_name = "SECONDS", default_value = "2", value_parser = positive, allow_hyphen_values = true)]
    pub duration: f64,
    /// The RK4 step, s
    #[arg(long, value_name = "SECONDS", default_value = "0.001", value_parser = positive, allow_hyphen_values = true)]
    pub dt: f64,
    /// The value of a parameter of the robot; once for each of them
    #[arg(long = "set", value_name = "NAME=VALUE", allow_hyphen_values = true)]
    pub set: Vec<Setting>,
    /// Write the trajectory (t,q..,qd..,qdd.., a valid `size --csv` input) to FILE and print
    /// a summary [default: the trajectory on stdout]
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub csv: Option<String>,
    /// Write a plot of the joint positions and of the energy, as SVG
    #[arg(long, value_name = "FILE", value_parser = file, allow_hyphen_values = true)]
    pub svg: Option<String>,
    #[command(flatten)]
    pub limits: Limits,
}

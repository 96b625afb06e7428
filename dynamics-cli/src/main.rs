//! `dynamics`: the generator on the command line, for a robot description file (JSON or TOML,
//! as `#[dynamics(file = "...")]` reads) or a URDF file (`ROBOT.urdf [--base LINK] [--tip
//! LINK]`, as `#[dynamics(urdf = "...", base = "..", tip = "..")]` reads).
//!
//! * `inspect ROBOT [--latex]`: the equations of motion in the book's notation;
//! * `emit ROBOT`: a standalone Rust module with the code the derive generates;
//! * `stats ROBOT`: expansion time, operation counts, longest chain of operations and code
//!   size per method, and the cost of the readable equations the derive adds;
//! * `eval ROBOT --q .. [--qd ..] [--qdd ..] [--set NAME=VALUE].. [--json]`: τ, M, C and g;
//! * `size ROBOT (--csv FILE | --from .. --to ..) [--svg FILE] [--json]`: actuator sizing
//!   along a trajectory: peak and RMS torque, peak power, the terms of τ at its peak;
//! * `simulate ROBOT [--q0 ..] [--qd0 ..] [--tau ..] [--csv FILE] [--svg FILE]`: the forward
//!   dynamics integrated by RK4;
//! * `identify ROBOT --csv FILE [--rotors] [--friction KINDS] [--cutoff HZ] [--plot FILE]
//!   [--json]`: the parameters estimated from measured motions and torques;
//! * `excite ROBOT [--rotors] [--friction KINDS] [--q-min ..] [--q-max ..] [--qd-max ..]
//!   [--qdd-max ..] [--seed S] [--csv FILE]`: a periodic motion within the joints' limits that
//!   excites the base parameters, for `identify`.
//!
//! Errors in the file are reported as `file:line:col: message` (exit code 1); usage errors are
//! clap's (exit code 2). `dynamics help COMMAND` or `dynamics COMMAND --help` for the options.

mod args;
mod commands;
mod excite;
mod format;
mod identify;
mod plot;
mod sizing;
mod trajectory;

use clap::Parser;
use commands::Failure;
use std::process::ExitCode;

fn main() -> ExitCode {
    // `--help`, `--version` and usage errors end here, with clap's exit codes (0 and 2).
    let cli = args::Cli::parse();
    match commands::run(&cli.command) {
        Ok(out) => {
            print!("{out}");
            ExitCode::SUCCESS
        }
        Err(Failure::Usage(error)) => error.exit(),
        Err(Failure::File(message)) => {
            eprintln!("dynamics: {message}");
            ExitCode::from(1)
        }
    }
}

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
//!   [--validate FILE] [--json]`: the parameters estimated from measured motions and torques;
//! * `excite ROBOT [--rotors] [--friction KINDS] [--q-min ..] [--q-max ..] [--qd-max ..]
//!   [--qdd-max ..] [--seed S] [--csv FILE]`: a periodic motion within the joints' limits that
//!   excites the base parameters, for `identify`.
//!
//! Errors in the file are reported as `file:line:col: message` (exit code 1); usage errors are
//! clap's (exit code 2). `dynamics help COMMAND` or `dynamics COMMAND --help` for the options.
//!
//! The same commands are a library, [`run`], for programs that chain them (the examples that
//! excite, measure and identify a robot): the words of a command line in, what the command
//! prints out. One implementation: the binary is [`main`].

mod args;
mod budget;
mod commands;
mod format;
mod plot;
mod report;

use clap::Parser;
use commands::Failure;
use std::io::Write;
use std::process::ExitCode;

/// The `dynamics` binary: the command line of the process, its output on stdout, its errors on
/// stderr, and the exit code.
#[must_use]
pub fn main() -> ExitCode {
    // `--help`, `--version` and usage errors end here, with clap's exit codes (0 and 2).
    let cli = args::Cli::parse();
    match commands::run(&cli.command) {
        Ok(out) => {
            // A reader that stops early (`dynamics emit .. | head`) closes the pipe: not an
            // error of the command, and no panic as `print!` would.
            let mut stdout = std::io::stdout().lock();
            match stdout
                .write_all(out.as_bytes())
                .and_then(|()| stdout.flush())
            {
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
                    eprintln!("dynamics: writing the output: {e}");
                    ExitCode::from(1)
                }
                _ => ExitCode::SUCCESS,
            }
        }
        Err(Failure::Usage(error)) => error.exit(),
        Err(Failure::File(message)) => {
            eprintln!("dynamics: {message}");
            ExitCode::from(1)
        }
    }
}

/// The command line as clap declares it, every command and option with its help: for programs
/// that walk the options (the test that tries each with bad values, shell completions).
#[must_use]
pub fn command() -> clap::Command {
    <args::Cli as clap::CommandFactory>::command()
}

/// Runs the command `words` (`["identify", "robot.toml", "--csv", "m.csv", "--json"]`, without
/// the program's name) in this process: what it prints on stdout, or its error message (a usage
/// error as clap words it, `--help` included). A command that writes its main output to stdout
/// unless given a file (`excite`, `simulate`) still does: give them the file.
///
/// # Errors
/// The command's usage or file error.
pub fn run<I, T>(words: I) -> Result<String, String>
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let program = std::iter::once(std::ffi::OsString::from("dynamics"));
    let cli = args::Cli::try_parse_from(program.chain(words.into_iter().map(Into::into)))
        .map_err(|e| e.to_string())?;
    commands::run(&cli.command).map_err(|failure| match failure {
        Failure::Usage(error) => error.to_string(),
        Failure::File(message) => message,
    })
}

#[cfg(test)]
mod tests {
    use super::run;

    const PUMA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");

    #[test]
    fn a_command_runs_in_process_and_its_errors_come_back() {
        let out = run(["eval", PUMA, "--q", "0,0,0,0,0,0", "--json"]).expect("runs");
        let report: serde_json::Value = serde_json::from_str(&out).expect("JSON");
        assert_eq!(report["tau"].as_array().map(Vec::len), Some(6));
        let missing = run(["eval", "no-such-robot.toml", "--q", "0"]).unwrap_err();
        assert!(missing.starts_with("no-such-robot.toml: "), "{missing}");
        let usage = run(["eval", PUMA, "--q", "0,0"]).unwrap_err();
        assert!(
            usage.contains("--q: 2 values given, the robot has 6 joints"),
            "{usage}"
        );
        assert!(run(["excite"]).unwrap_err().contains("<ROBOT>"));
    }
}

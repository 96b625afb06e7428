//! `dynamics`: the generator on the command line; its commands are those of the library
//! (`dynamics_cli`).

fn main() -> std::process::ExitCode {
    dynamics_cli::main()
}

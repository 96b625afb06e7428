//! The command line's integration tests, one module per file, in one test binary: one link of
//! the generator and the command's library instead of one per file. `cargo test -p dynamics-cli
//! --test it golden::` runs one file's tests.

mod c_floating;
mod c_floating_extras;
mod c_header;
mod c_parameters;
mod c_support;
mod c_tree;
mod c_trig;
mod cli;
mod cli_consistent;
mod cli_csv;
mod cli_excite;
mod cli_floating;
mod cli_fuzz;
mod cli_identify;
mod cli_identify_floating;
mod cli_identify_mimic;
mod cli_limits;
mod cli_mimic;
mod cli_pipe;
mod cli_round_trip;
mod cli_simplify;
mod cli_tool;
mod cli_trajectory;
mod cli_urdf;
mod compile_support;
mod derive_equations;
mod emit_names;
mod emit_round_trip;
mod fuzz;
mod golden;
mod runner;
mod synthetic;

//! Identification from end to end on the PUMA 560 (`robots/puma560.toml`), by the library
//! `dynamics_identification`: an exciting motion (`excite`), its torques simulated by the
//! generated inverse dynamics with 1 % noise, the base parameters identified (`identify`) and
//! printed beside the true ones, the torques of another motion predicted (`predict`), and
//! predicted again by the generated `base_regressor` with the estimates (what a controller would
//! use). The steps are `dynamics_identification_examples`'s; it fails if an estimate is more
//! than five standard deviations off, a prediction error is more than 5 % of a joint's RMS
//! torque, or the generated code and the library disagree.
//!
//! Run with `cargo run --release -p dynamics-identification-examples --example identify_puma560`.

use dynamics_codegen::Source;
use dynamics_identification_examples::example;
use dynamics_runtime::Dynamics;

/// The robot of the description file: the simulation's truth, and its 36 base parameters'
/// regressor for the estimates.
#[derive(Dynamics)]
#[dynamics(file = "../../robots/puma560.toml", base_parameters = true)]
struct Puma560;

fn main() {
    let robot = concat!(env!("CARGO_MANIFEST_DIR"), "/../../robots/puma560.toml");
    example::<_, 6, 36>(&Puma560, Source::file(robot), "puma560");
}

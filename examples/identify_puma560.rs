//! Identification from end to end on the PUMA 560 (`robots/puma560.toml`): an exciting motion
//! (`dynamics excite`), its torques simulated by the generated inverse dynamics with 1 % noise,
//! the base parameters identified (`dynamics identify`) and printed beside the true ones, and
//! the torques of another motion predicted and plotted (`identify --validate`). The steps are
//! `dynamics_examples::identification`'s; it fails if an estimate is more than five standard
//! deviations off or a prediction error more than twice the noise.
//!
//! Run with `cargo run --release -p dynamics-examples --example identify_puma560`.

use dynamics_examples::identification::example;
use dynamics_runtime::Dynamics;

/// The robot of the description file: the simulation's truth.
#[derive(Dynamics)]
#[dynamics(file = "../robots/puma560.toml")]
struct Puma560;

fn main() {
    let robot = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/puma560.toml");
    example(&Puma560, &[robot], "puma560");
}

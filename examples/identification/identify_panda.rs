//! Identification from end to end on a URDF robot, the Franka Emika Panda
//! (`robots/urdf/panda.urdf`, from `panda_link0` to `panda_hand`): its joint ranges and speeds
//! are the URDF's `<limit>`s (Franka's), and its `<dynamics damping friction>` gives every
//! joint viscous, Coulomb and offset friction, identified with the links' parameters: 64 base
//! parameters. Otherwise as `identify_puma560`: an exciting motion, torques simulated by the
//! generated inverse dynamics with 1 % noise, the estimates beside the truth, another motion's
//! torques predicted by the library, and by the generated `base_regressor`.
//!
//! Run with `cargo run --release -p dynamics-identification-examples --example identify_panda`.

use dynamics_codegen::{front, Source};
use dynamics_identification_examples::example;
use dynamics_runtime::Dynamics;

/// The robot of the URDF file: the simulation's truth, and its base parameters' regressor.
#[derive(Dynamics)]
#[dynamics(
    urdf = "../../robots/urdf/panda.urdf",
    base = "panda_link0",
    tip = "panda_hand",
    base_parameters = true
)]
struct Panda;

fn main() {
    let robot = concat!(env!("CARGO_MANIFEST_DIR"), "/../../robots/urdf/panda.urdf");
    let chain = front::Chain {
        base: Some("panda_link0"),
        tip: Some("panda_hand"),
        tips: &[],
    };
    let source = Source {
        chain,
        ..Source::file(robot)
    };
    example::<_, 7, 64>(&Panda, source, "panda");
}

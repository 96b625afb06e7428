//! Identification from end to end on a URDF robot, the UR5 (`robots/urdf/ur5.urdf`, from
//! `base_link` to `tool0`): its joint ranges and speeds are the URDF's `<limit>`s, and the
//! joints' viscous and Coulomb friction are identified with the links' parameters (`--friction
//! viscous,coulomb`, for excite and identify alike; the file's are zero, and so should the
//! estimates be, within their standard deviations). Otherwise as `identify_puma560`: an
//! exciting motion, torques simulated by the generated inverse dynamics with 1 % noise, the
//! estimates beside the truth, another motion's torques predicted and plotted.
//!
//! Run with `cargo run --release -p dynamics-examples --example identify_ur5`.

use dynamics_examples::identification::example;
use dynamics_runtime::Dynamics;

/// The robot of the URDF file: the simulation's truth.
#[derive(Dynamics)]
#[dynamics(urdf = "../robots/urdf/ur5.urdf", base = "base_link", tip = "tool0")]
struct Ur5;

fn main() {
    let robot = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf/ur5.urdf");
    example(
        &Ur5,
        &[
            robot,
            "--base",
            "base_link",
            "--tip",
            "tool0",
            "--friction",
            "viscous,coulomb",
        ],
        "ur5",
    );
}

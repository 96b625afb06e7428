use dynamics_runtime::{Dynamics, DynamicsDerivatives};

// A robot that cannot be read still implements the traits it asks for, for any number of
// joints, so the calls below add no errors to the one about the file.
#[derive(Dynamics)]
#[dynamics(file = "robots/nowhere.json", derivatives = true)]
struct Arm;

fn main() {
    let q = [0.0; 3];
    let _ = Arm.mass_matrix(&q);
    let _ = Arm.forward_dynamics_derivatives(&q, &q, &q);
}

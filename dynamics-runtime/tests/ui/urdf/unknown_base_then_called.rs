use dynamics_runtime::Dynamics;

// A robot that cannot be read still implements the trait, for any number of joints, so the
// calls below add no errors to the one about the base.
#[derive(Dynamics)]
#[dynamics(urdf = "arm.urdf", base = "floor")]
struct Arm;

fn main() {
    let q = [0.0; 2];
    let _ = Arm.inverse_dynamics(&q, &q, &q);
    let _ = Arm.hand_pose(&q);
}

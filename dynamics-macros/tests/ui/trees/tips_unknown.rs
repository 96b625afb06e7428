use dynamics_runtime::{Dynamics, Pose, TipKinematics};

// tips naming a link the URDF does not have: that error alone, the tips' methods still callable.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tips = ["fore", "hand"])]
struct Arm;

fn main() {
    let _: [Pose<f64>; 2] = Arm.tip_poses(&[0.0; 2]);
}

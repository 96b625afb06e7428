use dynamics_runtime::{Dynamics, Pose, TipKinematics};

// tips naming a link the URDF does not have: that error alone, the tips' methods and their
// names' constants (as written) still there.
#[derive(Dynamics)]
#[dynamics(urdf = "tree.urdf", tips = ["fore", "hand"])]
struct Arm;

fn main() {
    let poses: [Pose<f64>; 2] = Arm.tip_poses(&[0.0; 2]);
    let _ = (&poses[Arm::TIP_HAND], Arm::TIP_FORE, Arm::TIP_NAMES);
}

use dynamics_runtime::Dynamics;

// A description file with b on a joint given by origin and axis.
#[derive(Dynamics)]
#[dynamics(file = "b_with_frames.json")]
struct Arm;

fn main() {}

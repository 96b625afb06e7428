use dynamics_runtime::Dynamics;

// A negative stiffness as a literal; a struct field would be read at run time instead.
#[derive(Dynamics)]
#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1, spring = (-5, 0)))]
struct Arm;

fn main() {}

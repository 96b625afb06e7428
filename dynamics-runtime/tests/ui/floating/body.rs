use dynamics_runtime::Dynamics;

// Without a URDF or a file, the floating body is given in `floating(..)`, as a link is.
#[derive(Dynamics)]
#[dynamics(
    base = floating,
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 0.1, 0], [q, 0, 0.2, 0]],
    link(mass = 0.5, com = [0.05, 0, 0], inertia = [0.001, 0.002, 0.003, 0, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0], inertia = [0.0005, 0.001, 0.0012, 0, 0, 0]),
)]
struct NoBody;

// The floating body has no joint: a joint's keys are refused on their value.
#[derive(Dynamics)]
#[dynamics(
    base = floating(mass = 2, com = [0, 0, 0], inertia = [0.02, 0.03, 0.04, 0, 0, 0], gear_ratio = 50),
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 0.1, 0], [q, 0, 0.2, 0]],
    link(mass = 0.5, com = [0.05, 0, 0], inertia = [0.001, 0.002, 0.003, 0, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0], inertia = [0.0005, 0.001, 0.0012, 0, 0, 0]),
)]
struct GearedBody;

// A body without its mass.
#[derive(Dynamics)]
#[dynamics(
    base = floating(com = [0, 0, 0], inertia = [0.02, 0.03, 0.04, 0, 0, 0]),
    gravity = [0, 0, -9.81],
    dh = [[q, 0, 0.1, 0], [q, 0, 0.2, 0]],
    link(mass = 0.5, com = [0.05, 0, 0], inertia = [0.001, 0.002, 0.003, 0, 0, 0]),
    link(mass = 0.3, com = [0.1, 0, 0], inertia = [0.0005, 0.001, 0.0012, 0, 0, 0]),
)]
struct MasslessBody;

fn main() {}

use dynamics_runtime::Dynamics;

// `rated` without `tolerance_percent`, and a list of two values for one joint: each at its
// line and column in the file. And `simplify` in the attribute too, beside the file's.
#[derive(Dynamics)]
#[dynamics(file = "simplify_mistakes.toml")]
struct Arm;

#[derive(Dynamics)]
#[dynamics(file = "simplify_ok.json", simplify(tolerance = 1))]
struct Twice;

fn main() {}

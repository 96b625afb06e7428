//! The options of `emit`: the language, and the C functions' prefix.

use super::{Families, RobotFile};
use clap::Args;
use dynamics_codegen::c_prefix_problem;

#[derive(Args, Debug)]
pub struct Emit {
    #[command(flatten)]
    pub robot: RobotFile,
    #[command(flatten)]
    pub families: Families,
    /// The language: a Rust module on the `dynamics-runtime` crate, or one header-only C99
    /// file (`static inline` functions in `double` and `float`, no allocation, no globals)
    #[arg(long, value_enum, default_value_t = Lang::Rust, allow_hyphen_values = true)]
    pub lang: Lang,
    /// C only: the functions' prefix, NAME_mass_matrix, ... [default: the robot's name in lower
    /// case, other characters than letters and digits `_`]. ASCII letters, digits and single
    /// underscores, a letter first: for two robots whose names give the same prefix
    #[arg(long, value_name = "NAME", value_parser = prefix, allow_hyphen_values = true)]
    pub prefix: Option<String>,
    /// C only: the robot on a free-flying base (the derive's `base = floating`): its
    /// `FloatingDynamics` methods, `q` of n + 7 elements (base position, quaternion, joints),
    /// the others n + 6. A URDF's root link (or --base) flies, a description file's
    /// `[floating]` table is the body
    #[arg(long, conflicts_with_all = ["tip", "tips", "tool"])]
    pub floating: bool,
    /// With --floating: also the kinematics (`FloatingKinematics`): centre of mass and its
    /// Jacobian, A_G and Ȧ_G v, each frame's pose, Jacobians (LOCAL_WORLD_ALIGNED, LOCAL) and
    /// J̇ v
    #[arg(long, requires = "floating")]
    pub kinematics: bool,
    /// With --floating: also the contacts at the frames (with the kinematics): the contact
    /// terms in closed form, `contact_dynamics` (point contacts held), the inverse and forward
    /// dynamics with given wrenches
    #[arg(long, requires = "floating")]
    pub contacts: bool,
    /// With --floating: also `integrate` and `difference` on the configuration space
    #[arg(long, requires = "floating")]
    pub configuration: bool,
}

/// The language `dynamics emit` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Lang {
    /// A standalone Rust module, as `#[derive(Dynamics)]` generates it
    Rust,
    /// A header-only C99 file
    C,
}

/// `--prefix NAME`: a name that makes valid C functions `NAME_method`.
fn prefix(name: &str) -> Result<String, String> {
    match c_prefix_problem(name) {
        Some(problem) => Err(problem),
        None => Ok(name.to_owned()),
    }
}

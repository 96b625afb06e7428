//! `dynamics inspect ROBOT [--latex] [--kinematics]`: the equations of motion, or the hand pose
//! and Jacobians, in the book's notation.

use super::{load, Failure};
use crate::args::Inspect;
use dynamics_codegen::derive;
use dynamics_codegen::inspect::{inspect, inspect_kinematics, Format, Limits};

pub fn run(args: &Inspect) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = derive(&robot);
    let format = if args.latex {
        Format::Latex
    } else {
        Format::Text
    };
    let inspection = if args.kinematics {
        inspect_kinematics(&eq, &robot, Limits::UNBOUNDED)
    } else {
        inspect(&eq, &robot, Limits::UNBOUNDED)
    };
    Ok(inspection.render(format))
}

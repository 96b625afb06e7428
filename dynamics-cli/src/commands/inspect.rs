//! `dynamics inspect ROBOT [--latex] [--kinematics | --base-parameters [--rotors]
//! [--friction ..]]`: the equations of motion, the hand pose and Jacobians, or the base
//! parameters, in the book's notation.

use super::{base_parameters, load, Failure};
use crate::args::Inspect;
use dynamics_codegen::derive;
use dynamics_codegen::inspect::{
    inspect, inspect_kinematics, render_base_parameters, Format, Limits,
};

pub fn run(args: &Inspect) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let mut eq = derive(&robot);
    let format = if args.latex {
        Format::Latex
    } else {
        Format::Text
    };
    if args.base_parameters {
        let columns = args.joint_terms.columns(&robot);
        let base = base_parameters(&mut eq, &robot, &args.robot, &columns)?;
        return Ok(render_base_parameters(&robot.name, &base, format));
    }
    let inspection = if args.kinematics {
        inspect_kinematics(&eq, &robot, Limits::UNBOUNDED)
    } else {
        inspect(&eq, &robot, Limits::UNBOUNDED)
    };
    Ok(inspection.render(format))
}

//! `dynamics inspect ROBOT [--latex]`: the equations of motion in the book's notation.

use super::{load, Failure};
use crate::args::Inspect;
use dynamics_codegen::derive;
use dynamics_codegen::inspect::{inspect, Format, Limits};

pub fn run(args: &Inspect) -> Result<String, Failure> {
    let robot = load(&args.robot)?;
    let eq = derive(&robot);
    let format = if args.latex {
        Format::Latex
    } else {
        Format::Text
    };
    Ok(inspect(&eq, &robot, Limits::UNBOUNDED).render(format))
}

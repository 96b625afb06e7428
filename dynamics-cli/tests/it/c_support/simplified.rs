//! The simplified models a description file asks for (`[simplify]`), built into the equations
//! the header is checked against, as the derive and `dynamics emit` build them.

use dynamics_codegen::front::{At, FileRequest, Given};
use dynamics_codegen::model::Robot;
use dynamics_codegen::Equations;

/// Adds to `eq` the simplified models of `robot` that the file at `path` asks for with
/// `given`, its `[simplify]`, if it has one.
pub fn add(eq: &mut Equations, robot: &Robot, given: Option<Given<At>>, path: &str) {
    let request = FileRequest {
        given,
        limits: None,
        path: path.to_owned(),
    };
    if let Some(r) = request.resolve(robot, &[]).expect("a valid request") {
        dynamics_codegen::simplify::add(eq, &r).expect("simplifies");
    }
}

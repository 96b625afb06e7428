//! A robot's base regressor `Y_B`, ready to evaluate, with what identification and excitation
//! need beside it: the base parameters' names and described values, the joint terms taken, the
//! standard parameters behind them, and the description's springs.

use crate::identify::base::{self, Standard};
use crate::identify::model::LinearModel;
use crate::identify::rows::Springs;
use crate::trajectory::Columns;
use crate::Error;
use dynamics_codegen::derive;
use dynamics_codegen::model::{Robot, Value};
use dynamics_codegen::Equations;
use dynamics_codegen::{BaseParameters, JointColumns};

/// The base regressor of a robot, for [`crate::identify()`], [`crate::predict`] and
/// [`crate::excite()`].
pub struct Regressor {
    model: LinearModel,
    eq: Equations,
    base: BaseParameters,
    joint_columns: Vec<JointColumns>,
    fields: Vec<f64>,
    springs: Vec<Option<(f64, f64)>>,
}

impl Regressor {
    /// The base regressor of `robot`, with joint i's terms `joint_columns[i]`
    /// (`JointColumns::described` takes those its description gives) and `fields`, the values
    /// of the robot's struct fields in the order of `Robot::fields` (empty for a robot of
    /// numbers only).
    ///
    /// # Errors
    /// [`Error::StructFields`]: lengths or angles that are struct fields;
    /// [`Error::Regressor`]: an entry a sample does not give, or a robot with mimic joints.
    ///
    /// # Panics
    /// `fields` or `joint_columns` of another length than the robot's.
    pub fn new(
        robot: &Robot,
        joint_columns: Vec<JointColumns>,
        fields: Vec<f64>,
    ) -> Result<Regressor, Error> {
        if robot.has_mimics() {
            // The regressor has a row per coordinate and a column per link, where the estimate
            // and the samples read both per joint.
            return Err(Error::Regressor(
                "a robot with mimic joints is not identified yet: its base regressor is traced \
                 (a row per coordinate, the links' parameters), but the estimate reads a link \
                 per coordinate"
                    .to_owned(),
            ));
        }
        let names = robot.fields();
        assert_eq!(fields.len(), names.len(), "a value per field");
        assert_eq!(joint_columns.len(), robot.joints.len(), "columns per joint");
        let mut eq = derive(robot);
        let base = eq
            .base_parameters(robot, &joint_columns)
            .ok_or(Error::StructFields)?;
        let model =
            LinearModel::new(&base::entries(&eq, &base, &fields)).map_err(Error::Regressor)?;
        let springs = springs(robot, &names, &fields);
        Ok(Regressor {
            model,
            eq,
            base,
            joint_columns,
            fields,
            springs,
        })
    }

    /// The regressor's tape and columns.
    #[must_use]
    pub fn model(&self) -> &LinearModel {
        &self.model
    }

    /// The base parameters' names, in the estimate's order.
    #[must_use]
    pub fn names(&self) -> &[String] {
        &self.model.names
    }

    /// The columns of the samples `identify` reads: t, q, any q̇ and q̈, and τ.
    #[must_use]
    pub fn columns(&self) -> Columns {
        Columns {
            joints: self.model.joints(),
            torques: true,
        }
    }

    /// The joint terms taken, in words: `actuator inertia (joints 1, 2), viscous (joints
    /// 1-4)`, or `none`.
    #[must_use]
    pub fn joint_terms(&self) -> String {
        base::describe(&self.joint_columns)
    }

    /// The standard parameters behind the base parameters (for the consistent estimate).
    #[must_use]
    pub fn standard(&self) -> Standard {
        base::standard(&self.eq, &self.base, &self.joint_columns, &self.fields)
    }

    /// Per joint, the description's spring `(k, rest)`, if any: its torque is known, not
    /// identified.
    #[must_use]
    pub fn springs(&self) -> &Springs {
        &self.springs
    }
}

/// Per joint, the description's spring `(k, rest)`, if any, at these fields' values.
fn springs(robot: &Robot, names: &[String], values: &[f64]) -> Vec<Option<(f64, f64)>> {
    let field = |f: &str| names.iter().position(|n| n == f).map(|k| values[k]);
    robot
        .joints
        .iter()
        .map(|j| {
            let spring = j.link.spring.as_ref()?;
            // Every field has a value (checked above), and a spring has no joint variable.
            let value = |v: &Value| v.eval(&field).unwrap_or(f64::NAN);
            Some((value(&spring.stiffness), value(&spring.rest)))
        })
        .collect()
}

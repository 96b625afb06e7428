//! A robot's base regressor `Y_B`, ready to evaluate, with what identification and excitation
//! need beside it: the base parameters' names and described values, the joint terms taken, the
//! standard parameters behind them, and the description's springs.

use crate::identify::base::{self, Standard};
use crate::identify::model::LinearModel;
use crate::identify::rows::Springs;
use crate::trajectory::{Base, Columns};
use crate::Error;
use dynamics_codegen::derive;
use dynamics_codegen::model::{Robot, Value};
use dynamics_codegen::{BaseParameters, JointColumns};
use dynamics_codegen::{Equations, Family, FamilySet, Loaded};

/// The base regressor of a robot, for [`crate::identify()`], [`crate::predict`] and
/// [`crate::excite()`].
pub struct Regressor {
    model: LinearModel,
    eq: Equations,
    base: BaseParameters,
    joint_columns: Vec<JointColumns>,
    fields: Vec<f64>,
    springs: Vec<Option<(f64, f64)>>,
    layout: Base,
}

impl Regressor {
    /// The base regressor of `robot`, with joint i's terms `joint_columns[i]`
    /// (`JointColumns::described` takes those its description gives) and `fields`, the values
    /// of the robot's struct fields in the order of `Robot::fields` (empty for a robot of
    /// numbers only).
    ///
    /// # Errors
    /// [`Error::StructFields`]: lengths or angles that are struct fields;
    /// [`Error::Regressor`]: an entry a sample does not give.
    ///
    /// # Panics
    /// `fields` or `joint_columns` of another length than the robot's.
    pub fn new(
        robot: &Robot,
        joint_columns: Vec<JointColumns>,
        fields: Vec<f64>,
    ) -> Result<Regressor, Error> {
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
            layout: Base::Fixed,
        })
    }

    /// The base regressor of `loaded` on a free-flying base (the derive's `base = floating`,
    /// Pinocchio's free flyer), with `fields` as [`Regressor::new`]'s: `Y_B` of the `n + 6`
    /// rows of τ, the base's six (the wrench on it, in its frame: what the contacts supply)
    /// then the joints', or with `joint_rows` the joints' `n` alone; the base parameters of the
    /// `n + 1` bodies, the floating one first. Its samples' q has `n + 7` values, q̇ and q̈
    /// `n + 6` (`trajectory::Base::Floating`).
    ///
    /// # Errors
    /// [`Error::Regressor`]: what a floating base does not support (the message has the
    /// file's diagnostics: joint friction or actuator inertia beside the regressor, lengths or
    /// angles that are struct fields, mimic joints).
    ///
    /// # Panics
    /// `fields` of another length than the robot's.
    pub fn floating(
        loaded: &Loaded,
        fields: Vec<f64>,
        joint_rows: bool,
    ) -> Result<Regressor, Error> {
        let robot = &loaded.robot;
        let names = robot.fields();
        assert_eq!(fields.len(), names.len(), "a value per field");
        let families = FamilySet::default().with(Family::BaseParameters);
        let eq = loaded.floating_equations_with(families).map_err(|d| {
            let lines: Vec<String> = d.iter().map(ToString::to_string).collect();
            Error::Regressor(lines.join("\ndynamics: "))
        })?;
        let Some(base) = eq.base_parameters.clone() else {
            return Err(Error::StructFields);
        };
        let model = {
            let mut entries = base::entries(&eq, &base, &fields);
            if joint_rows {
                entries.rows.drain(..6);
            }
            LinearModel::new(&entries).map_err(Error::Regressor)?
        };
        let model = model.on_floating_base(eq.dof);
        let springs = vec![None; model.joints()];
        Ok(Regressor {
            model,
            eq,
            base,
            joint_columns: vec![JointColumns::default(); robot.joints.len()],
            fields,
            springs,
            layout: Base::Floating { joint_rows },
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
        let joints = match self.layout {
            Base::Fixed => self.model.joints(),
            Base::Floating { .. } => self.eq.dof - 6,
        };
        Columns {
            joints,
            torques: true,
            base: self.layout,
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

/// Per coordinate, the description's springs on it, `(k, rest)`, if any, at these fields'
/// values. A mimic joint m following j (`q_m = c q_j + o`) carries its spring's torque
/// `k (q_m − rest)` onto j times c: `c² k (q_j − (rest − o) / c)`; springs on one coordinate add
/// to one of their summed stiffness, its rest the stiffness-weighted mean.
fn springs(robot: &Robot, names: &[String], values: &[f64]) -> Vec<Option<(f64, f64)>> {
    let field = |f: &str| names.iter().position(|n| n == f).map(|k| values[k]);
    // Every field has a value (checked above), and a spring has no joint variable.
    let value = |v: &Value| v.eval(&field).unwrap_or(f64::NAN);
    let coordinates = robot.coordinates();
    // Per coordinate, Σ stiffness and Σ stiffness × rest.
    let mut sums: Vec<Option<(f64, f64)>> = vec![None; coordinates.len()];
    for (i, joint) in robot.joints.iter().enumerate() {
        let Some(spring) = joint.link.spring.as_ref() else {
            continue;
        };
        let (k, rest) = (value(&spring.stiffness), value(&spring.rest));
        let (followed, c, o) = joint.mimic.as_ref().map_or((i, 1.0, 0.0), |m| {
            (m.joint, value(&m.multiplier), value(&m.offset))
        });
        let Some(row) = coordinates.iter().position(|&j| j == followed) else {
            continue;
        };
        let (k, rest) = (c * c * k, (rest - o) / c);
        let (sum, moment) = sums[row].unwrap_or((0.0, 0.0));
        sums[row] = Some((sum + k, moment + k * rest));
    }
    sums.into_iter()
        .map(|s| s.map(|(k, moment)| (k, if k == 0.0 { 0.0 } else { moment / k })))
        .collect()
}

//! Physical checks on the values of a link that are known at compile time: the mass is finite
//! and not negative, and the inertia tensor is one a rigid body can have: positive
//! semi-definite, with principal moments `λ1 ≤ λ2 ≤ λ3` obeying the triangle inequality
//! `λ1 + λ2 ≥ λ3`.

use super::eigenvalues;
use crate::model::Value;

/// The link parameter a problem is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkParameter {
    /// `mass`.
    Mass,
    /// `inertia`.
    Inertia,
    /// `actuator_inertia`.
    ActuatorInertia,
    /// The stiffness of `spring` (`spring_stiffness` in files).
    SpringStiffness,
    /// The rest position of `spring` (`spring_rest` in files).
    SpringRest,
    /// `friction = (viscous = ..)` (`friction_viscous` in files).
    FrictionViscous,
    /// `friction = (coulomb = ..)` (`friction_coulomb` in files).
    FrictionCoulomb,
    /// `friction = (offset = ..)` (`friction_offset` in files).
    FrictionOffset,
    /// `friction = (smoothing = ..)` (`friction_smoothing` in files).
    FrictionSmoothing,
    /// `rotor_inertia`.
    RotorInertia,
    /// `gear_ratio`.
    GearRatio,
}

impl LinkParameter {
    /// The key that gives it in a description file (`mass`, `spring_stiffness`, ...): every
    /// front end files where it found each value under these keys, so that a problem finds its
    /// place through one table, whatever the input.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            LinkParameter::Mass => "mass",
            LinkParameter::Inertia => "inertia",
            LinkParameter::ActuatorInertia => "actuator_inertia",
            LinkParameter::SpringStiffness => "spring_stiffness",
            LinkParameter::SpringRest => "spring_rest",
            LinkParameter::FrictionViscous => "friction_viscous",
            LinkParameter::FrictionCoulomb => "friction_coulomb",
            LinkParameter::FrictionOffset => "friction_offset",
            LinkParameter::FrictionSmoothing => "friction_smoothing",
            LinkParameter::RotorInertia => "rotor_inertia",
            LinkParameter::GearRatio => "gear_ratio",
        }
    }
}

/// A physical problem with one link.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkProblem {
    /// Which value is wrong.
    pub parameter: LinkParameter,
    /// What is wrong and how to fix it.
    pub message: String,
}

/// The problems of one link's mass and (unless `check_inertia` is false) inertia tensor
/// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`. Values that name struct fields are not known yet and pass.
#[must_use]
pub fn link(mass: &Value, inertia: &[Value; 6], check_inertia: bool) -> Vec<LinkProblem> {
    let mass = mass_problem(mass);
    let inertia = check_inertia.then(|| inertia_problem(inertia)).flatten();
    mass.into_iter().chain(inertia).collect()
}

fn mass_problem(mass: &Value) -> Option<LinkProblem> {
    let m = mass.exact()?;
    let x = m.to_f64();
    let message = if !x.is_finite() {
        "the mass is not a finite number".into()
    } else if m.is_negative() {
        format!("the mass is negative ({}): a mass is 0 or more", short(x))
    } else {
        return None;
    };
    Some(LinkProblem {
        parameter: LinkParameter::Mass,
        message,
    })
}

fn inertia_problem(inertia: &[Value; 6]) -> Option<LinkProblem> {
    let i = inertia
        .iter()
        .map(|v| v.exact().map(crate::symbolic::Number::to_f64))
        .collect::<Option<Vec<f64>>>()?;
    let message = if i.iter().any(|x| !x.is_finite()) {
        "the inertia tensor has an entry that is not a finite number".into()
    } else {
        principal_moments_problem(&i)?
    };
    Some(LinkProblem {
        parameter: LinkParameter::Inertia,
        message,
    })
}

/// What is wrong with the principal moments of the finite tensor `i`, if anything.
fn principal_moments_problem(i: &[f64]) -> Option<String> {
    let tensor = [[i[0], i[3], i[4]], [i[3], i[1], i[5]], [i[4], i[5], i[2]]];
    let [l1, l2, l3] = eigenvalues(tensor);
    // Relative tolerance: the data are decimals rounded far above f64's rounding error.
    let tol = 1e-9 * i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let opt_out = "or add `check_inertia = false` to this link to keep the values as they are";
    let (s1, s2, s3) = (short(l1), short(l2), short(l3));
    if l1 < -tol {
        Some(format!(
            "the inertia tensor is not positive semi-definite (its principal moments are \
             {s1}, {s2}, {s3}), so no rigid body has it: check the signs of Ixy, Ixz, Iyz (they \
             are tensor entries, −∫xy dm), {opt_out}"
        ))
    } else if l1 + l2 < l3 - tol {
        Some(format!(
            "the principal moments of inertia {s1}, {s2}, {s3} break the triangle inequality \
             ({s1} + {s2} < {s3}) that every rigid body obeys: check the values, {opt_out} \
             (some published tables, such as PUMA 560's, have such links)"
        ))
    } else {
        None
    }
}

/// A number with four significant digits, for messages.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    #[allow(clippy::cast_possible_truncation)]
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 17);
    let text = format!("{x:.*}", usize::try_from(digits).unwrap_or(0));
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

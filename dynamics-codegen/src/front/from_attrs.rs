//! The robot built from the attributes: gravity, one joint per D-H row and its `link(...)`,
//! every value checked where it is written. In row i, `q` (or `qi`) in the θ cell makes
//! joint i revolute with `θ = q + offset`, in the d cell prismatic with `d = q + offset`.

use super::angle::unitless_angle;
use super::attr::{Attrs, DhRowAttr, LinkAttr};
use super::errors::Errors;
use super::fields::{check_names, Field};
use super::friction_attr::FrictionAttr;
use super::from_joints;
use super::value::Spanned;
use crate::check;
use crate::model::{
    snap_angle, Convention, Friction, Joint, JointKind, Link, Placement, Pose, Robot, Spring, Value,
};
use proc_macro2::Span;

/// The robot the attributes describe; its errors go to `errors`.
pub(super) fn robot_from_attrs(
    attrs: &Attrs,
    input: &syn::DeriveInput,
    fields: &[Field],
    errors: &mut Errors,
) -> Robot {
    let span = input.ident.span();
    let mut reader = Reader { fields, errors };
    let gravity = match &attrs.gravity {
        Some(g) => reader.values(g),
        None => {
            reader.errors.push(span, "missing `gravity = [gx, gy, gz]`: the gravity acceleration in the base frame, e.g. `[0, 0, -9.81]`");
            Default::default()
        }
    };
    let joints = match (&attrs.dh, &attrs.joints) {
        (None, Some(joints)) => {
            return from_joints::robot(attrs, joints, input, gravity, &mut reader)
        }
        (None, None) => {
            reader.errors.push(
                span,
                "missing `dh = [[θ, d, a, α], ...]`: the D-H table, one row per joint (or \
                 `joints = [revolute(xyz = [..], rpy = [..], axis = [..]), ...]`)",
            );
            Vec::new()
        }
        (Some((rows, table_span)), _) => {
            let spans: Vec<Span> = rows.iter().map(|(at, _)| *at).collect();
            let list = JointList {
                spans: &spans,
                span: *table_span,
                empty: "the D-H table is empty: give one row `[θ, d, a, α]` per joint",
                counted: |n| format!("the D-H table has {n} rows"),
            };
            check_joint_count(&list, &attrs.links, reader.errors);
            rows.iter()
                .enumerate()
                .map(|(i, row)| reader.joint(i + 1, row, attrs, span))
                .collect()
        }
    };
    let tool = tool(&mut reader, attrs);
    Robot {
        name: input.ident.to_string(),
        convention: attrs.convention.map_or(Convention::Standard, |c| c.0),
        gravity,
        joints,
        base: Pose::identity(),
        tool,
    }
}

/// The tool frame in the hand frame, `tool = [x, y, z, roll, pitch, yaw]`.
pub(super) fn tool(reader: &mut Reader, attrs: &Attrs) -> Option<Placement> {
    attrs.tool.as_ref().map(|t| {
        let [x, y, z, roll, pitch, yaw] = reader.values(t);
        Placement::written([x, y, z], [roll, pitch, yaw])
    })
}

/// A list of joints in the attribute, as the count errors name it: a D-H table's rows or a
/// `joints = [..]` list.
pub(super) struct JointList<'a> {
    /// Each joint's tokens.
    pub spans: &'a [Span],
    /// The list's brackets.
    pub span: Span,
    /// The error for an empty list.
    pub empty: &'static str,
    /// How the count is said: `the D-H table has 3 rows`, `3 joints are given`.
    pub counted: fn(usize) -> String,
}

/// Errors for an empty list of joints, one with too many, and a number of `link(...)` entries
/// that is not the number of joints.
pub(super) fn check_joint_count(list: &JointList, links: &[LinkAttr], errors: &mut Errors) {
    let n = list.spans.len();
    if n == 0 {
        errors.push(list.span, list.empty);
    }
    if let Some(at) = list.spans.get(check::MAX_JOINTS) {
        errors.push(
            *at,
            format!(
                "{}; at most {} joints are supported (the generated code grows as n³)",
                (list.counted)(n),
                check::MAX_JOINTS
            ),
        );
    }
    if n != 0 && n != links.len() {
        let at = links.get(n).and_then(|l| l.span).unwrap_or(list.span);
        errors.push(
            at,
            format!(
                "{} but {} `link(...)` entries are given: give one per joint",
                (list.counted)(n),
                links.len()
            ),
        );
    }
}

/// Turns attribute values into model values, reporting the errors of each.
pub(super) struct Reader<'a> {
    fields: &'a [Field],
    pub errors: &'a mut Errors,
}

impl Reader<'_> {
    /// A constant value (not a D-H cell that holds `q`), or zero where none is given.
    pub(super) fn value(&mut self, s: Option<&Spanned>) -> Value {
        let Some(s) = s else {
            return Value::zero();
        };
        check_names(s, self.fields, self.errors);
        check_arithmetic(s, self.errors);
        if s.value.joint_occurrences() > 0 {
            self.errors.push(
                s.span,
                "the joint variable `q` may appear only in the θ or d column of the D-H table",
            );
        }
        s.value.clone()
    }

    /// Constant values, in order.
    pub(super) fn values<const N: usize>(&mut self, s: &[Spanned; N]) -> [Value; N] {
        s.each_ref().map(|s| self.value(Some(s)))
    }

    /// Joint `n` (1-based) from its D-H row and its `link(...)`.
    fn joint(&mut self, n: usize, row: &DhRowAttr, attrs: &Attrs, span: Span) -> Joint {
        let (row_span, [theta, d, a, alpha]) = row;
        for cell in [theta, d] {
            check_names(cell, self.fields, self.errors);
            check_arithmetic(cell, self.errors);
            check_joint_index(&cell.value, n, cell.span, self.errors);
        }
        for angle in [theta, alpha] {
            if let Some((term, message)) = unitless_angle(&angle.unitless, false) {
                self.errors.push_range(term.span, term.end, message);
            }
        }
        let kind = self.kind(n, *row_span, theta, d);
        // Angles near quarter turns (1.5708) are those quarter turns, as in frames and URDFs.
        let theta = snap_angle(&self.offset(theta));
        let d = self.offset(d);
        let a = self.value(Some(a));
        let alpha = snap_angle(&self.value(Some(alpha)));
        let link = self.link(n, attrs.links.get(n - 1), attrs.check_inertia, span);
        Joint::dh(kind, [theta, d, a, alpha], link)
    }

    /// The actuator inertia `gear_ratio² · rotor_inertia` of link `n`'s `link(...)` (ratio 1
    /// without `gear_ratio`), which may not also give `actuator_inertia`.
    fn geared(&mut self, n: usize, link: &LinkAttr) -> Value {
        if let Some(a) = &link.actuator_inertia {
            self.errors.push(a.span, format!("link {n}: give either `actuator_inertia` or `rotor_inertia` and `gear_ratio` (its N² I_rotor), not both"));
        }
        let Some(rotor) = &link.rotor_inertia else {
            let at = link
                .gear_ratio
                .as_ref()
                .map_or(Span::call_site(), |g| g.span);
            self.errors.push(at, format!("link {n}: `gear_ratio` without `rotor_inertia`: the actuator inertia is gear_ratio² × rotor_inertia"));
            return Value::zero();
        };
        let rotor = self.value(Some(rotor));
        let ratio = link
            .gear_ratio
            .as_ref()
            .map_or(Value::Num(crate::symbolic::Number::ONE), |g| {
                self.value(Some(g))
            });
        for problem in check::gear(&rotor, &ratio) {
            let at = match problem.parameter {
                check::LinkParameter::GearRatio => link.gear_ratio.as_ref(),
                _ => link.rotor_inertia.as_ref(),
            };
            let (start, end) =
                at.map_or((Span::call_site(), Span::call_site()), |s| (s.span, s.end));
            self.errors
                .push_range(start, end, format!("link {n}: {}", problem.message));
        }
        check::geared_inertia(&rotor, &ratio)
    }

    /// Revolute if `q` is in the θ cell, prismatic if in the d cell.
    fn kind(&mut self, n: usize, row_span: Span, theta: &Spanned, d: &Spanned) -> JointKind {
        match (theta.value.joint_occurrences(), d.value.joint_occurrences()) {
            (1, 0) => JointKind::Revolute,
            (0, 1) => JointKind::Prismatic,
            (0, 0) => {
                self.errors.push(row_span, format!("row {n} has no joint variable: write `q` in the θ column (revolute) or the d column (prismatic)"));
                JointKind::Revolute
            }
            _ => {
                self.errors.push(
                    row_span,
                    format!(
                        "row {n} must have the joint variable `q` once, in the θ or the d column"
                    ),
                );
                JointKind::Revolute
            }
        }
    }

    /// The offset added to `q` in a D-H cell, or the cell's value where it has no `q`.
    fn offset(&mut self, cell: &Spanned) -> Value {
        if cell.value.joint_occurrences() == 0 {
            return cell.value.clone();
        }
        cell.value.joint_offset().unwrap_or_else(|| {
            self.errors.push(
                cell.span,
                "write the joint variable as `q`, `q + offset` or `q - offset`",
            );
            Value::zero()
        })
    }

    /// The values of link `n`'s `link(...)`, checked; `check_all` is the derive's
    /// `check_inertia`, which the link's own overrides.
    pub(super) fn link(
        &mut self,
        n: usize,
        link: Option<&LinkAttr>,
        check_all: Option<bool>,
        span: Span,
    ) -> Link {
        let com = match link.and_then(|l| l.com.as_ref()) {
            Some(c) => self.values(c),
            None => Default::default(),
        };
        let inertia = match link.and_then(|l| l.inertia.as_ref()) {
            Some((c, _)) => self.values(c),
            None => Default::default(),
        };
        let mass = self.value(link.and_then(|l| l.mass.as_ref()));
        // After an unknown key (a misspelt `mass`?), a missing mass is no news.
        if let Some(l) = link.filter(|l| l.mass.is_none() && !l.unknown_key) {
            self.errors.push(
                l.span.unwrap_or(span),
                format!("link {n} has no `mass = ..`"),
            );
        }
        let actuator_inertia = match link {
            Some(l) if l.rotor_inertia.is_some() || l.gear_ratio.is_some() => self.geared(n, l),
            _ => self.value(link.and_then(|l| l.actuator_inertia.as_ref())),
        };
        let friction = link.and_then(|l| l.friction.as_ref()).map(|f| Friction {
            viscous: self.value(f.viscous.as_ref()),
            coulomb: self.value(f.coulomb.as_ref()),
            offset: self.value(f.offset.as_ref()),
            smoothing: f.smoothing.as_ref().map(|s| self.value(Some(s))),
        });
        let spring = link
            .and_then(|l| l.spring.as_ref())
            .map(|(k, rest)| Spring {
                stiffness: self.value(Some(k)),
                rest: self.value(Some(rest)),
            });
        let values = Link {
            mass,
            com,
            inertia,
            actuator_inertia,
            spring,
            friction,
        };
        if let Some(l) = link {
            let checked = l.check_inertia.or(check_all).unwrap_or(true);
            check_link(n, l, checked, &values, self.errors);
        }
        values
    }
}

/// Errors for literal arithmetic that has no finite result.
fn check_arithmetic(spanned: &Spanned, errors: &mut Errors) {
    if spanned.value.divides_by_zero() {
        errors.push(
            spanned.span,
            format!("division by zero in `{}`", spanned.value),
        );
    } else if spanned
        .value
        .exact()
        .is_some_and(|x| !x.to_f64().is_finite())
    {
        errors.push(
            spanned.span,
            format!(
                "`{}` overflows an f64: it is not a finite number",
                spanned.value
            ),
        );
    }
}

/// The physical checks of link `n` and its joint's drive, each error on the value it is about.
fn check_link(n: usize, link: &LinkAttr, checked: bool, values: &Link, errors: &mut Errors) {
    let finite = |v: &Value| v.exact().map_or(true, |x| x.to_f64().is_finite());
    // A non-finite literal was reported where it is written; do not report it twice.
    let known = |v: &Value| if finite(v) { v.clone() } else { Value::zero() };
    let checked = checked && values.inertia.iter().all(finite);
    let spring = values.spring.as_ref().map(|s| Spring {
        stiffness: known(&s.stiffness),
        rest: known(&s.rest),
    });
    // A geared inertia was checked as its rotor and ratio.
    let geared = link.rotor_inertia.is_some() || link.gear_ratio.is_some();
    let actuator = if geared {
        Value::zero()
    } else {
        known(&values.actuator_inertia)
    };
    let problems = check::link(&known(&values.mass), &values.inertia, checked)
        .into_iter()
        .chain(check::drive(&actuator, spring.as_ref()))
        .chain(values.friction.iter().flat_map(check::friction));
    let whole = |s: &Spanned| (s.span, s.end);
    let friction = |key: fn(&FrictionAttr) -> Option<&Spanned>| {
        let f = link.friction.as_ref()?;
        Some(key(f).map_or((f.span, f.span), whole))
    };
    for problem in problems {
        let at = match problem.parameter {
            check::LinkParameter::Mass => link.mass.as_ref().map(|m| (m.span, m.span)),
            check::LinkParameter::Inertia => link.inertia.as_ref().map(|(_, s)| (*s, *s)),
            check::LinkParameter::ActuatorInertia => link.actuator_inertia.as_ref().map(whole),
            check::LinkParameter::SpringStiffness => link.spring.as_ref().map(|(k, _)| whole(k)),
            check::LinkParameter::SpringRest => link.spring.as_ref().map(|(_, r)| whole(r)),
            check::LinkParameter::FrictionViscous => friction(|f| f.viscous.as_ref()),
            check::LinkParameter::FrictionCoulomb => friction(|f| f.coulomb.as_ref()),
            check::LinkParameter::FrictionOffset => friction(|f| f.offset.as_ref()),
            check::LinkParameter::FrictionSmoothing => friction(|f| f.smoothing.as_ref()),
            check::LinkParameter::RotorInertia => link.rotor_inertia.as_ref().map(whole),
            check::LinkParameter::GearRatio => link.gear_ratio.as_ref().map(whole),
        };
        let fallback = link.span.unwrap_or_else(Span::call_site);
        let (start, end) = at.unwrap_or((fallback, fallback));
        errors.push_range(start, end, format!("link {n}: {}", problem.message));
    }
}

/// An error for `qk` in row `row` with `k ≠ row`.
fn check_joint_index(v: &Value, row: usize, span: Span, errors: &mut Errors) {
    match v {
        Value::Joint(Some(k)) if *k != row => errors.push(
            span,
            format!("`q{k}` in row {row}: the joint variable of row {row} is `q` or `q{row}`"),
        ),
        Value::Neg(a) => check_joint_index(a, row, span, errors),
        Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
            check_joint_index(a, row, span, errors);
            check_joint_index(b, row, span, errors);
        }
        _ => {}
    }
}

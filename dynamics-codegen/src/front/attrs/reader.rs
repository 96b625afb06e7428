//! Attribute values turned into model values: each checked where it is written (the fields it
//! names, literal arithmetic without a finite result, a joint variable out of place), a
//! `link(...)` into a [`Link`] with the tokens of each of its values, and the count of the
//! joint list against the `link(...)` entries. The physical checks of the links come later,
//! in the one pass every input goes through.

use super::link::LinkAttr;
use crate::check;
use crate::front::errors::Errors;
use crate::front::fields::{check_names, Field};
use crate::front::sources::{Sources, Tokens};
use crate::front::value::Spanned;
use crate::model::{Friction, Link, Placement, Spring, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;

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

/// Errors for an empty list of joints and for a number of `link(...)` entries that is not the
/// number of joints.
pub(super) fn check_joint_count(list: &JointList, links: &[LinkAttr], errors: &mut Errors) {
    let n = list.spans.len();
    if n == 0 {
        errors.push(list.span, list.empty);
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

/// Turns attribute values into model values, reporting the errors of each, and keeps where
/// each joint's values are written and whether its inertia tensor is checked.
pub(super) struct Reader<'a> {
    pub fields: &'a [Field],
    pub errors: &'a mut Errors,
    /// Per joint read so far, the tokens of each key.
    pub sources: Sources<Tokens>,
    /// Per joint read so far, whether its inertia tensor is checked.
    pub check_inertia: Vec<bool>,
}

impl<'a> Reader<'a> {
    pub(super) fn new(fields: &'a [Field], errors: &'a mut Errors) -> Reader<'a> {
        Reader {
            fields,
            errors,
            sources: Sources::default(),
            check_inertia: Vec::new(),
        }
    }

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

    /// The tool frame in the hand frame, `tool = [x, y, z, roll, pitch, yaw]`.
    pub(super) fn tool(&mut self, tool: Option<&[Spanned; 6]>) -> Option<Placement> {
        tool.map(|t| {
            let [x, y, z, roll, pitch, yaw] = self.values(t);
            Placement::written([x, y, z], [roll, pitch, yaw])
        })
    }

    /// The link of joint `n` (1-based), whose entry (`type`) is at `entry`, from its
    /// `link(...)`, zero where it gives no value; its inertia is checked unless its own
    /// `check_inertia`, or else the derive's `check_inertia`, is false. `span` is the
    /// derive's name, for a missing mass.
    pub(super) fn link(
        &mut self,
        (n, entry): (usize, Span),
        links: &[LinkAttr],
        check_inertia: Option<bool>,
        span: Span,
    ) -> Link {
        let given = links.get(n - 1);
        let mut places = given.map(places).unwrap_or_default();
        places.insert("type".into(), (entry, entry));
        self.sources.joints.push(places);
        let Some(given) = given else {
            self.check_inertia.push(false);
            return Link::default();
        };
        let link = self.link_values(n, given, span);
        let checked = given.check_inertia.or(check_inertia).unwrap_or(true);
        self.check_inertia
            .push(checked && link.inertia.iter().all(finite));
        // A non-finite literal was reported where it is written: the checks do not report it
        // twice. The robot of an input with errors is not derived.
        Link {
            mass: known(link.mass),
            actuator_inertia: known(link.actuator_inertia),
            spring: link.spring.map(|s| Spring {
                stiffness: known(s.stiffness),
                rest: known(s.rest),
            }),
            friction: link.friction.map(|f| Friction {
                viscous: known(f.viscous),
                coulomb: known(f.coulomb),
                offset: known(f.offset),
                // Left out rather than zero, which the checks would refuse as a smoothing.
                smoothing: f.smoothing.filter(finite),
            }),
            ..link
        }
    }

    /// The values of link `n`'s `link(...)`, each checked where it is written.
    fn link_values(&mut self, n: usize, link: &LinkAttr, span: Span) -> Link {
        let com = match &link.com {
            Some(c) => self.values(c),
            None => Default::default(),
        };
        let inertia = match &link.inertia {
            Some((c, _)) => self.values(c),
            None => Default::default(),
        };
        let mass = self.value(link.mass.as_ref());
        // After an unknown key (a misspelt `mass`?), a missing mass is no news.
        if link.mass.is_none() && !link.unknown_key {
            let at = link.span.unwrap_or(span);
            self.errors.push(at, format!("link {n} has no `mass = ..`"));
        }
        let actuator_inertia = if link.rotor_inertia.is_some() || link.gear_ratio.is_some() {
            self.geared(n, link)
        } else {
            self.value(link.actuator_inertia.as_ref())
        };
        let friction = link.friction.as_ref().map(|f| Friction {
            viscous: self.value(f.viscous.as_ref()),
            coulomb: self.value(f.coulomb.as_ref()),
            offset: self.value(f.offset.as_ref()),
            smoothing: f.smoothing.as_ref().map(|s| self.value(Some(s))),
        });
        let spring = link.spring.as_ref().map(|(k, rest)| Spring {
            stiffness: self.value(Some(k)),
            rest: self.value(Some(rest)),
        });
        Link {
            mass,
            com,
            inertia,
            actuator_inertia,
            spring,
            friction,
        }
    }

    /// The actuator inertia `gear_ratio² · rotor_inertia` of link `n`'s `link(...)` (ratio 1
    /// without `gear_ratio`), which may not also give `actuator_inertia`; zero where the gear
    /// has a problem, which is reported on the rotor or the ratio rather than again on the
    /// product.
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
        let problems = check::gear(&rotor, &ratio);
        let places = places(link);
        for problem in &problems {
            let (start, end) = places
                .get(problem.parameter.key())
                .copied()
                .unwrap_or((Span::call_site(), Span::call_site()));
            self.errors
                .push_range(start, end, format!("link {n}: {}", problem.message));
        }
        if problems.is_empty() {
            check::geared_inertia(&rotor, &ratio)
        } else {
            Value::zero()
        }
    }
}

/// The tokens of each value `link(...)` gives, by the keys of a description file, and the
/// `link` keyword (`link`), where a problem of a value it does not give goes.
fn places(link: &LinkAttr) -> BTreeMap<String, Tokens> {
    let whole = |s: &Spanned| (s.span, s.end);
    let friction = link.friction.iter().flat_map(|f| {
        // A coefficient left out is zero and has no problem; the parentheses stand for it.
        let at = |v: &Option<Spanned>| v.as_ref().map_or((f.span, f.span), whole);
        [
            ("friction_viscous", at(&f.viscous)),
            ("friction_coulomb", at(&f.coulomb)),
            ("friction_offset", at(&f.offset)),
            ("friction_smoothing", at(&f.smoothing)),
        ]
    });
    let given = [
        ("link", link.span.map(|s| (s, s))),
        ("mass", link.mass.as_ref().map(|m| (m.span, m.span))),
        ("inertia", link.inertia.as_ref().map(|(_, s)| (*s, *s))),
        (
            "actuator_inertia",
            link.actuator_inertia.as_ref().map(whole),
        ),
        (
            "spring_stiffness",
            link.spring.as_ref().map(|(k, _)| whole(k)),
        ),
        ("spring_rest", link.spring.as_ref().map(|(_, r)| whole(r))),
        ("rotor_inertia", link.rotor_inertia.as_ref().map(whole)),
        ("gear_ratio", link.gear_ratio.as_ref().map(whole)),
    ];
    given
        .into_iter()
        .filter_map(|(key, at)| Some((key, at?)))
        .chain(friction)
        .map(|(key, at)| (key.to_string(), at))
        .collect()
}

/// Whether `v` is not a literal without a finite value.
fn finite(v: &Value) -> bool {
    v.exact().map_or(true, |x| x.to_f64().is_finite())
}

/// `v`, or zero if it is a literal without a finite value (reported where it is written).
fn known(v: Value) -> Value {
    if finite(&v) {
        v
    } else {
        Value::zero()
    }
}

/// Errors for literal arithmetic that has no finite result.
pub(super) fn check_arithmetic(spanned: &Spanned, errors: &mut Errors) {
    if spanned.value.divides_by_zero() {
        errors.push(
            spanned.span,
            format!("division by zero in `{}`", spanned.value),
        );
    } else if !finite(&spanned.value) {
        errors.push(
            spanned.span,
            format!(
                "`{}` overflows an f64: it is not a finite number",
                spanned.value
            ),
        );
    }
}

//! Arranging a polynomial's terms for reading: grouped by their accelerations and velocities
//! (`(…) θ1''`, `… θ1' θ2'`), then by their sines and cosines with the common parameters taken
//! out (`(1/2 m1 + m2) g l1 C1`). The kinematics, which have no velocities, take the sines and
//! cosines that several terms share out of them instead, as chapter 3 writes the hand pose:
//! `px = C1(a2 C2 + a3 C23)`.

use crate::poly::{AngleSum, Expander, Monomial, Sym};
use crate::symbolic::{NodeId, Number};
use std::collections::BTreeMap;

/// A printed term: `coef · (group) · factors`, with an empty group meaning none.
#[derive(Clone, Debug, PartialEq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Term {
    pub(super) coef: Number,
    pub(super) group: Vec<Term>,
    pub(super) factors: Monomial,
}

/// The readable form of node `id`: its polynomial with sines and cosines of sums folded,
/// arranged; `None` when it does not fit the expander's limits.
pub(super) fn terms(x: &mut Expander<'_>, id: NodeId) -> Option<Vec<Term>> {
    Some(arrange(without_rounding_noise(x.folded(id)?)))
}

/// The readable form of node `id` as [`terms`] gives it, its common sines and cosines taken
/// out (the kinematics).
pub(super) fn factored_terms(x: &mut Expander<'_>, id: NodeId) -> Option<Vec<Term>> {
    Some(arrange_factored(without_rounding_noise(x.folded(id)?)))
}

/// Below this fraction of an output's largest coefficient, an inexact coefficient is what is
/// left of float constants that cancel in exact arithmetic (`5.42101e-20 S3 C1 C2`, 2⁻⁶⁴,
/// beside `0.00051738 S2,3 C1`): far below the six digits printed, and not a term of the model.
const ROUNDING_NOISE: f64 = 1e-12;

/// The terms of a polynomial, less those whose inexact coefficient is rounding noise
/// ([`ROUNDING_NOISE`]). Exact coefficients are all kept, however small.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn without_rounding_noise(terms: BTreeMap<Monomial, Number>) -> Vec<(Monomial, Number)> {
    let largest = terms.values().map(|c| c.to_f64().abs()).fold(0.0, f64::max);
    terms
        .into_iter()
        .filter(|(_, c)| c.is_exact() || c.to_f64().abs() > ROUNDING_NOISE * largest)
        .collect()
}

/// Groups terms by their accelerations and velocities, then by their sines and cosines.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn arrange(terms: Vec<(Monomial, Number)>) -> Vec<Term> {
    let mut by_motion: BTreeMap<(u8, Monomial), Vec<(Monomial, Number)>> = BTreeMap::new();
    for (m, c) in terms {
        let (motion, rest) = m.split(Sym::is_motion);
        // accelerations first, then velocity products, then what has neither
        let rank = if motion
            .factors()
            .iter()
            .any(|(s, _)| matches!(s, Sym::Qdd(_)))
        {
            0
        } else if motion.is_one() {
            2
        } else {
            1
        };
        by_motion.entry((rank, motion)).or_default().push((rest, c));
    }
    let mut out = Vec::new();
    for ((_, motion), group) in by_motion {
        let inner = arrange_configuration(group);
        out.extend(wrap(inner, motion));
    }
    out
}

/// Terms without accelerations or velocities, grouped by their sines and cosines with their
/// common factors taken out. A prismatic position stays inside the group, as the book writes
/// `(m1 g l1/2 + m2 g r) Cθ` (6.14).
fn arrange_configuration(terms: Vec<(Monomial, Number)>) -> Vec<Term> {
    let mut by_config: BTreeMap<Monomial, Vec<(Monomial, Number)>> = BTreeMap::new();
    for (m, c) in terms {
        let (config, params) = m.split(Sym::is_trig);
        by_config.entry(config).or_default().push((params, c));
    }
    let mut out = Vec::new();
    for (config, group) in by_config {
        if config.is_one() || group.len() == 1 {
            out.extend(group.into_iter().map(|(params, coef)| Term {
                coef,
                group: Vec::new(),
                factors: params.times(&config),
            }));
            continue;
        }
        // the parameters every term of the group has, to their lowest power
        let common = group[1..]
            .iter()
            .fold(group[0].0.clone(), |common, (p, _)| common.common(p));
        let inner: Vec<Term> = group
            .into_iter()
            .map(|(mut params, coef)| {
                params.divide(&common);
                Term {
                    coef,
                    group: Vec::new(),
                    factors: params,
                }
            })
            .collect();
        out.extend(wrap(inner, common.times(&config)));
    }
    out
}

/// Terms without velocities, the sine or cosine that most terms have taken out of them (of the
/// lowest joints where several tie), then again inside and in the rest, until no two terms
/// share one: `a2 C1 C2 + a3 C1 C23 + d3 S1` → `C1(a2 C2 + a3 C23) + d3 S1`. A sum starts with
/// its positive terms (`C4 C5 C6 - S4 S6`), each sign's in the order of their lowest joints.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn arrange_factored(terms: Vec<(Monomial, Number)>) -> Vec<Term> {
    let mut out = factor_out(terms);
    // The lowest joints' sines and cosines first, as `l1 C1 + l2 C12`.
    let first_angle = |t: &Term| {
        let angles = t.factors.factors().iter();
        angles
            .filter_map(|(s, _)| s.as_trig())
            .map(|(_, a)| a)
            .min()
    };
    out.sort_by_key(|t| (t.coef.is_negative(), first_angle(t)));
    out
}

fn factor_out(terms: Vec<(Monomial, Number)>) -> Vec<Term> {
    let mut shared: BTreeMap<(AngleSum, bool), usize> = BTreeMap::new();
    for (m, _) in &terms {
        for (s, _) in m.factors() {
            if let Some((cos, angle)) = s.as_trig() {
                *shared.entry((angle, cos)).or_default() += 1;
            }
        }
    }
    // The first of the most shared: BTreeMap order is the lowest joints first, sine first.
    let best = shared.into_iter().fold(
        None,
        |best: Option<((AngleSum, bool), usize)>, (key, n)| match best {
            Some((_, m)) if m >= n => best,
            _ => Some((key, n)),
        },
    );
    let Some(((angle, cos), 2..)) = best else {
        return arrange_configuration(terms);
    };
    let factor = if cos {
        Sym::Cos(angle)
    } else {
        Sym::Sin(angle)
    };
    let (mut with, without): (Vec<_>, Vec<_>) = terms
        .into_iter()
        .partition(|(m, _)| m.exponent(&factor) > 0);
    for (m, _) in &mut with {
        m.divide_once(&factor);
    }
    let mut out = wrap(arrange_factored(with), Monomial::of(factor));
    out.extend(arrange_factored(without));
    out
}

/// `(inner) · factors`, written without parentheses when `inner` is one term, and with a
/// leading minus when all of it is negative.
fn wrap(mut inner: Vec<Term>, factors: Monomial) -> Vec<Term> {
    if factors.is_one() {
        return inner;
    }
    if inner.len() == 1 {
        let mut t = inner.remove(0);
        t.factors = t.factors.times(&factors);
        return vec![t];
    }
    let negative = inner.iter().all(|t| t.coef.is_negative());
    if negative {
        for t in &mut inner {
            t.coef = -t.coef;
        }
    }
    vec![Term {
        coef: if negative {
            Number::MINUS_ONE
        } else {
            Number::ONE
        },
        group: inner,
        factors,
    }]
}

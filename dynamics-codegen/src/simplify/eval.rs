//! Numeric evaluation of a polynomial's terms at one state, for checking a pruning against
//! the full polynomial and the graph: `S12 = sin(θ1 + θ2)` from the joint angles, each with
//! its constant offset.

use crate::poly::{Monomial, Sym};
use crate::symbolic::{Node, Number, Var};
use crate::trace::Equations;
use std::collections::BTreeMap;

/// A state of the robot: positions, velocities and accelerations, one per joint.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    /// The joint positions `q` (the angle without its offset for a revolute joint).
    pub q: &'a [f64],
    /// The velocities `q̇`.
    pub qd: &'a [f64],
    /// The accelerations `q̈`.
    pub qdd: &'a [f64],
}

/// The robot's constants that the symbols hide: each joint's θ offset (0 where there is
/// none), the `offset_i` of [`Equations::angle_offsets`], and the gain `1/ε_i` of its smooth
/// Coulomb friction `tanh(q̇_i / ε_i)` (0 where there is none).
#[derive(Clone, Debug, PartialEq)]
pub struct Constants {
    /// The θ offsets.
    pub offsets: Vec<f64>,
    /// The gains `1/ε_i` of `tanh`.
    pub tanh_gains: Vec<f64>,
}

/// The [`Constants`] of `eq`.
///
/// # Errors
/// The joint whose offset depends on a parameter, which has no value here.
pub fn constants(eq: &Equations) -> Result<Constants, String> {
    // Parameters read as NaN: an offset that depends on one comes out NaN. With every
    // velocity 1, a tanh's argument is its gain.
    let values = eq.graph.eval(|v| match v {
        Var::Param(_) => f64::NAN,
        Var::Qd(_) => 1.0,
        _ => 0.0,
    });
    let offsets = eq
        .angle_offsets
        .iter()
        .enumerate()
        .map(|(i, o)| match o {
            None => Ok(0.0),
            Some(id) if values[id.index()].is_finite() => Ok(values[id.index()]),
            Some(_) => Err(format!(
                "joint {}'s angle offset depends on a parameter of the robot",
                i + 1
            )),
        })
        .collect::<Result<_, _>>()?;
    let mut tanh_gains = vec![0.0; eq.dof];
    for (_, node) in eq.graph.nodes() {
        if let (Node::Tanh(a), Some(Sym::Tanh(i))) = (node, Sym::of_friction(&eq.graph, node)) {
            if let Some(g) = tanh_gains.get_mut(usize::from(i)) {
                *g = values[a.index()];
            }
        }
    }
    Ok(Constants {
        offsets,
        tanh_gains,
    })
}

/// The value of symbol `s` at `state`; `None` for a parameter.
#[must_use]
pub fn symbol_value(s: &Sym, state: State<'_>, k: &Constants) -> Option<f64> {
    let offsets = &k.offsets[..];
    let at = |v: &[f64], i: &u16| v.get(usize::from(*i)).copied();
    Some(match s {
        Sym::Param(_) => return None,
        Sym::Tanh(i) => (at(state.qd, i)? * at(&k.tanh_gains, i)?).tanh(),
        Sym::Q(i) => at(state.q, i)?,
        Sym::Sin(a) | Sym::Cos(a) => {
            let mut angle = 0.0;
            for j in a.joints() {
                angle += at(state.q, &j)? + at(offsets, &j)?;
            }
            if matches!(s, Sym::Sin(_)) {
                angle.sin()
            } else {
                angle.cos()
            }
        }
        Sym::MimicSin(a) => a.at(at(state.q, &a.joint)?).sin(),
        Sym::MimicCos(a) => a.at(at(state.q, &a.joint)?).cos(),
        Sym::Qd(i) => at(state.qd, i)?,
        Sym::Qdd(i) => at(state.qdd, i)?,
        Sym::Sign(i) => {
            let v = at(state.qd, i)?;
            if v == 0.0 {
                0.0
            } else {
                v.signum()
            }
        }
    })
}

/// The sum of `terms` at `state`; `None` where a symbol has no value ([`symbol_value`]).
#[must_use]
pub fn eval_terms(
    terms: &BTreeMap<Monomial, Number>,
    state: State<'_>,
    k: &Constants,
) -> Option<f64> {
    Terms::new(terms)?.eval(state, k)
}

/// A polynomial made ready to evaluate at many states: its few dozen distinct symbols each
/// valued once a state (a sine or cosine per factor of thousands of terms took most of a test's
/// time), each term its coefficient and its factors as indices into them.
pub struct Terms<'a> {
    symbols: Vec<&'a Sym>,
    terms: Vec<(f64, Vec<(usize, i32)>)>,
}

impl<'a> Terms<'a> {
    /// `terms` indexed; `None` where an exponent does not fit an `i32`.
    #[must_use]
    pub fn new(terms: &'a BTreeMap<Monomial, Number>) -> Option<Self> {
        let mut index: BTreeMap<&Sym, usize> = BTreeMap::new();
        let mut symbols = Vec::new();
        let mut indexed = Vec::with_capacity(terms.len());
        for (m, c) in terms {
            let mut factors = Vec::new();
            for (s, e) in m.factors() {
                let k = *index.entry(s).or_insert_with(|| {
                    symbols.push(s);
                    symbols.len() - 1
                });
                factors.push((k, i32::try_from(*e).ok()?));
            }
            indexed.push((c.to_f64(), factors));
        }
        Some(Terms {
            symbols,
            terms: indexed,
        })
    }

    /// The sum of the terms at `state`; `None` where a symbol has no value ([`symbol_value`]).
    #[must_use]
    pub fn eval(&self, state: State<'_>, k: &Constants) -> Option<f64> {
        let values = self
            .symbols
            .iter()
            .map(|s| symbol_value(s, state, k))
            .collect::<Option<Vec<f64>>>()?;
        let mut sum = 0.0;
        for (c, factors) in &self.terms {
            let mut x = *c;
            for &(s, e) in factors {
                x *= values[s].powi(e);
            }
            sum += x;
        }
        Some(sum)
    }
}

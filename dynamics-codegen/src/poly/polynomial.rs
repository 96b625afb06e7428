//! A canonical form for closed forms: sparse polynomials in sines and cosines of joint angles
//! (`S1`, `C1`) and of mimic joints' angles, prismatic positions, velocities, accelerations and parameters, with exact
//! rational coefficients and `S² = 1 − C²` applied, so that two expressions are equal
//! exactly when their canonical forms are. For display and tests on small robots; code is
//! emitted from the graph.

use super::{AngleSum, Monomial, Sym};
use crate::symbolic::{Graph, Node, NodeId, Number};
use std::collections::btree_map::Entry;
use std::collections::BTreeMap;
use std::fmt;

/// A polynomial with exact coefficients.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Poly {
    terms: BTreeMap<Monomial, Number>,
}

impl Poly {
    /// The constant `c`.
    #[must_use]
    pub fn constant(c: Number) -> Poly {
        let mut p = Poly::default();
        if !c.is_zero() {
            p.terms.insert(Monomial::default(), c);
        }
        p
    }

    /// The symbol `s`.
    #[must_use]
    pub fn sym(s: Sym) -> Poly {
        let mut p = Poly::default();
        p.terms.insert(Monomial::of(s), Number::ONE);
        p
    }

    /// Whether the polynomial is zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Number of terms.
    #[must_use]
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The terms in canonical order: each monomial and its coefficient.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, Number)> + '_ {
        self.terms.iter().map(|(m, c)| (m, *c))
    }

    /// The terms by monomial.
    #[must_use]
    pub fn into_terms(self) -> BTreeMap<Monomial, Number> {
        self.terms
    }

    /// The coefficient of the constant term, if that is the only term (or there is none).
    #[must_use]
    pub fn as_constant(&self) -> Option<Number> {
        match self.terms.iter().next() {
            None => Some(Number::ZERO),
            Some((m, c)) if m.is_one() && self.len() == 1 => Some(*c),
            Some(_) => None,
        }
    }

    fn add_term(&mut self, m: Monomial, c: Number) {
        match self.terms.entry(m) {
            Entry::Occupied(mut e) => {
                let sum = *e.get() + c;
                if sum.is_zero() {
                    e.remove();
                } else {
                    *e.get_mut() = sum;
                }
            }
            Entry::Vacant(e) => {
                if !c.is_zero() {
                    e.insert(c);
                }
            }
        }
    }

    /// `self + o`.
    #[must_use]
    pub fn add(&self, o: &Poly) -> Poly {
        let mut r = self.clone();
        for (m, c) in &o.terms {
            r.add_term(m.clone(), *c);
        }
        r
    }

    /// `k · self`.
    #[must_use]
    pub fn scale(&self, k: Number) -> Poly {
        let mut r = Poly::default();
        if k.is_zero() {
            return r;
        }
        for (m, c) in &self.terms {
            r.terms.insert(m.clone(), *c * k);
        }
        r
    }

    /// `self − o`.
    #[must_use]
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.scale(Number::MINUS_ONE))
    }

    /// `self · o`, with `S² = 1 − C²`.
    #[must_use]
    pub fn mul(&self, o: &Poly) -> Poly {
        let mut r = Poly::default();
        let right = o.in_summation_order();
        for (ma, ca) in self.in_summation_order() {
            for &(mb, cb) in &right {
                for (mono, c) in reduce_sine_squares(ma.times(mb)) {
                    r.add_term(mono, c * (ca * cb));
                }
            }
        }
        r
    }

    /// The terms in the order a product accumulates them. Float coefficients (from floats
    /// in the description, or rationals that overflow) round differently in another order,
    /// so this order is fixed, independent of the order of [`Sym`], keeping printed
    /// equations the same: by parameters, cosines, sines, positions, velocities, then
    /// accelerations.
    fn in_summation_order(&self) -> Vec<(&Monomial, Number)> {
        let mut terms: Vec<(&Monomial, Number)> = self.terms().collect();
        if terms.len() > 1 {
            terms.sort_by_cached_key(|(m, _)| {
                let mut key: Vec<(SummationKey<'_>, u32)> = m
                    .factors()
                    .iter()
                    .map(|(s, e)| (SummationKey::of(s), *e))
                    .collect();
                key.sort_unstable();
                key
            });
        }
        terms
    }

    /// The canonical form of graph node `id`; `None` where the graph holds a reciprocal or the
    /// sine of a parameter, or the form exceeds `max_terms`.
    #[must_use]
    pub fn from_graph(
        graph: &Graph,
        id: NodeId,
        fields: &[String],
        max_terms: usize,
    ) -> Option<Poly> {
        let live = graph.live(&[id]);
        let mut memo: Vec<Option<Poly>> = vec![None; id.index() + 1];
        for (n, node) in graph.nodes().take(id.index() + 1) {
            if !live[n.index()] {
                continue;
            }
            let get = |x: NodeId| memo[x.index()].clone();
            let p = match node {
                Node::Const(c) => Poly::constant(c),
                Node::Var(v) => Poly::sym(Sym::of(v, fields)?),
                Node::Add(a, b) => get(a)?.add(&get(b)?),
                Node::Mul(a, b) => get(a)?.mul(&get(b)?),
                Node::Neg(a) => get(a)?.scale(Number::MINUS_ONE),
                Node::Sign(_) | Node::Tanh(_) => Poly::sym(Sym::of_friction(graph, node)?),
                Node::Sin(a) | Node::Cos(a) => {
                    Poly::sym(Sym::mimic_trig(matches!(node, Node::Cos(_)), &get(a)?)?)
                }
                Node::Recip(_) => return None,
            };
            if p.len() > max_terms {
                return None;
            }
            memo[n.index()] = Some(p);
        }
        memo[id.index()].clone()
    }
}

/// A symbol's place in [`Poly::in_summation_order`], by the order of the variants.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum SummationKey<'a> {
    Param(&'a str),
    Cos(AngleSum),
    Sin(AngleSum),
    Mimic(&'a Sym),
    Q(u16),
    Qd(u16),
    Qdd(u16),
    Friction(&'a Sym),
}

impl SummationKey<'_> {
    fn of(s: &Sym) -> SummationKey<'_> {
        match s {
            Sym::Param(p) => SummationKey::Param(p),
            Sym::Cos(a) => SummationKey::Cos(*a),
            Sym::Sin(a) => SummationKey::Sin(*a),
            Sym::MimicSin(_) | Sym::MimicCos(_) => SummationKey::Mimic(s),
            Sym::Q(i) => SummationKey::Q(*i),
            Sym::Qd(i) => SummationKey::Qd(*i),
            Sym::Qdd(i) => SummationKey::Qdd(*i),
            Sym::Sign(_) | Sym::Tanh(_) => SummationKey::Friction(s),
        }
    }
}

/// Rewrites `S^e` with `e ≥ 2` through `S² = 1 − C²`, into monomials with their
/// coefficients.
fn reduce_sine_squares(m: Monomial) -> Vec<(Monomial, Number)> {
    let square_sine = |m: &Monomial| {
        m.factors()
            .iter()
            .find(|(s, e)| s.cosine_of_sine().is_some() && *e >= 2)
            .map(|(s, _)| s.clone())
    };
    let mut out = vec![(m, Number::ONE)];
    while let Some((pos, sine)) = out
        .iter()
        .enumerate()
        .find_map(|(k, (m, _))| Some((k, square_sine(m)?)))
    {
        let (m, c) = out.swap_remove(pos);
        let Some(cosine) = sine.cosine_of_sine() else {
            break;
        };
        let mut base = m;
        base.divide(&Monomial::from_iter([(sine, 2)]));
        let mut with_cos = base.clone();
        with_cos.multiply(cosine, 2);
        out.push((base, c));
        out.push((with_cos, -c));
    }
    out
}

impl fmt::Display for Poly {
    /// Terms in canonical order, in the syntax of [`Poly::parse`]: `1/3*m1*l^2 + m2*l^2*C2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        for (k, (m, c)) in self.terms.iter().enumerate() {
            let negative = c.is_negative();
            let abs = if negative { -*c } else { *c };
            match (k, negative) {
                (0, true) => write!(f, "-")?,
                (0, false) => {}
                (_, true) => write!(f, " - ")?,
                (_, false) => write!(f, " + ")?,
            }
            let mut parts: Vec<String> = Vec::new();
            if !abs.is_one() || m.is_one() {
                parts.push(abs.to_string());
            }
            for (s, e) in m.factors() {
                parts.push(if *e == 1 {
                    s.to_string()
                } else {
                    format!("{s}^{e}")
                });
            }
            write!(f, "{}", parts.join("*"))?;
        }
        Ok(())
    }
}

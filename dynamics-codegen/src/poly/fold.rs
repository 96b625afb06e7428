//! Folding of sines and cosines of single angles back into those of sums, by the addition
//! formulas read backwards: `C_a C_b − S_a S_b = C_(a+b)` and `S_a C_b + C_a S_b = S_(a+b)`
//! (`C1 C2 − S1 S2` → `C12`).

use super::{AngleSum, Monomial, Sym};
use crate::symbolic::Number;
use std::collections::{BTreeMap, BTreeSet};
use std::ops::Bound;

/// One fold: `k · rest · trig(a + b)` replaces `k` of term `m` and of its partner.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Fold {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub m: Monomial,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub partner: Monomial,
    /// Added to the partner's coefficient.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub partner_delta: Number,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub folded: Monomial,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub k: Number,
}

/// Folds `c Ca Cb − c Sa Sb` into `c C(a+b)` and `c Sa Cb + c Ca Sb` into `c S(a+b)` until
/// no pair is left; where the two coefficients differ, the smaller is folded. `charge` is
/// told the number of terms before each search and stops the folding with `None`.
///
/// Each fold is the first in the terms' order, as a search from the start would find it, but
/// no term is searched twice unless a fold may have given it one: a fold only shrinks its two
/// terms (never flipping a sign), so only the term folded (if some of it is left), the new term
/// and the terms the new one partners can start a new fold. Those are searched again, in order,
/// before the terms past the furthest searched. Searching from the start each time made the
/// Panda's torques take minutes; resuming from the first of those terms still searched the
/// terms between them again, most of a 7-joint arm's `dynamics inspect`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn fold_trig(
    terms: &mut BTreeMap<Monomial, Number>,
    charge: &mut dyn FnMut(usize) -> Option<()>,
) -> Option<()> {
    let mut search = Search::default();
    loop {
        charge(terms.len())?;
        let Some(fold) = search.next(terms) else {
            return Some(());
        };
        for p in partners(&fold.folded).filter(|p| terms.contains_key(p)) {
            search.again.insert(p);
        }
        search.again.insert(fold.m.clone());
        search.again.insert(fold.folded.clone());
        add_term(terms, fold.m, -fold.k);
        add_term(terms, fold.partner, fold.partner_delta);
        add_term(terms, fold.folded, fold.k);
    }
}

/// Where the folding's search stands: every term up to `searched` starts no fold, except
/// those in `again`.
#[derive(Default)]
struct Search {
    searched: Option<Monomial>,
    again: BTreeSet<Monomial>,
}

impl Search {
    /// The first fold in the terms' order.
    fn next(&mut self, terms: &BTreeMap<Monomial, Number>) -> Option<Fold> {
        while let Some(m) = self.again.pop_first() {
            if !self.searched.as_ref().is_some_and(|s| m <= *s) {
                // Past the furthest searched: the search below reaches it in its turn.
                self.again.insert(m);
                break;
            }
            if let Some(fold) = terms
                .get_key_value(&m)
                .and_then(|(m, &c)| fold_of(terms, m, c))
            {
                return Some(fold);
            }
        }
        let range = match &self.searched {
            Some(s) => terms.range((Bound::Excluded(s.clone()), Bound::Unbounded)),
            None => terms.range(..),
        };
        // The furthest term searched, cloned once a search rather than once a term.
        let mut last = None;
        for (m, &c) in range {
            last = Some(m);
            if let Some(fold) = fold_of(terms, m, c) {
                self.searched = Some(m.clone());
                return Some(fold);
            }
        }
        if let Some(m) = last {
            self.searched = Some(m.clone());
        }
        None
    }
}

/// The monomials that `m` could fold with: one of its cosines and another of its sines or
/// cosines, of disjoint angles, both swapped (cosine for sine).
fn partners(m: &Monomial) -> impl Iterator<Item = Monomial> + '_ {
    let trigs: Vec<(bool, AngleSum)> = m
        .factors()
        .iter()
        .filter_map(|(s, _)| s.as_trig())
        .collect();
    let pairs: Vec<_> = trigs
        .iter()
        .enumerate()
        .flat_map(|(x, &a)| trigs[x + 1..].iter().map(move |&b| (a, b)))
        .filter(|&((cos_a, a), (cos_b, b))| (cos_a || cos_b) && a.is_disjoint(b))
        .collect();
    pairs.into_iter().map(|((cos_a, a), (cos_b, b))| {
        let mut p = m.clone();
        p.divide_once(&Sym::trig(cos_a, a));
        p.divide_once(&Sym::trig(cos_b, b));
        p.multiply(Sym::trig(!cos_a, a), 1);
        p.multiply(Sym::trig(!cos_b, b), 1);
        p
    })
}

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn add_term(terms: &mut BTreeMap<Monomial, Number>, m: Monomial, c: Number) {
    let entry = terms.entry(m.clone()).or_insert(Number::ZERO);
    *entry = *entry + c;
    if entry.is_zero() {
        terms.remove(&m);
    }
}

/// The first pair of terms, in their order, that folds.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn find_fold(terms: &BTreeMap<Monomial, Number>) -> Option<Fold> {
    terms.iter().find_map(|(m, &c)| fold_of(terms, m, c))
}

/// The first fold that term `c · m` starts, its pairs of factors in order.
fn fold_of(terms: &BTreeMap<Monomial, Number>, m: &Monomial, c: Number) -> Option<Fold> {
    // The pairs of sines and cosines read off the factors in place: collected into a vector,
    // they were an allocation for every term searched.
    let factors = m.factors();
    for (x, (s, _)) in factors.iter().enumerate() {
        let Some(a) = s.as_trig() else { continue };
        for (t, _) in &factors[x + 1..] {
            let Some(b) = t.as_trig() else { continue };
            if let Some(fold) = fold_pair(terms, m, c, a, b) {
                return Some(fold);
            }
        }
    }
    None
}

/// The fold of the factors `a` and `b` (each a cosine flag and an angle) of term `c · m` with
/// its partner, if the partner is there with the sign that makes a sum formula.
fn fold_pair(
    terms: &BTreeMap<Monomial, Number>,
    m: &Monomial,
    c: Number,
    (cos_a, angle_a): (bool, AngleSum),
    (cos_b, angle_b): (bool, AngleSum),
) -> Option<Fold> {
    if !(cos_a || cos_b) || !angle_a.is_disjoint(angle_b) {
        return None;
    }
    let both_cos = cos_a && cos_b;
    // `m` without the two factors: built only for a fold, as most pairs have no partner.
    let rest = || {
        let mut rest = m.clone();
        rest.divide_once(&Sym::trig(cos_a, angle_a));
        rest.divide_once(&Sym::trig(cos_b, angle_b));
        rest
    };
    // cos-cos pairs with sin-sin of the opposite sign; sin-cos with cos-sin of the same sign.
    let mut partner = rest();
    partner.multiply(Sym::trig(!cos_a, angle_a), 1);
    partner.multiply(Sym::trig(!cos_b, angle_b), 1);
    let &pc = terms.get(&partner)?;
    let same_sign = c.is_negative() == pc.is_negative();
    if same_sign == both_cos {
        return None;
    }
    let k = if c.to_f64().abs() <= pc.to_f64().abs() {
        c
    } else if both_cos {
        -pc
    } else {
        pc
    };
    let mut folded = rest();
    folded.multiply(Sym::trig(both_cos, angle_a.union(angle_b)), 1);
    Some(Fold {
        m: m.clone(),
        partner,
        partner_delta: if both_cos { k } else { -k },
        folded,
        k,
    })
}

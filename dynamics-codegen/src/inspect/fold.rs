//! Folding of sines and cosines of single angles back into those of sums, by the addition
//! formulas read backwards: `C_a C_b − S_a S_b = C_(a+b)` and `S_a C_b + C_a S_b = S_(a+b)`
//! (`C1 C2 − S1 S2` → `C12`).

use super::{AngleSum, Monomial, Sym};
use crate::symbolic::Number;
use std::collections::BTreeMap;

/// One fold: `k · rest · trig(a + b)` replaces `k` of term `m` and of its partner.
struct Fold {
    m: Monomial,
    partner: Monomial,
    /// Added to the partner's coefficient.
    partner_delta: Number,
    folded: Monomial,
    k: Number,
}

/// Folds `c Ca Cb − c Sa Sb` into `c C(a+b)` and `c Sa Cb + c Ca Sb` into `c S(a+b)` until
/// no pair is left; where the two coefficients differ, the smaller is folded. `charge` is
/// told the number of terms before each search and stops the folding with `None`.
pub(super) fn fold_trig(
    terms: &mut BTreeMap<Monomial, Number>,
    charge: &mut dyn FnMut(usize) -> Option<()>,
) -> Option<()> {
    loop {
        charge(terms.len())?;
        let Some(fold) = find_fold(terms) else {
            return Some(());
        };
        add_term(terms, fold.m, -fold.k);
        add_term(terms, fold.partner, fold.partner_delta);
        add_term(terms, fold.folded, fold.k);
    }
}

fn add_term(terms: &mut BTreeMap<Monomial, Number>, m: Monomial, c: Number) {
    let entry = terms.entry(m.clone()).or_insert(Number::ZERO);
    *entry = *entry + c;
    if entry.is_zero() {
        terms.remove(&m);
    }
}

/// The first pair of terms, in order, that folds.
fn find_fold(terms: &BTreeMap<Monomial, Number>) -> Option<Fold> {
    for (m, &c) in terms {
        let trigs: Vec<(bool, AngleSum)> = m
            .factors()
            .iter()
            .filter_map(|(s, _)| s.as_trig())
            .collect();
        for (x, &a) in trigs.iter().enumerate() {
            for &b in &trigs[x + 1..] {
                if let Some(fold) = fold_pair(terms, m, c, a, b) {
                    return Some(fold);
                }
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

//! A product of symbols with positive integer exponents, `m2 l1² C12 θ1'`: the key of a
//! polynomial's terms and the factors of a printed term.

use super::Sym;
use std::cmp::Ordering;

/// A product of symbols, kept sorted by symbol with positive exponents, so that equal
/// products are equal values. Ordered as its list of `(symbol, exponent)` pairs.
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Monomial(Vec<(Sym, u32)>);

impl Monomial {
    /// The symbol `s` to the first power.
    #[must_use]
    pub fn of(s: Sym) -> Monomial {
        Monomial(vec![(s, 1)])
    }

    /// The factors with their exponents, in order.
    #[must_use]
    pub fn factors(&self) -> &[(Sym, u32)] {
        &self.0
    }

    /// Whether it is the empty product 1.
    #[must_use]
    pub fn is_one(&self) -> bool {
        self.0.is_empty()
    }

    /// The exponent of `s` (0 when absent).
    #[must_use]
    pub fn exponent(&self, s: &Sym) -> u32 {
        self.position(s).map_or(0, |k| self.0[k].1)
    }

    fn position(&self, s: &Sym) -> Result<usize, usize> {
        self.0.binary_search_by(|(x, _)| x.cmp(s))
    }

    /// Multiplies by `s^e`.
    pub fn multiply(&mut self, s: Sym, e: u32) {
        if e == 0 {
            return;
        }
        match self.position(&s) {
            Ok(k) => self.0[k].1 += e,
            Err(k) => self.0.insert(k, (s, e)),
        }
    }

    /// Divides by `s` once, if it is a factor.
    pub fn divide_once(&mut self, s: &Sym) {
        if let Ok(k) = self.position(s) {
            self.0[k].1 -= 1;
            if self.0[k].1 == 0 {
                self.0.remove(k);
            }
        }
    }

    /// `self · o`.
    #[must_use]
    pub fn times(&self, o: &Monomial) -> Monomial {
        let (a, b) = (&self.0, &o.0);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].0.cmp(&b[j].0) {
                Ordering::Less => {
                    out.push(a[i].clone());
                    i += 1;
                }
                Ordering::Greater => {
                    out.push(b[j].clone());
                    j += 1;
                }
                Ordering::Equal => {
                    out.push((a[i].0.clone(), a[i].1 + b[j].1));
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend_from_slice(&a[i..]);
        out.extend_from_slice(&b[j..]);
        Monomial(out)
    }

    /// The factors for which `pred` holds, and the others.
    #[must_use]
    pub fn split(self, pred: impl Fn(&Sym) -> bool) -> (Monomial, Monomial) {
        let (yes, no) = self.0.into_iter().partition(|(s, _)| pred(s));
        (Monomial(yes), Monomial(no))
    }

    /// The greatest common divisor: the symbols both have, each to the lower power.
    #[must_use]
    pub fn common(&self, o: &Monomial) -> Monomial {
        Monomial(
            self.0
                .iter()
                .filter_map(|(s, e)| match o.exponent(s) {
                    0 => None,
                    e2 => Some((s.clone(), (*e).min(e2))),
                })
                .collect(),
        )
    }

    /// Divides by `d`, which must divide it.
    pub fn divide(&mut self, d: &Monomial) {
        for (s, e) in &d.0 {
            if let Ok(k) = self.position(s) {
                self.0[k].1 -= e;
            }
        }
        self.0.retain(|(_, e)| *e > 0);
    }
}

impl FromIterator<(Sym, u32)> for Monomial {
    fn from_iter<I: IntoIterator<Item = (Sym, u32)>>(iter: I) -> Monomial {
        let mut m = Monomial::default();
        for (s, e) in iter {
            m.multiply(s, e);
        }
        m
    }
}

impl IntoIterator for Monomial {
    type Item = (Sym, u32);
    type IntoIter = std::vec::IntoIter<(Sym, u32)>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.into_iter()
    }
}

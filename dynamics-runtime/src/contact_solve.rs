//! The linear algebra of held contacts, shared by the point and the surface contacts and the
//! contact terms: `J M⁻¹ Jᵀ x = b` solved by `L D Lᵀ` on the stack, whose pivots are positive
//! exactly when the contacts are independent, and why a solve can fail.

use crate::{NotPositiveDefinite, Real};
use core::fmt;

/// Why [`crate::FloatingContacts::contact_dynamics`] has no solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ContactError {
    /// `M(q)` is not positive definite (as in `forward_dynamics`).
    NotPositiveDefinite,
    /// The contacts constrain the robot dependently: `J M⁻¹ Jᵀ` has a pivot that is not
    /// positive (two feet in contact at one point, a leg stretched so that a foot cannot move
    /// along some direction in any way, or an input is NaN).
    DependentContacts,
}

impl From<NotPositiveDefinite> for ContactError {
    fn from(_: NotPositiveDefinite) -> Self {
        Self::NotPositiveDefinite
    }
}

impl fmt::Display for ContactError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::NotPositiveDefinite => {
                "the mass matrix is not positive definite at this configuration"
            }
            Self::DependentContacts => "the contacts are not independent at this configuration",
        })
    }
}

impl core::error::Error for ContactError {}

pub(crate) fn dot<T: Real, const V: usize>(a: &[T; V], b: &[T; V]) -> T {
    a.iter().zip(b).fold(T::ZERO, |s, (&x, &y)| s + x * y)
}

/// `m x` for a symmetric `m` and an `x` of a frame's Jacobian row, which is zero at the
/// joints of the other branches: those columns skipped (half of Solo 12's).
pub(crate) fn sparse_mat_vec<T: Real, const V: usize>(m: &[[T; V]; V], x: &[T; V]) -> [T; V] {
    let mut out = [T::ZERO; V];
    for (column, &x) in m.iter().zip(x) {
        if x != T::ZERO {
            for (o, &c) in out.iter_mut().zip(column) {
                *o += c * x;
            }
        }
    }
    out
}

/// Solves the symmetric `system x = rhs` (`R` F unknowns, `R` rows per frame, index
/// `R f + i`) by `L D Lᵀ`, row by row (each row of the system, `[[T; R]; F]`, is `R` F numbers
/// in a row), on the stack; `None` where a pivot is not positive.
pub(crate) fn solve_contacts<T: Real, const R: usize, const F: usize>(
    mut system: [[[[T; R]; F]; R]; F],
    rhs: [[T; R]; F],
) -> Option<[[T; R]; F]> {
    let rows = system.as_flattened_mut();
    let mut pivots = [[T::ZERO; R]; F];
    let d = pivots.as_flattened_mut();
    // In place: row i's entries before the diagonal become L's (unit diagonal).
    for i in 0..rows.len() {
        let (done, rest) = rows.split_at_mut(i);
        let row = rest[0].as_flattened_mut();
        for (k, above) in done.iter().enumerate() {
            let above = above.as_flattened();
            let mut s = row[k];
            for ((&l, &u), &p) in row[..k].iter().zip(&above[..k]).zip(&d[..k]) {
                s -= l * u * p;
            }
            row[k] = s / d[k];
        }
        let mut pivot = row[i];
        for (&l, &p) in row[..i].iter().zip(&d[..i]) {
            pivot -= l * l * p;
        }
        if !pivot.all_positive() {
            return None;
        }
        d[i] = pivot;
    }
    let mut solution = rhs;
    let x = solution.as_flattened_mut();
    for (i, row) in rows.iter().enumerate() {
        let row = row.as_flattened();
        let s = row[..i]
            .iter()
            .zip(&x[..i])
            .fold(x[i], |s, (&l, &y)| s - l * y);
        x[i] = s;
    }
    for (y, &p) in x.iter_mut().zip(d.iter()) {
        *y = *y / p;
    }
    for i in (0..rows.len()).rev() {
        let s = rows[i + 1..]
            .iter()
            .zip(&x[i + 1..])
            .fold(x[i], |s, (row, &y)| s - row.as_flattened()[i] * y);
        x[i] = s;
    }
    Some(solution)
}

//! The error of the methods that solve with the mass matrix (`forward_dynamics`,
//! `mass_matrix_inverse`): they factor `M = L D Lᵀ` and need every pivot `d_j` positive.

use core::fmt;

/// `M(q)` is not positive definite at this configuration: a pivot of its LDLᵀ factorization is
/// zero, negative or NaN (for example where the robot's parameters leave a joint with no
/// inertia to move, or an input is NaN).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct NotPositiveDefinite;

impl fmt::Display for NotPositiveDefinite {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("the mass matrix is not positive definite at this configuration")
    }
}

impl core::error::Error for NotPositiveDefinite {}

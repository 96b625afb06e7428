//! The terms of the forward dynamics with 3-D point contacts at every frame of
//! [`FloatingKinematics`] at once, so that a call with any set of feet in contact takes the
//! block of those feet and solves it ([`ContactTerms::solve`], which
//! [`crate::FloatingContacts::contact_dynamics`] calls). With `J` the frames' linear rows in
//! world axes stacked (3 per frame) and `γ = J̇ v` their origins' classical accelerations at
//! `a = 0`:
//!
//! ```text
//! a₀ = M⁻¹ (τ − h − τ_f),   J a₀ + γ,   M⁻¹ Jᵀ,   Λ⁻¹ = J M⁻¹ Jᵀ   (3F × 3F)
//! (Λ⁻¹)_cc λ_c = −(J a₀ + γ)_c,   a = a₀ + (M⁻¹ Jᵀ)_c λ_c       (c: the frames in contact)
//! ```
//!
//! The block of `Λ⁻¹` of the frames in contact is exactly `J_c M⁻¹ J_cᵀ`. `#[derive(Dynamics)]`
//! generates [`FloatingContactTerms::contact_terms`] in closed form (through the LDLᵀ of `M`
//! factored from the tips, see `docs/floating-base.md`); the provided method computes the same
//! at run time from the generated forward dynamics, `M⁻¹` and the frames' Jacobians.

use crate::contact_solve::{dot, solve_contacts, sparse_mat_vec};
use crate::{
    ContactDynamics, ContactError, FloatingDynamics, FloatingKinematics, NotPositiveDefinite, Real,
};

/// The contact terms of every frame at once (see the module's equations); `V` coordinates, `F`
/// frames, a frame's axis `i` its row `3 f + i` of `J`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactTerms<T, const V: usize, const F: usize> {
    /// `a₀ = M⁻¹ (τ − h)`, the acceleration without contact (`forward_dynamics`').
    pub free_acceleration: [T; V],
    /// `J_f a₀ + γ_f`: each frame origin's acceleration in world axes at `a₀`.
    pub frame_accelerations: [[T; 3]; F],
    /// `M⁻¹ J_fᵀ`'s columns, `[f][i]` for axis i of frame f: the acceleration that a unit force
    /// along world axis i at frame f's origin adds.
    pub minv_jt: [[[T; V]; 3]; F],
    /// `Λ⁻¹ = J M⁻¹ Jᵀ` (the Delassus matrix, the inverse of the operational-space inertia),
    /// `[f][i][g][j]`: frame f's acceleration along axis i per unit force along axis j at frame
    /// g. Symmetric.
    pub delassus: [[[[T; 3]; F]; 3]; F],
}

impl<T: Real, const V: usize, const F: usize> ContactTerms<T, V, F> {
    /// The terms from the generated function's packed result: `free` is `[a₀; J a₀ + γ]`,
    /// `rows[3 f + i]` is `[(M⁻¹ J_{f,i}ᵀ)ᵀ, row 3 f + i of Λ⁻¹]` (`W = V + 3F`).
    #[doc(hidden)] // Called by the derive's code.
    #[must_use]
    pub fn from_packed<const W: usize>(free: &[T; W], rows: &[[T; W]]) -> Self {
        Self {
            free_acceleration: core::array::from_fn(|k| free[k]),
            frame_accelerations: core::array::from_fn(|f| {
                core::array::from_fn(|i| free[V + 3 * f + i])
            }),
            minv_jt: core::array::from_fn(|f| {
                core::array::from_fn(|i| core::array::from_fn(|k| rows[3 * f + i][k]))
            }),
            delassus: core::array::from_fn(|f| {
                core::array::from_fn(|i| {
                    core::array::from_fn(|g| {
                        core::array::from_fn(|j| rows[3 * f + i][V + 3 * g + j])
                    })
                })
            }),
        }
    }

    /// The forward dynamics with the origins of the frames where `in_contact[f]` held (see
    /// [`crate::FloatingContacts::contact_dynamics`]): the block of `Λ⁻¹` of those frames
    /// factored `L D Lᵀ` on the stack, a frame not in contact given the identity's rows and
    /// `λ_f = 0`. One set of terms serves any number of masks (a gait's candidate stances).
    ///
    /// # Errors
    ///
    /// `Err(DependentContacts)` where a pivot of the block is not positive (on lane types,
    /// where one lane's is not).
    pub fn solve(&self, in_contact: &[bool; F]) -> Result<ContactDynamics<T, V, F>, ContactError> {
        let mut system = [[[[T::ZERO; 3]; F]; 3]; F];
        let mut rhs = [[T::ZERO; 3]; F];
        for f in 0..F {
            for i in 0..3 {
                if !in_contact[f] {
                    system[f][i][f][i] = T::ONE;
                    continue;
                }
                rhs[f][i] = -self.frame_accelerations[f][i];
                for g in (0..F).filter(|&g| in_contact[g]) {
                    system[f][i][g] = self.delassus[f][i][g];
                }
            }
        }
        let forces = solve_contacts(system, rhs).ok_or(ContactError::DependentContacts)?;
        let mut acceleration = self.free_acceleration;
        for ((columns, force), &held) in self.minv_jt.iter().zip(&forces).zip(in_contact) {
            if !held {
                continue;
            }
            for (column, &lambda) in columns.iter().zip(force) {
                for (x, &c) in acceleration.iter_mut().zip(column) {
                    *x += c * lambda;
                }
            }
        }
        Ok(ContactDynamics {
            acceleration,
            forces,
        })
    }
}

/// The contact terms of the `F` frames of [`FloatingKinematics`] at `(q, v, tau)`.
/// `#[derive(Dynamics)]` implements it for every `base = floating` robot in closed form
/// (`CLOSED_FORM`); the provided method computes the same at run time from the generated
/// methods, for a robot that implements the two traits by hand.
pub trait FloatingContactTerms<const Q: usize, const V: usize, const F: usize>:
    FloatingDynamics<Q, V> + FloatingKinematics<Q, V, F>
{
    /// Whether [`Self::contact_terms`] is generated (in closed form).
    const CLOSED_FORM: bool = false;

    /// `a₀ = M⁻¹ (τ − h)`, `J a₀ + γ`, `M⁻¹ Jᵀ` and `Λ⁻¹ = J M⁻¹ Jᵀ` for every frame (see
    /// [`ContactTerms`]).
    ///
    /// # Errors
    ///
    /// `Err(NotPositiveDefinite)` as `forward_dynamics`.
    fn contact_terms<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        tau: &[T; V],
    ) -> Result<ContactTerms<T, V, F>, NotPositiveDefinite> {
        let minv = self.mass_matrix_inverse(q)?;
        let jacobians = self.frame_jacobians_world_aligned(q);
        let drifts = self.frame_acceleration_biases_world_aligned(q, v);
        // `forward_dynamics`' own: `M⁻¹ (τ − h − τ_f)`, with the joints' friction.
        let free = self.forward_dynamics(q, v, tau)?;
        let minv_jt: [[[T; V]; 3]; F] = core::array::from_fn(|f| {
            core::array::from_fn(|i| sparse_mat_vec(&minv, &jacobians[f][i]))
        });
        Ok(ContactTerms {
            free_acceleration: free,
            frame_accelerations: core::array::from_fn(|f| {
                core::array::from_fn(|i| dot(&jacobians[f][i], &free) + drifts[f][i])
            }),
            minv_jt,
            delassus: core::array::from_fn(|f| {
                core::array::from_fn(|i| {
                    core::array::from_fn(|g| {
                        core::array::from_fn(|j| dot(&jacobians[f][i], &minv_jt[g][j]))
                    })
                })
            }),
        })
    }
}

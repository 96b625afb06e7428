//! Contacts at the named frames of a robot on a free-flying base (issue 43, item 3): inverse
//! and forward dynamics with given contact wrenches, and the forward dynamics with 3-D point
//! contacts held, for every robot that has [`FloatingContactTerms`] (every `base = floating`
//! derive, whose contact terms are generated in closed form). Written once over the generated
//! methods, heap-free; see `docs/floating-base.md`.
//!
//! With `w_f` the wrench `[f, m]` that the environment exerts on the robot at frame `f`'s
//! origin, in world axes (Pinocchio's LOCAL_WORLD_ALIGNED), and `J_f` the frame's Jacobian in
//! the same axes:
//!
//! ```text
//! τ = M(q) a + h(q, v) − Σ_f J_fᵀ w_f          a = M(q)⁻¹ (τ − h(q, v) + Σ_f J_fᵀ w_f)
//! ```
//!
//! Held point contacts at the frames in contact, `J` their Jacobians' linear rows stacked
//! (3 per foot) and `γ = J̇ v` their origins' classical accelerations at `a = 0`, solve
//! Pinocchio's `constraintDynamics` (CONTACT_3D, LOCAL_WORLD_ALIGNED, no Baumgarte):
//!
//! ```text
//! [M  Jᵀ] [ a] = [τ − h]        a₀ = M⁻¹ (τ − h),   (J M⁻¹ Jᵀ) λ = −(J a₀ + γ),
//! [J  0 ] [−λ]   [ −γ  ]        a = a₀ + M⁻¹ Jᵀ λ
//! ```
//!
//! `a₀`, `J a₀ + γ`, `M⁻¹ Jᵀ` and `J M⁻¹ Jᵀ` (the inverse of the operational-space inertia,
//! 3F × 3F) come for every frame from [`FloatingContactTerms::contact_terms`]; the block of
//! the frames in contact is factored `L D Lᵀ` on the stack; its pivots are positive exactly
//! when the contacts are independent (J of full row rank).

use crate::{
    ConstrainedDynamics, Contact, ContactError, FloatingContactTerms, NotPositiveDefinite, Real,
};

/// The forward dynamics with point contacts held: the acceleration and the contact forces.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactDynamics<T, const V: usize, const F: usize> {
    /// `a`, as `FloatingDynamics::forward_dynamics`' (the base's in its own frame).
    pub acceleration: [T; V],
    /// `λ_f`: the force that the ground exerts on the robot at frame `f`'s origin, in world
    /// axes (Pinocchio's `lambda_c` in LOCAL_WORLD_ALIGNED); zero for a frame not in contact.
    pub forces: [[T; 3]; F],
}

/// Contact wrenches, forces and held point contacts at the `F` frames of
/// [`FloatingKinematics`](crate::FloatingKinematics) (`tips = [..]`, else the leaf links: a quadruped's feet), indexed as
/// its results (`Robot::FRAME_FL_FOOT`). Implemented for every robot with
/// [`FloatingContactTerms`]; not generated (written once over its methods and those of
/// `FloatingDynamics` and `FloatingKinematics`).
///
/// Every wrench or force here is the one the **environment exerts on the robot**, at the
/// frame's origin, in **world axes** (Pinocchio's LOCAL_WORLD_ALIGNED): a standing foot
/// pushed up by the ground has `f_z > 0`. A wrench is `[f_x, f_y, f_z, m_x, m_y, m_z]`, its
/// moment about the frame's origin.
pub trait FloatingContacts<const Q: usize, const V: usize, const F: usize>:
    FloatingContactTerms<Q, V, F>
{
    /// `τ = M(q) a + h(q, v) − Σ_f J_fᵀ w_f`: the generalized forces that give `a` while the
    /// environment exerts the wrench `wrenches[f]` at frame `f` (Pinocchio's `rnea` with
    /// `fext`). The base's six rows are what is left for other contacts to supply (zero where
    /// the wrenches hold the robot).
    fn inverse_dynamics_with_wrenches<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        a: &[T; V],
        wrenches: &[[T; 6]; F],
    ) -> [T; V] {
        let mut tau = self.inverse_dynamics(q, v, a);
        let generalized = wrenches_to_generalized(&self.frame_jacobians_world_aligned(q), wrenches);
        for (t, w) in tau.iter_mut().zip(generalized) {
            *t -= w;
        }
        tau
    }

    /// As [`Self::inverse_dynamics_with_wrenches`] with point forces `forces[f]` at the
    /// frames' origins (no moments).
    fn inverse_dynamics_with_forces<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        a: &[T; V],
        forces: &[[T; 3]; F],
    ) -> [T; V] {
        self.inverse_dynamics_with_wrenches(q, v, a, &point_wrenches(forces))
    }

    /// `a = M(q)⁻¹ (τ − h(q, v) + Σ_f J_fᵀ w_f)` (Pinocchio's `aba` with `fext`), the inverse of
    /// [`Self::inverse_dynamics_with_wrenches`]. `Err(NotPositiveDefinite)` as
    /// `forward_dynamics`.
    fn forward_dynamics_with_wrenches<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        tau: &[T; V],
        wrenches: &[[T; 6]; F],
    ) -> Result<[T; V], NotPositiveDefinite> {
        let mut total = *tau;
        let generalized = wrenches_to_generalized(&self.frame_jacobians_world_aligned(q), wrenches);
        for (t, w) in total.iter_mut().zip(generalized) {
            *t += w;
        }
        self.forward_dynamics(q, v, &total)
    }

    /// As [`Self::forward_dynamics_with_wrenches`] with point forces at the frames' origins.
    fn forward_dynamics_with_forces<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        tau: &[T; V],
        forces: &[[T; 3]; F],
    ) -> Result<[T; V], NotPositiveDefinite> {
        self.forward_dynamics_with_wrenches(q, v, tau, &point_wrenches(forces))
    }

    /// The forward dynamics with the origins of the frames where `in_contact[f]` held fixed
    /// in the world (3-D point contacts, no friction limit): the acceleration and the contact
    /// forces of Pinocchio's `constraintDynamics` with a `RigidConstraintModel` CONTACT_3D in
    /// LOCAL_WORLD_ALIGNED at each such frame and no Baumgarte correction (see the module's
    /// equations). The contacts change from call to call with the mask (a gait's stance
    /// feet); a frame not in contact moves freely and has a zero force. No foot in contact
    /// gives `forward_dynamics`' acceleration.
    ///
    /// `Err(NotPositiveDefinite)` as `forward_dynamics`, `Err(DependentContacts)` where
    /// `J M⁻¹ Jᵀ` is singular (on lane types, where one lane's is).
    fn contact_dynamics<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        tau: &[T; V],
        in_contact: &[bool; F],
    ) -> Result<ContactDynamics<T, V, F>, ContactError> {
        self.contact_terms(q, v, tau)?.solve(in_contact)
    }

    /// The forward dynamics with each frame held as `contacts[f]` says: a 3-D point contact
    /// (its origin held, Pinocchio's CONTACT_3D), a 6-D surface contact (its pose held, a flat
    /// foot: CONTACT_6D), or free; the acceleration and the contact wrenches of Pinocchio's
    /// `constraintDynamics` with those `RigidConstraintModel`s in LOCAL_WORLD_ALIGNED and no
    /// Baumgarte correction (a surface's drift its spatial acceleration, see
    /// `docs/floating-base.md`). Computed at run time from the generated methods (the point
    /// contacts alone: [`Self::contact_dynamics`], in closed form).
    ///
    /// `Err(NotPositiveDefinite)` as `forward_dynamics`, `Err(DependentContacts)` where a
    /// pivot of the rows held is not positive (they are not independent: Solo 12's legs of
    /// three joints cannot hold three feet flat).
    fn constrained_dynamics<T: Real>(
        &self,
        q: &[T; Q],
        v: &[T; V],
        tau: &[T; V],
        contacts: &[Contact; F],
    ) -> Result<ConstrainedDynamics<T, V, F>, ContactError> {
        crate::floating_surface_contacts::constrained_dynamics(self, q, v, tau, contacts)
    }
}

impl<R, const Q: usize, const V: usize, const F: usize> FloatingContacts<Q, V, F> for R where
    R: FloatingContactTerms<Q, V, F>
{
}

/// `Σ_f J_fᵀ w_f`.
fn wrenches_to_generalized<T: Real, const V: usize, const F: usize>(
    jacobians: &[[[T; V]; 6]; F],
    wrenches: &[[T; 6]; F],
) -> [T; V] {
    let mut out = [T::ZERO; V];
    for (jacobian, wrench) in jacobians.iter().zip(wrenches) {
        for (row, &w) in jacobian.iter().zip(wrench) {
            for (o, &j) in out.iter_mut().zip(row) {
                *o += j * w;
            }
        }
    }
    out
}

fn point_wrenches<T: Real, const F: usize>(forces: &[[T; 3]; F]) -> [[T; 6]; F] {
    forces.map(|[x, y, z]| [x, y, z, T::ZERO, T::ZERO, T::ZERO])
}

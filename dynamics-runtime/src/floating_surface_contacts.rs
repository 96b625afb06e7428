//! The forward dynamics with contacts of two kinds held at the frames of
//! [`FloatingKinematics`](crate::FloatingKinematics), per frame: a 3-D point contact (the
//! frame's origin held, Pinocchio's CONTACT_3D) or a 6-D surface contact (the frame's pose
//! held, a flat foot: Pinocchio's CONTACT_6D), both in LOCAL_WORLD_ALIGNED, no Baumgarte. With
//! `J` the rows held (a point's three linear rows of the frame's Jacobian in world axes, a
//! surface's six) and `γ` their accelerations at `a = 0`:
//!
//! ```text
//! [M  Jᵀ] [ a] = [τ − h − τ_f]      a₀ = forward_dynamics(q, v, τ),   (J M⁻¹ Jᵀ) λ = −(J a₀ + γ),
//! [J  0 ] [−λ]   [    −γ     ]      a = a₀ + M⁻¹ Jᵀ λ
//! ```
//!
//! `γ` is, at a point, its origin's classical acceleration (`J̇ v`, as
//! [`ContactTerms`](crate::ContactTerms)' `γ`); on a surface, the frame's spatial acceleration
//! at its origin in world axes, `[c − ω × v_o, α]` from the classical `[c, α]`, `v_o` and `ω`
//! its origin's and its angular velocity (`J v`): holding the pose holds the frame's twist at
//! zero, whose derivative is the spatial acceleration (Pinocchio's `getFrameAcceleration`, as
//! its `constraintDynamics` writes CONTACT_6D; the two agree where the frame is at rest). Its
//! `λ` is a wrench `[f, m]` on the robot at the frame's origin in world axes. Computed at run
//! time from the generated `M⁻¹`, forward dynamics, Jacobians and `J̇ v` (the 6F × 6F block of
//! the frames held, `L D Lᵀ` on the stack).

use crate::contact_solve::{dot, solve_contacts, sparse_mat_vec};
use crate::{ContactError, FloatingContactTerms, Real};

/// How a frame is held in [`crate::FloatingContacts::constrained_dynamics`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Contact {
    /// Not held: it moves freely; its wrench is zero.
    #[default]
    Free,
    /// A 3-D point contact (Pinocchio's CONTACT_3D): the frame's origin held, the frame free to
    /// turn about it; its wrench a force, the moment zero.
    Point,
    /// A 6-D surface contact (Pinocchio's CONTACT_6D): the frame's pose held, a foot flat on the
    /// ground; its wrench a force and a moment about the frame's origin.
    Surface,
}

impl Contact {
    /// Whether row `r` of the frame's six (`[linear, angular]`) is held.
    fn holds(self, r: usize) -> bool {
        match self {
            Self::Free => false,
            Self::Point => r < 3,
            Self::Surface => true,
        }
    }
}

/// The forward dynamics with point and surface contacts held: the acceleration and the
/// contact wrenches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConstrainedDynamics<T, const V: usize, const F: usize> {
    /// `a`, as `FloatingDynamics::forward_dynamics`' (the base's in its own frame).
    pub acceleration: [T; V],
    /// The wrench `[f, m]` that the ground exerts on the robot at frame `f`'s origin, in world
    /// axes, its moment about that origin (Pinocchio's `lambda_c` in LOCAL_WORLD_ALIGNED): a
    /// surface contact's force and moment, a point contact's force (its moment zero), zero at a
    /// frame not held.
    pub wrenches: [[T; 6]; F],
}

/// [`crate::FloatingContacts::constrained_dynamics`] (see the module's equations).
pub(crate) fn constrained_dynamics<R, T, const Q: usize, const V: usize, const F: usize>(
    robot: &R,
    q: &[T; Q],
    v: &[T; V],
    tau: &[T; V],
    contacts: &[Contact; F],
) -> Result<ConstrainedDynamics<T, V, F>, ContactError>
where
    R: FloatingContactTerms<Q, V, F> + ?Sized,
    T: Real,
{
    let free = robot.forward_dynamics(q, v, tau)?;
    let minv = robot.mass_matrix_inverse(q)?;
    let jacobians = robot.frame_jacobians_world_aligned(q);
    let classical = robot.frame_acceleration_biases_world_aligned(q, v);
    // `M⁻¹ Jᵀ`'s column of each row held; zero elsewhere (unread).
    let mut minv_jt = [[[T::ZERO; V]; 6]; F];
    for ((columns, rows), &contact) in minv_jt.iter_mut().zip(&jacobians).zip(contacts) {
        for (r, (column, row)) in columns.iter_mut().zip(rows).enumerate() {
            if contact.holds(r) {
                *column = sparse_mat_vec(&minv, row);
            }
        }
    }
    let mut system = [[[[T::ZERO; 6]; F]; 6]; F];
    let mut rhs = [[T::ZERO; 6]; F];
    for f in 0..F {
        let drift = drift(contacts[f], &jacobians[f], &classical[f], v);
        for r in 0..6 {
            if !contacts[f].holds(r) {
                system[f][r][f][r] = T::ONE;
                continue;
            }
            rhs[f][r] = -(dot(&jacobians[f][r], &free) + drift[r]);
            for g in 0..F {
                for s in (0..6).filter(|&s| contacts[g].holds(s)) {
                    system[f][r][g][s] = dot(&jacobians[f][r], &minv_jt[g][s]);
                }
            }
        }
    }
    let wrenches = solve_contacts(system, rhs).ok_or(ContactError::DependentContacts)?;
    let mut acceleration = free;
    for ((columns, wrench), &contact) in minv_jt.iter().zip(&wrenches).zip(contacts) {
        for (r, (column, &lambda)) in columns.iter().zip(wrench).enumerate() {
            if contact.holds(r) {
                for (x, &c) in acceleration.iter_mut().zip(column) {
                    *x += c * lambda;
                }
            }
        }
    }
    Ok(ConstrainedDynamics {
        acceleration,
        wrenches,
    })
}

/// `γ` of a frame held as `contact`: the classical `[c, α]` at a point, `[c − ω × v_o, α]` on a
/// surface (`[v_o, ω] = J v`).
fn drift<T: Real, const V: usize>(
    contact: Contact,
    jacobian: &[[T; V]; 6],
    classical: &[T; 6],
    v: &[T; V],
) -> [T; 6] {
    if contact != Contact::Surface {
        return *classical;
    }
    let twist: [T; 6] = core::array::from_fn(|r| dot(&jacobian[r], v));
    let (o, w) = (
        [twist[0], twist[1], twist[2]],
        [twist[3], twist[4], twist[5]],
    );
    let w_cross_o = [
        w[1] * o[2] - w[2] * o[1],
        w[2] * o[0] - w[0] * o[2],
        w[0] * o[1] - w[1] * o[0],
    ];
    core::array::from_fn(|r| {
        if r < 3 {
            classical[r] - w_cross_o[r]
        } else {
            classical[r]
        }
    })
}

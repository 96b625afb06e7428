//! Statics with numbers given at run time (Niku, ch. 6.7): the joint torques that hold a
//! wrench, `T = Jᵀ F` (eq. 6.64), and a wrench moved to another frame (eq. 6.73).
//!
//! A wrench is `[fx, fy, fz, mx, my, mz]`, a Jacobian's rows are `[dx, dy, dz, δx, δy, δz]`
//! (eq. 6.58), both in the same frame. A frame B is the 4×4 homogeneous transform
//! `[n o a p; 0 0 0 1]` that places it in the reference frame.

use crate::Real;

/// The joint torques (revolute joints) and forces (prismatic joints) that hold `wrench`,
/// `T = Jᵀ F` (eq. 6.64), for a `jacobian` given by its 6 rows `[dx, dy, dz, δx, δy, δz]`.
#[must_use]
pub fn joint_torques<T: Real, const N: usize>(jacobian: &[[T; N]; 6], wrench: &[T; 6]) -> [T; N] {
    core::array::from_fn(|j| {
        (1..6).fold(jacobian[0][j] * wrench[0], |sum, i| {
            jacobian[i][j].mul_add(wrench[i], sum)
        })
    })
}

/// The wrench in frame `b` equivalent to `wrench` given in the reference frame (eq. 6.73):
/// `ᴮf = [n·f, o·f, a·f]`, `ᴮm = [n·(f × p + m), o·(f × p + m), a·(f × p + m)]`, where
/// `n`, `o`, `a` are the columns of `b`'s rotation and `p` its position. Both wrenches do the
/// same virtual work (eq. 6.69).
#[must_use]
pub fn wrench_in_frame<T: Real>(b: &[[T; 4]; 4], wrench: &[T; 6]) -> [T; 6] {
    let [fx, fy, fz, mx, my, mz] = *wrench;
    let [px, py, pz] = [b[0][3], b[1][3], b[2][3]];
    // f × p + m: the moment about B's origin.
    let moment = [
        fy.mul_add(pz, (-fz).mul_add(py, mx)),
        fz.mul_add(px, (-fx).mul_add(pz, my)),
        fx.mul_add(py, (-fy).mul_add(px, mz)),
    ];
    // The component along column `k` of the rotation: `b[.][k] · v`.
    let along = |k: usize, v: [T; 3]| b[0][k].mul_add(v[0], b[1][k].mul_add(v[1], b[2][k] * v[2]));
    [
        along(0, [fx, fy, fz]),
        along(1, [fx, fy, fz]),
        along(2, [fx, fy, fz]),
        along(0, moment),
        along(1, moment),
        along(2, moment),
    ]
}

//! Static force analysis (Niku, section "Static Force Analysis of Robots" and
//! "Transformation of Forces and Moments between Coordinate Frames").
//!
//! A wrench is `[fx, fy, fz, mx, my, mz]`: force then moment, as in eqs. (6.57), (6.65).

use nalgebra::{DMatrix, DVector, Matrix4, Vector3, Vector6};

/// Joint torques/forces that balance a wrench at the hand: `T = Jᵀ F` (eq. 6.64).
///
/// The Jacobian and the wrench must be expressed in the same frame (Niku uses the hand
/// frame, `ᴴJ` and `ᴴF`; the base-frame Jacobian of [`crate::Robot::jacobian`] goes with a
/// base-frame wrench). Rows of the Jacobian are `[dx, dy, dz, δx, δy, δz]`, matching the
/// order of the wrench.
///
/// # Panics
///
/// If `jacobian` does not have 6 rows.
pub fn joint_forces(jacobian: &DMatrix<f64>, wrench: [f64; 6]) -> DVector<f64> {
    assert_eq!(
        jacobian.nrows(),
        6,
        "a Jacobian for a wrench must have 6 rows, got {}",
        jacobian.nrows()
    );
    jacobian.transpose() * DVector::from_row_slice(&wrench)
}

/// The force and moment in frame `B` equivalent to a wrench given in the reference frame
/// (eq. 6.73):
///
/// ```text
/// ᴮfx = n·f      ᴮmx = n·(f × P + m)
/// ᴮfy = o·f      ᴮmy = o·(f × P + m)
/// ᴮfz = a·f      ᴮmz = a·(f × P + m)
/// ```
///
/// where `n`, `o`, `a`, `P` are the columns of `frame` (the pose of `B` in the reference
/// frame), `f`, `m` the force and moment of `wrench` (acting at the reference origin,
/// in reference axes). `f × P + m` is the moment of the same loads about the origin
/// of `B`.
pub fn equivalent_wrench(frame: &Matrix4<f64>, wrench: [f64; 6]) -> [f64; 6] {
    let column = |c: usize| Vector3::new(frame[(0, c)], frame[(1, c)], frame[(2, c)]);
    let (n, o, a, p) = (column(0), column(1), column(2), column(3));
    let f = Vector3::new(wrench[0], wrench[1], wrench[2]);
    let m = Vector3::new(wrench[3], wrench[4], wrench[5]);
    let moment = f.cross(&p) + m;
    let b = Vector6::new(
        n.dot(&f),
        o.dot(&f),
        a.dot(&f),
        n.dot(&moment),
        o.dot(&moment),
        a.dot(&moment),
    );
    b.into()
}

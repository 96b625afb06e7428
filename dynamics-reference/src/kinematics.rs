//! Link matrices, their derivatives, the `U_ij`/`U_ijk` matrices and the Jacobian
//! (Niku eqs. 6.21–6.29), along the path from the base to each link of a tree.

use nalgebra::{DMatrix, Matrix3, Matrix4, Vector3};

use crate::robot::{Convention, JointKind, Placement, Robot};

/// Rotation about x by `angle`: the book's `Rot(x, angle)` as a 4×4 homogeneous matrix.
pub fn rot_x(angle: f64) -> Matrix4<f64> {
    let (s, c) = angle.sin_cos();
    #[rustfmt::skip]
    let m = Matrix4::new(
        1.0, 0.0, 0.0, 0.0,
        0.0, c,   -s,  0.0,
        0.0, s,   c,   0.0,
        0.0, 0.0, 0.0, 1.0,
    );
    m
}

/// Rotation about z by `angle`: the book's `Rot(z, angle)` as a 4×4 homogeneous matrix.
pub fn rot_z(angle: f64) -> Matrix4<f64> {
    let (s, c) = angle.sin_cos();
    #[rustfmt::skip]
    let m = Matrix4::new(
        c,   -s,  0.0, 0.0,
        s,   c,   0.0, 0.0,
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
    );
    m
}

/// Translation by `dist` along x: the book's `Trans(dist, 0, 0)`.
pub fn trans_x(dist: f64) -> Matrix4<f64> {
    let mut m = Matrix4::identity();
    m[(0, 3)] = dist;
    m
}

/// Translation by `dist` along z: the book's `Trans(0, 0, dist)`.
pub fn trans_z(dist: f64) -> Matrix4<f64> {
    let mut m = Matrix4::identity();
    m[(2, 3)] = dist;
    m
}

/// The constant matrix `Q_i` of eq. (6.27), with `∂A_i/∂q_i = Q_i A_i` (eqs. 6.23, 6.26)
/// for the standard convention.
///
/// Revolute: `Q[0][1] = −1`, `Q[1][0] = 1`; prismatic: `Q[2][3] = 1`; all other entries 0.
pub fn q_matrix(kind: JointKind) -> Matrix4<f64> {
    let mut q = Matrix4::zeros();
    match kind {
        JointKind::Revolute => {
            q[(0, 1)] = -1.0;
            q[(1, 0)] = 1.0;
        }
        JointKind::Prismatic => {
            q[(2, 3)] = 1.0;
        }
    }
    q
}

/// `[k]×`, the cross-product matrix of `k`.
fn skew(k: &[f64; 3]) -> Matrix3<f64> {
    Matrix3::new(0.0, -k[2], k[1], k[2], 0.0, -k[0], -k[1], k[0], 0.0)
}

/// `Q` of a URDF-style joint, the generator of its motion about or along the unit `axis`:
/// revolute `[[ [axis]×, 0 ], [0, 0]]`, prismatic `[[0, axis], [0, 0]]`. With `axis = z` it is
/// the book's `Q` of eq. (6.27).
pub fn axis_q_matrix(kind: JointKind, axis: &[f64; 3]) -> Matrix4<f64> {
    let mut q = Matrix4::zeros();
    match kind {
        JointKind::Revolute => q.fixed_view_mut::<3, 3>(0, 0).copy_from(&skew(axis)),
        JointKind::Prismatic => {
            for r in 0..3 {
                q[(r, 3)] = axis[r];
            }
        }
    }
    q
}

/// The motion of a URDF-style joint: `Rot(axis, q)` (Rodrigues: `1 + sin q [k]× + (1 − cos q)
/// [k]×²`) or `Trans(axis q)`.
pub fn axis_motion(kind: JointKind, axis: &[f64; 3], q: f64) -> Matrix4<f64> {
    let mut m = Matrix4::identity();
    match kind {
        JointKind::Revolute => {
            let k = skew(axis);
            let r = Matrix3::identity() + k * q.sin() + k * k * (1.0 - q.cos());
            m.fixed_view_mut::<3, 3>(0, 0).copy_from(&r);
        }
        JointKind::Prismatic => {
            for r in 0..3 {
                m[(r, 3)] = axis[r] * q;
            }
        }
    }
    m
}

/// The placement `X` of a URDF-style joint as a 4×4 homogeneous matrix.
pub fn placement_matrix(placement: &Placement) -> Matrix4<f64> {
    let mut m = Matrix4::identity();
    for r in 0..3 {
        for c in 0..3 {
            m[(r, c)] = placement.rotation[r][c];
        }
        m[(r, 3)] = placement.xyz[r];
    }
    m
}

impl Robot {
    /// The three factors of `A_i = pre · Z(q_i) · post`, where `Z` holds the joint motion,
    /// `Rotz(θ_i) Transz(d_i)` in a D-H table, in the antecedent's frame:
    ///
    /// * standard: `pre = 1`, `post = Transx(a_i) Rotx(α_i)`;
    /// * modified: `pre = Rotz(γ_i) Transz(b_i) Rotx(α_{i−1}) Transx(a_{i−1})`, `post = 1`
    ///   (`γ = b = 0` in a chain);
    /// * URDF style: `pre = X_i`, `Z = Rot(axis_i, q_i)` or `Trans(axis_i q_i)`, `post = 1`.
    ///
    /// # Panics
    ///
    /// If joint `i` is not valid (see [`Robot::check`]).
    fn link_factors(&self, i: usize, q_i: f64) -> (Matrix4<f64>, Matrix4<f64>, Matrix4<f64>) {
        if let Err(e) = self.check_joint(i) {
            panic!("robot {:?}: {e}", self.name);
        }
        let joint = &self.joints[i];
        if let Some(p) = &joint.placement {
            let z = axis_motion(joint.kind, &p.axis, q_i);
            return (placement_matrix(p), z, Matrix4::identity());
        }
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (q_i + joint.theta, joint.d),
            JointKind::Prismatic => (joint.theta, q_i + joint.d),
        };
        let z = rot_z(theta) * trans_z(d);
        let x = rot_z(joint.gamma) * trans_z(joint.b) * rot_x(joint.alpha) * trans_x(joint.a);
        let x_std = trans_x(joint.a) * rot_x(joint.alpha);
        match self.convention {
            Convention::Standard => (Matrix4::identity(), z, x_std),
            Convention::Modified | Convention::Urdf => (x, z, Matrix4::identity()),
        }
    }

    /// `Q_i` of joint `i`: the book's (eq. 6.27) for a D-H row, [`axis_q_matrix`] for a
    /// URDF-style joint.
    fn joint_q_matrix(&self, i: usize) -> Matrix4<f64> {
        let joint = &self.joints[i];
        match &joint.placement {
            Some(p) => axis_q_matrix(joint.kind, &p.axis),
            None => q_matrix(joint.kind),
        }
    }

    /// `∂^order A_i / ∂q_i^order = pre · Q_i^order · Z(q_i) · post`.
    ///
    /// `Q_i` generates the motion of `Z = Rotz(θ) Transz(d)`: `d/dθ Rotz(θ) = Q Rotz(θ)`
    /// (so every further derivative multiplies by `Q` again), and for a prismatic joint
    /// `d/dd Transz(d) = Q` with `Q² = 0`. `Q_i` commutes with both `Rotz` and `Transz`,
    /// so it may be placed right before `Z`. For the standard convention, `pre = 1` and
    /// this is the book's `Q_i A_i` (eqs. 6.23, 6.26). The same holds of a URDF-style joint's
    /// `Z = exp(q Q)` about or along its axis.
    fn link_transform_nth_derivative(&self, i: usize, q_i: f64, order: usize) -> Matrix4<f64> {
        let (pre, z, post) = self.link_factors(i, q_i);
        let q = self.joint_q_matrix(i);
        let mut m = pre;
        for _ in 0..order {
            m *= q;
        }
        m * z * post
    }

    /// The link matrix `A_i` (0-based `i`, the book's `A_{i+1}`) at joint value `q_i`:
    /// the book's eq. (2.53), the matrix that eq. (6.21) differentiates, for the
    /// standard convention; Craig's form for the modified one (see [`Convention`]).
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn link_transform(&self, i: usize, q_i: f64) -> Matrix4<f64> {
        let (pre, z, post) = self.link_factors(i, q_i);
        pre * z * post
    }

    /// `∂A_i/∂q_i` (0-based `i`). Standard convention: `Q_i A_i` (eqs. 6.23, 6.26, 6.27).
    /// Modified convention: `Rotx(α) Transx(a) · Q_i · Rotz(θ_i) Transz(d_i)`, because
    /// there the joint motion is the *last* factor of `A_i`, so `Q_i A_i` would be wrong.
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn link_transform_derivative(&self, i: usize, q_i: f64) -> Matrix4<f64> {
        self.link_transform_nth_derivative(i, q_i, 1)
    }

    /// Product of the `A_l` along the path from the base to link `i` ([`Robot::path`]), in
    /// which factor `l` is differentiated as many times as `l` occurs in `wrt`. Indices in
    /// `wrt` off the path (not `i` nor an ancestor of `i`) give the zero matrix.
    fn chain_derivative(&self, q: &[f64], i: usize, wrt: &[usize]) -> Matrix4<f64> {
        self.check_len("q", q);
        assert!(
            i < self.dof(),
            "frame index {i} out of range for {} joints",
            self.dof()
        );
        let path = self.path(i);
        if wrt.iter().any(|j| !path.contains(j)) {
            return Matrix4::zeros();
        }
        let mut t = Matrix4::identity();
        for l in path {
            let order = wrt.iter().filter(|&&j| j == l).count();
            t *= self.link_transform_nth_derivative(l, q[l], order);
        }
        t
    }

    /// `⁰T_i = ⁰T_{a(i)} A_i`, the product of the `A_l` along the path from the base to link
    /// `i` (eq. 6.20 in a chain, `A_0 A_1 ⋯ A_i`; 0-based: the book's `⁰T_{i+1} = A_1 ⋯
    /// A_{i+1}`), the pose of link frame `i` in the base frame.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn frame(&self, q: &[f64], i: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[])
    }

    /// `U_ij = ∂ ⁰T_i/∂q_j = A_0 ⋯ A_{j−1} (∂A_j/∂q_j) A_{j+1} ⋯ A_i` (the `A`s along the
    /// path to link `i`) when `j` is `i` or an ancestor of `i`, and zero otherwise (in a chain,
    /// for `j > i`; eq. 6.28; with the standard convention `∂A_j/∂q_j = Q_j A_j`).
    /// 0-based: `u(q, 4, 1)` is the book's `U_52`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn u(&self, q: &[f64], i: usize, j: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[j])
    }

    /// `U_ijk = ∂U_ij/∂q_k` (eq. 6.29): the product of the `A`s up to `i` with factor `j`
    /// and factor `k` differentiated (factor `j` twice if `j = k`); zero unless `j` and `k`
    /// are both `i` or ancestors of `i`. Symmetric in `j`, `k`. 0-based: `u2(q, 5, 2, 4)` is the book's `U_635`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn u2(&self, q: &[f64], i: usize, j: usize, k: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[j, k])
    }

    /// Pose of the last D-H frame: `⁰T_n = A_1 ⋯ A_n` (eq. 2.55 of the book), the last
    /// joint's link frame in a tree. There is no tool transform. Returns the identity for a
    /// robot without joints.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn forward_kinematics(&self, q: &[f64]) -> Matrix4<f64> {
        self.check_len("q", q);
        match self.dof() {
            0 => Matrix4::identity(),
            n => self.frame(q, n - 1),
        }
    }

    /// Geometric Jacobian (6×n) of the origin of the last frame ([`Robot::forward_kinematics`]):
    /// [`Robot::frame_jacobian`] of link `n − 1` with no offset; empty for a robot without
    /// joints.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn jacobian(&self, q: &[f64]) -> DMatrix<f64> {
        self.check_len("q", q);
        match self.dof() {
            0 => DMatrix::zeros(6, 0),
            n => self.frame_jacobian(q, n - 1, &Matrix4::identity()),
        }
    }

    /// Geometric Jacobian (6×n) of a frame fixed on link `i`, `⁰T_i · offset`, in base-frame
    /// axes, rows `[v_x, v_y, v_z, ω_x, ω_y, ω_z]`, computed from `U_ij = ∂ ⁰T_i/∂q_j`
    /// (eq. 6.28):
    ///
    /// * linear part: the position column of `U_ij · offset` (the derivative of the frame's
    ///   origin);
    /// * angular part: `∂R/∂q_j = [ω_j]× R`, so `[ω_j]× = (∂R/∂q_j) Rᵀ`, whose skew part
    ///   gives `ω_j` (zero for a prismatic joint).
    ///
    /// Column `j` is zero unless joint `j` is `i` or an ancestor of `i`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn frame_jacobian(&self, q: &[f64], i: usize, offset: &Matrix4<f64>) -> DMatrix<f64> {
        let n = self.dof();
        let mut jac = DMatrix::zeros(6, n);
        let t = self.frame(q, i) * offset;
        let r: Matrix3<f64> = t.fixed_view::<3, 3>(0, 0).into_owned();
        for j in 0..n {
            let u = self.u(q, i, j) * offset;
            let dr: Matrix3<f64> = u.fixed_view::<3, 3>(0, 0).into_owned();
            let w = dr * r.transpose();
            let omega = Vector3::new(
                0.5 * (w[(2, 1)] - w[(1, 2)]),
                0.5 * (w[(0, 2)] - w[(2, 0)]),
                0.5 * (w[(1, 0)] - w[(0, 1)]),
            );
            for row in 0..3 {
                jac[(row, j)] = u[(row, 3)];
                jac[(row + 3, j)] = omega[row];
            }
        }
        jac
    }
}

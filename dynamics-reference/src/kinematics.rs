//! Link matrices, their derivatives, the `U_ij`/`U_ijk` matrices and the Jacobian
//! (Niku eqs. 6.21–6.29).

use nalgebra::{DMatrix, Matrix3, Matrix4, Vector3};

use crate::robot::{Convention, JointKind, Robot};

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

impl Robot {
    /// The three factors of `A_i = pre · Z(q_i) · post`, where `Z = Rotz(θ_i) Transz(d_i)`
    /// holds the joint motion:
    ///
    /// * standard: `pre = 1`, `post = Transx(a_i) Rotx(α_i)`;
    /// * modified: `pre = Rotx(α_{i−1}) Transx(a_{i−1})`, `post = 1`.
    fn link_factors(&self, i: usize, q_i: f64) -> (Matrix4<f64>, Matrix4<f64>, Matrix4<f64>) {
        let joint = &self.joints[i];
        let (theta, d) = match joint.kind {
            JointKind::Revolute => (q_i + joint.theta, joint.d),
            JointKind::Prismatic => (joint.theta, q_i + joint.d),
        };
        let z = rot_z(theta) * trans_z(d);
        let x = rot_x(joint.alpha) * trans_x(joint.a);
        let x_std = trans_x(joint.a) * rot_x(joint.alpha);
        match self.convention {
            Convention::Standard => (Matrix4::identity(), z, x_std),
            Convention::Modified => (x, z, Matrix4::identity()),
        }
    }

    /// `∂^order A_i / ∂q_i^order = pre · Q_i^order · Z(q_i) · post`.
    ///
    /// `Q_i` generates the motion of `Z = Rotz(θ) Transz(d)`: `d/dθ Rotz(θ) = Q Rotz(θ)`
    /// (so every further derivative multiplies by `Q` again), and for a prismatic joint
    /// `d/dd Transz(d) = Q` with `Q² = 0`. `Q_i` commutes with both `Rotz` and `Transz`,
    /// so it may be placed right before `Z`. For the standard convention, `pre = 1` and
    /// this is the book's `Q_i A_i` (eqs. 6.23, 6.26).
    fn link_transform_nth_derivative(&self, i: usize, q_i: f64, order: usize) -> Matrix4<f64> {
        let (pre, z, post) = self.link_factors(i, q_i);
        let q = q_matrix(self.joints[i].kind);
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

    /// Product `A_0 ⋯ A_i` in which factor `l` is differentiated as many times as `l`
    /// occurs in `wrt`. Indices in `wrt` larger than `i` give the zero matrix.
    fn chain_derivative(&self, q: &[f64], i: usize, wrt: &[usize]) -> Matrix4<f64> {
        self.check_len("q", q);
        assert!(
            i < self.dof(),
            "frame index {i} out of range for {} joints",
            self.dof()
        );
        if wrt.iter().any(|&j| j > i) {
            return Matrix4::zeros();
        }
        let mut t = Matrix4::identity();
        for (l, &q_l) in q.iter().enumerate().take(i + 1) {
            let order = wrt.iter().filter(|&&j| j == l).count();
            t *= self.link_transform_nth_derivative(l, q_l, order);
        }
        t
    }

    /// `⁰T_i = A_0 A_1 ⋯ A_i` (eq. 6.20; 0-based: the book's `⁰T_{i+1} = A_1 ⋯ A_{i+1}`),
    /// the pose of link frame `i` in the base frame.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn frame(&self, q: &[f64], i: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[])
    }

    /// `U_ij = ∂ ⁰T_i/∂q_j = A_0 ⋯ A_{j−1} (∂A_j/∂q_j) A_{j+1} ⋯ A_i` for `j ≤ i`, and zero
    /// for `j > i` (eq. 6.28; with the standard convention `∂A_j/∂q_j = Q_j A_j`).
    /// 0-based: `u(q, 4, 1)` is the book's `U_52`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn u(&self, q: &[f64], i: usize, j: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[j])
    }

    /// `U_ijk = ∂U_ij/∂q_k` (eq. 6.29): the product of the `A`s up to `i` with factor `j`
    /// and factor `k` differentiated (factor `j` twice if `j = k`); zero if `j > i` or
    /// `k > i`. Symmetric in `j`, `k`. 0-based: `u2(q, 5, 2, 4)` is the book's `U_635`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()` or `i >= self.dof()`.
    pub fn u2(&self, q: &[f64], i: usize, j: usize, k: usize) -> Matrix4<f64> {
        self.chain_derivative(q, i, &[j, k])
    }

    /// Pose of the last D-H frame: `⁰T_n = A_1 ⋯ A_n` (eq. 2.55 of the book). There is no
    /// tool transform. Returns the identity for a robot without joints.
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

    /// Geometric Jacobian (6×n) of the origin of the last frame, in base-frame axes, rows
    /// `[v_x, v_y, v_z, ω_x, ω_y, ω_z]`, computed from `U_nj = ∂ ⁰T_n/∂q_j` (eq. 6.28):
    ///
    /// * linear part: the position column of `U_nj` (the derivative of the origin);
    /// * angular part: `∂R/∂q_j = [ω_j]× R`, so `[ω_j]× = (∂R/∂q_j) Rᵀ`, whose skew part
    ///   gives `ω_j` (zero for a prismatic joint).
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn jacobian(&self, q: &[f64]) -> DMatrix<f64> {
        let n = self.dof();
        let mut jac = DMatrix::zeros(6, n);
        if n == 0 {
            return jac;
        }
        let t = self.forward_kinematics(q);
        let r: Matrix3<f64> = t.fixed_view::<3, 3>(0, 0).into_owned();
        for j in 0..n {
            let u = self.u(q, n - 1, j);
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

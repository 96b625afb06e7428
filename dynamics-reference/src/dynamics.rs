//! Pseudo-inertia, energies and the Lagrangian equations of motion
//! (Niku eqs. 6.36–6.46); in a tree each sum runs over the links that the joints of its
//! indices move (in a chain, `p ≥ max(i, …)`).

use nalgebra::{DMatrix, DVector, Matrix3, Matrix4, Vector3, Vector4};

use crate::robot::Robot;

/// Trace of a product of three 4×4 matrices, `Tr(a b cᵀ)`: the building block of
/// eqs. (6.38), (6.43) and (6.44).
fn trace_abct(a: &Matrix4<f64>, b: &Matrix4<f64>, c: &Matrix4<f64>) -> f64 {
    (a * b * c.transpose()).trace()
}

/// The matrices `U_ij`, `U_ijk` (eqs. 6.28, 6.29) and `J_i` (eq. 6.37) at one `q`,
/// evaluated once with [`Robot::u`], [`Robot::u2`] and [`Robot::pseudo_inertia`] and then
/// looked up by the sums below. This is plain memoization (the O(n⁴) sums stay as in the
/// book); it only keeps unoptimized test builds from recomputing the same products.
struct Tables {
    /// `u[i][j] = U_ij`.
    u: Vec<Vec<Matrix4<f64>>>,
    /// `u2[i][j][k] = U_ijk`.
    u2: Vec<Vec<Vec<Matrix4<f64>>>>,
    /// `j[i] = J_i`.
    j: Vec<Matrix4<f64>>,
    /// `moves[j][p]`: whether joint `j` is `p` or an ancestor of `p` ([`Robot::moves`]).
    moves: Vec<Vec<bool>>,
}

impl Tables {
    fn new(robot: &Robot, q: &[f64]) -> Tables {
        robot.check_len("q", q);
        let n = robot.dof();
        Tables {
            u: (0..n)
                .map(|i| (0..n).map(|j| robot.u(q, i, j)).collect())
                .collect(),
            u2: (0..n)
                .map(|i| {
                    (0..n)
                        .map(|j| (0..n).map(|k| robot.u2(q, i, j, k)).collect())
                        .collect()
                })
                .collect(),
            j: (0..n).map(|i| robot.pseudo_inertia(i)).collect(),
            moves: (0..n)
                .map(|j| (0..n).map(|p| robot.moves(j, p)).collect())
                .collect(),
        }
    }

    /// The links `p` that every joint of `joints` moves: `p ≥ max(joints)` in a chain.
    fn links_moved_by<'a>(&'a self, joints: &'a [usize]) -> impl Iterator<Item = usize> + 'a {
        (0..self.j.len()).filter(move |&p| joints.iter().all(|&j| self.moves[j][p]))
    }

    /// `D_ij` of eq. (6.43) without the actuator term:
    /// `Σ_p Tr(U_pj J_p U_piᵀ)` over the links `p` moved by both `i` and `j`
    /// (`p = max(i,j) … n` in a chain).
    fn inertia_coefficient(&self, i: usize, j: usize) -> f64 {
        self.links_moved_by(&[i, j])
            .map(|p| trace_abct(&self.u[p][j], &self.j[p], &self.u[p][i]))
            .sum()
    }

    /// `D_ijk` of eq. (6.44): `Σ_p Tr(U_pjk J_p U_piᵀ)` over the links `p` moved by `i`, `j`
    /// and `k` (`p = max(i,j,k) … n` in a chain).
    fn coriolis_coefficient(&self, i: usize, j: usize, k: usize) -> f64 {
        self.links_moved_by(&[i, j, k])
            .map(|p| trace_abct(&self.u2[p][j][k], &self.j[p], &self.u[p][i]))
            .sum()
    }
}

impl Robot {
    /// The book's pseudo-inertia matrix `J_i` of link `i` (eqs. 6.36, 6.37; 0-based `i`):
    ///
    /// ```text
    /// J_i = ∫ r̄ r̄ᵀ dm = [[Σ, m c], [m cᵀ, m]],   Σ = ∫ r rᵀ dm  (about the origin of frame i)
    /// ```
    ///
    /// The description gives the inertia *tensor* `I_C` about the centre of mass, whose
    /// off-diagonal entries are `−∫xy dm` etc., while (6.37) uses the positive products
    /// `∫xy dm` and moments about the frame origin. Conversion (see the project's
    /// `docs/errata.md`): parallel axis `I_O = I_C + m (cᵀc·1 − c cᵀ)`, then
    /// `Σ = ½ tr(I_O)·1 − I_O` (whose diagonal is (6.37)'s `(−Ixx + Iyy + Izz)/2` etc.
    /// and whose off-diagonal is `+∫xy dm`).
    ///
    /// # Panics
    ///
    /// If `i >= self.dof()`.
    pub fn pseudo_inertia(&self, i: usize) -> Matrix4<f64> {
        let joint = &self.joints[i];
        let m = joint.mass;
        let c = Vector3::from(joint.com);
        let [ixx, iyy, izz, ixy, ixz, iyz] = joint.inertia;
        #[rustfmt::skip]
        let i_c = Matrix3::new(
            ixx, ixy, ixz,
            ixy, iyy, iyz,
            ixz, iyz, izz,
        );
        let i_o = i_c + (Matrix3::identity() * c.dot(&c) - c * c.transpose()) * m;
        let sigma = Matrix3::identity() * (0.5 * i_o.trace()) - i_o;
        let mut j = Matrix4::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&sigma);
        for r in 0..3 {
            j[(r, 3)] = m * c[r];
            j[(3, r)] = m * c[r];
        }
        j[(3, 3)] = m;
        j
    }

    /// Homogeneous centre of mass `r̄_i = [x, y, z, 1]ᵀ` of link `i` in its own frame.
    fn com_homogeneous(&self, i: usize) -> Vector4<f64> {
        let [x, y, z] = self.joints[i].com;
        Vector4::new(x, y, z, 1.0)
    }

    /// The book's `gᵀ = [gx, gy, gz, 0]` (eq. 6.45): the gravity acceleration.
    fn gravity_homogeneous(&self) -> Vector4<f64> {
        let [gx, gy, gz] = self.gravity;
        Vector4::new(gx, gy, gz, 0.0)
    }

    /// Joint-space inertia (mass) matrix: `D_ij` of eq. (6.43),
    /// `D_ij = Σ_p Tr(U_pj J_p U_piᵀ)` over the links `p` that joints `i` and `j` both move
    /// (`p = max(i,j) … n` in a chain; so `D_ij = 0` when neither joint is an ancestor of the
    /// other), plus the actuator inertia
    /// `I_i(act)` on the diagonal (the `I_i(act) q̈_i` term of eq. 6.46). Symmetric.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn mass_matrix(&self, q: &[f64]) -> DMatrix<f64> {
        let tables = Tables::new(self, q);
        let n = self.dof();
        DMatrix::from_fn(n, n, |i, j| {
            let actuator = if i == j {
                self.joints[i].actuator_inertia
            } else {
                0.0
            };
            tables.inertia_coefficient(i, j) + actuator
        })
    }

    /// All coefficients `D_ijk` of eq. (6.44),
    /// `D_ijk = Σ_p Tr(U_pjk J_p U_piᵀ)` over the links `p` that joints `i`, `j`, `k` all
    /// move (`p = max(i,j,k) … n` in a chain).
    ///
    /// Indexing: `christoffel(q)[i][(j, k)] = D_ijk` (0-based; the book's `D_{i+1,j+1,k+1}`).
    /// `D_ijk` is symmetric in `j`, `k` (because `U_pjk = U_pkj`) and equals the
    /// Christoffel symbol of the first kind
    /// `½ (∂D_ij/∂q_k + ∂D_ik/∂q_j − ∂D_jk/∂q_i)`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn christoffel(&self, q: &[f64]) -> Vec<DMatrix<f64>> {
        let tables = Tables::new(self, q);
        let n = self.dof();
        (0..n)
            .map(|i| DMatrix::from_fn(n, n, |j, k| tables.coriolis_coefficient(i, j, k)))
            .collect()
    }

    /// Coriolis matrix `C_ij = Σ_k D_ijk q̇_k` with `D_ijk` of eq. (6.44), so that the
    /// velocity terms of eq. (6.46) are `C q̇`. This is the Christoffel-symbol Coriolis
    /// matrix, for which `Ṁ = C + Cᵀ` (`M` the mass matrix).
    ///
    /// # Panics
    ///
    /// If `q.len()` or `qd.len()` differs from `self.dof()`.
    pub fn coriolis_matrix(&self, q: &[f64], qd: &[f64]) -> DMatrix<f64> {
        self.check_len("qd", qd);
        let n = self.dof();
        let d = self.christoffel(q);
        DMatrix::from_fn(n, n, |i, j| (0..n).map(|k| d[i][(j, k)] * qd[k]).sum())
    }

    /// Coriolis and centrifugal torques, the double sum of eq. (6.46):
    /// `Σ_j Σ_k D_ijk q̇_j q̇_k`, computed term by term (not through
    /// [`Robot::coriolis_matrix`], so the two are independent checks of each other).
    ///
    /// # Panics
    ///
    /// If `q.len()` or `qd.len()` differs from `self.dof()`.
    pub fn coriolis_torques(&self, q: &[f64], qd: &[f64]) -> DVector<f64> {
        self.check_len("qd", qd);
        let tables = Tables::new(self, q);
        let n = self.dof();
        DVector::from_fn(n, |i, _| {
            let mut sum = 0.0;
            for j in 0..n {
                for k in 0..n {
                    sum += tables.coriolis_coefficient(i, j, k) * qd[j] * qd[k];
                }
            }
            sum
        })
    }

    /// Gravity torques `D_i` of eq. (6.45), `D_i = −Σ_p m_p gᵀ U_pi r̄_p` over the links `p`
    /// that joint `i` moves (`p = i … n` in a chain), with
    /// `gᵀ = [gx, gy, gz, 0]` the gravity acceleration and `r̄_p` the homogeneous centre
    /// of mass of link `p` in frame `p`; plus the joint-spring force `k_i (q_i − rest_i)`.
    /// Equals `∂P/∂q` for the potential energy of [`Robot::potential_energy`].
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn gravity_torques(&self, q: &[f64]) -> DVector<f64> {
        self.check_len("q", q);
        let n = self.dof();
        let g = self.gravity_homogeneous();
        DVector::from_fn(n, |i, _| {
            let gravity: f64 = (0..n)
                .filter(|&p| self.moves(i, p))
                .map(|p| {
                    let u_r = self.u(q, p, i) * self.com_homogeneous(p);
                    -self.joints[p].mass * g.dot(&u_r)
                })
                .sum();
            let joint = &self.joints[i];
            let spring = joint.spring_stiffness * (q[i] - joint.spring_rest);
            gravity + spring
        })
    }

    /// Inverse dynamics, eq. (6.46):
    /// `T_i = Σ_j D_ij q̈_j + I_i(act) q̈_i + Σ_j Σ_k D_ijk q̇_j q̇_k + D_i`
    /// (`D_ij` of eq. 6.43 without the actuator term, `D_ijk` of 6.44, `D_i` of 6.45 plus
    /// springs). Torques for revolute joints, forces for prismatic ones.
    ///
    /// # Panics
    ///
    /// If `q.len()`, `qd.len()` or `qdd.len()` differs from `self.dof()`.
    pub fn inverse_dynamics(&self, q: &[f64], qd: &[f64], qdd: &[f64]) -> DVector<f64> {
        self.check_len("q", q);
        self.check_len("qd", qd);
        self.check_len("qdd", qdd);
        let n = self.dof();
        let tables = Tables::new(self, q);
        let velocity_terms = self.coriolis_torques(q, qd);
        let gravity_terms = self.gravity_torques(q);
        DVector::from_fn(n, |i, _| {
            let inertial: f64 = (0..n)
                .map(|j| tables.inertia_coefficient(i, j) * qdd[j])
                .sum();
            let actuator = self.joints[i].actuator_inertia * qdd[i];
            inertial + actuator + velocity_terms[i] + gravity_terms[i]
        })
    }

    /// Kinetic energy, eq. (6.39):
    /// `K = ½ Σ_i Σ_{p≤i} Σ_{r≤i} Tr(U_ip J_i U_irᵀ) q̇_p q̇_r + ½ Σ_i I_i(act) q̇_i²`, where in
    /// a tree `p ≤ i` reads "`p` is `i` or an ancestor of `i`".
    ///
    /// # Panics
    ///
    /// If `q.len()` or `qd.len()` differs from `self.dof()`.
    pub fn kinetic_energy(&self, q: &[f64], qd: &[f64]) -> f64 {
        self.check_len("qd", qd);
        let tables = Tables::new(self, q);
        let n = self.dof();
        let mut k = 0.0;
        for i in 0..n {
            let path = self.path(i);
            for &p in &path {
                for &r in &path {
                    let trace = trace_abct(&tables.u[i][p], &tables.j[i], &tables.u[i][r]);
                    k += 0.5 * trace * qd[p] * qd[r];
                }
            }
            k += 0.5 * self.joints[i].actuator_inertia * qd[i] * qd[i];
        }
        k
    }

    /// Potential energy (the equation after (6.39) in the book; its number is lost in the
    /// text extraction): `P = −Σ_i m_i gᵀ ⁰T_i r̄_i` (`⁰T_i` along the path to link `i`) (zero for a mass at the base origin)
    /// plus the joint springs `Σ_i ½ k_i (q_i − rest_i)²`.
    ///
    /// # Panics
    ///
    /// If `q.len() != self.dof()`.
    pub fn potential_energy(&self, q: &[f64]) -> f64 {
        self.check_len("q", q);
        let g = self.gravity_homogeneous();
        (0..self.dof())
            .map(|i| {
                let joint = &self.joints[i];
                let gravity = -joint.mass * g.dot(&(self.frame(q, i) * self.com_homogeneous(i)));
                let stretch = q[i] - joint.spring_rest;
                gravity + 0.5 * joint.spring_stiffness * stretch * stretch
            })
            .sum()
    }
}

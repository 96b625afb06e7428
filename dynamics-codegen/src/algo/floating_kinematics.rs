//! The kinematic outputs of a tree on a free-flying base, written once over the scalar: the
//! centre of mass and its Jacobian, the centroidal momentum matrix `A_G` and `Ȧ_G v`, and each
//! named frame's pose, Jacobian and `J̇ v` (Pinocchio's `centerOfMass`,
//! `jacobianCenterOfMass`, `computeCentroidalMap`, `computeCentroidalMapTimeVariation`,
//! `getFrameJacobian` and `getFrameClassicalAcceleration`). Coordinates as
//! [`super::floating_rnea`]'s; `R` is the base's orientation ([`quaternion_rotation`]).
//!
//! * **Momentum.** The first six rows of `M` map `v` to the robot's spatial momentum about the
//!   base origin in base axes, `[p; L_O]` (Wensing and Orin, 2013): `M`'s base block is the
//!   whole robot's composite inertia and its coupling column k the momentum of the bodies a
//!   unit `q̇_k` moves. The whole robot's mass `m` and first moment `h` sit in that block, so
//!   the CoM is `c = h / m` in base axes, `p + R c` in the world. About the CoM,
//!   `L_G = L_O − c × p`, so `A_G = [R M_p; R (M_L − c × M_p)]` column by column, and the
//!   CoM's Jacobian is `R M_p / m`.
//! * **Its rate.** `ḣ_G = A_G a + Ȧ_G v`, and `ḣ_G` is the wrench the world puts on the robot
//!   about the CoM (gravity aside): Newton-Euler's base rows at `a = 0` without gravity,
//!   `[f; n_O]` in base axes, give `Ȧ_G v = [R f; R (n_O − c × f)]`.
//! * **Frames.** The fixed-base kinematics ([`super::tip_kinematics`]) give the frame's pose
//!   `(R_f, p_f)` in the base frame, its Jacobian `[J_v; J_ω]` in base axes and the bias
//!   `[a_f; α_f] = J̇ q̇` (the frame's classical acceleration relative to the base). On the
//!   flying base the frame's origin moves with `R (v + ω × p_f + J_v q̇)` and turns with
//!   `R (ω + J_ω q̇)`: LOCAL_WORLD_ALIGNED's Jacobian is
//!   `[[R, −R [p_f]×, R J_v], [0, R, R J_ω]]`, LOCAL's the same with `R_fᵀ` for `R`. At
//!   `a = 0` (the base's `v`, `ω` constant in base axes) the origin accelerates by
//!   `R (ω × v + ω × (ω × p_f) + 2 ω × J_v q̇ + a_f)` and the frame's angular acceleration is
//!   `R (ω × J_ω q̇ + α_f)`: the classical `J̇ v`, in world axes, or in the frame's with `R_f`.

use super::{
    floating_crba, floating_rnea, quaternion_rotation, Chain, FloatingBase, Jacobian, Kinematics,
    Mat3, Scalar, V3,
};
use std::ops::Add;

/// The centroidal quantities of a floating-base robot at one configuration.
#[derive(Clone, Debug)]
pub struct Centroidal<S> {
    /// The centre of mass relative to the base origin, in world axes (`R c`): add the base
    /// position for the world's.
    pub com: V3<S>,
    /// The centre of mass in base axes, `c`.
    pub com_in_base: V3<S>,
    /// `A_G`, 6 rows of `6 + n`: `[linear; angular]` momentum about the CoM in world axes.
    pub matrix: [Vec<S>; 6],
    /// The CoM's Jacobian in world axes, 3 rows of `6 + n`.
    pub com_jacobian: [Vec<S>; 3],
}

/// A 3-vector from entries `k..k + 3`.
fn vector<S: Copy>(x: &[S], k: usize) -> V3<S> {
    V3 {
        x: x[k],
        y: x[k + 1],
        z: x[k + 2],
    }
}

/// The centre of mass, its Jacobian and `A_G` (see the module's doc).
pub fn centroidal<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    quaternion: [S; 4],
) -> Centroidal<S> {
    let m = floating_crba(chain, base);
    let r = quaternion_rotation(quaternion);
    let mass = m[0][0];
    let inverse_mass = mass.recip();
    // The composite's first moment, in its block `[[m 1, −[h]×], [[h]×, I]]`.
    let c = V3::new(m[5][1], m[3][2], m[4][0]).scale(inverse_mass);
    let columns = m[0].len();
    let mut matrix: [Vec<S>; 6] = Default::default();
    let mut com_jacobian: [Vec<S>; 3] = Default::default();
    let momenta = (0..columns).map(|k| std::array::from_fn::<S, 6, _>(|i| m[i][k]));
    for column in momenta {
        let (p, l) = (vector(&column, 0), vector(&column, 3));
        let linear = r.mul_vec(p);
        let angular = r.mul_vec(l - c.cross(p));
        let velocity = linear.scale(inverse_mass);
        for (row, x) in matrix.iter_mut().zip([
            linear.x, linear.y, linear.z, angular.x, angular.y, angular.z,
        ]) {
            row.push(x);
        }
        for (row, x) in com_jacobian
            .iter_mut()
            .zip([velocity.x, velocity.y, velocity.z])
        {
            row.push(x);
        }
    }
    Centroidal {
        com: r.mul_vec(c),
        com_in_base: c,
        matrix,
        com_jacobian,
    }
}

/// `Ȧ_G v`: `[linear; angular]` in world axes (see the module's doc); `com_in_base` is
/// [`Centroidal::com_in_base`].
pub fn centroidal_bias<S: Scalar>(
    chain: &Chain<S>,
    base: &FloatingBase<S>,
    quaternion: [S; 4],
    v: &[S],
    com_in_base: V3<S>,
) -> [S; 6] {
    let zero = com_in_base.x.zero();
    let zeros = vec![zero; v.len()];
    let wrench = floating_rnea(chain, base, quaternion, v, &zeros, V3::zero(zero));
    let r = quaternion_rotation(quaternion);
    let (f, n) = (vector(&wrench, 0), vector(&wrench, 3));
    let linear = r.mul_vec(f);
    let angular = r.mul_vec(n - com_in_base.cross(f));
    [
        linear.x, linear.y, linear.z, angular.x, angular.y, angular.z,
    ]
}

/// A frame's kinematics on a floating base: Pinocchio's `oMf`, `getFrameJacobian` and
/// `getFrameClassicalAcceleration` at `a = 0`.
#[derive(Clone, Debug)]
pub struct FloatingFrame<S> {
    /// Its axes in the world's.
    pub rotation: Mat3<S>,
    /// Its origin relative to the base origin, in world axes: add the base position for the
    /// world's.
    pub position: V3<S>,
    /// LOCAL_WORLD_ALIGNED: `[origin's velocity; angular velocity]` in world axes, 6 rows of
    /// `6 + n`.
    pub jacobian_world: Jacobian<S>,
    /// LOCAL: the same in the frame's axes.
    pub jacobian_local: Jacobian<S>,
    /// `J̇ v`, the classical acceleration at `a = 0`, in world axes.
    pub bias_world: [S; 6],
    /// The same in the frame's axes.
    pub bias_local: [S; 6],
}

/// The kinematics of the frame `k.hand` (from [`super::tip_kinematics`] in the base frame) on
/// the base turned by `quaternion`, at the velocity `v` (`6 + n`; see the module's doc).
pub fn floating_frame<S: Scalar>(
    k: &Kinematics<S>,
    fixed: &Jacobian<S>,
    fixed_bias: &[S; 6],
    quaternion: [S; 4],
    v: &[S],
) -> FloatingFrame<S> {
    let r = quaternion_rotation(quaternion);
    let rf = k.hand.rotation;
    let pf = k.hand.position;
    let zero = pf.x.zero();
    let one = zero.one();
    let unit = |i: usize| {
        let mut e = [zero; 3];
        e[i] = one;
        V3::new(e[0], e[1], e[2])
    };
    // Columns in base axes: the base's six, then the joints'.
    let mut columns: Vec<(V3<S>, V3<S>)> = Vec::with_capacity(v.len());
    for i in 0..3 {
        columns.push((unit(i), V3::zero(zero)));
    }
    for i in 0..3 {
        columns.push((unit(i).cross(pf), unit(i)));
    }
    let joints = (0..fixed[0].len()).map(|j| std::array::from_fn::<S, 6, _>(|i| fixed[i][j]));
    columns.extend(joints.map(|c| (vector(&c, 0), vector(&c, 3))));
    let world = jacobian(&columns, |x| r.mul_vec(x));
    let local = jacobian(&columns, |x| rf.tr_mul_vec(x));
    let (lin, w) = (vector(v, 0), vector(v, 3));
    let qd = &v[6..];
    let (mut velocity, mut spin) = (V3::zero(zero), V3::zero(zero));
    for (j, &rate) in qd.iter().enumerate() {
        velocity = velocity.add(V3::new(fixed[0][j], fixed[1][j], fixed[2][j]).scale(rate));
        spin = spin.add(V3::new(fixed[3][j], fixed[4][j], fixed[5][j]).scale(rate));
    }
    let linear = w
        .cross(lin)
        .add(w.cross(w.cross(pf)))
        .add(w.cross(velocity).scale(one + one))
        .add(vector(fixed_bias, 0));
    let angular = w.cross(spin).add(vector(fixed_bias, 3));
    let six = |f: &dyn Fn(V3<S>) -> V3<S>| {
        let (a, b) = (f(linear), f(angular));
        [a.x, a.y, a.z, b.x, b.y, b.z]
    };
    FloatingFrame {
        rotation: r.mul(&rf),
        position: r.mul_vec(pf),
        jacobian_world: world,
        jacobian_local: local,
        bias_world: six(&|x| r.mul_vec(x)),
        bias_local: six(&|x| rf.tr_mul_vec(x)),
    }
}

/// The 6-row Jacobian of `columns` (`[v; ω]` each) with both halves mapped by `turn`.
fn jacobian<S: Scalar>(columns: &[(V3<S>, V3<S>)], turn: impl Fn(V3<S>) -> V3<S>) -> Jacobian<S> {
    let mut rows: Jacobian<S> = Default::default();
    for &(a, b) in columns {
        let (a, b) = (turn(a), turn(b));
        for (row, x) in rows.iter_mut().zip([a.x, a.y, a.z, b.x, b.y, b.z]) {
            row.push(x);
        }
    }
    rows
}

//! The configuration space of a floating base, Pinocchio's free flyer: `integrate(q, v)` (the
//! base moved by SE(3)'s exponential of the twist `v` in its own frame, the joints added),
//! `difference(q0, q1)` (the logarithm), and `∂ integrate / ∂v` (SE(3)'s right Jacobian).
//! The same for every robot, hence functions of the runtime rather than generated code; the
//! functions of the rotation angle θ that are 0/0 at θ = 0 take their Taylor series below a
//! threshold (a branch on the scalar, so `f32` and `f64` only, not lanes).

use crate::RealScalar;

/// `Σ_k (−1)^k θ^{2k} c_k` for `θ² = t`, the series of the even functions below.
fn series<T: RealScalar>(t: T, c: impl Fn(u32) -> f64) -> T {
    (0..10)
        .rev()
        .fold(T::ZERO, |acc, k| T::from_f64(c(k)) + (-t) * acc)
}

/// `1 / (n)!` as `f64`.
fn inverse_factorial(n: u32) -> f64 {
    (1..=n).fold(1.0, |acc, k| acc / f64::from(k))
}

/// Below this `θ²` the coefficients are their series (ten terms: the first left out is below
/// `1 / 22!` there), above it their closed forms, whose cancellation costs at most a few ulp
/// from θ = 1 up.
const SERIES_BELOW: f64 = 1.0;

/// The rotation's coefficients at `θ² = t`: `sin θ / θ`, `(1 − cos θ) / θ²`,
/// `(θ − sin θ) / θ³`, `(θ² + 2 cos θ − 2) / (2 θ⁴)`, `(2θ − 3 sin θ + θ cos θ) / (2 θ⁵)`.
fn coefficients<T: RealScalar>(t: T) -> [T; 5] {
    if t.to_f64() < SERIES_BELOW {
        return [
            series(t, |k| inverse_factorial(2 * k + 1)),
            series(t, |k| inverse_factorial(2 * k + 2)),
            series(t, |k| inverse_factorial(2 * k + 3)),
            series(t, |k| inverse_factorial(2 * k + 4)),
            series(t, |k| f64::from(k + 1) * inverse_factorial(2 * k + 5)),
        ];
    }
    let theta = T::from_f64(libm::sqrt(t.to_f64()));
    let (s, c) = theta.sin_cos();
    let two = T::from_f64(2.0);
    [
        s / theta,
        (T::ONE - c) / t,
        (theta - s) / (t * theta),
        (t + two * c - two) / (two * t * t),
        (two * theta - T::from_f64(3.0) * s + theta * c) / (two * t * t * theta),
    ]
}

type V3<T> = [T; 3];
type M3<T> = [[T; 3]; 3];

fn cross<T: RealScalar>(a: V3<T>, b: V3<T>) -> V3<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot<T: RealScalar>(a: V3<T>, b: V3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn add<T: RealScalar>(a: V3<T>, b: V3<T>) -> V3<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn scale<T: RealScalar>(k: T, a: V3<T>) -> V3<T> {
    a.map(|x| k * x)
}

/// The quaternion's rotation matrix, the polynomial of its components `[x, y, z, w]` (as the
/// dynamics read it).
fn rotation<T: RealScalar>(q: [T; 4]) -> M3<T> {
    let [x, y, z, w] = q;
    let (one, two) = (T::ONE, T::from_f64(2.0));
    [
        [
            one - two * (y * y + z * z),
            two * (x * y - z * w),
            two * (x * z + y * w),
        ],
        [
            two * (x * y + z * w),
            one - two * (x * x + z * z),
            two * (y * z - x * w),
        ],
        [
            two * (x * z - y * w),
            two * (y * z + x * w),
            one - two * (x * x + y * y),
        ],
    ]
}

/// The Hamilton product `a ⊗ b` of quaternions `[x, y, z, w]`.
fn product<T: RealScalar>(a: [T; 4], b: [T; 4]) -> [T; 4] {
    let (av, bv) = ([a[0], a[1], a[2]], [b[0], b[1], b[2]]);
    let v = add(add(scale(a[3], bv), scale(b[3], av)), cross(av, bv));
    [v[0], v[1], v[2], a[3] * b[3] - dot(av, bv)]
}

/// The base's part of `q`: position and quaternion.
fn base<T: RealScalar, const Q: usize>(q: &[T; Q]) -> (V3<T>, [T; 4]) {
    ([q[0], q[1], q[2]], [q[3], q[4], q[5], q[6]])
}

/// Pinocchio's `integrate`: the base placed at `M0 exp6(v_b)`, its quaternion
/// `q0 ⊗ exp(ω / 2)` renormalised to first order (as Pinocchio's `firstOrderNormalize`), the
/// joints `q_i + v_i`.
#[must_use]
pub fn integrate<T: RealScalar, const Q: usize, const N: usize>(q: &[T; Q], v: &[T; N]) -> [T; Q] {
    let (p0, quaternion) = base(q);
    let (linear, omega) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
    let [_, a, b, ..] = coefficients(dot(omega, omega));
    // V(ω) v = v + a ω × v + b ω × (ω × v): the origin's displacement in the base frame.
    let wv = cross(omega, linear);
    let step = add(add(linear, scale(a, wv)), scale(b, cross(omega, wv)));
    let r = rotation(quaternion);
    let moved: V3<T> = core::array::from_fn(|i| p0[i] + dot(r[i], step));
    // exp(ω/2) = [sin(θ/2)/θ ω, cos(θ/2)]: the coefficients at (θ/2)².
    let quarter = T::from_f64(0.25) * dot(omega, omega);
    let [half_sinc, ..] = coefficients(quarter);
    let half = T::from_f64(0.5);
    let s = half * half_sinc;
    let c = if quarter.to_f64() < SERIES_BELOW {
        series(quarter, |k| inverse_factorial(2 * k))
    } else {
        T::from_f64(libm::cos(libm::sqrt(quarter.to_f64())))
    };
    let e = [s * omega[0], s * omega[1], s * omega[2], c];
    let mut turned = product(quaternion, e);
    let norm2 = turned.iter().fold(T::ZERO, |acc, &x| acc + x * x);
    let first_order = half * (T::from_f64(3.0) - norm2);
    turned = turned.map(|x| x * first_order);
    core::array::from_fn(|i| match i {
        0..=2 => moved[i],
        3..=6 => turned[i - 3],
        _ => q[i] + v[i - 1],
    })
}

/// Pinocchio's `difference`: the twist `log6(M0⁻¹ M1)` of the base in its frame at q0, then
/// `q1_i − q0_i`: `integrate(q0, difference(q0, q1)) = q1` (the quaternion up to its sign).
#[must_use]
pub fn difference<T: RealScalar, const Q: usize, const N: usize>(
    q0: &[T; Q],
    q1: &[T; Q],
) -> [T; N] {
    let ((p0, a0), (p1, a1)) = (base(q0), base(q1));
    // q0⁻¹ ⊗ q1 for a unit q0, on the half where w ≥ 0 (the shorter rotation).
    let mut r = product([-a0[0], -a0[1], -a0[2], a0[3]], a1);
    if r[3].to_f64() < 0.0 {
        r = r.map(|x| -x);
    }
    let (u, w) = ([r[0], r[1], r[2]], r[3]);
    let s2 = dot(u, u);
    // θ = 2 atan2(|u|, w), ω = θ u / |u|; 2 atan(x)/x's series for small x = |u|/w.
    let ratio = s2.to_f64() / (w * w).to_f64();
    let theta_over_s = if ratio < 1e-2 {
        let x2 = s2 / (w * w);
        T::from_f64(2.0) / w * series(x2, |k| 1.0 / f64::from(2 * k + 1))
    } else {
        let s = libm::sqrt(s2.to_f64());
        T::from_f64(2.0 * libm::atan2(s, w.to_f64()) / s)
    };
    let omega = scale(theta_over_s, u);
    let r0 = rotation(a0);
    let d = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
    // R0ᵀ (p1 − p0): the displacement in the base frame at q0.
    let local: V3<T> =
        core::array::from_fn(|j| (0..3).fold(T::ZERO, |acc, i| acc + r0[i][j] * d[i]));
    // V(ω)⁻¹ = 1 − ½[ω]× + e [ω]×².
    let e = inverse_coefficient(dot(omega, omega));
    let wl = cross(omega, local);
    let linear = add(
        add(local, scale(T::from_f64(-0.5), wl)),
        scale(e, cross(omega, wl)),
    );
    core::array::from_fn(|i| match i {
        0..=2 => linear[i],
        3..=5 => omega[i - 3],
        _ => q1[i + 1] - q0[i + 1],
    })
}

/// `e = 1/θ² − (1 + cos θ)/(2 θ sin θ)` at `θ² = t`, of `V(ω)⁻¹ = 1 − ½[ω]× + e [ω]×²` and
/// `J_r3(ω)⁻¹ = 1 + ½[ω]× + e [ω]×²`; its series below `θ² = 10⁻²`.
fn inverse_coefficient<T: RealScalar>(t: T) -> T {
    if t.to_f64() < 1e-2 {
        let c = [
            1.0 / 12.0,
            1.0 / 720.0,
            1.0 / 30240.0,
            1.0 / 1_209_600.0,
            1.0 / 47_900_160.0,
        ];
        c.iter()
            .rev()
            .fold(T::ZERO, |acc, &ck| T::from_f64(ck) + t * acc)
    } else {
        let theta = T::from_f64(libm::sqrt(t.to_f64()));
        let (s, c) = theta.sin_cos();
        T::ONE / t - (T::ONE + c) / (T::from_f64(2.0) * theta * s)
    }
}

/// `[a]×`.
fn skew<T: RealScalar>(a: V3<T>) -> M3<T> {
    let z = T::ZERO;
    [[z, -a[2], a[1]], [a[2], z, -a[0]], [-a[1], a[0], z]]
}

fn mul<T: RealScalar>(a: &M3<T>, b: &M3<T>) -> M3<T> {
    core::array::from_fn(|i| {
        core::array::from_fn(|j| (0..3).fold(T::ZERO, |acc, k| acc + a[i][k] * b[k][j]))
    })
}

fn combine<T: RealScalar>(terms: &[(T, M3<T>)]) -> M3<T> {
    core::array::from_fn(|i| {
        core::array::from_fn(|j| terms.iter().fold(T::ZERO, |acc, (k, m)| acc + *k * m[i][j]))
    })
}

/// Pinocchio's `dIntegrate` by `v`: the base's block SE(3)'s right Jacobian `J_r(v_b)` (the
/// change of the result, in its own frame, per change of `v_b`), the joints' the identity.
/// `J_r(ρ, φ) = [[J_r3(φ), Q_r(ρ, φ)], [0, J_r3(φ)]]` with `J_r3 = 1 − a[φ]× + b[φ]×²` and
/// `Q_r(ρ, φ) = Q_l(−ρ, −φ)`, Barfoot's `Q_l` (*State Estimation for Robotics*, eq. 7.86).
#[must_use]
pub fn integrate_jacobian<T: RealScalar, const N: usize>(v: &[T; N]) -> [[T; N]; N] {
    let (rho, phi) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
    let [_, a, b, c, d] = coefficients(dot(phi, phi));
    let (p, r) = (skew(phi), skew(rho));
    let pp = mul(&p, &p);
    let (pr, rp, prp) = (mul(&p, &r), mul(&r, &p), mul(&mul(&p, &r), &p));
    let (ppr, rpp) = (mul(&pp, &r), mul(&r, &pp));
    let (prpp, pprp) = (mul(&prp, &p), mul(&pp, &rp));
    let one = T::ONE;
    let three = T::from_f64(3.0);
    let q = combine(&[
        (T::from_f64(-0.5), r),
        (b, pr),
        (b, rp),
        (-b, prp),
        (-c, ppr),
        (-c, rpp),
        (three * c, prp),
        (d, prpp),
        (d, pprp),
    ]);
    let j3 = combine(&[(one, identity()), (-a, p), (b, pp)]);
    blocks(&j3, &q, &j3, one)
}

/// `Mᵀ`.
fn transpose<T: RealScalar>(m: &M3<T>) -> M3<T> {
    core::array::from_fn(|i| core::array::from_fn(|j| m[j][i]))
}

/// `[[a, b], [0, d]]` in the base's 6 × 6 block, `diagonal` on the joints'.
fn blocks<T: RealScalar, const N: usize>(
    a: &M3<T>,
    b: &M3<T>,
    d: &M3<T>,
    diagonal: T,
) -> [[T; N]; N] {
    let mut out = [[T::ZERO; N]; N];
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = a[i][j];
            out[i][j + 3] = b[i][j];
            out[i + 3][j + 3] = d[i][j];
        }
    }
    for (i, row) in out.iter_mut().enumerate().skip(6) {
        row[i] = diagonal;
    }
    out
}

/// `Ad(M⁻¹) = [[Rᵀ, −Rᵀ [p]×], [0, Rᵀ]]`, `M = (R, p)`, scaled by `sign`.
fn inverse_adjoint<T: RealScalar>(r: &M3<T>, p: V3<T>, sign: T) -> [M3<T>; 2] {
    let rt = transpose(r);
    let corner = mul(&rt, &skew(p));
    [combine(&[(sign, rt)]), combine(&[(-sign, corner)])]
}

/// Pinocchio's `dIntegrate(q, v, ARG0)`: `∂ integrate(q, v) / ∂q` in the tangent spaces at
/// `q` and at the result, the base's block `Ad(exp6(v_b)⁻¹)` (a change `δ` of the base at `q`
/// is `exp6(v_b)⁻¹ δ exp6(v_b)` at the result), the joints' the identity; it does not depend
/// on `q`. `exp6(ρ, φ) = (exp3(φ), V(φ) ρ)`, `exp3(φ) = 1 + sin θ/θ [φ]× + (1 − cos θ)/θ² [φ]×²`.
#[must_use]
pub fn integrate_jacobian_q<T: RealScalar, const N: usize>(v: &[T; N]) -> [[T; N]; N] {
    let (rho, phi) = ([v[0], v[1], v[2]], [v[3], v[4], v[5]]);
    let [sinc, a, b, ..] = coefficients(dot(phi, phi));
    let (p, pp) = (skew(phi), mul(&skew(phi), &skew(phi)));
    let identity = identity();
    let r = combine(&[(T::ONE, identity), (sinc, p), (a, pp)]);
    let pr = cross(phi, rho);
    let origin = add(add(rho, scale(a, pr)), scale(b, cross(phi, pr)));
    let [rt, corner] = inverse_adjoint(&r, origin, T::ONE);
    blocks(&rt, &corner, &rt, T::ONE)
}

/// The 3 × 3 identity.
fn identity<T: RealScalar>() -> M3<T> {
    core::array::from_fn(|i| core::array::from_fn(|j| if i == j { T::ONE } else { T::ZERO }))
}

/// Pinocchio's `Jlog6(M0⁻¹ M1)`, the base's block of `∂ difference(q0, q1) / ∂q1`: the inverse
/// of SE(3)'s right Jacobian at `ξ = log6(M0⁻¹ M1)`,
/// `[[J_r3⁻¹, −J_r3⁻¹ Q_r J_r3⁻¹], [0, J_r3⁻¹]]`, `J_r3(φ)⁻¹ = 1 + ½[φ]× + e [φ]×²`.
fn log_jacobian<T: RealScalar>(xi: &[T; 6]) -> [M3<T>; 2] {
    let right = integrate_jacobian(xi);
    let q: M3<T> = core::array::from_fn(|i| core::array::from_fn(|j| right[i][j + 3]));
    let phi = [xi[3], xi[4], xi[5]];
    let e = inverse_coefficient(dot(phi, phi));
    let p = skew(phi);
    let inverse = combine(&[
        (T::ONE, identity()),
        (T::from_f64(0.5), p),
        (e, mul(&p, &p)),
    ]);
    let corner = mul(&mul(&inverse, &q), &inverse);
    [inverse, combine(&[(-T::ONE, corner)])]
}

/// The base's twist `log6(M0⁻¹ M1)`.
fn base_difference<T: RealScalar, const Q: usize>(q0: &[T; Q], q1: &[T; Q]) -> [T; 6] {
    let (b0, b1): ([T; 7], [T; 7]) = (
        core::array::from_fn(|i| q0[i]),
        core::array::from_fn(|i| q1[i]),
    );
    difference(&b0, &b1)
}

/// Pinocchio's `dDifference(q0, q1, ARG1)`: `∂ difference(q0, q1) / ∂q1` in the tangent space
/// at `q1`, the base's block `Jlog6(M0⁻¹ M1)`, the joints' the identity.
#[must_use]
pub fn difference_jacobian_q1<T: RealScalar, const Q: usize, const N: usize>(
    q0: &[T; Q],
    q1: &[T; Q],
) -> [[T; N]; N] {
    let [inverse, corner] = log_jacobian(&base_difference(q0, q1));
    blocks(&inverse, &corner, &inverse, T::ONE)
}

/// Pinocchio's `dDifference(q0, q1, ARG0)`: `∂ difference(q0, q1) / ∂q0` in the tangent space
/// at `q0`, the base's block `−Jlog6(M) Ad(M⁻¹)` for `M = M0⁻¹ M1 = (R0ᵀ R1, R0ᵀ (p1 − p0))`
/// (moving `M0` by `δ` moves `M` by `−Ad(M⁻¹) δ` on its right), the joints' `−1`.
#[must_use]
pub fn difference_jacobian_q0<T: RealScalar, const Q: usize, const N: usize>(
    q0: &[T; Q],
    q1: &[T; Q],
) -> [[T; N]; N] {
    let ((p0, a0), (p1, a1)) = (base(q0), base(q1));
    let r0t = transpose(&rotation(a0));
    let r = mul(&r0t, &rotation(a1));
    let d = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
    let p: V3<T> = core::array::from_fn(|i| dot(r0t[i], d));
    let [ad, ad_corner] = inverse_adjoint(&r, p, -T::ONE);
    let [inverse, corner] = log_jacobian(&base_difference(q0, q1));
    // [[A, B], [0, A]] [[C, D], [0, C]] = [[AC, AD + BC], [0, AC]].
    let ac = mul(&inverse, &ad);
    let top = combine(&[
        (T::ONE, mul(&inverse, &ad_corner)),
        (T::ONE, mul(&corner, &ad)),
    ]);
    blocks(&ac, &top, &ac, -T::ONE)
}

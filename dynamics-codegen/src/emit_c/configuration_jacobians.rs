//! The configuration space's Jacobians in C (`--configuration`): the runtime's
//! `integrate_jacobian`, `integrate_jacobian_q`, `difference_jacobian_q0` and `_q1`
//! (`dynamics-runtime/src/configuration.rs`, Pinocchio's `dIntegrate` and `dDifference` with
//! `ARG1`/`ARG0`) written out in C, the same products in the same order, the same series and
//! branches, `<math.h>`'s sines and cosines. The base's 6 × 6 block, the joints' the identity
//! (`−1` for `∂/∂q0`):
//!
//! ```text
//! ∂ integrate/∂v   = J_r(v_b) = [[J_r3, Q_r], [0, J_r3]],  J_r3(φ) = 1 − a[φ]× + b[φ]×²
//! ∂ integrate/∂q   = Ad(exp6(v_b)⁻¹) = [[Rᵀ, −Rᵀ[p]×], [0, Rᵀ]]
//! ∂ difference/∂q1 = Jlog6(ξ) = [[J_r3⁻¹, −J_r3⁻¹ Q_r J_r3⁻¹], [0, J_r3⁻¹]],  ξ = log6(M0⁻¹ M1)
//! ∂ difference/∂q0 = −Jlog6(ξ) Ad(M⁻¹),  M = M0⁻¹ M1
//! ```
//!
//! `Q_r` is Barfoot's `Q_l(−ρ, −φ)` with `c = (θ² + 2 cos θ − 2)/(2θ⁴)` and
//! `d = (2θ − 3 sin θ + θ cos θ)/(2θ⁵)` beside `a` and `b`, their series below `θ² = 1`.
//! Defined once under the configuration's guard; the robot's functions pass its joints' count.

use super::expr::Precision;

/// The robot's four functions in both precisions, after the shared ones.
pub(super) fn robot_functions(dof: usize, prefix: &str) -> String {
    let (nq, nv, joints) = (dof + 1, dof, dof - 6);
    let mut text = String::new();
    for p in Precision::ALL {
        let (ty, sfx) = (p.c_type(), p.suffix());
        let of_v = |name: &str, doc: &str, inner: &str| {
            format!(
                "/* {name}{sfx}: {doc} */\n\
                 static inline void {prefix}_{name}{sfx}(const {ty} q[{nq}], const {ty} v[{nv}], {ty} out[{nv}][{nv}]) {{\n    \
                 (void)q; /* the Jacobian does not depend on q */\n    \
                 dynamics_{inner}{sfx}(v, &out[0][0], {joints});\n}}\n\n"
            )
        };
        let of_q = |name: &str, doc: &str| {
            format!(
                "/* {name}{sfx}: {doc} */\n\
                 static inline void {prefix}_{name}{sfx}(const {ty} q0[{nq}], const {ty} q1[{nq}], {ty} out[{nv}][{nv}]) {{\n    \
                 dynamics_{name}{sfx}(q0, q1, &out[0][0], {joints});\n}}\n\n"
            )
        };
        text.push_str(&of_v(
            "integrate_jacobian_v",
            "d integrate(q, v) / dv (Pinocchio's dIntegrate, ARG1).",
            "integrate_jacobian",
        ));
        text.push_str(&of_v(
            "integrate_jacobian_q",
            "d integrate(q, v) / dq (Pinocchio's dIntegrate, ARG0).",
            "integrate_jacobian_q",
        ));
        text.push_str(&of_q(
            "difference_jacobian_q0",
            "d difference(q0, q1) / dq0 (Pinocchio's dDifference, ARG0).",
        ));
        text.push_str(&of_q(
            "difference_jacobian_q1",
            "d difference(q0, q1) / dq1 (Pinocchio's dDifference, ARG1).",
        ));
    }
    text
}

/// The shared functions of precision `p` (inside the configuration's guard, after
/// `configuration.rs`'s).
#[allow(clippy::too_many_lines)] // One C text, read as C.
pub(super) fn shared(p: Precision) -> String {
    let (t, s) = (p.c_type(), p.suffix());
    let (sqrt, sin, cos) = (p.math("sqrt"), p.math("sin"), p.math("cos"));
    format!(
        "/* Beside sin th/th, (1 - cos th)/th^2, (th - sin th)/th^3: (th^2 + 2 cos th - 2)/(2 th^4),
 * (2 th - 3 sin th + th cos th)/(2 th^5) at th^2 = t, series below t = 1. */
static inline void dynamics_se3_coefficients5{s}({t} t, {t} k[5]) {{
    dynamics_se3_coefficients{s}(t, k);
    if ((double)t < 1.0) {{
        k[3] = dynamics_series{s}(t, 4, 0);
        k[4] = dynamics_series{s}(t, 5, 1);
    }} else {{
        const {t} th = ({t}){sqrt}(t);
        const {t} sn = {sin}(th), cs = {cos}(th);
        k[3] = (t + 2 * cs - 2) / (2 * t * t);
        k[4] = (2 * th - 3 * sn + th * cs) / (2 * t * t * th);
    }}
}}

static inline void dynamics_skew{s}(const {t} a[3], {t} m[3][3]) {{
    m[0][0] = 0; m[0][1] = -a[2]; m[0][2] = a[1];
    m[1][0] = a[2]; m[1][1] = 0; m[1][2] = -a[0];
    m[2][0] = -a[1]; m[2][1] = a[0]; m[2][2] = 0;
}}

/* out = a b; out may be a or b. */
static inline void dynamics_mul{s}({t} a[3][3], {t} b[3][3], {t} out[3][3]) {{
    {t} m[3][3];
    int i, j, k;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {{
            {t} acc = 0;
            for (k = 0; k < 3; ++k) acc = acc + a[i][k] * b[k][j];
            m[i][j] = acc;
        }}
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) out[i][j] = m[i][j];
}}

/* acc += k m. */
static inline void dynamics_add_scaled{s}({t} k, {t} m[3][3], {t} acc[3][3]) {{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) acc[i][j] = acc[i][j] + k * m[i][j];
}}

static inline void dynamics_set{s}({t} k, {t} m[3][3], {t} out[3][3]) {{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) out[i][j] = 0;
    dynamics_add_scaled{s}(k, m, out);
}}

/* [[a, b], [0, d]] in the base's 6 x 6 block of the n x n out, diagonal on the joints'. */
static inline void dynamics_blocks{s}({t} a[3][3], {t} b[3][3], {t} d[3][3], {t} diagonal, {t} *out, int joints) {{
    const int n = 6 + joints;
    int i, j;
    for (i = 0; i < n * n; ++i) out[i] = 0;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {{
            out[n * i + j] = a[i][j];
            out[n * i + j + 3] = b[i][j];
            out[n * (i + 3) + j + 3] = d[i][j];
        }}
    for (i = 6; i < n; ++i) out[n * i + i] = diagonal;
}}

static inline void dynamics_identity{s}({t} m[3][3]) {{
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) m[i][j] = i == j ? 1 : 0;
}}

/* SE(3)'s right Jacobian at v's twist, the base's block J_r = [[J_r3, Q_r], [0, J_r3]]. */
static inline void dynamics_right_jacobian{s}(const {t} *v, {t} j3[3][3], {t} q[3][3]) {{
    const {t} rho[3] = {{v[0], v[1], v[2]}}, phi[3] = {{v[3], v[4], v[5]}};
    {t} k[5], p[3][3], r[3][3], pp[3][3], pr[3][3], rp[3][3], prp[3][3], ppr[3][3], rpp[3][3];
    {t} prpp[3][3], pprp[3][3];
    dynamics_se3_coefficients5{s}(dynamics_dot{s}(phi, phi), k);
    dynamics_skew{s}(phi, p);
    dynamics_skew{s}(rho, r);
    dynamics_mul{s}(p, p, pp);
    dynamics_mul{s}(p, r, pr);
    dynamics_mul{s}(r, p, rp);
    dynamics_mul{s}(pr, p, prp);
    dynamics_mul{s}(pp, r, ppr);
    dynamics_mul{s}(r, pp, rpp);
    dynamics_mul{s}(prp, p, prpp);
    dynamics_mul{s}(pp, rp, pprp);
    dynamics_set{s}(({t})-0.5, r, q);
    dynamics_add_scaled{s}(k[2], pr, q);
    dynamics_add_scaled{s}(k[2], rp, q);
    dynamics_add_scaled{s}(-k[2], prp, q);
    dynamics_add_scaled{s}(-k[3], ppr, q);
    dynamics_add_scaled{s}(-k[3], rpp, q);
    dynamics_add_scaled{s}(3 * k[3], prp, q);
    dynamics_add_scaled{s}(k[4], prpp, q);
    dynamics_add_scaled{s}(k[4], pprp, q);
    dynamics_identity{s}(j3);
    dynamics_add_scaled{s}(-k[1], p, j3);
    dynamics_add_scaled{s}(k[2], pp, j3);
}}

static inline void dynamics_integrate_jacobian{s}(const {t} *v, {t} *out, int joints) {{
    {t} j3[3][3], q[3][3];
    dynamics_right_jacobian{s}(v, j3, q);
    dynamics_blocks{s}(j3, q, j3, 1, out, joints);
}}

/* Ad(M^-1) = [[R^T, -R^T [p]x], [0, R^T]] of M = (R, p), scaled by sign. */
static inline void dynamics_inverse_adjoint{s}({t} r[3][3], const {t} p[3], {t} sign, {t} rt[3][3], {t} corner[3][3]) {{
    {t} transposed[3][3], px[3][3], m[3][3];
    int i, j;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) transposed[i][j] = r[j][i];
    dynamics_skew{s}(p, px);
    dynamics_mul{s}(transposed, px, m);
    dynamics_set{s}(sign, transposed, rt);
    dynamics_set{s}(-sign, m, corner);
}}

static inline void dynamics_integrate_jacobian_q{s}(const {t} *v, {t} *out, int joints) {{
    const {t} rho[3] = {{v[0], v[1], v[2]}}, phi[3] = {{v[3], v[4], v[5]}};
    {t} k[3], p[3][3], pp[3][3], r[3][3], wr[3], wwr[3], origin[3], rt[3][3], corner[3][3];
    int i;
    dynamics_se3_coefficients{s}(dynamics_dot{s}(phi, phi), k);
    dynamics_skew{s}(phi, p);
    dynamics_mul{s}(p, p, pp);
    /* exp3(phi) = 1 + sin th/th [phi]x + (1 - cos th)/th^2 [phi]x^2, origin V(phi) rho. */
    dynamics_identity{s}(r);
    dynamics_add_scaled{s}(k[0], p, r);
    dynamics_add_scaled{s}(k[1], pp, r);
    dynamics_cross{s}(phi, rho, wr);
    dynamics_cross{s}(phi, wr, wwr);
    for (i = 0; i < 3; ++i) origin[i] = (rho[i] + k[1] * wr[i]) + k[2] * wwr[i];
    dynamics_inverse_adjoint{s}(r, origin, 1, rt, corner);
    dynamics_blocks{s}(rt, corner, rt, 1, out, joints);
}}

/* Jlog6(xi) = [[J_r3^-1, -J_r3^-1 Q_r J_r3^-1], [0, J_r3^-1]], J_r3^-1 = 1 + [phi]x/2 + e [phi]x^2. */
static inline void dynamics_log_jacobian{s}(const {t} xi[6], {t} inverse[3][3], {t} corner[3][3]) {{
    const {t} phi[3] = {{xi[3], xi[4], xi[5]}};
    {t} j3[3][3], q[3][3], p[3][3], pp[3][3], m[3][3];
    dynamics_right_jacobian{s}(xi, j3, q);
    dynamics_skew{s}(phi, p);
    dynamics_mul{s}(p, p, pp);
    dynamics_identity{s}(inverse);
    dynamics_add_scaled{s}(({t})0.5, p, inverse);
    dynamics_add_scaled{s}(dynamics_inverse_coefficient{s}(dynamics_dot{s}(phi, phi)), pp, inverse);
    dynamics_mul{s}(inverse, q, m);
    dynamics_mul{s}(m, inverse, m);
    dynamics_set{s}(-1, m, corner);
}}

static inline void dynamics_difference_jacobian_q1{s}(const {t} *q0, const {t} *q1, {t} *out, int joints) {{
    {t} xi[6], inverse[3][3], corner[3][3];
    dynamics_difference{s}(q0, q1, xi, 0);
    dynamics_log_jacobian{s}(xi, inverse, corner);
    dynamics_blocks{s}(inverse, corner, inverse, 1, out, joints);
}}

/* -Jlog6(M) Ad(M^-1), M = M0^-1 M1 = (R0^T R1, R0^T (p1 - p0)): [[A, B], [0, A]] [[C, D], [0, C]]
 * = [[AC, AD + BC], [0, AC]]. */
static inline void dynamics_difference_jacobian_q0{s}(const {t} *q0, const {t} *q1, {t} *out, int joints) {{
    const {t} a0[4] = {{q0[3], q0[4], q0[5], q0[6]}}, a1[4] = {{q1[3], q1[4], q1[5], q1[6]}};
    {t} r0[3][3], r0t[3][3], r1[3][3], r[3][3], d[3], p[3], ad[3][3], ad_corner[3][3];
    {t} xi[6], inverse[3][3], corner[3][3], ac[3][3], m[3][3], top[3][3];
    int i, j;
    dynamics_rotation{s}(a0, r0);
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) r0t[i][j] = r0[j][i];
    dynamics_rotation{s}(a1, r1);
    dynamics_mul{s}(r0t, r1, r);
    for (i = 0; i < 3; ++i) d[i] = q1[i] - q0[i];
    for (i = 0; i < 3; ++i) p[i] = dynamics_dot{s}(r0t[i], d);
    dynamics_inverse_adjoint{s}(r, p, -1, ad, ad_corner);
    dynamics_difference{s}(q0, q1, xi, 0);
    dynamics_log_jacobian{s}(xi, inverse, corner);
    dynamics_mul{s}(inverse, ad, ac);
    dynamics_mul{s}(inverse, ad_corner, m);
    dynamics_set{s}(1, m, top);
    dynamics_mul{s}(corner, ad, m);
    dynamics_add_scaled{s}(1, m, top);
    dynamics_blocks{s}(ac, top, ac, -1, out, joints);
}}

"
    )
}

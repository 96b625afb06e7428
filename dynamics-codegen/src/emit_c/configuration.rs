//! The configuration space of a floating base in C (`--configuration`): the runtime's
//! `integrate` and `difference` (`dynamics-runtime/src/configuration.rs`, Pinocchio's free
//! flyer), the same operations in the same order, but the sines, cosines and square roots
//! `<math.h>`'s (so not always the Rust results' bits); their Jacobians in
//! `configuration_jacobians.rs`. The base's part is the same for every
//! robot: `dynamics_integrate`, `dynamics_difference` (`_f32`), defined once under a guard that
//! headers included together share; each robot's `{prefix}_integrate`, `_difference` call them
//! with its number of joints.
//!
//! ```text
//! integrate:   p = p0 + R0 V(ω) v_lin,  quat = q0 ⊗ [sin(θ/2) ω/θ, cos(θ/2)] (renormalised to
//!              first order),  q_i + v_i;   V(ω) = 1 + a [ω]× + b [ω]×²
//! difference:  ω = θ u/|u| (u, w: q0⁻¹ ⊗ q1 on its half with w ≥ 0, θ = 2 atan2(|u|, w)),
//!              v_lin = V(ω)⁻¹ R0ᵀ (p1 − p0),  q1_i − q0_i
//! ```
//!
//! `a = (1 − cos θ)/θ²`, `b = (θ − sin θ)/θ³`, `sin θ/θ` are their Taylor series below `θ² = 1`,
//! `V(ω)⁻¹`'s `e = 1/θ² − (1 + cos θ)/(2θ sin θ)` below `θ² = 10⁻²`, as the runtime's.

use super::expr::Precision;

/// The robot-independent part and the robot's two functions.
pub(super) fn functions(dof: usize, prefix: &str) -> String {
    let (nq, nv, joints) = (dof + 1, dof, dof - 6);
    let mut text = "#ifndef DYNAMICS_CONFIGURATION_H\n#define DYNAMICS_CONFIGURATION_H\n\
         /* 1/n!, as the runtime computes it. */\n\
         static inline double dynamics_inverse_factorial(int n) {\n    \
         double x = 1.0;\n    int k;\n    for (k = 1; k <= n; ++k) x /= (double)k;\n    \
         return x;\n}\n\n"
        .to_owned();
    for p in Precision::ALL {
        text.push_str(&shared(p));
        text.push_str(&super::configuration_jacobians::shared(p));
    }
    text.push_str("#endif /* DYNAMICS_CONFIGURATION_H */\n\n");
    for p in Precision::ALL {
        let (ty, sfx) = (p.c_type(), p.suffix());
        text.push_str(&format!(
            "/* integrate{sfx}: q moved by v over a unit time on the configuration space \
             (Pinocchio's integrate):\n * the base by exp6 of its twist in its own frame, the \
             joints q_i + v_i. out may be q. */\n\
             static inline void {prefix}_integrate{sfx}(const {ty} q[{nq}], const {ty} v[{nv}], {ty} out[{nq}]) {{\n    \
             dynamics_integrate{sfx}(q, v, out, {joints});\n}}\n\n\
             /* difference{sfx}: the v that integrate moves q0 by to q1 (Pinocchio's \
             difference): the base's\n * log6(M0^-1 M1), q1_i - q0_i. */\n\
             static inline void {prefix}_difference{sfx}(const {ty} q0[{nq}], const {ty} q1[{nq}], {ty} out[{nv}]) {{\n    \
             dynamics_difference{sfx}(q0, q1, out, {joints});\n}}\n\n"
        ));
    }
    text.push_str(&super::configuration_jacobians::robot_functions(
        dof, prefix,
    ));
    text
}

/// The shared functions of precision `p`.
#[allow(clippy::too_many_lines)] // One C text, read as C.
fn shared(p: Precision) -> String {
    let (t, s) = (p.c_type(), p.suffix());
    let (sqrt, sin, cos) = (p.math("sqrt"), p.math("sin"), p.math("cos"));
    format!(
        "/* sum_k (-t)^k c_k over ten terms, c_k = (k + 1)^weighted / (2k + first)!, or 1/(2k + 1)
 * where first is 0 and weighted 2 (the series of atan(x)/x at t = x^2). */
static inline {t} dynamics_series{s}({t} t, int first, int weighted) {{
    {t} acc = 0;
    int k;
    for (k = 9; k >= 0; --k) {{
        double c = weighted == 2 ? 1.0 / (double)(2 * k + 1) : dynamics_inverse_factorial(2 * k + first);
        if (weighted == 1) c = (double)(k + 1) * c;
        acc = ({t})c + (-t) * acc;
    }}
    return acc;
}}

/* sin(th)/th, (1 - cos th)/th^2, (th - sin th)/th^3 at th^2 = t: series below t = 1. */
static inline void dynamics_se3_coefficients{s}({t} t, {t} k[3]) {{
    if ((double)t < 1.0) {{
        k[0] = dynamics_series{s}(t, 1, 0);
        k[1] = dynamics_series{s}(t, 2, 0);
        k[2] = dynamics_series{s}(t, 3, 0);
    }} else {{
        const {t} th = ({t}){sqrt}(t);
        const {t} sn = {sin}(th), cs = {cos}(th);
        k[0] = sn / th;
        k[1] = (1 - cs) / t;
        k[2] = (th - sn) / (t * th);
    }}
}}

static inline void dynamics_cross{s}(const {t} a[3], const {t} b[3], {t} out[3]) {{
    const {t} x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    out[0] = x;
    out[1] = y;
    out[2] = z;
}}

static inline {t} dynamics_dot{s}(const {t} a[3], const {t} b[3]) {{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}}

/* The quaternion [x, y, z, w]'s rotation matrix, its polynomial (not normalised). */
static inline void dynamics_rotation{s}(const {t} q[4], {t} r[3][3]) {{
    const {t} x = q[0], y = q[1], z = q[2], w = q[3];
    r[0][0] = 1 - 2 * (y * y + z * z);
    r[0][1] = 2 * (x * y - z * w);
    r[0][2] = 2 * (x * z + y * w);
    r[1][0] = 2 * (x * y + z * w);
    r[1][1] = 1 - 2 * (x * x + z * z);
    r[1][2] = 2 * (y * z - x * w);
    r[2][0] = 2 * (x * z - y * w);
    r[2][1] = 2 * (y * z + x * w);
    r[2][2] = 1 - 2 * (x * x + y * y);
}}

/* The Hamilton product a (x) b of quaternions [x, y, z, w]. */
static inline void dynamics_product{s}(const {t} a[4], const {t} b[4], {t} out[4]) {{
    {t} c[3];
    int i;
    dynamics_cross{s}(a, b, c);
    out[3] = a[3] * b[3] - dynamics_dot{s}(a, b);
    for (i = 0; i < 3; ++i) out[i] = (a[3] * b[i] + b[3] * a[i]) + c[i];
}}

static inline void dynamics_integrate{s}(const {t} *q, const {t} *v, {t} *out, int joints) {{
    const {t} quaternion[4] = {{q[3], q[4], q[5], q[6]}};
    const {t} *linear = v, *omega = v + 3;
    {t} k[3], wv[3], wwv[3], step[3], r[3][3], moved[3], e[4], turned[4];
    {t} t, quarter, half_s, c, norm2 = 0, first_order;
    int i;
    t = dynamics_dot{s}(omega, omega);
    dynamics_se3_coefficients{s}(t, k);
    /* V(w) v = v + a w x v + b w x (w x v): the origin's displacement in the base frame. */
    dynamics_cross{s}(omega, linear, wv);
    dynamics_cross{s}(omega, wv, wwv);
    for (i = 0; i < 3; ++i) step[i] = (linear[i] + k[1] * wv[i]) + k[2] * wwv[i];
    dynamics_rotation{s}(quaternion, r);
    for (i = 0; i < 3; ++i) moved[i] = q[i] + dynamics_dot{s}(r[i], step);
    /* exp(w/2) = [sin(th/2)/th w, cos(th/2)]: the coefficients at (th/2)^2. */
    quarter = ({t})0.25 * t;
    dynamics_se3_coefficients{s}(quarter, k);
    half_s = ({t})0.5 * k[0];
    c = (double)quarter < 1.0 ? dynamics_series{s}(quarter, 0, 0) : {cos}({sqrt}(quarter));
    for (i = 0; i < 3; ++i) e[i] = half_s * omega[i];
    e[3] = c;
    dynamics_product{s}(quaternion, e, turned);
    for (i = 0; i < 4; ++i) norm2 = norm2 + turned[i] * turned[i];
    first_order = ({t})0.5 * (3 - norm2);
    for (i = 0; i < 3; ++i) out[i] = moved[i];
    for (i = 0; i < 4; ++i) out[3 + i] = turned[i] * first_order;
    for (i = 0; i < joints; ++i) out[7 + i] = q[7 + i] + v[6 + i];
}}

/* e = 1/th^2 - (1 + cos th)/(2 th sin th) at th^2 = t, of V(w)^-1 = 1 - [w]x/2 + e [w]x^2. */
static inline {t} dynamics_inverse_coefficient{s}({t} t) {{
    if ((double)t < 1e-2) {{
        static const double c[5] = {{1.0 / 12.0, 1.0 / 720.0, 1.0 / 30240.0, 1.0 / 1209600.0, 1.0 / 47900160.0}};
        {t} acc = 0;
        int k;
        for (k = 4; k >= 0; --k) acc = ({t})c[k] + t * acc;
        return acc;
    }} else {{
        const {t} th = ({t}){sqrt}(t);
        return 1 / t - (1 + {cos}(th)) / (2 * th * {sin}(th));
    }}
}}

static inline void dynamics_difference{s}(const {t} *q0, const {t} *q1, {t} *out, int joints) {{
    const {t} inverse[4] = {{-q0[3], -q0[4], -q0[5], q0[6]}}, a0[4] = {{q0[3], q0[4], q0[5], q0[6]}};
    const {t} a1[4] = {{q1[3], q1[4], q1[5], q1[6]}};
    {t} r[4], omega[3], r0[3][3], d[3], local[3], wl[3], wwl[3], linear[3], s2, w, over, e;
    int i, j;
    /* q0^-1 (x) q1 for a unit q0, on the half where w >= 0 (the shorter rotation). */
    dynamics_product{s}(inverse, a1, r);
    if ((double)r[3] < 0.0) {{
        for (i = 0; i < 4; ++i) r[i] = -r[i];
    }}
    w = r[3];
    s2 = dynamics_dot{s}(r, r);
    /* th = 2 atan2(|u|, w), w = th u/|u|; 2 atan(x)/x's series for small x = |u|/w. */
    if ((double)s2 / (double)(w * w) < 1e-2) {{
        over = ({t})2 / w * dynamics_series{s}(s2 / (w * w), 0, 2);
    }} else {{
        const double sn = sqrt((double)s2);
        over = ({t})(2.0 * atan2(sn, (double)w) / sn);
    }}
    for (i = 0; i < 3; ++i) omega[i] = over * r[i];
    dynamics_rotation{s}(a0, r0);
    for (i = 0; i < 3; ++i) d[i] = q1[i] - q0[i];
    /* R0^T (p1 - p0): the displacement in the base frame at q0. */
    for (j = 0; j < 3; ++j) {{
        {t} acc = 0;
        for (i = 0; i < 3; ++i) acc = acc + r0[i][j] * d[i];
        local[j] = acc;
    }}
    e = dynamics_inverse_coefficient{s}(dynamics_dot{s}(omega, omega));
    dynamics_cross{s}(omega, local, wl);
    dynamics_cross{s}(omega, wl, wwl);
    for (i = 0; i < 3; ++i) linear[i] = (local[i] + ({t})-0.5 * wl[i]) + e * wwl[i];
    for (i = 0; i < 3; ++i) {{
        out[i] = linear[i];
        out[3 + i] = omega[i];
    }}
    for (i = 0; i < joints; ++i) out[6 + i] = q1[7 + i] - q0[7 + i];
}}

"
    )
}

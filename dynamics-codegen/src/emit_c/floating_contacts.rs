//! The contacts of a floating base in C, written once over the generated functions
//! (`{prefix}_contact_terms`, `_inverse_dynamics`, `_forward_dynamics`,
//! `_frame_jacobians_world_aligned`), as the runtime's `FloatingContacts` is over the Rust
//! ones. A wrench `w_f = [f, m]` is what the environment exerts on the robot at frame f's
//! origin, in world axes (Pinocchio's LOCAL_WORLD_ALIGNED):
//!
//! ```text
//! inverse_dynamics_with_wrenches:  τ = M a + h − Σ_f J_fᵀ w_f
//! forward_dynamics_with_wrenches:  a = M⁻¹ (τ − h + Σ_f J_fᵀ w_f)
//! contact_dynamics:                (J M⁻¹ Jᵀ)_cc λ_c = −(J a₀ + γ)_c,  a = a₀ + (M⁻¹ Jᵀ)_c λ_c
//! ```
//!
//! `contact_dynamics` factors the block of the frames in contact `L D Lᵀ` on the stack, a
//! frame not in contact given the identity's rows and `λ_f = 0`, as `ContactTerms::solve`.

use super::expr::Precision;
use super::floating_batch::parameters;
use crate::trace::Equations;

/// The three functions in precision `p`, for a robot of `frames` frames.
#[allow(clippy::too_many_lines)] // One C text, read as C.
pub(super) fn functions(eq: &Equations, frames: usize, prefix: &str, p: Precision) -> String {
    let ty = p.c_type();
    let sfx = p.suffix();
    let (nq, nv, rows) = (eq.dof + 1, eq.dof, 3 * frames);
    let width = nv + rows;
    let (zero, one) = (p.literal(0.0), p.literal(1.0));
    let head = parameters(eq, p).join(", ");
    let (head, pass) = if head.is_empty() {
        (String::new(), "")
    } else {
        (format!("{head}, "), "params, ")
    };
    format!(
        "/* inverse_dynamics_with_wrenches{sfx}: tau = M qdd + h - sum_f J_f^T w_f, wrenches[f] = \
         [f, m] on the\n * robot at frame f's origin in world axes (rnea with fext carried to \
         the frames). */
static inline void {prefix}_inverse_dynamics_with_wrenches{sfx}({head}const {ty} q[{nq}], const {ty} qd[{nv}], const {ty} qdd[{nv}], const {ty} wrenches[{frames}][6], {ty} tau[{nv}]) {{
    {ty} rigid[{nv}], j[{frames}][6][{nv}];
    int f, i, k;
    {prefix}_inverse_dynamics{sfx}({pass}q, qd, qdd, rigid);
    {prefix}_frame_jacobians_world_aligned{sfx}({pass}q, j);
    for (k = 0; k < {nv}; ++k) {{
        {ty} s = rigid[k];
        for (f = 0; f < {frames}; ++f) {{
            for (i = 0; i < 6; ++i) s -= j[f][i][k] * wrenches[f][i];
        }}
        tau[k] = s;
    }}
}}

/* forward_dynamics_with_wrenches{sfx}: qdd = M^-1 (tau - h + sum_f J_f^T w_f) (aba with fext).
 * Returns 0, or 1 where a pivot of M is not positive. */
static inline int {prefix}_forward_dynamics_with_wrenches{sfx}({head}const {ty} q[{nq}], const {ty} qd[{nv}], const {ty} tau[{nv}], const {ty} wrenches[{frames}][6], {ty} qdd[{nv}]) {{
    {ty} total[{nv}], j[{frames}][6][{nv}];
    int f, i, k;
    {prefix}_frame_jacobians_world_aligned{sfx}({pass}q, j);
    for (k = 0; k < {nv}; ++k) {{
        {ty} s = tau[k];
        for (f = 0; f < {frames}; ++f) {{
            for (i = 0; i < 6; ++i) s += j[f][i][k] * wrenches[f][i];
        }}
        total[k] = s;
    }}
    return {prefix}_forward_dynamics{sfx}({pass}q, qd, total, qdd);
}}

/* contact_dynamics{sfx}: the forward dynamics with the origins of the frames where in_contact[f]
 * is not 0 held (constraintDynamics, CONTACT_3D in LOCAL_WORLD_ALIGNED, no Baumgarte):
 * [M J^T; J 0] [qdd; -lambda] = [tau - h; -Jd v]. forces[f] is lambda_f, the force on the
 * robot at frame f's origin in world axes (0 where not held). Returns 0; 1 where a pivot of M
 * is not positive; 2 where one of J M^-1 J^T's block is not (dependent contacts). */
static inline int {prefix}_contact_dynamics{sfx}({head}const {ty} q[{nq}], const {ty} qd[{nv}], const {ty} tau[{nv}], const int in_contact[{frames}], {ty} qdd[{nv}], {ty} forces[{frames}][3]) {{
    {ty} accelerations[{width}], terms[{rows}][{width}], system[{rows}][{rows}], x[{rows}], d[{rows}];
    int i, j, k;
    if ({prefix}_contact_terms{sfx}({pass}q, qd, tau, accelerations, terms) != 0) return 1;
    for (i = 0; i < {rows}; ++i) {{
        const int held = in_contact[i / 3] != 0;
        x[i] = held ? -accelerations[{nv} + i] : {zero};
        for (j = 0; j < {rows}; ++j) {{
            system[i][j] = held && in_contact[j / 3] != 0 ? terms[i][{nv} + j] : (i == j ? {one} : {zero});
        }}
    }}
    /* L D L^T in place: row i's entries before the diagonal become L's. */
    for (i = 0; i < {rows}; ++i) {{
        {ty} pivot;
        for (k = 0; k < i; ++k) {{
            {ty} s = system[i][k];
            for (j = 0; j < k; ++j) s -= system[i][j] * system[k][j] * d[j];
            system[i][k] = s / d[k];
        }}
        pivot = system[i][i];
        for (j = 0; j < i; ++j) pivot -= system[i][j] * system[i][j] * d[j];
        if (!(pivot > {zero})) return 2;
        d[i] = pivot;
    }}
    for (i = 0; i < {rows}; ++i) {{
        for (j = 0; j < i; ++j) x[i] -= system[i][j] * x[j];
    }}
    for (i = 0; i < {rows}; ++i) x[i] /= d[i];
    for (i = {rows} - 1; i >= 0; --i) {{
        for (j = i + 1; j < {rows}; ++j) x[i] -= system[j][i] * x[j];
    }}
    for (k = 0; k < {nv}; ++k) qdd[k] = accelerations[k];
    for (i = 0; i < {rows}; ++i) {{
        const int held = in_contact[i / 3] != 0;
        forces[i / 3][i % 3] = held ? x[i] : {zero};
        if (held) {{
            for (k = 0; k < {nv}; ++k) qdd[k] += terms[i][k] * x[i];
        }}
    }}
    return 0;
}}

"
    )
}

//! A floating base's C functions beyond the method table's, each asked for
//! (`dynamics emit --lang c ROBOT --floating --kinematics --contacts --configuration`):
//!
//! * the kinematics (`FloatingKinematics`' outputs, traced on the floating equations' graph by
//!   [`Equations::floating_kinematics`]): `center_of_mass`, `center_of_mass_jacobian`,
//!   `centroidal_momentum_matrix`, `centroidal_momentum_bias`, `frame_poses` (`[R | p]`, 3 × 4
//!   a frame), `frame_jacobians_world_aligned`, `frame_jacobians_local` and
//!   `frame_acceleration_biases_world_aligned`, `_local`; the base position, which the graph
//!   leaves out, added to the centre of mass and the frames' origins after the closed form, as
//!   the Rust impl adds it;
//! * the contacts: `contact_terms` (the closed form of `contacts = true`, `[a₀; J a₀ + γ]` and
//!   the rows `[(M⁻¹ J_rᵀ)ᵀ, (J M⁻¹ Jᵀ)_r]`, packed as the Rust function packs them), and by
//!   hand over it and the kinematics, the runtime's `FloatingContacts` in C:
//!   `contact_dynamics` (`(J M⁻¹ Jᵀ)_cc λ_c = −(J a₀ + γ)_c`, `a = a₀ + (M⁻¹ Jᵀ)_c λ_c`, by
//!   `L D Lᵀ` on the stack as `ContactTerms::solve`), `inverse_dynamics_with_wrenches`
//!   (`τ = M a + h − Σ J_fᵀ w_f`) and `forward_dynamics_with_wrenches`;
//! * the configuration space (`configuration.rs`): `integrate` and `difference`, and their
//!   Jacobians (`configuration_jacobians.rs`).
//!
//! The generated bodies are written as the table's functions' are (`body.rs`), the element
//! names of a carrier method left out (they would describe another output). Each has a batch
//! twin (`floating_batch.rs`).

use super::body::Writer;
use super::expr::Precision;
use super::floating_batch::{parameters, Signature};
use crate::method::Method;
use crate::trace::{Equations, FloatingContactEquations, FloatingKinematicEquations, Shape};

/// What a floating base's header holds beyond the method table's functions.
#[derive(Clone, Copy, Debug, Default)]
pub struct FloatingExtras<'a> {
    /// The kinematic outputs (`--kinematics`, and `--contacts`, which reads the Jacobians).
    pub kinematics: Option<&'a FloatingKinematicEquations>,
    /// The contact terms in closed form and the contacts' functions over them (`--contacts`).
    pub contacts: Option<&'a FloatingContactEquations>,
    /// `integrate` and `difference` (`--configuration`).
    pub configuration: bool,
}

impl FloatingExtras<'_> {
    /// Whether the header holds none of them (it is then the table's alone, byte for byte).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.kinematics.is_none() && self.contacts.is_none() && !self.configuration
    }

    /// The nodes the generated functions read (for the header's choice of `<math.h>` and of a
    /// sign function).
    pub(super) fn outputs(&self, eq: &Equations) -> Vec<crate::symbolic::NodeId> {
        let mut outputs = Vec::new();
        if let Some(k) = self.kinematics {
            for (_, shape, _) in kinematic_outputs(k) {
                outputs.extend(shape.outputs());
            }
        }
        if let Some(c) = self.contacts {
            outputs.extend(&c.free);
            outputs.extend(c.rows.iter().flatten());
            outputs.extend(&eq.forward.factors.pivots);
        }
        outputs
    }
}

/// A kinematic output: its function's name, its shape, and whether it reads `qd`.
type Kinematic<'k> = (&'static str, Shape<'k>, bool);

/// The kinematic outputs in the header's order (the Rust trait's).
fn kinematic_outputs(k: &FloatingKinematicEquations) -> [Kinematic<'_>; 9] {
    [
        ("center_of_mass", Shape::Vector(&k.com), false),
        (
            "center_of_mass_jacobian",
            Shape::Matrix(&k.com_jacobian),
            false,
        ),
        (
            "centroidal_momentum_matrix",
            Shape::Matrix(&k.centroidal_matrix),
            false,
        ),
        (
            "centroidal_momentum_bias",
            Shape::Vector(&k.centroidal_bias),
            true,
        ),
        ("frame_poses", Shape::Stack(&k.frame_poses), false),
        (
            "frame_jacobians_world_aligned",
            Shape::Stack(&k.jacobians_world),
            false,
        ),
        (
            "frame_jacobians_local",
            Shape::Stack(&k.jacobians_local),
            false,
        ),
        (
            "frame_acceleration_biases_world_aligned",
            Shape::Matrix(&k.biases_world),
            true,
        ),
        (
            "frame_acceleration_biases_local",
            Shape::Matrix(&k.biases_local),
            true,
        ),
    ]
}

/// Each kinematic output's summary, the comment above its function.
const SUMMARIES: [&str; 9] = [
    "the centre of mass in the world (Pinocchio's centerOfMass)",
    "the centre of mass's Jacobian in world axes, 3 x NV (jacobianCenterOfMass)",
    "the centroidal momentum matrix A_G, 6 x NV, linear rows first, about the centre of mass \
     in world axes (computeCentroidalMap)",
    "Ad_G v, the centroidal momentum's drift (computeCentroidalMapTimeVariation(q, v) v)",
    "each frame's pose in the world, rows [R | p] (oMf after updateFramePlacements)",
    "each frame's Jacobian in LOCAL_WORLD_ALIGNED, 6 x NV (getFrameJacobian)",
    "each frame's Jacobian in LOCAL, 6 x NV (getFrameJacobian)",
    "each frame origin's classical acceleration at a = 0 in world axes, [linear, angular]: \
     Jd v (getFrameClassicalAcceleration)",
    "the same in the frame's own axes (LOCAL)",
];

/// The text of the extras of `eq` for the header with functions `{prefix}_*`; `sign` names
/// the header's sign function in each precision.
pub(super) fn extras(
    eq: &Equations,
    extras: &FloatingExtras,
    prefix: &str,
    sign: impl Fn(Precision) -> String,
) -> String {
    let mut text = String::new();
    if let Some(k) = extras.kinematics {
        text.push_str(&frame_constants(&k.frame_names, prefix));
        for p in Precision::ALL {
            for ((name, shape, with_v), summary) in kinematic_outputs(k).into_iter().zip(SUMMARIES)
            {
                let f = Generated {
                    name,
                    summary,
                    with_v,
                };
                text.push_str(&f.kinematic(eq, shape, prefix, p, &sign(p)));
            }
        }
    }
    if let (Some(c), Some(k)) = (extras.contacts, extras.kinematics) {
        for p in Precision::ALL {
            text.push_str(&contact_terms(eq, c, prefix, p, &sign(p)));
            text.push_str(&super::floating_contacts::functions(
                eq,
                k.frame_names.len(),
                prefix,
                p,
            ));
        }
    }
    if extras.configuration {
        text.push_str(&super::configuration::functions(eq.dof, prefix));
    }
    let signatures = signatures(eq, extras);
    if !signatures.is_empty() {
        text.push_str(&super::floating_batch::section(
            &signatures,
            prefix,
            eq.fields.len(),
        ));
    }
    if extras.configuration {
        // The same for every robot: no parameters, whatever the robot's.
        let (nq, nv) = (eq.dof + 1, eq.dof);
        let signatures = configuration_signatures(nq, nv);
        text.push_str(&super::floating_batch::section(&signatures, prefix, 0));
    }
    text
}

/// The extras' signatures but the configuration's, for their batch twins.
fn signatures(eq: &Equations, extras: &FloatingExtras) -> Vec<Signature> {
    let (nq, nv) = (eq.dof + 1, eq.dof);
    let state = |names: [&'static str; 3]| {
        let lengths = [nq, nv, nv];
        names
            .into_iter()
            .zip(lengths)
            .map(|(name, len)| (name, len, vec![], false))
            .collect::<Vec<_>>()
    };
    let mut signatures = Vec::new();
    if let Some(k) = extras.kinematics {
        for (name, shape, with_v) in kinematic_outputs(k) {
            let mut inputs = state(["q", "qd", "qd"]);
            inputs.truncate(if with_v { 2 } else { 1 });
            signatures.push(Signature {
                name,
                inputs,
                outputs: vec![("out", dimensions(&shape))],
                status: false,
            });
        }
    }
    if let (Some(c), Some(k)) = (extras.contacts, extras.kinematics) {
        let frames = k.frame_names.len();
        let width = c.free.len();
        let wrenches = ("wrenches", 6 * frames, vec![6], false);
        let with = |mut inputs: Vec<_>, extra| {
            inputs.push(extra);
            inputs
        };
        signatures.extend([
            Signature {
                name: "contact_terms",
                inputs: state(["q", "qd", "tau"]),
                outputs: vec![
                    ("accelerations", vec![width]),
                    ("rows", vec![3 * frames, width]),
                ],
                status: true,
            },
            Signature {
                name: "inverse_dynamics_with_wrenches",
                inputs: with(state(["q", "qd", "qdd"]), wrenches.clone()),
                outputs: vec![("tau", vec![nv])],
                status: false,
            },
            Signature {
                name: "forward_dynamics_with_wrenches",
                inputs: with(state(["q", "qd", "tau"]), wrenches),
                outputs: vec![("qdd", vec![nv])],
                status: true,
            },
            Signature {
                name: "contact_dynamics",
                inputs: with(
                    state(["q", "qd", "tau"]),
                    ("in_contact", frames, vec![], true),
                ),
                outputs: vec![("qdd", vec![nv]), ("forces", vec![frames, 3])],
                status: true,
            },
        ]);
    }
    signatures
}

/// `integrate`'s and `difference`'s signatures and their Jacobians', for their batch twins.
fn configuration_signatures(nq: usize, nv: usize) -> Vec<Signature> {
    let mut signatures = vec![
        Signature {
            name: "integrate",
            inputs: vec![("q", nq, vec![], false), ("v", nv, vec![], false)],
            outputs: vec![("out", vec![nq])],
            status: false,
        },
        Signature {
            name: "difference",
            inputs: vec![("q0", nq, vec![], false), ("q1", nq, vec![], false)],
            outputs: vec![("out", vec![nv])],
            status: false,
        },
    ];
    // The Jacobians, n x n: of integrate(q, v) and of difference(q0, q1).
    for (name, first, second, len) in [
        ("integrate_jacobian_v", "q", "v", nv),
        ("integrate_jacobian_q", "q", "v", nv),
        ("difference_jacobian_q0", "q0", "q1", nq),
        ("difference_jacobian_q1", "q0", "q1", nq),
    ] {
        signatures.push(Signature {
            name,
            inputs: vec![(first, nq, vec![], false), (second, len, vec![], false)],
            outputs: vec![("out", vec![nv, nv])],
            status: false,
        });
    }
    signatures
}

/// The dimensions of a kinematic output's array.
fn dimensions(shape: &Shape) -> Vec<usize> {
    match *shape {
        Shape::Vector(v) => vec![v.len()],
        Shape::Matrix(m) => vec![m.len(), m[0].len()],
        Shape::Stack(s) => vec![s.len(), s[0].len(), s[0][0].len()],
        _ => unreachable!("the kinematic outputs are vectors, matrices and stacks"),
    }
}

/// `#define SOLO12_FRAMES 4`, `#define SOLO12_FRAME_FL_FOOT 0`: the frames' count and each
/// one's index in the results.
fn frame_constants(names: &[String], prefix: &str) -> String {
    let upper = prefix.to_ascii_uppercase();
    let mut text = format!(
        "/* The frames of the kinematics and the contacts, in the order of their results: {}. */\n\
         #define {upper}_FRAMES {}\n",
        super::function::comment_safe(&names.join(", ")),
        names.len()
    );
    for (i, ident) in crate::emit::tip_names::index_names(names, "FRAME")
        .iter()
        .enumerate()
    {
        text.push_str(&format!("#define {upper}_{ident} {i}\n"));
    }
    text.push('\n');
    text
}

/// A generated kinematic function: its name after the prefix, its summary, whether it reads
/// `qd`.
struct Generated {
    name: &'static str,
    summary: &'static str,
    with_v: bool,
}

impl Generated {
    /// Its definition in precision `p`.
    fn kinematic(
        &self,
        eq: &Equations,
        shape: Shape,
        prefix: &str,
        p: Precision,
        sign: &str,
    ) -> String {
        let ty = p.c_type();
        let (nq, nv) = (eq.dof + 1, eq.dof);
        let array = "out";
        let dims: String = dimensions(&shape)
            .iter()
            .map(|d| format!("[{d}]"))
            .collect();
        let mut arguments = parameters(eq, p);
        arguments.push(format!("const {ty} q[{nq}]"));
        if self.with_v {
            arguments.push(format!("const {ty} qd[{nv}]"));
        }
        arguments.push(format!("{ty} {array}{dims}"));
        let mut text = format!(
            "/* {}{}: {} */\nstatic inline void {prefix}_{}{}({}) {{\n",
            self.name,
            p.suffix(),
            super::function::comment_safe(self.summary),
            self.name,
            p.suffix(),
            arguments.join(", ")
        );
        // The base position, read before any output is written (the outputs may alias q).
        let base = matches!(self.name, "center_of_mass" | "frame_poses");
        if base {
            text.push_str(&format!(
                "    const {ty} base_x = q[0], base_y = q[1], base_z = q[2];\n"
            ));
        }
        let body = Writer::new(eq, p, sign.to_owned()).anonymous_body(
            Method::GravityTorques,
            shape,
            &[array.to_owned()],
        );
        push_unread(
            &mut text,
            eq,
            body.reads.params,
            self.with_v && !body.reads.qd,
        );
        if !body.reads.q && !base {
            text.push_str("    (void)q;\n");
        }
        for line in &body.lines {
            text.push_str(&format!("    {line}\n"));
        }
        if self.name == "center_of_mass" {
            text.push_str(&format!(
                "    {array}[0] += base_x;\n    {array}[1] += base_y;\n    {array}[2] += base_z;\n"
            ));
        } else if base {
            let frames = match shape {
                Shape::Stack(s) => s.len(),
                _ => 0,
            };
            for f in 0..frames {
                for (i, x) in ["base_x", "base_y", "base_z"].iter().enumerate() {
                    text.push_str(&format!("    {array}[{f}][{i}][3] += {x};\n"));
                }
            }
        }
        text.push_str("}\n\n");
        text
    }
}

/// The `(void)` casts of the inputs a body does not read.
fn push_unread(text: &mut String, eq: &Equations, params: bool, unread_qd: bool) {
    if !eq.fields.is_empty() && !params {
        text.push_str("    (void)params;\n");
    }
    if unread_qd {
        text.push_str("    (void)qd;\n");
    }
}

/// `{prefix}_contact_terms`: the closed form of the contact terms of every frame.
fn contact_terms(
    eq: &Equations,
    c: &FloatingContactEquations,
    prefix: &str,
    p: Precision,
    sign: &str,
) -> String {
    let ty = p.c_type();
    let (nq, nv, width, rows) = (eq.dof + 1, eq.dof, c.free.len(), c.rows.len());
    let stack = [c.rows.clone()];
    let shape = Shape::SolvedStack {
        pivots: &eq.forward.factors.pivots,
        vector: &c.free,
        stack: &stack,
    };
    let body = Writer::new(eq, p, sign.to_owned()).anonymous_body(
        Method::ForwardDynamics,
        shape,
        &["accelerations".to_owned(), "rows".to_owned()],
    );
    let mut arguments = parameters(eq, p);
    arguments.extend([
        format!("const {ty} q[{nq}]"),
        format!("const {ty} qd[{nv}]"),
        format!("const {ty} tau[{nv}]"),
        format!("{ty} accelerations[{width}]"),
        format!("{ty} rows[{rows}][{width}]"),
    ]);
    let mut text = format!(
        "/* contact_terms{sfx}: every frame's point-contact terms at once, J the frames' linear \
         rows\n * in world axes (3 a frame), gamma = Jd v: accelerations = [a0; J a0 + gamma] with a0 = \
         M^-1 (tau - h),\n * rows[r] = [(M^-1 J_r^T)^T, row r of J M^-1 J^T]. Returns 0, or 1 \
         where a pivot of M is\n * not positive. */\nstatic inline int {prefix}_contact_terms{sfx}({}) {{\n",
        arguments.join(", "),
        sfx = p.suffix(),
    );
    push_unread(&mut text, eq, body.reads.params, !body.reads.qd);
    for line in &body.lines {
        // The emitter's solved stack has one matrix: `rows[0][i][j]` is `rows[i][j]` here.
        let line = line
            .strip_prefix("rows[0]")
            .map_or_else(|| line.clone(), |rest| format!("rows{rest}"));
        text.push_str(&format!("    {line}\n"));
    }
    text.push_str("}\n\n");
    text
}

/// The preamble's lines on the extras (none without).
pub(super) fn preamble(extras: &FloatingExtras, prefix: &str) -> Vec<String> {
    let mut lines = Vec::new();
    if extras.kinematics.is_some() {
        let upper = prefix.to_ascii_uppercase();
        lines.extend([
            String::new(),
            "The kinematics (FloatingKinematics): the centre of mass, its Jacobian, A_G and"
                .to_owned(),
            "Ad_G v, and each frame's pose [R | p], Jacobians (LOCAL_WORLD_ALIGNED, LOCAL) and"
                .to_owned(),
            format!("Jd v, one block per frame in the order of {upper}_FRAME_*."),
        ]);
    }
    if extras.contacts.is_some() {
        lines.extend([
            String::new(),
            "The contacts (FloatingContacts): a wrench [f, m] or force is what the environment"
                .to_owned(),
            "exerts on the robot at a frame's origin, in world axes; contact_dynamics holds the"
                .to_owned(),
            "origins of the frames where in_contact[f] is not 0.".to_owned(),
        ]);
    }
    if extras.configuration {
        lines.extend([
            String::new(),
            "The configuration space: integrate and difference (Pinocchio's) and their".to_owned(),
            "Jacobians (dIntegrate, dDifference); they call <math.h>'s sqrt, atan2, sin and"
                .to_owned(),
            "cos (link with -lm).".to_owned(),
        ]);
    }
    lines
}

//! One emission: the shared configuration and motion functions of a set of outputs, and each
//! output's body reading them.

use super::depends::{boundary, dependencies, shared_motion, trig_and_constants, Depends};
use super::emitter::{release_spare_tables, Emitter, Origin};
use super::expr::block;
use super::names::{output_names, Element};
use super::parts::{Body, Context, Output, Part, Shared};
use super::rows::{kept_lanes, local_layout, row_groups, solved_groups, split};
use crate::method::Argument;
use crate::symbolic::{Node, NodeId};
use crate::trace::{Equations, Shape, Solved};
use quote::quote;

/// Everything [`emit`] writes.
pub struct Emission {
    /// The shared configuration function, if any output needs one.
    pub configuration: Option<Shared>,
    /// The shared motion function, if two methods compute the same terms in `q̇`.
    pub motion: Option<Shared>,
    /// One body per output, in order.
    pub bodies: Vec<Body>,
    /// The functions of groups of rows the bodies call (`emit/rows.rs`).
    pub parts: Vec<Part>,
}

/// Emits the functions computing `outputs` from `eq`. What depends only on the parameters and
/// `q` (the trigonometry, the kinematics, `M`, `g`, the `Γ_ijk`) goes into one shared
/// configuration function; each output's body calls it and adds the terms in `q̇` and `q̈`.
/// Inlined, the compiler keeps of the shared code only what each function reads, so the run
/// time is that of separate functions, and the code is written once.
#[must_use]
pub fn emit(eq: &Equations, all: &[Output], ctx: &Context) -> Emission {
    let emission = emit_with(eq, all, ctx, &dependencies(eq));
    release_spare_tables();
    emission
}

/// `emit` with `depends`, the dependencies of `eq`'s nodes, shared by every family's emission.
pub(super) fn emit_with(
    eq: &Equations,
    all: &[Output],
    ctx: &Context,
    depends: &[Depends],
) -> Emission {
    // The shared functions take `q`: a method without it (friction) computes all it reads.
    let reads_q = |o: &&Output| o.method.arguments().contains(&Argument::Q);
    let outputs: Vec<&Output> = all.iter().filter(reads_q).collect();
    let (shared, apart_reads) = configuration_reads(eq, depends, &outputs);
    let boundary: Vec<NodeId> = eq
        .graph
        .nodes()
        .filter(|(id, _)| shared[id.index()])
        .map(|(id, _)| id)
        .collect();
    // Field names: outputs computed entirely in the configuration keep their names (`m1_2`,
    // `g3`); leaves keep theirs (`s1`, `p_m2`, `k4`); the rest are numbered temporaries.
    let mut field_names: Vec<Option<Element>> = vec![None; eq.graph.len()];
    for o in &outputs {
        let is_leaf = |id| matches!(eq.graph.node(id), Node::Var(_) | Node::Const(_));
        for (id, element) in output_names(&o.shape, o.method, is_leaf) {
            if shared[id.index()] && field_names[id.index()].is_none() {
                field_names[id.index()] = Some(element);
            }
        }
    }
    let configuration = (!boundary.is_empty()).then(|| {
        let mut e = Emitter::new(eq, Some(ctx));
        e.temporary_prefix = "u";
        e.configuration(&boundary, &field_names, depends)
    });
    // Terms in q̇ (without q̈) that two methods or more compute: written once, in the motion
    // function, whose fields the methods read.
    let motion_boundary = shared_motion(eq, depends, &outputs);
    let config_names = |e: &mut Emitter| {
        e.has_configuration = configuration.is_some();
        if let Some(c) = &configuration {
            e.read_from(&boundary, c, Origin::Configuration);
        }
    };
    let motion = (!motion_boundary.is_empty()).then(|| {
        let mut e = Emitter::new(eq, Some(ctx));
        e.temporary_prefix = "v";
        config_names(&mut e);
        e.motion(&motion_boundary, &field_names)
    });
    let tree = branches(eq);
    let body_of = |o: &Output, shape: &Shape, group: Option<Group>| {
        let mut e = Emitter::new(eq, Some(ctx));
        // A tree's lanes: each row stored once its lane is computed.
        e.returned_in_place = tree && matches!(shape, Shape::Lanes { .. });
        if let Some(group) = group {
            (e.kept, e.columns, e.rows) = (Some(group.kept), Some(group.columns), Some(group.rows));
        }
        if !reads_q(&o) {
            return e.function(shape, o.method);
        }
        if written_apart(eq, o) {
            e.has_configuration = configuration.is_some();
            if let Some(c) = &configuration {
                e.read_some_from(&boundary, c, Origin::Configuration, &apart_reads);
            }
            e.returned_in_place = true;
            return e.function(shape, o.method);
        }
        config_names(&mut e);
        if let Some(m) = &motion {
            e.read_from(&motion_boundary, m, Origin::Motion);
        }
        e.function(shape, o.method)
    };
    let (bodies, parts) = bodies(eq, ctx, all, tree, body_of);
    Emission {
        configuration,
        motion,
        bodies,
        parts,
    }
}

/// The body of each output in `all`, by `body_of` (a function of a group of rows where it is
/// given the lanes the group keeps), and the functions of groups of rows they call: a tree's
/// ∂τ in functions of groups of rows where it has several (`emit/rows.rs`).
fn bodies<'a>(
    eq: &Equations,
    ctx: &Context,
    all: &[Output<'a>],
    tree: bool,
    body_of: impl Fn(&Output<'a>, &Shape<'_>, Option<Group>) -> Body,
) -> (Vec<Body>, Vec<Part>) {
    let body = |o: &Output<'a>, shape: &Shape<'a>| body_of(o, shape, None);
    let mut parts = Vec::new();
    let bodies = all
        .iter()
        .map(|o| match (o.shape, groups(o, tree)) {
            (
                Shape::Lanes {
                    lanes: plans,
                    stack,
                    solved,
                },
                groups,
            ) if groups.len() > 1 => {
                let first = parts.len();
                parts.extend(groups.iter().enumerate().map(|(k, rows)| {
                    // Each group's lanes in its own layout of directions (`local_layout`).
                    let kept = kept_lanes(plans, rows);
                    let (local, columns) = local_layout(plans, &kept);
                    let lanes = &local;
                    // `∂q̈`'s group tests its own pivots.
                    let pivots = solved.map(|s| own_pivots(eq, s.pivots, rows));
                    let solved = solved.zip(pivots.as_deref()).map(|(s, pivots)| Solved {
                        pivots,
                        vector: s.vector,
                    });
                    let shape = Shape::Lanes {
                        stack,
                        lanes,
                        solved,
                    };
                    let group = Group {
                        kept,
                        columns,
                        rows: rows.clone(),
                    };
                    Part {
                        method: o.method,
                        index: k + 1,
                        tokens: body_of(o, &shape, Some(group)).tokens,
                        solved: solved.is_some(),
                        matrices: stack.len(),
                    }
                }));
                let lanes = split(eq, ctx, o, &parts[first..]);
                either(lanes, body(o, &o.shape.scalar()))
            }
            (Shape::Lanes { .. }, _) => either(body(o, &o.shape), body(o, &o.shape.scalar())),
            _ => body(o, &o.shape),
        })
        .collect();
    (bodies, parts)
}

/// The groups of rows of `output`'s plans on a tree (not of a method without `q`): ∂τ's where
/// fetch-bound ([`row_groups`]), ∂q̈'s, solved through M, by its independent subtrees
/// ([`solved_groups`]).
fn groups(output: &Output, tree: bool) -> Vec<Vec<bool>> {
    match output.shape {
        _ if !tree || !output.method.arguments().contains(&Argument::Q) => Vec::new(),
        Shape::Lanes {
            lanes,
            solved: None,
            ..
        } => row_groups(lanes),
        Shape::Lanes { lanes, .. } => solved_groups(lanes),
        _ => Vec::new(),
    }
}

/// The pivots of M's factors that belong to the joints of `rows`: pivot k is joint k's, or
/// joint n − 1 − k's where the factors are M's reversed (a tree's).
fn own_pivots(eq: &Equations, pivots: &[NodeId], rows: &[bool]) -> Vec<NodeId> {
    let n = pivots.len();
    let joint = |k: usize| {
        if eq.forward.factors.reversed {
            n - 1 - k
        } else {
            k
        }
    };
    let own = pivots.iter().enumerate().filter(|&(k, _)| rows[joint(k)]);
    own.map(|(_, &pivot)| pivot).collect()
}

/// A group of rows: per plan, the lanes it writes and the column of each of its directions
/// ([`local_layout`]); its rows.
struct Group {
    kept: Vec<Vec<bool>>,
    columns: Vec<Vec<usize>>,
    rows: Vec<bool>,
}

/// Tangents in lanes where the build computes them there (AVX-512), else the columns one by
/// one. The test is a constant: the compiler keeps one branch. Either branch spills vector
/// registers where `T` has lanes: the frame is kept aligned for them (`align_stack`).
fn either(mut lanes: Body, scalar: Body) -> Body {
    let a = std::mem::take(&mut lanes.tokens);
    let mut tokens = quote!(align_stack::<T>(); if T::TANGENTS_IN_LANES);
    tokens.extend([block(a), quote!(else), block(scalar.tokens)]);
    Body { tokens, ..lanes }
}

/// Whether `output` computes its terms in `q` itself, from the configuration's sines, cosines
/// and constants, storing each element as soon as it is computed: the mass matrix of a tree
/// ([`branches`]). Read from the configuration, its hundreds of
/// elements would all be computed before the first is stored, and wait on the stack.
fn written_apart(eq: &Equations, output: &Output) -> bool {
    output.method.is_mass_matrix() && branches(eq)
}

/// Whether the robot branches (its `M` factored from the tips, [`crate::algo::Ldlt`]'s
/// `reversed`).
fn branches(eq: &Equations) -> bool {
    eq.forward.factors.reversed
}

/// Per node, whether the code of `outputs` reads it from the configuration (the parameter- and
/// q-only nodes), and whether an output written apart ([`written_apart`]) does.
fn configuration_reads(
    eq: &Equations,
    depends: &[Depends],
    outputs: &[&Output],
) -> (Vec<bool>, Vec<bool>) {
    let mut shared = vec![false; eq.graph.len()];
    let mut apart_reads = vec![false; eq.graph.len()];
    for o in outputs {
        let reads = if written_apart(eq, o) {
            let reads = trig_and_constants(eq, depends, &o.shape.outputs());
            for id in &reads {
                apart_reads[id.index()] = true;
            }
            reads
        } else {
            boundary(eq, depends, &o.shape.outputs())
        };
        for id in reads {
            shared[id.index()] = true;
        }
    }
    (shared, apart_reads)
}

//! Emission: the graph's outputs become straight-line Rust.
//!
//! Everything that depends on the parameters and `q` alone (constants, struct fields, the
//! sines and cosines, the kinematics, `M`, `g`, the `Γ_ijk`) is written once, in a shared
//! *configuration* function returning a struct; each method calls it, binds the fields it reads
//! under their names (`let Configuration { s2, c2, k9, .. } = configuration(p_, q_);`), and adds
//! only its terms in `q̇` and `q̈`. The configuration function is `#[inline(always)]`, so each
//! method compiles to just the operations it needs, as if written alone, while the source holds
//! each expression once. Terms in `q̇` that two methods or more compute (the velocities and
//! Coriolis accelerations of Newton-Euler, which `C q̇`, `C q̇ + g`, `τ` and the kinetic energy
//! all need) go the same way into a *motion* function, which also computes the configuration
//! and hands both over: `let (Configuration { s2, .. }, Motion { v3, .. }) = motion(p_, q_,
//! qd_);`. A product is left to each method that reads it, which may fuse it into a
//! multiply-add.
//!
//! Within a function, only the nodes the outputs need are emitted, in the arena's order
//! (children first): the constants (`let k1: T = T::from_f64(0.42);`), the struct fields read
//! (`let [p_m1, _, p_cx1, …] = *p_;`) and the nodes that depend on them alone; then each needed
//! joint's sine and cosine, computed once, four joints side by side
//! (`let ([s1, s2, s3, s4], [c1, c2, c3, c4]) = T::sin_cos_4([q_[0], q_[1], q_[2], q_[3]]);`);
//! then the rest.
//! A node used once is written inline in its user; a node used more often gets a `let tN`
//! (`uN` in the configuration, whose names the methods bind too), numbered in order of
//! appearance; each output element gets a name saying what it is
//! (`m1_2` for M₁₂, `g3` for g₃, `tau3` for τ₃). `a + (−b)` is written `a − b`, `x·y + z` is
//! `x.mul_add(y, z)` (the runtime's `Real::mul_add`: one fused instruction where the target
//! has FMA), and parentheses appear only where precedence or the order of evaluation needs
//! them. The
//! arguments are `q_`, `qd_` and `qdd_` (a pattern cannot shadow a constant, and the trait's
//! methods, in the user's scope, take the same names); each function names the components it
//! reads as the book numbers them, `let [qd1, _, qd3] = *qd_;`.
//!
//! By job: `depends` (what each node depends on, hence which function computes it),
//! `emitter` (one function's state), `expr` (expressions and parentheses), `sum_order` (the
//! order of a sum's additions), `inputs` (joint variables, sines and cosines), `shared` (the
//! configuration and motion functions), `body` (a method's body), `names` (output elements),
//! `count` (operation counts), `items` (the derive's items: the families' modules, the
//! parameters' reader), `impls` (the trait impls: signatures, calls into the modules),
//! `fallback` (the expansion of a failed derive), `equations` (the readable equations'
//! constants).

mod body;
mod count;
mod depends;
mod emitter;
mod equations;
mod expr;
mod fallback;
mod impls;
mod inputs;
mod items;
mod names;
mod shared;
mod sum_order;

pub use count::{count, OpCount};
pub(crate) use equations::readable;
pub(crate) use fallback::fallback;
pub use impls::method;
pub(crate) use impls::runtime_path;
pub use items::{generate, Generated, Items, MethodCode, Module};

use crate::method::{Argument, Method};
use crate::symbolic::NodeId;
use crate::trace::Equations;
use depends::{boundary, dependencies, shared_motion};
use emitter::{Emitter, Origin};
use names::Element;
use proc_macro2::{Span, TokenStream};

/// An emitted function body.
pub struct Body {
    /// The statements and the result expression.
    pub tokens: TokenStream,
    /// Its operations, shared code included.
    pub ops: OpCount,
}

/// The shape of a function's result.
#[derive(Clone, Copy)]
pub enum Shape<'a> {
    /// A scalar.
    Scalar(NodeId),
    /// A vector.
    Vector(&'a [NodeId]),
    /// A matrix, rows first.
    Matrix(&'a [Vec<NodeId>]),
    /// Matrices, one after the other.
    Stack(&'a [Vec<Vec<NodeId>>]),
    /// A vector through the LDLᵀ of M, `Some` where every pivot is positive.
    SolvedVector {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The vector.
        vector: &'a [NodeId],
    },
    /// A matrix through the LDLᵀ of M, `Some` where every pivot is positive.
    SolvedMatrix {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The matrix, rows first.
        matrix: &'a [Vec<NodeId>],
    },
    /// A vector and matrices through the LDLᵀ of M, `Some((vector, [matrices]))` where every
    /// pivot is positive.
    SolvedStack {
        /// The pivots.
        pivots: &'a [NodeId],
        /// The vector.
        vector: &'a [NodeId],
        /// The matrices, rows first.
        stack: &'a [Vec<Vec<NodeId>>],
    },
}

impl Shape<'_> {
    /// Its elements, rows first.
    pub fn outputs(&self) -> Vec<NodeId> {
        match self {
            Shape::Scalar(id) => vec![*id],
            Shape::Vector(v) => v.to_vec(),
            Shape::Matrix(m) => m.iter().flatten().copied().collect(),
            Shape::Stack(s) => s.iter().flatten().flatten().copied().collect(),
            Shape::SolvedVector { pivots, vector } => {
                pivots.iter().chain(*vector).copied().collect()
            }
            Shape::SolvedMatrix { pivots, matrix } => {
                let elements = matrix.iter().flatten();
                pivots.iter().chain(elements).copied().collect()
            }
            Shape::SolvedStack {
                pivots,
                vector,
                stack,
            } => {
                let elements = stack.iter().flatten().flatten();
                let values = vector.iter().chain(elements);
                pivots.iter().chain(values).copied().collect()
            }
        }
    }
}

/// Where emitted code finds the robot's parameters.
pub struct Context {
    /// The array `[T; N]` of the parameters, in the order of [`Equations::fields`] (`p_`).
    pub parameters: proc_macro2::Ident,
}

/// A name the generated code binds (see [`Generated::items`] for why no user item can
/// take its place).
pub fn local(name: &str) -> proc_macro2::Ident {
    proc_macro2::Ident::new(name, Span::mixed_site())
}

/// One output of [`emit`]: the method returning it, which names its elements (`m1_2`,
/// `tau3`), and its shape.
pub struct Output<'a> {
    /// The method.
    pub method: Method,
    /// Shape.
    pub shape: Shape<'a>,
}

/// Code shared by several functions, computed by one inlined function and handed over as a
/// struct: the configuration (what depends on the parameters and `q` alone) and the motion
/// (what several methods compute from `q̇` too).
pub struct Shared {
    /// The struct's fields, in order.
    pub fields: Vec<proc_macro2::Ident>,
    /// The function's body, ending in the struct literal.
    pub tokens: TokenStream,
}

/// Everything [`emit`] writes.
pub struct Emission {
    /// The shared configuration function, if any output needs one.
    pub configuration: Option<Shared>,
    /// The shared motion function, if two methods compute the same terms in `q̇`.
    pub motion: Option<Shared>,
    /// One body per output, in order.
    pub bodies: Vec<Body>,
}

/// Name of the configuration struct.
pub const CONFIGURATION_STRUCT: &str = "Configuration";
/// Name of the function computing it, `configuration(p_, q_)`.
pub const CONFIGURATION_FN: &str = "configuration";
/// Name of the struct of terms in `q̇` that several methods share.
pub const MOTION_STRUCT: &str = "Motion";
/// Name of the function computing it with the configuration, `motion(p_, q_, qd_)`.
pub const MOTION_FN: &str = "motion";
/// Name of the local holding the configuration in the motion function.
pub const CONFIGURATION_LOCAL: &str = "c_";
/// Name of the argument holding the robot's parameters, `[T; K]` in the order of
/// [`Equations::fields`].
pub const PARAMETERS: &str = "p_";

/// Emits the functions computing `outputs` from `eq`. What depends only on the parameters and
/// `q` (the trigonometry, the kinematics, `M`, `g`, the `Γ_ijk`) goes into one shared
/// configuration function; each output's body calls it and adds the terms in `q̇` and `q̈`.
/// Inlined, the compiler keeps of the shared code only what each function reads, so the run
/// time is that of separate functions, and the code is written once.
#[must_use]
pub fn emit(eq: &Equations, all: &[Output], ctx: &Context) -> Emission {
    let depends = dependencies(eq);
    // The shared functions take `q`: a method without it (friction) computes all it reads.
    let reads_q = |o: &&Output| o.method.arguments().contains(&Argument::Q);
    let outputs: Vec<&Output> = all.iter().filter(reads_q).collect();
    // Per output, the parameter- and q-only nodes its own code reads.
    let mut shared = vec![false; eq.graph.len()];
    for o in &outputs {
        for id in boundary(eq, &depends, &o.shape.outputs()) {
            shared[id.index()] = true;
        }
    }
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
        let e = Emitter::new(eq, Some(ctx));
        for (id, element) in e.output_names(&o.shape, o.method) {
            if shared[id.index()] && field_names[id.index()].is_none() {
                field_names[id.index()] = Some(element);
            }
        }
    }
    let configuration = (!boundary.is_empty()).then(|| {
        let mut e = Emitter::new(eq, Some(ctx));
        e.temporary_prefix = "u";
        e.configuration(&boundary, &field_names)
    });
    // Terms in q̇ (without q̈) that two methods or more compute: written once, in the motion
    // function, whose fields the methods read.
    let motion_boundary = shared_motion(eq, &depends, &outputs);
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
    let bodies = all
        .iter()
        .map(|o| {
            let mut e = Emitter::new(eq, Some(ctx));
            if !reads_q(&o) {
                return e.function(&o.shape, o.method);
            }
            config_names(&mut e);
            if let Some(m) = &motion {
                e.read_from(&motion_boundary, m, Origin::Motion);
            }
            e.function(&o.shape, o.method)
        })
        .collect();
    Emission {
        configuration,
        motion,
        bodies,
    }
}

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

use crate::derive::Equations;
use crate::symbolic::{Graph, Node, NodeId, Var};
use proc_macro2::{Span, TokenStream};
use quote::quote;

/// Operation counts of an emitted function.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCount {
    /// Multiplications.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
    /// Negations.
    pub neg: usize,
    /// Divisions.
    pub div: usize,
    /// Sine and cosine evaluations (a `sin_cos` pair counts 2).
    pub trig: usize,
    /// The longest chain of dependent multiplications, additions and divisions from the inputs
    /// (the joint variables, their sines and cosines, the parameters) to a result, each sum
    /// added in the order the emitted code adds it: the operations that cannot overlap, which
    /// bound the time of a call from below as the count bounds its throughput.
    pub depth: usize,
}

/// An emitted function body.
pub struct Body {
    /// The statements and the result expression.
    pub tokens: TokenStream,
    /// Its operations, shared code included.
    pub ops: OpCount,
}

impl OpCount {
    /// Multiplications, additions and negations together.
    #[must_use]
    pub fn flops(&self) -> usize {
        self.mul + self.add + self.neg + self.div
    }
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
}

impl Shape<'_> {
    fn outputs(&self) -> Vec<NodeId> {
        match self {
            Shape::Scalar(id) => vec![*id],
            Shape::Vector(v) => v.to_vec(),
            Shape::Matrix(m) => m.iter().flatten().copied().collect(),
        }
    }
}

/// Where emitted code finds the robot's parameters.
pub struct Context {
    /// The array `[T; N]` of the parameters, in the order of [`Equations::fields`] (`p_`).
    pub parameters: proc_macro2::Ident,
}

/// A name the generated code binds (see [`crate::Generated::items`] for why no user item can
/// take its place).
pub fn local(name: &str) -> proc_macro2::Ident {
    proc_macro2::Ident::new(name, Span::mixed_site())
}

/// One output of [`emit`]: the prefix of its element names (`m` gives `m1_2`, `tau` gives
/// `tau3`) and its shape.
pub struct Output<'a> {
    /// Element name prefix.
    pub prefix: &'a str,
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
pub fn emit(eq: &Equations, outputs: &[Output], ctx: &Context) -> Emission {
    let class = classes(eq);
    // Per output, the parameter- and q-only nodes its own code reads.
    let mut shared = vec![false; eq.graph.len()];
    for o in outputs {
        for id in boundary(eq, &class, &o.shape.outputs()) {
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
    let mut field_names: Vec<Option<String>> = vec![None; eq.graph.len()];
    for o in outputs {
        let e = Emitter::new(eq, Some(ctx));
        for (id, name) in e.output_names(&o.shape, o.prefix) {
            if shared[id.index()] && field_names[id.index()].is_none() {
                field_names[id.index()] = Some(name);
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
    let motion_boundary = shared_motion(eq, &class, outputs);
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
    let bodies = outputs
        .iter()
        .map(|o| {
            let mut e = Emitter::new(eq, Some(ctx));
            config_names(&mut e);
            if let Some(m) = &motion {
                e.read_from(&motion_boundary, m, Origin::Motion);
            }
            e.function(&o.shape, o.prefix)
        })
        .collect();
    Emission {
        configuration,
        motion,
        bodies,
    }
}

/// The terms in `q̇` (class 2) that the code of two outputs or more computes, as the nodes the
/// rest of each output's code reads of them, in the arena's order.
fn shared_motion(eq: &Equations, class: &[u8], outputs: &[Output]) -> Vec<NodeId> {
    let e = Emitter::new(eq, None);
    let n = eq.graph.len();
    // Per node, how many outputs' code computes it.
    let mut users = vec![0u32; n];
    let walk = |outs: Vec<NodeId>, shared: Option<&[u32]>, found: &mut Vec<bool>| {
        let mut seen = vec![false; n];
        let mut stack = outs;
        while let Some(id) = stack.pop() {
            let i = id.index();
            if class[i] < 2 || e.is_leaf(id) || std::mem::replace(&mut seen[i], true) {
                continue;
            }
            // A product stays with its user, which may fuse it into a multiply-add.
            let product = matches!(eq.graph.node(id), Node::Mul(..));
            if !product && shared.is_some_and(|u| u[i] >= 2 && class[i] == 2) {
                found[i] = true;
                continue;
            }
            stack.extend(e.operands(id));
        }
        seen
    };
    let mut unused = vec![false; n];
    for o in outputs {
        for (i, seen) in walk(o.shape.outputs(), None, &mut unused)
            .into_iter()
            .enumerate()
        {
            users[i] += u32::from(seen);
        }
    }
    let mut found = vec![false; n];
    for o in outputs {
        walk(o.shape.outputs(), Some(&users), &mut found);
    }
    eq.graph
        .nodes()
        .filter(|(id, _)| found[id.index()])
        .map(|(id, _)| id)
        .collect()
}

/// What a node depends on: 0 for parameters and constants only, 1 for `q` too, 2 for `q̇`,
/// 3 for `q̈`.
fn classes(eq: &Equations) -> Vec<u8> {
    let e = Emitter::new(eq, None);
    let mut class = vec![0u8; eq.graph.len()];
    for (id, node) in eq.graph.nodes() {
        class[id.index()] = match node {
            Node::Var(Var::Param(_)) | Node::Const(_) => 0,
            Node::Var(Var::Qd(_)) => 2,
            Node::Var(Var::Qdd(_)) => 3,
            Node::Var(Var::Q(_)) => 1,
            _ => e
                .operands(id)
                .iter()
                .map(|c| class[c.index()])
                .max()
                .unwrap_or(1)
                .max(u8::from(matches!(
                    node,
                    Node::Var(Var::SinQ(_) | Var::CosQ(_))
                ))),
        };
    }
    class
}

/// The nodes without `q̇` and `q̈` that the code of `outputs` reads: outputs of class ≤ 1 and
/// operands of its class-2 and class-3 nodes, except zero, one and `q_i`, which are written in
/// place.
fn boundary(eq: &Equations, class: &[u8], outputs: &[NodeId]) -> Vec<NodeId> {
    let e = Emitter::new(eq, None);
    let mut seen = vec![false; eq.graph.len()];
    let mut found = Vec::new();
    let mut stack = outputs.to_vec();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut seen[id.index()], true) {
            continue;
        }
        if class[id.index()] >= 2 {
            stack.extend(e.operands(id));
        } else if !matches!(eq.graph.node(id), Node::Var(Var::Q(_)))
            && !matches!(eq.graph.node(id), Node::Const(c) if c.is_zero() || c.is_one())
        {
            found.push(id);
        }
    }
    found
}

/// A partial sum while [`Emitter::sum`] combines the terms of a sum: a term not yet written,
/// or written code and what it ends in (which decides the parentheses around it).
enum Part {
    Term(NodeId),
    Call(TokenStream),
    Sum(TokenStream),
}

/// Latencies in cycles, roughly those of current x86-64 and aarch64 cores, by which
/// [`sum_order`] weighs the orders of a sum's additions.
const ADD_LATENCY: u32 = 3;
/// See [`ADD_LATENCY`].
const MUL_LATENCY: u32 = 3;
/// See [`ADD_LATENCY`].
const FMA_LATENCY: u32 = 4;

/// A term of a sum for [`sum_order`]: ready after `depth` operations (a product's own
/// included), subtracted or added, and whether it is a product that a fused multiply-add can
/// take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct SumTerm {
    depth: u32,
    negative: bool,
    fusable: bool,
}

/// One addition of [`sum_order`]: partial sums `a` and `b` (indices: the terms, then each
/// addition's result in turn), with `b` a product that a fused multiply-add takes if `fused`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Addition {
    a: usize,
    b: usize,
    fused: bool,
}

/// The order in which the terms of a sum are added: repeatedly the two that are ready first
/// (the first in the list among equals), as in Huffman's algorithm with the maximum in place
/// of the sum, weighed in cycles ([`ADD_LATENCY`]). A pair is one fused multiply-add if either
/// is a fusable product, which is then ready when its operands are: of two products, the
/// negative one if their signs differ, else the one whose operands come later. (Either sign
/// fuses, [`Emitter::combine`] negating an operand; fusing the negative one measured faster:
/// the random 6-joint robot's τ 82.2 ns against 83.3 by the operands alone.) Gives the additions and the sum's depth in operations (a fused
/// multiply-add counting two, as in the flop counts).
///
/// Every order of n terms takes n − 1 additions. This one makes the last wait little, where
/// the order in which the algorithm met the terms may start with the latest and carry it
/// through all the others, and a chain of n terms ready together waits n − 1 operations where
/// pairs wait about log₂ n. The random 6-joint robot: τ 87.5 → 82.2 ns, C 161 → 145 ns.
fn sum_order(terms: &[SumTerm]) -> (Vec<Addition>, u32) {
    #[derive(Clone, Copy)]
    struct Partial {
        cycles: u32,
        index: usize,
        depth: u32,
        negative: bool,
        /// When a fusable product's operands are ready.
        operands: Option<u32>,
    }
    let mut ready: Vec<Partial> = terms
        .iter()
        .zip(0..)
        .map(|(t, index)| {
            let cycles = ADD_LATENCY * t.depth;
            Partial {
                cycles,
                index,
                depth: t.depth,
                negative: t.negative,
                operands: t.fusable.then(|| cycles.saturating_sub(MUL_LATENCY)),
            }
        })
        .collect();
    let mut additions = Vec::with_capacity(terms.len().saturating_sub(1));
    while ready.len() > 1 {
        ready.sort_unstable_by_key(|p| (p.cycles, p.index));
        let (x, y) = (ready.remove(0), ready.remove(0));
        let (a, b) = match (x.operands, y.operands) {
            (Some(_), Some(_)) if x.negative != y.negative => {
                if x.negative {
                    (y, x)
                } else {
                    (x, y)
                }
            }
            (Some(i), Some(j)) if i > j => (y, x),
            (Some(_), None) => (y, x),
            _ => (x, y),
        };
        let fused = b.operands.is_some();
        let (cycles, depth, negative) = if fused {
            let cycles = a.cycles.max(b.operands.unwrap_or(b.cycles)) + FMA_LATENCY;
            (cycles, 1 + a.depth.max(b.depth), a.negative && b.negative)
        } else {
            let cycles = a.cycles.max(b.cycles) + ADD_LATENCY;
            (cycles, 1 + a.depth.max(b.depth), a.negative && b.negative)
        };
        additions.push(Addition {
            a: a.index,
            b: b.index,
            fused,
        });
        ready.push(Partial {
            cycles,
            index: terms.len() + additions.len() - 1,
            depth,
            negative,
            operands: None,
        });
    }
    (additions, ready.first().map_or(0, |p| p.depth))
}

/// Operation counts of the code computing `outputs`, shared parts included: what a function
/// costs once the compiler has inlined the configuration and dropped what it does not read.
#[must_use]
pub fn count(eq: &Equations, outputs: &[NodeId]) -> OpCount {
    let mut e = Emitter::new(eq, None);
    e.mark(outputs);
    let mut ops = OpCount::default();
    for &o in outputs {
        ops.depth = ops.depth.max(e.depth(o) as usize);
    }
    for (id, node) in eq.graph.nodes() {
        if !e.needed[id.index()] {
            continue;
        }
        match node {
            Node::Add(..) => ops.add += 1,
            Node::Mul(..) => ops.mul += 1,
            Node::Neg(_) => ops.neg += 1,
            Node::Recip(_) => ops.div += 1,
            Node::Sin(_) | Node::Cos(_) | Node::Var(Var::SinQ(_) | Var::CosQ(_)) => ops.trig += 1,
            Node::Const(_) | Node::Var(_) => {}
        }
    }
    ops
}

/// Where an expression is written, which decides whether it needs parentheses.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Place {
    /// A statement's right-hand side or an array element.
    Top,
    /// Left of `+` or `−`.
    AddLeft,
    /// Right of `+` or `−`.
    AddRight,
    /// Left of `*`.
    MulLeft,
    /// Right of `*` or `/`, or under a unary minus.
    MulRight,
    /// Before a method call's dot.
    Receiver,
}

/// Where a node read by a function is computed.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Origin {
    /// In the function itself.
    Here,
    /// In the configuration.
    Configuration,
    /// In the motion.
    Motion,
}

struct Emitter<'a> {
    graph: &'a Graph,
    eq: &'a Equations,
    ctx: Option<&'a Context>,
    uses: Vec<u32>,
    needed: Vec<bool>,
    /// What each bound node (and each constant) is read as: a local, or a field of the
    /// configuration.
    names: Vec<Option<TokenStream>>,
    /// Nodes computed elsewhere (the configuration's and the motion's fields): marking stops there.
    stop: Vec<bool>,
    /// Which shared function computes a stop node.
    origin: Vec<Origin>,
    temporaries: usize,
    /// `t` in a method, `u` in the configuration and `v` in the motion, whose fields a method
    /// binds as locals too.
    temporary_prefix: &'static str,
    /// Whether there is a configuration function (the motion function takes its result).
    has_configuration: bool,
    /// Each node's number of dependent operations as emitted ([`Emitter::depth`]), once
    /// asked for (`u32::MAX` before).
    depth: Vec<u32>,
}

impl<'a> Emitter<'a> {
    fn new(eq: &'a Equations, ctx: Option<&'a Context>) -> Emitter<'a> {
        let n = eq.graph.len();
        Emitter {
            graph: &eq.graph,
            eq,
            ctx,
            uses: vec![0; n],
            needed: vec![false; n],
            names: vec![None; n],
            stop: vec![false; n],
            origin: vec![Origin::Here; n],
            temporaries: 0,
            temporary_prefix: "t",
            has_configuration: false,
            depth: vec![u32::MAX; n],
        }
    }

    /// Reads the nodes `computed` from the fields of `shared` (by `origin`): by name, without
    /// computing them.
    fn read_from(&mut self, computed: &[NodeId], shared: &Shared, origin: Origin) {
        for (&id, field) in computed.iter().zip(&shared.fields) {
            let local = local(&field.to_string());
            self.names[id.index()] = Some(quote!(#local));
            self.stop[id.index()] = true;
            self.origin[id.index()] = origin;
        }
    }

    /// The nodes an emitted node reads, with `a + (−b)` read as `a − b`.
    fn operands(&self, id: NodeId) -> Vec<NodeId> {
        match self.graph.node(id) {
            Node::Add(a, b) => {
                let (a, b) = self.as_sub(a, b).unwrap_or((a, b));
                vec![a, b]
            }
            Node::Mul(a, b) => vec![a, b],
            Node::Neg(a) | Node::Recip(a) | Node::Sin(a) | Node::Cos(a) => vec![a],
            Node::Var(Var::SinQ(i) | Var::CosQ(i)) => {
                self.eq.angle_offsets[usize::from(i)].into_iter().collect()
            }
            Node::Const(_) | Node::Var(_) => vec![],
        }
    }

    /// `(a, x)` if `a + b` is `a − x`.
    fn as_sub(&self, a: NodeId, b: NodeId) -> Option<(NodeId, NodeId)> {
        match (self.graph.node(a), self.graph.node(b)) {
            (_, Node::Neg(x)) => Some((a, x)),
            (Node::Neg(x), _) => Some((b, x)),
            _ => None,
        }
    }

    fn mark(&mut self, outputs: &[NodeId]) {
        let mut stack = outputs.to_vec();
        for &o in outputs {
            self.uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut self.needed[id.index()], true) || self.stop[id.index()] {
                continue;
            }
            for c in self.operands(id) {
                self.uses[c.index()] += 1;
                stack.push(c);
            }
        }
    }

    fn is_leaf(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Var(_) | Node::Const(_))
    }

    /// A constant other than 0 and 1, which gets its own `let kN`.
    fn is_named_constant(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Const(c) if !c.is_zero() && !c.is_one())
    }

    fn leaf(&self, id: NodeId) -> TokenStream {
        if let Some(name) = &self.names[id.index()] {
            return name.clone();
        }
        match self.graph.node(id) {
            Node::Const(c) if c.is_zero() => quote!(T::ZERO),
            Node::Const(c) if c.is_one() => quote!(T::ONE),
            Node::Const(c) => {
                let x = c.to_f64();
                // A literal cannot spell a non-finite value (and the literal constructor
                // panics on one); such a constant can only come from overflowing arithmetic
                // of finite parameters.
                let value = if x.is_nan() {
                    quote!(::core::f64::NAN)
                } else if x.is_infinite() && x > 0.0 {
                    quote!(::core::f64::INFINITY)
                } else if x.is_infinite() {
                    quote!(::core::f64::NEG_INFINITY)
                } else {
                    let lit = proc_macro2::Literal::f64_unsuffixed(x);
                    quote!(#lit)
                };
                quote!(T::from_f64(#value))
            }
            Node::Var(Var::Q(i)) => {
                let q = local(&format!("q{}", i + 1));
                quote!(#q)
            }
            Node::Var(Var::Qd(i)) => {
                let qd = local(&format!("qd{}", i + 1));
                quote!(#qd)
            }
            Node::Var(Var::Qdd(i)) => {
                let qdd = local(&format!("qdd{}", i + 1));
                quote!(#qdd)
            }
            Node::Var(Var::SinQ(i)) => {
                let s = local(&format!("s{}", i + 1));
                quote!(#s)
            }
            Node::Var(Var::CosQ(i)) => {
                let c = local(&format!("c{}", i + 1));
                quote!(#c)
            }
            Node::Var(Var::Param(k)) => {
                let p = local(&format!("p_{}", self.eq.fields[usize::from(k)]));
                quote!(#p)
            }
            _ => quote!(),
        }
    }

    /// A node's expression at `place`: its name if it has one, else written out, in
    /// parentheses where the place needs them.
    fn expr(&mut self, id: NodeId, place: Place) -> TokenStream {
        if self.is_leaf(id) {
            return self.leaf(id);
        }
        if let Some(name) = &self.names[id.index()] {
            return name.clone();
        }
        if self.is_sum(id) {
            // A fused multiply-add is a method call, which needs no parentheses.
            let (e, call) = self.sum(id);
            return if call || place == Place::Top || place == Place::AddLeft {
                e
            } else {
                quote!((#e))
            };
        }
        let wrap = match self.graph.node(id) {
            Node::Mul(..) | Node::Recip(_) => place == Place::MulRight || place == Place::Receiver,
            Node::Neg(_) => matches!(place, Place::MulRight | Place::AddRight | Place::Receiver),
            _ => false,
        };
        let e = self.define(id);
        if wrap {
            quote!((#e))
        } else {
            e
        }
    }

    /// Whether node `c` is written where it is read, not bound to a name: read once.
    fn in_place(&self, c: NodeId) -> bool {
        self.names[c.index()].is_none() && self.uses[c.index()] <= 1
    }

    /// The terms of the sum `id` with their signs (`true`: subtracted), through the sums and
    /// negated sums written in place.
    fn sum_terms(&self, id: NodeId, negative: bool, terms: &mut Vec<(NodeId, bool)>) {
        let Node::Add(a, b) = self.graph.node(id) else {
            terms.push((id, negative));
            return;
        };
        // The operands as `operands` reads them: `a + (−x)` reads `a` and `x`.
        let (a, b, b_negative) = match self.as_sub(a, b) {
            Some((a, x)) => (a, x, !negative),
            None => (a, b, negative),
        };
        for (c, negative) in [(a, negative), (b, b_negative)] {
            let (c, negative) = match self.graph.node(c) {
                Node::Neg(x) if self.in_place(c) => (x, !negative),
                _ => (c, negative),
            };
            match self.graph.node(c) {
                Node::Add(..) if self.in_place(c) => self.sum_terms(c, negative, terms),
                _ => terms.push((c, negative)),
            }
        }
    }

    /// Whether `id` is written as a sum: a sum, or a negated sum written in place, whose terms
    /// then change sign (`−(a − x·y)` is written `x.mul_add(y, −a)`, not negated again).
    fn is_sum(&self, id: NodeId) -> bool {
        match self.graph.node(id) {
            Node::Add(..) => true,
            Node::Neg(a) => matches!(self.graph.node(a), Node::Add(..)) && self.in_place(a),
            _ => false,
        }
    }

    /// The terms of the sum [`Emitter::is_sum`] `id` with their signs, and as [`sum_order`]
    /// weighs them.
    fn sum_terms_with_depth(&mut self, id: NodeId) -> (Vec<(NodeId, bool)>, Vec<SumTerm>) {
        let mut terms = Vec::new();
        match self.graph.node(id) {
            Node::Neg(a) => self.sum_terms(a, true, &mut terms),
            _ => self.sum_terms(id, false, &mut terms),
        }
        let weighed = terms
            .iter()
            .map(|&(t, negative)| SumTerm {
                depth: self.depth(t),
                negative,
                fusable: self.fusable(t),
            })
            .collect();
        (terms, weighed)
    }

    /// Whether `t` is a product written in place, which a fused multiply-add can take.
    fn fusable(&self, t: NodeId) -> bool {
        matches!(self.graph.node(t), Node::Mul(..)) && self.in_place(t)
    }

    /// The number of dependent operations from the inputs to node `id` as emitted, each sum
    /// added in [`sum_order`]. A fused multiply-add counts as its two operations, as in the
    /// flop counts; a negation folds into what reads it.
    fn depth(&mut self, id: NodeId) -> u32 {
        if self.depth[id.index()] != u32::MAX {
            return self.depth[id.index()];
        }
        let d = match self.graph.node(id) {
            Node::Add(..) => {
                let (_, depths) = self.sum_terms_with_depth(id);
                sum_order(&depths).1
            }
            Node::Mul(a, b) => 1 + self.depth(a).max(self.depth(b)),
            Node::Recip(a) | Node::Sin(a) | Node::Cos(a) => 1 + self.depth(a),
            Node::Neg(a) => self.depth(a),
            Node::Const(_) | Node::Var(_) => 0,
        };
        self.depth[id.index()] = d;
        d
    }

    /// The sum `id` written in [`sum_order`], through the sums written in place
    /// ([`Emitter::sum_terms`]): `a + b`, `a − b` and `x.mul_add(y, a)`; `true` if it ends in
    /// `mul_add` (a method call, which needs no parentheses).
    fn sum(&mut self, id: NodeId) -> (TokenStream, bool) {
        let (terms, depths) = self.sum_terms_with_depth(id);
        let (additions, _) = sum_order(&depths);
        let mut parts: Vec<Option<(Part, bool)>> = terms
            .iter()
            .map(|&(t, negative)| Some((Part::Term(t), negative)))
            .collect();
        for addition in additions {
            let (a, b) = (parts[addition.a].take(), parts[addition.b].take());
            let (Some(a), Some(b)) = (a, b) else {
                unreachable!("each partial sum is added once");
            };
            parts.push(Some(self.combine(a, b, addition.fused)));
        }
        let Some(Some((root, negative))) = parts.pop() else {
            unreachable!("a sum has terms");
        };
        match (root, negative) {
            (Part::Call(e), false) => (e, true),
            (root, false) => (self.part(root, Place::Top), false),
            (root, true) => {
                let e = self.part(root, Place::MulRight);
                (quote!(-#e), false)
            }
        }
    }

    /// Two partial sums with their signs (`true`: negative) added: if `fused`, `b` is a
    /// product written in place, `±x·y`, and the sum is `x.mul_add(y, a)` with the sign of both
    /// if they have the same, else `(-x).mul_add(y, a)` or `x.mul_add(y, -a)`, positive (a
    /// negated operand of `mul_add` costs nothing: x86-64 and aarch64 have fused forms with
    /// either sign, and without FMA `−x·y + a` is `a − x·y`); else `a + b` or `a − b`.
    fn combine(&mut self, a: (Part, bool), b: (Part, bool), fused: bool) -> (Part, bool) {
        let product = match b.0 {
            Part::Term(t) if fused => match self.graph.node(t) {
                Node::Mul(x, y) => Some((x, y)),
                _ => None,
            },
            _ => None,
        };
        let Some((x, y)) = product else {
            return match (a.1, b.1) {
                (false, true) => (Part::Sum(self.difference(a.0, b.0)), false),
                (true, false) => (Part::Sum(self.difference(b.0, a.0)), false),
                (negative, _) => {
                    let (a, b) = (
                        self.part(a.0, Place::AddLeft),
                        self.part(b.0, Place::AddRight),
                    );
                    (Part::Sum(quote!(#a + #b)), negative)
                }
            };
        };
        let x = if b.1 && !a.1 {
            let x = self.expr(x, Place::MulRight);
            quote!((-#x))
        } else {
            self.expr(x, Place::Receiver)
        };
        let y = self.expr(y, Place::Top);
        let rest = if a.1 && !b.1 {
            let rest = self.part(a.0, Place::MulRight);
            quote!(-#rest)
        } else {
            self.part(a.0, Place::Top)
        };
        (Part::Call(quote!(#x.mul_add(#y, #rest))), a.1 && b.1)
    }

    /// `a − b`.
    fn difference(&mut self, a: Part, b: Part) -> TokenStream {
        let (a, b) = (self.part(a, Place::AddLeft), self.part(b, Place::AddRight));
        quote!(#a - #b)
    }

    /// A partial sum written at `place`.
    fn part(&mut self, part: Part, place: Place) -> TokenStream {
        let wrap = |e: TokenStream| quote!((#e));
        match part {
            Part::Term(t) => self.expr(t, place),
            Part::Call(e) => e,
            Part::Sum(e) if matches!(place, Place::Top | Place::AddLeft) => e,
            Part::Sum(e) => wrap(e),
        }
    }

    fn define(&mut self, id: NodeId) -> TokenStream {
        if self.is_sum(id) {
            return self.sum(id).0;
        }
        match self.graph.node(id) {
            Node::Add(..) => unreachable!("a sum is written by `sum`"),
            Node::Mul(a, b) => {
                let (a, b) = (self.expr(a, Place::MulLeft), self.expr(b, Place::MulRight));
                quote!(#a * #b)
            }
            Node::Neg(a) => {
                let a = self.expr(a, Place::MulRight);
                quote!(-#a)
            }
            Node::Recip(a) => {
                let a = self.expr(a, Place::MulRight);
                quote!(T::ONE / #a)
            }
            Node::Sin(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::sin(#a))
            }
            Node::Cos(a) => {
                let a = self.expr(a, Place::Top);
                quote!(T::cos(#a))
            }
            Node::Const(_) | Node::Var(_) => self.leaf(id),
        }
    }

    /// `let name = expr;` for node `id`, which from then on is read by its name; an output
    /// element gets a one-line doc comment saying what it is, which `cargo expand` shows.
    fn bind(&mut self, id: NodeId, name: proc_macro2::Ident) -> TokenStream {
        let e = self.define(id);
        self.names[id.index()] = Some(quote!(#name));
        match describe(&name.to_string()) {
            Some(doc) => {
                let doc = format!(" {doc}");
                quote!(#[doc = #doc] let #name = #e;)
            }
            None => quote!(let #name = #e;),
        }
    }

    fn temporary(&mut self) -> proc_macro2::Ident {
        self.temporaries += 1;
        local(&format!("{}{}", self.temporary_prefix, self.temporaries))
    }

    /// The names of the output elements, by node; an element equal to an earlier one (M's
    /// lower triangle) keeps the earlier name.
    fn output_names(&self, shape: &Shape, output: &str) -> Vec<(NodeId, String)> {
        let mut named: Vec<(NodeId, String)> = Vec::new();
        let mut add = |id: NodeId, name: String| {
            if !self.is_leaf(id) && !named.iter().any(|(n, _)| *n == id) {
                named.push((id, name));
            }
        };
        match shape {
            Shape::Scalar(id) => add(*id, output.to_owned()),
            Shape::Vector(v) => {
                for (i, &id) in v.iter().enumerate() {
                    add(id, format!("{output}{}", i + 1));
                }
            }
            Shape::Matrix(m) => {
                for (i, row) in m.iter().enumerate() {
                    for (j, &id) in row.iter().enumerate() {
                        add(id, format!("{output}{}_{}", i + 1, j + 1));
                    }
                }
            }
        }
        named
    }

    /// The body of the configuration function: computes `boundary` and returns it as the
    /// configuration struct, each node under its field name where `field_names` has one.
    fn configuration(&mut self, boundary: &[NodeId], field_names: &[Option<String>]) -> Shared {
        let ctx = self.ctx.expect("emission has a context");
        self.mark(boundary);
        let mut statements = Vec::new();
        // Constants, once each.
        let mut constants = 0;
        for (id, _) in self.graph.nodes() {
            if self.needed[id.index()] && self.is_named_constant(id) {
                let value = self.leaf(id);
                constants += 1;
                let k = local(&format!("k{constants}"));
                statements.push(quote!(let #k: T = #value;));
                self.names[id.index()] = Some(quote!(#k));
            }
        }
        // Parameters, read once: `let [p_m1, _, p_cx1, …] = *p_;`.
        let mut parameters = vec![quote!(_); self.eq.fields.len()];
        let mut any = false;
        for (id, node) in self.graph.nodes() {
            if let Node::Var(Var::Param(k)) = node {
                if self.needed[id.index()] {
                    parameters[usize::from(k)] = self.leaf(id);
                    any = true;
                }
            }
        }
        if any {
            let array = &ctx.parameters;
            statements.push(quote!(let [#(#parameters),*] = *#array;));
        }
        let class = classes(self.eq);
        statements.extend(self.joint_variables());
        for phase in [0, 1] {
            if phase == 1 {
                self.sines_and_cosines(&mut statements);
            }
            self.bind_shared_nodes(
                &|i| class[i] == phase,
                boundary,
                field_names,
                &mut statements,
            );
        }
        // The struct literal, one field per boundary node, named as its local.
        let locals: Vec<TokenStream> = boundary.iter().map(|&id| self.leaf(id)).collect();
        let fields = locals
            .iter()
            .map(|l| proc_macro2::Ident::new(&l.to_string(), Span::call_site()))
            .collect();
        let ty = proc_macro2::Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        Shared {
            fields,
            tokens: quote!(#(#statements)* #ty { #(#locals),* }),
        }
    }

    /// `let name = …;` for each needed node that `select` admits (by index) and that is read
    /// more than once or handed over (in `boundary`), in the arena's order, under its name in
    /// `field_names` or a new temporary.
    fn bind_shared_nodes(
        &mut self,
        select: &dyn Fn(usize) -> bool,
        boundary: &[NodeId],
        field_names: &[Option<String>],
        statements: &mut Vec<TokenStream>,
    ) {
        let mut handed_over = vec![false; self.graph.len()];
        for id in boundary {
            handed_over[id.index()] = true;
        }
        for (id, _) in self.graph.nodes() {
            let i = id.index();
            if !self.needed[i] || !select(i) || self.is_leaf(id) {
                continue;
            }
            if self.uses[i] <= 1 && !handed_over[i] {
                continue;
            }
            let name = match &field_names[i] {
                Some(name) => local(name),
                None => self.temporary(),
            };
            statements.push(self.bind(id, name));
        }
    }

    /// The body of the motion function: computes the configuration (`let c_ =
    /// configuration(p_, q_);`), reads the fields it needs, computes `boundary` and returns both
    /// structs, `(c_, Motion { … })`.
    fn motion(&mut self, boundary: &[NodeId], field_names: &[Option<String>]) -> Shared {
        self.mark(boundary);
        let mut statements = self.bind_shared(false);
        statements.extend(self.joint_variables());
        let stop = self.stop.clone();
        self.bind_shared_nodes(&|i| !stop[i], boundary, field_names, &mut statements);
        let locals: Vec<TokenStream> = boundary
            .iter()
            .map(|&id| self.expr(id, Place::Top))
            .collect();
        let fields = boundary
            .iter()
            .map(|&id| {
                let name = self.names[id.index()].clone().unwrap_or_default();
                proc_macro2::Ident::new(&name.to_string(), Span::call_site())
            })
            .collect();
        let ty = proc_macro2::Ident::new(MOTION_STRUCT, Span::call_site());
        let result = quote!(#ty { #(#locals),* });
        let c = local(CONFIGURATION_LOCAL);
        Shared {
            fields,
            tokens: if self.has_configuration {
                quote!(#(#statements)* (#c, #result))
            } else {
                quote!(#(#statements)* #result)
            },
        }
    }

    /// The statements binding the shared fields this function reads: in a method,
    /// `let Configuration { s2, .. } = configuration(p_, q_);`, or when it reads the motion too,
    /// `let (Configuration { s2, .. }, Motion { v3, .. }) = motion(p_, q_, qd_);`; in the motion
    /// function (`in_method` false), `let c_ = configuration(p_, q_);` and
    /// `let Configuration { s2, .. } = c_;`.
    fn bind_shared(&self, in_method: bool) -> Vec<TokenStream> {
        let read = |origin: Origin| -> Vec<TokenStream> {
            self.graph
                .nodes()
                .filter(|(id, _)| {
                    let i = id.index();
                    self.stop[i] && self.needed[i] && self.origin[i] == origin
                })
                .filter_map(|(id, _)| self.names[id.index()].clone())
                .collect()
        };
        let (config, motion) = (read(Origin::Configuration), read(Origin::Motion));
        let ty = proc_macro2::Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        let f = proc_macro2::Ident::new(CONFIGURATION_FN, Span::call_site());
        let c = local(CONFIGURATION_LOCAL);
        let (p, q, qd) = (local(PARAMETERS), local("q_"), local("qd_"));
        let mut statements = Vec::new();
        if !in_method {
            if self.has_configuration {
                statements.push(quote!(let #c = #f(#p, #q);));
                if !config.is_empty() {
                    statements.push(quote!(let #ty { #(#config,)* .. } = #c;));
                }
            }
            return statements;
        }
        if motion.is_empty() {
            if !config.is_empty() {
                statements.push(quote!(let #ty { #(#config,)* .. } = #f(#p, #q);));
            }
            return statements;
        }
        let mty = proc_macro2::Ident::new(MOTION_STRUCT, Span::call_site());
        let mf = proc_macro2::Ident::new(MOTION_FN, Span::call_site());
        if self.has_configuration {
            statements.push(quote!(
                let (#ty { #(#config,)* .. }, #mty { #(#motion,)* .. }) = #mf(#p, #q, #qd);
            ));
        } else {
            statements.push(quote!(let #mty { #(#motion,)* .. } = #mf(#p, #q, #qd);));
        }
        statements
    }

    /// A function's body computing `shape`: the configuration's fields it reads, then
    /// the terms in `q̇` and `q̈`, then the result.
    fn function(mut self, shape: &Shape, output: &str) -> Body {
        let outputs = shape.outputs();
        self.mark(&outputs);
        let mut output_names = self.output_names(shape, output);
        // A scalar result is returned as an expression, not bound.
        if matches!(shape, Shape::Scalar(_)) {
            output_names.clear();
        }
        let mut statements = Vec::new();
        // The shared fields this function reads, bound under their names.
        statements.extend(self.bind_shared(true));
        statements.extend(self.joint_variables());
        for (id, _) in self.graph.nodes() {
            let i = id.index();
            if !self.needed[i] || self.stop[i] || self.is_leaf(id) {
                continue;
            }
            // A scalar result is written in place unless it is read elsewhere too.
            let bound_output = outputs.contains(&id) && !matches!(shape, Shape::Scalar(_));
            if self.uses[i] <= 1 && !bound_output {
                continue;
            }
            let name = match output_names.iter().find(|(n, _)| *n == id) {
                Some((_, name)) => local(name),
                None => self.temporary(),
            };
            statements.push(self.bind(id, name));
        }
        let result = match shape {
            Shape::Scalar(id) => self.expr(*id, Place::Top),
            Shape::Vector(v) => {
                let items: Vec<TokenStream> =
                    v.iter().map(|&id| self.expr(id, Place::Top)).collect();
                quote!([#(#items),*])
            }
            Shape::Matrix(m) => {
                let rows: Vec<TokenStream> = m
                    .iter()
                    .map(|r| {
                        let items: Vec<TokenStream> =
                            r.iter().map(|&id| self.expr(id, Place::Top)).collect();
                        quote!([#(#items),*])
                    })
                    .collect();
                quote!([#(#rows),*])
            }
        };
        Body {
            tokens: quote!(#(#statements)* #result),
            ops: count(self.eq, &outputs),
        }
    }

    /// `let [qd1, _, qd3] = *qd_;`: the joint positions, velocities and accelerations the
    /// marked nodes read, named as the book numbers them.
    fn joint_variables(&self) -> Vec<TokenStream> {
        let n = self.eq.dof;
        let mut used = [vec![false; n], vec![false; n], vec![false; n]];
        for (id, node) in self.graph.nodes() {
            if !self.needed[id.index()] {
                continue;
            }
            match node {
                Node::Var(Var::Q(i)) => used[0][usize::from(i)] = true,
                Node::Var(Var::Qd(i)) => used[1][usize::from(i)] = true,
                Node::Var(Var::Qdd(i)) => used[2][usize::from(i)] = true,
                _ => {}
            }
        }
        ["q", "qd", "qdd"]
            .iter()
            .zip(used)
            .filter(|(_, used)| used.contains(&true))
            .map(|(name, used)| {
                let array = local(&format!("{name}_"));
                let names = used.iter().enumerate().map(|(i, &u)| {
                    if u {
                        let v = local(&format!("{name}{}", i + 1));
                        quote!(#v)
                    } else {
                        quote!(_)
                    }
                });
                quote!(let [#(#names),*] = *#array;)
            })
            .collect()
    }

    /// The sines and cosines of the joints that need them, four joints a call computed side by
    /// side, `let ([s2, s3, s4, s5], [c2, c3, c4, c5]) = T::sin_cos_4([q_[1], …]);` (`_` for
    /// an unused one; a last group of two or three is padded with `T::ONE`), a last single joint
    /// on its own, `let (s6, c6) = T::sin_cos(q_[5]);`.
    fn sines_and_cosines(&mut self, statements: &mut Vec<TokenStream>) {
        let mut joints = Vec::new();
        for i in 0..self.eq.dof {
            let i16 = u16::try_from(i).unwrap_or(u16::MAX);
            let needed = |v: Var| {
                self.graph
                    .nodes()
                    .any(|(id, node)| node == Node::Var(v) && self.needed[id.index()])
            };
            let (s, c) = (needed(Var::SinQ(i16)), needed(Var::CosQ(i16)));
            if !s && !c {
                continue;
            }
            let q = local("q_");
            let index = proc_macro2::Literal::usize_unsuffixed(i);
            let angle = match self.eq.angle_offsets[i] {
                Some(off) => {
                    let o = self.expr(off, Place::AddRight);
                    quote!(#q[#index] + #o)
                }
                None => quote!(#q[#index]),
            };
            let name = |used: bool, letter: char| {
                if used {
                    let n = local(&format!("{letter}{}", i + 1));
                    quote!(#n)
                } else {
                    quote!(_)
                }
            };
            joints.push((name(s, 's'), name(c, 'c'), angle, s, c));
        }
        for group in joints.chunks(4) {
            if let [(sn, cn, angle, s, c)] = group {
                statements.push(match (s, c) {
                    (true, true) => quote!(let (#sn, #cn) = T::sin_cos(#angle);),
                    (true, false) => quote!(let #sn = T::sin(#angle);),
                    _ => quote!(let #cn = T::cos(#angle);),
                });
                continue;
            }
            let pad = 4 - group.len();
            let blank = std::iter::repeat(quote!(_)).take(pad);
            let sines = group.iter().map(|j| j.0.clone()).chain(blank.clone());
            let cosines = group.iter().map(|j| j.1.clone()).chain(blank);
            let angles = group
                .iter()
                .map(|j| j.2.clone())
                .chain(std::iter::repeat(quote!(T::ONE)).take(pad));
            statements.push(quote!(
                let ([#(#sines),*], [#(#cosines),*]) = T::sin_cos_4([#(#angles),*]);
            ));
        }
    }
}

/// What an output element named `name` (`m1_2`, `tau3`, …) is, in the book's terms: short and
/// ASCII, since a large robot has a hundred of them and non-ASCII text is escaped in tokens.
fn describe(name: &str) -> Option<String> {
    let pair = |rest: &str| {
        let (i, j) = rest.split_once('_')?;
        Some((i.parse::<usize>().ok()?, j.parse::<usize>().ok()?))
    };
    let one = |rest: &str| rest.parse::<usize>().ok();
    if let Some((i, j)) = name.strip_prefix("cor").and_then(pair) {
        return Some(format!("C{i}{j} = sum of D{i}{j}k qd_k (6.44)"));
    }
    if let Some(i) = name.strip_prefix("cqd").and_then(one) {
        return Some(format!("centripetal and Coriolis torque {i}"));
    }
    if let Some(i) = name.strip_prefix("tau").and_then(one) {
        return Some(format!("T{i} (6.46)"));
    }
    if let Some((i, j)) = name.strip_prefix('m').and_then(pair) {
        return Some(if i == j {
            format!("D{i}{i} (6.43) + actuator inertia")
        } else {
            format!("D{i}{j} = D{j}{i} (6.43)")
        });
    }
    if let Some(i) = name.strip_prefix('g').and_then(one) {
        return Some(format!("D{i} (6.45), gravity and spring"));
    }
    if let Some(i) = name.strip_prefix('h').and_then(one) {
        return Some(format!("centripetal, Coriolis and gravity torque {i}"));
    }
    (name == "p").then(|| "potential energy".to_owned())
}

#[cfg(test)]
mod tests {
    use super::{sum_order, Addition, SumTerm};

    fn term(depth: u32, negative: bool, fusable: bool) -> SumTerm {
        SumTerm {
            depth,
            negative,
            fusable,
        }
    }

    fn add(a: usize, b: usize, fused: bool) -> Addition {
        Addition { a, b, fused }
    }

    #[test]
    fn sums_add_their_terms_in_the_order_they_are_ready() {
        let plain = |d: u32| term(d, false, false);
        // (terms, additions, depth in operations)
        let table: Vec<(Vec<SumTerm>, Vec<Addition>, u32)> = vec![
            // The latest term, met first, is added last.
            (
                vec![plain(6), plain(0), plain(3)],
                vec![add(1, 2, false), add(3, 0, false)],
                7,
            ),
            // Four terms ready together: two pairs, two operations deep rather than three.
            (
                vec![plain(2); 4],
                vec![add(0, 1, false), add(2, 3, false), add(4, 5, false)],
                4,
            ),
            // A product is fused, with the other term as the addend, whichever comes first.
            (
                vec![term(1, false, true), plain(2)],
                vec![add(1, 0, true)],
                3,
            ),
            (
                vec![plain(1), term(2, false, true)],
                vec![add(0, 1, true)],
                3,
            ),
            // Of two products, the one whose operands come later is fused.
            (
                vec![term(3, false, true), term(2, false, true)],
                vec![add(1, 0, true)],
                4,
            ),
            // Of two products of opposite signs, the negative one.
            (
                vec![term(2, true, true), term(2, false, true)],
                vec![add(1, 0, true)],
                3,
            ),
            // One term: nothing to add.
            (vec![plain(5)], vec![], 5),
        ];
        for (terms, additions, depth) in table {
            assert_eq!(sum_order(&terms), (additions, depth), "{terms:?}");
        }
    }
}

//! One function's body: the nodes its outputs need, each once, in the graph's order (children
//! first), as `const double` locals, then the stores into the output arrays (a regressor's
//! output by output, as its Rust `into` form writes it).
//!
//! The order is the Rust emission's: the joint variables and parameters read, the nodes that
//! depend on the parameters alone, each needed joint's sine and cosine, the rest. The sines
//! and cosines come after the parameters because a joint's angle offset may be a parameter
//! expression traced after the joint's sine.

use super::expr::Precision;
use crate::emit::plan::Place;
// The writer is declared with the expressions, which this file's statements are made of.
pub(super) use super::expr::Writer;
use crate::emit::lanes::Queue;
use crate::emit::output_names;
use crate::method::Method;
use crate::symbolic::{Node, NodeId, Var};
use crate::trace::{Equations, Shape, Solved};

/// A written body, and which inputs it reads.
pub(super) struct Body {
    /// The statements, one a line, without indentation.
    pub(super) lines: Vec<String>,
    /// Whether the body reads the parameters, `q`, `qd`, `qdd`, the wrench and `tau`: an
    /// argument it does not read is cast to `void`, which C compilers take as used.
    pub(super) reads: Reads,
}

/// Which arguments a body reads.
#[derive(Clone, Copy, Default)]
pub(super) struct Reads {
    pub(super) params: bool,
    pub(super) q: bool,
    pub(super) qd: bool,
    pub(super) qdd: bool,
    pub(super) wrench: bool,
    pub(super) wrenches: bool,
    pub(super) tau: bool,
}

impl<'a> Writer<'a> {
    pub(super) fn new(eq: &'a Equations, precision: Precision, sign: String) -> Writer<'a> {
        let n = eq.graph.len();
        Writer {
            eq,
            precision,
            sign,
            uses: vec![0; n],
            needed: vec![false; n],
            names: vec![None; n],
            comments: vec![None; n],
            temporaries: 0,
            depth: vec![std::cell::Cell::new(u32::MAX); n],
        }
    }

    /// Marks what `outputs` read, counting each read (as [`Writer::operands`] reads).
    fn mark(&mut self, outputs: &[NodeId]) {
        let mut stack = outputs.to_vec();
        for &o in outputs {
            self.uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut self.needed[id.index()], true) {
                continue;
            }
            for c in self.operands(id) {
                self.uses[c.index()] += 1;
                stack.push(c);
            }
        }
    }

    fn is_operation(&self, id: NodeId) -> bool {
        !matches!(self.eq.graph.node(id), Node::Var(_) | Node::Const(_))
    }

    /// Whether node `id` gets a local of its own: an operation read more than once, or named.
    fn is_bound(&self, id: NodeId) -> bool {
        self.needed[id.index()]
            && self.is_operation(id)
            && (self.uses[id.index()] > 1 || self.names[id.index()].is_some())
    }

    /// The body of `method`'s function: its locals, the stores into its output arrays (named
    /// `arrays`, as [`super::function::Function`] declares them) and its `return`; with
    /// `lanes`, the tangents of a method that plans them computed in lanes (`lanes.rs`).
    pub(super) fn body(self, method: Method, arrays: &[String], lanes: bool) -> Body {
        let shape = method.shape(self.eq);
        let shape = if lanes { shape } else { shape.scalar() };
        self.body_of(method, shape, arrays, true)
    }

    /// The body of an output that is no method of the table (the floating base's kinematics
    /// and contact terms, `floating_extras.rs`): `shape`, its elements unnamed (the carrier
    /// `method`'s element names and comments would describe another output), else as
    /// [`Writer::body`].
    pub(super) fn anonymous_body(self, method: Method, shape: Shape, arrays: &[String]) -> Body {
        self.body_of(method, shape, arrays, false)
    }

    fn body_of(mut self, method: Method, shape: Shape, arrays: &[String], named: bool) -> Body {
        self.mark(&shape.lane_outputs());
        self.bind_factors(&shape);
        if named {
            for (id, element) in output_names(&shape, method, |id| !self.is_operation(id)) {
                self.names[id.index()] = Some(element.ident().to_string());
                self.comments[id.index()] = Some(element.describe());
            }
        }
        let pivots = pivots(&shape);
        for (j, &id) in pivots.iter().enumerate() {
            if self.is_operation(id) && self.names[id.index()].is_none() {
                self.names[id.index()] = Some(format!("d{}", j + 1));
                self.comments[id.index()] = Some(format!("pivot {} of M = L D L^T", j + 1));
            }
        }
        let (mut lines, reads) = self.inputs();
        let state = self.depends_on_state();
        let order: Vec<NodeId> = self.eq.graph.nodes().map(|(id, _)| id).collect();
        for &id in order.iter().filter(|id| !state[id.index()]) {
            self.bind(id, &mut lines);
        }
        self.sines_and_cosines(&mut lines);
        let stores = self.stores(&shape, arrays);
        if method.always_in_place() {
            self.output_by_output(stores, &state, &mut lines);
        } else {
            let mut queue = Queue::new(&shape, None);
            for &id in order.iter().filter(|id| state[id.index()]) {
                self.lanes_due(&mut queue, Some(id), &mut lines);
                self.bind(id, &mut lines);
            }
            self.lanes_due(&mut queue, None, &mut lines);
            lines.extend(stores.iter().map(|(to, id)| self.store(to, *id)));
            if let Shape::Lanes { lanes: plans, .. } = shape {
                // The matrices' array, after the solution's where there is one.
                let matrices = arrays.last().map_or("", String::as_str);
                for (k, plan) in plans.iter().enumerate() {
                    let Some(plan) = plan else { continue };
                    lines.extend(self.lane_rows(&format!("{matrices}[{k}]"), k, plan));
                }
            }
        }
        if let Shape::Scalar(id) = shape {
            lines.push(format!("return {};", self.expr(id, Place::Top)));
        }
        if !pivots.is_empty() {
            lines.push(self.status(pivots));
        }
        Body { lines, reads }
    }

    /// A method with an `into` form in Rust (the regressors), written as that form is: its
    /// constant elements (mostly zeros) once every input is read, then output by output in the
    /// result's order, the bindings it needs not yet written (operands first) and its store.
    /// In the graph's order, hundreds of values live at once, past the registers, and wait on
    /// the stack: compilers do not reorder a block that long to shorten them.
    fn output_by_output(
        &mut self,
        stores: Vec<(String, NodeId)>,
        state: &[bool],
        lines: &mut Vec<String>,
    ) {
        let (constant, computed): (Vec<_>, Vec<_>) =
            stores.into_iter().partition(|(_, id)| !state[id.index()]);
        lines.extend(constant.iter().map(|(to, id)| self.store(to, *id)));
        let mut done = vec![false; self.eq.graph.len()];
        for (to, output) in computed {
            let mut pending = vec![(output, false)];
            while let Some((id, operands_done)) = pending.pop() {
                if done[id.index()] || !state[id.index()] {
                    continue;
                }
                if !operands_done {
                    pending.push((id, true));
                    pending.extend(self.operands(id).into_iter().rev().map(|c| (c, false)));
                    continue;
                }
                done[id.index()] = true;
                self.bind(id, lines);
            }
            lines.push(self.store(&to, output));
        }
    }

    /// `const double q1 = q[0];` for each joint variable, parameter, wrench component and
    /// torque read, by kind (`Var`'s order), then by index.
    fn inputs(&self) -> (Vec<String>, Reads) {
        let mut reads = Reads::default();
        let mut lines = Vec::new();
        let ty = self.precision.c_type();
        let mut vars: Vec<Var> = self
            .eq
            .graph
            .nodes()
            .filter_map(|(id, node)| match node {
                Node::Var(v) if self.needed[id.index()] => Some(v),
                _ => None,
            })
            .collect();
        vars.sort();
        for v in vars {
            let (array, index) = match v {
                Var::Q(i) => (
                    ("q", &mut reads.q),
                    usize::from(i) + super::q_shift(self.eq),
                ),
                Var::Qd(i) => (("qd", &mut reads.qd), usize::from(i)),
                Var::Qdd(i) => (("qdd", &mut reads.qdd), usize::from(i)),
                Var::Param(k) => (("params", &mut reads.params), usize::from(k)),
                Var::Wrench(k) => (("wrench", &mut reads.wrench), usize::from(k)),
                Var::TipWrench(k) => (("wrenches", &mut reads.wrenches), usize::from(k)),
                Var::Tau(i) => (("tau", &mut reads.tau), usize::from(i)),
                // Computed by `sines_and_cosines`; the placeholders are never emitted.
                Var::SinQ(_) | Var::CosQ(_) => {
                    reads.q = true;
                    continue;
                }
                Var::Inertial(_) | Var::Exact(_) => continue,
            };
            *array.1 = true;
            let name = self.var_name(v);
            lines.push(format!("const {ty} {name} = {}[{index}];", array.0));
        }
        (lines, reads)
    }

    /// Whether each node depends on the state (`q`, `q̇`, `q̈`, `τ`, the wrench), not on the
    /// parameters and constants alone.
    fn depends_on_state(&self) -> Vec<bool> {
        let mut state = vec![false; self.eq.graph.len()];
        for (id, node) in self.eq.graph.nodes() {
            state[id.index()] = match node {
                Node::Var(Var::Param(_) | Var::Inertial(_) | Var::Exact(_)) | Node::Const(_) => {
                    false
                }
                Node::Var(_) => true,
                _ => node.operands().any(|c| state[c.index()]),
            };
        }
        state
    }

    /// `const double t4 = ...;` for a node bound to a local (a temporary numbered in order,
    /// or its element's name with what it is as a comment).
    fn bind(&mut self, id: NodeId, lines: &mut Vec<String>) {
        if !self.is_bound(id) {
            return;
        }
        let value = self.write(id);
        let ty = self.precision.c_type();
        let line = match (&self.names[id.index()], &self.comments[id.index()]) {
            (Some(name), Some(comment)) => format!("const {ty} {name} = {value}; /* {comment} */"),
            (Some(name), None) => format!("const {ty} {name} = {value};"),
            (None, _) => {
                self.temporaries += 1;
                let name = format!("t{}", self.temporaries);
                let line = format!("const {ty} {name} = {value};");
                self.names[id.index()] = Some(name);
                line
            }
        };
        lines.push(line);
    }

    /// A bound node's value, written out (not by its own name).
    fn write(&self, id: NodeId) -> String {
        crate::emit::plan::written(self, id).0
    }

    /// The sines and cosines of the joints that read them, four joints a call as the Rust
    /// emission groups them (five as four and one):
    ///
    /// ```c
    /// const double angles1_[4] = {q[1], q[2], q[3], q[4] + 0.3};
    /// double sines1_[4], cosines1_[4];
    /// dynamics_sincos4(angles1_, sines1_, cosines1_);
    /// const double s2 = sines1_[0], c2 = cosines1_[0];
    /// ```
    ///
    /// a group of two or three padded with its last angle again (whose values nothing reads: a
    /// constant there, `1.0`, made gcc build the array on the stack, and the vector load of
    /// it wait on the narrower stores, three times the time of the UR5 twins' `g`); a joint
    /// on its own, `double s6, c6; dynamics_sincos(q[5], &s6,
    /// &c6);`, or `const double s6 = dynamics_sin(q[5]);` for its sine alone.
    fn sines_and_cosines(&self, lines: &mut Vec<String>) {
        let read = |v: Var| {
            self.eq
                .graph
                .nodes()
                .any(|(id, node)| node == Node::Var(v) && self.needed[id.index()])
        };
        let mut joints = Vec::new();
        for i in 0..self.eq.dof {
            let joint = u16::try_from(i).expect("at most 64 joints");
            let (sine, cosine) = (Var::SinQ(joint), Var::CosQ(joint));
            let at = i + super::q_shift(self.eq);
            let angle = match self.eq.angle_offsets[i] {
                Some(offset) => format!("q[{at}] + {}", self.expr(offset, Place::AddRight)),
                None => format!("q[{at}]"),
            };
            let s = read(sine).then(|| self.var_name(sine));
            let c = read(cosine).then(|| self.var_name(cosine));
            if s.is_some() || c.is_some() {
                joints.push((angle, s, c));
            }
        }
        let mut rest = &joints[..];
        let mut groups = 0;
        while !rest.is_empty() {
            let width = if rest.len() == 5 {
                4
            } else {
                rest.len().min(4)
            };
            let (group, tail) = rest.split_at(width);
            rest = tail;
            if let [(angle, s, c)] = group {
                self.one_sine_and_cosine(angle, s.as_deref(), c.as_deref(), lines);
            } else {
                groups += 1;
                self.four_sines_and_cosines(groups, group, lines);
            }
        }
    }

    /// The sine and cosine of one joint's `angle`, as named (`None`: not read).
    fn one_sine_and_cosine(
        &self,
        angle: &str,
        s: Option<&str>,
        c: Option<&str>,
        lines: &mut Vec<String>,
    ) {
        let p = self.precision;
        let ty = p.c_type();
        match (s, c) {
            (Some(s), Some(c)) => {
                lines.push(format!("{ty} {s}, {c};"));
                lines.push(format!("{}({angle}, &{s}, &{c});", p.trig("sincos")));
            }
            (Some(s), None) => lines.push(format!("const {ty} {s} = {}({angle});", p.trig("sin"))),
            (None, Some(c)) => lines.push(format!("const {ty} {c} = {}({angle});", p.trig("cos"))),
            (None, None) => {}
        }
    }

    /// Group `k`'s sines and cosines, two to four joints, in one `dynamics_sincos4`.
    fn four_sines_and_cosines(
        &self,
        k: usize,
        group: &[(String, Option<String>, Option<String>)],
        lines: &mut Vec<String>,
    ) {
        let p = self.precision;
        let ty = p.c_type();
        let mut angles: Vec<String> = group.iter().map(|(angle, _, _)| angle.clone()).collect();
        let last = angles.last().expect("a group has angles").clone();
        angles.resize(4, last);
        let (a, s, c) = (
            format!("angles{k}_"),
            format!("sines{k}_"),
            format!("cosines{k}_"),
        );
        lines.push(format!("const {ty} {a}[4] = {{{}}};", angles.join(", ")));
        lines.push(format!("{ty} {s}[4], {c}[4];"));
        lines.push(format!("{}({a}, {s}, {c});", p.trig("sincos4")));
        for (lane, (_, sine, cosine)) in group.iter().enumerate() {
            let reads: Vec<String> = [(sine, &s), (cosine, &c)]
                .into_iter()
                .filter_map(|(name, array)| {
                    name.as_ref()
                        .map(|name| format!("{name} = {array}[{lane}]"))
                })
                .collect();
            lines.push(format!("const {ty} {};", reads.join(", ")));
        }
    }

    /// `m[0][1]`, where each element of the result goes in its array, with the node it stores.
    fn stores(&self, shape: &Shape, arrays: &[String]) -> Vec<(String, NodeId)> {
        let vector = |v: &[NodeId]| -> Vec<(String, NodeId)> {
            v.iter()
                .enumerate()
                .map(|(i, &id)| (format!("[{i}]"), id))
                .collect()
        };
        let stack = |s: &[Vec<Vec<NodeId>>]| -> Vec<(String, NodeId)> {
            s.iter()
                .enumerate()
                .flat_map(|(k, m)| matrix(m, &format!("[{k}]")))
                .collect()
        };
        let parts = match *shape {
            Shape::Scalar(_) => vec![],
            Shape::Vector(v) | Shape::SolvedVector { vector: v, .. } => vec![vector(v)],
            Shape::Matrix(m) | Shape::SolvedMatrix { matrix: m, .. } => vec![matrix(m, "")],
            Shape::Stack(s) => vec![stack(s)],
            // The matrices without a plan: the others are read off their lanes.
            Shape::Lanes {
                stack: s,
                lanes,
                solved,
            } => {
                let unplanned = s
                    .iter()
                    .zip(lanes)
                    .enumerate()
                    .filter(|(_, (_, p))| p.is_none());
                let matrices = unplanned
                    .flat_map(|(k, (m, _))| matrix(m, &format!("[{k}]")))
                    .collect();
                let solution = solved.map(|s| vector(s.vector));
                solution.into_iter().chain([matrices]).collect()
            }
            Shape::SolvedStack {
                vector: v,
                stack: s,
                ..
            } => vec![vector(v), stack(s)],
        };
        assert_eq!(
            parts.len(),
            arrays.len(),
            "one array per part of the result"
        );
        arrays
            .iter()
            .zip(parts)
            .flat_map(|(array, part)| {
                part.into_iter()
                    .map(move |(index, id)| (format!("{array}{index}"), id))
            })
            .collect()
    }

    /// `m[0][1] = m1_2;`: node `id` stored at `to`. Written once `id` is bound: before, its
    /// whole expression would be written out.
    fn store(&self, to: &str, id: NodeId) -> String {
        format!("{to} = {};", self.expr(id, Place::Top))
    }

    /// `return (d1 > 0.0 && d2 > 0.0) ? 0 : 1;`: 0 where every pivot is positive (a test
    /// that NaN fails), a constant positive pivot not tested.
    fn status(&self, pivots: &[NodeId]) -> String {
        let zero = self.precision.literal(0.0);
        let tests: Vec<String> = pivots
            .iter()
            .filter_map(|&id| match self.eq.graph.constant(id) {
                Some(c) if c.to_f64() > 0.0 => None,
                Some(_) => Some("0".to_owned()),
                None => Some(format!("{} > {zero}", self.expr(id, Place::AddLeft))),
            })
            .collect();
        if tests.is_empty() {
            "return 0;".to_owned()
        } else {
            format!("return ({}) ? 0 : 1;", tests.join(" && "))
        }
    }
}

/// `[i][j]` after `at` for each element of `m`, rows first.
fn matrix(m: &[Vec<NodeId>], at: &str) -> Vec<(String, NodeId)> {
    let mut entries = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, &id) in row.iter().enumerate() {
            entries.push((format!("{at}[{i}][{j}]"), id));
        }
    }
    entries
}

/// The pivots of the LDLᵀ of M that a solved result is valid under, none for another.
fn pivots<'s>(shape: &Shape<'s>) -> &'s [NodeId] {
    match *shape {
        Shape::SolvedVector { pivots, .. }
        | Shape::SolvedMatrix { pivots, .. }
        | Shape::SolvedStack { pivots, .. }
        | Shape::Lanes {
            solved: Some(Solved { pivots, .. }),
            ..
        } => pivots,
        _ => &[],
    }
}

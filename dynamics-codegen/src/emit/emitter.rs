//! The emitter's state for one function: which nodes it needs and how often each is read,
//! what each is read as, and which shared function computes it.

use super::parts::{Context, Shared};
use super::plan;
use super::sums::Sums;
use crate::symbolic::{Graph, Node, NodeId};
use crate::trace::Equations;
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;
use std::cell::{Cell, RefCell};

/// Where a node read by a function is computed.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Origin {
    /// In the function itself.
    Here,
    /// In the configuration.
    Configuration,
    /// In the motion.
    Motion,
}

/// Writes one function (or only counts its operations, without a [`Context`]).
pub(super) struct Emitter<'a> {
    pub(super) graph: &'a Graph,
    pub(super) eq: &'a Equations,
    pub(super) ctx: Option<&'a Context>,
    /// How many times each node is read by the needed nodes (outputs count once).
    pub(super) uses: Vec<u32>,
    /// Whether each node is computed by (or read from the shared functions by) this function.
    pub(super) needed: Vec<bool>,
    /// What each bound node (and each constant) is read as: a local, or a field of the
    /// configuration.
    pub(super) names: Names,
    /// Nodes computed elsewhere (the configuration's and the motion's fields): marking stops there.
    pub(super) stop: Vec<bool>,
    /// Which shared function computes a stop node.
    pub(super) origin: Vec<Origin>,
    /// The stop nodes, as they were read (each boundary in the arena's order).
    pub(super) stops: Vec<NodeId>,
    pub(super) temporaries: usize,
    /// `t` in a method, `u` in the configuration and `v` in the motion, whose fields a method
    /// binds as locals too.
    pub(super) temporary_prefix: &'static str,
    /// Whether there is a configuration function (the motion function takes its result).
    pub(super) has_configuration: bool,
    /// Whether the function stores its result's elements into a local as they are computed
    /// and returns it, as the `into` methods store into the caller's (a tree's `M`).
    pub(super) returned_in_place: bool,
    /// Per plan, the lanes a function of a group of rows writes ([`super::rows`]); `None`: all,
    /// the result's zeros its own.
    pub(super) kept: Option<Vec<Vec<bool>>>,
    /// Per plan of a group's function, the column of `y_` each of its local directions is
    /// stored in ([`super::rows::local_layout`]); `None`: the plan's own order.
    pub(super) columns: Option<Vec<Vec<usize>>>,
    /// A group's rows, of which a group of `∂q̈`'s stores `q̈` into `x_` ([`super::rows`]).
    pub(super) rows: Option<Vec<bool>>,
    /// Each node's number of dependent operations as emitted ([`Sums::depth`]), once
    /// asked for (`u32::MAX` before).
    pub(super) depth: Vec<Cell<u32>>,
    /// The nodes marked needed (the only ones whose `uses` may be non-zero) and those whose
    /// depth is known: the entries of the tables to reset for the next emitter.
    marked: Vec<u32>,
    depth_known: RefCell<Vec<u32>>,
    /// `T::ZERO` and `T::ONE`, made once and cloned: a regressor's or a derivative's result
    /// writes thousands of zeros, each a new pair of idents otherwise.
    pub(super) zero: TokenStream,
    pub(super) one: TokenStream,
}

impl<'a> Emitter<'a> {
    pub(super) fn new(eq: &'a Equations, ctx: Option<&'a Context>) -> Emitter<'a> {
        let n = eq.graph.len();
        let mut t = SPARE
            .with(|spare| spare.borrow_mut().pop())
            .unwrap_or_default();
        // Tables of this graph's size come back reset (`Drop`); others are filled anew.
        if t.uses.len() != n {
            refill(&mut t.uses, n, 0);
            refill(&mut t.needed, n, false);
            refill(&mut t.slots, n, 0);
            refill(&mut t.stop, n, false);
            refill(&mut t.origin, n, Origin::Here);
            refill(&mut t.depth, n, Cell::new(u32::MAX));
        }
        Emitter {
            graph: &eq.graph,
            eq,
            ctx,
            uses: t.uses,
            needed: t.needed,
            names: Names {
                slots: t.slots,
                idents: Vec::new(),
                named: Vec::new(),
            },
            stop: t.stop,
            origin: t.origin,
            stops: Vec::new(),
            temporaries: 0,
            temporary_prefix: "t",
            has_configuration: false,
            returned_in_place: false,
            kept: None,
            columns: None,
            rows: None,
            depth: t.depth,
            marked: Vec::new(),
            depth_known: RefCell::new(Vec::new()),
            zero: quote!(T::ZERO),
            one: quote!(T::ONE),
        }
    }

    /// Reads the nodes `computed` from the fields of `shared` (by `origin`): by name, without
    /// computing them.
    pub(super) fn read_from(&mut self, computed: &[NodeId], shared: &Shared, origin: Origin) {
        for (&id, field) in computed.iter().zip(&shared.fields) {
            let mut local = field.clone();
            local.set_span(Span::mixed_site());
            self.names.set(id.index(), local);
            self.stop[id.index()] = true;
            self.stops.push(id);
            self.origin[id.index()] = origin;
        }
    }

    /// [`Emitter::read_from`] for the nodes of `computed` that `keep` marks, by index.
    pub(super) fn read_some_from(
        &mut self,
        computed: &[NodeId],
        shared: &Shared,
        origin: Origin,
        keep: &[bool],
    ) {
        let kept = computed.iter().zip(&shared.fields);
        for (&id, field) in kept.filter(|(id, _)| keep[id.index()]) {
            let mut local = field.clone();
            local.set_span(Span::mixed_site());
            self.names.set(id.index(), local);
            self.stop[id.index()] = true;
            self.stops.push(id);
            self.origin[id.index()] = origin;
        }
    }

    /// The nodes an emitted node reads ([`plan::operands`]).
    pub(super) fn operands(&self, id: NodeId) -> plan::Operands {
        plan::operands(self.eq, id)
    }

    pub(super) fn mark(&mut self, outputs: &[NodeId]) {
        let mut stack = outputs.to_vec();
        for &o in outputs {
            self.uses[o.index()] += 1;
        }
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut self.needed[id.index()], true) {
                continue;
            }
            // Every node whose uses count is read first, as it is pushed.
            self.marked.push(id.0);
            if self.stop[id.index()] {
                continue;
            }
            for c in self.operands(id) {
                self.uses[c.index()] += 1;
                stack.push(c);
            }
        }
    }

    /// The needed nodes, in the arena's order (children first): the few thousand a function
    /// computes, where a scan of the arena visits every node of every family's graph.
    pub(super) fn needed_in_order(&self) -> Vec<NodeId> {
        let mut order = self.marked.clone();
        order.sort_unstable();
        order.dedup();
        order.retain(|&i| self.needed[i as usize]);
        order.into_iter().map(NodeId).collect()
    }

    /// Counts node `i` as read at least twice, so that it is bound to a name.
    pub(super) fn read_twice(&mut self, i: usize) {
        self.uses[i] = self.uses[i].max(2);
        self.marked
            .push(u32::try_from(i).expect("graph exceeds u32 nodes"));
    }

    pub(super) fn is_leaf(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Var(_) | Node::Const(_))
    }

    /// A constant other than 0 and 1, which gets its own `let kN`.
    pub(super) fn is_named_constant(&self, id: NodeId) -> bool {
        matches!(self.graph.node(id), Node::Const(c) if !c.is_zero() && !c.is_one())
    }

    /// What node `id` is read as, if it is read by name: its binding, or a joint variable,
    /// sine, cosine or parameter (`q2`, `qd2`, `s2`, `c2`, `p_m2`).
    pub(super) fn name(&self, id: NodeId) -> Option<Ident> {
        if let Some(name) = self.names.get(id.index()) {
            return Some(name.clone());
        }
        let Node::Var(v) = self.graph.node(id) else {
            return None;
        };
        Some(self.variable_name(v))
    }

    /// A leaf (or a bound node) as written: its name, or a constant's value.
    pub(super) fn leaf(&self, id: NodeId) -> TokenStream {
        if let Some(name) = self.name(id) {
            return quote!(#name);
        }
        match self.graph.node(id) {
            Node::Const(c) => self.literal(c),
            _ => quote!(),
        }
    }
}

/// An emitter's tables of the graph's size, kept for the next emitter when one is dropped.
#[derive(Default)]
struct Tables {
    uses: Vec<u32>,
    needed: Vec<bool>,
    slots: Vec<u32>,
    stop: Vec<bool>,
    origin: Vec<Origin>,
    depth: Vec<Cell<u32>>,
}

thread_local! {
    /// Tables of dropped emitters: an emission makes one emitter per function, each with
    /// tables of the whole graph's size, whose allocation and release cost more than refilling.
    static SPARE: RefCell<Vec<Tables>> = const { RefCell::new(Vec::new()) };
}

/// The tables an emission keeps at most: each function's emitter is dropped before the next
/// is made.
const SPARE_TABLES: usize = 2;

/// Drops the spare tables: called at the end of an emission, so that none outlives it.
pub(super) fn release_spare_tables() {
    SPARE.with(|spare| spare.borrow_mut().clear());
}

/// `table` holding `n` copies of `value`, its allocation reused.
fn refill<T: Clone>(table: &mut Vec<T>, n: usize, value: T) {
    table.clear();
    table.resize(n, value);
}

impl Drop for Emitter<'_> {
    /// Resets the entries the emitter wrote, a few thousand where the graph may have tens of
    /// thousands of nodes, and keeps the tables for the next emitter.
    fn drop(&mut self) {
        for &i in &self.marked {
            self.uses[i as usize] = 0;
            self.needed[i as usize] = false;
        }
        for &i in &self.names.named {
            self.names.slots[i as usize] = 0;
        }
        for id in &self.stops {
            self.stop[id.index()] = false;
            self.origin[id.index()] = Origin::Here;
        }
        for &i in self.depth_known.get_mut().iter() {
            self.depth[i as usize].set(u32::MAX);
        }
        let tables = Tables {
            uses: std::mem::take(&mut self.uses),
            needed: std::mem::take(&mut self.needed),
            slots: std::mem::take(&mut self.names.slots),
            stop: std::mem::take(&mut self.stop),
            origin: std::mem::take(&mut self.origin),
            depth: std::mem::take(&mut self.depth),
        };
        SPARE.with(|spare| {
            let mut spare = spare.borrow_mut();
            if spare.len() < SPARE_TABLES {
                spare.push(tables);
            }
        });
    }
}

impl Sums for Emitter<'_> {
    fn graph(&self) -> &Graph {
        self.graph
    }

    fn in_place(&self, c: NodeId) -> bool {
        self.names.get(c.index()).is_none() && self.uses[c.index()] <= 1
    }

    fn depths(&self) -> &[Cell<u32>] {
        &self.depth
    }

    fn remember_depth(&self, id: NodeId, depth: u32) {
        self.depth[id.index()].set(depth);
        self.depth_known.borrow_mut().push(id.0);
    }
}

/// What each node is read as, if it has a name: an index per node into the names given, so
/// that an emitter for a graph of many nodes starts from zeros and drops only the names.
pub(super) struct Names {
    /// Per node, 0 for none, else 1 + its name's index in `idents`.
    slots: Vec<u32>,
    idents: Vec<Ident>,
    /// The nodes named, whose slots are reset when the emitter is dropped.
    named: Vec<u32>,
}

impl Names {
    /// Node `i`'s name, if it has one.
    pub(super) fn get(&self, i: usize) -> Option<&Ident> {
        let slot = self.slots[i].checked_sub(1)?;
        self.idents.get(slot as usize)
    }

    /// Names node `i` (in place of a name it had).
    pub(super) fn set(&mut self, i: usize, name: Ident) {
        self.idents.push(name);
        self.slots[i] = u32::try_from(self.idents.len()).expect("fewer names than nodes");
        self.named
            .push(u32::try_from(i).expect("graph exceeds u32 nodes"));
    }
}

//! Tangents in lanes ([`crate::symbolic::Tangents`]): each planned lane written as a
//! `Tangent<[T; 8], K>` right after the node it is the tangent of, so that it is computed while the
//! scalar values it reads are fresh, and the rows of a Jacobian read off the output lanes.
//!
//! `K` is n rounded up to a multiple of the plan's block (eight, whole AVX-512 registers of
//! `f64`, or four, AVX registers; the lanes past n stay zero). A term `± f₁ f₂ · x` is `x.mul_add(f₁ * f₂, acc)`, a term of no factor `acc ± x`,
//! the unit vectors of a tangent one array literal, `Tangent([T::ZERO, c2, …])`.
//!
//! A lane is kept in its blocks of eight or four ([`Tangents::blocks`], [`Tangents::group`]),
//! `Tangent<[T; 8], Q>` or `Tangent<[T; 4], Q>` with `Q` its
//! own count: a term of fewer blocks is added into its place (`x.mul_add_into(f, acc, 1)`, 1
//! the offset of its blocks in the lane's), and a row read off at its place (`dq7.row_at(1)`).
//! A lane of every block is written as before.

use super::emitter::Emitter;
use super::expr::let_statement;
use super::names::{local, OUTPUT};
use super::plan::Place;
use crate::symbolic::{NodeId, Of, Tangents, Term};
use crate::trace::Shape;
use core::ops::Range;
use proc_macro2::{Delimiter, Group, Ident, TokenStream, TokenTree};
use quote::quote;

/// The lanes still to write, in the order they are written (the C back end's too).
pub(crate) struct Queue<'a> {
    /// `(after, plan, lane)`, sorted by `after`, the plan's order kept within.
    pending: Vec<(NodeId, usize, usize)>,
    plans: Vec<Option<&'a Tangents>>,
    /// Per plan, each lane's blocks ([`Tangents::blocks`]).
    blocks: Vec<Vec<Range<usize>>>,
    next: usize,
}

/// The lanes' names: `dq3` for the tangents by `q`, `dqd3` by `q̇` (plan 0 and 1).
fn lane_name(plan: usize, lane: usize) -> Ident {
    local(&lane_text(plan, lane))
}

/// [`lane_name`]'s text, which the C back end names its lanes by too.
pub(crate) fn lane_text(plan: usize, lane: usize) -> String {
    let prefix = ["dq", "dqd"].get(plan).copied().unwrap_or("dx");
    format!("{prefix}{}", lane + 1)
}

/// `n` as a literal without a suffix (`2`, not `2usize`).
fn unsuffixed(n: usize) -> proc_macro2::Literal {
    proc_macro2::Literal::usize_unsuffixed(n)
}

/// The row of a Jacobian that lane `l` of plan `p` holds: `dq7.row()`, or `dq7.row_at(1)` for
/// a lane kept in fewer blocks than the whole.
fn lane_row(p: usize, plan: &Tangents, l: usize, blocks: &[Range<usize>]) -> TokenStream {
    let x = lane_name(p, l);
    if blocks[l].len() == plan.block_count() {
        quote!(#x.row())
    } else {
        let at = unsuffixed(blocks[l].start);
        quote!(#x.row_at(#at))
    }
}

/// Row `i` of plan `p` stored from `row`, a row in a group's own order of directions
/// (`columns`: the column of `y_` of each local direction): each run of local directions in
/// `blocks` (the lane's) whose columns follow each other copied at once.
fn scattered(
    y: &Ident,
    (p, i): (usize, usize),
    row: TokenStream,
    n: usize,
    columns: &[usize],
    blocks: Range<usize>,
) -> TokenStream {
    let mut runs: Vec<(usize, usize, usize)> = Vec::new();
    let within = columns
        .iter()
        .enumerate()
        .skip(blocks.start)
        .take(blocks.len());
    for (l, &column) in within {
        match runs.last_mut() {
            Some((from, start, len)) if *from + *len == l && *start + *len == column => {
                *len += 1;
            }
            _ => runs.push((l, column, 1)),
        }
    }
    let (n, p, i, r) = (unsuffixed(n), unsuffixed(p), unsuffixed(i), local("r_"));
    let copies = runs.iter().map(|&(from, column, len)| {
        let (a, b) = (unsuffixed(column), unsuffixed(column + len));
        let (c, d) = (unsuffixed(from), unsuffixed(from + len));
        quote!(#y[#p][#i][#a..#b].copy_from_slice(&#r[#c..#d]);)
    });
    quote!({
        let #r: [T; #n] = #row;
        #(#copies)*
    })
}

/// The streams one after the other, moved: `quote!` would copy each (the sums of a lane's
/// terms, growing with each term).
fn cat<const N: usize>(parts: [TokenStream; N]) -> TokenStream {
    let mut all = TokenStream::new();
    all.extend(parts);
    all
}

/// `(a)`, `a` moved in.
fn parenthesized(a: TokenStream) -> TokenStream {
    TokenStream::from(TokenTree::Group(Group::new(Delimiter::Parenthesis, a)))
}

/// The number of lanes of a plan of `n` directions: whole AVX-512 registers of `f64`.
pub(crate) fn width(n: usize) -> usize {
    n.div_ceil(8) * 8
}

/// The operations on lanes of `shape`'s plans: one per term of each lane written, the unit
/// vectors of a lane one together.
pub(super) fn lane_operations(shape: &Shape) -> usize {
    let Shape::Lanes { lanes, .. } = shape else {
        return 0;
    };
    lanes
        .iter()
        .flatten()
        .flat_map(|plan| &plan.lanes)
        .map(|lane| {
            let vectors = lane.terms.iter().filter(|t| matches!(t.of, Of::Lane(_)));
            vectors.count() + usize::from(lane.terms.iter().any(|t| matches!(t.of, Of::Unit(_))))
        })
        .sum()
}

impl<'a> Queue<'a> {
    /// The lanes of `shape`'s plans (none for another shape), those `kept` marks if given.
    pub(crate) fn new(shape: &Shape<'a>, kept: Option<&[Vec<bool>]>) -> Queue<'a> {
        let plans: Vec<Option<&Tangents>> = match shape {
            Shape::Lanes { lanes, .. } => lanes.iter().map(Option::as_ref).collect(),
            _ => Vec::new(),
        };
        let mut pending: Vec<(NodeId, usize, usize)> = plans
            .iter()
            .enumerate()
            .filter_map(|(p, plan)| plan.map(|plan| (p, plan)))
            .flat_map(|(p, plan)| (0..plan.lanes.len()).map(move |k| (plan.lanes[k].after, p, k)))
            .filter(|&(_, p, k)| match kept {
                Some(kept) => kept[p][k],
                None => true,
            })
            .collect();
        // Stable: a lane reads only lanes of its plan written before it, after nodes before.
        pending.sort_by_key(|&(after, p, _)| (after, p));
        let blocks = plans
            .iter()
            .map(|plan| plan.map(Tangents::blocks).unwrap_or_default())
            .collect();
        Queue {
            pending,
            plans,
            blocks,
            next: 0,
        }
    }

    /// The blocks of each lane of plan `p`.
    pub(crate) fn blocks(&self, p: usize) -> &[Range<usize>] {
        &self.blocks[p]
    }

    /// The next lane due before node `before` (any left for `None`): its plan's index, the
    /// plan and the lane's index in it.
    pub(crate) fn next_due(
        &mut self,
        before: Option<NodeId>,
    ) -> Option<(usize, &'a Tangents, usize)> {
        while let Some(&(after, p, k)) = self.pending.get(self.next) {
            if before.is_some_and(|b| after >= b) {
                return None;
            }
            self.next += 1;
            if let Some(plan) = self.plans[p] {
                return Some((p, plan, k));
            }
        }
        None
    }
}

impl Emitter<'_> {
    /// Makes every factor of `shape`'s plans a bound value, read by name.
    pub(super) fn bind_factors(&mut self, shape: &Shape) {
        let Shape::Lanes { lanes, .. } = shape else {
            return;
        };
        let factors = match &self.kept {
            Some(kept) => kept_factors(lanes, kept),
            None => lanes.iter().flatten().flat_map(Tangents::factors).collect(),
        };
        for f in factors {
            self.read_twice(f.index());
        }
    }

    /// The statements of the lanes due before node `before` (all of them for `None`).
    pub(super) fn lanes_due(
        &mut self,
        queue: &mut Queue,
        before: Option<NodeId>,
        statements: &mut Vec<TokenStream>,
    ) {
        while let Some((p, plan, k)) = queue.next_due(before) {
            let name = lane_name(p, k);
            let value = self.lane(p, plan, k, queue.blocks(p));
            statements.push(let_statement(&name, value));
            if self.returned_in_place {
                // Its rows stored at once, so that it need not be kept to the end.
                let y = local(OUTPUT);
                let rows = plan.outputs.iter().enumerate();
                for (i, _) in rows.filter(|(_, lane)| **lane == Some(k)) {
                    let row = lane_row(p, plan, k, queue.blocks(p));
                    statements.push(match &self.columns {
                        Some(columns) => {
                            let own = &queue.blocks(p)[k];
                            let local = own.start * plan.group..own.end * plan.group;
                            scattered(&y, (p, i), row, plan.directions, &columns[p], local)
                        }
                        None => {
                            let (p, i) = (unsuffixed(p), unsuffixed(i));
                            quote!(#y[#p][#i] = #row;)
                        }
                    });
                }
            }
        }
    }

    /// The sum of lane `k`'s terms, in its blocks.
    fn lane(
        &mut self,
        p: usize,
        plan: &Tangents,
        k: usize,
        blocks: &[Range<usize>],
    ) -> TokenStream {
        let terms = &plan.lanes[k].terms;
        let own = blocks[k].clone();
        // A lane of every block is written as it was before lanes had blocks.
        let whole = own.len() == plan.block_count();
        let (units, lanes): (Vec<&Term>, Vec<&Term>) =
            terms.iter().partition(|t| matches!(t.of, Of::Unit(_)));
        let mut acc: Option<TokenStream> = None;
        if !units.is_empty() {
            let elements: Vec<TokenStream> = (own.start * plan.group..own.end * plan.group)
                .map(|j| {
                    let at: Vec<&&Term> = units
                        .iter()
                        .filter(|t| t.of == Of::Unit(u16::try_from(j).unwrap_or(u16::MAX)))
                        .collect();
                    self.unit_sum(&at)
                })
                .collect();
            let groups = elements.chunks(plan.group).map(|g| quote!([#(#g),*]));
            acc = Some(quote!(Tangent([#(#groups),*])));
        }
        // A term twice (the tangent of a square, `2 a ∂a`) is taken once, its factor times the count.
        let mut counted: Vec<(&Term, usize)> = Vec::new();
        for t in lanes {
            match counted.iter_mut().find(|(u, _)| *u == t) {
                Some((_, n)) => *n += 1,
                None => counted.push((t, 1)),
            }
        }
        for (t, n) in counted {
            let Of::Lane(l) = t.of else { continue };
            let x = lane_name(p, l);
            // Added into its place where the term has fewer blocks than the lane.
            let at = (blocks[l] != own).then(|| unsuffixed(blocks[l].start - own.start));
            // Without factors, a negative term is subtracted (or negated, first).
            let signed = t.negative && (!t.factors.is_empty() || n > 1);
            let factor = match self.product(&t.factors, signed) {
                Some(f) if n > 1 => {
                    let n = proc_macro2::Literal::f64_unsuffixed(n as f64);
                    Some(quote!((#f * T::from_f64(#n))))
                }
                None if n > 1 => {
                    let n = proc_macro2::Literal::f64_unsuffixed(n as f64);
                    Some(quote!(T::from_f64(#n)))
                }
                f => f,
            };
            let q = unsuffixed(own.len());
            acc = Some(match (at, acc, factor) {
                (None, None, None) if t.negative => quote!(-#x),
                (None, None, None) => quote!(#x),
                (None, None, Some(f)) => quote!(#x.scale(#f)),
                (None, Some(a), None) if t.negative => cat([a, quote!(- #x)]),
                (None, Some(a), None) => cat([a, quote!(+ #x)]),
                (None, Some(a), Some(f)) => {
                    cat([quote!(#x.mul_add), parenthesized(cat([f, quote!(,), a]))])
                }
                (Some(at), None, None) if t.negative => quote!((-#x).widen::<#q>(#at)),
                (Some(at), None, None) => quote!(#x.widen::<#q>(#at)),
                (Some(at), None, Some(f)) => quote!(#x.scale(#f).widen::<#q>(#at)),
                (Some(at), Some(a), None) if t.negative => {
                    cat([quote!(#x.sub_from), parenthesized(cat([a, quote!(, #at)]))])
                }
                (Some(at), Some(a), None) => {
                    cat([quote!(#x.add_into), parenthesized(cat([a, quote!(, #at)]))])
                }
                (Some(at), Some(a), Some(f)) => cat([
                    quote!(#x.mul_add_into),
                    parenthesized(cat([f, quote!(,), a, quote!(, #at)])),
                ]),
            });
        }
        let groups = if whole { plan.block_count() } else { own.len() };
        let group = unsuffixed(plan.group);
        acc.unwrap_or_else(|| quote!(Tangent([[T::ZERO; #group]; #groups])))
    }

    /// One lane's value in a sum of unit vectors: the sum of the terms' signed products.
    fn unit_sum(&mut self, terms: &[&&Term]) -> TokenStream {
        let mut sum: Option<TokenStream> = None;
        for t in terms {
            let value = self
                .product(&t.factors, false)
                .unwrap_or_else(|| quote!(T::ONE));
            sum = Some(match (sum, t.negative) {
                (None, false) => value,
                (None, true) => cat([quote!(-), value]),
                (Some(s), false) => cat([s, quote!(+), value]),
                (Some(s), true) => cat([s, quote!(-), value]),
            });
        }
        sum.unwrap_or_else(|| quote!(T::ZERO))
    }

    /// `f₁ * f₂ ⋯`, negated if `negative`, or `None` for no factor and positive.
    fn product(&mut self, factors: &[NodeId], negative: bool) -> Option<TokenStream> {
        let mut product: Option<TokenStream> = None;
        for &f in factors {
            let e = self.expr(f, Place::MulRight);
            product = Some(match product {
                None => e,
                Some(p) => cat([p, quote!(*), e]),
            });
        }
        match (product, negative) {
            (None, false) => None,
            (None, true) => Some(quote!(-T::ONE)),
            (Some(p), false) => Some(p),
            (Some(p), true) => Some(parenthesized(cat([quote!(-), parenthesized(p)]))),
        }
    }

    /// The matrices of a stack with plans: a plan's rows read off its output lanes
    /// (`dq7.row()`, zeros where a row is zero), the other matrices from their nodes.
    pub(super) fn lane_stack(
        &mut self,
        stack: &[Vec<Vec<NodeId>>],
        plans: &[Option<Tangents>],
    ) -> TokenStream {
        let matrices: Vec<TokenStream> = stack
            .iter()
            .zip(plans)
            .enumerate()
            .map(|(p, (m, plan))| match plan {
                None => self.matrix(m),
                Some(plan) => {
                    let n = plan.directions;
                    let blocks = plan.blocks();
                    let rows = plan.outputs.iter().map(|lane| match lane {
                        Some(l) => lane_row(p, plan, *l, &blocks),
                        None => quote!([T::ZERO; #n]),
                    });
                    quote!([#(#rows),*])
                }
            })
            .collect();
        quote!([#(#matrices),*])
    }
}

/// The scalar nodes the lanes `kept` read as factors: what a group's function computes.
pub(super) fn kept_factors(plans: &[Option<Tangents>], kept: &[Vec<bool>]) -> Vec<NodeId> {
    let mut all: Vec<NodeId> = plans
        .iter()
        .zip(kept)
        .filter_map(|(plan, kept)| plan.as_ref().map(|plan| (plan, kept)))
        .flat_map(|(plan, kept)| plan.lanes.iter().zip(kept).filter(|(_, &k)| k))
        .flat_map(|(lane, _)| lane.terms.iter().flat_map(|t| t.factors.iter().copied()))
        .collect();
    all.sort_unstable();
    all.dedup();
    all
}

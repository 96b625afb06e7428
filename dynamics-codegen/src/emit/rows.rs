//! A tree's ∂τ in one function per group of rows: rows whose tangents share no direction (a
//! dual arm's two arms, each with its fingers: branches with no joint in common) are computed
//! by functions of their own, `inverse_dynamics_derivatives_rows1`, `…_rows2`, each storing
//! its rows `∂τ_i/∂q` and `∂τ_i/∂q̇` into the caller's result, called one after the other.
//!
//! Written as one function, Baxter's ∂τ is 61 kB of straight-line code, fetch-bound (twice the
//! 32 kB instruction cache), and no layout of its lanes made it faster (docs/performance.md).
//! Apart, each function is the code of one branch, about half, and is compiled on its own:
//! fewer values live at once, fewer spills. Each reads the configuration and the motion
//! itself (inlined: the compiler keeps of them what it reads, its branch's sines and cosines)
//! and computes the scalars and lanes its rows need by the same expressions as the whole
//! function: the same bits. Only where a plan is fetch-bound ([`FETCH_BOUND_OPERATIONS`] in
//! blocks of eight): a smaller tree's and a serial robot's ∂τ are one function, as before.
//!
//! Each group's lanes hold its own directions first ([`local_layout`]), so that an arm's lanes
//! take the blocks its directions need, not those their columns straddle in the whole; a row
//! is stored into its columns of `y_` by runs.
//!
//! A fixed-base tree's fetch-bound ∂q̈ = −M⁻¹ ∂τ/∂x splits the same way: M is
//! block-diagonal across the subtrees hanging from the base (no joint in common), so each
//! subtree's `q̈ = M_s⁻¹ (τ_s − h_s)`, its pivots, its rows of `∂q̈/∂q`, `∂q̈/∂q̇` and `M⁻¹` are
//! its own problem, with its own directions ([`solved_groups`]: Baxter's head and arms; the
//! Allegro hand's fingers, not fetch-bound, measured no faster apart). Each group's function
//! `forward_dynamics_derivatives_rows1`, … also stores its `q̈` into `x_` and its rows into
//! the trait's result, which the function compiled apart builds and returns, and returns
//! whether its pivots are positive; the entries between subtrees stay zeros.

use super::count::count;
use super::emitter::Emitter;
use super::expr::with_body;
use super::impls::{call_arguments, signature, Counts};
use super::lanes::{kept_factors, lane_operations};
use super::names::{local, OUTPUT, PARAMETERS, SOLUTION};
use super::parts::{Body, Context, OpCount, Output, Part};
use super::plan::Place;
use crate::symbolic::tangent::FETCH_BOUND_OPERATIONS;
use crate::symbolic::{NodeId, Of, Tangents, BLOCK};
use crate::trace::{Equations, Shape, Solved};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// The groups of rows of `∂τ`'s `plans` ([`independent_rows`]) where a plan is fetch-bound;
/// none otherwise.
pub(super) fn row_groups(plans: &[Option<Tangents>]) -> Vec<Vec<bool>> {
    if !fetch_bound(plans) {
        return Vec::new();
    }
    independent_rows(plans)
}

/// Whether a plan passes [`FETCH_BOUND_OPERATIONS`] in blocks of eight.
fn fetch_bound(plans: &[Option<Tangents>]) -> bool {
    plans
        .iter()
        .flatten()
        .any(|p| p.block_operations(BLOCK) > FETCH_BOUND_OPERATIONS)
}

/// The groups of rows of `∂q̈`'s `plans` ([`independent_rows`]) where a plan is fetch-bound,
/// there are several and every row is in one: a fixed-base tree's subtrees hanging from the
/// base, whose block of M is their own, so that `q̈`, its pivots and its derivatives are each
/// subtree's own problem.
pub(super) fn solved_groups(plans: &[Option<Tangents>]) -> Vec<Vec<bool>> {
    if !fetch_bound(plans) {
        return Vec::new();
    }
    let groups = independent_rows(plans);
    let rows = groups.first().map_or(0, Vec::len);
    let covered = (0..rows).all(|i| groups.iter().any(|g| g[i]));
    if groups.len() > 1 && covered {
        groups
    } else {
        Vec::new()
    }
}

/// The groups of rows of `plans` (one mask of rows each, in the order of their first row)
/// whose tangents share no direction, by `q` or by `q̇`. A row whose tangents are zero belongs
/// to none.
fn independent_rows(plans: &[Option<Tangents>]) -> Vec<Vec<bool>> {
    let plans: Vec<&Tangents> = plans.iter().flatten().collect();
    let Some(first) = plans.first() else {
        return Vec::new();
    };
    let (directions, rows) = (first.directions, first.outputs.len());
    let mut sets = Sets::new(directions);
    // Per plan, per lane, one direction it can be nonzero in, its others joined to it.
    let seeds: Vec<Vec<Option<usize>>> = plans.iter().map(|p| sets.join_lanes(p)).collect();
    // A row's tangents by q and by q̇ go together.
    let row_seed = |sets: &mut Sets, i: usize| {
        let mut seed = None;
        for (plan, lanes) in plans.iter().zip(&seeds) {
            if let Some(d) = plan.outputs[i].and_then(|k| lanes[k]) {
                seed = Some(seed.map_or(d, |s| sets.join(s, d)));
            }
        }
        seed
    };
    let seeds: Vec<Option<usize>> = (0..rows).map(|i| row_seed(&mut sets, i)).collect();
    let mut groups: Vec<(usize, Vec<bool>)> = Vec::new();
    for (i, seed) in seeds.iter().enumerate() {
        let Some(d) = *seed else { continue };
        let root = sets.root(d);
        match groups.iter_mut().find(|(r, _)| *r == root) {
            Some((_, rows)) => rows[i] = true,
            None => {
                let mut mask = vec![false; rows];
                mask[i] = true;
                groups.push((root, mask));
            }
        }
    }
    groups.into_iter().map(|(_, rows)| rows).collect()
}

/// Per plan, the lanes the rows `rows` read: their own and, back to front, every lane those
/// read.
pub(super) fn kept_lanes(plans: &[Option<Tangents>], rows: &[bool]) -> Vec<Vec<bool>> {
    plans
        .iter()
        .map(|plan| {
            let Some(plan) = plan else {
                return Vec::new();
            };
            let mut kept = vec![false; plan.lanes.len()];
            let outputs = plan.outputs.iter().zip(rows);
            for (k, _) in outputs.filter(|(_, &row)| row) {
                if let Some(k) = *k {
                    kept[k] = true;
                }
            }
            for k in (0..plan.lanes.len()).rev() {
                if !kept[k] {
                    continue;
                }
                for t in &plan.lanes[k].terms {
                    if let Of::Lane(l) = t.of {
                        kept[l] = true;
                    }
                }
            }
            kept
        })
        .collect()
}

/// Per plan, the plan with the directions of the lanes `kept` first, in their order, the others
/// after them, and the column of each of the first: a group's own layout of its directions.
/// Baxter's arm reads eight directions by `q` (the shoulder's own angle is none of them) at
/// columns 2-9 or 11-18 of nineteen: in the whole's blocks of eight, two blocks a lane; in its
/// own, one. Each lane computes what it computed at its place, so the bits are the same.
pub(super) fn local_layout(
    plans: &[Option<Tangents>],
    kept: &[Vec<bool>],
) -> (Vec<Option<Tangents>>, Vec<Vec<usize>>) {
    plans
        .iter()
        .zip(kept)
        .map(|(plan, kept)| {
            let Some(plan) = plan else {
                return (None, Vec::new());
            };
            let mut read = vec![false; plan.directions];
            let lanes = plan.lanes.iter().zip(kept).filter(|(_, &k)| k);
            for t in lanes.flat_map(|(lane, _)| &lane.terms) {
                if let Of::Unit(j) = t.of {
                    read[usize::from(j)] = true;
                }
            }
            let (first, rest): (Vec<usize>, Vec<usize>) =
                (0..plan.directions).partition(|&j| read[j]);
            let mut position = vec![0u16; plan.directions];
            for (l, &j) in first.iter().chain(&rest).enumerate() {
                position[j] = u16::try_from(l).unwrap_or(u16::MAX);
            }
            let mut local = plan.clone();
            for t in local.lanes.iter_mut().flat_map(|lane| &mut lane.terms) {
                if let Of::Unit(j) = t.of {
                    t.of = Of::Unit(position[usize::from(j)]);
                }
            }
            (Some(local), first)
        })
        .unzip()
}

/// The lanes' branch of `output`'s body: its result's zeros, each group's function called on
/// them (`parts`), the result returned. `∂q̈`'s groups store `q̈` too and say whether their
/// pivots are positive: the trait's result, `Ok` where all are, is returned from the function
/// compiled apart.
pub(super) fn split(eq: &Equations, ctx: &Context, output: &Output, parts: &[Part]) -> Body {
    let y = local(OUTPUT);
    let (p, arguments) = (&ctx.parameters, call_arguments(output.method));
    let (n, count) = (
        Literal::usize_unsuffixed(eq.dof),
        Literal::usize_unsuffixed(match output.shape {
            Shape::Lanes { stack, .. } => stack.len(),
            _ => 0,
        }),
    );
    let names = parts.iter().map(part_name);
    let tokens = if parts.iter().any(|part| part.solved) {
        // The trait's result built where the groups store into it, and returned from the
        // function compiled apart: stored into locals and converted, Baxter's 9 kB were
        // copied five times a call (docs/performance.md, 2026-11-30).
        let (r, d, positive) = (local("r_"), local("d_"), local("positive_"));
        let calls = names.map(|name| {
            let blocks = quote!([&mut #d.dqdd_dq, &mut #d.dqdd_dqd, &mut #d.dqdd_dtau]);
            quote!(#name(#p, #arguments, &mut #d.qdd, #blocks))
        });
        quote! {
            let mut #r = ::core::result::Result::Ok(ForwardDynamicsDerivatives::from_parts((
                [T::ZERO; #n],
                [[[T::ZERO; #n]; #n]; #count],
            )));
            let mut #positive = false;
            if let ::core::result::Result::Ok(#d) = &mut #r {
                // `&`, not `&&`: every group stores its rows.
                #positive = #(#calls)&*;
            }
            return if #positive {
                #r
            } else {
                ::core::result::Result::Err(NotPositiveDefinite)
            };
        }
    } else {
        let calls = names.map(|name| quote!(#name(#p, #arguments, &mut #y);));
        quote! {
            let mut #y = [[[T::ZERO; #n]; #n]; #count];
            #(#calls)*
            #y
        }
    };
    Body {
        tokens,
        ops: split_ops(eq, ctx, &output.shape),
        zeros: None,
        lanes: true,
    }
}

/// The operations of the groups' functions together: those of the whole (the groups share
/// nothing but the configuration's leaves), where the context asks.
fn split_ops(eq: &Equations, ctx: &Context, shape: &Shape) -> OpCount {
    if !ctx.counted {
        return OpCount::default();
    }
    OpCount {
        lanes: lane_operations(shape),
        ..count(eq, &shape.lane_outputs())
    }
}

/// The name of group `index`'s function (from 1): `inverse_dynamics_derivatives_rows1`.
fn part_name(part: &Part) -> Ident {
    let name = format!("{}_rows{}", part.method.name(), part.index);
    Ident::new(&name, Span::call_site())
}

impl Emitter<'_> {
    /// The nodes a function computing `shape` in lanes reads ([`Shape::lane_outputs`]): of a
    /// group of rows, the factors of the lanes it keeps.
    pub(super) fn lane_outputs(&self, shape: &Shape) -> Vec<NodeId> {
        match (&self.kept, shape) {
            (Some(kept), Shape::Lanes { lanes, solved, .. }) => {
                let mut nodes = solved.map_or_else(Vec::new, |s| self.own_solved(&s));
                nodes.extend(kept_factors(lanes, kept));
                nodes
            }
            _ => shape.lane_outputs(),
        }
    }

    /// Of a group of `∂q̈`'s rows: its pivots, then its rows' `q̈`.
    fn own_solved(&self, solved: &Solved) -> Vec<NodeId> {
        let rows = self.rows.as_deref().unwrap_or_default();
        let own = solved.vector.iter().zip(rows).filter(|(_, &row)| row);
        let vector = own.map(|(&id, _)| id);
        solved.pivots.iter().copied().chain(vector).collect()
    }

    /// The end of a group's function: nothing for ∂τ's; for ∂q̈'s, its rows' `q̈` stored into
    /// `x_` and whether its pivots are positive.
    pub(super) fn group_result(&mut self, shape: &Shape) -> TokenStream {
        let Shape::Lanes {
            solved: Some(solved),
            ..
        } = shape
        else {
            return TokenStream::new();
        };
        let x = local(SOLUTION);
        let rows = self.rows.clone().unwrap_or_default();
        let own = solved.vector.iter().enumerate().filter(|&(i, _)| rows[i]);
        let stores: Vec<TokenStream> = own
            .map(|(i, &id)| {
                let (i, value) = (Literal::usize_unsuffixed(i), self.expr(id, Place::Top));
                quote!(#x[#i] = #value;)
            })
            .collect();
        let positive = self.positive(solved.pivots).unwrap_or_else(|| quote!(true));
        quote!(#(#stores)* #positive)
    }
}

/// Group `part`'s function, storing its rows into the caller's `y_`: `#[inline(never)]`,
/// so that each is compiled, and fetched, on its own; its frame aligned for its lanes' spills
/// (`align_stack`). `k` is the parameters' count.
pub(super) fn part_function(
    part: &Part,
    k: usize,
    counts: &Counts,
    krate: &TokenStream,
) -> TokenStream {
    let name = part_name(part);
    let (p, y) = (local(PARAMETERS), local(OUTPUT));
    let scalar = Ident::new("T", Span::call_site());
    let (args, ret) = signature(part.method, counts, &scalar, krate, true);
    let head = if part.solved {
        let (x, n) = (local(SOLUTION), &counts.joints);
        let count = Literal::usize_unsuffixed(part.matrices);
        quote! {
            #[inline(never)]
            pub(super) fn #name<T: #krate::Real>(
                #p: &[T; #k], #args, #x: &mut [T; #n], #y: [&mut [[T; #n]; #n]; #count]
            ) -> bool
        }
    } else {
        quote! {
            #[inline(never)]
            pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #args, #y: &mut #ret)
        }
    };
    let mut body = quote!(align_stack::<T>(););
    body.extend(part.tokens.clone());
    with_body(head, body)
}

/// Disjoint sets of directions (union-find).
struct Sets {
    parent: Vec<usize>,
}

impl Sets {
    fn new(n: usize) -> Sets {
        Sets {
            parent: (0..n).collect(),
        }
    }

    fn root(&mut self, mut d: usize) -> usize {
        while self.parent[d] != d {
            self.parent[d] = self.parent[self.parent[d]];
            d = self.parent[d];
        }
        d
    }

    /// Joins the sets of `a` and `b`; returns the root.
    fn join(&mut self, a: usize, b: usize) -> usize {
        let (a, b) = (self.root(a), self.root(b));
        self.parent[b] = a;
        a
    }

    /// Joins the directions each lane of `plan` can be nonzero in; per lane, one of them.
    fn join_lanes(&mut self, plan: &Tangents) -> Vec<Option<usize>> {
        let mut seeds: Vec<Option<usize>> = Vec::with_capacity(plan.lanes.len());
        for lane in &plan.lanes {
            let mut seed = None;
            for t in &lane.terms {
                let d = match t.of {
                    Of::Lane(l) => seeds[l],
                    Of::Unit(j) => Some(usize::from(j)),
                };
                if let Some(d) = d {
                    seed = Some(seed.map_or(d, |s| self.join(s, d)));
                }
            }
            seeds.push(seed);
        }
        seeds
    }
}

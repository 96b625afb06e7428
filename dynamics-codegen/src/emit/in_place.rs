//! A result written into the caller's `&mut` (`y_`) rather than returned: the methods whose row
//! in the method table has `into` (the regressors). Each element is stored right after its
//! value is computed, output by output; returned whole, hundreds of values would wait on the
//! stack, past the registers, for the copy at the end.

use super::emitter::Emitter;
use super::expr::with_body;
use super::impls::{call_arguments, signature};
use super::items::{Generated, MethodCode};
use super::names::{local, Element, OUTPUT, PARAMETERS};
use crate::symbolic::NodeId;
use crate::trace::{Shape, BASE_COORDINATES};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

/// One innermost row of a result: the indices that lead to it, and its elements.
struct Row<'a> {
    path: Vec<usize>,
    elements: &'a [NodeId],
}

/// The innermost rows of `shape` and its value of zeros (`[[T::ZERO; 10]; 6]`), for a vector,
/// a matrix or a stack of matrices; `None` for another shape.
fn rows<'a>(shape: &Shape<'a>) -> Option<(Vec<Row<'a>>, TokenStream)> {
    let zeros = |len: usize, inner: TokenStream| {
        let len = Literal::usize_unsuffixed(len);
        quote!([#inner; #len])
    };
    let width = |rows: &[Vec<NodeId>]| rows.first().map_or(0, Vec::len);
    match shape {
        Shape::Vector(v) => Some((
            vec![Row {
                path: vec![],
                elements: v,
            }],
            zeros(v.len(), quote!(T::ZERO)),
        )),
        Shape::Matrix(m) => Some((
            m.iter()
                .enumerate()
                .map(|(i, row)| Row {
                    path: vec![i],
                    elements: row,
                })
                .collect(),
            zeros(m.len(), zeros(width(m), quote!(T::ZERO))),
        )),
        Shape::Stack(s) => {
            let rows = s.iter().enumerate().flat_map(|(i, m)| {
                m.iter().enumerate().map(move |(j, row)| Row {
                    path: vec![i, j],
                    elements: row,
                })
            });
            let matrix = s.first().map_or(&[][..], Vec::as_slice);
            let zero = zeros(
                s.len(),
                zeros(matrix.len(), zeros(width(matrix), quote!(T::ZERO))),
            );
            Some((rows.collect(), zero))
        }
        _ => None,
    }
}

/// `y_[i][j]`, or `*y_` for the empty path.
fn place(path: &[usize]) -> TokenStream {
    let y = local(OUTPUT);
    if path.is_empty() {
        return quote!(*#y);
    }
    let indices = path.iter().map(|&i| Literal::usize_unsuffixed(i));
    quote!(#y #([#indices])*)
}

impl Emitter<'_> {
    /// The statements writing `shape` into `y_`, and the shape's value of zeros (for the
    /// function that returns it, calling this one); `None` for a shape not written in place.
    /// First the rows of zeros and the elements that are leaves, then, output by output in the
    /// result's order (`base_rows_last`: a floating base's `M`, its joints' rows first), the
    /// bindings it needs that are not written yet (operands first) and its stores.
    pub(super) fn write_in_place(
        &mut self,
        shape: &Shape,
        output_names: &[(NodeId, Element)],
        base_rows_last: bool,
    ) -> Option<(Vec<TokenStream>, TokenStream)> {
        let (mut rows, zeros) = rows(shape)?;
        // A floating base's `M`: the joints' rows first, leg by leg, then the base's six.
        // Written base rows first, every leg's sines, cosines and composites were live from
        // the first row to the last and spilled (Solo 12: 567 stack accesses against 305,
        // 15 % of the time; the G1 20 %).
        if base_rows_last && rows.len() > BASE_COORDINATES {
            rows.rotate_left(BASE_COORDINATES);
        }
        let mut statements = Vec::new();
        let mut places: Vec<Vec<TokenStream>> = vec![Vec::new(); self.graph.len()];
        // A local starts as zeros, and a tree's `M` leaves them to the caller's matrix (the
        // `_into`'s contract): only the regressors store their zeros.
        let zeros_stored = !self.returned_in_place;
        for row in &rows {
            if row.elements.iter().all(|&id| self.graph.is_zero(id)) {
                if !zeros_stored {
                    continue;
                }
                let (y, len) = (
                    place(&row.path),
                    Literal::usize_unsuffixed(row.elements.len()),
                );
                statements.push(quote!(#y = [T::ZERO; #len];));
                continue;
            }
            for (k, &id) in row.elements.iter().enumerate() {
                let path: Vec<usize> = row.path.iter().copied().chain([k]).collect();
                if self.is_leaf(id) {
                    if !zeros_stored && self.graph.is_zero(id) {
                        continue;
                    }
                    let (y, e) = (place(&path), self.leaf(id));
                    statements.push(quote!(#y = #e;));
                } else {
                    places[id.index()].push(place(&path));
                }
            }
        }
        let mut done = vec![false; self.graph.len()];
        for &id in rows.iter().flat_map(|row| row.elements) {
            self.write_operands_first(id, &mut done, &places, output_names, &mut statements);
        }
        Some((statements, zeros))
    }

    /// The bindings `id` needs that are not written yet, in post-order, each followed by its
    /// stores into `y_`: a node read once and stored nowhere is written where it is read.
    fn write_operands_first(
        &mut self,
        id: NodeId,
        done: &mut [bool],
        places: &[Vec<TokenStream>],
        output_names: &[(NodeId, Element)],
        statements: &mut Vec<TokenStream>,
    ) {
        let mut pending = vec![(id, false)];
        while let Some((id, operands_done)) = pending.pop() {
            let i = id.index();
            if done[i] || self.is_leaf(id) {
                continue;
            }
            // A node of a shared function is read by its name: nothing to visit below it.
            if !self.stop[i] && !operands_done {
                pending.push((id, true));
                pending.extend(self.operands(id).into_iter().rev().map(|c| (c, false)));
                continue;
            }
            done[i] = true;
            if !self.stop[i] {
                if places[i].is_empty() && self.uses[i] <= 1 {
                    continue;
                }
                let element = output_names.iter().find(|(n, _)| *n == id).map(|&(_, e)| e);
                statements.push(self.bind(id, element));
            }
            let name = self.names.get(i).cloned();
            for y in &places[i] {
                statements.push(quote!(#y = #name;));
            }
        }
    }
}

impl Generated {
    /// The two functions of a method written in place: `name_into`, its body storing into
    /// `y_`, and `name`, calling it on zeros (which the stores overwrite: the optimiser drops
    /// them).
    pub(super) fn in_place_functions(
        &self,
        m: &MethodCode,
        zeros: &TokenStream,
        into: &str,
        krate: &TokenStream,
    ) -> TokenStream {
        let (name, into) = (
            Ident::new(m.name, Span::call_site()),
            Ident::new(into, Span::call_site()),
        );
        let (p, y, k) = (local(PARAMETERS), local(OUTPUT), self.fields.len());
        let scalar = Ident::new("T", Span::call_site());
        let (args, ret) = signature(m.method, &self.counts(), &scalar, krate, true);
        let pass = call_arguments(m.method);
        let head = quote! {
            #[inline(always)]
            pub(super) fn #into<T: #krate::Real>(#p: &[T; #k], #args, #y: &mut #ret)
        };
        let mut into_fn = with_body(head, m.body.clone());
        into_fn.extend(quote! {
            #[inline(always)]
            pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #args) -> #ret {
                let mut #y = #zeros;
                #into(#p, #pass, &mut #y);
                #y
            }
        });
        into_fn
    }
}

//! The body of a method: the shared fields it reads, its own terms in `q̇` and `q̈`, its
//! result; each output element bound under its name with a doc comment saying what it is.

use super::count::count;
use super::emitter::Emitter;
use super::expr::array;
use super::lanes::{lane_operations, Queue};
use super::names::{local, output_names, Element, OUTPUT};
use super::parts::Body;
use super::parts::OpCount;
use super::plan::Place;
use crate::method::{Argument, Method};
use crate::symbolic::{Node, NodeId};
use crate::trace::{Shape, Solved};
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;
use std::collections::HashMap;

impl Emitter<'_> {
    /// `let name = expr;` for node `id`, which from then on is read by its name: an output
    /// `element`'s name with a one-line doc comment saying what it is (which `cargo expand`
    /// shows), else a new temporary.
    pub(super) fn bind(&mut self, id: NodeId, element: Option<Element>) -> TokenStream {
        let name = match element {
            Some(element) => element.ident(),
            None => self.temporary(),
        };
        let e = self.define(id);
        self.names.set(id.index(), name.clone());
        let mut statement = match element {
            Some(element) => {
                let doc = format!(" {}", element.describe());
                quote!(#[doc = #doc] let #name =)
            }
            None => quote!(let #name =),
        };
        // Moved in, not interpolated: `quote!` would copy the expression's tokens.
        statement.extend([e, quote!(;)]);
        statement
    }

    /// Lanes stored as they are computed ([`Emitter::lanes_due`]) where asked for and every
    /// matrix has its plan: the zeros of the result they are stored into.
    fn lanes_in_place(&self, shape: &Shape) -> Option<TokenStream> {
        match shape {
            // A group of `∂q̈`'s rows stores its rows too.
            Shape::Lanes {
                stack,
                lanes,
                solved,
            } if self.returned_in_place
                && (solved.is_none() || self.kept.is_some())
                && lanes.iter().all(Option::is_some) =>
            {
                let n = Literal::usize_unsuffixed(self.eq.dof);
                let count = Literal::usize_unsuffixed(stack.len());
                Some(quote!([[[T::ZERO; #n]; #n]; #count]))
            }
            _ => None,
        }
    }

    /// A function's body computing `shape`: the configuration's fields it reads, then
    /// the terms in `q̇` and `q̈`, then the result, returned or, for a method with an `into`
    /// form, written into `y_` (`in_place`).
    pub(super) fn function(mut self, shape: &Shape, method: Method) -> Body {
        let outputs = self.lane_outputs(shape);
        self.mark(&outputs);
        self.bind_factors(shape);
        let mut lanes = Queue::new(shape, self.kept.as_deref());
        let mut output_names = output_names(shape, method, |id| self.is_leaf(id));
        // A scalar result is returned as an expression, not bound.
        if matches!(shape, Shape::Scalar(_)) {
            output_names.clear();
        }
        let mut statements = Vec::new();
        // A method without `q` (friction) calls no shared function: it reads its constants
        // and parameters itself.
        if !method.arguments().contains(&Argument::Q) {
            self.constants_and_parameters(&mut statements);
        }
        // The shared fields this function reads, bound under their names.
        statements.extend(self.bind_shared(true));
        statements.extend(self.joint_variables());
        // A tree's `M` is written apart and in place: its `_into` leaves the zero blocks between
        // the branches unwritten ([`Emitter::write_in_place`]).
        let into = method.always_in_place()
            || (method.in_place_name().is_some() && self.returned_in_place);
        if into || self.returned_in_place {
            if let Some((stores, zeros)) =
                self.write_in_place(shape, &output_names, method == Method::FloatingMassMatrix)
            {
                statements.extend(stores);
                let y = local(OUTPUT);
                let (tokens, zeros) = if into {
                    (statements.into_iter().collect(), Some(zeros))
                } else {
                    // Moved in, not interpolated: `quote!` would copy the statements.
                    let mut tokens = quote!(let mut #y = #zeros;);
                    tokens.extend(statements);
                    tokens.extend([quote!(#y)]);
                    (tokens, None)
                };
                return Body {
                    tokens,
                    ops: self.count(&outputs),
                    zeros,
                    lanes: false,
                };
            }
        }
        let lanes_in_place = self.lanes_in_place(shape);
        self.returned_in_place = lanes_in_place.is_some();
        // By node, rather than a search of the outputs at every node.
        let mut is_output = vec![false; self.graph.len()];
        for o in &outputs {
            is_output[o.index()] = true;
        }
        let element_of: HashMap<NodeId, Element> = output_names.iter().copied().collect();
        for id in self.needed_in_order() {
            let i = id.index();
            if self.stop[i] || self.is_leaf(id) {
                continue;
            }
            // A scalar result is written in place unless it is read elsewhere too.
            let bound_output = is_output[i] && !matches!(shape, Shape::Scalar(_));
            if self.uses[i] <= 1 && !bound_output {
                continue;
            }
            // The lanes due before a node that writes nothing come before the next that does:
            // the same statements in the same order, without a call at every node.
            self.lanes_due(&mut lanes, Some(id), &mut statements);
            let element = element_of.get(&id).copied();
            statements.push(self.bind(id, element));
        }
        self.lanes_due(&mut lanes, None, &mut statements);
        let result = if self.kept.is_some() {
            // A group's function: the caller's `y_` holds the zeros and is returned there.
            self.group_result(shape)
        } else if let Some(zeros) = &lanes_in_place {
            let y = local(OUTPUT);
            statements.insert(0, quote!(let mut #y = #zeros;));
            quote!(#y)
        } else {
            self.result(shape)
        };
        Body {
            tokens: statements.into_iter().chain([result]).collect(),
            ops: OpCount {
                lanes: lane_operations(shape),
                ..self.count(&outputs)
            },
            zeros: None,
            lanes: matches!(shape, Shape::Lanes { .. }),
        }
    }

    /// The value a function of `shape` returns, its elements bound before.
    fn result(&mut self, shape: &Shape) -> TokenStream {
        match shape {
            Shape::Scalar(id) => self.expr(*id, Place::Top),
            Shape::Lanes {
                stack,
                lanes,
                solved: None,
            } => self.lane_stack(stack, lanes),
            Shape::Lanes {
                stack,
                lanes,
                solved: Some(Solved { pivots, vector }),
            } => {
                let items: Vec<TokenStream> =
                    vector.iter().map(|&id| self.expr(id, Place::Top)).collect();
                let matrices = self.lane_stack(stack, lanes);
                self.checked(pivots, &quote!(([#(#items),*], #matrices)))
            }
            Shape::Vector(v) => {
                let items: Vec<TokenStream> =
                    v.iter().map(|&id| self.expr(id, Place::Top)).collect();
                quote!([#(#items),*])
            }
            Shape::Matrix(m) => self.matrix(m),
            Shape::Stack(s) => self.stack(s),
            Shape::SolvedVector { pivots, vector } => {
                let items: Vec<TokenStream> =
                    vector.iter().map(|&id| self.expr(id, Place::Top)).collect();
                self.checked(pivots, &quote!([#(#items),*]))
            }
            Shape::SolvedMatrix { pivots, matrix } => {
                let value = self.matrix(matrix);
                self.checked(pivots, &value)
            }
            Shape::SolvedStack {
                pivots,
                vector,
                stack,
            } => {
                let items: Vec<TokenStream> =
                    vector.iter().map(|&id| self.expr(id, Place::Top)).collect();
                let matrices = self.stack(stack);
                self.checked(pivots, &quote!(([#(#items),*], #matrices)))
            }
        }
    }

    /// `Some(value)` where every pivot is positive (false for NaN), else `None`; the value is
    /// computed either way, since floating-point division by zero does not trap. A constant
    /// positive pivot needs no test. The test is `Real::all_positive`, not `>`: on the lane
    /// types (which have no order) it is true where every lane is positive, so a `None` there
    /// means that at least one lane failed. By reference, as `>` takes its operands: the same
    /// machine code as `d > T::ZERO` for `f64` and `f32`.
    fn checked(&mut self, pivots: &[NodeId], value: &TokenStream) -> TokenStream {
        match self.positive(pivots) {
            None => quote!(::core::option::Option::Some(#value)),
            Some(tests) => quote!(if #tests {
                ::core::option::Option::Some(#value)
            } else {
                ::core::option::Option::None
            }),
        }
    }

    /// Whether every pivot is positive, `T::all_positive(&d1) && ⋯`; `None` where each is a
    /// positive constant.
    pub(super) fn positive(&mut self, pivots: &[NodeId]) -> Option<TokenStream> {
        let graph = self.graph;
        let positive = |id: NodeId| matches!(graph.node(id), Node::Const(c) if c.to_f64() > 0.0);
        let tests: Vec<TokenStream> = pivots
            .iter()
            .filter(|&&id| !positive(id))
            .map(|&id| {
                let d = self.expr(id, Place::Top);
                quote!(T::all_positive(&#d))
            })
            .collect();
        (!tests.is_empty()).then(|| quote!(#(#tests)&&*))
    }

    /// The array of arrays of matrix `m`'s rows.
    pub(super) fn matrix(&mut self, m: &[Vec<NodeId>]) -> TokenStream {
        let rows: Vec<TokenStream> = m
            .iter()
            .map(|r| array(r.iter().map(|&id| self.expr(id, Place::Top))))
            .collect();
        array(rows)
    }

    /// The array of matrices `s`.
    fn stack(&mut self, s: &[Vec<Vec<NodeId>>]) -> TokenStream {
        let matrices: Vec<TokenStream> = s.iter().map(|m| self.matrix(m)).collect();
        array(matrices)
    }

    /// The operations of the code computing `outputs` ([`count`]), where the context asks.
    fn count(&self, outputs: &[NodeId]) -> OpCount {
        match self.ctx {
            Some(ctx) if !ctx.counted => OpCount::default(),
            _ => count(self.eq, outputs),
        }
    }

    /// A new temporary, `t3` (`u3`, `v3` in the shared functions).
    fn temporary(&mut self) -> Ident {
        self.temporaries += 1;
        local(&format!("{}{}", self.temporary_prefix, self.temporaries))
    }
}

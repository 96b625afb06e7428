//! The bodies of the shared functions: the configuration, what depends on the parameters and
//! `q` alone, and the motion, what several methods compute from `q̇` too; and the statements
//! with which a function binds the fields it reads of them.

use super::depends::Depends;
use super::emitter::{Emitter, Origin};
use super::names::{
    local, Element, CONFIGURATION_FN, CONFIGURATION_LOCAL, CONFIGURATION_STRUCT, MOTION_FN,
    MOTION_STRUCT, PARAMETERS,
};
use super::parts::Shared;
use super::plan::Place;
use crate::symbolic::{Node, NodeId, Var};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

impl Emitter<'_> {
    /// The body of the configuration function: computes `boundary` and returns it as the
    /// configuration struct, each node under its field name where `field_names` has one.
    pub(super) fn configuration(
        &mut self,
        boundary: &[NodeId],
        field_names: &[Option<Element>],
        depends: &[Depends],
    ) -> Shared {
        self.mark(boundary);
        let mut statements = Vec::new();
        self.constants_and_parameters(&mut statements);
        statements.extend(self.joint_variables());
        // What depends on the parameters alone first, then the sines and cosines, then the
        // rest.
        for phase in [Depends::Constants, Depends::Configuration] {
            if phase == Depends::Configuration {
                self.sines_and_cosines(&mut statements);
            }
            self.bind_shared_nodes(
                &|i| depends[i] == phase,
                boundary,
                field_names,
                &mut statements,
            );
        }
        // The struct literal, one field per boundary node, named as its local.
        let locals: Vec<TokenStream> = boundary.iter().map(|&id| self.leaf(id)).collect();
        let fields = boundary.iter().map(|&id| self.field(id)).collect();
        let ty = Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        Shared {
            fields,
            tokens: statements
                .into_iter()
                .chain([quote!(#ty { #(#locals),* })])
                .collect(),
        }
    }

    /// `let k1: T = …;` for each needed constant and `let [p_m1, _, …] = *p_;` for the
    /// parameters: what the configuration reads first, and a function without one itself.
    pub(super) fn constants_and_parameters(&mut self, statements: &mut Vec<TokenStream>) {
        let ctx = self.ctx.expect("emission has a context");
        // Constants, once each.
        let mut constants = 0;
        for (id, _) in self.graph.leaves() {
            if self.needed[id.index()] && self.is_named_constant(id) {
                let value = self.leaf(id);
                constants += 1;
                let k = local(&format!("k{constants}"));
                statements.push(quote!(let #k: T = #value;));
                self.names.set(id.index(), k);
            }
        }
        // Parameters, read once: `let [p_m1, _, p_cx1, …] = *p_;`.
        let mut parameters = vec![quote!(_); self.eq.fields.len()];
        let mut any = false;
        for (id, node) in self.graph.leaves() {
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
    }

    /// `let name = …;` for each needed node that `select` admits (by index) and that is read
    /// more than once or handed over (in `boundary`), in the arena's order, under its name in
    /// `field_names` or a new temporary.
    fn bind_shared_nodes(
        &mut self,
        select: &dyn Fn(usize) -> bool,
        boundary: &[NodeId],
        field_names: &[Option<Element>],
        statements: &mut Vec<TokenStream>,
    ) {
        let mut handed_over = vec![false; self.graph.len()];
        for id in boundary {
            handed_over[id.index()] = true;
        }
        for id in self.needed_in_order() {
            let i = id.index();
            if !select(i) || self.is_leaf(id) {
                continue;
            }
            if self.uses[i] <= 1 && !handed_over[i] {
                continue;
            }
            statements.push(self.bind(id, field_names[i]));
        }
    }

    /// The body of the motion function: computes the configuration (`let c_ =
    /// configuration(p_, q_);`), reads the fields it needs, computes `boundary` and returns both
    /// structs, `(c_, Motion { … })`.
    pub(super) fn motion(
        &mut self,
        boundary: &[NodeId],
        field_names: &[Option<Element>],
    ) -> Shared {
        self.mark(boundary);
        let mut statements = self.bind_shared(false);
        statements.extend(self.joint_variables());
        let stop = self.stop.clone();
        self.bind_shared_nodes(&|i| !stop[i], boundary, field_names, &mut statements);
        let locals: Vec<TokenStream> = boundary
            .iter()
            .map(|&id| self.expr(id, Place::Top))
            .collect();
        let fields = boundary.iter().map(|&id| self.field(id)).collect();
        let ty = Ident::new(MOTION_STRUCT, Span::call_site());
        let result = quote!(#ty { #(#locals),* });
        let c = local(CONFIGURATION_LOCAL);
        // Moved in, not interpolated: `quote!` would copy the statements.
        let mut tokens: TokenStream = statements.into_iter().collect();
        if self.has_configuration {
            tokens.extend([quote!((#c, #result))]);
        } else {
            tokens.extend([result]);
        }
        Shared { fields, tokens }
    }

    /// The statements binding the shared fields this function reads: in a method,
    /// `let Configuration { s2, .. } = configuration(p_, q_);`, or when it reads the motion too,
    /// `let (Configuration { s2, .. }, Motion { v3, .. }) = motion(p_, q_, qd_);`; in the motion
    /// function (`in_method` false), `let c_ = configuration(p_, q_);` and
    /// `let Configuration { s2, .. } = c_;`.
    pub(super) fn bind_shared(&self, in_method: bool) -> Vec<TokenStream> {
        // The stop nodes in the arena's order, without a walk of the whole arena.
        let mut stops = self.stops.clone();
        stops.sort_unstable();
        stops.dedup();
        let read = |origin: Origin| -> Vec<Ident> {
            stops
                .iter()
                .filter(|id| {
                    let i = id.index();
                    self.needed[i] && self.origin[i] == origin
                })
                .filter_map(|id| self.names.get(id.index()).cloned())
                .collect()
        };
        let (config, motion) = (read(Origin::Configuration), read(Origin::Motion));
        let ty = Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        let f = Ident::new(CONFIGURATION_FN, Span::call_site());
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
        let mty = Ident::new(MOTION_STRUCT, Span::call_site());
        let mf = Ident::new(MOTION_FN, Span::call_site());
        if self.has_configuration {
            statements.push(quote!(
                let (#ty { #(#config,)* .. }, #mty { #(#motion,)* .. }) = #mf(#p, #q, #qd);
            ));
        } else {
            statements.push(quote!(let #mty { #(#motion,)* .. } = #mf(#p, #q, #qd);));
        }
        statements
    }

    /// The struct field handing over node `id`: named as its local.
    fn field(&self, id: NodeId) -> Ident {
        let mut field = self
            .name(id)
            .expect("a handed-over node is bound to a name");
        field.set_span(Span::call_site());
        field
    }
}

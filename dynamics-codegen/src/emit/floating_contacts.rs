//! The derive's items for the contact terms of a robot on a free-flying base
//! ([`crate::trace::FloatingContactEquations`]): a module `__floating_contacts` of one function,
//! `contact_terms(p, q, v, tau)` over the floating coordinates (as [`super::floating_items`]'s),
//! which returns, where every pivot of `M` is positive, `[a₀; J a₀ + γ]` and the rows
//! `[(M⁻¹ J_rᵀ)ᵀ, (J M⁻¹ Jᵀ)_r]` packed in one array (the emitter's solved stack), and the
//! `FloatingContactTerms<NQ, NV, F>` impl, which unpacks them into `ContactTerms`.
//!
//! The function borrows the element names of the fixed base's `forward_dynamics`, whose
//! arguments it takes (`q`, `v`, `tau`), within this module only.

use super::expr::with_body;
use super::impls::argument_local;
use super::items::{Generated, PARAMETERS_FN};
use super::program::{emit, Emission};
use super::{local, Context, OpCount, Output, PARAMETERS};
use crate::method::{Argument, Method};
use crate::trace::{Equations, FloatingContactEquations, FloatingKinematicEquations, Shape};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// The fixed base's method whose arguments the function takes and whose names it borrows.
const CARRIER: Method = Method::ForwardDynamics;

/// The items of the contact terms `out` of the floating robot `input` (equations `eq`, struct
/// fields read by `fields`), for the derive's `const _: () = { … };` block beside
/// [`super::floating_items`]'s (whose parameters' reader they call).
#[must_use]
pub fn floating_contacts_items(
    eq: &Equations,
    out: &FloatingContactEquations,
    fields: &[TokenStream],
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    let emission = emission(eq, out, false);
    let nv = eq.dof;
    let (width, rows) = (out.free.len(), out.rows.len());
    let generated = Generated::counts_only(eq, fields);
    let (p, k) = (local(PARAMETERS), fields.len());
    let (q, v, tau) = (
        argument_local(Argument::Q),
        argument_local(Argument::Qd),
        argument_local(Argument::Tau),
    );
    let head = quote! {
        #[inline(always)]
        pub(super) fn contact_terms<T: #krate::Real>(#p: &[T; #k], #q: &[T; #nv], #v: &[T; #nv], #tau: &[T; #nv])
            -> ::core::option::Option<([T; #width], [[[T; #width]; #rows]; 1])>
    };
    let function = with_body(head, emission.bodies[0].tokens.clone());
    let configuration = generated.configuration_item(emission.configuration.as_ref(), krate);
    let motion = generated.motion_item(
        emission.motion.as_ref(),
        emission.configuration.is_some(),
        krate,
    );
    let impls = trait_impl(nv, rows / 3, krate, input);
    quote! {
        /// The generated function, out of reach of the names around the derive.
        #[allow(non_snake_case, non_camel_case_types, unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
        mod __floating_contacts {
            #configuration
            #motion
            #function
        }
        #impls
    }
}

/// The emission of the one function, its operations `counted` or not.
fn emission(eq: &Equations, out: &FloatingContactEquations, counted: bool) -> Emission {
    let ctx = Context {
        parameters: local(PARAMETERS),
        counted,
    };
    let stack = [out.rows.clone()];
    let shape = Shape::SolvedStack {
        pivots: &eq.forward.factors.pivots,
        vector: &out.free,
        stack: &stack,
    };
    let output = Output {
        method: CARRIER,
        shape,
    };
    emit(eq, &[output], &ctx)
}

/// The operations of the emitted function (for `dynamics stats --floating`).
#[must_use]
pub fn floating_contacts_count(eq: &Equations, out: &FloatingContactEquations) -> OpCount {
    emission(eq, out, true).bodies[0].ops
}

/// `impl FloatingContactTerms<NQ, NV, F>` with the closed form.
fn trait_impl(
    nv: usize,
    frames: usize,
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    let nq = nv + 1;
    let (ident, generics) = (&input.ident, &input.generics);
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
    let (q, v, tau) = (
        argument_local(Argument::Q),
        argument_local(Argument::Qd),
        argument_local(Argument::Tau),
    );
    quote! {
        #[automatically_derived]
        impl #impl_generics #krate::FloatingContactTerms<#nq, #nv, #frames> for #ident #ty_generics #where_clause {
            const CLOSED_FORM: bool = true;
            #[inline]
            fn contact_terms<T: #krate::Real>(&self, #q: &[T; #nq], #v: &[T; #nv], #tau: &[T; #nv])
                -> ::core::result::Result<#krate::ContactTerms<T, #nv, #frames>, #krate::NotPositiveDefinite>
            {
                // The graph's coordinates leave out the base's x, which nothing here reads.
                let q = ::core::array::from_fn(|i| #q[i + 1]);
                match __floating_contacts::contact_terms(&self.#parameters(), &q, #v, #tau) {
                    ::core::option::Option::Some((free, [rows])) => {
                        ::core::result::Result::Ok(#krate::ContactTerms::from_packed(&free, &rows))
                    }
                    ::core::option::Option::None => ::core::result::Result::Err(#krate::NotPositiveDefinite),
                }
            }
        }
    }
}

/// `impl FloatingContactTerms<NQ, NV, F>` without `contacts = true`: the trait's provided
/// method computes the terms at run time from the generated `M⁻¹`, `h` and Jacobians.
#[must_use]
pub fn floating_contacts_at_run_time(
    nv: usize,
    kinematics: &FloatingKinematicEquations,
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    let (nq, frames) = (nv + 1, kinematics.frame_names.len());
    let (ident, generics) = (&input.ident, &input.generics);
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    quote! {
        #[automatically_derived]
        impl #impl_generics #krate::FloatingContactTerms<#nq, #nv, #frames> for #ident #ty_generics #where_clause {}
    }
}

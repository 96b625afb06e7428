//! The derive's items for a robot on a free-flying base: the module of `M`, `h`, `τ` and `g`
//! emitted as every family's is, over the coordinates `[y, z, qx, qy, qz, qw, q_1 …]` of
//! [`crate::trace::derive_floating`] (`n + 6` entries, as the velocity), and the
//! `FloatingDynamics<NQ, NV>` impl, whose methods take the configuration's `n + 7` entries and
//! pass on all but the first (the base's x, which nothing reads).

use super::impls::{forward, signature, Counts};
use super::items::{module_name, Generated, MethodCode, Module, PARAMETERS_FN};
use super::program::emit;
use super::{local, Context, Output, PARAMETERS};
use crate::method::{Argument, Family, Method};
use crate::trace::Equations;
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// The floating-base methods: the `Dynamics` method whose output of [`Equations`] each
/// returns, and its name in `FloatingDynamics`.
const METHODS: [(Method, &str); 4] = [
    (Method::MassMatrix, "mass_matrix"),
    (Method::BiasTorques, "bias_forces"),
    (Method::InverseDynamics, "inverse_dynamics"),
    (Method::GravityTorques, "generalized_gravity"),
];

/// The items of the floating-base robot `ident` whose equations are `eq`; `fields` reads its
/// struct fields, in the order of [`Equations::fields`]. They go in a `const _: () = { … };`
/// block.
#[must_use]
pub fn floating_items(
    eq: &Equations,
    fields: &[TokenStream],
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    // The derive reads no operation counts (`dynamics stats` does not know floating robots).
    let ctx = Context {
        parameters: local(PARAMETERS),
        counted: false,
    };
    let outputs: Vec<Output> = METHODS
        .iter()
        .map(|&(method, _)| Output {
            method,
            shape: method.shape(eq),
        })
        .collect();
    let emission = emit(eq, &outputs, &ctx);
    let methods = METHODS
        .iter()
        .zip(emission.bodies)
        .map(|(&(method, _), b)| MethodCode {
            method,
            name: method.name(),
            body: b.tokens,
            ops: b.ops,
            zeros: b.zeros,
            lanes: b.lanes,
        })
        .collect();
    let module = Module {
        family: Family::Dynamics,
        configuration: emission.configuration,
        motion: emission.motion,
    };
    let generated = Generated {
        dof: eq.dof,
        base_count: 0,
        links: eq.links,
        joint_rows: None,
        tip_names: None,
        fields: fields.to_vec(),
        modules: Vec::new(),
        methods,
    };
    let ident = &input.ident;
    let module = generated.module(&module, krate, ident);
    let impls = trait_impl(&generated, krate, input);
    quote! {
        #module
        #impls
    }
}

/// The parameters' reader and `impl FloatingDynamics<NQ, NV>`.
fn trait_impl(generated: &Generated, krate: &TokenStream, input: &syn::DeriveInput) -> TokenStream {
    let (nv, k) = (generated.dof, generated.fields.len());
    let nq = nv + 1;
    let (ident, generics) = (&input.ident, &input.generics);
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let t = Ident::new("T", Span::call_site());
    let counts = Counts {
        joints: quote!(#nv),
        base: quote!(0),
        tips: quote!(0),
        links: quote!(#nv),
    };
    let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
    let module = module_name(Family::Dynamics, ident);
    let fns = METHODS.iter().map(|&(method, name)| {
        let name = Ident::new(name, Span::call_site());
        let inner = Ident::new(method.name(), Span::call_site());
        let (_, ret) = signature(method, &counts, &t, krate, false);
        let (mut args, mut pass) = (Vec::new(), Vec::new());
        for &a in method.arguments() {
            if a == Argument::Q {
                args.push(quote!(q: &[#t; #nq]));
                pass.push(quote!(&::core::array::from_fn(|i| q[i + 1])));
            } else {
                let public = Ident::new(public_name(a), Span::call_site());
                args.push(quote!(#public: &[#t; #nv]));
                pass.push(quote!(#public));
            }
        }
        let call = quote!(#module::#inner(&self.#parameters(), #(#pass),*));
        let call = forward(method, call, &counts, &t, krate);
        quote! {
            #[inline]
            fn #name<#t: #krate::Real>(&self, #(#args),*) -> #ret {
                #call
            }
        }
    });
    let fields = &generated.fields;
    let reader = (k > 0).then(|| quote!(use #krate::__private::param;));
    quote! {
        impl #impl_generics #ident #ty_generics #where_clause {
            /// The parameters the equations read, in the order of the description.
            #[doc(hidden)]
            #[inline(always)]
            #[allow(clippy::all, clippy::pedantic, clippy::nursery)]
            fn #parameters<#t: #krate::Real>(&self) -> [#t; #k] {
                #reader
                [#(param(#fields)),*]
            }
        }
        #[automatically_derived]
        impl #impl_generics #krate::FloatingDynamics<#nq, #nv> for #ident #ty_generics #where_clause {
            #(#fns)*
        }
    }
}

/// The trait's name for an argument other than `q`: `v`, `a`.
fn public_name(argument: Argument) -> &'static str {
    match argument {
        Argument::Qdd => "a",
        _ => "v",
    }
}

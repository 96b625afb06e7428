//! The derive's items for a robot on a free-flying base: the module of its family's methods
//! (the method table's `FloatingDynamics` rows, emitted as every family's are, over the
//! coordinates `[y, z, qx, qy, qz, qw, q_1 …]` of [`crate::trace::derive_floating`], `n + 6`
//! entries, as the velocity), and the `FloatingDynamics<NQ, NV>` impl, whose methods take the
//! configuration's `n + 7` entries and pass on all but the first (the base's x, which nothing
//! reads). The modules of a family with a method compiled apart (the derivatives') go beside
//! the struct, as a fixed base's ([`Items::beside`]).

use super::impls::{forward, signature, Counts};
use super::items::{generate_uncounted, module_name, Generated, Items, PARAMETERS_FN};
use super::names::{local, OUTPUT};
use crate::method::{Argument, Method};
use crate::trace::Equations;
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// The items of the floating-base robot `ident` whose equations are `eq`; `fields` reads its
/// struct fields, in the order of [`Equations::fields`]. Those of [`Items::within`] go in a
/// `const _: () = { … };` block, those of [`Items::beside`] beside the struct.
#[must_use]
pub fn floating_items(
    eq: &Equations,
    fields: &[TokenStream],
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> Items {
    let mut generated = generate_uncounted(eq, fields.to_vec());
    // The regressor's bodies: the floating one and the links.
    generated.links = eq
        .regressor
        .as_ref()
        .map_or(eq.links, |r| r.parameters.len());
    let ident = &input.ident;
    let (beside, within): (Vec<_>, Vec<_>) = generated
        .modules
        .iter()
        .partition(|module| module.family.is_beside_the_struct());
    let module = |m: &&super::Module| generated.module(m, krate, ident);
    let (beside, modules) = (beside.iter().map(module), within.iter().map(module));
    let (beside, modules): (Vec<TokenStream>, Vec<TokenStream>) =
        (beside.collect(), modules.collect());
    let impls = trait_impl(&generated, krate, input);
    Items {
        beside: quote!(#(#beside)*),
        within: quote! {
            #(#modules)*
            #impls
        },
    }
}

/// The parameters' reader and `impl FloatingDynamics<NQ, NV>`.
fn trait_impl(generated: &Generated, krate: &TokenStream, input: &syn::DeriveInput) -> TokenStream {
    let (nv, k) = (generated.dof, generated.fields.len());
    let nq = nv + 1;
    let (ident, generics) = (&input.ident, &input.generics);
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let t = Ident::new("T", Span::call_site());
    let (base, links) = (generated.base_count, generated.links);
    let counts = Counts {
        joints: quote!(#nv),
        base: quote!(#base),
        tips: quote!(0),
        links: quote!(#links),
    };
    let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
    let fns: Vec<(Method, TokenStream)> = generated
        .methods
        .iter()
        .map(|code| {
            let method = code.method;
            let module = module_name(method.family(), ident);
            let name = Ident::new(code.name, Span::call_site());
            let (_, ret) = signature(method, &counts, &t, krate, false);
            let (args, pass) = arguments(method, &t, nv);
            let call = quote!(#module::#name(&self.#parameters(), #(#pass),*));
            // A function compiled apart returns the trait's type itself.
            let call = if method.is_compiled_apart() {
                call
            } else {
                forward(method, call, &counts, &t, krate)
            };
            // A tree's `M` written in place: the blocks between the legs left as the caller's.
            let into = code.zeros.as_ref().and(method.in_place_name()).map(|into| {
                let (into, y) = (Ident::new(into, Span::call_site()), local(OUTPUT));
                quote! {
                    #[inline]
                    fn #into<#t: #krate::Real>(&self, #(#args),*, #y: &mut #ret) {
                        #module::#into(&self.#parameters(), #(#pass),*, #y)
                    }
                }
            });
            let function = quote! {
                #[inline]
                fn #name<#t: #krate::Real>(&self, #(#args),*) -> #ret {
                    #call
                }
                #into
            };
            (method, function)
        })
        .collect();
    // One impl per trait, in the table's order.
    let mut traits: Vec<&str> = fns.iter().map(|(m, _)| m.family().trait_name()).collect();
    traits.dedup();
    let impls = traits.into_iter().map(|name| {
        let functions = fns.iter().filter(|(m, _)| m.family().trait_name() == name);
        let counts_of = functions.clone().next().map(|(m, _)| m.family().count_parameters());
        // The trait's counts of its own (`B`, `LINKS`), after the two lengths.
        let own = counts_of.unwrap_or_default().iter().map(|&c| match c {
            "LINKS" => &counts.links,
            _ => &counts.base,
        });
        let functions = functions.map(|(_, f)| f);
        let name = Ident::new(name, Span::call_site());
        quote! {
            #[automatically_derived]
            impl #impl_generics #krate::#name<#nq, #nv #(, #own)*> for #ident #ty_generics #where_clause {
                #(#functions)*
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
        #(#impls)*
    }
}

/// A method's arguments in the trait (`q: &[T; NQ]`, the others `&[T; NV]`) and what it passes
/// its module's function: `q` without its first entry (the base's x, which nothing reads).
fn arguments(method: Method, t: &Ident, nv: usize) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let nq = nv + 1;
    let (mut args, mut pass) = (Vec::new(), Vec::new());
    for (&a, &public) in method.arguments().iter().zip(method.argument_names()) {
        let public = Ident::new(public, Span::call_site());
        if a == Argument::Q {
            args.push(quote!(#public: &[#t; #nq]));
            pass.push(quote!(&::core::array::from_fn(|i| #public[i + 1])));
        } else {
            args.push(quote!(#public: &[#t; #nv]));
            pass.push(quote!(#public));
        }
    }
    (args, pass)
}

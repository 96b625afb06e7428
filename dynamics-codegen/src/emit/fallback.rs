//! The expansion of a derive that failed: its errors, plus an impl whose methods are
//! unreachable, so that code calling them compiles and the user sees only the real errors.

use super::impls::{method, runtime_path, scalar_name, trait_impls, Sizes};
use crate::front;
use crate::method::{Family, Method};
use proc_macro2::TokenStream;
use quote::quote;

/// The errors, and an impl of every [`Method`] of the families asked for, unreachable: for
/// the robot's number of joints where it was read, else for any number, so that each mistake
/// is one error even where the robot could not be read at all (a missing file, a base link the
/// URDF does not have); the tips' constants where their names are known.
pub(crate) fn fallback(input: &syn::DeriveInput, failure: &front::Failure) -> TokenStream {
    let errors = failure.error.to_compile_error();
    let names = failure.tip_names.as_deref();
    let sizes = Sizes {
        joints: failure.dof,
        base: None,
        tips: names.map(<[String]>::len),
        links: None,
    };
    let krate = runtime_path(failure.krate.as_ref());
    let impls = unreachable_impls(input, &sizes, &krate, |m| failure.families.has(m));
    let constants = names.map(|names| {
        let ident = &input.ident;
        let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
        let constants = super::tip_names::constants(names);
        quote!(impl #impl_generics #ident #ty_generics #where_clause { #constants })
    });
    quote! {
        #errors
        const _: () = {
            #impls
            #constants
        };
    }
}

/// The impls of `family`'s methods for a robot of `joints` coordinates and `links` links,
/// unreachable: beside the error of a family the derive could not trace.
pub(crate) fn unreachable_family(
    input: &syn::DeriveInput,
    (joints, links): (usize, usize),
    krate: &TokenStream,
    family: Family,
) -> TokenStream {
    let sizes = Sizes {
        joints: Some(joints),
        base: None,
        tips: None,
        links: (links != joints).then_some(links),
    };
    unreachable_impls(input, &sizes, krate, |m| m.family() == family)
}

/// The impls of the methods `wanted`, unreachable.
fn unreachable_impls(
    input: &syn::DeriveInput,
    sizes: &Sizes,
    krate: &TokenStream,
    wanted: impl Fn(Method) -> bool,
) -> TokenStream {
    let counts = &sizes.counts(&input.generics);
    let body = quote!(::core::unreachable!("the Dynamics derive failed"));
    let t = scalar_name(&input.generics);
    let fns = Method::ALL.iter().copied().filter(|&m| wanted(m));
    let fns = fns.map(|m| (m, method(m, counts, krate, &t, &body)));
    trait_impls(krate, sizes, &input.ident, &input.generics, fns)
}

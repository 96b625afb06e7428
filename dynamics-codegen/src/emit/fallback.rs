//! The expansion of a derive that failed: its errors, plus an impl whose methods are
//! unreachable, so that code calling them compiles and the user sees only the real errors.

use super::impls::{method, runtime_path, scalar_name, trait_impls, Sizes};
use crate::front;
use crate::method::Method;
use proc_macro2::TokenStream;
use quote::quote;

/// The errors, and an impl of every [`Method`] of the families asked for, unreachable: for
/// the robot's number of joints where it was read, else for any number, so that each mistake
/// is one error even where the robot could not be read at all (a missing file, a base link the
/// URDF does not have).
pub(crate) fn fallback(input: &syn::DeriveInput, failure: &front::Failure) -> TokenStream {
    let errors = failure.error.to_compile_error();
    let sizes = Sizes {
        joints: failure.dof,
        base: None,
    };
    let counts = &sizes.counts(&input.generics);
    let krate = runtime_path(failure.krate.as_ref());
    let body = quote!(::core::unreachable!("the Dynamics derive failed"));
    let t = scalar_name(&input.generics);
    let fns = Method::ALL
        .iter()
        .copied()
        .filter(|&m| failure.families.has(m));
    let fns = fns.map(|m| (m, method(m, counts, &krate, &t, &body)));
    let impls = trait_impls(&krate, &sizes, &input.ident, &input.generics, fns);
    quote! {
        #errors
        const _: () = {
            #impls
        };
    }
}

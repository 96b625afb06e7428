//! The expansion of a derive that failed: its errors, plus an impl whose methods are
//! unreachable, so that code calling them compiles and the user sees only the real errors.

use super::impls::{method, runtime_path, scalar_name, trait_impls};
use crate::front;
use crate::method::Method;
use proc_macro2::TokenStream;
use quote::quote;

/// The errors, and where the joint count is known an impl of every [`Method`] of the families
/// asked for, unreachable.
pub(crate) fn fallback(input: &syn::DeriveInput, failure: &front::Failure) -> TokenStream {
    let errors = failure.error.to_compile_error();
    let Some(n) = failure.dof else {
        return errors;
    };
    let krate = runtime_path(failure.krate.as_ref());
    let body = quote!(::core::unreachable!("the Dynamics derive failed"));
    let t = scalar_name(&input.generics);
    let fns = Method::ALL
        .iter()
        .copied()
        .filter(|&m| failure.families.has(m));
    let fns = fns.map(|m| (m, method(m, n, &krate, &t, &body)));
    let impls = trait_impls(&krate, n, &input.ident, &input.generics, fns);
    quote! {
        #errors
        const _: () = {
            #impls
        };
    }
}

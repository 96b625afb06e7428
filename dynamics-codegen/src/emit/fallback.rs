//! The expansion of a derive that failed: its errors, plus an impl whose methods are
//! unreachable, so that code calling them compiles and the user sees only the real errors.

use super::items::{method, runtime_path, scalar_name};
use crate::front;
use crate::method::Method;
use proc_macro2::TokenStream;
use quote::quote;

/// The errors, and where the joint count is known an impl of every [`Method`] (of
/// `DynamicsDerivatives` too if the robot asked for it), unreachable.
pub(crate) fn fallback(input: &syn::DeriveInput, failure: &front::Failure) -> TokenStream {
    let errors = failure.error.to_compile_error();
    let Some(n) = failure.dof else {
        return errors;
    };
    let krate = runtime_path(failure.krate.as_ref());
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let body = quote!(::core::unreachable!("the Dynamics derive failed"));
    let t = scalar_name(&input.generics);
    let fns = |family_trait: &str| -> Vec<TokenStream> {
        let methods = Method::ALL.iter().copied();
        let in_trait = methods.filter(|m| m.family().trait_name() == family_trait);
        in_trait.map(|m| method(m, n, &krate, &t, &body)).collect()
    };
    let dynamics = fns("Dynamics");
    let derivatives = fns("DynamicsDerivatives");
    let derivatives = failure.derivatives.then(|| {
        quote! {
            #[automatically_derived]
            impl #impl_generics #krate::DynamicsDerivatives<#n> for #ident #ty_generics #where_clause {
                #(#derivatives)*
            }
        }
    });
    quote! {
        #errors
        const _: () = {
            #[automatically_derived]
            impl #impl_generics #krate::Dynamics<#n> for #ident #ty_generics #where_clause {
                #(#dynamics)*
            }
            #derivatives
        };
    }
}

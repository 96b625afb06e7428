//! `#[derive(Dynamics)]`: a thin shim over `dynamics-codegen`. Use it through
//! `dynamics-runtime`, which re-exports it beside the `Dynamics` trait it implements.

use proc_macro::TokenStream;

/// Derives `dynamics_runtime::Dynamics` from a D-H table given in `#[dynamics(...)]`; see the
/// `dynamics-runtime` documentation for the attribute syntax.
#[proc_macro_derive(Dynamics, attributes(dynamics))]
pub fn derive_dynamics(input: TokenStream) -> TokenStream {
    dynamics_codegen::derive_dynamics(input.into()).into()
}

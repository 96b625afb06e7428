//! The derive's expansion for a robot on a free-flying base (`base = floating`): its
//! equations traced by [`crate::trace::derive_floating`], emitted as
//! [`crate::emit::floating_items`], in the derive's `const _: () = { … };` block.

use crate::front::Input;
use crate::model::FreeFlyer;
use crate::{emit, identifiers, trace};
use proc_macro2::TokenStream;
use quote::quote;

/// What `#[derive(Dynamics)]` expands to for `parsed`, whose base is the free flyer `flyer`.
pub(crate) fn expand_floating(
    input: &syn::DeriveInput,
    parsed: &Input,
    flyer: &FreeFlyer,
) -> TokenStream {
    let mut eq = trace::derive_floating(&parsed.robot, flyer);
    let kinematics = eq.floating_kinematics(&parsed.robot, flyer);
    let krate = emit::runtime_path(parsed.krate.as_ref());
    let fields = identifiers::field_readers(&eq.fields);
    let items = emit::floating_items(&eq, &fields, &krate, input);
    let kinematics = emit::floating_kinematics_items(&eq, &kinematics, &fields, &krate, input);
    let track = parsed.tracked_file.as_ref().map(|path| {
        quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        )
    });
    quote! {
        const _: () = {
            #track
            #items
            #kinematics
        };
    }
}

//! The derive's expansion for a robot on a free-flying base (`base = floating`): its
//! equations traced by [`crate::trace::derive_floating`] (and, where asked for, their
//! derivatives), emitted as [`crate::emit::floating_items`], in the derive's
//! `const _: () = { … };` block but for the modules compiled apart, beside the struct.

use crate::front::Input;
use crate::method::Family;
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
    // After the kinematics, whose code stays what it is without them.
    if parsed.families.contains(Family::Derivatives) {
        eq.add_floating_derivatives(&parsed.robot, flyer);
    }
    // Last, so that the code of the other outputs stays what it is without it; asked for, as
    // its trace costs the derive about as much as the rest (the run-time form serves else).
    let contacts = parsed
        .contact_terms
        .then(|| eq.floating_contacts(&kinematics));
    let krate = emit::runtime_path(parsed.krate.as_ref());
    let fields = identifiers::field_readers(&eq.fields);
    let emit::Items { beside, within } = emit::floating_items(&eq, &fields, &krate, input);
    let contacts = match &contacts {
        Some(contacts) => emit::floating_contacts_items(&eq, contacts, &fields, &krate, input),
        None => emit::floating_contacts_at_run_time(eq.dof, &kinematics, &krate, input),
    };
    let kinematics = emit::floating_kinematics_items(&eq, &kinematics, &fields, &krate, input);
    let track = parsed.tracked_file.as_ref().map(|path| {
        quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        )
    });
    quote! {
        #beside
        const _: () = {
            #track
            #within
            #kinematics
            #contacts
        };
    }
}

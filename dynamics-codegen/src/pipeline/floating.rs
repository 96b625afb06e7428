//! The derive's expansion for a robot on a free-flying base (`base = floating`): its
//! equations traced by [`crate::trace::derive_floating`] (and, where asked for, their
//! derivatives, regressor and base parameters), emitted as [`crate::emit::floating_items`], in the derive's
//! `const _: () = { … };` block but for the modules compiled apart, beside the struct.

use crate::front::Input;
use crate::method::{Family, FamilySet};
use crate::model::{FreeFlyer, Robot};
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
    let traced = add_floating_families(&mut eq, &parsed.robot, flyer, parsed.families);
    let untraced = (!traced).then(|| {
        let message = "`base_parameters = true` needs the robot's lengths and angles as numbers: \
                       the base parameters group the bodies' parameters by them, and this robot \
                       takes some from struct fields";
        syn::Error::new(proc_macro2::Span::call_site(), message).to_compile_error()
    });
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
        #untraced
        #beside
        const _: () = {
            #track
            #within
            #kinematics
            #contacts
        };
    }
}

/// Traces onto the floating equations `eq` the opt-in families of `families` (the fixed base's
/// names: `derivatives`, `regressor`, `base_parameters`); false where the base parameters were
/// asked for and cannot be traced (a length or angle given by a struct field).
pub(crate) fn add_floating_families(
    eq: &mut trace::Equations,
    robot: &Robot,
    flyer: &FreeFlyer,
    families: FamilySet,
) -> bool {
    if families.contains(Family::Derivatives) {
        eq.add_floating_derivatives(robot, flyer);
    }
    if families.contains(Family::Regressor) {
        eq.add_floating_regressor(robot, flyer);
    }
    if !families.contains(Family::BaseParameters) {
        return true;
    }
    // The regressor it traces is not emitted unless it was asked for too.
    let asked = eq.families;
    eq.base_parameters = eq.floating_base_parameters(robot, flyer);
    eq.families = match eq.base_parameters {
        Some(_) => asked.with(Family::FloatingBaseParameters),
        None => asked,
    };
    eq.base_parameters.is_some()
}

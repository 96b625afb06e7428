//! The generator behind `#[derive(Dynamics)]`: it turns a serial robot's Denavit-Hartenberg
//! table into closed-form, straight-line Rust for its equations of motion.
//!
//! This crate is an implementation detail of `dynamics-macros` and of the command-line tool;
//! its API is **not** semver-stable. Use `dynamics-runtime` with its `derive` feature.
//!
//! The pipeline is a compiler, one module per step:
//!
//! 1. [`front`]: the derive input (or a description file, [`front::from_text`]) is parsed
//!    into a [`model::Robot`], with every error on its span;
//! 2. [`trace`]: the algorithms of [`algo`] run on the symbolic scalar of [`symbolic`], which
//!    builds the closed forms as one hash-consed expression graph, simplified as it is built;
//! 3. [`emit`]: each [`Method`]'s output (`M`, `C`, `g`, `τ`, …) becomes a straight-line
//!    function body, and the bodies the items of the derive; [`emit_c`] writes the same
//!    outputs as a header-only C file (`dynamics emit --lang c`).

pub mod algo;
pub mod check;
pub mod emit;
pub mod emit_c;
pub mod front;
pub mod identifiers;
pub mod inspect;
pub mod method;
pub mod model;
pub mod numeric;
pub mod pipeline;
pub mod poly;
pub mod simplify;
pub mod symbolic;
pub mod trace;

use proc_macro2::TokenStream;
use quote::quote;

pub use emit::{generate, Generated, MethodCode, OpCount};
pub use front::{Chain, SIMPLIFY_KEYS};
pub use identifiers::{c_prefix_problem, one_line, rust_field, rust_type};
pub use method::{Family, FamilySet, Method};
pub use numeric::{NotPositiveDefinite, Numeric};
pub use pipeline::{
    asked_by_name, families, load, opt_in_family, problems, CHeader, Diagnostic, Loaded, Readable,
    RustModule, Source, State, Values,
};
pub use trace::base_parameters::{BaseParameters, JointColumns, Parameter};
pub use trace::{derive, Equations, SimplifiedEquations};

/// Entry point of `#[derive(Dynamics)]`.
#[must_use]
pub fn derive_dynamics(input: TokenStream) -> TokenStream {
    let input: syn::DeriveInput = match syn::parse2(input) {
        Ok(i) => i,
        Err(e) => return e.to_compile_error(),
    };
    match front::parse(&input) {
        Ok(parsed) => expand(&input, &parsed),
        Err(failure) => emit::fallback(&input, &failure),
    }
}

/// What `#[derive(Dynamics)]` expands to for `robot` on the type `input`, once the derive
/// input is parsed, with the opt-in families of `families` (and the simplified models of
/// `simplify`, which asks for their family): for tools that time the derive (`dynamics
/// stats`) on a robot they loaded.
#[must_use]
pub fn expand_robot(
    input: &syn::DeriveInput,
    robot: &model::Robot,
    families: FamilySet,
    simplify: Option<&model::Simplification>,
) -> TokenStream {
    let families = match simplify {
        Some(_) => families.with(Family::Simplified),
        None => families,
    };
    let parsed = front::Input {
        robot: robot.clone(),
        krate: None,
        tracked_file: None,
        families,
        simplify: simplify.cloned(),
        floating: None,
        contact_terms: false,
    };
    expand(input, &parsed)
}

/// The expansion of a parsed derive: the generated items and the readable equations, in a
/// `const _: () = { … };` block, with the description file (if any) tracked for rebuilds.
fn expand(input: &syn::DeriveInput, parsed: &front::Input) -> TokenStream {
    if let Some(flyer) = &parsed.floating {
        return pipeline::expand_floating(input, parsed, flyer);
    }
    let (eq, simplified) =
        pipeline::equations(&parsed.robot, parsed.families, parsed.simplify.as_ref());
    let krate = emit::runtime_path(parsed.krate.as_ref());
    let fields = identifiers::field_readers(&eq.fields);
    let generated = emit::generate_uncounted(&eq, fields);
    let readable = emit::readable(input, &eq, &parsed.robot);
    let items = generated.items(&krate, &input.ident, &input.generics, &|method| {
        readable.doc(method)
    });
    let equations = readable.equations;
    let track = parsed.tracked_file.as_ref().map(|path| {
        quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        )
    });
    let emit::Items { beside, within } = items;
    // A family asked for that could not be traced: its error, and its methods unreachable.
    let untraced = |family| parsed.families.contains(family) && !eq.families.contains(family);
    let untraced = untraced(Family::BaseParameters);
    let error = untraced.then(|| {
        let message = "`base_parameters = true` needs the robot's lengths and angles as \
                       numbers: the base parameters group the links' parameters by them, and \
                       this robot takes some from struct fields (masses and inertias may be \
                       fields)";
        untraced_family(input, &eq, &krate, Family::BaseParameters, message)
    });
    let simplify_error = match simplified {
        Some(Err(e)) => Some(untraced_family(
            input,
            &eq,
            &krate,
            Family::Simplified,
            &format!("`simplify`: {e}"),
        )),
        _ => None,
    };
    quote! {
        #error
        #simplify_error
        #beside
        const _: () = {
            #track
            #within
            #equations
        };
    }
}

/// The error of an opt-in family asked for that could not be traced, and its trait's methods
/// unreachable, so that calls to them add no errors of their own.
fn untraced_family(
    input: &syn::DeriveInput,
    eq: &trace::Equations,
    krate: &TokenStream,
    family: Family,
    message: &str,
) -> TokenStream {
    let error = syn::Error::new(proc_macro2::Span::call_site(), message).to_compile_error();
    let impls = emit::unreachable_family(input, (eq.dof, eq.links), krate, family);
    quote!(#error const _: () = { #impls };)
}

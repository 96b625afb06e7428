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
//! 3. [`emit`]: each output (`M`, `C`, `g`, `τ`, …) becomes a straight-line function body.

pub mod algo;
pub mod check;
pub mod emit;
pub mod front;
pub mod inspect;
pub mod model;
pub mod numeric;
pub mod symbolic;
pub mod trace;

use proc_macro2::TokenStream;
use quote::{quote, ToTokens};

pub use emit::OpCount;
/// The trace's former path, which the emitter and the readable form still name.
pub use trace as derive;
pub use trace::{derive, Equations};
// The former path of `inspect`, for callers not yet moved to it.
#[doc(hidden)]
pub use inspect as readable;

/// Entry point of `#[derive(Dynamics)]`.
#[must_use]
pub fn derive_dynamics(input: TokenStream) -> TokenStream {
    let input: syn::DeriveInput = match syn::parse2(input) {
        Ok(i) => i,
        Err(e) => return e.to_compile_error(),
    };
    match front::parse(&input) {
        Ok(parsed) => expand(&input, &parsed),
        Err(failure) => fallback(&input, &failure),
    }
}

/// One generated method: its name, its arguments and its body, with operation counts.
pub struct Method {
    /// Method name, e.g. `mass_matrix`.
    pub name: &'static str,
    /// The body.
    pub body: TokenStream,
    /// Its operations, the shared configuration's included.
    pub ops: OpCount,
}

/// The generated code of a robot: the shared configuration (see [`emit::emit`]) and the
/// methods of the `Dynamics` impl.
pub struct Generated {
    /// Number of joints.
    pub dof: usize,
    /// How to read each struct field of the robot, in the order of [`Equations::fields`].
    pub fields: Vec<TokenStream>,
    /// The configuration function's struct fields and body, if any method reads it.
    pub configuration: Option<emit::Shared>,
    /// The motion function's struct fields and body, if two methods share terms in `q̇`.
    pub motion: Option<emit::Shared>,
    /// The methods, in the trait's order.
    pub methods: Vec<Method>,
}

/// The generated code of the [`Equations`]; `fields` reads struct field `k` of the robot
/// (`self.name`), in the order of [`Equations::fields`].
#[must_use]
pub fn generate(eq: &Equations, fields: Vec<TokenStream>) -> Generated {
    use emit::{Output, Shape};
    let ctx = emit::Context {
        parameters: emit::local(emit::PARAMETERS),
    };
    // Each method with the name of its output elements (`m1_2`, `tau3`).
    let table: [(&'static str, &str, Shape); 8] = [
        ("mass_matrix", "m", Shape::Matrix(&eq.mass)),
        ("coriolis_matrix", "cor", Shape::Matrix(&eq.coriolis)),
        (
            "coriolis_torques",
            "cqd",
            Shape::Vector(&eq.coriolis_torques),
        ),
        ("gravity_torques", "g", Shape::Vector(&eq.gravity)),
        ("bias_torques", "h", Shape::Vector(&eq.bias)),
        ("inverse_dynamics", "tau", Shape::Vector(&eq.tau)),
        ("kinetic_energy", "k", Shape::Scalar(eq.kinetic_energy)),
        ("potential_energy", "p", Shape::Scalar(eq.potential_energy)),
    ];
    let shapes: Vec<Output> = table
        .iter()
        .map(|&(_, prefix, shape)| Output { prefix, shape })
        .collect();
    let emission = emit::emit(eq, &shapes, &ctx);
    let methods = table
        .iter()
        .zip(emission.bodies)
        .map(|(&(name, _, _), b)| Method {
            name,
            body: b.tokens,
            ops: b.ops,
        })
        .collect();
    Generated {
        dof: eq.dof,
        fields,
        configuration: emission.configuration,
        motion: emission.motion,
        methods,
    }
}

impl Generated {
    /// The items for the robot type `ident`, to go in a `const _: () = { … };` block:
    ///
    /// * a module `__dynamics` holding the configuration struct and function and one function
    ///   per method, which take the parameters as an array `p_: &[T; K]`. A module sees none of
    ///   the items around it, so no user constant can collide with a generated local (`let`
    ///   patterns cannot shadow constants: a user's `const t1` would otherwise break the code);
    /// * a hidden inherent method `__dynamics_parameters` reading the struct's fields into that
    ///   array (every field the description names, so none is left unread);
    /// * the `Dynamics` impl, each method one call into the module.
    ///
    /// `docs` gives each method's doc comment.
    #[must_use]
    pub fn items(
        &self,
        krate: &TokenStream,
        ident: &syn::Ident,
        generics: &syn::Generics,
        docs: &dyn Fn(&str) -> Option<String>,
    ) -> TokenStream {
        let n = self.dof;
        let k = self.fields.len();
        let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
        let module = syn::Ident::new(MODULE, proc_macro2::Span::call_site());
        let parameters = syn::Ident::new(PARAMETERS_FN, proc_macro2::Span::call_site());
        let p = emit::local(emit::PARAMETERS);
        let q = emit::local("q_");
        let configuration = self.configuration.as_ref().map(|c| {
            let ty = syn::Ident::new(emit::CONFIGURATION_STRUCT, proc_macro2::Span::call_site());
            let f = syn::Ident::new(emit::CONFIGURATION_FN, proc_macro2::Span::call_site());
            let fields = &c.fields;
            let body = &c.tokens;
            quote! {
                /// What the dynamics need from the parameters and `q` alone, computed once.
                pub(super) struct #ty<T> { #(#fields: T),* }
                // Inlined into each method, which keeps of it only what it reads.
                #[inline(always)]
                pub(super) fn #f<T: #krate::Real>(#p: &[T; #k], #q: &[T; #n]) -> #ty<T> {
                    #body
                }
            }
        });
        let motion = self.motion.as_ref().map(|m| {
            let ty = syn::Ident::new(emit::MOTION_STRUCT, proc_macro2::Span::call_site());
            let f = syn::Ident::new(emit::MOTION_FN, proc_macro2::Span::call_site());
            let fields = &m.fields;
            let body = &m.tokens;
            let qd = emit::local("qd_");
            // With a configuration, the motion function computes it too and hands both over.
            let ret = match &self.configuration {
                Some(_) => {
                    let c = syn::Ident::new(emit::CONFIGURATION_STRUCT, proc_macro2::Span::call_site());
                    quote!((#c<T>, #ty<T>))
                }
                None => quote!(#ty<T>),
            };
            quote! {
                /// What several methods compute from `q̇` too, computed once.
                pub(super) struct #ty<T> { #(#fields: T),* }
                // Inlined into each method, which keeps of it only what it reads.
                #[inline(always)]
                pub(super) fn #f<T: #krate::Real>(#p: &[T; #k], #q: &[T; #n], #qd: &[T; #n]) -> #ret {
                    #body
                }
            }
        });
        let bodies = self.methods.iter().map(|m| {
            let name = syn::Ident::new(m.name, proc_macro2::Span::call_site());
            let (args, ret) = signature(m.name, n);
            let body = &m.body;
            quote! {
                #[inline(always)]
                pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #args) -> #ret {
                    #body
                }
            }
        });
        let fns = self.methods.iter().map(|m| {
            let name = syn::Ident::new(m.name, proc_macro2::Span::call_site());
            let (args, ret) = signature(m.name, n);
            let pass = call_arguments(m.name);
            let f = quote! {
                #[inline]
                fn #name<T: #krate::Real>(&self, #args) -> #ret {
                    #module::#name(&self.#parameters(), #pass)
                }
            };
            match docs(m.name) {
                Some(doc) => quote!(#[doc = #doc] #f),
                None => f,
            }
        });
        let fields = &self.fields;
        let reader = (k > 0).then(|| quote!(use #krate::__private::param;));
        quote! {
            /// The generated functions, out of reach of the names around the derive.
            #[allow(non_snake_case, non_camel_case_types, unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
            mod #module {
                #configuration
                #motion
                #(#bodies)*
            }
            impl #impl_generics #ident #ty_generics #where_clause {
                /// The parameters the equations read, in the order of the description.
                #[doc(hidden)]
                #[inline(always)]
                #[allow(clippy::all, clippy::pedantic, clippy::nursery)]
                fn #parameters<T: #krate::Real>(&self) -> [T; #k] {
                    #reader
                    [#(param(#fields)),*]
                }
            }
            #[automatically_derived]
            impl #impl_generics #krate::Dynamics<#n> for #ident #ty_generics #where_clause {
                #(#fns)*
            }
        }
    }
}

/// Name of the module holding the generated functions.
const MODULE: &str = "__dynamics";
/// Name of the hidden inherent method reading the robot's parameters.
const PARAMETERS_FN: &str = "__dynamics_parameters";

fn expand(input: &syn::DeriveInput, parsed: &front::Input) -> TokenStream {
    let eq = derive::derive(&parsed.robot);
    let krate = runtime_path(parsed.krate.as_ref());
    let fields = eq
        .fields
        .iter()
        .map(|f| {
            let ident = syn::Ident::new(f, proc_macro2::Span::call_site());
            quote!(self.#ident)
        })
        .collect();
    let generated = generate(&eq, fields);
    let items = generated.items(&krate, &input.ident, &input.generics, &|_| None);
    let equations = equations(input, &eq, &parsed.robot);
    let track = parsed.tracked_file.as_ref().map(|path| {
        quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        )
    });
    quote! {
        const _: () = {
            #track
            #items
            #equations
        };
    }
}

/// `EQUATIONS` and `EQUATIONS_LATEX` on the derived type: its equations of motion in the
/// book's notation ([`readable`]), also shown in the rustdoc of that impl. Expanded within
/// [`readable::Limits::DERIVE`], which keeps the derive fast: a section that does not fit
/// says so and points to `dynamics inspect`.
fn equations(input: &syn::DeriveInput, eq: &Equations, robot: &model::Robot) -> TokenStream {
    let inspection = readable::inspect(eq, robot, readable::Limits::DERIVE);
    let text = inspection.render(readable::Format::Text);
    let latex = inspection.render(readable::Format::Latex);
    let doc = format!(
        " The equations of motion of `{}`, derived by `#[derive(Dynamics)]`.\n\n```text\n{text}```",
        input.ident
    );
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    quote! {
        #[doc = #doc]
        #[automatically_derived]
        #[allow(dead_code)] // the constants are there to be read, not necessarily used
        impl #impl_generics #ident #ty_generics #where_clause {
            /// The equations of motion in the notation of Niku, *Introduction to Robotics*,
            /// ch. 6, as plain text: the same as this impl's documentation.
            pub const EQUATIONS: &'static str = #text;
            /// The equations of motion as LaTeX (`align*` environments).
            pub const EQUATIONS_LATEX: &'static str = #latex;
        }
    }
}

/// One method of the `Dynamics` impl with the given body (also used by the command-line
/// tool's `emit`).
#[must_use]
pub fn method(name: &str, n: usize, krate: &TokenStream, body: &TokenStream) -> TokenStream {
    let (args, ret) = signature(name, n);
    let name = syn::Ident::new(name, proc_macro2::Span::call_site());
    quote! {
        #[inline]
        #[allow(unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
        fn #name<T: #krate::Real>(&self, #args) -> #ret {
            #body
        }
    }
}

/// The arguments and the result type of a method of the `Dynamics` trait.
fn signature(name: &str, n: usize) -> (TokenStream, TokenStream) {
    let (q, qd, qdd) = (emit::local("q_"), emit::local("qd_"), emit::local("qdd_"));
    let vector = quote!(&[T; #n]);
    match name {
        "mass_matrix" => (quote!(#q: #vector), quote!([[T; #n]; #n])),
        "coriolis_matrix" => (quote!(#q: #vector, #qd: #vector), quote!([[T; #n]; #n])),
        "coriolis_torques" | "bias_torques" => (quote!(#q: #vector, #qd: #vector), quote!([T; #n])),
        "gravity_torques" => (quote!(#q: #vector), quote!([T; #n])),
        "inverse_dynamics" => (
            quote!(#q: #vector, #qd: #vector, #qdd: #vector),
            quote!([T; #n]),
        ),
        "kinetic_energy" => (quote!(#q: #vector, #qd: #vector), quote!(T)),
        _ => (quote!(#q: #vector), quote!(T)),
    }
}

/// The arguments a method passes on, as in [`signature`].
fn call_arguments(name: &str) -> TokenStream {
    let (q, qd, qdd) = (emit::local("q_"), emit::local("qd_"), emit::local("qdd_"));
    match name {
        "coriolis_matrix" | "coriolis_torques" | "bias_torques" | "kinetic_energy" => {
            quote!(#q, #qd)
        }
        "inverse_dynamics" => quote!(#q, #qd, #qdd),
        _ => quote!(#q),
    }
}

/// The names of the generated methods, in the trait's order.
const METHODS: [&str; 8] = [
    "mass_matrix",
    "coriolis_matrix",
    "coriolis_torques",
    "gravity_torques",
    "bias_torques",
    "inverse_dynamics",
    "kinetic_energy",
    "potential_energy",
];

/// The errors, and where the joint count is known an impl whose methods are unreachable, so
/// that code calling them compiles and the user sees only the real errors.
fn fallback(input: &syn::DeriveInput, failure: &front::Failure) -> TokenStream {
    let errors = failure.error.to_compile_error();
    let Some(n) = failure.dof else {
        return errors;
    };
    let krate = runtime_path(failure.krate.as_ref());
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let body = quote!(::core::unreachable!("the Dynamics derive failed"));
    let fns = METHODS.iter().map(|name| method(name, n, &krate, &body));
    quote! {
        #errors
        const _: () = {
            #[automatically_derived]
            impl #impl_generics #krate::Dynamics<#n> for #ident #ty_generics #where_clause {
                #(#fns)*
            }
        };
    }
}

/// The runtime crate's path: `crate = "..."` if given, else `::dynamics_runtime`.
fn runtime_path(krate: Option<&syn::Path>) -> TokenStream {
    krate.map_or_else(|| quote!(::dynamics_runtime), ToTokens::to_token_stream)
}

//! The generator behind `#[derive(Dynamics)]`: it turns a serial robot's Denavit-Hartenberg
//! table into closed-form, straight-line Rust for its equations of motion.
//!
//! This crate is an implementation detail of `dynamics-macros` and of the command-line tool;
//! its API is **not** semver-stable. Use `dynamics-runtime` with its `derive` feature.
//!
//! The pipeline is a compiler, one module per step:
//!
//! 1. [`front`]: the derive input (or a description file, [`model::from_text`]) is parsed
//!    into a [`model::Robot`], with every error on its span;
//! 2. [`mod@derive`]: the algorithms of [`algo`] run on the symbolic scalar of [`symbolic`], which
//!    builds the closed forms as one hash-consed expression graph, simplified as it is built;
//! 3. [`emit`]: each output (`M`, `C`, `g`, `τ`, …) becomes a straight-line function body.

pub mod algo;
pub mod check;
pub mod derive;
pub mod emit;
pub mod front;
pub mod model;
pub mod numeric;
pub mod poly;
pub mod readable;
pub mod symbolic;

use proc_macro2::TokenStream;
use quote::{quote, ToTokens};

pub use derive::{derive, Equations};
pub use emit::OpCount;

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
    /// The configuration function's struct fields and body, if any method reads it.
    pub configuration: Option<emit::Configuration>,
    /// The methods, in the trait's order.
    pub methods: Vec<Method>,
}

/// The generated code of the [`Equations`], reading struct fields through `fields`.
#[must_use]
pub fn generate(eq: &Equations, krate: &TokenStream, fields: Vec<TokenStream>) -> Generated {
    use emit::{Output, Shape};
    let ctx = emit::Context { krate, fields };
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
        configuration: emission.configuration,
        methods,
    }
}

impl Generated {
    /// The items for the robot type `ident`: the configuration struct and the hidden inherent
    /// method computing it, and the `Dynamics` impl. `docs` gives each method's doc comment.
    #[must_use]
    pub fn items(
        &self,
        krate: &TokenStream,
        ident: &syn::Ident,
        generics: &syn::Generics,
        prologue: &TokenStream,
        docs: &dyn Fn(&str) -> Option<String>,
    ) -> TokenStream {
        let n = self.dof;
        let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
        let configuration = self.configuration.as_ref().map(|c| {
            let ty = syn::Ident::new(emit::CONFIGURATION_STRUCT, proc_macro2::Span::call_site());
            let f = syn::Ident::new(emit::CONFIGURATION_FN, proc_macro2::Span::call_site());
            let fields = &c.fields;
            let q = proc_macro2::Ident::new("q_", proc_macro2::Span::mixed_site());
            let body = &c.tokens;
            quote! {
                /// What the dynamics need from the parameters and `q` alone, computed once.
                #[doc(hidden)]
                #[allow(non_camel_case_types)]
                struct #ty<T> { #(#fields: T),* }
                impl #impl_generics #ident #ty_generics #where_clause {
                    // Inlined into each method, which keeps of it only what it reads.
                    #[doc(hidden)]
                    #[inline(always)]
                    #[allow(unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
                    fn #f<T: #krate::Real>(&self, #q: &[T; #n]) -> #ty<T> {
                        #prologue
                        #body
                    }
                }
            }
        });
        // Without a configuration, the prologue goes to the first method.
        let mut prologue = self.configuration.is_none().then_some(prologue);
        let fns = self.methods.iter().map(|m| {
            let body = &m.body;
            let first = prologue.take();
            let f = method(m.name, n, krate, &quote!(#first #body));
            match docs(m.name) {
                Some(doc) => quote!(#[doc = #doc] #f),
                None => f,
            }
        });
        quote! {
            #configuration
            #[automatically_derived]
            impl #impl_generics #krate::Dynamics<#n> for #ident #ty_generics #where_clause {
                #(#fns)*
            }
        }
    }
}

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
    let generated = generate(&eq, &krate, fields);
    // A field the description names may drop out of every equation (a gravity magnitude on a
    // horizontal axis); reading it once keeps the user's crate free of dead-code warnings.
    let read = generated
        .configuration
        .as_ref()
        .map_or(&[][..], |c| &c.fields_read[..]);
    let unread: Vec<proc_macro2::Ident> = eq
        .fields
        .iter()
        .enumerate()
        .filter(|(k, _)| !read.contains(k))
        .map(|(_, f)| syn::Ident::new(f, proc_macro2::Span::call_site()))
        .collect();
    let touch = (!unread.is_empty()).then(|| quote!(let _ = (#(&self.#unread,)*);));
    let items = generated.items(
        &krate,
        &input.ident,
        &input.generics,
        &quote!(#touch),
        &|_| None,
    );
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
    let q = proc_macro2::Ident::new("q_", proc_macro2::Span::mixed_site());
    let qd = proc_macro2::Ident::new("qd_", proc_macro2::Span::mixed_site());
    let qdd = proc_macro2::Ident::new("qdd_", proc_macro2::Span::mixed_site());
    let vector = quote!(&[T; #n]);
    let (args, ret) = match name {
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
    };
    let name = syn::Ident::new(name, proc_macro2::Span::call_site());
    quote! {
        #[inline]
        #[allow(unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
        fn #name<T: #krate::Real>(&self, #args) -> #ret {
            #body
        }
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

//! `equations()` and `equations_latex()` on the derived type (and the hidden constants
//! `EQUATIONS`, `EQUATIONS_LATEX` they return): its equations of motion in the book's
//! notation ([`inspect`]), the text also shown in the rustdoc of that impl.

use crate::trace::Equations;
use crate::{inspect, model};
use proc_macro2::TokenStream;
use quote::quote;

/// The impl holding the equations. Expanded within [`inspect::Limits::DERIVE`], which keeps
/// the derive fast: a section that does not fit says so and points to `dynamics inspect`.
pub(crate) fn equations(
    input: &syn::DeriveInput,
    eq: &Equations,
    robot: &model::Robot,
) -> TokenStream {
    let inspection = inspect::inspect(eq, robot, inspect::Limits::DERIVE);
    let text = inspection.render(inspect::Format::Text);
    let latex = inspection.render(inspect::Format::Latex);
    let doc = format!(
        " The equations of motion of `{}`, derived by `#[derive(Dynamics)]`.\n\n```text\n{text}```",
        input.ident
    );
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    // The constants are hidden: rustdoc would print their whole values, escaped
    // (`\u{3b8}`), on the type's page; the accessors show only their docs.
    quote! {
        #[doc = #doc]
        #[automatically_derived]
        #[allow(dead_code)] // the equations are there to be read, not necessarily used
        impl #impl_generics #ident #ty_generics #where_clause {
            /// The equations of motion as plain text; see [`Self::equations`].
            #[doc(hidden)]
            pub const EQUATIONS: &'static str = #text;
            /// The equations of motion as LaTeX; see [`Self::equations_latex`].
            #[doc(hidden)]
            pub const EQUATIONS_LATEX: &'static str = #latex;

            /// The equations of motion in the notation of Niku, *Introduction to Robotics*,
            /// ch. 6, as plain text: the same as this impl's documentation. Also the
            /// constant `EQUATIONS`.
            #[must_use]
            pub const fn equations() -> &'static str {
                Self::EQUATIONS
            }

            /// The equations of motion as LaTeX (`align*` environments). Also the constant
            /// `EQUATIONS_LATEX`.
            #[must_use]
            pub const fn equations_latex() -> &'static str {
                Self::EQUATIONS_LATEX
            }
        }
    }
}

//! `equations()` and `equations_latex()` on the derived type (and the hidden constants
//! `EQUATIONS`, `EQUATIONS_LATEX` they return): its equations of motion in the book's
//! notation ([`inspect`]), the text also shown in the rustdoc of that impl; and the hand pose
//! and Jacobians in the same notation, in the rustdoc of their methods.

use super::expr::raw_string;
use crate::inspect::{Format, KinematicPart};
use crate::method::Method;
use crate::trace::{Equations, SimplifiedEquations};
use crate::{inspect, model};
use proc_macro2::TokenStream;
use quote::quote;

/// What the derive prints for reading.
pub(crate) struct Readable {
    /// The impl holding the equations of motion.
    pub(crate) equations: TokenStream,
    /// The rustdoc of the kinematic methods that print in the book's notation.
    pub(crate) docs: Vec<(Method, String)>,
}

impl Readable {
    /// The rustdoc of `method`, if it has its own.
    pub(crate) fn doc(&self, method: Method) -> Option<String> {
        let (_, doc) = self.docs.iter().find(|(m, _)| *m == method)?;
        Some(doc.clone())
    }
}

/// The equations of motion and the kinematics in the book's notation, expanded together within
/// [`inspect::Limits::DERIVE`], which keeps the derive fast: a section that does not fit says
/// so and points to `dynamics inspect`.
pub(crate) fn readable(input: &syn::DeriveInput, eq: &Equations, robot: &model::Robot) -> Readable {
    let (dynamics, kinematics) =
        inspect::inspect_with_kinematics(eq, robot, inspect::Limits::DERIVE);
    let docs = [
        (Method::HandPose, KinematicPart::HandPose),
        (Method::HandJacobianInBase, KinematicPart::JacobianInBase),
        (Method::HandJacobianInHand, KinematicPart::JacobianInHand),
    ]
    .into_iter()
    .filter_map(|(method, part)| {
        let text = kinematics.render_part(part, Format::Text)?;
        let doc = format!(" {}\n\n```text\n{text}```", method.summary());
        Some((method, doc))
    })
    .chain(simplified_docs(eq))
    .collect();
    Readable {
        equations: equations(input, &dynamics),
        docs,
    }
}

/// The impl holding the equations of motion.
fn equations(input: &syn::DeriveInput, inspection: &inspect::Inspection) -> TokenStream {
    let text = inspection.render(inspect::Format::Text);
    let latex = inspection.render(inspect::Format::Latex);
    let doc = format!(
        " The equations of motion of `{}`, derived by `#[derive(Dynamics)]`.\n\n```text\n{text}```",
        input.ident
    );
    let (text, latex, doc) = (raw_string(&text), raw_string(&latex), raw_string(&doc));
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

/// The rustdoc of the simplified methods: each output's proven bound and the envelope, or why
/// the output is left exact ([`simplified_doc`]).
fn simplified_docs(eq: &Equations) -> Vec<(Method, String)> {
    [
        Method::InverseDynamicsSimplified,
        Method::MassMatrixSimplified,
        Method::CoriolisTorquesSimplified,
        Method::GravityTorquesSimplified,
    ]
    .into_iter()
    .filter_map(|method| Some((method, simplified_doc(eq, method)?)))
    .collect()
}

/// The rustdoc of a simplified method of `eq` (`None` for any other method, or equations
/// not simplified): its summary, each output's proven bound and the envelope, or why it is
/// left exact. The derive and
/// `dynamics emit` write it on the method, the C header (in ASCII) above its function.
#[must_use]
pub fn simplified_doc(eq: &Equations, method: Method) -> Option<String> {
    let s = eq.simplified.as_ref()?;
    let output = s.output(method)?;
    let unit = |joint: Option<usize>| match joint.map(|i| eq.kinds[i]) {
        Some(crate::algo::JointKind::Revolute) => " N·m",
        Some(crate::algo::JointKind::Prismatic) => " N",
        None => "",
    };
    let bounds = output.named_bounds().map(|(name, joint, b)| {
        format!(
            "|{name} − {name},simplified| ≤ {:.6e}{} (tolerance {:.6e}; {} of {} terms kept)",
            b.bound,
            unit(joint),
            b.tolerance,
            b.kept,
            b.terms
        )
    });
    let bounds = bounds.collect::<Vec<_>>().join("\n");
    Some(match output.fallback {
        // No link to the exact method: the trait's page has it, the robot's impl may not.
        Some(f) => format!(
            " Left exact: the same values as `{}` (bound 0).\n\nNot pruned: {f}.",
            output.exact.name()
        ),
        None => format!(
            " {}\n\nProven over the envelope below (interval arithmetic on the closed form; \
             nothing is promised outside it):\n\n```text\n{bounds}\n```\n\nThe \
             envelope:\n\n```text\n{}```",
            method.summary(),
            envelope_text(s)
        ),
    })
}

/// The envelope, a line per joint.
fn envelope_text(s: &SimplifiedEquations) -> String {
    s.request
        .envelope
        .joints
        .iter()
        .enumerate()
        .map(|(i, j)| {
            format!(
                "q{0} in [{1}, {2}], |qd{0}| <= {3}, |qdd{0}| <= {4}\n",
                i + 1,
                j.lower,
                j.upper,
                j.speed,
                j.acceleration
            )
        })
        .collect()
}

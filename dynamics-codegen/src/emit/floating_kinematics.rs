//! The derive's items for the kinematic outputs of a robot on a free-flying base
//! ([`crate::trace::FloatingKinematicEquations`]): a module `__floating_kinematics` of one
//! function per output over the floating coordinates (as [`super::floating_items`]'s), the
//! `FloatingKinematics<NQ, NV, F>` impl, which adds the base position to the centre of mass
//! and the frames' origins (the graph traces them relative to it), and the frames' names as
//! the robot's constants (`FRAME_NAMES`, `FRAME_FL_FOOT`).
//!
//! The emitter names an output's elements after a method of the table (`m1_2`), and these
//! outputs have no rows there yet: each borrows the element names of a method of the same
//! arguments (`CARRIERS`), within this module only, where no other output uses them.

use super::expr::with_body;
use super::impls::argument_local;
use super::items::{Generated, PARAMETERS_FN};
use super::program::emit;
use super::{local, Context, Output, PARAMETERS};
use crate::method::{Argument, Method};
use crate::trace::{Equations, FloatingKinematicEquations, Shape};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// Each output's function, and the method whose arguments it takes and whose element names
/// it borrows (see the module's doc).
const CARRIERS: [(&str, Method); 9] = [
    ("center_of_mass", Method::GravityTorques),
    ("center_of_mass_jacobian", Method::HandJacobianInBase),
    ("centroidal_momentum_matrix", Method::HandJacobianInHand),
    (
        "centroidal_momentum_bias",
        Method::HandAccelerationBiasInBase,
    ),
    ("frame_poses", Method::TipPoses),
    ("frame_jacobians_world_aligned", Method::TipJacobiansInBase),
    ("frame_jacobians_local", Method::TipJacobiansInTip),
    (
        "frame_acceleration_biases_world_aligned",
        Method::TipAccelerationBiasesInBase,
    ),
    (
        "frame_acceleration_biases_local",
        Method::TipAccelerationBiasesInTip,
    ),
];

/// The items of the kinematic outputs `out` of the floating robot `input`, whose equations
/// are `eq` and struct fields read by `fields`, for the derive's `const _: () = { … };` block
/// beside [`super::floating_items`]'s (whose parameters' reader they call).
#[must_use]
pub fn floating_kinematics_items(
    eq: &Equations,
    out: &FloatingKinematicEquations,
    fields: &[TokenStream],
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    let ctx = Context {
        parameters: local(PARAMETERS),
        counted: false,
    };
    let shapes = [
        Shape::Vector(&out.com),
        Shape::Matrix(&out.com_jacobian),
        Shape::Matrix(&out.centroidal_matrix),
        Shape::Vector(&out.centroidal_bias),
        Shape::Stack(&out.frame_poses),
        Shape::Stack(&out.jacobians_world),
        Shape::Stack(&out.jacobians_local),
        Shape::Matrix(&out.biases_world),
        Shape::Matrix(&out.biases_local),
    ];
    let outputs: Vec<Output> = CARRIERS
        .iter()
        .zip(shapes)
        .map(|(&(_, method), shape)| Output { method, shape })
        .collect();
    let emission = emit(eq, &outputs, &ctx);
    let (nv, frames) = (eq.dof, out.frame_names.len());
    let generated = Generated::counts_only(eq, fields);
    let types = result_types(nv, frames);
    let (p, k) = (local(PARAMETERS), fields.len());
    let functions =
        CARRIERS
            .iter()
            .zip(&emission.bodies)
            .zip(&types)
            .map(|((&(name, method), body), ret)| {
                let name = Ident::new(name, Span::call_site());
                let args = method
                    .arguments()
                    .iter()
                    .map(|&a| argument_local(a))
                    .map(|a| quote!(#a: &[T; #nv]));
                let head = quote! {
                    #[inline(always)]
                    pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #(#args),*) -> #ret
                };
                with_body(head, body.tokens.clone())
            });
    let configuration = generated.configuration_item(emission.configuration.as_ref(), krate);
    let motion = generated.motion_item(
        emission.motion.as_ref(),
        emission.configuration.is_some(),
        krate,
    );
    let impls = trait_impl(nv, &out.frame_names, krate, input);
    quote! {
        /// The generated functions, out of reach of the names around the derive.
        #[allow(non_snake_case, non_camel_case_types, unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
        mod __floating_kinematics {
            #configuration
            #motion
            #(#functions)*
        }
        #impls
    }
}

/// The module functions' result types, in `CARRIERS`' order: arrays of rows.
fn result_types(nv: usize, frames: usize) -> [TokenStream; 9] {
    [
        quote!([T; 3]),
        quote!([[T; #nv]; 3]),
        quote!([[T; #nv]; 6]),
        quote!([T; 6]),
        quote!([[[T; 4]; 3]; #frames]),
        quote!([[[T; #nv]; 6]; #frames]),
        quote!([[[T; #nv]; 6]; #frames]),
        quote!([[T; 6]; #frames]),
        quote!([[T; 6]; #frames]),
    ]
}

/// `impl FloatingKinematics<NQ, NV, F>`, and the frames' names as the robot's constants.
fn trait_impl(
    nv: usize,
    names: &[String],
    krate: &TokenStream,
    input: &syn::DeriveInput,
) -> TokenStream {
    let (nq, frames) = (nv + 1, names.len());
    let (ident, generics) = (&input.ident, &input.generics);
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
    let (q, v) = (argument_local(Argument::Q), argument_local(Argument::Qd));
    // The graph's coordinates leave out the base's x, which only the positions read.
    let call = |name: &str, with_v: bool| {
        let name = Ident::new(name, Span::call_site());
        let v = with_v.then(|| quote!(, #v));
        quote!(__floating_kinematics::#name(&self.#parameters(), &::core::array::from_fn(|i| #q[i + 1]) #v))
    };
    let (com, jcom, ag, bias, poses, jw, jl, bw, bl) = (
        call("center_of_mass", false),
        call("center_of_mass_jacobian", false),
        call("centroidal_momentum_matrix", false),
        call("centroidal_momentum_bias", true),
        call("frame_poses", false),
        call("frame_jacobians_world_aligned", false),
        call("frame_jacobians_local", false),
        call("frame_acceleration_biases_world_aligned", true),
        call("frame_acceleration_biases_local", true),
    );
    let constants = frame_constants(names);
    quote! {
        impl #impl_generics #ident #ty_generics #where_clause {
            #constants
        }
        #[automatically_derived]
        impl #impl_generics #krate::FloatingKinematics<#nq, #nv, #frames> for #ident #ty_generics #where_clause {
            #[inline]
            fn center_of_mass<T: #krate::Real>(&self, #q: &[T; #nq]) -> [T; 3] {
                let c = #com;
                [#q[0] + c[0], #q[1] + c[1], #q[2] + c[2]]
            }
            #[inline]
            fn center_of_mass_jacobian<T: #krate::Real>(&self, #q: &[T; #nq]) -> [[T; #nv]; 3] {
                #jcom
            }
            #[inline]
            fn centroidal_momentum_matrix<T: #krate::Real>(&self, #q: &[T; #nq]) -> [[T; #nv]; 6] {
                #ag
            }
            #[inline]
            fn centroidal_momentum_bias<T: #krate::Real>(&self, #q: &[T; #nq], #v: &[T; #nv]) -> [T; 6] {
                #bias
            }
            #[inline]
            fn frame_poses<T: #krate::Real>(&self, #q: &[T; #nq]) -> [#krate::Pose<T>; #frames] {
                #poses.map(|mut rows| {
                    for (row, x) in rows.iter_mut().zip(&#q[..3]) {
                        row[3] += *x;
                    }
                    #krate::Pose::from_rows(rows)
                })
            }
            #[inline]
            fn frame_jacobians_world_aligned<T: #krate::Real>(&self, #q: &[T; #nq]) -> [[[T; #nv]; 6]; #frames] {
                #jw
            }
            #[inline]
            fn frame_jacobians_local<T: #krate::Real>(&self, #q: &[T; #nq]) -> [[[T; #nv]; 6]; #frames] {
                #jl
            }
            #[inline]
            fn frame_acceleration_biases_world_aligned<T: #krate::Real>(&self, #q: &[T; #nq], #v: &[T; #nv]) -> [[T; 6]; #frames] {
                #bw
            }
            #[inline]
            fn frame_acceleration_biases_local<T: #krate::Real>(&self, #q: &[T; #nq], #v: &[T; #nv]) -> [[T; 6]; #frames] {
                #bl
            }
        }
    }
}

/// `FRAME_NAMES` and `FRAME_<NAME>`, each frame's index in the results (the name in capitals,
/// every other character than a letter or digit an underscore).
fn frame_constants(names: &[String]) -> TokenStream {
    let count = names.len();
    let idents = super::tip_names::index_names(names, "FRAME");
    let indices = names
        .iter()
        .zip(idents)
        .enumerate()
        .map(|(i, (name, ident))| {
            let doc =
                format!("The index of the frame `{name}` in the `FloatingKinematics` results.");
            quote! {
                #[doc = #doc]
                pub const #ident: usize = #i;
            }
        });
    quote! {
        /// The frames' names, in the order of the `FloatingKinematics` results.
        pub const FRAME_NAMES: [&'static str; #count] = [#(#names),*];
        #(#indices)*
    }
}

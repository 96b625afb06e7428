//! The generated items: the emitted bodies of every [`Method`] put together into a module of
//! functions, a parameter reader and the `Dynamics` impl forwarding to them.

use super::depends::dependencies;
use super::emitter::release_spare_tables;
use super::expr::{block, with_body};
use super::impls::{argument_local, call_arguments, forward, scalar_name, signature};
use super::impls::{trait_impls, Counts, Sizes};
use super::names::{local, CONFIGURATION_FN, CONFIGURATION_STRUCT, MOTION_FN, MOTION_STRUCT};
use super::names::{OUTPUT, PARAMETERS};
use super::parts::{Context, OpCount, Output, Part, Shared};
use super::program::emit_with;
use super::rows::part_function;
use crate::method::{Argument, Family, Method};
use crate::trace::Equations;
use proc_macro2::{Delimiter, Group, Ident, Span, TokenStream, TokenTree};
use quote::{quote, ToTokens};

/// One generated method: which, its body, with operation counts.
pub struct MethodCode {
    /// The method.
    pub method: Method,
    /// Its name, `method.name()`, e.g. `mass_matrix`.
    pub name: &'static str,
    /// The body.
    pub body: TokenStream,
    /// Its operations, the shared configuration's included.
    pub ops: OpCount,
    /// For a method with an `into` form, whose body writes its result into `y_`, the
    /// result's value of zeros (`Body::zeros`).
    pub zeros: Option<TokenStream>,
    /// Whether its body computes in lanes of tangents (`Body::lanes`).
    pub lanes: bool,
}

/// The generated code of a robot: the shared configuration (see [`emit`](super::emit)) and the
/// methods of the `Dynamics` impl.
pub struct Generated {
    /// Number of joints.
    pub dof: usize,
    /// Number of base parameters (zero unless the robot asked for them).
    pub base_count: usize,
    /// Number of links (one per joint): `dof` but on a robot with mimic joints.
    pub links: usize,
    /// Per joint, the row of τ its joint regressor's columns add to, where that is not the
    /// joint itself (a robot with mimic joints that asked for the regressor).
    pub joint_rows: Option<Vec<usize>>,
    /// The tips' names, where the robot has the tips' kinematics.
    pub tip_names: Option<Vec<String>>,
    /// How to read each struct field of the robot, in the order of [`Equations::fields`].
    pub fields: Vec<TokenStream>,
    /// Each [`Family`]'s shared functions, in [`Family::ALL`]'s order: emitted apart, so code
    /// that calls only the dynamics does not inline the kinematics, nor the reverse.
    pub modules: Vec<Module>,
    /// The methods, in the trait's order.
    pub methods: Vec<MethodCode>,
}

/// The shared functions of one family's module.
pub struct Module {
    /// The family.
    pub family: Family,
    /// The configuration function's struct fields and body, if any method reads it.
    pub configuration: Option<Shared>,
    /// The motion function's struct fields and body, if two methods share terms in `q̇`.
    pub motion: Option<Shared>,
    /// The functions of groups of a tree's rows its methods call (`emit/rows.rs`).
    pub parts: Vec<Part>,
}

/// A derive's items: those that go beside the robot's struct and those that go in the
/// `const _: () = { … };` block, where their names are out of the user's reach.
pub struct Items {
    /// The modules of the families beside the struct ([`Family::is_beside_the_struct`]), named
    /// after the robot (`__derivatives_of_Puma560`).
    pub beside: TokenStream,
    /// The other modules, the parameters' reader and the trait impls.
    pub within: TokenStream,
}

impl ToTokens for Items {
    /// Both parts, one after the other, as a standalone module has them.
    fn to_tokens(&self, tokens: &mut TokenStream) {
        self.beside.to_tokens(tokens);
        self.within.to_tokens(tokens);
    }
}

/// The name of `family`'s module for the robot `ident`: the robot's name is part of it where
/// the module goes beside the struct, so that two robots' modules differ.
pub(super) fn module_name(family: Family, ident: &syn::Ident) -> Ident {
    if family.is_beside_the_struct() {
        // `unraw`: a struct may be named `r#type`.
        let robot = syn::ext::IdentExt::unraw(ident);
        Ident::new(
            &format!("{}_of_{robot}", family.module()),
            Span::call_site(),
        )
    } else {
        Ident::new(family.module(), Span::call_site())
    }
}

/// Name of the hidden inherent method reading the robot's parameters.
pub(super) const PARAMETERS_FN: &str = "__dynamics_parameters";

/// The generated code of the [`Equations`], every method of [`Method::ALL`]; `fields` reads
/// struct field `k` of the robot (`self.name`), in the order of [`Equations::fields`].
#[must_use]
pub fn generate(eq: &Equations, fields: Vec<TokenStream>) -> Generated {
    generate_with(eq, fields, true)
}

/// [`generate`] without the operation counts (each [`MethodCode::ops`] zero): what the derive
/// and the standalone module write, which read none.
#[must_use]
pub(crate) fn generate_uncounted(eq: &Equations, fields: Vec<TokenStream>) -> Generated {
    generate_with(eq, fields, false)
}

/// [`generate`], the operations counted if `counted`.
fn generate_with(eq: &Equations, fields: Vec<TokenStream>, counted: bool) -> Generated {
    let ctx = Context {
        parameters: local(PARAMETERS),
        counted,
    };
    let mut modules = Vec::new();
    let mut methods = Vec::new();
    let depends = dependencies(eq);
    for &family in Family::ALL {
        // A method the trait gives a body of zeros (friction) only where the robot has the
        // term, so that the code of a robot without it is what it always was.
        let members: Vec<Method> = Method::ALL
            .iter()
            .copied()
            .filter(|m| m.family() == family && m.is_generated(eq))
            .collect();
        // No module for a family with nothing to generate (derivatives not asked for).
        if members.is_empty() {
            continue;
        }
        let outputs: Vec<Output> = members
            .iter()
            .map(|&method| Output {
                method,
                shape: method.shape(eq),
            })
            .collect();
        let emission = emit_with(eq, &outputs, &ctx, &depends);
        // The bodies moved, not cloned: a shared stream is copied when extended.
        methods.extend(
            members
                .iter()
                .zip(emission.bodies)
                .map(|(&method, b)| MethodCode {
                    method,
                    name: method.name(),
                    body: b.tokens,
                    ops: b.ops,
                    zeros: b.zeros,
                    lanes: b.lanes,
                }),
        );
        modules.push(Module {
            family,
            configuration: emission.configuration,
            motion: emission.motion,
            parts: emission.parts,
        });
    }
    release_spare_tables();
    methods.sort_by_key(|m| m.method);
    Generated {
        dof: eq.dof,
        base_count: eq.base_parameters.as_ref().map_or(0, |b| b.values.len()),
        links: eq.links,
        joint_rows: eq
            .regressor
            .as_ref()
            .map(|r| r.rows.clone())
            .filter(|rows| rows.iter().enumerate().any(|(i, &row)| row != i)),
        tip_names: eq
            .families
            .contains(Family::Tips)
            .then(|| eq.tips.as_ref().map(|t| t.names.clone()))
            .flatten(),
        fields,
        modules,
        methods,
    }
}

impl Generated {
    /// A robot's counts and fields alone, without methods: what a family emitted outside the
    /// method table (a floating base's kinematics, its contact terms) writes its types with.
    pub(super) fn counts_only(eq: &Equations, fields: &[TokenStream]) -> Self {
        Generated {
            dof: eq.dof,
            base_count: 0,
            links: eq.links,
            joint_rows: None,
            tip_names: None,
            fields: fields.to_vec(),
            modules: Vec::new(),
            methods: Vec::new(),
        }
    }

    /// The counts its types are written with.
    pub(super) fn counts(&self) -> Counts {
        let (dof, base, links) = (self.dof, self.base_count, self.links);
        let tips = self.tip_names.as_ref().map_or(0, Vec::len);
        Counts {
            joints: quote!(#dof),
            base: quote!(#base),
            tips: quote!(#tips),
            links: quote!(#links),
        }
    }

    /// The items for the robot type `ident`, most to go in a `const _: () = { … };` block:
    ///
    /// * a module `__dynamics` holding the configuration struct and function and one function
    ///   per method, which take the parameters as an array `p_: &[T; K]`. A module sees none of
    ///   the items around it, so no user constant can collide with a generated local (`let`
    ///   patterns cannot shadow constants: a user's `const t1` would otherwise break the code);
    ///   a module per other [`Family`] (`__kinematics`), the same for its methods; those of
    ///   [`Family::is_beside_the_struct`] go beside the struct instead ([`Items::beside`]);
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
        docs: &dyn Fn(Method) -> Option<String>,
    ) -> Items {
        let counts = &self.counts();
        let k = self.fields.len();
        let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
        let t = scalar_name(generics);
        let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
        let (beside, within): (Vec<&Module>, Vec<&Module>) = self
            .modules
            .iter()
            .partition(|module| module.family.is_beside_the_struct());
        let module = |m: &&Module| self.module(m, krate, ident);
        let (beside, modules) = (beside.iter().map(module), within.iter().map(module));
        let fns = self.methods.iter().map(|m| {
            let name = Ident::new(m.name, Span::call_site());
            let (args, ret) = signature(m.method, counts, &t, krate, false);
            let pass = call_arguments(m.method);
            let module = module_name(m.method.family(), ident);
            let call = quote!(#module::#name(&self.#parameters(), #pass));
            let call = if m.method.is_compiled_apart() {
                call
            } else {
                forward(m.method, call, counts, &t, krate)
            };
            let f = quote! {
                #[inline]
                fn #name<#t: #krate::Real>(&self, #args) -> #ret {
                    #call
                }
            };
            let f = match docs(m.method) {
                Some(doc) => quote!(#[doc = #doc] #f),
                None => f,
            };
            let into = m.zeros.as_ref().and(m.method.in_place_name()).map(|into| {
                let (into, y) = (Ident::new(into, Span::call_site()), local(OUTPUT));
                quote! {
                    #[inline]
                    fn #into<#t: #krate::Real>(&self, #args, #y: &mut #ret) {
                        #module::#into(&self.#parameters(), #pass, #y)
                    }
                }
            });
            (m.method, quote!(#f #into))
        });
        let known = Sizes {
            joints: Some(self.dof),
            base: Some(self.base_count),
            tips: Some(self.tip_names.as_ref().map_or(0, Vec::len)),
            links: (self.links != self.dof).then_some(self.links),
        };
        // The trait's default (each joint's own row) but on a robot with mimic joints.
        let joint_rows = self.joint_rows.as_ref().map(|rows| {
            let links = self.links;
            (
                Method::JointRegressor,
                quote!(const JOINT_ROWS: [usize; #links] = [#(#rows),*];),
            )
        });
        let fns = fns.chain(joint_rows);
        let tip_names = self.tip_names.as_deref().map(super::tip_names::constants);
        let impls = trait_impls(krate, &known, ident, generics, fns);
        let fields = &self.fields;
        let reader = (k > 0).then(|| quote!(use #krate::__private::param;));
        let within = quote! {
            #(#modules)*
            impl #impl_generics #ident #ty_generics #where_clause {
                /// The parameters the equations read, in the order of the description.
                #[doc(hidden)]
                #[inline(always)]
                #[allow(clippy::all, clippy::pedantic, clippy::nursery)]
                fn #parameters<#t: #krate::Real>(&self) -> [#t; #k] {
                    #reader
                    [#(param(#fields)),*]
                }
                #tip_names
            }
            #impls
        };
        Items {
            beside: quote!(#(#beside)*),
            within,
        }
    }

    /// The module of one family's functions: the shared functions and one function per
    /// method.
    pub(super) fn module(
        &self,
        module: &Module,
        krate: &TokenStream,
        ident: &syn::Ident,
    ) -> TokenStream {
        let k = self.fields.len();
        let counts = &self.counts();
        let p = local(PARAMETERS);
        let (configuration, motion) = (module.configuration.as_ref(), module.motion.as_ref());
        let configuration_item = self.configuration_item(configuration, krate);
        let motion_item = self.motion_item(motion, configuration.is_some(), krate);
        let bodies = self
            .methods
            .iter()
            .filter(|m| m.method.family() == module.family);
        let bodies = bodies.map(|m| {
            let name = Ident::new(m.name, Span::call_site());
            let scalar = Ident::new("T", Span::call_site());
            let body = &m.body;
            if let (Some(zeros), Some(into)) = (&m.zeros, m.method.in_place_name()) {
                return self.in_place_functions(m, zeros, into, krate);
            }
            // A function compiled apart returns the trait's type, built where its result is
            // written: converted after the call, the result would be copied, and the copy's
            // wide loads of values just stored one by one would wait for the stores.
            let apart = m.method.is_compiled_apart();
            let (args, ret) = signature(m.method, counts, &scalar, krate, !apart);
            let (inline, body) = if apart {
                let call = TokenStream::from(TokenTree::Group(Group::new(
                    Delimiter::Parenthesis,
                    block(body.clone()),
                )));
                (
                    quote!(#[inline(never)]),
                    forward(m.method, call, counts, &scalar, krate),
                )
            } else {
                (quote!(#[inline(always)]), body.clone())
            };
            let head = quote! {
                #inline
                pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #args) -> #ret
            };
            with_body(head, body)
        });
        let name = module_name(module.family, ident);
        let tangent = self
            .methods
            .iter()
            .any(|m| m.method.family() == module.family && m.lanes)
            .then(|| quote!(use #krate::__private::{align_stack, Tangent};));
        // ∂q̈ by subtrees builds the trait's result itself (`emit/rows.rs`).
        let solved = module
            .parts
            .iter()
            .any(|part| part.solved)
            .then(|| quote!(use #krate::{ForwardDynamicsDerivatives, NotPositiveDefinite};));
        // Beside the struct, the module is in the user's namespace, out of their docs.
        let hidden = module
            .family
            .is_beside_the_struct()
            .then(|| quote!(#[doc(hidden)]));
        let mut inner = TokenStream::new();
        inner.extend(
            tangent
                .into_iter()
                .chain(solved)
                .chain(configuration_item)
                .chain(motion_item),
        );
        let parts = module.parts.iter();
        let (k, counts) = (self.fields.len(), self.counts());
        inner.extend(parts.map(|part| part_function(part, k, &counts, krate)));
        inner.extend(bodies);
        let head = quote! {
            /// The generated functions, out of reach of the names around the derive.
            #hidden
            #[allow(non_snake_case, non_camel_case_types, unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
            mod #name
        };
        with_body(head, inner)
    }

    /// The configuration struct and function, if any method reads them.
    pub(super) fn configuration_item(
        &self,
        configuration: Option<&Shared>,
        krate: &TokenStream,
    ) -> Option<TokenStream> {
        let ty = Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        let function = SharedFunction {
            doc: quote!(
                /// What the dynamics need from the parameters and `q` alone, computed once.
            ),
            result: quote!(#ty<T>),
            ty,
            name: CONFIGURATION_FN,
            arguments: &[Argument::Q],
        };
        Some(self.shared_item(configuration?, krate, function))
    }

    /// The motion struct and function, if two methods share terms in `q̇`; with a
    /// configuration, the motion function computes it too and hands both over.
    pub(super) fn motion_item(
        &self,
        motion: Option<&Shared>,
        with_configuration: bool,
        krate: &TokenStream,
    ) -> Option<TokenStream> {
        let ty = Ident::new(MOTION_STRUCT, Span::call_site());
        let configuration = Ident::new(CONFIGURATION_STRUCT, Span::call_site());
        let result = if with_configuration {
            quote!((#configuration<T>, #ty<T>))
        } else {
            quote!(#ty<T>)
        };
        let function = SharedFunction {
            doc: quote!(
                /// What several methods compute from `q̇` too, computed once.
            ),
            result,
            ty,
            name: MOTION_FN,
            arguments: &[Argument::Q, Argument::Qd],
        };
        Some(self.shared_item(motion?, krate, function))
    }

    /// A shared function's struct and the inlined function computing it.
    fn shared_item(
        &self,
        shared: &Shared,
        krate: &TokenStream,
        function: SharedFunction,
    ) -> TokenStream {
        let (n, k) = (self.dof, self.fields.len());
        let p = local(PARAMETERS);
        let SharedFunction {
            doc,
            ty,
            name,
            arguments,
            result,
        } = function;
        let name = Ident::new(name, Span::call_site());
        let arguments = arguments.iter().map(|&a| argument_local(a));
        let fields = &shared.fields;
        let head = quote! {
            #doc
            pub(super) struct #ty<T> { #(#fields: T),* }
            // Inlined into each method, which keeps of it only what it reads.
            #[inline(always)]
            pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #(#arguments: &[T; #n]),*) -> #result
        };
        with_body(head, shared.tokens.clone())
    }
}

/// A shared function: its struct's doc and name, its name, its arguments after the
/// parameters and its result type.
struct SharedFunction {
    doc: TokenStream,
    ty: Ident,
    name: &'static str,
    arguments: &'static [Argument],
    result: TokenStream,
}

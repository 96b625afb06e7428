//! The generated items: the emitted bodies of every [`Method`] put together into a module of
//! functions, a parameter reader and the `Dynamics` impl forwarding to them.

use super::{emit, local, Context, OpCount, Output, Shared};
use super::{CONFIGURATION_FN, CONFIGURATION_STRUCT, MOTION_FN, MOTION_STRUCT, PARAMETERS};
use crate::method::{Argument, Family, Method, Returns};
use crate::trace::Equations;
use proc_macro2::{Ident, Span, TokenStream};
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
}

/// The generated code of a robot: the shared configuration (see [`emit`]) and the methods of
/// the `Dynamics` impl.
pub struct Generated {
    /// Number of joints.
    pub dof: usize,
    /// How to read each struct field of the robot, in the order of [`Equations::fields`].
    pub fields: Vec<TokenStream>,
    /// The shared functions of each [`Family`] of methods, in the order of [`Family::ALL`]:
    /// each family is emitted apart, so code that calls only the dynamics does not inline the
    /// kinematics, nor the reverse.
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
}
/// Name of the hidden inherent method reading the robot's parameters.
const PARAMETERS_FN: &str = "__dynamics_parameters";

/// The generated code of the [`Equations`], every method of [`Method::ALL`]; `fields` reads
/// struct field `k` of the robot (`self.name`), in the order of [`Equations::fields`].
#[must_use]
pub fn generate(eq: &Equations, fields: Vec<TokenStream>) -> Generated {
    let ctx = Context {
        parameters: local(PARAMETERS),
    };
    let mut modules = Vec::new();
    let mut methods = Vec::new();
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
        let emission = emit(eq, &outputs, &ctx);
        methods.extend(
            members
                .iter()
                .zip(&emission.bodies)
                .map(|(&method, b)| MethodCode {
                    method,
                    name: method.name(),
                    body: b.tokens.clone(),
                    ops: b.ops,
                }),
        );
        modules.push(Module {
            family,
            configuration: emission.configuration,
            motion: emission.motion,
        });
    }
    methods.sort_by_key(|m| m.method);
    Generated {
        dof: eq.dof,
        fields,
        modules,
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
    ///   a module per other [`Family`] (`__kinematics`), the same for its methods;
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
    ) -> TokenStream {
        let n = self.dof;
        let k = self.fields.len();
        let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
        let t = scalar_name(generics);
        let parameters = Ident::new(PARAMETERS_FN, Span::call_site());
        let modules = self.modules.iter().map(|module| self.module(module, krate));
        let fns = self.methods.iter().map(|m| {
            let name = Ident::new(m.name, Span::call_site());
            let (args, ret) = signature(m.method, n, &t, krate, false);
            let pass = call_arguments(m.method);
            let module = Ident::new(m.method.family().module(), Span::call_site());
            let call = quote!(#module::#name(&self.#parameters(), #pass));
            let call = forward(m.method, call, krate);
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
            (m.method, f)
        });
        let impls = trait_impls(krate, n, ident, generics, fns);
        let fields = &self.fields;
        let reader = (k > 0).then(|| quote!(use #krate::__private::param;));
        quote! {
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
            }
            #impls
        }
    }

    /// The module of one family's functions: the shared functions and one function per
    /// method.
    fn module(&self, module: &Module, krate: &TokenStream) -> TokenStream {
        let (n, k) = (self.dof, self.fields.len());
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
            let (args, ret) = signature(m.method, n, &scalar, krate, true);
            let body = &m.body;
            quote! {
                #[inline(always)]
                pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #args) -> #ret {
                    #body
                }
            }
        });
        let name = Ident::new(module.family.module(), Span::call_site());
        quote! {
            /// The generated functions, out of reach of the names around the derive.
            #[allow(non_snake_case, non_camel_case_types, unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
            mod #name {
                #configuration_item
                #motion_item
                #(#bodies)*
            }
        }
    }

    /// The configuration struct and function, if any method reads them.
    fn configuration_item(
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
    fn motion_item(
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
        let body = &shared.tokens;
        quote! {
            #doc
            pub(super) struct #ty<T> { #(#fields: T),* }
            // Inlined into each method, which keeps of it only what it reads.
            #[inline(always)]
            pub(super) fn #name<T: #krate::Real>(#p: &[T; #k], #(#arguments: &[T; #n]),*) -> #result {
                #body
            }
        }
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

/// The name of the generated methods' scalar type parameter: `T`, unless the struct has a
/// generic parameter of that name (a method's parameter may not reuse its impl's), then the
/// first of `S`, `R`, `F`, `T0`, `T1`, … it does not use.
#[must_use]
pub fn scalar_name(generics: &syn::Generics) -> Ident {
    let taken: Vec<String> = generics
        .params
        .iter()
        .filter_map(|p| match p {
            syn::GenericParam::Type(t) => Some(t.ident.to_string()),
            syn::GenericParam::Const(c) => Some(c.ident.to_string()),
            syn::GenericParam::Lifetime(_) => None,
        })
        .collect();
    let name = ["T", "S", "R", "F"]
        .into_iter()
        .map(String::from)
        .chain((0..).map(|i| format!("T{i}")))
        .find(|name| !taken.contains(name))
        .unwrap_or_default();
    Ident::new(&name, Span::call_site())
}

/// One method of the `Dynamics` impl with the given body, its scalar type parameter named
/// `scalar` (see `scalar_name`).
#[must_use]
pub fn method(
    method: Method,
    n: usize,
    krate: &TokenStream,
    scalar: &Ident,
    body: &TokenStream,
) -> TokenStream {
    let (args, ret) = signature(method, n, scalar, krate, false);
    let name = Ident::new(method.name(), Span::call_site());
    quote! {
        #[inline]
        #[allow(unused_variables, unused_doc_comments, clippy::all, clippy::pedantic, clippy::nursery)]
        fn #name<#scalar: #krate::Real>(&self, #args) -> #ret {
            #body
        }
    }
}

/// `impl Trait<N> for Type { … }` for each runtime trait that `methods` (a method and its item)
/// implement: `Dynamics`, then `DynamicsDerivatives` where the robot has its methods.
pub(super) fn trait_impls(
    krate: &TokenStream,
    n: usize,
    ident: &syn::Ident,
    generics: &syn::Generics,
    methods: impl Iterator<Item = (Method, TokenStream)>,
) -> TokenStream {
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let methods: Vec<(Method, TokenStream)> = methods.collect();
    let mut traits: Vec<&str> = Family::ALL.iter().map(|f| f.trait_name()).collect();
    traits.dedup();
    let impls = traits.into_iter().filter_map(|name| {
        let fns = methods
            .iter()
            .filter(|(m, _)| m.family().trait_name() == name);
        let fns: Vec<&TokenStream> = fns.map(|(_, f)| f).collect();
        let name = Ident::new(name, Span::call_site());
        (!fns.is_empty()).then(|| {
            quote! {
                #[automatically_derived]
                impl #impl_generics #krate::#name<#n> for #ident #ty_generics #where_clause {
                    #(#fns)*
                }
            }
        })
    });
    quote!(#(#impls)*)
}

/// The local an argument is bound to in generated code: `q_`, `qd_`, `qdd_`.
fn argument_local(argument: Argument) -> Ident {
    local(&format!("{}_", argument.name()))
}

/// The arguments and the result type of a method of the `Dynamics` trait, over scalar `t`;
/// with `rows`, the result as the module's function returns it (a pose as its rows `[R | p]`,
/// a result through the LDLᵀ of M as an `Option`, the derivatives' structs as arrays).
fn signature(
    method: Method,
    n: usize,
    t: &Ident,
    krate: &TokenStream,
    rows: bool,
) -> (TokenStream, TokenStream) {
    let arguments = method.arguments().iter().map(|&a| {
        let name = argument_local(a);
        match a {
            Argument::Wrench => quote!(#name: &[#t; 6]),
            Argument::Q | Argument::Qd | Argument::Qdd | Argument::Tau => quote!(#name: &[#t; #n]),
        }
    });
    let result = match method.returns() {
        Returns::Matrix => quote!([[#t; #n]; #n]),
        Returns::Vector => quote!([#t; #n]),
        Returns::Scalar => quote!(#t),
        Returns::Pose if rows => quote!([[#t; 4]; 3]),
        Returns::Pose => quote!(#krate::Pose<#t>),
        Returns::Poses if rows => quote!([[[#t; 4]; 3]; #n]),
        Returns::Poses => quote!([#krate::Pose<#t>; #n]),
        Returns::Jacobian => quote!([[#t; #n]; 6]),
        Returns::Spatial => quote!([#t; 6]),
        Returns::SolvedMatrix if rows => quote!(::core::option::Option<[[#t; #n]; #n]>),
        Returns::SolvedMatrix => {
            quote!(::core::result::Result<[[#t; #n]; #n], #krate::NotPositiveDefinite>)
        }
        Returns::SolvedVector if rows => quote!(::core::option::Option<[#t; #n]>),
        Returns::SolvedVector => {
            quote!(::core::result::Result<[#t; #n], #krate::NotPositiveDefinite>)
        }
        Returns::InverseDerivatives if rows => quote!([[[#t; #n]; #n]; 2]),
        Returns::InverseDerivatives => quote!(#krate::InverseDynamicsDerivatives<[[#t; #n]; #n]>),
        Returns::ForwardDerivatives if rows => {
            quote!(::core::option::Option<([#t; #n], [[[#t; #n]; #n]; 3])>)
        }
        Returns::ForwardDerivatives => quote!(::core::result::Result<
            #krate::ForwardDynamicsDerivatives<[#t; #n], [[#t; #n]; #n]>,
            #krate::NotPositiveDefinite,
        >),
    };
    (quote!(#(#arguments),*), result)
}

/// The call of a method's function in the generated module, `module::name(p_, q_)`, turned
/// into the trait's result (poses from their rows, the derivatives' structs from their
/// blocks).
fn forward(method: Method, call: TokenStream, krate: &TokenStream) -> TokenStream {
    match method.returns() {
        Returns::Pose => quote!(#krate::Pose::from_rows(#call)),
        Returns::Poses => quote!(#call.map(#krate::Pose::from_rows)),
        Returns::SolvedMatrix | Returns::SolvedVector => {
            quote!(#call.ok_or(#krate::NotPositiveDefinite))
        }
        Returns::InverseDerivatives => {
            quote!(#krate::InverseDynamicsDerivatives::from_blocks(#call))
        }
        Returns::ForwardDerivatives => quote!(#call
            .map(#krate::ForwardDynamicsDerivatives::from_parts)
            .ok_or(#krate::NotPositiveDefinite)),
        _ => call,
    }
}

/// The arguments a method passes on, as in [`signature`].
fn call_arguments(method: Method) -> TokenStream {
    let arguments = method.arguments().iter().map(|&a| argument_local(a));
    quote!(#(#arguments),*)
}

/// The runtime crate's path: `crate = "..."` if given, else `::dynamics_runtime`.
pub(crate) fn runtime_path(krate: Option<&syn::Path>) -> TokenStream {
    krate.map_or_else(|| quote!(::dynamics_runtime), ToTokens::to_token_stream)
}

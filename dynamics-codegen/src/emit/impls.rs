//! The trait's side of a derive: each method's signature, the `impl`s of the runtime's traits,
//! and the call of a method into its family's module, with the result turned into the trait's
//! type.

use super::names::local;
use crate::method::{Argument, Family, Instance, Method};
use proc_macro2::{Ident, Span, TokenStream};
use quote::{quote, ToTokens};

/// The name of the generated methods' scalar type parameter: `T`, unless the struct has a
/// generic parameter of that name (a method's parameter may not reuse its impl's), then the
/// first of `S`, `R`, `F`, `T0`, `T1`, … it does not use.
#[must_use]
pub fn scalar_name(generics: &syn::Generics) -> Ident {
    unused_name(generics, &["T", "S", "R", "F"], "T")
}

/// The first of `names`, then of `prefix0`, `prefix1`, …, that no generic parameter of the
/// struct takes.
fn unused_name(generics: &syn::Generics, names: &[&str], prefix: &str) -> Ident {
    let taken: Vec<String> = generics
        .params
        .iter()
        .filter_map(|p| match p {
            syn::GenericParam::Type(t) => Some(t.ident.to_string()),
            syn::GenericParam::Const(c) => Some(c.ident.to_string()),
            syn::GenericParam::Lifetime(_) => None,
        })
        .collect();
    let name = names
        .iter()
        .map(|name| (*name).to_owned())
        .chain((0..).map(|i| format!("{prefix}{i}")))
        .find(|name| !taken.contains(name))
        .unwrap_or_default();
    Ident::new(&name, Span::call_site())
}

/// The counts a derive's types are written with: the number of joints (`N`), of base
/// parameters (`B`), of tips (`TIPS`) and of links (`LINKS`: `N` but on a robot with mimic
/// joints), each a literal or a const parameter of the impls.
pub struct Counts {
    pub joints: TokenStream,
    pub base: TokenStream,
    pub tips: TokenStream,
    pub links: TokenStream,
}

impl Counts {
    /// The count a family's trait takes after `N`, by the name its row gives it.
    fn of(&self, parameter: &str) -> &TokenStream {
        match parameter {
            "TIPS" => &self.tips,
            "LINKS" => &self.links,
            _ => &self.base,
        }
    }

    /// What a result's types are written with, over scalar `t`.
    fn instance<'a>(&'a self, t: &'a Ident, krate: &'a TokenStream) -> Instance<'a> {
        Instance {
            scalar: t,
            n: &self.joints,
            base: &self.base,
            tips: &self.tips,
            links: &self.links,
            krate,
        }
    }
}

/// The counts the traits are implemented for: the robot's, or, where a derive failed before it
/// could read one (the number of joints of a missing file; the base parameters, always), any:
/// a const parameter of the impls, so that calls to the traits still compile and report
/// nothing of their own.
pub(super) struct Sizes {
    pub joints: Option<usize>,
    pub base: Option<usize>,
    pub tips: Option<usize>,
    /// The number of links where it is not the number of joints (a robot with mimic joints).
    pub links: Option<usize>,
}

impl Sizes {
    /// The counts as the impls write them: literals (`6usize`), or the names of the const
    /// parameters, which the struct's generics do not take.
    pub(super) fn counts(&self, generics: &syn::Generics) -> Counts {
        let joints = match self.joints {
            Some(n) => quote!(#n),
            None => unused_name(generics, &["N", "J"], "N").into_token_stream(),
        };
        let base = match self.base {
            Some(b) => quote!(#b),
            None => unused_name(generics, &["B", "K"], "B").into_token_stream(),
        };
        let tips = match self.tips {
            Some(t) => quote!(#t),
            None => unused_name(generics, &["TIPS"], "TIPS").into_token_stream(),
        };
        // The trait's default, `N`, unless the robot has more links than coordinates.
        let links = match self.links {
            Some(l) => quote!(#l),
            None => joints.clone(),
        };
        Counts {
            joints,
            base,
            tips,
            links,
        }
    }

    /// Whether the count named `parameter` (a trait row's) is known.
    fn knows(&self, parameter: &str) -> bool {
        match parameter {
            "TIPS" => self.tips.is_some(),
            // `N`'s, when not a count of its own.
            "LINKS" => true,
            _ => self.base.is_some(),
        }
    }
}

/// One method of the `Dynamics` impl with the given body, its scalar type parameter named
/// `scalar` (see `scalar_name`).
#[must_use]
pub fn method(
    method: Method,
    counts: &Counts,
    krate: &TokenStream,
    scalar: &Ident,
    body: &TokenStream,
) -> TokenStream {
    let (args, ret) = signature(method, counts, scalar, krate, false);
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
/// implement: `Dynamics`, then each opt-in family's trait where the robot has its methods
/// (`Trait<N, B>` for a trait with a count of its own). A count that [`Sizes`] does not know is
/// a const parameter of the impls, named as [`Sizes::counts`] names it, which the methods' items
/// must use.
pub(super) fn trait_impls(
    krate: &TokenStream,
    sizes: &Sizes,
    ident: &syn::Ident,
    generics: &syn::Generics,
    methods: impl Iterator<Item = (Method, TokenStream)>,
) -> TokenStream {
    let (impl_generics, ty_generics, where_clause) = generics.split_for_impl();
    let counts = sizes.counts(generics);
    let n = &counts.joints;
    let methods: Vec<(Method, TokenStream)> = methods.collect();
    let mut families: Vec<Family> = Family::ALL.to_vec();
    families.dedup_by_key(|f| f.trait_name());
    let impls = families.into_iter().filter_map(|family| {
        let name = family.trait_name();
        let fns = methods
            .iter()
            .filter(|(m, _)| m.family().trait_name() == name);
        let fns: Vec<&TokenStream> = fns.map(|(_, f)| f).collect();
        // The struct's parameters as an impl writes them (no defaults), and the counts not known.
        let mut params: syn::Generics =
            syn::parse2(impl_generics.to_token_stream()).unwrap_or_default();
        if sizes.joints.is_none() {
            params.params.push(syn::parse_quote!(const #n: usize));
        }
        // `LINKS` left to its default, `N`, where it is `N`: the impls of every serial robot.
        let written = family
            .count_parameters()
            .iter()
            .filter(|&&parameter| parameter != "LINKS" || sizes.links.is_some());
        let mut trait_counts = vec![n.clone()];
        for &parameter in written {
            let c = counts.of(parameter);
            if !sizes.knows(parameter) {
                params.params.push(syn::parse_quote!(const #c: usize));
            }
            trait_counts.push(c.clone());
        }
        let counts = quote!(#(#trait_counts),*);
        let name = Ident::new(name, Span::call_site());
        (!fns.is_empty()).then(|| {
            quote! {
                #[automatically_derived]
                impl #params #krate::#name<#counts> for #ident #ty_generics #where_clause {
                    #(#fns)*
                }
            }
        })
    });
    quote!(#(#impls)*)
}

/// The local an argument is bound to in generated code: `q_`, `qd_`, `qdd_`.
pub(super) fn argument_local(argument: Argument) -> Ident {
    local(&format!("{}_", argument.name()))
}

/// The arguments and the result type of a method of the `Dynamics` trait, over scalar `t`;
/// with `rows`, the result as the module's function returns it (a pose as its rows `[R | p]`,
/// a result through the LDLᵀ of M as an `Option`, the derivatives' structs as arrays).
pub(super) fn signature(
    method: Method,
    counts: &Counts,
    t: &Ident,
    krate: &TokenStream,
    rows: bool,
) -> (TokenStream, TokenStream) {
    let n = &counts.joints;
    let arguments = method.arguments().iter().map(|&a| {
        let name = argument_local(a);
        match a {
            Argument::Wrench => quote!(#name: &[#t; 6]),
            Argument::Wrenches => {
                let tips = &counts.tips;
                quote!(#name: &[[#t; 6]; #tips])
            }
            Argument::Q | Argument::Qd | Argument::Qdd | Argument::Tau => quote!(#name: &[#t; #n]),
        }
    });
    let at = counts.instance(t, krate);
    let result = if rows {
        method.returns().rows_type(&at)
    } else {
        method.returns().array_type(&at)
    };
    (quote!(#(#arguments),*), result)
}

/// The call of a method's function in the generated module, `module::name(p_, q_)`, turned
/// into the trait's result (poses from their rows, the derivatives' structs from their
/// blocks).
pub(super) fn forward(
    method: Method,
    call: TokenStream,
    counts: &Counts,
    t: &Ident,
    krate: &TokenStream,
) -> TokenStream {
    let at = counts.instance(t, krate);
    method.returns().convert_rows(call, &at)
}

/// The arguments a method passes on, as in [`signature`].
pub(super) fn call_arguments(method: Method) -> TokenStream {
    let arguments = method.arguments().iter().map(|&a| argument_local(a));
    quote!(#(#arguments),*)
}

/// The runtime crate's path: `crate = "..."` if given, else `::dynamics_runtime`.
pub(crate) fn runtime_path(krate: Option<&syn::Path>) -> TokenStream {
    krate.map_or_else(|| quote!(::dynamics_runtime), ToTokens::to_token_stream)
}

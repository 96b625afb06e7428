//! The result of a method, [`Returns`], from the rows of the result table (`results.rs`, the
//! runtime's): each row's types are written there once, with `T` and `N`, and turned here into
//! the tokens of one derive (its scalar, its number of joints, its path to the runtime).

use proc_macro2::{Group, Ident, TokenStream, TokenTree};
use quote::quote;
use std::str::FromStr;

/// `enum Returns`, its row's texts, and `returns!(keyword)` for the method table's rows.
macro_rules! declare_returns {
    ($d:tt $(
        $(#[doc = $doc:literal])*
        $keyword:ident {
            variant: $variant:ident,
            array: $array:ty,
            nalgebra: $_nalgebra:ty,
            to_nalgebra: $_to_nalgebra:expr,
            rows: $rows:ty,
            from_rows: $from_rows:expr,
        }
    )*) => {
        /// The result of a generated method.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Returns {
            $($(#[doc = $doc])* $variant,)*
        }

        impl Returns {
            /// The trait method's result type, with `T` and `N`.
            fn array_text(self) -> &'static str {
                match self { $(Returns::$variant => stringify!($array),)* }
            }

            /// The generated module's result type, with `T` and `N`.
            fn rows_text(self) -> &'static str {
                match self { $(Returns::$variant => stringify!($rows),)* }
            }

            /// The closure turning the module's result into the trait's.
            fn conversion_text(self) -> &'static str {
                match self { $(Returns::$variant => stringify!($from_rows),)* }
            }
        }

        /// The `Returns` of a row's result keyword.
        macro_rules! returns {
            $(($keyword) => { Returns::$variant };)*
        }
    };
}

for_each_result!(declare_returns $);

/// What a result's types are written with in one derive.
pub struct Instance<'a> {
    /// The scalar type parameter (`T`, or another name where the struct takes `T`).
    pub scalar: &'a Ident,
    /// The number of joints: a literal (`6usize`), or a const parameter.
    pub n: &'a TokenStream,
    /// The number of base parameters, likewise (read by `DynamicsBaseParameters` only).
    pub base: &'a TokenStream,
    /// The number of tips, likewise (read by `TipKinematics` only).
    pub tips: &'a TokenStream,
    /// The number of links, likewise (read by `DynamicsRegressor` and `DynamicsBaseParameters`
    /// only): `n` but on a robot with mimic joints.
    pub links: &'a TokenStream,
    /// The runtime crate's path.
    pub krate: &'a TokenStream,
}

impl Returns {
    /// The trait method's result type: `[[T; 6usize]; 6usize]`,
    /// `::dynamics_runtime::Pose<T>`.
    #[must_use]
    pub fn array_type(self, at: &Instance) -> TokenStream {
        at.instantiate(parse(self.array_text()), None)
    }

    /// The result type of its function in the generated module: a pose as its rows
    /// `[R | p]`, a result through the LDLᵀ of M as an `Option`, the derivatives' structs as
    /// their blocks.
    #[must_use]
    pub fn rows_type(self, at: &Instance) -> TokenStream {
        at.instantiate(parse(self.rows_text()), None)
    }

    /// `call`, the module function's result, turned into the trait's.
    #[must_use]
    pub fn convert_rows(self, call: TokenStream, at: &Instance) -> TokenStream {
        // The row's closure `|value| body`: its body, with `call` for `value`.
        let body = parse(self.conversion_text()).into_iter().skip(3).collect();
        at.instantiate(body, Some(&call))
    }
}

impl Instance<'_> {
    /// `tokens` with `T` the scalar, `N` the number of joints, `B` the number of base
    /// parameters, `TIPS` of tips, `LINKS` of links, `value` the given tokens,
    /// `Result` and `Option` core's, and every other type name the runtime's.
    fn instantiate(&self, tokens: TokenStream, value: Option<&TokenStream>) -> TokenStream {
        let mut out = TokenStream::new();
        let mut after_path = false;
        for tree in tokens {
            let next_after_path = matches!(&tree, TokenTree::Punct(p) if p.as_char() == ':');
            match tree {
                TokenTree::Group(g) => {
                    let inner = self.instantiate(g.stream(), value);
                    out.extend([TokenTree::Group(Group::new(g.delimiter(), inner))]);
                }
                TokenTree::Ident(i) if !after_path => out.extend(self.ident(&i, value)),
                other => out.extend([other]),
            }
            after_path = next_after_path;
        }
        out
    }

    /// One name of a row, in this derive.
    fn ident(&self, ident: &Ident, value: Option<&TokenStream>) -> TokenStream {
        let krate = self.krate;
        match ident.to_string().as_str() {
            "T" => TokenTree::Ident(self.scalar.clone()).into(),
            "N" => self.n.clone(),
            "B" => self.base.clone(),
            "TIPS" => self.tips.clone(),
            "LINKS" => self.links.clone(),
            "value" => value.cloned().unwrap_or_else(|| quote!(#ident)),
            "Result" => quote!(::core::result::Result),
            "Option" => quote!(::core::option::Option),
            name if name.starts_with(char::is_uppercase) => quote!(#krate::#ident),
            _ => quote!(#ident),
        }
    }
}

/// A row's text as tokens. The runtime compiles every row, so the text always parses; were
/// it not to, the derive would say so rather than panic.
fn parse(text: &str) -> TokenStream {
    TokenStream::from_str(text).unwrap_or_else(|_| {
        let message = format!("dynamics-codegen: a result type does not parse: {text}");
        quote!(::core::compile_error!(#message))
    })
}

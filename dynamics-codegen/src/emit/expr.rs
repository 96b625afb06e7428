//! The Rust printer of the plan ([`super::plan`]): `a + b`, `x.mul_add(y, a)`, `T::sin(a)`,
//! `T::ONE / a`, constants as `T::from_f64(0.42)` (bound to a `kN` where a function reads them)
//! and inputs and bound nodes by their names.

use super::emitter::Emitter;
use super::names::local;
use super::plan::{self, Function, Operator, Place, Precedence, Printer};
use crate::symbolic::{NodeId, Number, Var};
use proc_macro2::{Delimiter, Group, Punct, Spacing, TokenStream, TokenTree};
use quote::quote;

impl Emitter<'_> {
    /// A node's expression at `place`: its name if it has one, else written out, in
    /// parentheses where the place needs them.
    pub(super) fn expr(&self, id: NodeId, place: Place) -> TokenStream {
        plan::expr(self, id, place)
    }

    /// A node written out, not by its name.
    pub(super) fn define(&self, id: NodeId) -> TokenStream {
        plan::written(self, id).0
    }

    /// A constant's value: `T::ZERO`, `T::ONE`, `T::from_f64(0.42)`.
    pub(super) fn literal(&self, c: Number) -> TokenStream {
        if c.is_zero() {
            return self.zero.clone();
        }
        if c.is_one() {
            return self.one.clone();
        }
        let x = c.to_f64();
        // A literal cannot spell a non-finite value (and the literal constructor panics on
        // one); such a constant can only come from overflowing arithmetic of finite parameters.
        let value = if x.is_nan() {
            quote!(::core::f64::NAN)
        } else if x.is_infinite() && x > 0.0 {
            quote!(::core::f64::INFINITY)
        } else if x.is_infinite() {
            quote!(::core::f64::NEG_INFINITY)
        } else {
            let lit = proc_macro2::Literal::f64_unsuffixed(x);
            quote!(#lit)
        };
        quote!(T::from_f64(#value))
    }

    /// Input `v`'s name: `q2`, `s2`, `p_m2` (a parameter by its field's name).
    pub(super) fn variable_name(&self, v: Var) -> proc_macro2::Ident {
        local(&plan::leaf_name(v, |k| format!("p_{}", self.eq.fields[k])))
    }
}

impl Printer for Emitter<'_> {
    type Code = TokenStream;
    const MUL_ADD_FIRST: Place = Place::MulRight;

    fn bound(&self, id: NodeId) -> Option<TokenStream> {
        let name = self.names.get(id.index())?;
        Some(TokenStream::from(TokenTree::Ident(name.clone())))
    }

    fn variable(&self, v: Var) -> TokenStream {
        let name = self.variable_name(v);
        quote!(#name)
    }

    fn constant(&self, c: Number) -> (TokenStream, Precedence) {
        (self.literal(c), Precedence::Atom)
    }

    fn binary(&self, a: TokenStream, op: Operator, b: TokenStream) -> TokenStream {
        binary(a, op, b)
    }

    fn negate(&self, a: TokenStream) -> TokenStream {
        negate(a)
    }

    fn call(&self, f: Function, a: TokenStream) -> TokenStream {
        call(f, a)
    }

    fn mul_add(&self, x: TokenStream, y: TokenStream, a: TokenStream) -> TokenStream {
        mul_add(x, y, a)
    }

    fn parenthesized(&self, a: TokenStream) -> TokenStream {
        TokenStream::from(parenthesized(a))
    }
}

// The printer's forms join their operands' streams by moving them: `quote!(#a + #b)` would
// copy each (an interpolated stream is shared, and a shared stream is copied when extended),
// at every level of an expression.

/// `a + b`, `a - b`, `a * b`, `a / b`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn binary(mut a: TokenStream, op: Operator, b: TokenStream) -> TokenStream {
    let op = match op {
        Operator::Add => '+',
        Operator::Sub => '-',
        Operator::Mul => '*',
        Operator::Div => '/',
    };
    a.extend([TokenTree::Punct(Punct::new(op, Spacing::Alone))]);
    a.extend([b]);
    a
}

/// `-a`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn negate(a: TokenStream) -> TokenStream {
    let mut minus = TokenStream::from(TokenTree::Punct(Punct::new('-', Spacing::Alone)));
    minus.extend([a]);
    minus
}

/// `T::sin(a)`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn call(f: Function, a: TokenStream) -> TokenStream {
    let mut call = match f {
        Function::Sin => quote!(T::sin),
        Function::Cos => quote!(T::cos),
        Function::Tanh => quote!(T::tanh),
        Function::Sign => quote!(T::sign),
    };
    call.extend([parenthesized(a)]);
    call
}

/// `x.mul_add(y, a)`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn mul_add(mut x: TokenStream, mut y: TokenStream, a: TokenStream) -> TokenStream {
    x.extend(quote!(.mul_add));
    y.extend([TokenTree::Punct(Punct::new(',', Spacing::Alone))]);
    y.extend([a]);
    x.extend([parenthesized(y)]);
    x
}

/// `[a, b, c]`, the elements moved in.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn array(items: impl IntoIterator<Item = TokenStream>) -> TokenStream {
    let mut inner = TokenStream::new();
    for (k, item) in items.into_iter().enumerate() {
        if k > 0 {
            inner.extend([TokenTree::Punct(Punct::new(',', Spacing::Alone))]);
        }
        inner.extend([item]);
    }
    TokenStream::from(TokenTree::Group(Group::new(Delimiter::Bracket, inner)))
}

/// `{ a }`, `a` moved into the block.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn block(a: TokenStream) -> TokenStream {
    TokenStream::from(TokenTree::Group(Group::new(Delimiter::Brace, a)))
}

/// `head { body }`, the body moved into its braces: interpolated into `quote!`, a stream is
/// copied token by token (each name allocated again), where a clone of it is shared.
pub(super) fn with_body(mut head: TokenStream, body: TokenStream) -> TokenStream {
    head.extend([block(body)]);
    head
}

/// `let name = value;`, the value moved in.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn let_statement(name: &proc_macro2::Ident, value: TokenStream) -> TokenStream {
    let mut statement = quote!(let #name =);
    statement.extend([value, quote!(;)]);
    statement
}

/// `(a)`, `a` moved into the group.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn parenthesized(a: TokenStream) -> TokenTree {
    TokenTree::Group(Group::new(Delimiter::Parenthesis, a))
}

/// `text` as a raw string literal, `r#"…"#` with enough `#`s: the same string as
/// `Literal::string`, which escapes it character by character (a tenth of the readable
/// equations' cost for tens of kilobytes of text), where a raw string is only scanned for its
/// end. A text a raw string cannot hold (a bare carriage return) is escaped as before.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn raw_string(text: &str) -> proc_macro2::Literal {
    let mut fence = 0;
    let mut run = None;
    for c in text.chars() {
        run = match (c, run) {
            ('"', _) => Some(0),
            ('#', Some(n)) => Some(n + 1),
            _ => None,
        };
        fence = fence.max(run.map_or(0, |n| n + 1));
    }
    let fence = "#".repeat(fence);
    format!("r{fence}\"{text}\"{fence}")
        .parse()
        .unwrap_or_else(|_| proc_macro2::Literal::string(text))
}

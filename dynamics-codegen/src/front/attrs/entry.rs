//! Readers of the value after an attribute key: `N` values in brackets, the D-H table, a
//! spring, a convention, a boolean, a string, each reporting a malformed value as a syntax
//! error that says what was expected; and the bookkeeping every key list shares: a repeated
//! key is reported on its second occurrence, an unknown key skipped.

use crate::front::errors::Errors;
use crate::front::value::Spanned;
use crate::model::Convention;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::punctuated::Punctuated;
use syn::{bracketed, parenthesized, Ident, LitStr, Token};

/// A D-H row `[θ, d, a, α]` with the span of its first token.
/// A D-H row: its span, `[θ, d, a, α]`, and in a tree `[antecedent, γ, b]`.
pub(super) type DhRowAttr = (Span, [Spanned; 4], Option<[Spanned; 3]>);

/// One `key = value` entry of an attribute list, where a repeated key is reported.
pub(super) struct Entry<'a> {
    /// The key as written.
    pub ident: &'a Ident,
    /// What the keys of the list are called in messages.
    pub what: &'static str,
    pub errors: &'a mut Errors,
}

impl Entry<'_> {
    /// Stores the first value given for the key; a repeated key is an error on its second
    /// occurrence, and parsing goes on.
    pub(super) fn keep_first<T>(&mut self, slot: &mut Option<T>, value: T) {
        if slot.is_some() {
            let (key, what) = (self.ident, self.what);
            self.errors.push(
                key.span(),
                format!("duplicate {what} `{key}`: it is given earlier in this list"),
            );
        } else {
            *slot = Some(value);
        }
    }
}

/// Skips what follows an unknown key, up to the next `,` at this level, so that the keys
/// after it are still checked.
pub(super) fn skip_entry(input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() && !input.peek(Token![,]) {
        input.parse::<proc_macro2::TokenTree>()?;
    }
    Ok(())
}

/// `N` values in brackets, and the span of the brackets.
pub(super) fn values<const N: usize>(
    input: ParseStream,
    what: &str,
) -> syn::Result<([Spanned; N], Span)> {
    if !input.peek(syn::token::Bracket) {
        return Err(input.error(format!("expected {N} values in brackets: {what}")));
    }
    let content;
    let bracket = bracketed!(content in input);
    let items: Punctuated<Spanned, Token![,]> = Punctuated::parse_terminated(&content)?;
    let count = items.len();
    let span = bracket.span.join();
    let items: [Spanned; N] = items
        .into_iter()
        .collect::<Vec<_>>()
        .try_into()
        .map_err(|_| syn::Error::new(span, format!("{what} takes {N} values, found {count}")))?;
    Ok((items, span))
}

pub(super) fn parse_spring(input: ParseStream) -> syn::Result<(Spanned, Spanned)> {
    let usage = "expected `spring = (stiffness, rest_position)`";
    if !input.peek(syn::token::Paren) {
        return Err(input.error(usage));
    }
    let content;
    parenthesized!(content in input);
    let k: Spanned = content.parse()?;
    if !content.peek(Token![,]) {
        return Err(content.error(usage));
    }
    content.parse::<Token![,]>()?;
    let rest: Spanned = content.parse()?;
    content.parse::<Option<Token![,]>>()?;
    if !content.is_empty() {
        return Err(content.error(usage));
    }
    Ok((k, rest))
}

pub(super) fn parse_convention(input: ParseStream) -> syn::Result<(Convention, Span)> {
    let (text, span) = if input.peek(LitStr) {
        let s: LitStr = input.parse()?;
        (s.value(), s.span())
    } else if input.peek(Ident) {
        let i: Ident = input.parse()?;
        (i.to_string(), i.span())
    } else {
        return Err(input.error("expected `standard` or `modified`"));
    };
    match text.as_str() {
        "standard" => Ok((Convention::Standard, span)),
        "modified" => Ok((Convention::Modified, span)),
        _ => Err(syn::Error::new(
            span,
            format!("unknown convention `{text}`: expected `standard` or `modified`"),
        )),
    }
}

pub(super) fn parse_dh(input: ParseStream) -> syn::Result<(Vec<DhRowAttr>, Span)> {
    if !input.peek(syn::token::Bracket) {
        return Err(input.error(
            "expected the D-H table in brackets, one row per joint: `dh = [[θ, d, a, α], ...]`",
        ));
    }
    let content;
    let bracket = bracketed!(content in input);
    let mut rows = Vec::new();
    while !content.is_empty() {
        let span = content.span();
        let (cells, tree) = row(&content)?;
        rows.push((span, cells, tree));
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok((rows, bracket.span.join()))
}

/// `true` or `false`; `usage` says what the key does, for the error.
pub(super) fn boolean(input: ParseStream, usage: &str) -> syn::Result<bool> {
    if input.peek(syn::LitBool) {
        Ok(input.parse::<syn::LitBool>()?.value)
    } else {
        Err(input.error(format!("expected `true` or `false`: {usage}")))
    }
}

pub(super) fn string(input: ParseStream, usage: &str) -> syn::Result<LitStr> {
    if input.peek(LitStr) {
        input.parse()
    } else {
        Err(input.error(format!("expected a string: {usage}")))
    }
}

/// A bracketed list of strings, `["a", "b"]`, with the span of its brackets.
pub(super) fn strings(input: ParseStream, usage: &str) -> syn::Result<(Vec<LitStr>, Span)> {
    if !input.peek(syn::token::Bracket) {
        return Err(input.error(format!("expected a list of strings: {usage}")));
    }
    let content;
    let bracket = syn::bracketed!(content in input);
    let mut list = Vec::new();
    while !content.is_empty() {
        list.push(string(&content, usage)?);
        if content.is_empty() {
            break;
        }
        content.parse::<Token![,]>()?;
    }
    Ok((list, bracket.span.join()))
}

/// A D-H row of 4 values, or of 7 in a tree: `[θ, d, a, α, antecedent, γ, b]`.
fn row(input: ParseStream) -> syn::Result<([Spanned; 4], Option<[Spanned; 3]>)> {
    if !input.peek(syn::token::Bracket) {
        return Err(input.error("expected 4 values in brackets: a D-H row `[θ, d, a, α]`"));
    }
    let content;
    let bracket = bracketed!(content in input);
    let items: Punctuated<Spanned, Token![,]> = Punctuated::parse_terminated(&content)?;
    let count = items.len();
    if count != 4 && count != 7 {
        return Err(syn::Error::new(
            bracket.span.join(),
            format!(
                "a D-H row `[θ, d, a, α]` takes 4 values, found {count} (or 7 in a tree, \
                 modified convention: `[θ, d, a, α, antecedent, γ, b]`)"
            ),
        ));
    }
    let mut cells = items.into_iter();
    let mut next = || cells.next().expect("counted");
    let row = [next(), next(), next(), next()];
    let tree = (count == 7).then(|| [next(), next(), next()]);
    Ok((row, tree))
}

//! `simplify(tolerance = .., q_min = .., ...)`: the request for the pruned models, read as
//! numbers with their tokens; [`crate::front::simplify`] resolves it once the joints are known.

use super::entry::skip_entry;
use crate::front::errors::{unknown_key, Errors};
use crate::front::simplify::given::{Given, KEYS};
use crate::front::value::Spanned;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::punctuated::Punctuated;
use syn::{bracketed, parenthesized, Ident, Token};

/// The usage, for the errors of its syntax.
const USAGE: &str = "`simplify(tolerance = 0.5, q_min = -3.14, q_max = 3.14, qd_max = 2, \
                     qdd_max = 5)`: one number for every joint or `[..]` one per joint";

/// Parses what follows `simplify`; a key's mistakes go to `errors`, and parsing goes on.
pub(super) fn parse_simplify(
    input: ParseStream,
    ident: &Ident,
    errors: &mut Errors,
) -> syn::Result<Given<Span>> {
    if !input.peek(syn::token::Paren) {
        return Err(input.error(format!("expected {USAGE}")));
    }
    let content;
    parenthesized!(content in input);
    let mut given = Given {
        at: ident.span(),
        keys: Vec::new(),
    };
    while !content.is_empty() {
        let key: Ident = content.parse()?;
        let known = KEYS.iter().copied().find(|k| key == k);
        match known {
            Some(name) if given.keys.iter().any(|(k, _, _)| *k == name) => {
                let message =
                    format!("duplicate simplify key `{key}`: it is given earlier in this list");
                errors.push(key.span(), message);
                content.parse::<Token![=]>()?;
                skip_entry(&content)?;
            }
            Some(name) => {
                content.parse::<Token![=]>()?;
                if let Some(values) = numbers(&content, errors)? {
                    given.keys.push((name, values, key.span()));
                }
            }
            None => {
                errors.push(key.span(), unknown_key(&key, "simplify key", KEYS));
                skip_entry(&content)?;
            }
        }
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok(given)
}

/// One number or `[..]` of numbers; `None` (and an error on it) for a value that is not a
/// number, such as a struct field.
fn numbers(input: ParseStream, errors: &mut Errors) -> syn::Result<Option<Vec<f64>>> {
    let values: Vec<Spanned> = if input.peek(syn::token::Bracket) {
        let content;
        bracketed!(content in input);
        let items: Punctuated<Spanned, Token![,]> = Punctuated::parse_terminated(&content)?;
        items.into_iter().collect()
    } else {
        vec![input.parse()?]
    };
    let mut numbers = Vec::with_capacity(values.len());
    for v in &values {
        match v.value.eval(&|_| None) {
            Some(x) if v.fields.is_empty() => numbers.push(x),
            _ => {
                let message = "expected a number: the simplified model is proven over an \
                               envelope of numbers (no struct field or joint variable)";
                errors.push_range(v.span, v.end, message);
                return Ok(None);
            }
        }
    }
    Ok(Some(numbers))
}

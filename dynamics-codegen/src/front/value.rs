//! The value parser: the grammar of a robot's values, read from attribute tokens (with the span
//! of every token, for error messages) or from a description file's strings.
//!
//! ```text
//! value := term (('+' | '-') term)*
//! term  := power (('*' | '/') power)*
//! power := unary ('^' integer)?
//! unary := '-' unary | atom ('deg' | 'rad')?
//! atom  := number | 'pi' | 'PI' | 'q' | 'q'N | field | 'self' '.' field | '(' value ')'
//! ```
//!
//! A field is a struct field's name: an identifier, or a Rust keyword with or without `r#`
//! (`type` names the field `r#type`), but not `self`, `Self`, `super`, `crate` or `_`, which no
//! field can have. `q` (or `qN` in row N) is the joint variable and may appear only in the θ or
//! d cell of a D-H row. `90 deg` is exactly π/2, so its sine and cosine are exact; `rad` states
//! that a number is in radians. A number literal takes no suffix (`2m`, `2.5f64`, `90deg`): it
//! would be silently ignored. The terms of the top-level sum written as plain numbers (no unit, `pi`
//! or field) are kept as [`Unitless`], for the angle check of [`super::angle`].

use crate::identifiers::parameter_problem;
use crate::model::Value;
use crate::symbolic::Number;
use proc_macro2::Span;
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::{Ident, Lit, Token};

/// A value parsed with the span of its first token (for error messages).
pub struct Spanned {
    /// The value.
    pub value: Value,
    /// Where it was written: its first token.
    pub span: Span,
    /// Its last token.
    pub end: Span,
    /// Fields it names, each with where it was written.
    pub fields: Vec<(String, Span)>,
    /// The terms of its top-level sum that are plain numbers, without a unit.
    pub unitless: Vec<Unitless>,
}

/// A term of a value's top-level sum (`90` in `q + 90`, `-90`, `45 * 2` in `pi + 45 * 2`) made
/// of numbers alone: no `deg`, `rad`, `pi`, field or `q`.
#[derive(Clone, Debug)]
pub struct Unitless {
    /// Its value (its sign as written in the term: `q - 90` gives 90).
    pub value: Number,
    /// Its first token.
    pub span: Span,
    /// Its last token.
    pub end: Span,
}

/// What the parser gathers besides the value.
#[derive(Default)]
struct State {
    fields: Vec<(String, Span)>,
    /// How many `deg` and `rad` units it has read.
    units: usize,
    unitless: Vec<Unitless>,
}

impl Parse for Spanned {
    fn parse(input: ParseStream) -> syn::Result<Spanned> {
        let span = input.span();
        let start = input.cursor();
        bounded_extent(start, 0, &mut 0)?;
        let mut state = State::default();
        let value = parse_sum(input, &mut state, true)?;
        Ok(Spanned {
            value,
            span,
            end: last_span(start, input.cursor(), span),
            fields: state.fields,
            unitless: state.unitless,
        })
    }
}

/// The span of the last token from `start` up to `stop`, `default` if there is none.
fn last_span(start: syn::buffer::Cursor, stop: syn::buffer::Cursor, default: Span) -> Span {
    let mut end = default;
    let mut cursor = start;
    while cursor != stop {
        let Some((token, next)) = cursor.token_tree() else {
            break;
        };
        end = token.span();
        cursor = next;
    }
    end
}

/// The deepest nesting of parentheses a value may have.
const MAX_DEPTH: usize = 32;
/// The most tokens a value may have.
const MAX_TOKENS: usize = 2000;
/// The longest literal a value may have: an `f64` has 17 significant digits.
const MAX_LITERAL: usize = 1000;

/// Rejects a value (the tokens up to the next `,` at this level) that is nested or long enough
/// to exhaust the stack of the recursive parser and of the tree walks after it, or that has a
/// literal too long to read quickly.
fn bounded_extent(
    mut cursor: syn::buffer::Cursor,
    depth: usize,
    count: &mut usize,
) -> syn::Result<()> {
    while let Some((token, next)) = cursor.token_tree() {
        if depth == 0 && matches!(&token, proc_macro2::TokenTree::Punct(p) if p.as_char() == ',') {
            break;
        }
        *count += 1;
        if *count > MAX_TOKENS {
            return Err(syn::Error::new(
                token.span(),
                format!("a value may have at most {MAX_TOKENS} tokens"),
            ));
        }
        // syn reads a literal's digits in quadratic time (seconds for 10,000 digits).
        if let Some((lit, _)) = cursor.literal() {
            if lit.to_string().len() > MAX_LITERAL {
                return Err(syn::Error::new(
                    lit.span(),
                    format!("a literal may have at most {MAX_LITERAL} characters"),
                ));
            }
        }
        if let Some((inner, span, _)) = cursor.group(proc_macro2::Delimiter::Parenthesis) {
            if depth >= MAX_DEPTH {
                return Err(syn::Error::new(
                    span.open(),
                    format!("parentheses nested more than {MAX_DEPTH} deep"),
                ));
            }
            bounded_extent(inner, depth + 1, count)?;
        }
        cursor = next;
    }
    Ok(())
}

/// Parses a value from text (a description-file string).
///
/// # Errors
/// A message if the text is not a value.
pub fn parse_value(text: &str) -> Result<Value, String> {
    parse_spanned(text).map(|s| s.value)
}

/// Parses a value from text (a description-file string), with what [`Spanned`] keeps.
///
/// # Errors
/// A message if the text is not a value.
pub fn parse_spanned(text: &str) -> Result<Spanned, String> {
    let tokens: proc_macro2::TokenStream = text
        .parse()
        .map_err(|e: proc_macro2::LexError| format!("cannot read `{text}`: {e}"))?;
    syn::parse2::<Spanned>(tokens).map_err(|e| format!("cannot read `{text}` as a value: {e}"))
}

/// A sum; at the `top` level, its terms made of plain numbers go to `state.unitless`.
fn parse_sum(input: ParseStream, state: &mut State, top: bool) -> syn::Result<Value> {
    let mut left = parse_term(input, state, top)?;
    loop {
        if input.peek(Token![+]) {
            input.parse::<Token![+]>()?;
            left = Value::Add(Box::new(left), Box::new(parse_term(input, state, top)?));
        } else if input.peek(Token![-]) {
            input.parse::<Token![-]>()?;
            left = Value::Sub(Box::new(left), Box::new(parse_term(input, state, top)?));
        } else {
            return Ok(left);
        }
    }
}

/// One term of a sum, kept in `state.unitless` at the `top` level if made of plain numbers.
fn parse_term(input: ParseStream, state: &mut State, top: bool) -> syn::Result<Value> {
    let (span, start, units) = (input.span(), input.cursor(), state.units);
    let term = parse_product(input, state)?;
    // `exact` is `None` for `pi`, `deg` (a multiple of π), fields and `q`; `rad` is counted.
    if let (true, true, Some(value)) = (top, state.units == units, term.exact()) {
        state.unitless.push(Unitless {
            value,
            span,
            end: last_span(start, input.cursor(), span),
        });
    }
    Ok(term)
}

fn parse_product(input: ParseStream, state: &mut State) -> syn::Result<Value> {
    let mut left = parse_power(input, state)?;
    loop {
        if input.peek(Token![*]) {
            input.parse::<Token![*]>()?;
            left = Value::Mul(Box::new(left), Box::new(parse_power(input, state)?));
        } else if input.peek(Token![/]) {
            input.parse::<Token![/]>()?;
            left = Value::Div(Box::new(left), Box::new(parse_power(input, state)?));
        } else {
            return Ok(left);
        }
    }
}

/// The most terms a power may expand to.
const MAX_POWER_SIZE: usize = 4096;

fn parse_power(input: ParseStream, state: &mut State) -> syn::Result<Value> {
    let base = parse_unary(input, state)?;
    if !input.peek(Token![^]) {
        return Ok(base);
    }
    input.parse::<Token![^]>()?;
    let exponent: syn::LitInt = input.parse()?;
    let n: u32 = exponent.base10_parse()?;
    if !(1..=8).contains(&n) {
        return Err(syn::Error::new(
            exponent.span(),
            "exponent must be an integer from 1 to 8",
        ));
    }
    // `x^n` is stored as n − 1 products of copies of `x`, so nested powers grow as a product
    // of exponents: bound the copies so that `((x^8)^8)^8…` is an error, not a hang.
    if base.size().saturating_mul(n as usize) > MAX_POWER_SIZE {
        return Err(syn::Error::new(
            exponent.span(),
            format!("this power expands to more than {MAX_POWER_SIZE} terms: write it with fewer nested powers"),
        ));
    }
    let mut value = base.clone();
    for _ in 1..n {
        value = Value::Mul(Box::new(value), Box::new(base.clone()));
    }
    Ok(value)
}

fn parse_unary(input: ParseStream, state: &mut State) -> syn::Result<Value> {
    if input.peek(Token![-]) {
        input.parse::<Token![-]>()?;
        return Ok(Value::Neg(Box::new(parse_unary(input, state)?)));
    }
    let atom = parse_atom(input, state)?;
    if input.peek(Ident) {
        let fork = input.fork();
        let unit: Ident = fork.parse()?;
        if unit == "deg" {
            input.parse::<Ident>()?;
            state.units += 1;
            let pi_over_180 =
                Value::Div(Box::new(Value::Pi), Box::new(Value::Num(Number::int(180))));
            return Ok(Value::Mul(Box::new(atom), Box::new(pi_over_180)));
        }
        if unit == "rad" {
            input.parse::<Ident>()?;
            state.units += 1;
        }
    }
    Ok(atom)
}

fn parse_atom(input: ParseStream, state: &mut State) -> syn::Result<Value> {
    if input.peek(syn::token::Paren) {
        let content;
        syn::parenthesized!(content in input);
        let v = parse_sum(&content, state, false)?;
        if !content.is_empty() {
            return Err(content.error("expected `)` after the value"));
        }
        return Ok(v);
    }
    if input.peek(Token![self]) {
        let this = input.parse::<Token![self]>()?;
        if !input.peek(Token![.]) {
            let message = parameter_problem("self").unwrap_or_default();
            return Err(syn::Error::new(this.span, message));
        }
        input.parse::<Token![.]>()?;
        let name = parameter(input)?;
        state.fields.push(name.clone());
        return Ok(Value::Field(name.0));
    }
    if input.peek(Lit) {
        let lit: Lit = input.parse()?;
        let (digits, suffix) = match &lit {
            Lit::Int(i) => (i.base10_digits().to_string(), i.suffix()),
            Lit::Float(f) => (f.base10_digits().to_string(), f.suffix()),
            Lit::Str(_) => {
                return Err(syn::Error::new(
                    lit.span(),
                    "write the value without quotes (quotes are for description files)",
                ))
            }
            _ => {
                return Err(syn::Error::new(
                    lit.span(),
                    "expected a number, a struct field or an expression of them",
                ))
            }
        };
        if !suffix.is_empty() {
            return Err(syn::Error::new(lit.span(), suffix_message(&digits, suffix)));
        }
        let n = Number::parse_decimal(&digits)
            .or_else(|| digits.parse::<f64>().ok().map(Number::from_f64))
            .ok_or_else(|| syn::Error::new(lit.span(), "this number cannot be read"))?;
        if !n.to_f64().is_finite() {
            return Err(syn::Error::new(
                lit.span(),
                "this number is too large for an f64",
            ));
        }
        return Ok(Value::Num(n));
    }
    if input.peek(Ident::peek_any) {
        // `pi`, `q` and `q2` are the grammar's own; written raw (`r#pi`), they name fields.
        let text = input.fork().call(Ident::parse_any)?.to_string();
        let own = match text.as_str() {
            "pi" | "PI" => Some(Value::Pi),
            "q" => Some(Value::Joint(None)),
            _ => text
                .strip_prefix('q')
                .and_then(|d| d.parse::<usize>().ok())
                .map(|index| Value::Joint(Some(index))),
        };
        if let Some(value) = own {
            input.call(Ident::parse_any)?;
            return Ok(value);
        }
        let name = parameter(input)?;
        state.fields.push(name.clone());
        return Ok(Value::Field(name.0));
    }
    Err(input.error("expected a number, a struct field or an expression of them"))
}

/// A struct field's name and where it is written: an identifier, a keyword (Rust's field
/// `r#type`) or a raw identifier without its `r#`, but not a name no field can have (`Self`).
fn parameter(input: ParseStream) -> syn::Result<(String, Span)> {
    let ident = input.call(Ident::parse_any)?;
    let name = ident.unraw().to_string();
    match parameter_problem(&name) {
        Some(message) => Err(syn::Error::new(ident.span(), message)),
        None => Ok((name, ident.span())),
    }
}

/// Why a number may not have `suffix` (as in `2m`, `2.5f64`, `90deg`), and what to write.
fn suffix_message(digits: &str, suffix: &str) -> String {
    match suffix {
        "deg" | "rad" => format!(
            "write a space between the number and its unit: `{digits} {suffix}` (`{digits}{suffix}` \
             is one number with a type suffix)"
        ),
        "f32" | "f64" => format!(
            "write `{digits}` without the suffix `{suffix}`: values are exact numbers, converted \
             to the scalar type of each generated method"
        ),
        _ => format!(
            "`{digits}{suffix}`: a number takes no suffix; values are in SI units (m, kg, kg·m², \
             N·m/rad) and angles take `deg` or `rad` after a space"
        ),
    }
}

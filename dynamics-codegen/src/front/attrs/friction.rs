//! `friction = (viscous = f_v, coulomb = f_c, offset = f_0, smoothing = ε)` in a `link(...)`:
//! the joint's friction torque `f_v q̇ + f_c sign(q̇) + f_0`, with `f_c tanh(q̇ / ε)` in place of
//! the Coulomb term where `smoothing` is given. Every key is optional (zero; no smoothing).
//! Named keys rather than a tuple like `spring`'s: four numbers in a row would be easy to
//! misread, and most joints give only one or two of them.

use super::keys::FrictionKey;
use crate::front::errors::{unknown_key, Errors};
use crate::front::value::Spanned;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::{parenthesized, Ident, Token};

/// The values of `friction = (...)`, with the span of the parentheses.
pub(super) struct FrictionAttr {
    pub viscous: Option<Spanned>,
    pub coulomb: Option<Spanned>,
    pub offset: Option<Spanned>,
    pub smoothing: Option<Spanned>,
    pub span: Span,
}

/// Parses `(key = value, ...)` after `friction =`; an unknown or repeated key is an error
/// and parsing goes on.
pub(super) fn parse_friction(input: ParseStream, errors: &mut Errors) -> syn::Result<FrictionAttr> {
    if !input.peek(syn::token::Paren) {
        return Err(input.error(
            "expected `friction = (viscous = fv, coulomb = fc, offset = f0, smoothing = eps)`, \
             each key optional",
        ));
    }
    let content;
    let paren = parenthesized!(content in input);
    let mut friction = FrictionAttr {
        viscous: None,
        coulomb: None,
        offset: None,
        smoothing: None,
        span: paren.span.join(),
    };
    let mut unknown = None;
    while !content.is_empty() {
        let ident: Ident = content.parse()?;
        content.parse::<Token![=]>()?;
        let value: Spanned = content.parse()?;
        let slot = match FrictionKey::find(&ident) {
            Some(FrictionKey::Viscous) => &mut friction.viscous,
            Some(FrictionKey::Coulomb) => &mut friction.coulomb,
            Some(FrictionKey::Offset) => &mut friction.offset,
            Some(FrictionKey::Smoothing) => &mut friction.smoothing,
            None => {
                errors.push(
                    ident.span(),
                    unknown_key(&ident, "friction key", FrictionKey::NAMES),
                );
                &mut unknown
            }
        };
        if slot.is_some() {
            errors.push(
                ident.span(),
                format!("duplicate friction key `{ident}`: it is given earlier in this list"),
            );
        } else {
            *slot = Some(value);
        }
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok(friction)
}

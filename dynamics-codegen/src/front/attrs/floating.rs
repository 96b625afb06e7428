//! `base = floating` and `base = floating("trunk")`: a URDF robot on a free-flying base, its
//! root link (or the link named) the floating body; beside `base = "base_link"`, the link
//! fixed to the ground.

use super::entry::{string, Entry};
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::{parenthesized, Ident, LitStr, Token};

/// What `base = floating` says: where it is written, and the link named, if any.
pub(in crate::front) struct FloatingAttr {
    pub span: Span,
    pub link: Option<LitStr>,
}

/// The forms `base` takes, for messages.
const USAGE: &str = "`base = \"base_link\"` (the link fixed to the ground), `base = floating` \
                     (the root link flies free) or `base = floating(\"trunk\")`";

/// The value of `base` into the attributes' `base` and `floating`: a link's name, or a floating
/// base (whose link, if named, is also the base of the URDF's tree).
pub(super) fn parse_base(
    input: ParseStream,
    entry: &mut Entry,
    (base, floating): (&mut Option<LitStr>, &mut Option<FloatingAttr>),
) -> syn::Result<()> {
    if !input.peek(Ident) {
        let link = string(input, USAGE)?;
        entry.keep_first(base, link);
        return Ok(());
    }
    let ident: Ident = input.parse()?;
    if ident != "floating" {
        return Err(syn::Error::new(
            ident.span(),
            format!("unknown base `{ident}`: expected {USAGE}"),
        ));
    }
    let link = if input.peek(syn::token::Paren) {
        let content;
        parenthesized!(content in input);
        let link = string(&content, "`floating(\"trunk\")`, the floating body's link")?;
        content.parse::<Option<Token![,]>>()?;
        if !content.is_empty() {
            return Err(content.error("`floating(..)` takes one link's name"));
        }
        Some(link)
    } else {
        None
    };
    if let Some(link) = &link {
        entry.keep_first(base, link.clone());
    } else if base.is_some() || floating.is_some() {
        // The same error as any repeated key.
        entry.keep_first(&mut Some(()), ());
        return Ok(());
    }
    let span = ident.span();
    floating.get_or_insert(FloatingAttr { span, link });
    Ok(())
}

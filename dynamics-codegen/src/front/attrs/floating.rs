//! `base = floating` and `base = floating("trunk")`: a URDF robot on a free-flying base, its
//! root link (or the link named) the floating body; beside `base = "base_link"`, the link
//! fixed to the ground. A robot without a URDF (a D-H table, `joints = [..]`) gives the
//! floating body's inertia as a link's, `base = floating(mass = .., com = [..], inertia = [..])`
//! in its base frame (frame 0); a description file as its `[floating]` table.

use super::entry::{string, Entry};
use super::link::{parse_link, LinkAttr};
use super::reader::Reader;
use crate::front::errors::Errors;
use crate::front::fields::Field;
use crate::model::Link;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::{parenthesized, Ident, LitStr, Token};

/// What `base = floating` says: where it is written, and the link named, if any.
pub(in crate::front) struct FloatingAttr {
    pub span: Span,
    pub link: Option<LitStr>,
    /// `floating(mass = .., com = [..], inertia = [..])`: the body of a robot without a URDF.
    pub(super) body: Option<LinkAttr>,
}

impl FloatingAttr {
    /// Where `floating(mass = ..)` gives the body, if it does.
    pub(in crate::front) fn body_span(&self) -> Option<Span> {
        self.body.as_ref().map(|b| b.span.unwrap_or(self.span))
    }

    /// The body `floating(mass = .., com = [..], inertia = [..])` gives (its centre of mass
    /// and its inertia about it in the base frame, as a link's), each value checked where it
    /// is written; `None` without one.
    pub(in crate::front) fn body(&self, fields: &[Field], errors: &mut Errors) -> Option<Link> {
        let body = self.body.as_ref()?;
        let mut reader = Reader::new(fields, errors);
        if body.mass.is_none() && !body.unknown_key {
            let at = body.span.unwrap_or(self.span);
            reader
                .errors
                .push(at, "the floating body has no `mass = ..`");
        }
        let mass = reader.value(body.mass.as_ref());
        let com = body
            .com
            .as_ref()
            .map(|c| reader.values(c))
            .unwrap_or_default();
        let inertia = body
            .inertia
            .as_ref()
            .map(|(c, _)| reader.values(c))
            .unwrap_or_default();
        Some(Link {
            mass,
            com,
            inertia,
            ..Link::default()
        })
    }
}

/// The forms `base` takes, for messages.
const USAGE: &str = "`base = \"base_link\"` (the link fixed to the ground), `base = floating` \
                     (the root link flies free), `base = floating(\"trunk\")` or, without a \
                     URDF, `base = floating(mass = .., com = [..], inertia = [..])`";

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
    let (mut link, mut body) = (None, None);
    if input.peek(syn::token::Paren) {
        let content;
        let paren = parenthesized!(content in input);
        if content.peek(Ident) {
            let read = parse_link(&content, paren.span.open(), entry.errors)?;
            refuse_joint_terms(&read, entry);
            body = Some(read);
        } else {
            link = Some(string(
                &content,
                "`floating(\"trunk\")`, the floating body's link",
            )?);
            content.parse::<Option<Token![,]>>()?;
            if !content.is_empty() {
                return Err(content.error("`floating(..)` takes one link's name"));
            }
        }
    }
    if let Some(link) = &link {
        entry.keep_first(base, link.clone());
    } else if base.is_some() || floating.is_some() {
        // The same error as any repeated key.
        entry.keep_first(&mut Some(()), ());
        return Ok(());
    }
    let span = ident.span();
    floating.get_or_insert(FloatingAttr { span, link, body });
    Ok(())
}

/// A floating body has no joint: a joint's keys in `floating(..)` are errors on their value.
fn refuse_joint_terms(body: &LinkAttr, entry: &mut Entry) {
    let given = [
        (
            "actuator_inertia",
            body.actuator_inertia.as_ref().map(|v| v.span),
        ),
        ("spring", body.spring.as_ref().map(|(k, _)| k.span)),
        ("rotor_inertia", body.rotor_inertia.as_ref().map(|v| v.span)),
        ("gear_ratio", body.gear_ratio.as_ref().map(|v| v.span)),
        ("friction", body.friction.as_ref().map(|f| f.span)),
    ];
    for (key, span) in given {
        if let Some(span) = span {
            entry.errors.push(span, format!("`{key}` has no meaning on a floating body (it has no joint): `floating(..)` takes `mass`, `com`, `inertia` and `check_inertia`"));
        }
    }
}

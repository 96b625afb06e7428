//! One `link(mass = .., com = [..], inertia = [..], ..)` entry read into [`LinkAttr`], still as
//! tokens: of a joint in the attribute, and of the floating body in `base = floating(..)`.

use super::entry::{boolean, parse_spring, skip_entry, values, Entry};
use super::friction::{parse_friction, FrictionAttr};
use super::keys::LinkKey;
use crate::front::errors::{unknown_key, Errors};
use crate::front::value::Spanned;
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::{Ident, Token};

/// What the keys of `link(...)` are called in messages.
const LINK_ATTRIBUTE: &str = "link attribute";
/// What `check_inertia` does, for an error in its value.
pub(super) const KEEP: &str =
    "`check_inertia = false` keeps an inertia tensor that fails the physical checks";

/// The keys of one `link(...)`.
#[derive(Default)]
pub(super) struct LinkAttr {
    /// The `link` keyword.
    pub span: Option<Span>,
    pub mass: Option<Spanned>,
    pub com: Option<[Spanned; 3]>,
    /// The six values and the span of their brackets.
    pub inertia: Option<([Spanned; 6], Span)>,
    pub actuator_inertia: Option<Spanned>,
    pub spring: Option<(Spanned, Spanned)>,
    pub check_inertia: Option<bool>,
    pub friction: Option<FrictionAttr>,
    pub rotor_inertia: Option<Spanned>,
    pub gear_ratio: Option<Spanned>,
    /// Whether an unknown key was given (perhaps a misspelt `mass`).
    pub unknown_key: bool,
}

/// Parses the keys of one `link(...)`, whose keyword is at `span`.
pub(super) fn parse_link(
    input: ParseStream,
    span: Span,
    errors: &mut Errors,
) -> syn::Result<LinkAttr> {
    let mut link = LinkAttr {
        span: Some(span),
        ..LinkAttr::default()
    };
    while !input.is_empty() {
        let ident: Ident = input.parse()?;
        if let Some(key) = LinkKey::find(&ident) {
            input.parse::<Token![=]>()?;
            parse_link_attr(input, key, &ident, &mut link, errors)?;
        } else {
            let message = unknown_key(&ident, LINK_ATTRIBUTE, LinkKey::NAMES);
            errors.push(ident.span(), message);
            link.unknown_key = true;
            skip_entry(input)?;
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(link)
}

/// Parses the value after `key =` (written as `ident`) into its slot of `link`.
fn parse_link_attr(
    input: ParseStream,
    key: LinkKey,
    ident: &Ident,
    link: &mut LinkAttr,
    errors: &mut Errors,
) -> syn::Result<()> {
    let mut entry = Entry {
        ident,
        what: LINK_ATTRIBUTE,
        errors,
    };
    match key {
        LinkKey::Mass => entry.keep_first(&mut link.mass, input.parse()?),
        LinkKey::Com => {
            let (com, _) = values::<3>(input, "`com = [x, y, z]`")?;
            entry.keep_first(&mut link.com, com);
        }
        LinkKey::Inertia => {
            let inertia = values::<6>(input, "`inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`")?;
            entry.keep_first(&mut link.inertia, inertia);
        }
        LinkKey::ActuatorInertia => entry.keep_first(&mut link.actuator_inertia, input.parse()?),
        LinkKey::Spring => entry.keep_first(&mut link.spring, parse_spring(input)?),
        LinkKey::CheckInertia => entry.keep_first(&mut link.check_inertia, boolean(input, KEEP)?),
        LinkKey::Friction => {
            let friction = parse_friction(input, entry.errors)?;
            entry.keep_first(&mut link.friction, friction);
        }
        LinkKey::RotorInertia => entry.keep_first(&mut link.rotor_inertia, input.parse()?),
        LinkKey::GearRatio => entry.keep_first(&mut link.gear_ratio, input.parse()?),
    }
    Ok(())
}

//! The attribute parser: the keys of `#[dynamics(...)]` and of its `link(...)` entries read
//! into [`Attrs`], still as tokens with their spans. An unknown or repeated key is an error
//! and parsing goes on with the next key, so that one build reports every mistake.

use super::entry::{
    boolean, parse_convention, parse_dh, skip_entry, string, strings, values, DhRowAttr, Entry,
};
use super::floating::{parse_base, FloatingAttr};
use super::joints::{parse_joints, JointAttr};
use super::keys::Key;
use super::link::{parse_link, LinkAttr, KEEP};
use super::simplify::parse_simplify;
use crate::front::errors::{unknown_key, Errors};
use crate::front::simplify::given::Given;
use crate::front::value::Spanned;
use crate::method::{Family, FamilySet};
use crate::model::Convention;
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::parse::ParseStream;
use syn::{parenthesized, Ident, LitStr, Token};

/// The keys of every `#[dynamics(...)]` of the input.
#[derive(Default)]
pub(in crate::front) struct Attrs {
    pub file: Option<LitStr>,
    pub krate: Option<syn::Path>,
    pub convention: Option<(Convention, Span)>,
    pub gravity: Option<[Spanned; 3]>,
    /// The rows and the span of the table's brackets.
    pub(super) dh: Option<(Vec<DhRowAttr>, Span)>,
    /// The joints given by placements and axes, and the span of the list's brackets.
    pub(super) joints: Option<(Vec<JointAttr>, Span)>,
    pub(super) links: Vec<LinkAttr>,
    pub name: Option<LitStr>,
    /// `check_inertia = false` for every link (or every joint of the file).
    pub check_inertia: Option<bool>,
    /// `urdf = "..."`, and the links of the chain it takes: `base = ".."`, `tip = ".."`, or of
    /// the tree: `tips = ["..", ..]` (with the span of its brackets).
    pub urdf: Option<LitStr>,
    pub base: Option<LitStr>,
    /// `base = floating` or `base = floating("trunk")` (whose link is `base` too).
    pub floating: Option<FloatingAttr>,
    pub tip: Option<LitStr>,
    pub tips: Option<(Vec<LitStr>, Span)>,
    /// `tool = [x, y, z, roll, pitch, yaw]`: the tool frame in link frame n.
    pub tool: Option<[Spanned; 6]>,
    /// `contacts = true`: a floating base's contact terms traced in closed form.
    pub contacts: Option<syn::LitBool>,
    /// `derivatives = true` and the like: the opt-in families asked for, or refused.
    pub families: BTreeMap<Family, bool>,
    /// `simplify(...)`: the pruned models' request (which also asks for their family).
    pub simplify: Option<Given<Span>>,
}

impl Attrs {
    /// The families the robot has: the opt-in ones it asks for, and every other.
    pub(in crate::front) fn families(&self) -> FamilySet {
        let asked = self.families.iter().filter(|(_, &asked)| asked);
        asked.fold(FamilySet::default(), |set, (&f, _)| set.with(f))
    }

    /// The number of joints of the D-H table or the joint list, if one was read.
    pub(in crate::front) fn joint_count(&self) -> Option<usize> {
        let rows = self.dh.as_ref().map(|(rows, _)| rows.len());
        rows.or_else(|| self.joints.as_ref().map(|(joints, _)| joints.len()))
    }

    /// Whether the attribute gives `key`, one of the keys a description file or a URDF
    /// replaces.
    fn gives(&self, key: &str) -> bool {
        match key {
            "file" => self.file.is_some(),
            "gravity" => self.gravity.is_some(),
            "dh" => self.dh.is_some(),
            "joints" => self.joints.is_some(),
            "link" => !self.links.is_empty(),
            "convention" => self.convention.is_some(),
            "tool" => self.tool.is_some(),
            _ => unreachable!("not a key of the robot's description: {key}"),
        }
    }

    /// An error on the `source` string for each of `keys` the attribute also gives, since
    /// the source describes the whole robot; `hint` adds to a key's message.
    pub(in crate::front) fn refuse_beside(
        &self,
        source: &Source,
        keys: &[&str],
        hint: fn(&str) -> &'static str,
        errors: &mut Errors,
    ) {
        let Source {
            key: name,
            at,
            called,
        } = source;
        for key in keys.iter().filter(|key| self.gives(key)) {
            errors.push(
                at.span(),
                format!(
                    "`{key}` cannot be combined with `{name}`: {called} describes the whole robot{}",
                    hint(key)
                ),
            );
        }
    }
}

impl Attrs {
    /// `base = ".."`, `tip = ".."` and `tips = [..]` name links of a URDF file: an error on
    /// each without `urdf`.
    pub(in crate::front) fn refuse_chain_without_urdf(&self, errors: &mut Errors) {
        let tips = self.tips.as_ref().map(|(_, span)| *span);
        let given = [("base", &self.base), ("tip", &self.tip)]
            .map(|(key, literal)| (key, "a link", literal.as_ref().map(LitStr::span)));
        for (key, what, span) in given.into_iter().chain([("tips", "links", tips)]) {
            if let Some(span) = span {
                errors.push(
                    span,
                    format!("`{key}` names {what} of a URDF file: give the file with `urdf = \"robots/arm.urdf\"`"),
                );
            }
        }
    }

    /// The `tips` named, as strings; an error at the list where `tip` is given too (a serial
    /// chain or a tree: one of them) or the list is empty.
    pub(in crate::front) fn tip_names(&self, errors: &mut Errors) -> Option<Vec<String>> {
        let (tips, span) = self.tips.as_ref()?;
        if self.tip.is_some() {
            errors.push(*span, "`tips` cannot be combined with `tip`: `tip` takes the serial path to one link, `tips` the branches to several; give one");
        } else if tips.is_empty() {
            errors.push(*span, "`tips` is empty: name the links the branches lead to, e.g. `tips = [\"left_hand\", \"right_hand\"]`, or leave it out to take every branch");
        }
        Some(tips.iter().map(LitStr::value).collect())
    }
}

/// A description of the whole robot named in the attribute: `file = ".."` or `urdf = ".."`.
pub(in crate::front) struct Source<'a> {
    /// Its key, `file` or `urdf`.
    pub key: &'static str,
    /// The string naming it.
    pub at: &'a LitStr,
    /// What messages call it, `the file`.
    pub called: &'static str,
}

/// What the keys of `#[dynamics(...)]` are called in messages.
const ATTRIBUTE: &str = "dynamics attribute";
/// The error for `dh` and `joints` both given, on the second.
const BOTH_TABLES: &str = "`dh` and `joints` cannot be combined: give the joints either as a \
                           D-H table (`dh = [[θ, d, a, α], ...]`) or by placements and axes \
                           (`joints = [revolute(xyz = [..], rpy = [..], axis = [..]), ...]`)";

/// What `contacts` does, for an error in its value.
const CONTACTS: &str = "`contacts = true` traces a floating base's contact terms (`FloatingContactTerms`) in closed form";

/// Parses the keys of one `#[dynamics(...)]` into `attrs`.
pub(in crate::front) fn parse_attrs(
    input: ParseStream,
    attrs: &mut Attrs,
    errors: &mut Errors,
) -> syn::Result<()> {
    while !input.is_empty() {
        let ident: Ident = if input.peek(Token![crate]) {
            let k: Token![crate] = input.parse()?;
            Ident::new("crate", k.span)
        } else {
            input.parse()?
        };
        if let Some(key) = Key::find(&ident) {
            parse_attr(input, key, &ident, attrs, errors)?;
        } else if ident == Family::Simplified.name() {
            let given = parse_simplify(input, &ident, errors)?;
            if attrs.simplify.is_some() {
                errors.push(
                    ident.span(),
                    "duplicate `simplify`: it is given earlier in this attribute",
                );
            } else {
                attrs.simplify = Some(given);
                attrs.families.insert(Family::Simplified, true);
            }
        } else if let Some(family) = opt_in_family(&ident) {
            parse_family(input, family, &ident, attrs, errors)?;
        } else {
            let known = Key::NAMES.iter().copied().chain(Family::opt_in_names());
            let known: Vec<&str> = known.collect();
            errors.push(ident.span(), unknown_key(&ident, ATTRIBUTE, &known));
            skip_entry(input)?;
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(())
}

/// The opt-in family `ident` names, whose key asks for it (`derivatives = true`).
fn opt_in_family(ident: &Ident) -> Option<Family> {
    Family::from_name(&ident.to_string()).filter(|f| f.is_opt_in())
}

/// Parses `= true` or `= false` after the name of an opt-in family.
fn parse_family(
    input: ParseStream,
    family: Family,
    ident: &Ident,
    attrs: &mut Attrs,
    errors: &mut Errors,
) -> syn::Result<()> {
    input.parse::<Token![=]>()?;
    let usage = format!("`{ident} = true` also implements `{}`", family.trait_name());
    let mut asked = attrs.families.get(&family).copied();
    let mut entry = Entry {
        ident,
        what: ATTRIBUTE,
        errors,
    };
    entry.keep_first(&mut asked, boolean(input, &usage)?);
    attrs.families.insert(family, asked.unwrap_or_default());
    Ok(())
}

/// Parses what follows `key` (written as `ident`) into its slot of `attrs`.
fn parse_attr(
    input: ParseStream,
    key: Key,
    ident: &Ident,
    attrs: &mut Attrs,
    errors: &mut Errors,
) -> syn::Result<()> {
    if key == Key::Link {
        if !input.peek(syn::token::Paren) {
            return Err(input
                .error("expected `link(mass = .., com = [..], inertia = [..])`, one per joint"));
        }
        let content;
        parenthesized!(content in input);
        attrs
            .links
            .push(parse_link(&content, ident.span(), errors)?);
        return Ok(());
    }
    input.parse::<Token![=]>()?;
    let mut entry = Entry {
        ident,
        what: ATTRIBUTE,
        errors,
    };
    match key {
        Key::File => entry.keep_first(
            &mut attrs.file,
            string(input, "`file = \"robots/arm.toml\"`")?,
        ),
        Key::Urdf => entry.keep_first(
            &mut attrs.urdf,
            string(input, "`urdf = \"robots/arm.urdf\"`")?,
        ),
        Key::Base => parse_base(input, &mut entry, (&mut attrs.base, &mut attrs.floating))?,
        Key::Tip => entry.keep_first(&mut attrs.tip, string(input, "`tip = \"tool0\"`")?),
        Key::Tips => entry.keep_first(
            &mut attrs.tips,
            strings(input, "`tips = [\"left_hand\", \"right_hand\"]`")?,
        ),
        Key::Name => entry.keep_first(&mut attrs.name, string(input, "`name = \"arm\"`")?),
        Key::Crate => {
            let path = string(input, "`crate = \"path::to::dynamics_runtime\"`")?.parse()?;
            entry.keep_first(&mut attrs.krate, path);
        }
        Key::Convention => entry.keep_first(&mut attrs.convention, parse_convention(input)?),
        Key::Gravity => {
            let (gravity, _) = values::<3>(input, "`gravity = [gx, gy, gz]`")?;
            entry.keep_first(&mut attrs.gravity, gravity);
        }
        Key::CheckInertia => entry.keep_first(&mut attrs.check_inertia, boolean(input, KEEP)?),
        Key::Dh => {
            let dh = parse_dh(input)?;
            if attrs.joints.is_some() {
                entry.errors.push(ident.span(), BOTH_TABLES);
            } else {
                entry.keep_first(&mut attrs.dh, dh);
            }
        }
        Key::Joints => {
            let joints = parse_joints(input, entry.errors)?;
            if attrs.dh.is_some() {
                entry.errors.push(ident.span(), BOTH_TABLES);
            } else {
                entry.keep_first(&mut attrs.joints, joints);
            }
        }
        Key::Contacts => {
            let contacts = if input.peek(syn::LitBool) {
                input.parse::<syn::LitBool>()?
            } else {
                return Err(input.error(format!("expected `true` or `false`: {CONTACTS}")));
            };
            entry.keep_first(&mut attrs.contacts, contacts);
        }
        Key::Tool => {
            let (tool, _) = values::<6>(input, "`tool = [x, y, z, roll, pitch, yaw]`")?;
            entry.keep_first(&mut attrs.tool, tool);
        }
        // Read above: a `link(...)` has no `=`.
        Key::Link => {}
    }
    Ok(())
}

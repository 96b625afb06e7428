//! The derive's front end: `#[dynamics(...)]` attributes (or the description file they name)
//! parsed into a [`Robot`], with every error kept on the span of the token that caused it.
//!
//! ```text
//! #[dynamics(
//!     gravity = [0, 0, -9.81],
//!     dh = [
//!         //  θ         d          a         α
//!         [   q,        0.6718,    0,        90 deg ],
//!         [   q,        0,         0.4318,   0      ],
//!     ],
//!     link(mass = 0, inertia = [0, 0.35, 0, 0, 0, 0]),
//!     link(mass = 17.4, com = [-0.3638, 0.006, 0.2275], inertia = [0.13, 0.524, 0.539, 0, 0, 0]),
//! )]
//! ```
//!
//! The D-H table's columns are in the order of `A_i = Rot(z,θ) Trans(0,0,d) Trans(a,0,0)
//! Rot(x,α)`; the joint variable `q` (or `qN` in row N) in the θ cell makes the joint revolute,
//! in the d cell prismatic, with an optional constant offset (`q + 90 deg`).
//!
//! The steps, one module each: `attr` reads the attributes (by the keys of `symbol`, each
//! value by `attr_value`) into tokens with their spans; `from_attrs` builds the syn-free
//! [`Robot`] from them, or `from_file` from the description file they name (read by `file`,
//! also for the command-line tool: [`load`]); values follow the grammar of `value`
//! ([`parse_value`]), and angles written as plain numbers above 2π are refused by `angle`. Every error goes to one [`Errors`] and all are reported together.

mod angle;
mod attr;
mod attr_joints;
mod attr_value;
mod errors;
mod fields;
mod file;
mod friction_attr;
mod from_attrs;
mod from_file;
mod from_joints;
mod from_urdf;
mod symbol;
mod urdf;
mod value;

pub use errors::Errors;
pub use fields::{struct_fields, Field};
pub use file::{from_json, from_text, from_toml, load, FileError, Loaded, Positions};
pub use symbol::attribute_words;
pub use urdf::{load_urdf, Chain};
pub use value::{parse_spanned, parse_value, Spanned, Unitless};

use crate::method::FamilySet;
use crate::model::Robot;
use attr::{parse_attrs, Attrs};
use syn::parse::ParseStream;

/// What the derive input says.
pub struct Input {
    /// The robot.
    pub robot: Robot,
    /// The runtime crate's path (`crate = "..."`), default `::dynamics_runtime`.
    pub krate: Option<syn::Path>,
    /// A description file to track for rebuilds (absolute path).
    pub tracked_file: Option<String>,
    /// The families to implement: the opt-in ones asked for (`derivatives = true`), and
    /// every other.
    pub families: FamilySet,
}

/// Why the derive input gave no robot.
pub struct Failure {
    /// Every error found, each on its own span.
    pub error: syn::Error,
    /// The number of joints, where the table was read that far: the fallback expansion then
    /// still implements the trait, so that the user sees these errors and not a cascade.
    pub dof: Option<usize>,
    /// The runtime crate's path, if `crate = "..."` was read.
    pub krate: Option<syn::Path>,
    /// The families asked for, as far as read: the fallback then implements their traits
    /// too.
    pub families: FamilySet,
}

/// The `#[dynamics(...)]` attributes of the input.
struct ReadAttrs {
    attrs: Attrs,
    /// Whether the input has any.
    seen: bool,
    /// Whether one had a syntax error: what follows it is unknown, so no key is missing.
    parse_failed: bool,
}

/// Parses the derive input into a robot; every error found is returned together.
///
/// # Errors
/// The combined errors, each on its own span, and the number of joints if known.
pub fn parse(input: &syn::DeriveInput) -> Result<Input, Failure> {
    let mut errors = Errors::default();
    let read = read_attrs(input, &mut errors);
    let fields = struct_fields(input);
    if !matches!(input.data, syn::Data::Struct(_)) {
        errors.push(
            input.ident.span(),
            "`Dynamics` can only be derived for a struct",
        );
    }
    if !read.seen {
        errors.push(
            input.ident.span(),
            "missing `#[dynamics(...)]`: give the D-H table with `gravity = [..]`, `dh = [..]` and \
             one `link(..)` per joint, `file = \"robot.json\"` or `urdf = \"robot.urdf\"`",
        );
    }
    let mut tracked_file = None;
    let robot = robot(input, &read, &fields, &mut errors, &mut tracked_file);
    finish(input, read.attrs, errors, robot, tracked_file)
}

/// Reads every `#[dynamics(...)]` of the input into one [`Attrs`].
fn read_attrs(input: &syn::DeriveInput, errors: &mut Errors) -> ReadAttrs {
    let mut read = ReadAttrs {
        attrs: Attrs::default(),
        seen: false,
        parse_failed: false,
    };
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("dynamics")) {
        read.seen = true;
        let parsed = attr.parse_args_with(|s: ParseStream| parse_attrs(s, &mut read.attrs, errors));
        if let Err(e) = parsed {
            errors.push_error(e);
            read.parse_failed = true;
        }
    }
    read
}

/// The robot the description file or the attributes describe, where they could be read.
fn robot(
    input: &syn::DeriveInput,
    read: &ReadAttrs,
    fields: &[Field],
    errors: &mut Errors,
    tracked_file: &mut Option<String>,
) -> Option<Robot> {
    let attrs = &read.attrs;
    if let Some(urdf) = &attrs.urdf {
        return from_urdf::robot_from_urdf(urdf, attrs, fields, errors, tracked_file);
    }
    from_urdf::chain_without_urdf(attrs, errors);
    if let Some(file) = &attrs.file {
        let source = attr::Source {
            key: "file",
            at: file,
            called: "the file",
        };
        let keys = ["gravity", "dh", "joints", "link", "convention", "tool"];
        attrs.refuse_beside(&source, &keys, |_| "", errors);
        let checked = attrs.check_inertia.unwrap_or(true);
        from_file::robot_from_file(file, checked, fields, errors, tracked_file)
    } else if read.parse_failed || !read.seen {
        None
    } else {
        Some(from_attrs::robot_from_attrs(attrs, input, fields, errors))
    }
}

/// The robot, or every error with what the fallback expansion needs.
fn finish(
    input: &syn::DeriveInput,
    attrs: Attrs,
    errors: Errors,
    robot: Option<Robot>,
    tracked_file: Option<String>,
) -> Result<Input, Failure> {
    let families = attrs.families();
    match (errors.combine(), robot) {
        (None, Some(mut robot)) => {
            if let Some(name) = &attrs.name {
                robot.name = name.value();
            }
            Ok(Input {
                robot,
                krate: attrs.krate,
                tracked_file,
                families,
            })
        }
        (Some(error), robot) => Err(Failure {
            error,
            dof: robot
                .map(|r| r.dof())
                .or_else(|| attrs.dh.as_ref().map(|(rows, _)| rows.len()))
                .or_else(|| attrs.joints.as_ref().map(|(joints, _)| joints.len()))
                .filter(|n| *n > 0),
            families,
            krate: attrs.krate,
        }),
        (None, None) => Err(Failure {
            error: syn::Error::new(input.ident.span(), "no robot description"),
            dof: None,
            families,
            krate: attrs.krate,
        }),
    }
}

/// Parses `#[dynamics(...)]` from text, for tests and tools.
///
/// # Errors
/// The parse error.
pub fn parse_str(text: &str) -> syn::Result<Input> {
    let input: syn::DeriveInput = syn::parse_str(text)?;
    parse(&input).map_err(|f| f.error)
}

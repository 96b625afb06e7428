//! The derive's front end: `#[dynamics(...)]` attributes, or the description file or URDF file
//! they name, lowered to a syn-free [`Robot`], with every error on the span of the token that
//! caused it (or at the line and column of the file, in the message on the string naming it).
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
//! The pipeline, as [`parse`] runs it:
//!
//! 1. **Read**: `attrs` reads every `#[dynamics(...)]` into tokens with their spans.
//! 2. **Lower, by input kind**, one folder each: `attrs` (the D-H table or joint list of the
//!    attribute), `file` (a JSON or TOML description file, [`load`]) or `urdf` (a chain of a
//!    URDF file, [`load_urdf`]), the last two reached from the derive through `named_file`.
//!    Each gives a [`Robot`] and a table of where each of its values came from
//!    ([`Sources`]: tokens of the attribute, or lines and columns of the file), and reports
//!    what it alone can see: syntax, unknown keys, values (their grammar in `value`, their
//!    angles in `angle`, the struct fields they name in `fields`), joints given by frames
//!    that have no D-H table, and the values the model does not keep (a rotor and gear
//!    ratio before they become an actuator inertia, each URDF link before fixed links merge).
//! 3. **Check**: one pass of [`check::robot`] for every input, each problem placed through the
//!    table on the value it concerns (as thiserror's `valid.rs` runs after its `ast.rs`).
//!
//! Every error goes to one [`Errors`] and all are reported together. The command-line tool
//! runs steps 2 and 3 on its files, with the same table ([`Loaded::describe`]).

#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod angle;
mod attrs;
mod errors;
mod fields;
mod file;
mod floating;
mod floating_frames;
mod named_file;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod parent;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod simplify;
mod sources;
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub mod urdf;
mod value;

pub use attrs::attribute_words;
pub use errors::{Errors, FileError};
pub use fields::{struct_fields, Field};
pub use file::{from_json, from_text, from_toml, load};
pub use floating::joint_terms_refusal as floating_joint_terms_refusal;
pub use floating::unsupported as floating_unsupported;
pub use simplify::given::{default_joint as default_envelope, Given, KEYS as SIMPLIFY_KEYS};
pub use simplify::{FileRequest, RequestError};
pub use sources::{At, Loaded, Lowered, Positions, Sources, Tokens};
pub use urdf::{free_flyer, joint_limits, load_urdf, Chain, Limit};
pub use value::{parse_spanned, parse_value, Spanned, Unitless};

use crate::check::{self, Problem};
use crate::method::FamilySet;
use crate::model::{FreeFlyer, Robot, Simplification};
use attrs::{parse_attrs, Attrs, Source};
use named_file::Named;
use syn::parse::ParseStream;
use syn::LitStr;

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
    /// `simplify(...)`, resolved: the pruned models' tolerances and envelope.
    pub simplify: Option<Simplification>,
    /// `base = floating`: the free-flying base the robot's tree hangs from.
    pub floating: Option<FreeFlyer>,
    /// `contacts = true`: the floating base's contact terms in closed form, not at run time.
    pub contact_terms: bool,
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
    /// The tips' names where known (the robot's, else the derive's `tips = [..]` as written):
    /// the fallback then names them too (`TIP_NAMES`, `TIP_<NAME>`).
    pub tip_names: Option<Box<[String]>>,
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
    let lowered = lower(input, &read, &fields, &mut errors, &mut tracked_file);
    let simplify = lowered.as_ref().and_then(|lowered| {
        let attr = read.attrs.simplify.as_ref();
        simplify::request(attr, lowered.simplify.as_ref(), &lowered.robot, &mut errors)
    });
    let mut file_body = None;
    let robot = lowered.map(|lowered| {
        check(&lowered, &mut errors);
        file_body = lowered.floating;
        lowered.robot
    });
    let given = floating::Given {
        tracked_file: tracked_file.as_deref(),
        file_body,
        fields: &fields,
    };
    let floating = floating::free_flyer(&read.attrs, given, robot.as_ref(), &mut errors);
    let read = Read {
        attrs: read.attrs,
        simplify,
        floating,
    };
    finish(input, read, errors, robot, tracked_file)
}

/// The attributes read, and `simplify(...)` resolved for the robot.
struct Read {
    attrs: Attrs,
    simplify: Option<Simplification>,
    floating: Option<FreeFlyer>,
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

/// How a problem of the checks is told where the input gives the value: on which tokens, in
/// which words (the attribute says `link 2`, a file `path:line:col: joint 2`).
type Tell<'a> = Box<dyn Fn(&Problem) -> (Tokens, String) + 'a>;

/// A robot lowered from the derive input, and how the checks' problems are told there.
struct Derived<'a> {
    robot: Robot,
    check_inertia: Vec<bool>,
    tell: Tell<'a>,
    /// A file's `[simplify]` and a URDF's joint limits.
    simplify: Option<simplify::FromFile<'a>>,
    /// A description file's `[floating]` body, and its gravity as written.
    floating: Option<FreeFlyer>,
}

impl<'a> Derived<'a> {
    /// The robot of the file that the string `at` names.
    fn named(at: &'a LitStr, named: Named) -> Derived<'a> {
        let Named {
            loaded,
            path,
            limits,
        } = named;
        let Lowered {
            robot,
            check_inertia,
            sources,
            simplify,
            floating,
        } = loaded;
        let simplify = simplify::FromFile {
            request: FileRequest {
                given: simplify,
                limits,
                path: path.clone(),
            },
            at,
        };
        Derived {
            robot,
            check_inertia,
            tell: Box::new(move |problem| named_file::tell(at, &path, &sources, problem)),
            simplify: Some(simplify),
            floating,
        }
    }
}

/// The one check pass, the same for every input: each problem of [`check::robot`] told on the
/// value it concerns.
fn check(lowered: &Derived, errors: &mut Errors) {
    for problem in check::robot(&lowered.robot, &lowered.check_inertia) {
        let ((start, end), message) = (lowered.tell)(&problem);
        errors.push_range(start, end, message);
    }
}

/// The robot the URDF file, the description file or the attributes describe, lowered by its
/// kind, where they could be read.
fn lower<'a>(
    input: &syn::DeriveInput,
    read: &'a ReadAttrs,
    fields: &[Field],
    errors: &mut Errors,
    tracked_file: &mut Option<String>,
) -> Option<Derived<'a>> {
    let attrs = &read.attrs;
    if let Some(urdf) = &attrs.urdf {
        let source = Source {
            key: "urdf",
            at: urdf,
            called: "the URDF file",
        };
        let keys = ["file", "dh", "joints", "link", "convention", "tool"];
        attrs.refuse_beside(&source, &keys, tool_hint, errors);
        let (base, tip) = (
            attrs.base.as_ref().map(LitStr::value),
            attrs.tip.as_ref().map(LitStr::value),
        );
        let named_tips = attrs.tip_names(errors).unwrap_or_default();
        let (every_branch, frames) = floating_frames::every_branch(attrs, urdf, &named_tips);
        let tips: Vec<&str> = every_branch.iter().map(String::as_str).collect();
        let chain = Chain {
            base: base.as_deref(),
            tip: tip.as_deref(),
            // Both given: refused at the list; the path to the tip is read.
            tips: if tip.is_some() { &[] } else { &tips },
        };
        let checked = attrs.check_inertia.unwrap_or(true);
        let gravity = attrs.gravity.as_ref();
        let request = named_file::UrdfRequest {
            chain,
            base: attrs.base.as_ref(),
            tip: attrs.tip.as_ref(),
            tips: attrs.tips.as_ref().map_or(&[], |(tips, _)| tips.as_slice()),
        };
        let named = named_file::robot_from_urdf(
            urdf,
            &request,
            checked,
            gravity,
            fields,
            errors,
            tracked_file,
        );
        return named.map(|mut named| {
            // The leaves asked for beside a floating base's frames are not frames.
            if let Some(frames) = frames {
                named.loaded.robot.tips.truncate(frames);
            }
            Derived::named(urdf, named)
        });
    }
    attrs.refuse_chain_without_urdf(errors);
    if let Some(file) = &attrs.file {
        let source = Source {
            key: "file",
            at: file,
            called: "the file",
        };
        let keys = ["gravity", "dh", "joints", "link", "convention", "tool"];
        attrs.refuse_beside(&source, &keys, |_| "", errors);
        let checked = attrs.check_inertia.unwrap_or(true);
        let named = named_file::robot_from_file(file, checked, fields, errors, tracked_file);
        named.map(|named| Derived::named(file, named))
    } else if read.parse_failed || !read.seen {
        None
    } else {
        let (lowered, counted) = attrs::lower(attrs, input, fields, errors);
        let Lowered {
            robot,
            check_inertia,
            sources,
            ..
        } = lowered;
        Some(Derived {
            robot,
            check_inertia,
            tell: Box::new(move |problem| attrs::tell(&sources, counted, problem)),
            simplify: None,
            floating: None,
        })
    }
}

/// Why `tool` is refused beside a URDF.
fn tool_hint(key: &str) -> &'static str {
    if key == "tool" {
        " (its `tip` link is the hand frame: choose the tip)"
    } else {
        ""
    }
}

/// The robot, or every error with what the fallback expansion needs.
fn finish(
    input: &syn::DeriveInput,
    read: Read,
    errors: Errors,
    robot: Option<Robot>,
    tracked_file: Option<String>,
) -> Result<Input, Failure> {
    let Read {
        attrs,
        simplify,
        floating,
    } = read;
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
                simplify,
                floating,
                contact_terms: attrs.contacts.as_ref().is_some_and(|c| c.value),
            })
        }
        (Some(error), robot) => Err(Failure {
            error,
            tip_names: robot
                .as_ref()
                .filter(|r| r.is_tree())
                .map(|r| r.tip_frames().into_iter().map(|t| t.name).collect())
                .or_else(|| {
                    let (tips, _) = attrs.tips.as_ref()?;
                    Some(tips.iter().map(LitStr::value).collect())
                }),
            dof: robot
                .as_ref()
                .map(Robot::dof)
                .or_else(|| attrs.joint_count())
                .filter(|n| *n > 0),
            // A tree's calls of its tips' methods compile too (for any number of tips).
            families: if attrs.tips.is_some() || robot.as_ref().is_some_and(Robot::is_tree) {
                families.with(crate::method::Family::Tips)
            } else {
                families
            },
            krate: attrs.krate,
        }),
        (None, None) => Err(Failure {
            error: syn::Error::new(input.ident.span(), "no robot description"),
            dof: None,
            tip_names: None,
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

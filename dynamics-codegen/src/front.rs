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

use crate::check::{self, Part};
use crate::model::{self, Convention, Joint, JointKind, Robot, Spanned, Spring, Value};
use proc_macro2::Span;
use syn::parse::ParseStream;
use syn::punctuated::Punctuated;
use syn::{bracketed, parenthesized, Ident, LitStr, Token};

/// What the derive input says.
pub struct Input {
    /// The robot.
    pub robot: Robot,
    /// The runtime crate's path (`crate = "..."`), default `::dynamics_runtime`.
    pub krate: Option<syn::Path>,
    /// A description file to track for rebuilds (absolute path).
    pub tracked_file: Option<String>,
}

#[derive(Default)]
struct LinkAttr {
    span: Option<Span>,
    mass: Option<Spanned>,
    com: Option<[Spanned; 3]>,
    /// The six values and the span of their brackets.
    inertia: Option<([Spanned; 6], Span)>,
    actuator_inertia: Option<Spanned>,
    spring: Option<(Spanned, Spanned)>,
    check_inertia: Option<bool>,
    /// Whether an unknown key was given (perhaps a misspelt `mass`).
    unknown_key: bool,
}

/// A D-H row `[θ, d, a, α]` with the span of its first token.
type DhRowAttr = (Span, [Spanned; 4]);

#[derive(Default)]
struct Attrs {
    file: Option<LitStr>,
    krate: Option<syn::Path>,
    convention: Option<(Convention, Span)>,
    gravity: Option<[Spanned; 3]>,
    dh: Option<(Vec<DhRowAttr>, Span)>,
    links: Vec<LinkAttr>,
    name: Option<LitStr>,
    /// `check_inertia = false` for every link (or every joint of the file).
    check_inertia: Option<bool>,
}

/// Collects errors; they are all reported together.
#[derive(Default)]
pub struct Errors(Vec<syn::Error>);

impl Errors {
    fn push(&mut self, span: Span, message: impl std::fmt::Display) {
        self.0.push(syn::Error::new(span, message));
    }

    /// All errors as one `syn::Error`, or `None`.
    #[must_use]
    pub fn combine(self) -> Option<syn::Error> {
        self.0.into_iter().reduce(|mut a, b| {
            a.combine(b);
            a
        })
    }
}

/// `N` values in brackets, and the span of the brackets.
fn values<const N: usize>(input: ParseStream, what: &str) -> syn::Result<([Spanned; N], Span)> {
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

/// Stores the first value given for a key; a repeated key is an error, and parsing goes on.
fn set<T>(slot: &mut Option<T>, value: T, key: &Ident, what: &str, errors: &mut Errors) {
    if slot.is_some() {
        errors.push(
            key.span(),
            format!("duplicate {what} `{key}`: it is given earlier in this list"),
        );
    } else {
        *slot = Some(value);
    }
}

/// Skips what follows an unknown key, up to the next `,` at this level, so that the keys
/// after it are still checked.
fn skip_entry(input: ParseStream) -> syn::Result<()> {
    while !input.is_empty() && !input.peek(Token![,]) {
        input.parse::<proc_macro2::TokenTree>()?;
    }
    Ok(())
}

/// The number of single-character edits between two short words.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (diagonal + usize::from(ca != *cb))
                .min(row[j] + 1)
                .min(row[j + 1] + 1);
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// "unknown {what} `key`: expected ..." with a suggestion for a near miss.
fn unknown_key(key: &Ident, what: &str, known: &[&str]) -> String {
    let key = key.to_string();
    let list = known
        .iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ");
    let near = known
        .iter()
        .map(|k| (edit_distance(&key, k), *k))
        .filter(|(d, k)| *d <= 2 && *d < k.len())
        .min();
    match near {
        Some((_, k)) => {
            format!("unknown {what} `{key}`: did you mean `{k}`? (expected one of {list})")
        }
        None => format!("unknown {what} `{key}`: expected one of {list}"),
    }
}

const LINK_KEYS: [&str; 6] = [
    "mass",
    "com",
    "inertia",
    "actuator_inertia",
    "spring",
    "check_inertia",
];

const KEYS: [&str; 8] = [
    "gravity",
    "dh",
    "link",
    "convention",
    "file",
    "name",
    "crate",
    "check_inertia",
];

fn parse_link(input: ParseStream, span: Span, errors: &mut Errors) -> syn::Result<LinkAttr> {
    let mut link = LinkAttr {
        span: Some(span),
        ..LinkAttr::default()
    };
    let what = "link attribute";
    while !input.is_empty() {
        let key: Ident = input.parse()?;
        let name = key.to_string();
        if !LINK_KEYS.contains(&name.as_str()) {
            errors.push(key.span(), unknown_key(&key, what, &LINK_KEYS));
            link.unknown_key = true;
            skip_entry(input)?;
        } else {
            input.parse::<Token![=]>()?;
            match name.as_str() {
                "mass" => set(&mut link.mass, input.parse()?, &key, what, errors),
                "com" => {
                    let (com, _) = values::<3>(input, "`com = [x, y, z]`")?;
                    set(&mut link.com, com, &key, what, errors);
                }
                "inertia" => {
                    let inertia = values::<6>(input, "`inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`")?;
                    set(&mut link.inertia, inertia, &key, what, errors);
                }
                "actuator_inertia" => {
                    set(
                        &mut link.actuator_inertia,
                        input.parse()?,
                        &key,
                        what,
                        errors,
                    );
                }
                "spring" => {
                    let spring = parse_spring(input)?;
                    set(&mut link.spring, spring, &key, what, errors);
                }
                _ => set(&mut link.check_inertia, boolean(input)?, &key, what, errors),
            }
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(link)
}

fn parse_spring(input: ParseStream) -> syn::Result<(Spanned, Spanned)> {
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

fn parse_convention(input: ParseStream) -> syn::Result<(Convention, Span)> {
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

fn parse_dh(input: ParseStream) -> syn::Result<(Vec<DhRowAttr>, Span)> {
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
        let (row, _) = values::<4>(&content, "a D-H row `[θ, d, a, α]`")?;
        rows.push((span, row));
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok((rows, bracket.span.join()))
}

fn boolean(input: ParseStream) -> syn::Result<bool> {
    if input.peek(syn::LitBool) {
        Ok(input.parse::<syn::LitBool>()?.value)
    } else {
        Err(input.error(
            "expected `true` or `false`: `check_inertia = false` keeps an inertia tensor that \
             fails the physical checks",
        ))
    }
}

fn string(input: ParseStream, usage: &str) -> syn::Result<LitStr> {
    if input.peek(LitStr) {
        input.parse()
    } else {
        Err(input.error(format!("expected a string: {usage}")))
    }
}

fn parse_attrs(input: ParseStream, attrs: &mut Attrs, errors: &mut Errors) -> syn::Result<()> {
    let what = "dynamics attribute";
    while !input.is_empty() {
        let key: Ident = if input.peek(Token![crate]) {
            let k: Token![crate] = input.parse()?;
            Ident::new("crate", k.span)
        } else {
            input.parse()?
        };
        let name = key.to_string();
        if !KEYS.contains(&name.as_str()) {
            errors.push(key.span(), unknown_key(&key, what, &KEYS));
            skip_entry(input)?;
        } else if name == "link" {
            if !input.peek(syn::token::Paren) {
                return Err(input.error(
                    "expected `link(mass = .., com = [..], inertia = [..])`, one per joint",
                ));
            }
            let content;
            parenthesized!(content in input);
            attrs.links.push(parse_link(&content, key.span(), errors)?);
        } else {
            input.parse::<Token![=]>()?;
            match name.as_str() {
                "file" => {
                    let s = string(input, "`file = \"robots/arm.toml\"`")?;
                    set(&mut attrs.file, s, &key, what, errors);
                }
                "name" => {
                    let s = string(input, "`name = \"arm\"`")?;
                    set(&mut attrs.name, s, &key, what, errors);
                }
                "crate" => {
                    let s = string(input, "`crate = \"path::to::dynamics_runtime\"`")?;
                    set(&mut attrs.krate, s.parse()?, &key, what, errors);
                }
                "convention" => {
                    let c = parse_convention(input)?;
                    set(&mut attrs.convention, c, &key, what, errors);
                }
                "gravity" => {
                    let (g, _) = values::<3>(input, "`gravity = [gx, gy, gz]`")?;
                    set(&mut attrs.gravity, g, &key, what, errors);
                }
                "check_inertia" => {
                    set(
                        &mut attrs.check_inertia,
                        boolean(input)?,
                        &key,
                        what,
                        errors,
                    );
                }
                _ => {
                    let dh = parse_dh(input)?;
                    set(&mut attrs.dh, dh, &key, what, errors);
                }
            }
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(())
}

/// A struct field the values may name.
pub struct Field {
    /// Its name.
    pub name: String,
    /// Whether its type is `f32` or `f64`.
    pub is_float: bool,
}

/// The named fields of a struct.
#[must_use]
pub fn struct_fields(input: &syn::DeriveInput) -> Vec<Field> {
    let syn::Data::Struct(data) = &input.data else {
        return Vec::new();
    };
    data.fields
        .iter()
        .filter_map(|f| {
            let name = f.ident.as_ref()?.to_string();
            let is_float = matches!(&f.ty, syn::Type::Path(p)
                if p.qself.is_none() && (p.path.is_ident("f64") || p.path.is_ident("f32")));
            Some(Field { name, is_float })
        })
        .collect()
}

/// Errors for fields a value names that the struct lacks or that are not floats.
fn check_names(spanned: &Spanned, fields: &[Field], errors: &mut Errors) {
    for (name, span) in &spanned.fields {
        match fields.iter().find(|f| &f.name == name) {
            None => errors.push(
                *span,
                format!("`{name}` is not a field of this struct (values may name `f32` or `f64` fields)"),
            ),
            Some(f) if !f.is_float => {
                errors.push(*span, format!("field `{name}` must be of type `f64` or `f32`"));
            }
            Some(_) => {}
        }
    }
}

/// Errors for literal arithmetic that has no finite result.
fn check_arithmetic(spanned: &Spanned, errors: &mut Errors) {
    if divides_by_zero(&spanned.value) {
        errors.push(
            spanned.span,
            format!("division by zero in `{}`", spanned.value),
        );
    } else if spanned
        .value
        .exact()
        .is_some_and(|x| !x.to_f64().is_finite())
    {
        errors.push(
            spanned.span,
            format!(
                "`{}` overflows an f64: it is not a finite number",
                spanned.value
            ),
        );
    }
}

fn value(s: Option<&Spanned>, fields: &[Field], errors: &mut Errors) -> Value {
    match s {
        Some(s) => {
            check_names(s, fields, errors);
            check_arithmetic(s, errors);
            if s.value.joint_occurrences() > 0 {
                errors.push(
                    s.span,
                    "the joint variable `q` may appear only in the θ or d column of the D-H table",
                );
            }
            s.value.clone()
        }
        None => Value::zero(),
    }
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
}

/// Parses the derive input into a robot; every error found is returned together.
///
/// # Errors
/// The combined errors, each on its own span, and the number of joints if known.
pub fn parse(input: &syn::DeriveInput) -> Result<Input, Failure> {
    let mut errors = Errors::default();
    let mut attrs = Attrs::default();
    let mut seen = false;
    // After a syntax error, what follows it is unknown: report no missing keys then.
    let mut parse_failed = false;
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("dynamics")) {
        seen = true;
        let parsed = attr.parse_args_with(|s: ParseStream| parse_attrs(s, &mut attrs, &mut errors));
        if let Err(e) = parsed {
            errors.0.push(e);
            parse_failed = true;
        }
    }
    let fields = struct_fields(input);
    if !matches!(input.data, syn::Data::Struct(_)) {
        errors.push(
            input.ident.span(),
            "`Dynamics` can only be derived for a struct",
        );
    }
    if !seen {
        errors.push(
            input.ident.span(),
            "missing `#[dynamics(...)]`: give the D-H table with `gravity = [..]`, `dh = [..]` and \
             one `link(..)` per joint, or `file = \"robot.json\"`",
        );
    }
    let mut tracked_file = None;
    let robot = if let Some(file) = &attrs.file {
        for (present, what) in [
            (attrs.gravity.is_some(), "gravity"),
            (attrs.dh.is_some(), "dh"),
            (!attrs.links.is_empty(), "link"),
            (attrs.convention.is_some(), "convention"),
        ] {
            if present {
                errors.push(file.span(), format!("`{what}` cannot be combined with `file`: the file describes the whole robot"));
            }
        }
        let checked = attrs.check_inertia.unwrap_or(true);
        load_file(file, checked, &fields, &mut errors, &mut tracked_file)
    } else if parse_failed || !seen {
        None
    } else {
        Some(from_attrs(&attrs, input, &fields, &mut errors))
    };
    match (errors.combine(), robot) {
        (None, Some(mut robot)) => {
            if let Some(name) = &attrs.name {
                robot.name = name.value();
            }
            Ok(Input {
                robot,
                krate: attrs.krate,
                tracked_file,
            })
        }
        (Some(error), robot) => Err(Failure {
            error,
            dof: robot
                .map(|r| r.dof())
                .or_else(|| attrs.dh.as_ref().map(|(rows, _)| rows.len()))
                .filter(|n| *n > 0),
            krate: attrs.krate,
        }),
        (None, None) => Err(Failure {
            error: syn::Error::new(input.ident.span(), "no robot description"),
            dof: None,
            krate: attrs.krate,
        }),
    }
}

/// Reads the description file; its errors go on the `file = "..."` string, with the file's
/// name, line and column in the message.
fn load_file(
    file: &LitStr,
    check_inertia: bool,
    fields: &[Field],
    errors: &mut Errors,
    tracked: &mut Option<String>,
) -> Option<Robot> {
    let relative = file.value();
    let base = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".to_string());
    let path = std::path::Path::new(&base).join(&relative);
    let text = match std::fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) => {
            errors.push(
                file.span(),
                format!("cannot read `{relative}` (relative to the crate's Cargo.toml): {e}"),
            );
            return None;
        }
    };
    *tracked = Some(path.display().to_string());
    let loaded = match model::load(&relative, &text) {
        Ok(loaded) => loaded,
        Err(e) => {
            let sep = if e.line.is_some() { "" } else { " " };
            errors.push(file.span(), format!("{relative}:{sep}{e}"));
            return None;
        }
    };
    let robot = &loaded.robot;
    let at = |i: usize, key: &str| loaded.at(&relative, i, key);
    for name in robot.fields() {
        let (i, key) = field_location(robot, &name);
        let at = i.map_or_else(|| format!("{relative}: "), |i| at(i, key));
        match fields.iter().find(|f| f.name == name) {
            None => errors.push(
                file.span(),
                format!("{at}`{name}` is not a field of this struct (values may name `f32` or `f64` fields)"),
            ),
            Some(f) if !f.is_float => errors.push(
                file.span(),
                format!("{at}field `{name}` must be of type `f64` or `f32`"),
            ),
            Some(_) => {}
        }
    }
    if robot.dof() > check::MAX_JOINTS {
        errors.push(
            file.span(),
            format!(
                "{}{} joints; at most {} are supported (the generated code grows as n³)",
                at(check::MAX_JOINTS, "type"),
                robot.dof(),
                check::MAX_JOINTS
            ),
        );
    }
    for v in robot.values() {
        if divides_by_zero(v) {
            errors.push(
                file.span(),
                format!("{relative}: division by zero in `{v}`"),
            );
        }
    }
    for (i, joint) in robot.joints.iter().enumerate() {
        let checked = check_inertia && loaded.check_inertia.get(i).copied().unwrap_or(true);
        for problem in check::link(&joint.mass, &joint.inertia, checked) {
            let key = match problem.part {
                Part::Mass => "mass",
                Part::Inertia => "inertia",
            };
            errors.push(
                file.span(),
                format!("{}joint {}: {}", at(i, key), i + 1, problem.message),
            );
        }
    }
    Some(loaded.robot)
}

/// The first joint (`None` for gravity) and file key whose value names field `name`.
fn field_location(robot: &Robot, name: &str) -> (Option<usize>, &'static str) {
    let names = |v: &Value| {
        let mut set = std::collections::BTreeSet::new();
        v.collect_fields(&mut set);
        set.contains(name)
    };
    for (i, j) in robot.joints.iter().enumerate() {
        let spring = j.spring.as_ref();
        let keys: [(&'static str, Vec<&Value>); 10] = [
            ("theta", vec![&j.theta]),
            ("d", vec![&j.d]),
            ("a", vec![&j.a]),
            ("alpha", vec![&j.alpha]),
            ("mass", vec![&j.mass]),
            ("com", j.com.iter().collect()),
            ("inertia", j.inertia.iter().collect()),
            ("actuator_inertia", vec![&j.actuator_inertia]),
            (
                "spring_stiffness",
                spring.map(|s| &s.stiffness).into_iter().collect(),
            ),
            ("spring_rest", spring.map(|s| &s.rest).into_iter().collect()),
        ];
        if let Some((key, _)) = keys.iter().find(|(_, vs)| vs.iter().any(|v| names(v))) {
            return (Some(i), key);
        }
    }
    (None, "gravity")
}

fn from_attrs(
    attrs: &Attrs,
    input: &syn::DeriveInput,
    fields: &[Field],
    errors: &mut Errors,
) -> Robot {
    let span = input.ident.span();
    let gravity = match &attrs.gravity {
        Some(g) => [
            value(Some(&g[0]), fields, errors),
            value(Some(&g[1]), fields, errors),
            value(Some(&g[2]), fields, errors),
        ],
        None => {
            errors.push(span, "missing `gravity = [gx, gy, gz]`: the gravity acceleration in the base frame, e.g. `[0, 0, -9.81]`");
            Default::default()
        }
    };
    let mut joints = Vec::new();
    match &attrs.dh {
        None => errors.push(
            span,
            "missing `dh = [[θ, d, a, α], ...]`: the D-H table, one row per joint",
        ),
        Some((rows, table_span)) => {
            if rows.is_empty() {
                errors.push(
                    *table_span,
                    "the D-H table is empty: give one row `[θ, d, a, α]` per joint",
                );
            }
            if let Some((row_span, _)) = rows.get(check::MAX_JOINTS) {
                errors.push(
                    *row_span,
                    format!(
                        "the D-H table has {} rows; at most {} joints are supported (the \
                         generated code grows as n³)",
                        rows.len(),
                        check::MAX_JOINTS
                    ),
                );
            }
            if !rows.is_empty() && rows.len() != attrs.links.len() {
                let at = attrs
                    .links
                    .get(rows.len())
                    .and_then(|l| l.span)
                    .unwrap_or(*table_span);
                errors.push(
                    at,
                    format!(
                        "the D-H table has {} rows but {} `link(...)` entries are given: give one per joint",
                        rows.len(),
                        attrs.links.len()
                    ),
                );
            }
            for (i, (row_span, [theta, d, a, alpha])) in rows.iter().enumerate() {
                let n = i + 1;
                for cell in [theta, d] {
                    check_names(cell, fields, errors);
                    check_arithmetic(cell, errors);
                    check_joint_index(&cell.value, n, cell.span, errors);
                }
                let kind = match (theta.value.joint_occurrences(), d.value.joint_occurrences()) {
                    (1, 0) => JointKind::Revolute,
                    (0, 1) => JointKind::Prismatic,
                    (0, 0) => {
                        errors.push(*row_span, format!("row {n} has no joint variable: write `q` in the θ column (revolute) or the d column (prismatic)"));
                        JointKind::Revolute
                    }
                    _ => {
                        errors.push(*row_span, format!("row {n} must have the joint variable `q` once, in the θ or the d column"));
                        JointKind::Revolute
                    }
                };
                let split = |cell: &Spanned, errors: &mut Errors| -> Value {
                    if cell.value.joint_occurrences() == 0 {
                        return cell.value.clone();
                    }
                    cell.value.joint_offset().unwrap_or_else(|| {
                        errors.push(
                            cell.span,
                            "write the joint variable as `q`, `q + offset` or `q - offset`",
                        );
                        Value::zero()
                    })
                };
                let theta_v = split(theta, errors);
                let d_v = split(d, errors);
                let a_v = value(Some(a), fields, errors);
                let alpha_v = value(Some(alpha), fields, errors);
                let link = attrs.links.get(i);
                let link_value =
                    |s: Option<&Spanned>, errors: &mut Errors| value(s, fields, errors);
                let com = match link.and_then(|l| l.com.as_ref()) {
                    Some(c) => [
                        link_value(Some(&c[0]), errors),
                        link_value(Some(&c[1]), errors),
                        link_value(Some(&c[2]), errors),
                    ],
                    None => Default::default(),
                };
                let mut inertia: [Value; 6] = Default::default();
                if let Some((c, _)) = link.and_then(|l| l.inertia.as_ref()) {
                    for (o, s) in inertia.iter_mut().zip(c) {
                        *o = link_value(Some(s), errors);
                    }
                }
                let mass = link_value(link.and_then(|l| l.mass.as_ref()), errors);
                // After an unknown key (a misspelt `mass`?), a missing mass is no news.
                if let Some(l) = link.filter(|l| l.mass.is_none() && !l.unknown_key) {
                    errors.push(
                        l.span.unwrap_or(span),
                        format!("link {n} has no `mass = ..`"),
                    );
                }
                if let Some(l) = link {
                    let checked = l.check_inertia.or(attrs.check_inertia).unwrap_or(true);
                    check_link(n, l, checked, &mass, &inertia, errors);
                }
                let actuator_inertia =
                    link_value(link.and_then(|l| l.actuator_inertia.as_ref()), errors);
                let spring = link
                    .and_then(|l| l.spring.as_ref())
                    .map(|(k, rest)| Spring {
                        stiffness: link_value(Some(k), errors),
                        rest: link_value(Some(rest), errors),
                    });
                joints.push(Joint {
                    kind,
                    theta: theta_v,
                    d: d_v,
                    a: a_v,
                    alpha: alpha_v,
                    mass,
                    com,
                    inertia,
                    actuator_inertia,
                    spring,
                });
            }
        }
    }
    Robot {
        name: input.ident.to_string(),
        convention: attrs.convention.map_or(Convention::Standard, |c| c.0),
        gravity,
        joints,
    }
}

/// The physical checks of link `n`, each error on the value it is about.
fn check_link(
    n: usize,
    link: &LinkAttr,
    checked: bool,
    mass: &Value,
    inertia: &[Value; 6],
    errors: &mut Errors,
) {
    let finite = |v: &Value| v.exact().map_or(true, |x| x.to_f64().is_finite());
    // A non-finite literal was reported where it is written; do not report it twice.
    let mass = if finite(mass) {
        mass.clone()
    } else {
        Value::zero()
    };
    let checked = checked && inertia.iter().all(finite);
    let fallback = link.span.unwrap_or_else(Span::call_site);
    for problem in check::link(&mass, inertia, checked) {
        let at = match problem.part {
            Part::Mass => link.mass.as_ref().map(|m| m.span),
            Part::Inertia => link.inertia.as_ref().map(|(_, span)| *span),
        };
        errors.push(
            at.unwrap_or(fallback),
            format!("link {n}: {}", problem.message),
        );
    }
}

fn check_joint_index(v: &Value, row: usize, span: Span, errors: &mut Errors) {
    match v {
        Value::Joint(Some(k)) if *k != row => errors.push(
            span,
            format!("`q{k}` in row {row}: the joint variable of row {row} is `q` or `q{row}`"),
        ),
        Value::Neg(a) => check_joint_index(a, row, span, errors),
        Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) | Value::Div(a, b) => {
            check_joint_index(a, row, span, errors);
            check_joint_index(b, row, span, errors);
        }
        _ => {}
    }
}

fn divides_by_zero(v: &Value) -> bool {
    match v {
        Value::Div(a, b) => divides_by_zero(a) || b.exact().is_some_and(|x| x.is_zero()),
        Value::Neg(a) => divides_by_zero(a),
        Value::Add(a, b) | Value::Sub(a, b) | Value::Mul(a, b) => {
            divides_by_zero(a) || divides_by_zero(b)
        }
        _ => false,
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

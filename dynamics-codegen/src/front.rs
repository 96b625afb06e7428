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
    inertia: Option<[Spanned; 6]>,
    actuator_inertia: Option<Spanned>,
    spring: Option<(Spanned, Spanned)>,
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

fn values<const N: usize>(input: ParseStream, what: &str) -> syn::Result<[Spanned; N]> {
    let content;
    let bracket = bracketed!(content in input);
    let items: Punctuated<Spanned, Token![,]> = Punctuated::parse_terminated(&content)?;
    let count = items.len();
    items
        .into_iter()
        .collect::<Vec<_>>()
        .try_into()
        .map_err(|_| {
            syn::Error::new(
                bracket.span.join(),
                format!("{what} takes {N} values, found {count}"),
            )
        })
}

fn parse_link(input: ParseStream, span: Span) -> syn::Result<LinkAttr> {
    let mut link = LinkAttr {
        span: Some(span),
        ..LinkAttr::default()
    };
    while !input.is_empty() {
        let key: Ident = input.parse()?;
        let dup = |set: bool| -> syn::Result<()> {
            if set {
                Err(syn::Error::new(
                    key.span(),
                    format!("duplicate link attribute `{key}`"),
                ))
            } else {
                Ok(())
            }
        };
        input.parse::<Token![=]>()?;
        match key.to_string().as_str() {
            "mass" => {
                dup(link.mass.is_some())?;
                link.mass = Some(input.parse()?);
            }
            "com" => {
                dup(link.com.is_some())?;
                link.com = Some(values::<3>(input, "`com = [x, y, z]`")?);
            }
            "inertia" => {
                dup(link.inertia.is_some())?;
                link.inertia = Some(values::<6>(
                    input,
                    "`inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`",
                )?);
            }
            "actuator_inertia" => {
                dup(link.actuator_inertia.is_some())?;
                link.actuator_inertia = Some(input.parse()?);
            }
            "spring" => {
                dup(link.spring.is_some())?;
                let content;
                parenthesized!(content in input);
                let k: Spanned = content.parse()?;
                content.parse::<Token![,]>()?;
                let rest: Spanned = content.parse()?;
                content.parse::<Option<Token![,]>>()?;
                if !content.is_empty() {
                    return Err(content.error("expected `spring = (stiffness, rest_position)`"));
                }
                link.spring = Some((k, rest));
            }
            _ => {
                return Err(syn::Error::new(
                    key.span(),
                    format!(
                        "unknown link attribute `{key}`: expected `mass`, `com`, `inertia`, \
                         `actuator_inertia` or `spring`"
                    ),
                ))
            }
        }
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(link)
}

fn parse_attrs(input: ParseStream, attrs: &mut Attrs) -> syn::Result<()> {
    while !input.is_empty() {
        let key: Ident = if input.peek(Token![crate]) {
            let k: Token![crate] = input.parse()?;
            Ident::new("crate", k.span)
        } else {
            input.parse()?
        };
        let name = key.to_string();
        let dup = |set: bool| -> syn::Result<()> {
            if set {
                Err(syn::Error::new(
                    key.span(),
                    format!("duplicate dynamics attribute `{key}`"),
                ))
            } else {
                Ok(())
            }
        };
        if name == "link" {
            let content;
            parenthesized!(content in input);
            attrs.links.push(parse_link(&content, key.span())?);
        } else {
            input.parse::<Token![=]>()?;
            match name.as_str() {
                "file" => {
                    dup(attrs.file.is_some())?;
                    attrs.file = Some(input.parse()?);
                }
                "name" => {
                    dup(attrs.name.is_some())?;
                    attrs.name = Some(input.parse()?);
                }
                "crate" => {
                    dup(attrs.krate.is_some())?;
                    let s: LitStr = input.parse()?;
                    attrs.krate = Some(s.parse()?);
                }
                "convention" => {
                    dup(attrs.convention.is_some())?;
                    let (text, span) = if input.peek(LitStr) {
                        let s: LitStr = input.parse()?;
                        (s.value(), s.span())
                    } else {
                        let i: Ident = input.parse()?;
                        (i.to_string(), i.span())
                    };
                    let c = match text.as_str() {
                        "standard" => Convention::Standard,
                        "modified" => Convention::Modified,
                        _ => {
                            return Err(syn::Error::new(
                                span,
                                format!(
                                "unknown convention `{text}`: expected `standard` or `modified`"
                            ),
                            ))
                        }
                    };
                    attrs.convention = Some((c, span));
                }
                "gravity" => {
                    dup(attrs.gravity.is_some())?;
                    attrs.gravity = Some(values::<3>(input, "`gravity = [gx, gy, gz]`")?);
                }
                "dh" => {
                    dup(attrs.dh.is_some())?;
                    let content;
                    let bracket = bracketed!(content in input);
                    let mut rows = Vec::new();
                    while !content.is_empty() {
                        let span = content.span();
                        rows.push((span, values::<4>(&content, "a D-H row `[θ, d, a, α]`")?));
                        if !content.is_empty() {
                            content.parse::<Token![,]>()?;
                        }
                    }
                    attrs.dh = Some((rows, bracket.span.join()));
                }
                _ => {
                    return Err(syn::Error::new(
                        key.span(),
                        format!(
                            "unknown dynamics attribute `{key}`: expected `gravity`, `dh`, `link`, \
                             `convention`, `file`, `name` or `crate`"
                        ),
                    ))
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

fn check_fields(spanned: &Spanned, fields: &[Field], errors: &mut Errors) {
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
    if spanned.value.joint_occurrences() > 0 {
        errors.push(
            spanned.span,
            "the joint variable `q` may appear only in the θ or d column of the D-H table",
        );
    }
}

fn value(s: Option<&Spanned>, fields: &[Field], errors: &mut Errors) -> Value {
    match s {
        Some(s) => {
            check_fields(s, fields, errors);
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
        if let Err(e) = attr.parse_args_with(|s: ParseStream| parse_attrs(s, &mut attrs)) {
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
        load_file(file, &fields, &mut errors, &mut tracked_file)
    } else if parse_failed {
        None
    } else {
        Some(from_attrs(&attrs, input, &fields, &mut errors))
    };
    if let Some(robot) = &robot {
        check(
            robot,
            attrs.file.as_ref().map_or(input.ident.span(), LitStr::span),
            &mut errors,
        );
    }
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

fn load_file(
    file: &LitStr,
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
    match model::from_text(&relative, &text) {
        Ok(robot) => {
            for name in robot.fields() {
                match fields.iter().find(|f| f.name == name) {
                    None => errors.push(
                        file.span(),
                        format!("{relative}: `{name}` is not a field of this struct"),
                    ),
                    Some(f) if !f.is_float => errors.push(
                        file.span(),
                        format!("{relative}: field `{name}` must be of type `f64` or `f32`"),
                    ),
                    Some(_) => {}
                }
            }
            Some(robot)
        }
        Err(e) => {
            errors.push(file.span(), format!("{relative}:{e}"));
            None
        }
    }
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
                    for (name, span) in &cell.fields {
                        if !fields.iter().any(|f| &f.name == name) {
                            errors.push(*span, format!("`{name}` is not a field of this struct (values may name `f32` or `f64` fields)"));
                        }
                    }
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
                if let Some(c) = link.and_then(|l| l.inertia.as_ref()) {
                    for (o, s) in inertia.iter_mut().zip(c) {
                        *o = link_value(Some(s), errors);
                    }
                }
                let mass = link_value(link.and_then(|l| l.mass.as_ref()), errors);
                if let (Some(l), None) = (link, link.and_then(|l| l.mass.as_ref())) {
                    errors.push(
                        l.span.unwrap_or(span),
                        format!("link {n} has no `mass = ..`"),
                    );
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

/// Checks across fields that the parser cannot see: literal divisions by zero, negative or
/// non-finite literal masses.
fn check(robot: &Robot, span: Span, errors: &mut Errors) {
    if robot.joints.is_empty() {
        return;
    }
    for v in robot.values() {
        if divides_by_zero(v) {
            errors.push(span, format!("division by zero in `{v}`"));
        }
    }
    for (i, j) in robot.joints.iter().enumerate() {
        if let Some(m) = j.mass.exact() {
            if m.is_negative() {
                errors.push(span, format!("link {}: the mass {m} is negative", i + 1));
            }
        }
    }
    if robot.joints.len() > 64 {
        errors.push(span, "more than 64 joints are not supported");
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

//! The names generated code takes from user text (a robot's name, its parameters'), made
//! valid in the language written, or refused where nothing valid says the same thing.
//!
//! * Rust: a parameter is a struct field, `r#type` where its name is a keyword of any edition
//!   (2024's `gen` too); `self`, `Self`, `super`, `crate` and `_` have no raw form, so the
//!   value grammar refuses them ([`parameter_problem`]). The struct of `dynamics emit` is the
//!   robot's name in `CamelCase`, `Robot` before it where that is empty, starts with a digit or
//!   is `Self` ([`rust_type`]).
//! * C: no identifier is user text alone: the functions are `{prefix}_{method}`, the guard
//!   `DYNAMICS_ROBOT_{prefix}_H`, a parameter's local `p_{name}` (`p_{k}` for a name that would
//!   put two underscores together or leave ASCII, [`c_parameter`]), so C's and C++'s keywords
//!   cannot occur; the names are kept out of what C and C++ reserve to the implementation
//!   (a leading underscore, `__` anywhere, the standard headers' macro prefixes such as `E`,
//!   `SIG` and `LC_`). The prefix ([`c_prefix`]) is readable, not injective (`arm-a` and `arm_a`
//!   share `arm_a`): the guard carries a hash of the header, which refuses to compile beside
//!   another header with the same prefix (`emit_c`).

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// Rust's keywords of every edition: strict, reserved for later use (`abstract`, `yield`,
/// 2018's `async`, `await`, `dyn`, `try`, 2024's `gen`). A field so named is written raw.
const RUST_KEYWORDS: &[&str] = &[
    "Self", "abstract", "as", "async", "await", "become", "box", "break", "const", "continue",
    "crate", "do", "dyn", "else", "enum", "extern", "false", "final", "fn", "for", "gen", "if",
    "impl", "in", "let", "loop", "macro", "match", "mod", "move", "mut", "override", "priv", "pub",
    "ref", "return", "self", "static", "struct", "super", "trait", "true", "try", "type", "typeof",
    "unsafe", "unsized", "use", "virtual", "where", "while", "yield",
];

/// The names no Rust identifier can take, raw or not (`r#self` is not one).
const NOT_RAW: &[&str] = &["self", "Self", "super", "crate", "_"];

/// Whether `name` is a keyword of some edition of Rust.
#[must_use]
pub fn is_rust_keyword(name: &str) -> bool {
    RUST_KEYWORDS.contains(&name)
}

/// Why `name` cannot name a robot parameter (a struct field), if it cannot: Rust has no field
/// of that name, not even a raw one.
#[must_use]
pub fn parameter_problem(name: &str) -> Option<String> {
    NOT_RAW.contains(&name).then(|| {
        format!(
            "`{name}` cannot name a parameter: Rust has no struct field of that name (not even \
             `r#{name}`); rename it"
        )
    })
}

/// The Rust identifier of the parameter (struct field) `name`: raw for a keyword (`r#type`).
///
/// # Errors
/// The [`parameter_problem`] of a name no field can have, or a name that is not an identifier.
pub fn rust_field(name: &str) -> Result<Ident, String> {
    if let Some(problem) = parameter_problem(name) {
        return Err(problem);
    }
    // One identifier token, keywords included, and nothing else (not `r#type`, not `1m`).
    let parsed = syn::parse::Parser::parse_str(syn::ext::IdentExt::parse_any, name);
    if name.starts_with("r#") || !parsed.is_ok_and(|ident: Ident| ident == name) {
        return Err(format!(
            "`{name}` is not an identifier, so it cannot name a parameter"
        ));
    }
    Ok(if is_rust_keyword(name) {
        Ident::new_raw(name, Span::call_site())
    } else {
        Ident::new(name, Span::call_site())
    })
}

/// The struct `dynamics emit` writes for the robot named `robot`: its ASCII letters and digits
/// in `CamelCase` (`two_link` → `TwoLink`), `Robot` before a name that is empty (no ASCII
/// letter or digit), starts with a digit (`1arm` → `Robot1arm`) or is Rust's `Self`.
#[must_use]
pub fn rust_type(robot: &str) -> String {
    let mut out = String::new();
    for part in robot.split(|c: char| !c.is_ascii_alphanumeric()) {
        let mut chars = part.chars();
        if let Some(c) = chars.next() {
            out.push(c.to_ascii_uppercase());
            out.extend(chars);
        }
    }
    if out.is_empty() || out.starts_with(|c: char| c.is_ascii_digit()) || is_rust_keyword(&out) {
        out.insert_str(0, "Robot");
    }
    out
}

/// The prefix of the C functions of the robot named `robot`: its runs of ASCII letters and
/// digits in lower case, joined by single underscores (`UR5e` → `ur5e`, `arm--a` → `arm_a`),
/// `robot_` before a leading digit, `robot` where there is none. No leading underscore and no
/// `__`, which C and C++ reserve.
#[must_use]
pub fn c_prefix(robot: &str) -> String {
    let parts: Vec<String> = robot
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|part| !part.is_empty())
        .map(str::to_ascii_lowercase)
        .collect();
    let name = parts.join("_");
    match name.chars().next() {
        None => "robot".to_owned(),
        Some(c) if c.is_ascii_digit() => format!("robot_{name}"),
        Some(_) => name,
    }
}

/// Why `prefix` cannot prefix a header's C functions, if it cannot: it must be made of ASCII
/// letters, digits and single underscores, start with a letter and not end with `_` (so that
/// `{prefix}_{method}` has no `__`).
#[must_use]
pub fn c_prefix_problem(prefix: &str) -> Option<String> {
    let allowed = prefix
        .chars()
        .all(|c| c.is_ascii_alphanumeric() || c == '_');
    let problem = if prefix.is_empty() {
        "it is empty"
    } else if !allowed {
        "it may hold only ASCII letters, digits and `_`"
    } else if !prefix.starts_with(|c: char| c.is_ascii_alphabetic()) {
        "it must start with a letter (C reserves names that start with `_`)"
    } else if prefix.contains("__") || prefix.ends_with('_') {
        "it may not hold `__` nor end with `_` (C++ reserves names with `__`)"
    } else {
        return None;
    };
    Some(format!(
        "`{prefix}` cannot prefix the C functions: {problem}"
    ))
}

/// The local that holds parameter `k`, named `name`, in a C function: `p_{name}`, or `p_{k}`
/// where `p_{name}` would put two underscores together (`_m`, `m__2`) or leave ASCII (`θ`).
/// A name cannot start with a digit, so the two forms never meet.
#[must_use]
pub fn c_parameter(k: usize, name: &str) -> String {
    let plain = name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.contains("__");
    if plain {
        format!("p_{name}")
    } else {
        format!("p_{k}")
    }
}

/// `text` for one line of a comment or a message: each control character (a newline, which
/// would end a `//!` comment and turn the rest into code; a NUL, which C compilers refuse) as
/// its escape (`\n`, `\u{0}`).
#[must_use]
pub fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

/// How the generated code reads each of `fields` (the struct fields the equations name):
/// `self.field`.
pub(crate) fn field_readers(fields: &[String]) -> Vec<TokenStream> {
    fields
        .iter()
        .map(|f| match rust_field(f) {
            Ok(ident) => quote!(self.#ident),
            // Not expected: each name the values read is one of the struct's fields.
            Err(message) => quote!(::core::compile_error!(#message)),
        })
        .collect()
}

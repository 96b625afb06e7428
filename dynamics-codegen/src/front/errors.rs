//! The errors of the front end: the collector of every error of the derive input, each on the
//! span of the token that caused it, reported together; an error in a description or URDF
//! file, at its line and column; and the message for an unknown key, with a suggestion for a
//! near miss (at most two single-character edits, the Levenshtein distance).

use proc_macro2::Span;
use syn::Ident;

/// Collects errors; they are all reported together.
#[derive(Default)]
pub struct Errors(Vec<syn::Error>);

impl Errors {
    /// Adds an error on `span`.
    pub(super) fn push(&mut self, span: Span, message: impl std::fmt::Display) {
        self.0.push(syn::Error::new(span, message));
    }

    /// Adds an error on the tokens from `start` to `end` (rustc underlines them all).
    pub(super) fn push_range(&mut self, start: Span, end: Span, message: impl std::fmt::Display) {
        let ends = [start, end].map(|span| {
            let mut punct = proc_macro2::Punct::new('*', proc_macro2::Spacing::Alone);
            punct.set_span(span);
            proc_macro2::TokenTree::Punct(punct)
        });
        let tokens: proc_macro2::TokenStream = ends.into_iter().collect();
        self.0.push(syn::Error::new_spanned(tokens, message));
    }

    /// Whether no error has been found.
    pub(super) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// How many errors there are.
    pub(super) fn len(&self) -> usize {
        self.0.len()
    }

    /// Adds an error that already has its span (a syntax error).
    pub(super) fn push_error(&mut self, error: syn::Error) {
        self.0.push(error);
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

/// An error in a description or URDF file, with the 1-based line and column where known.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    /// What is wrong.
    pub message: String,
    /// Line, 1-based.
    pub line: Option<usize>,
    /// Column, 1-based.
    pub column: Option<usize>,
    /// The request key whose link the error is about, where it is one: the derive puts the
    /// error on that key's string rather than on the file's name.
    pub about: Option<Requested>,
}

/// A key of the request that names a link of a URDF file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Requested {
    /// `base`.
    Base,
    /// `tip`.
    Tip,
    /// The i-th name of `tips`.
    Tips(usize),
}

impl Requested {
    /// The key, as written.
    #[must_use]
    pub fn key(self) -> &'static str {
        match self {
            Requested::Base => "base",
            Requested::Tip => "tip",
            Requested::Tips(_) => "tips",
        }
    }
}

impl FileError {
    /// The error, about the link `key` names.
    #[must_use]
    pub fn about(mut self, key: Requested) -> FileError {
        self.about = Some(key);
        self
    }
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => write!(f, "{l}:{c}: {}", self.message),
            _ => write!(f, "{}", self.message),
        }
    }
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
pub(super) fn unknown_key(key: &Ident, what: &str, known: &[&str]) -> String {
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

//! Errors as data: a problem with a description and its place, printed one way.

use crate::front::{FileError, RequestError};
use std::fmt;

/// A problem with a description, and where it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The file, as its path was given; `None` for a problem of the caller's own values.
    pub file: Option<String>,
    /// Line, 1-based, where the problem has a place in the file.
    pub line: Option<usize>,
    /// Column, 1-based.
    pub column: Option<usize>,
    /// What is wrong.
    pub message: String,
    /// How to put it right, where a hint helps (the option or key to use).
    pub help: Option<String>,
}

impl Diagnostic {
    /// A problem of the file `path` as a whole (no line).
    pub(crate) fn of_file(path: &str, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            file: Some(path.to_owned()),
            line: None,
            column: None,
            message: message.into(),
            help: None,
        }
    }

    /// A problem of the caller's own values (an argument, an option), with no file.
    pub(crate) fn of_caller(message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            file: None,
            line: None,
            column: None,
            message: message.into(),
            help: None,
        }
    }

    /// This problem with the hint `help`.
    #[must_use]
    pub(crate) fn with_help(self, help: impl Into<String>) -> Diagnostic {
        Diagnostic {
            help: Some(help.into()),
            ..self
        }
    }

    /// A problem at `at` (line, column) in `path`, or of the whole file.
    pub(crate) fn at(
        path: &str,
        at: Option<(usize, usize)>,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic {
            line: at.map(|(line, _)| line),
            column: at.map(|(_, column)| column),
            ..Diagnostic::of_file(path, message)
        }
    }

    pub(crate) fn from_file_error(path: &str, e: &FileError) -> Diagnostic {
        let at = e.line.zip(e.column);
        Diagnostic::at(path, at, e.message.clone())
    }
}

/// A mistake in a file's `[simplify]` at its place; one of the caller's overrides without a
/// file.
impl From<&RequestError> for Diagnostic {
    fn from(e: &RequestError) -> Diagnostic {
        let diagnostic = Diagnostic::at(&e.path, e.at, e.problem.clone());
        if e.in_file {
            diagnostic
        } else {
            Diagnostic {
                file: None,
                ..diagnostic
            }
        }
    }
}

/// `file:line:col: message`, `file: message` without a place, `message` without a file; then
/// `help: ...` on a line of its own where there is a hint.
impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.file, self.line, self.column) {
            (Some(file), Some(line), Some(column)) => {
                write!(f, "{file}:{line}:{column}: {}", self.message)?;
            }
            (Some(file), ..) => write!(f, "{file}: {}", self.message)?,
            (None, ..) => f.write_str(&self.message)?,
        }
        match &self.help {
            Some(help) => write!(f, "\nhelp: {help}"),
            None => Ok(()),
        }
    }
}

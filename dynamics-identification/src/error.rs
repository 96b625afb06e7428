//! Why an identification or an excitation cannot be had: the kind of mistake, and its message
//! in words (the samples' file, line and column; the setting and its value).

use std::fmt;

/// Why [`crate::identify()`], [`crate::excite()`] or a step of theirs failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Error {
    /// The base parameters need the robot's lengths and angles as numbers, not struct fields.
    StructFields,
    /// The regressor depends on something a sample does not give (a wrench, a torque).
    Regressor(String),
    /// A setting outside its range; the message names the `dynamics` option that gives it
    /// (`--cutoff`, `--q-min`, `--period × --rate`, ...).
    Setting(String),
    /// The samples cannot be read: the file, or a line of it (`path: line L, column C: ...`).
    Samples(String),
    /// The samples cannot give the estimate (too few, every parameter unidentifiable), or the
    /// estimate cannot predict them (values too large).
    Estimate(String),
    /// The physically consistent estimate was not found (the solver failed, the cuts did not
    /// converge).
    Consistent(String),
    /// The search for an exciting motion found none within the limits.
    NoMotion,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::StructFields => f.write_str(
                "the base parameters need the robot's lengths and angles as numbers, not \
                 struct fields",
            ),
            Error::NoMotion => f.write_str("the search found no motion"),
            Error::Regressor(m)
            | Error::Setting(m)
            | Error::Samples(m)
            | Error::Estimate(m)
            | Error::Consistent(m) => f.write_str(m),
        }
    }
}

impl std::error::Error for Error {}

//! Robot description files: the JSON format of the reference data, unchanged, and the same
//! content as TOML. Numbers may also be written as strings holding a value (`"90 deg"`,
//! `"m2 * l2^2 / 12"`), read by the attribute's value grammar, which TOML makes pleasant to
//! write by hand. Errors carry the file's line and column.

mod convert;
mod frames;
mod json;
mod positions;
mod schema;
mod simplify;
mod toml;
mod tree;

use crate::front::errors::FileError;
use crate::front::sources::Loaded;
use crate::model::Robot;

/// Reads a robot from JSON text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_json(text: &str, default_name: &str) -> Result<Robot, FileError> {
    json::read(text, default_name).map(|l| l.robot)
}

/// Reads a robot from TOML text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_toml(text: &str, default_name: &str) -> Result<Robot, FileError> {
    self::toml::read(text, default_name).map(|l| l.robot)
}

/// Reads a robot from a file's text, as JSON or TOML by the file's extension.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_text(path: &str, text: &str) -> Result<Robot, FileError> {
    load(path, text).map(|l| l.robot)
}

/// Reads a robot and its per-joint check flags from a file's text, as JSON or TOML by the
/// file's extension.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn load(path: &str, text: &str) -> Result<Loaded, FileError> {
    let stem = std::path::Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("robot");
    if path.ends_with(".toml") {
        self::toml::read(text, stem)
    } else if path.ends_with(".json") {
        json::read(text, stem)
    } else {
        Err(convert::plain(
            "cannot tell the format from the file's extension: name it *.json or *.toml"
                .to_string(),
        ))
    }
}

//! Description files in TOML: the JSON format's content, pleasant to write by hand.

use super::positions::{line_column, positions_at};
use super::{convert, schema};
use crate::front::errors::FileError;
use crate::front::sources::{Loaded, Positions};
use serde::Deserialize;
use std::collections::BTreeMap;

/// Reads a robot from TOML text.
pub(super) fn read(text: &str, default_name: &str) -> Result<Loaded, FileError> {
    let file: schema::FileRobot = toml::from_str(text).map_err(|e| {
        let (line, column) = e
            .span()
            .map_or((None, None), |s| line_column(text, s.start));
        let mut message = e.message().trim_end().to_string();
        // toml does not say which key is repeated; it is the one its span starts at.
        if let (true, Some(s)) = (message == "duplicate key", e.span()) {
            let key = text.get(s.start..).unwrap_or_default();
            let key = key
                .split(['=', '\n', ']'])
                .next()
                .unwrap_or_default()
                .trim();
            if !key.is_empty() {
                message = format!("duplicate key `{key}`");
            }
        }
        FileError {
            message,
            line,
            column,
            about: None,
        }
    })?;
    let (mut loaded, deferred) = convert::convert(file, default_name)?;
    loaded.sources = positions(text);
    convert::first_error(loaded, &deferred)
}

/// Where each joint's values are in TOML text (read a second time, with spans).
fn positions(text: &str) -> Positions {
    #[derive(Deserialize)]
    struct Joints {
        #[serde(default)]
        joints: Vec<BTreeMap<String, toml::Spanned<serde::de::IgnoredAny>>>,
        gravity: Option<toml::Spanned<serde::de::IgnoredAny>>,
        simplify: Option<toml::Spanned<BTreeMap<String, toml::Spanned<serde::de::IgnoredAny>>>>,
    }
    let Ok(file) = toml::from_str::<Joints>(text) else {
        return Positions::default();
    };
    let gravity = file
        .gravity
        .and_then(|g| match line_column(text, g.span().start) {
            (Some(l), Some(c)) => Some((l, c)),
            _ => None,
        });
    let offsets = file.joints.into_iter().map(|joint| {
        joint
            .into_iter()
            .map(|(key, value)| (key, value.span().start))
            .collect()
    });
    let at = |offset: usize| match line_column(text, offset) {
        (Some(l), Some(c)) => Some((l, c)),
        _ => None,
    };
    let mut simplify = BTreeMap::new();
    if let Some(table) = file.simplify {
        simplify.extend(at(table.span().start).map(|a| ("simplify".to_string(), a)));
        for (key, value) in table.into_inner() {
            simplify.extend(at(value.span().start).map(|a| (key, a)));
        }
    }
    Positions {
        joints: positions_at(text, offsets),
        gravity,
        simplify,
    }
}

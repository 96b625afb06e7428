//! Description files in JSON, the format of the reference data.

use super::positions::{line_column, positions_at};
use super::{convert, schema};
use crate::front::errors::FileError;
use crate::front::sources::{Loaded, Positions};

/// Reads a robot from JSON text.
pub(super) fn read(text: &str, default_name: &str) -> Result<Loaded, FileError> {
    let file: schema::FileRobot = serde_json::from_str(text).map_err(|e| {
        let (line, column) = newline_at_end(text, e.line(), e.column());
        FileError {
            message: e
                .to_string()
                .split(" at line")
                .next()
                .unwrap_or_default()
                .to_string(),
            line: Some(line),
            column: Some(column),
            about: None,
        }
    })?;
    let (mut loaded, deferred) = convert::convert(file, default_name)?;
    loaded.sources = positions(text);
    convert::first_error(loaded, &deferred)
}

/// serde_json's line and column as 1-based characters, as TOML's are: its column counts bytes,
/// and is 0 for an error on a newline (once its line was counted), which is the column just
/// past the end of the line before.
fn newline_at_end(text: &str, line: usize, column: usize) -> (usize, usize) {
    let chars =
        |line: &str, bytes: usize| line.char_indices().take_while(|(i, _)| *i < bytes).count();
    match (column, text.split('\n').nth(line.wrapping_sub(2))) {
        (0, Some(before)) => (line - 1, before.chars().count() + 1),
        _ => match text.split('\n').nth(line.wrapping_sub(1)) {
            Some(this) => (line, chars(this, column.saturating_sub(1)) + 1),
            None => (line, column.max(1)),
        },
    }
}

/// Where each joint's values are in JSON text: a scan of the text that the parser has already
/// accepted (serde_json keeps no positions of values).
fn positions(text: &str) -> Positions {
    let mut scan = JsonScan {
        bytes: text.as_bytes(),
        at: 0,
    };
    let mut joints = Vec::new();
    let mut gravity = None;
    let mut simplify = Vec::new();
    scan.object(&mut |scan, key| {
        scan.space();
        if key == "simplify" && scan.peek() == Some(b'{') {
            simplify.push((key.to_string(), scan.at));
            scan.object(&mut |scan, key| {
                simplify.push((key.to_string(), scan.at));
                scan.value();
            });
        } else if key == "joints" && scan.peek() == Some(b'[') {
            scan.at += 1;
            loop {
                scan.space();
                match scan.peek() {
                    Some(b'{') => {
                        let mut keys = Vec::new();
                        scan.object(&mut |scan, key| {
                            keys.push((key.to_string(), scan.at));
                            scan.value();
                        });
                        joints.push(keys);
                    }
                    Some(b',') => scan.at += 1,
                    Some(b']') | None => break,
                    Some(_) => scan.value(),
                }
            }
            scan.at += 1;
        } else {
            if key == "gravity" {
                scan.space();
                gravity = Some(scan.at);
            }
            scan.value();
        }
    });
    let gravity = gravity.and_then(|at| match line_column(text, at) {
        (Some(l), Some(c)) => Some((l, c)),
        _ => None,
    });
    let simplify = positions_at(text, [simplify]).pop().unwrap_or_default();
    Positions {
        joints: positions_at(text, joints),
        gravity,
        simplify,
    }
}

/// A cursor over valid JSON.
struct JsonScan<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl JsonScan<'_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    fn space(&mut self) {
        while self.peek().is_some_and(|b| b.is_ascii_whitespace()) {
            self.at += 1;
        }
    }

    /// A string's raw content; the cursor is on its opening quote.
    fn string(&mut self) -> &str {
        self.at += 1;
        let start = self.at;
        while let Some(b) = self.peek() {
            match b {
                b'\\' => self.at += 2,
                b'"' => break,
                _ => self.at += 1,
            }
        }
        let end = self.at.min(self.bytes.len());
        self.at += 1;
        std::str::from_utf8(self.bytes.get(start..end).unwrap_or_default()).unwrap_or_default()
    }

    /// Skips one value (and the space before it).
    fn value(&mut self) {
        self.space();
        match self.peek() {
            Some(b'"') => {
                self.string();
            }
            Some(b'{' | b'[') => {
                let mut depth = 0usize;
                while let Some(b) = self.peek() {
                    match b {
                        b'"' => {
                            self.string();
                            continue;
                        }
                        b'{' | b'[' => depth += 1,
                        b'}' | b']' => depth = depth.saturating_sub(1),
                        _ => {}
                    }
                    self.at += 1;
                    if depth == 0 {
                        break;
                    }
                }
            }
            _ => {
                while self
                    .peek()
                    .is_some_and(|b| !matches!(b, b',' | b'}' | b']') && !b.is_ascii_whitespace())
                {
                    self.at += 1;
                }
            }
        }
    }

    /// Walks an object, calling `each` with the cursor on each key's value.
    fn object(&mut self, each: &mut dyn FnMut(&mut Self, &str)) {
        self.space();
        if self.peek() != Some(b'{') {
            return;
        }
        self.at += 1;
        loop {
            self.space();
            match self.peek() {
                Some(b'"') => {
                    let key = self.string().to_string();
                    self.space();
                    if self.peek() == Some(b':') {
                        self.at += 1;
                    }
                    self.space();
                    each(self, &key);
                }
                Some(b',') => self.at += 1,
                _ => break,
            }
        }
        self.at += 1;
    }
}

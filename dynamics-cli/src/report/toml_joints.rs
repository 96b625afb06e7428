//! Edits to the `[[joints]]` tables of a TOML text, spliced into the text where the parser
//! found each value: every byte not edited (comments, layout, number spellings, key order)
//! stays as it was written.
//!
//! The parser is the `toml` crate the front end reads descriptions with, not a format-keeping
//! editor: such an editor turns on other features of the parser's crates than the derive's
//! side of the build does, so the code generator would be compiled twice.

use std::ops::Range;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// Where a key's line is and where its value is, in the text.
struct Entry {
    /// The value, as written (a number, an array across lines...).
    value: Range<usize>,
    /// The key's whole lines, from the start of the key's line to past the end of the value's.
    lines: Range<usize>,
}

/// One `[[joints]]` table: its keys, and where a new key goes.
struct Joint {
    entries: Vec<(String, Entry)>,
    /// The start of the line after the table's last key (its header's, if it has none).
    insert_at: usize,
    /// The indentation of that last key's line, for the new keys.
    indent: String,
}

/// The edits to make to `text`'s joints, applied by [`JointEdits::finish`].
pub struct JointEdits<'t> {
    text: &'t str,
    joints: Vec<Joint>,
    /// Replacements `(range, new text)`; no two ranges overlap (each key is edited once).
    edits: Vec<(Range<usize>, String)>,
}

impl<'t> JointEdits<'t> {
    /// The joints of `text`, the `[[joints]]` tables of a TOML description.
    ///
    /// # Errors
    /// The text is not TOML, or has no `[[joints]]` tables (none, or an inline array).
    pub fn new(text: &'t str) -> Result<Self, String> {
        let document = DeTable::parse(text).map_err(|e| located(text, &e))?;
        let Some(joints) = document.get_ref().get("joints") else {
            return Err("the description has no [[joints]] tables".to_string());
        };
        let at = |offset: usize| position(text, offset);
        let tables = match joints.get_ref() {
            DeValue::Array(items) => items,
            _ => {
                return Err(format!(
                    "{}: `joints` is not [[joints]] tables",
                    at(joints.span().start)
                ))
            }
        };
        let mut headers = Vec::new();
        headers_in(text, document.get_ref(), &mut headers);
        headers.sort_unstable();
        let joints = tables
            .iter()
            .map(|table| match table.get_ref() {
                DeValue::Table(keys) if is_header(text, table) => {
                    Ok(joint(text, table.span(), keys, &headers))
                }
                _ => Err(format!(
                    "{}: --description-out rewrites [[joints]] tables, not an inline array of them",
                    at(table.span().start)
                )),
            })
            .collect::<Result<_, String>>()?;
        Ok(Self {
            text,
            joints,
            edits: Vec::new(),
        })
    }

    /// The number of `[[joints]]` tables.
    pub fn len(&self) -> usize {
        self.joints.len()
    }

    /// Gives `key` of joint `joint` (0-based) the value `value` (TOML, as it will be written):
    /// in place of its value if it has one, on a new line after its last key if not.
    pub fn set(&mut self, joint: usize, key: &str, value: String) {
        let table = &self.joints[joint];
        match table.entries.iter().find(|(k, _)| k == key) {
            Some((_, entry)) => self.edits.push((entry.value.clone(), value)),
            None => {
                let at = table.insert_at;
                let line = format!("{}{key} = {value}\n", table.indent);
                self.edits.push((at..at, line));
            }
        }
    }

    /// Removes `key`'s lines from joint `joint`, if it has that key.
    pub fn remove(&mut self, joint: usize, key: &str) {
        let table = &self.joints[joint];
        if let Some((_, entry)) = table.entries.iter().find(|(k, _)| k == key) {
            self.edits.push((entry.lines.clone(), String::new()));
        }
    }

    /// The text with the edits made.
    pub fn finish(mut self) -> String {
        // Stable: new keys at the same place keep the order they were given in.
        self.edits.sort_by_key(|(range, _)| range.start);
        let mut out = String::with_capacity(self.text.len());
        let mut done = 0;
        for (range, new) in &self.edits {
            out.push_str(&self.text[done..range.start]);
            // A new line at the end of a text whose last line has no newline.
            if range.is_empty() && !out.is_empty() && !out.ends_with('\n') {
                out.push('\n');
            }
            out.push_str(new);
            done = range.end;
        }
        out.push_str(&self.text[done..]);
        out
    }
}

/// A joint table with header span `header` and keys `keys`: where each key's value and lines
/// are, and where a new key goes (before the next header, `[joints.origin]` or another joint).
fn joint(text: &str, header: Range<usize>, keys: &DeTable, headers: &[usize]) -> Joint {
    let region_end = headers
        .iter()
        .copied()
        .find(|&h| h > header.start)
        .unwrap_or(text.len());
    let mut entries = Vec::new();
    let mut last = None::<(usize, usize)>;
    for (key, value) in keys {
        // A sub-table with a header of its own (`[joints.origin]`) is after this table's keys.
        let Some(end) = last_end(text, value).filter(|&end| end <= region_end) else {
            continue;
        };
        let key_start = key.span().start;
        if last.is_none_or(|(_, e)| end > e) {
            last = Some((key_start, end));
        }
        entries.push((
            key.get_ref().to_string(),
            Entry {
                value: value.span(),
                lines: line_start(text, key_start)..line_end(text, end),
            },
        ));
    }
    let (insert_at, indent) = match last {
        Some((key_start, end)) => {
            let start = line_start(text, key_start);
            (line_end(text, end), text[start..key_start].to_string())
        }
        None => (line_end(text, header.end), String::new()),
    };
    Joint {
        entries,
        insert_at,
        indent,
    }
}

/// The end of the last value `value` writes in the text: its own end, or for a dotted key
/// (`origin.xyz = [..]`, whose table has the key's span) its last leaf's. `None` for a table
/// or an array of tables with a header of its own.
fn last_end(text: &str, value: &Spanned<DeValue>) -> Option<usize> {
    let written = &text[value.span()];
    match value.get_ref() {
        DeValue::Table(_) if written.starts_with('[') => None,
        DeValue::Array(items) if items.first().is_some_and(|t| is_header(text, t)) => None,
        DeValue::Table(keys) if !written.starts_with('{') => {
            keys.values().filter_map(|v| last_end(text, v)).max()
        }
        _ => Some(value.span().end),
    }
}

/// The starts of the table headers (`[a]`, `[[a]]`) in `table`, at any depth.
fn headers_in(text: &str, table: &DeTable, headers: &mut Vec<usize>) {
    for value in table.values() {
        let span = value.span();
        match value.get_ref() {
            DeValue::Table(keys) => {
                if text[span.clone()].starts_with('[') {
                    headers.push(span.start);
                }
                headers_in(text, keys, headers);
            }
            DeValue::Array(items) => {
                for item in items.iter() {
                    if let DeValue::Table(keys) = item.get_ref() {
                        if is_header(text, item) {
                            headers.push(item.span().start);
                        }
                        headers_in(text, keys, headers);
                    }
                }
            }
            _ => {}
        }
    }
}

/// Whether `item`, an element of an array, is a table with a header (`[[joints]]`), not an
/// inline table.
fn is_header(text: &str, item: &Spanned<DeValue>) -> bool {
    matches!(item.get_ref(), DeValue::Table(_)) && text[item.span()].starts_with("[[")
}

/// The start of the line holding byte `offset`.
fn line_start(text: &str, offset: usize) -> usize {
    text[..offset].rfind('\n').map_or(0, |i| i + 1)
}

/// Past the end of the line holding byte `offset` (its newline included).
fn line_end(text: &str, offset: usize) -> usize {
    text[offset..]
        .find('\n')
        .map_or(text.len(), |i| offset + i + 1)
}

/// `line:column` (1-based, in characters) of byte `offset`.
fn position(text: &str, offset: usize) -> String {
    let start = line_start(text, offset);
    let line = text[..start].matches('\n').count() + 1;
    let column = text[start..offset].chars().count() + 1;
    format!("{line}:{column}")
}

/// The parser's error, with its line and column.
fn located(text: &str, error: &toml::de::Error) -> String {
    let message = error.message().trim_end();
    match error.span() {
        Some(span) => format!("{}: {message}", position(text, span.start)),
        None => message.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::JointEdits;

    /// Comments, blank lines and the spelling of the values not edited are kept; values of
    /// other lengths (a multi-line array for a short one) replace the old ones; a removed key
    /// takes its comment along; new keys go after a joint's last key, before its sub-table.
    #[test]
    fn edits_keep_the_rest_of_the_text() {
        let text = "\
# Two links.
name = \"two\"   # its name
gravity = [0, 0, -9.81]

[[joints]]  # the shoulder
type = \"revolute\"
mass = 1     # kg, a guess
com = [0, 0,
       0.1]  # across lines
inertia = [1, 1, 1, 0, 0, 0]
check_inertia = false   # a rod

# The elbow.
[[joints]]
type = \"revolute\"
\"mass\" = 2.5
[joints.origin]
xyz = [0, 0, 0.3]
";
        let mut edits = JointEdits::new(text).expect("joints");
        assert_eq!(edits.len(), 2);
        edits.set(0, "mass", "12.25".into());
        edits.set(0, "com", "[0.0, 0.0, 0.5]".into());
        edits.remove(0, "check_inertia");
        edits.set(0, "friction_viscous", "0.5".into());
        edits.set(1, "mass", "3.0".into());
        edits.set(1, "com", "[0.125, 0.0, 0.0]".into());
        edits.set(1, "actuator_inertia", "1e-19".into());
        edits.remove(1, "gear_ratio");
        let expected = "\
# Two links.
name = \"two\"   # its name
gravity = [0, 0, -9.81]

[[joints]]  # the shoulder
type = \"revolute\"
mass = 12.25     # kg, a guess
com = [0.0, 0.0, 0.5]  # across lines
inertia = [1, 1, 1, 0, 0, 0]
friction_viscous = 0.5

# The elbow.
[[joints]]
type = \"revolute\"
\"mass\" = 3.0
com = [0.125, 0.0, 0.0]
actuator_inertia = 1e-19
[joints.origin]
xyz = [0, 0, 0.3]
";
        assert_eq!(edits.finish(), expected);
    }

    /// A new key after a dotted key, indented as the keys before it, on a line of its own
    /// when the file's last line has no newline.
    #[test]
    fn new_keys_follow_the_last_line_of_the_table() {
        let text = "gravity = [0, 0, -9.81]\n[[joints]]\n  type = \"prismatic\"\n  \
                    origin.xyz = [0, 0, 1]\n  mass = 1\n  origin.rpy = [\n    0, 0, 0,\n  ]";
        let mut edits = JointEdits::new(text).expect("joints");
        edits.set(0, "friction_offset", "-0.25".into());
        edits.set(0, "friction_coulomb", "2.0".into());
        let expected = "gravity = [0, 0, -9.81]\n[[joints]]\n  type = \"prismatic\"\n  \
                        origin.xyz = [0, 0, 1]\n  mass = 1\n  origin.rpy = [\n    0, 0, 0,\n  ]\n  \
                        friction_offset = -0.25\n  friction_coulomb = 2.0\n";
        assert_eq!(edits.finish(), expected);
    }

    /// Inline tables are edited in place like any value; a key that is not there is not
    /// removed from anywhere else.
    #[test]
    fn inline_values_are_replaced_whole() {
        let text = "[[joints]]\ntype = \"revolute\"\norigin = { xyz = [0, 0, 1] }\n\
                    mass = 1\n[[joints]]\ntype = \"revolute\"\nmass = 2\n";
        let mut edits = JointEdits::new(text).expect("joints");
        edits.set(0, "origin", "{ xyz = [1, 2, 3] }".into());
        edits.remove(1, "check_inertia");
        let expected = "[[joints]]\ntype = \"revolute\"\norigin = { xyz = [1, 2, 3] }\n\
                        mass = 1\n[[joints]]\ntype = \"revolute\"\nmass = 2\n";
        assert_eq!(edits.finish(), expected);
    }

    /// What the rewrite cannot edit is refused with its line and column.
    #[test]
    fn texts_without_joint_tables_are_refused_where_they_fail() {
        let error = |text: &str| JointEdits::new(text).err().expect("refused");
        assert_eq!(
            error("name = \"x\"\njoints = [\n  { type = \"revolute\", mass = 1 },\n]\n"),
            "3:3: --description-out rewrites [[joints]] tables, not an inline array of them"
        );
        assert_eq!(
            error("gravity = [0, 0, -9.81]\n[joints]\nmass = 1\n"),
            "2:1: `joints` is not [[joints]] tables"
        );
        assert_eq!(
            error("gravity = [0, 0, -9.81]\n"),
            "the description has no [[joints]] tables"
        );
        assert!(
            error("[[joints]]\nmass = = 1\n").starts_with("2:"),
            "{}",
            error("[[joints]]\nmass = = 1\n")
        );
    }
}

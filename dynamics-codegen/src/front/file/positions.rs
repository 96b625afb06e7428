//! Where a description file writes each joint's values: 1-based lines and columns, so that
//! checks made after loading can point into the file.

use crate::front::sources::At;
use std::collections::BTreeMap;

/// The 1-based line and column (in characters) of a byte offset.
pub(super) fn line_column(text: &str, offset: usize) -> (Option<usize>, Option<usize>) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.chars().count()
        - before
            .rfind('\n')
            .map_or(0, |p| before[..=p].chars().count())
        + 1;
    (Some(line), Some(column))
}

/// Per joint, the line and column of each key's value, from its byte offset.
pub(super) fn positions_at(
    text: &str,
    joints: impl IntoIterator<Item = Vec<(String, usize)>>,
) -> Vec<BTreeMap<String, At>> {
    joints
        .into_iter()
        .map(|keys| {
            keys.into_iter()
                .filter_map(|(key, offset)| match line_column(text, offset) {
                    (Some(l), Some(c)) => Some((key, (l, c))),
                    _ => None,
                })
                .collect()
        })
        .collect()
}

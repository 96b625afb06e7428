//! The mutations of a text that know nothing of its format: a bit flipped, bytes deleted or
//! duplicated, a line of another base text spliced in.

use proptest::prelude::*;
use proptest::sample::Index;

/// A mutation of a text's bytes.
#[derive(Clone, Debug)]
pub enum Bytes {
    Flip(Index, u8),
    Delete(Index, usize),
    Duplicate(Index, usize),
    /// A line of another base text inserted before a line of this one.
    Splice {
        file: Index,
        line: Index,
        before: Index,
    },
}

impl Bytes {
    /// Each kind as likely as the others; a run of up to `longest` bytes duplicated.
    pub fn strategy(longest: usize) -> impl Strategy<Value = Bytes> {
        prop_oneof![
            (any::<Index>(), 0..8u8).prop_map(|(i, b)| Bytes::Flip(i, b)),
            (any::<Index>(), 1..64usize).prop_map(|(i, n)| Bytes::Delete(i, n)),
            (any::<Index>(), 1..longest).prop_map(|(i, n)| Bytes::Duplicate(i, n)),
            (any::<Index>(), any::<Index>(), any::<Index>())
                .prop_map(|(file, line, before)| Bytes::Splice { file, line, before }),
        ]
    }

    /// Applies the mutation to `text`; a splice takes its line from one of `bases`.
    pub fn apply(&self, text: &mut Vec<u8>, bases: &[&str]) {
        let at = |i: &Index, text: &Vec<u8>| i.index(text.len() + 1);
        match self {
            Bytes::Flip(i, bit) if !text.is_empty() => {
                let i = i.index(text.len());
                text[i] ^= 1 << bit;
            }
            Bytes::Flip(..) => {}
            Bytes::Delete(i, n) => {
                let i = at(i, text);
                text.drain(i..(i + n).min(text.len()));
            }
            Bytes::Duplicate(i, n) => {
                let i = at(i, text);
                let copy = text[i..(i + n).min(text.len())].to_vec();
                text.splice(i..i, copy);
            }
            Bytes::Splice { file, line, before } => {
                let other = file.get(bases).as_bytes();
                let from = super::line_start(other, *line);
                let end = other[from..]
                    .iter()
                    .position(|b| *b == b'\n')
                    .map_or(other.len(), |e| from + e + 1);
                let to = super::line_start(text, *before);
                text.splice(to..to, other[from..end].to_vec());
            }
        }
    }
}

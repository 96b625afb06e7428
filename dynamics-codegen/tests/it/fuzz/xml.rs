//! Where the tags and attributes of an XML text are, found leniently (a fuzzed text is seldom
//! well formed): enough for the URDF fuzzer to rename, delete and copy them.

use std::ops::Range;

/// `<name ...>`, `</name>` or `<name .../>`.
pub struct Tag {
    /// From `<` to after `>`.
    pub range: Range<usize>,
    pub name: Range<usize>,
    pub closing: bool,
}

/// `name="value"` in a start tag.
pub struct Attribute {
    /// From the name to after the closing quote.
    pub range: Range<usize>,
    pub name: Range<usize>,
    pub value: Range<usize>,
}

fn is_name(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b"_:-.".contains(&b)
}

/// The tags of `text`, in order; a `<` not followed by a name (a comment, `<?xml`) is skipped.
pub fn tags(text: &[u8]) -> Vec<Tag> {
    let mut found = Vec::new();
    let mut i = 0;
    while let Some(offset) = text[i..].iter().position(|b| *b == b'<') {
        let start = i + offset;
        let closing = text.get(start + 1) == Some(&b'/');
        let name_start = start + 1 + usize::from(closing);
        let name_end = (name_start..text.len())
            .find(|&j| !is_name(text[j]))
            .unwrap_or(text.len());
        let Some(end) = text[start..].iter().position(|b| *b == b'>') else {
            break;
        };
        if name_end > name_start {
            found.push(Tag {
                range: start..start + end + 1,
                name: name_start..name_end,
                closing,
            });
            i = start + end + 1;
        } else {
            i = start + 1;
        }
    }
    found
}

/// The byte range of the element that tag `k` starts: up to its end tag, or the tag alone
/// (an empty element, an end tag, or a start tag whose end tag is missing).
pub fn element(text: &[u8], tags: &[Tag], k: usize) -> Range<usize> {
    let tag = &tags[k];
    let empty = text[..tag.range.end].ends_with(b"/>");
    if tag.closing || empty {
        return tag.range.clone();
    }
    let name = &text[tag.name.clone()];
    let mut depth = 0usize;
    for other in &tags[k + 1..] {
        if &text[other.name.clone()] != name {
            continue;
        }
        if !other.closing {
            depth += usize::from(!text[..other.range.end].ends_with(b"/>"));
        } else if depth == 0 {
            return tag.range.start..other.range.end;
        } else {
            depth -= 1;
        }
    }
    tag.range.clone()
}

/// The attributes of the start tags `tags`, in order.
pub fn attributes(text: &[u8], tags: &[Tag]) -> Vec<Attribute> {
    let mut found = Vec::new();
    for tag in tags.iter().filter(|t| !t.closing) {
        let mut j = tag.name.end;
        while j < tag.range.end {
            let start = j;
            while j < tag.range.end && is_name(text[j]) {
                j += 1;
            }
            let quote = j + 1;
            let opens = j > start
                && j < tag.range.end
                && text[j] == b'='
                && matches!(text.get(quote), Some(b'"' | b'\''));
            if !opens {
                j += 1;
                continue;
            }
            let Some(length) = text[quote + 1..tag.range.end]
                .iter()
                .position(|b| *b == text[quote])
            else {
                break;
            };
            let end = quote + 1 + length;
            found.push(Attribute {
                range: start..end + 1,
                name: start..j,
                value: quote + 1..end,
            });
            j = end + 1;
        }
    }
    found
}

/// The names of the links of `text`: the `name` of each `<link>`.
pub fn link_names(text: &[u8]) -> Vec<String> {
    let tags = tags(text);
    let links: Vec<Tag> = tags
        .into_iter()
        .filter(|t| !t.closing && &text[t.name.clone()] == b"link")
        .collect();
    attributes(text, &links)
        .into_iter()
        .filter(|a| &text[a.name.clone()] == b"name")
        .map(|a| String::from_utf8_lossy(&text[a.value]).into_owned())
        .collect()
}

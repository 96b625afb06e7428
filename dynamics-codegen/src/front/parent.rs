//! A joint's antecedent in a tree, named in the attribute or a description file by an earlier
//! joint's 1-based number (0: the base) or by its `name`: one resolution and one wording for
//! both, so that a parent must come earlier (the joints make no cycle) wherever it is given.

use std::collections::BTreeMap;

/// A `parent` as written: a number or a name.
#[derive(Clone, Copy)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum ParentRef<'a> {
    Number(u64),
    Name(&'a str),
}

/// Joint `i`'s (0-based) antecedent: an earlier joint (0-based), or `None` for the base;
/// `count` joints, `names` the index of each named one. The message names the parent as
/// written, for the caller to place (and to prefix with the joint it is about).
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn resolve(
    i: usize,
    parent: ParentRef,
    count: usize,
    names: &BTreeMap<&str, usize>,
) -> Result<Option<usize>, String> {
    let (index, said) = match parent {
        ParentRef::Number(0) => return Ok(None),
        ParentRef::Number(k) => {
            let k = usize::try_from(k).unwrap_or(usize::MAX);
            if k > count {
                return Err(format!(
                    "parent {k}: there is no joint {k} ({count} are given; 0 is the base)"
                ));
            }
            (k - 1, format!("joint {k}"))
        }
        ParentRef::Name(name) => match names.get(name) {
            Some(&k) => (k, format!("`{name}` (joint {})", k + 1)),
            None => return Err(unknown_name(name, names)),
        },
    };
    match index.cmp(&i) {
        std::cmp::Ordering::Less => Ok(Some(index)),
        std::cmp::Ordering::Equal => Err(format!(
            "parent {said}: a joint cannot hang from itself (a cycle)"
        )),
        std::cmp::Ordering::Greater => Err(format!(
            "parent {said} comes after it: declare a parent before its children (a later one \
             could close a cycle)"
        )),
    }
}

/// No joint is called `name`: the message lists the names there are.
fn unknown_name(name: &str, names: &BTreeMap<&str, usize>) -> String {
    let known: Vec<String> = names.keys().map(|n| format!("`{n}`")).collect();
    let known = if known.is_empty() {
        "no joint has a `name`".to_string()
    } else {
        format!("the joints named are {}", known.join(", "))
    };
    format!("parent `{name}`: no joint has that name ({known})")
}

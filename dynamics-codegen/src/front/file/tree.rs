//! Trees in a description file: each joint's `parent` (an earlier joint's 1-based number, 0
//! for the base, or its `name`; by default the joint before) and, in a modified D-H table,
//! Khalil-Kleinfinger's `gamma` and `b`; a mimic joint's `mimic = { joint = .., multiplier =
//! .., offset = .. }` (the joint followed by number or name, before or after it). Each mistake
//! is deferred to its joint's key.

use super::schema::{Deferred, FileJoint, FileParent};
use crate::front::parent::{resolve, ParentRef};
use crate::model::{snap_angle, Branch, Convention, Mimic, Value};
use std::collections::BTreeMap;

impl FileParent {
    fn as_ref(&self) -> ParentRef<'_> {
        match self {
            FileParent::Number(n) => ParentRef::Number(*n),
            FileParent::Name(name) => ParentRef::Name(name),
        }
    }
}

/// Per joint, its mimic rule, with every problem deferred to its `mimic` key (the model's
/// check refuses a mimic of a mimic joint and a mimic of the other kind).
pub(super) fn mimics(joints: &[FileJoint], deferred: &mut Vec<Deferred>) -> Vec<Option<Mimic>> {
    if joints.iter().all(|j| j.mimic.is_none()) {
        return vec![None; joints.len()];
    }
    let names: BTreeMap<&str, usize> = joints
        .iter()
        .enumerate()
        .filter_map(|(i, j)| Some((j.name.as_deref()?, i)))
        .collect();
    let count = joints.len();
    let value = |v: &Option<super::schema::FileValue>, default: Value| {
        v.as_ref().map_or(default, |v| v.0.clone())
    };
    let mut mimics = Vec::with_capacity(count);
    for (i, j) in joints.iter().enumerate() {
        let Some(m) = &j.mimic else {
            mimics.push(None);
            continue;
        };
        let followed = match &m.joint {
            FileParent::Number(n) => usize::try_from(*n)
                .ok()
                .filter(|n| (1..=count).contains(n))
                .map(|n| n - 1)
                .ok_or_else(|| format!("mimic joint {n}: there is no joint {n} (the file has {count}, numbered from 1)")),
            FileParent::Name(name) => names
                .get(name.as_str())
                .copied()
                .ok_or_else(|| format!("mimic joint `{name}`: no joint has that name")),
        };
        let followed = followed.and_then(|k| {
            if k == i {
                Err("a joint cannot mimic itself".to_string())
            } else {
                Ok(k)
            }
        });
        match followed {
            Ok(k) => mimics.push(Some(Mimic {
                joint: k,
                multiplier: value(&m.multiplier, Value::num(crate::symbolic::Number::ONE)),
                offset: value(&m.offset, Value::zero()),
            })),
            Err(message) => {
                deferred.push((i, "mimic", message));
                mimics.push(None);
            }
        }
    }
    mimics
}

/// Whether some joint gives `name`, `parent`, `gamma` or `b`.
fn given(joints: &[FileJoint]) -> bool {
    joints
        .iter()
        .any(|j| j.name.is_some() || j.parent.is_some() || j.gamma.is_some() || j.b.is_some())
}

/// Per joint, its branch: `None` everywhere for a chain (no joint names another antecedent
/// than the one before, and γ = b = 0), with every problem deferred.
pub(super) fn branches(
    joints: &[FileJoint],
    convention: Convention,
    frames_given: bool,
    deferred: &mut Vec<Deferred>,
) -> Vec<Option<Branch>> {
    if !given(joints) {
        return vec![None; joints.len()];
    }
    let names = names(joints, deferred);
    let mut branches = Vec::with_capacity(joints.len());
    for (i, j) in joints.iter().enumerate() {
        let parent = match &j.parent {
            None => i.checked_sub(1),
            Some(parent) => {
                resolve(i, parent.as_ref(), joints.len(), &names).unwrap_or_else(|message| {
                    deferred.push((i, "parent", message));
                    i.checked_sub(1)
                })
            }
        };
        if convention == Convention::Standard && !frames_given && j.parent.is_some() {
            deferred.push((i, "parent", "a standard D-H table has no antecedent column: trees are given in the modified convention (Khalil-Kleinfinger); add `convention = \"modified\"` and write the rows in it".into()));
        }
        for (key, v) in [("gamma", &j.gamma), ("b", &j.b)] {
            if v.is_none() {
                continue;
            }
            if frames_given {
                deferred.push((i, key, format!("`{key}` is a D-H parameter of a tree (Khalil-Kleinfinger); a joint given by `origin` and `axis` has it derived: remove it")));
            } else if convention == Convention::Standard {
                deferred.push((i, key, format!("`{key}` is Khalil-Kleinfinger's, of the modified convention: add `convention = \"modified\"` and write the rows in it")));
            }
        }
        let value = |v: &Option<super::schema::FileValue>| {
            v.as_ref().map_or_else(Value::zero, |v| v.0.clone())
        };
        branches.push(Branch {
            parent,
            gamma: snap_angle(&value(&j.gamma)),
            b: value(&j.b),
        });
    }
    let serial = branches
        .iter()
        .enumerate()
        .all(|(i, b)| b.parent == i.checked_sub(1) && b.gamma.is_zero() && b.b.is_zero());
    if serial {
        vec![None; joints.len()]
    } else {
        branches.into_iter().map(Some).collect()
    }
}

/// Each joint's index by name; a name given twice is an error at the second.
fn names<'a>(joints: &'a [FileJoint], deferred: &mut Vec<Deferred>) -> BTreeMap<&'a str, usize> {
    let mut names = BTreeMap::new();
    for (i, j) in joints.iter().enumerate() {
        if let Some(name) = &j.name {
            if let Some(first) = names.insert(name.as_str(), i) {
                names.insert(name.as_str(), first);
                deferred.push((
                    i,
                    "name",
                    format!(
                        "joint {} is named `{name}` too: give each joint its own name",
                        first + 1
                    ),
                ));
            }
        }
    }
    names
}

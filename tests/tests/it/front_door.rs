//! The front door: no crate that drives the generator (the commands, identification, the
//! benchmarks, Python) names one of its stages; each enters through `dynamics_codegen::pipeline`
//! and the items the generator re-exports at its root.

use crate::layout::rust_files;
use std::path::Path;

/// The generator's stages, which only the generator itself (and its own tests) may name: every
/// other crate enters through the front door (`pipeline`, and the items `dynamics-codegen`
/// re-exports at its root), and names the robot (`model`) and the method table (`method`).
const STAGES: [&str; 12] = [
    "algo",
    "check",
    "emit",
    "emit_c",
    "front",
    "identifiers",
    "inspect",
    "numeric",
    "poly",
    "simplify",
    "symbolic",
    "trace",
];

/// The drivers of the generator: the commands, the benchmarks, Python, identification.
const DRIVERS: [&str; 5] = [
    "dynamics-cli/src",
    "bench/src",
    "bench/ffi/src",
    "python/src",
    "dynamics-identification/src",
];

/// The first path segment of each item that `dynamics_codegen::` names at the start of `text`: one
/// for a path, each of a `{..}` group's.
fn named_after(text: &str) -> Vec<&str> {
    let ident = |s: &str| -> usize {
        s.find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(s.len())
    };
    if let Some(group) = text.strip_prefix('{') {
        let mut depth = 0;
        let end = group
            .char_indices()
            .find(|&(_, c)| {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => return true,
                    '}' => depth -= 1,
                    _ => {}
                }
                false
            })
            .map_or(group.len(), |(i, _)| i);
        let mut names = Vec::new();
        let mut depth = 0;
        let mut start = 0;
        for (i, c) in group[..end].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    let item = group[start..i].trim_start();
                    names.push(&item[..ident(item)]);
                    start = i + 1;
                }
                _ => {}
            }
        }
        let item = group[start..end].trim_start();
        names.push(&item[..ident(item)]);
        names
    } else {
        vec![&text[..ident(text)]]
    }
}

#[test]
fn the_drivers_enter_the_generator_by_its_front_door() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for driver in DRIVERS {
        rust_files(&root.join(driver), &mut files);
    }
    assert!(files.len() > 20, "found only {} files", files.len());
    let mut reaching: Vec<String> = Vec::new();
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap_or_default();
        for (at, _) in text.match_indices("dynamics_codegen::") {
            let after = &text[at + "dynamics_codegen::".len()..];
            for name in named_after(after) {
                if STAGES.contains(&name) {
                    let line = text[..at].lines().count().max(1);
                    let file = path.strip_prefix(&root).unwrap_or(path).display();
                    reaching.push(format!("{file}:{line}: `{name}`"));
                }
            }
        }
    }
    assert!(
        reaching.is_empty(),
        "these reach past the front door into a stage (use or add a re-export of \
         dynamics-codegen's root): {reaching:#?}"
    );
}

/// The check above reads `use` groups as the compiler does, nested groups included.
#[test]
fn a_use_group_names_each_of_its_items() {
    assert_eq!(named_after("trace::Equations;"), ["trace"]);
    assert_eq!(
        named_after("{emit_c, generate,\n model::{Robot, Value}, Equations};"),
        ["emit_c", "generate", "model", "Equations"]
    );
}

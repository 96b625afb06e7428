//! Fuzzing the URDF front end: the real robots of `robots/urdf/`, mutated (byte flips,
//! deletions, duplications, lines spliced between files, numbers replaced by extreme values,
//! tags renamed, elements deleted or copied, attributes replaced, removed, doubled or renamed,
//! deep nesting, long names and values, and files grown to thousands of links), go through
//! `front::load_urdf`, the command-line tool's checks after it, and the derive's
//! `urdf = "..."`. Each case must finish within [`fuzz::BOUND`] without a panic, and:
//! - every error of `front::load_urdf` names a line and column inside the text (a URDF error
//!   always has an element to blame, if only `<robot>`);
//! - every `compile_error!` of the derive is on the `urdf = "..."` token (not the call site) and
//!   names `path:line:col` inside the text.
//!
//! The robots, chains and trees (`robots/urdf/trees/`), are taken with their tip (the Panda's
//! flange), their tips (Baxter's head and grippers) or with the default (every branch), so that
//! the chain's search, the tree's walk and their refusals are reached.
//!
//! proptest, seed fixed: 1,000 cases by default (about 8 s of CPU in the debug build, 14 to
//! 20 s on the 2-core machine shared with other builds; `huge_files` included). Long run:
//! `DYNAMICS_FUZZ_CASES=30000 cargo test -p dynamics-codegen --test it fuzz_urdf --release -- --nocapture`.
//! Run for issue 26: the default run found files of many links quadratic to read (more than
//! 10 s for 28,000 links; fixed, see `front/urdf/tests/errors.rs`); then 30,000 cases in
//! 10:45, and after the last fixes 60,000 in 19:47 (release build, 2 cores shared with other
//! builds), no failure.

use crate::fuzz;

use dynamics_codegen::{check, derive_dynamics, front};
use fuzz::urdf::{ATTRIBUTES, EXTREMES, PIECES, TAGS, VALUES};
use proptest::prelude::*;
use proptest::sample::Index;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::LazyLock;

/// The robots the mutations start from: every `robots/urdf/*.urdf` and `robots/urdf/trees/*.urdf`,
/// read where the crate is (not where the test runs), so that a robot added there is fuzzed too.
static BASES: LazyLock<Vec<(String, String)>> = LazyLock::new(|| {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/urdf");
    let entries = |dir: String| std::fs::read_dir(dir).expect("robots/urdf");
    let mut found: Vec<(String, String)> = entries(dir.into())
        .chain(entries(format!("{dir}/trees")))
        .map(|entry| entry.expect("an entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "urdf"))
        .map(|path| {
            let name = path.file_name().expect("a name").to_string_lossy().into();
            (name, std::fs::read_to_string(&path).expect("a URDF"))
        })
        .collect();
    found.sort();
    found
});

/// How a base is taken, besides the default (every branch): the Panda to its flange (`tip`, the
/// serial path), Baxter to its head and grippers (`tips`, the branches, above the mimic fingers
/// that the default refuses); the Allegro hand's published inertias break the triangle
/// inequality, so its inertias are not checked.
#[derive(Clone, Copy, Debug, Default)]
struct Take {
    tip: Option<&'static str>,
    tips: &'static [&'static str],
    check_inertia: bool,
}

fn take(name: &str, own: bool) -> Take {
    let mut take = Take {
        check_inertia: name != "allegro_right_hand.urdf",
        ..Take::default()
    };
    match name {
        "panda.urdf" if own => take.tip = Some("panda_link8"),
        "baxter.urdf" if own => take.tips = &["head", "right_gripper", "left_gripper"],
        _ => {}
    }
    take
}

#[derive(Clone, Debug)]
enum Mutation {
    /// A bit flipped, bytes deleted or duplicated, a line of another base file spliced in.
    Bytes(fuzz::bytes::Bytes),
    Number(Index, Index),
    /// A start or end tag's name replaced by one of [`fuzz::urdf::TAGS`].
    Rename(Index, Index),
    /// An element, from its start tag to its end tag, deleted (`copies` 0) or copied before
    /// another tag.
    Element {
        which: Index,
        to: Index,
        copies: usize,
    },
    /// An attribute's value replaced by one of [`fuzz::urdf::VALUES`] or the name of a link.
    Value(Index, Index),
    /// An attribute deleted, doubled (0, 1) or renamed to one of [`fuzz::urdf::ATTRIBUTES`].
    Attribute(Index, Index),
    Nest {
        at: Index,
        depth: usize,
        kind: u8,
    },
    Long {
        at: Index,
        len: usize,
        kind: u8,
    },
    Insert(Index, Index),
    /// The file grown by `n` links: a chain hung below a link, or as many lone links.
    Grow {
        link: Index,
        n: usize,
        chain: bool,
    },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let two = || (any::<Index>(), any::<Index>());
    prop_oneof![
        4 => fuzz::bytes::Bytes::strategy(400).prop_map(Mutation::Bytes),
        3 => two().prop_map(|(i, by)| Mutation::Number(i, by)),
        2 => two().prop_map(|(i, by)| Mutation::Rename(i, by)),
        2 => (any::<Index>(), any::<Index>(), 0..4usize)
            .prop_map(|(which, to, copies)| Mutation::Element { which, to, copies }),
        3 => two().prop_map(|(i, by)| Mutation::Value(i, by)),
        2 => two().prop_map(|(i, how)| Mutation::Attribute(i, how)),
        1 => (any::<Index>(), 1..20_000usize, 0..3u8)
            .prop_map(|(at, depth, kind)| Mutation::Nest { at, depth, kind }),
        1 => (any::<Index>(), 1..200_000usize, 0..4u8)
            .prop_map(|(at, len, kind)| Mutation::Long { at, len, kind }),
        2 => two().prop_map(|(i, p)| Mutation::Insert(i, p)),
        1 => (any::<Index>(), 1..20_000usize, any::<bool>())
            .prop_map(|(link, n, chain)| Mutation::Grow { link, n, chain }),
    ]
}

fn apply(text: &mut Vec<u8>, m: &Mutation) {
    let at = |i: &Index, text: &Vec<u8>| i.index(text.len() + 1);
    match m {
        Mutation::Bytes(bytes) => bytes.apply(
            text,
            &BASES.iter().map(|(_, t)| t.as_str()).collect::<Vec<_>>(),
        ),
        Mutation::Number(which, by) => {
            let spans = fuzz::numbers(text);
            if !spans.is_empty() {
                let (s, e) = *which.get(&spans);
                text.splice(s..e, by.get(&EXTREMES).bytes());
            }
        }
        Mutation::Nest { at: i, depth, kind } => {
            let (open, close) = match kind {
                0 => ("<a>", "</a>"),
                1 => ("<link name=\"n\">", "</link>"),
                _ => ("<inertial>", "</inertial>"),
            };
            let nested = open.repeat(*depth) + &close.repeat(*depth);
            let i = at(i, text);
            text.splice(i..i, nested.bytes());
        }
        Mutation::Long { at: i, len, kind } => {
            let long = match kind {
                0 => "a".repeat(*len),
                1 => "9".repeat(*len),
                2 => format!("<link name=\"{}\"/>", "l".repeat(*len)),
                _ => format!("<a {}=\"1\"/>", "b".repeat(*len)),
            };
            let i = at(i, text);
            text.splice(i..i, long.bytes());
        }
        Mutation::Insert(i, p) => {
            let i = at(i, text);
            text.splice(i..i, p.get(&PIECES).bytes());
        }
        _ => apply_xml(text, m),
    }
}

/// The mutations that follow the XML's structure.
fn apply_xml(text: &mut Vec<u8>, m: &Mutation) {
    let tags = fuzz::xml::tags(text);
    let attributes = fuzz::xml::attributes(text, &tags);
    match m {
        Mutation::Rename(which, by) if !tags.is_empty() => {
            let name = which.get(&tags).name.clone();
            text.splice(name, by.get(&TAGS).bytes());
        }
        Mutation::Element { which, to, copies } if !tags.is_empty() => {
            let element = fuzz::xml::element(text, &tags, which.index(tags.len()));
            let copy = text[element.clone()].repeat(*copies);
            let to = to.get(&tags).range.start;
            if *copies == 0 {
                text.drain(element);
            } else {
                text.splice(to..to, copy);
            }
        }
        Mutation::Value(which, by) if !attributes.is_empty() => {
            let links = fuzz::xml::link_names(text);
            let i = by.index(VALUES.len() + links.len());
            let value = VALUES
                .get(i)
                .map_or_else(|| links[i - VALUES.len()].clone(), |v| (*v).into());
            let range = which.get(&attributes).value.clone();
            text.splice(range, value.into_bytes());
        }
        Mutation::Attribute(which, how) if !attributes.is_empty() => {
            let attribute = which.get(&attributes);
            match how.index(ATTRIBUTES.len() + 2) {
                0 => drop(text.drain(attribute.range.clone())),
                1 => {
                    let copy = [b" ", &text[attribute.range.clone()]].concat();
                    text.splice(attribute.range.end..attribute.range.end, copy);
                }
                n => drop(text.splice(attribute.name.clone(), ATTRIBUTES[n - 2].bytes())),
            }
        }
        Mutation::Grow { link, n, chain } => grow(text, link, *n, *chain),
        _ => {}
    }
}

/// `n` links more before `</robot>`: a chain of revolute joints below one of the file's links,
/// or lone links (each a root).
fn grow(text: &mut Vec<u8>, link: &Index, n: usize, chain: bool) {
    let links = fuzz::xml::link_names(text);
    let mut parent = if links.is_empty() {
        "world".to_string()
    } else {
        link.get(&links).clone()
    };
    let mut more = String::new();
    for i in 0..n {
        more += &format!("<link name=\"grown{i}\"/>\n");
        if chain {
            more += &format!("<joint name=\"grown_joint{i}\" type=\"revolute\"><parent link=\"{parent}\"/><child link=\"grown{i}\"/><axis xyz=\"0 0 1\"/></joint>\n");
            parent = format!("grown{i}");
        }
    }
    let end = text
        .windows(8)
        .rposition(|w| w == b"</robot>")
        .unwrap_or(text.len());
    text.splice(end..end, more.into_bytes());
}

/// Cases that gave errors and that gave a robot: the fuzzing must reach both, or it tests
/// little.
static ERRORS: AtomicUsize = AtomicUsize::new(0);
static ROBOTS: AtomicUsize = AtomicUsize::new(0);

/// Loads `text` as `path` the ways the tools do; the first broken promise, if any.
fn check_file(path: &str, text: &str, take: Take) -> Result<(), String> {
    let chain = front::Chain {
        base: None,
        tip: take.tip,
        tips: take.tips,
    };
    let lines = fuzz::Lines::of(text);
    match front::load_urdf(path, text, chain, take.check_inertia) {
        Err(errors) if errors.is_empty() => return Err("an empty list of errors".into()),
        Err(errors) => {
            ERRORS.fetch_add(1, Ordering::Relaxed);
            for e in errors {
                match (e.line, e.column) {
                    (Some(l), Some(c)) if lines.inside(l, c) => {}
                    _ => return Err(format!("error without a position in the text: {e}")),
                }
            }
        }
        // The command-line tool's checks after loading.
        Ok(loaded) => {
            ROBOTS.fetch_add(1, Ordering::Relaxed);
            for problem in check::robot(&loaded.robot, &loaded.check_inertia) {
                let message = loaded.describe(path, &problem);
                if !lines.pointed_at(&message, path) {
                    return Err(format!("check without a position: {message}"));
                }
            }
        }
    }
    check_derive(path, text, &lines, take)
}

/// The derive's `urdf = "..."` on `text`, written to a temporary file.
fn check_derive(path: &str, text: &str, lines: &fuzz::Lines, take: Take) -> Result<(), String> {
    let file = fuzz::temp_file(path, text).map_err(|e| e.to_string())?;
    let file_name = file.display().to_string();
    let mut keys = take
        .tip
        .map_or_else(String::new, |t| format!(", tip = \"{t}\""));
    if !take.tips.is_empty() {
        keys += &format!(", tips = {:?}", take.tips);
    }
    if !take.check_inertia {
        keys += ", check_inertia = false";
    }
    let source = format!("#[dynamics(urdf = \"{file_name}\"{keys})] struct R;");
    let out = derive_dynamics(source.parse().expect("tokens"));
    let _ = std::fs::remove_file(&file);
    for e in fuzz::compile_errors(out) {
        if e.at.is_none() {
            return Err(format!("derive error on the call site: {}", e.message));
        }
        if !lines.pointed_at(&e.message, &file_name) {
            return Err(format!("derive error without a position: {}", e.message));
        }
    }
    Ok(())
}

/// Runs the mutated file through the checks on a bounded thread, with the base's tip or the
/// default chain.
fn run(base: usize, own_tip: bool, mutations: &[Mutation]) -> Result<(), TestCaseError> {
    let (name, text) = &BASES[base];
    let mut bytes = text.as_bytes().to_vec();
    for m in mutations {
        apply(&mut bytes, m);
    }
    let text = String::from_utf8_lossy(&bytes).into_owned();
    let shown: String = text.chars().take(4000).collect();
    let take = take(name, own_tip);
    let name = name.clone();
    let what = format!("{name} ({take:?}), {mutations:?}:\n{shown}");
    fuzz::bounded(&what, move || check_file(&name, &text, take))
        .and_then(|r| r)
        .map_err(TestCaseError::fail)
}

#[test]
fn mutated_urdf_files() {
    let strategy = (
        0..BASES.len(),
        any::<bool>(),
        prop::collection::vec(mutation(), 1..5),
    );
    fuzz::runner(26, 1000)
        .run(&strategy, |(base, own_tip, mutations)| {
            run(base, own_tip, &mutations)
        })
        .unwrap();
    let [errors, robots] = [&ERRORS, &ROBOTS].map(|n| n.load(Ordering::Relaxed));
    println!("{errors} gave errors, {robots} gave a robot");
    assert!(errors > 100 && robots > 100, "{errors} / {robots}");
}

/// The mutations start from robots that load, each with its tip, and that derive.
#[test]
fn the_bases_load() {
    assert!(BASES.len() >= 5, "{:?}", BASES.iter().map(|b| &b.0));
    for (name, text) in BASES.iter() {
        let take = take(name, true);
        let chain = front::Chain {
            base: None,
            tip: take.tip,
            tips: take.tips,
        };
        if let Err(e) = front::load_urdf(name, text, chain, take.check_inertia) {
            panic!("{name}: {e:?}");
        }
        check_derive(name, text, &fuzz::Lines::of(text), take).unwrap();
    }
}

/// `text` with `more` before `</robot>`.
fn before_end(text: &str, more: &str) -> String {
    let end = text.rfind("</robot>").expect("</robot>");
    format!("{}{more}{}", &text[..end], &text[end..])
}

/// Files of megabytes, each as the fuzzing grows them but larger: loaded (and derived) within
/// the bound, every error at its place.
#[test]
fn huge_files() {
    let ur5 = &BASES.iter().find(|b| b.0 == "ur5.urdf").expect("ur5").1;
    let n = 20_000;
    let lone: String = (0..n)
        .map(|i| format!("<link name=\"lone{i}\"/>\n"))
        .collect();
    let chain = |kind: &str| -> String {
        (0..n)
            .map(|i| {
                let parent = if i == 0 { "tool0".to_string() } else { format!("c{}", i - 1) };
                format!("<link name=\"c{i}\"/><joint name=\"cj{i}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"c{i}\"/><origin xyz=\"0.1 0 0\" rpy=\"0 0.5 0\"/></joint>\n")
            })
            .collect()
    };
    // A tree as wide as the chains are long: every joint on the flange.
    let fan: String = (0..n)
        .map(|i| format!("<link name=\"f{i}\"/><joint name=\"fj{i}\" type=\"revolute\"><parent link=\"tool0\"/><child link=\"f{i}\"/><origin xyz=\"0.1 0 0\"/></joint>\n"))
        .collect();
    let cases = [
        ("lone links", before_end(ur5, &lone)),
        ("a moving chain", before_end(ur5, &chain("revolute"))),
        ("a fixed chain", before_end(ur5, &chain("fixed"))),
        ("a fan of branches", before_end(ur5, &fan)),
        (
            "a long number",
            ur5.replacen("0.089159", &"9".repeat(10_000_000), 1),
        ),
        (
            "deep nesting",
            before_end(ur5, &("<a>".repeat(n) + &"</a>".repeat(n))),
        ),
        (
            "one line",
            before_end(ur5, &lone.replace('\n', " ")).replace('\n', " "),
        ),
    ];
    for (what, text) in cases {
        let start = std::time::Instant::now();
        let name = format!("{what}.urdf");
        fuzz::bounded(what, move || {
            check_file(
                &name,
                &text,
                Take {
                    check_inertia: true,
                    ..Take::default()
                },
            )
        })
        .and_then(|r| r)
        .unwrap();
        println!("{what}: {:?}", start.elapsed());
    }
}

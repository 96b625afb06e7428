//! Fuzzing the attribute parser: valid `#[derive(Dynamics)]` inputs, as token trees, mutated
//! (tokens deleted, duplicated, swapped, literals and identifiers replaced, tokens nested in
//! brackets), go through `derive_dynamics`. Each case must finish within [`fuzz::BOUND`]
//! without a panic, and give code or `compile_error!`s, each on a token of the input: its span
//! has a line and column. That holds for every error the fuzzing reaches; an error on the call
//! site (no token to blame) would fail the test.
//!
//! The mutated tokens are printed and lexed again, as rustc would hand them to the derive, so
//! that every token has a position; what does not lex (an unbalanced bracket) is skipped, as
//! rustc rejects it before any macro sees it.
//!
//! proptest, seed fixed: 1,500 cases by default (about 4 s in the debug build). Long run:
//! `DYNAMICS_FUZZ_CASES=60000 cargo test -p dynamics-codegen --test it fuzz_attributes -- --nocapture`.
//! Run for issue 15: 60,000 cases in 5 min (debug build, 2 cores shared with other builds),
//! 15,318 did not lex, 42,321 gave errors, 2,361 gave code; no failure.

use crate::fuzz;

use dynamics_codegen::derive_dynamics;
use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};
use proptest::prelude::*;
use proptest::sample::Index;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::LazyLock;

/// Cases that did not lex, that gave errors, that gave code: the fuzzing must reach the latter
/// two, or it tests nothing.
static SKIPPED: AtomicUsize = AtomicUsize::new(0);
static ERRORS: AtomicUsize = AtomicUsize::new(0);
static CODE: AtomicUsize = AtomicUsize::new(0);

/// Valid inputs: every key of the attribute, both conventions, generics, the PUMA 560, trees
/// by frames (one joint a mimic) and by modified D-H rows.
const VALID: [&str; 6] = [
    "#[dynamics(gravity = [0, 0, -9.81], joints = [revolute(name = \"palm\"),
       revolute(parent = \"palm\", xyz = [0.05, 0, 0], rpy = [0, 90 deg, 0], axis = [0, 1, 0]),
       prismatic(parent = 1, xyz = [0, l, 0.01], axis = [0.6, 0.8, 0]), revolute(parent = 0, xyz = [0, 0, 0.2],
       mimic = (joint = \"palm\", multiplier = -0.5, offset = 0.1))],
       link(mass = 0.5), link(mass = 0.1, com = [0, 0, 0.02]), link(mass = m), link(mass = 0.2))]
     struct Hand { l: f64, m: f64 }",
    "#[dynamics(convention = modified, gravity = [0, 0, -9.81], dh = [[q, 0, 0.1, 0],
       [q, 0, 0.2, 90 deg], [0, q, 0.3, 0, 1, -90 deg, 0.05], [q, 0.2, 0, 0, 0, 0.4, b]],
       link(mass = 1), link(mass = 1), link(mass = 1, com = [0, 0, 0.1]), link(mass = 1))]
     struct Tree { b: f64 }",
    "#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0.5, l1, 90 deg], [q + 0.3, 0, l2, 0], [0.2, q, 0, -pi/2]],
       link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0.1, 0.1, 0.1, 0, 0, 0]),
       link(mass = 2.5, com = [0, 0.1, 0], inertia = [0.2, 0.1, 0.15, 0.01, 0, 0], actuator_inertia = 0.05),
       link(mass = m1 * 2, spring = (k, 0.1), check_inertia = false))]
     struct Arm { l1: f64, l2: f64, m1: f64, k: f32 }",
    "#[dynamics(convention = modified, gravity = [0, -g, 0], dh = [[q, 0, 0, 0], [q, 0, 0.7, 0]],
       link(mass = 2, com = [0.35, 0, 0], inertia = [0, 2 * 0.7^2 / 12, 2 * 0.7^2 / 12, 0, 0, 0]),
       link(mass = 1.5, com = [0.35, 0, 0]))]
     struct Planar { g: f64 }",
    "#[dynamics(name = \"x\", crate = \"dynamics_runtime\", gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mass = 1))]
     pub struct One<T> where T: Copy { t: T }",
    "#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0.67183, 0, 90 deg], [q, 0, 0.4318, 0],
       [q, 0.15005, 0.0203, -90 deg], [q, 0.4318, 0, 90 deg], [q, 0, 0, -90 deg], [q, 0, 0, 0]],
       link(mass = 0, inertia = [0, 0.35, 0, 0, 0, 0], check_inertia = false),
       link(mass = 17.4, com = [-0.3638, 0.006, 0.2275], inertia = [0.13, 0.524, 0.539, 0, 0, 0]),
       link(mass = 4.8, com = [-0.0203, -0.0141, 0.07], inertia = [0.066, 0.086, 0.0125, 0, 0, 0], check_inertia = false),
       link(mass = 0.82, com = [0, 0.019, 0], inertia = [0.0018, 0.0013, 0.0018, 0, 0, 0]),
       link(mass = 0.34, inertia = [0.0003, 0.0004, 0.0003, 0, 0, 0]),
       link(mass = 0.09 + payload, com = [0, 0, 0.032], inertia = [0.00015, 0.00015, 0.00004, 0, 0, 0]))]
     struct Puma560 { payload: f64 }",
];

/// Literals that replace a literal: extremes of f64 and of the integers, other kinds.
const LITERALS: [&str; 24] = [
    "1e308",
    "1e309",
    "1e-400",
    "0",
    "0.0",
    "18446744073709551616",
    "340282366920938463463374607431768211457",
    "4.9e-324",
    "0x7fff_ffff",
    "0b1",
    "0o7",
    "1u8",
    "1.5f32",
    "1_000",
    "'c'",
    "b'c'",
    "\"s\"",
    "b\"s\"",
    "r#\"s\"#",
    "\"robots/none.json\"",
    "\"\"",
    "1e",
    "99999999999999999999999999999999999999",
    "2.",
];

/// Identifiers that replace an identifier besides the attribute's keys (`fuzz::words`): the
/// attribute's other words, and others.
const OTHER_IDENTS: [&str; 13] = [
    "modified",
    "standard",
    "true",
    "false",
    "q",
    "q0",
    "q7",
    "q99999999999999999999",
    "deg",
    "rad",
    "pi",
    "self",
    "T",
];

/// Every identifier a mutation puts in.
static IDENTS: LazyLock<Vec<&str>> = LazyLock::new(|| fuzz::words(&OTHER_IDENTS));

/// Pieces inserted anywhere.
const PIECES: [&str; 14] = [
    "=",
    ",",
    "-",
    "^",
    "*",
    "/",
    "+",
    ".",
    "[]",
    "()",
    "{}",
    "#[dynamics()]",
    "link(mass = 1)",
    "[q, 0, 1, 0]",
];

/// The tokens of a stream, flat: a group as its open and close brackets around its tokens,
/// and whether each is joined to the next (`::`, `->`).
fn flatten(stream: TokenStream, out: &mut Vec<(String, bool)>) {
    for tree in stream {
        match tree {
            TokenTree::Group(g) => {
                let (open, close) = match g.delimiter() {
                    Delimiter::Parenthesis => ("(", ")"),
                    Delimiter::Bracket => ("[", "]"),
                    Delimiter::Brace => ("{", "}"),
                    Delimiter::None => ("", ""),
                };
                out.push((open.to_string(), false));
                flatten(g.stream(), out);
                out.push((close.to_string(), false));
            }
            TokenTree::Punct(p) => {
                out.push((p.as_char().to_string(), p.spacing() == Spacing::Joint))
            }
            other => out.push((other.to_string(), false)),
        }
    }
}

#[derive(Clone, Debug)]
enum Mutation {
    Delete(Index),
    Duplicate(Index, usize),
    Swap(Index, Index),
    Literal(Index, Index),
    Ident(Index, Index),
    Insert(Index, Index),
    /// Token `at` wrapped in `depth` brackets (or parentheses).
    Nest {
        at: Index,
        depth: usize,
        paren: bool,
    },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        2 => any::<Index>().prop_map(Mutation::Delete),
        1 => (any::<Index>(), 1..6usize).prop_map(|(i, n)| Mutation::Duplicate(i, n)),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(i, j)| Mutation::Swap(i, j)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, by)| Mutation::Literal(i, by)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, by)| Mutation::Ident(i, by)),
        2 => (any::<Index>(), any::<Index>()).prop_map(|(i, p)| Mutation::Insert(i, p)),
        1 => (any::<Index>(), 1..300usize, any::<bool>())
            .prop_map(|(at, depth, paren)| Mutation::Nest { at, depth, paren }),
    ]
}

/// The positions of the tokens that `is` picks.
fn where_(tokens: &[(String, bool)], is: impl Fn(&str) -> bool) -> Vec<usize> {
    (0..tokens.len()).filter(|&i| is(&tokens[i].0)).collect()
}

fn apply(tokens: &mut Vec<(String, bool)>, m: &Mutation) {
    let piece = |s: &str| (s.to_string(), false);
    if tokens.is_empty() {
        return;
    }
    let any = |i: &Index, n: usize| i.index(n);
    match m {
        Mutation::Delete(i) => {
            tokens.remove(any(i, tokens.len()));
        }
        Mutation::Duplicate(i, n) => {
            let i = any(i, tokens.len());
            let copy = tokens[i..(i + n).min(tokens.len())].to_vec();
            tokens.splice(i..i, copy);
        }
        Mutation::Swap(i, j) => {
            let n = tokens.len();
            tokens.swap(any(i, n), any(j, n));
        }
        Mutation::Literal(i, by) | Mutation::Ident(i, by) => {
            let literal = matches!(m, Mutation::Literal(..));
            let spots = where_(tokens, |t| {
                let first = t.chars().next().unwrap_or(' ');
                if literal {
                    first.is_ascii_digit() || first == '"'
                } else {
                    first.is_alphabetic() || first == '_'
                }
            });
            if !spots.is_empty() {
                let at = *i.get(&spots);
                tokens[at] = piece(if literal {
                    by.get::<&str>(&LITERALS)
                } else {
                    by.get::<&str>(&IDENTS)
                });
            }
        }
        Mutation::Insert(i, p) => {
            let i = any(i, tokens.len() + 1);
            tokens.insert(i, piece(p.get::<&str>(&PIECES)));
        }
        Mutation::Nest { at, depth, paren } => {
            let i = any(at, tokens.len());
            let (open, close) = if *paren { ("(", ")") } else { ("[", "]") };
            tokens.insert(i + 1, piece(&close.repeat(*depth)));
            tokens.insert(i, piece(&open.repeat(*depth)));
        }
    }
}

/// The flat tokens as source text.
fn text(tokens: &[(String, bool)]) -> String {
    let mut out = String::new();
    for (t, joined) in tokens {
        out.push_str(t);
        if !joined {
            out.push(' ');
        }
    }
    out
}

/// Expands `source` (if it lexes): code, or errors each on a token. All on one thread, as
/// proc-macro2's positions are kept per thread.
fn check(source: &str) -> Result<(), String> {
    let Ok(tokens) = source.parse::<TokenStream>() else {
        SKIPPED.fetch_add(1, Ordering::Relaxed);
        return Ok(());
    };
    let out = derive_dynamics(tokens);
    let errors = fuzz::compile_errors(out.clone());
    if let Some(e) = errors.iter().find(|e| e.at.is_none()) {
        return Err(format!("error on the call site: {}", e.message));
    }
    if errors.is_empty() && !out.to_string().contains("impl") {
        return Err(format!("neither code nor an error: {out}"));
    }
    let seen = if errors.is_empty() { &CODE } else { &ERRORS };
    seen.fetch_add(1, Ordering::Relaxed);
    Ok(())
}

fn run(base: usize, mutations: &[Mutation]) -> Result<(), TestCaseError> {
    let mut tokens = Vec::new();
    flatten(VALID[base].parse().expect("valid"), &mut tokens);
    for m in mutations {
        apply(&mut tokens, m);
    }
    let source = text(&tokens);
    let shown: String = source.chars().take(4000).collect();
    fuzz::bounded(&shown, move || check(&source))
        .and_then(|r| r)
        .map_err(TestCaseError::fail)
}

#[test]
fn mutated_attributes() {
    let strategy = (0..VALID.len(), prop::collection::vec(mutation(), 1..5));
    fuzz::runner(15, 1500)
        .run(&strategy, |(base, mutations)| run(base, &mutations))
        .unwrap();
    let [skipped, errors, code] = [&SKIPPED, &ERRORS, &CODE].map(|n| n.load(Ordering::Relaxed));
    println!("{skipped} did not lex, {errors} gave errors, {code} gave code");
    assert!(errors > 100 && code > 10, "{skipped} / {errors} / {code}");
}

/// The check can fail: an error on a token has a position, one on the call site has none.
#[test]
fn positions_are_told_apart() {
    let out = fuzz::bounded("", || {
        let bad =
            "#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], link(mas = 1))]\nstruct A;";
        let on_token = fuzz::compile_errors(derive_dynamics(bad.parse().expect("lexes")));
        let on_site = syn::Error::new(proc_macro2::Span::call_site(), "x").to_compile_error();
        (
            on_token.iter().map(|e| e.at).collect::<Vec<_>>(),
            fuzz::compile_errors(on_site)
                .iter()
                .map(|e| e.at)
                .collect::<Vec<_>>(),
        )
    })
    .unwrap();
    // `mas` is the 63rd character of line 1; proc-macro2's columns are 0-based.
    assert!(out.0.contains(&Some((1, 62))), "{:?}", out.0);
    assert_eq!(out.1, vec![None]);
}

/// The valid inputs expand to code: the mutations start from inputs that work.
#[test]
fn valid_inputs_expand() {
    for source in VALID {
        let out = derive_dynamics(source.parse().expect("valid")).to_string();
        assert!(!out.contains("compile_error"), "{source}\n{out}");
    }
}

//! The derive never panics and never hangs: random token streams (mutations of valid inputs),
//! random robot tables, random description files and hand-made adversarial inputs go through
//! the front end and the generator (the library functions, not rustc). Each expansion runs on
//! its own thread under `catch_unwind` and must finish within `fuzz::BOUND`. The generator is
//! deterministic (a fixed-seed generator), so a failure is reproducible; the case is printed.

use crate::fuzz;

use dynamics_codegen::{derive_dynamics, front};
use dynamics_test_support::Rng;
use std::sync::LazyLock;
use std::time::{Duration, Instant};

/// Runs `f` under `fuzz::bounded` (its own thread, a time bound): `Err` if it panicked; with
/// the time it took.
fn bounded<T: Send + 'static>(
    what: &str,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<(T, Duration), String> {
    let start = Instant::now();
    let value = fuzz::bounded(what, f)?;
    Ok((value, start.elapsed()))
}

/// Expands `source` (if it lexes) and checks that the result is code or a compile error.
fn expand(source: &str) -> Result<Duration, String> {
    let owned = source.to_string();
    let (out, time) = bounded(source, move || {
        let tokens = owned.parse::<proc_macro2::TokenStream>().ok()?;
        Some(derive_dynamics(tokens).to_string())
    })?;
    let Some(out) = out else {
        // rustc rejects what does not lex before any macro sees it.
        return Ok(Duration::ZERO);
    };
    if out.contains("compile_error") || out.contains("impl") {
        Ok(time)
    } else {
        Err(format!(
            "neither code nor an error for:\n{source}\ngave:\n{out}"
        ))
    }
}

const VALID: [&str; 3] = [
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
     struct One<T> where T: Copy { t: T }",
];

/// Every word a mutation puts in.
static VOCABULARY: LazyLock<Vec<&str>> = LazyLock::new(|| fuzz::words(&OTHER_WORDS));

/// Words a mutation puts in besides the attribute's keys (`fuzz::words`).
const OTHER_WORDS: [&str; 39] = [
    "modified",
    "true",
    "false",
    "=",
    ",",
    "[]",
    "()",
    "[q, 0, 1, 0]",
    "q",
    "q1",
    "q2",
    "q0",
    "q18446744073709551616",
    "deg",
    "rad",
    "pi",
    "^",
    "^ 8",
    "^ 0",
    "^ 99999999999",
    "*",
    "/",
    "+",
    "-",
    "self",
    ".",
    "\"1\"",
    "\"robots/none.json\"",
    "0",
    "1",
    "-1",
    "1e308",
    "1e400",
    "0.5",
    "1_000",
    "0x10",
    "'c'",
    "m1",
    "struct",
];

/// A token-level mutation of a valid input.
fn mutate(rng: &mut Rng, source: &str) -> String {
    let mut tokens: Vec<String> = source
        .split_inclusive(|c: char| c.is_whitespace() || ",[]()=".contains(c))
        .map(str::to_string)
        .collect();
    for _ in 0..=rng.below(4) {
        if tokens.is_empty() {
            break;
        }
        let i = rng.below(tokens.len());
        match rng.below(5) {
            0 => {
                tokens.remove(i);
            }
            1 => tokens.insert(i, format!(" {} ", rng.pick(&VOCABULARY))),
            2 => tokens[i] = format!(" {} ", rng.pick(&VOCABULARY)),
            3 => {
                let t = tokens[i].clone();
                tokens.insert(i, t);
            }
            _ => {
                let j = rng.below(tokens.len());
                tokens.swap(i, j);
            }
        }
    }
    tokens.concat()
}

fn value(rng: &mut Rng, fields: &[&str]) -> String {
    match rng.below(9) {
        0 => "0".into(),
        1 => format!("{}", rng.below(2000) as f64 / 1000.0 - 1.0),
        2 => rng
            .pick(&["90 deg", "-90 deg", "pi / 2", "180 deg", "-pi", "45 deg"])
            .into(),
        3 => rng.pick(fields).into(),
        4 => format!("{} * {}", rng.pick(fields), rng.below(10)),
        5 => format!("{}^2 / 12", rng.pick(fields)),
        6 => format!("-{}", rng.below(5)),
        7 => format!("{}.{}", rng.below(3), rng.below(1000)),
        _ => format!("({} - {})", rng.pick(fields), rng.below(3)),
    }
}

/// A random robot table, physical or not, with 1 to 6 joints.
fn random_robot(rng: &mut Rng) -> String {
    let fields = ["a", "b", "m"];
    let n = 1 + rng.below(6);
    let mut rows = Vec::new();
    let mut links = Vec::new();
    for _ in 0..n {
        let (theta, d) = if rng.below(3) == 0 {
            (value(rng, &fields), "q".to_string())
        } else {
            (format!("q + {}", value(rng, &fields)), value(rng, &fields))
        };
        rows.push(format!(
            "[{theta}, {d}, {}, {}]",
            value(rng, &fields),
            value(rng, &fields)
        ));
        let v = |rng: &mut Rng| value(rng, &fields);
        links.push(format!(
            "link(mass = {}, com = [{}, {}, {}], inertia = [{}, {}, {}, {}, {}, {}]{})",
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            v(rng),
            if rng.below(2) == 0 {
                ", check_inertia = false"
            } else {
                ""
            }
        ));
    }
    format!(
        "#[dynamics(gravity = [{}, {}, {}], dh = [{}], {})] struct R {{ a: f64, b: f64, m: f32 }}",
        value(rng, &fields),
        value(rng, &fields),
        value(rng, &fields),
        rows.join(", "),
        links.join(", ")
    )
}

#[test]
fn mutated_inputs_never_panic_or_hang() {
    let mut rng = Rng::new(0x9E37_79B9_7F4A_7C15);
    let mut slowest = Duration::ZERO;
    for k in 0..1500 {
        let source = mutate(&mut rng, VALID[k % VALID.len()]);
        slowest = slowest.max(expand(&source).unwrap_or_else(|e| panic!("{e}")));
    }
    println!("slowest mutated expansion: {slowest:?}");
}

#[test]
fn random_robots_never_panic_or_hang() {
    let mut rng = Rng::new(0x0123_4567_89AB_CDEF);
    let mut slowest = Duration::ZERO;
    let mut expanded = 0;
    for _ in 0..120 {
        let source = random_robot(&mut rng);
        slowest = slowest.max(expand(&source).unwrap_or_else(|e| panic!("{e}")));
        let out = derive_dynamics(source.parse().expect("tokens")).to_string();
        expanded += usize::from(!out.contains("compile_error"));
    }
    // Not every random robot is physical, but many are: the generator itself ran on them.
    assert!(expanded > 20, "only {expanded} random robots expanded");
    println!("slowest random robot: {slowest:?}, {expanded} of 120 expanded");
}

#[test]
fn adversarial_inputs_never_panic_or_hang() {
    let wrap = |cell: &str| {
        format!(
            "#[dynamics(gravity = [0, 0, -9.81], dh = [[q, 0, {cell}, 0]], link(mass = 1))] struct A {{ x: f64 }}"
        )
    };
    let mut cases = vec![
        wrap(&format!("{}x{}", "(".repeat(3000), ")".repeat(3000))),
        wrap(&format!("{}x", "-".repeat(3000))),
        wrap(&vec!["x"; 5000].join(" + ")),
        wrap(&format!("{}x{}", "-(".repeat(1000), ")".repeat(1000))),
        wrap("((((x^8)^8)^8)^8)"),
        wrap("((((((((x^8)^8)^8)^8)^8)^8)^8)^8)"),
        wrap("x^4294967296"),
        wrap("1e-400"),
        wrap("1e308 * 10"),
        wrap("1 / 0"),
        wrap("0 / 0"),
        wrap("q99999999999999999999999"),
        wrap("170141183460469231731687303715884105727 * 170141183460469231731687303715884105727"),
        wrap(
            "1 / 170141183460469231731687303715884105727 / 170141183460469231731687303715884105727",
        ),
        wrap("0.1234567890123456789012345678901234567890123456789"),
        format!(
            "#[dynamics(gravity = [0, 0, -9.81], dh = [{}], {})] struct A;",
            vec!["[q, 0, 1, 0]"; 500].join(", "),
            vec!["link(mass = 1)"; 500].join(", ")
        ),
        "#[dynamics(gravity = [0, 0, 0], dh = [[q, 0, 0, 0]], link(mass = 0))] struct A;".into(),
        "#[dynamics(file = \"/dev/null\")] struct A;".into(),
        "#[dynamics(file = \"\")] struct A;".into(),
        "#[dynamics()] struct A;".into(),
        "#[dynamics] #[dynamics(dh = [])] union U { x: f64 }".into(),
        "struct A;".into(),
    ];
    let deep = format!("{}1{}", "[".repeat(60), "]".repeat(60));
    cases.push(format!("#[dynamics(gravity = {deep})] struct A;"));
    for source in &cases {
        expand(source).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn random_description_files_never_panic_or_hang() {
    let toml = include_str!("../../../robots/puma560.toml");
    let json = include_str!("../../../tests/data/reference/robots/stanford.json");
    let mut rng = Rng::new(0xDEAD_BEEF_CAFE_F00D);
    for k in 0..600 {
        let (path, base) = if k % 2 == 0 {
            ("r.toml", toml)
        } else {
            ("r.json", json)
        };
        let mut text: Vec<char> = base.chars().collect();
        for _ in 0..=rng.below(3) {
            let i = rng.below(text.len());
            let c = rng.pick(&[
                "", "\"", "[", "]", "{", "}", "=", ",", "-", "9", "e", "\n", "x",
            ]);
            match rng.below(3) {
                0 => {
                    text.remove(i);
                }
                1 => text.splice(i..i, c.chars()).for_each(drop),
                _ => text.splice(i..=i, c.chars()).for_each(drop),
            }
        }
        let text: String = text.into_iter().collect();
        let shown = text.clone();
        let lines = text.lines().count();
        // Deriving a 6-joint robot takes milliseconds: do it for every tenth file.
        let generate = k % 10 < 2;
        let (result, _) = bounded(&shown, move || {
            front::load(path, &text).map(|l| {
                if generate {
                    drop(dynamics_codegen::derive(&l.robot));
                }
            })
        })
        .unwrap_or_else(|e| panic!("{e}"));
        if let Err(e) = result {
            // An error the parser places is inside the text.
            if let Some(line) = e.line {
                assert!((1..=lines + 1).contains(&line), "{e} in:\n{shown}");
            }
        }
    }
}

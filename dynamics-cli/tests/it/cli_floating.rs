//! `dynamics inspect ROBOT --floating`: a floating base's readable equations, read back as
//! numbers. Every printed equation (`gbx`, `M[vx, θ1]`, `h[..]`, `g[..]`, `τ[..]`) is parsed
//! and evaluated at the 12 states of Pinocchio 4.1's reference data (`tests/data/floating/`),
//! `g_b` from its printed equations: each of M, h, g and τ must match Pinocchio's to 1e-5 of
//! its largest element (the printout rounds its coefficients to 6 significant digits), and
//! every entry of M must be printed but the zeros between two legs, which the header names.
//! A wrong name (`vx` for `ωx`), sign or term is off by far more. Its text and LaTeX for a
//! two-legged toy are golden files (`golden.rs`).

use serde_json::Value;
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

fn inspect(args: &[&str]) -> Result<String, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .arg("inspect")
        .args(args)
        .current_dir(root)
        .output()
        .expect("run dynamics");
    let text = |b: Vec<u8>| String::from_utf8(b).expect("UTF-8");
    if out.status.success() {
        Ok(text(out.stdout))
    } else {
        Err(text(out.stderr))
    }
}

/// The printed equations by each of their names (`M[vx, θ1]` and `M[θ1, vx]`).
fn equations(out: &str) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for line in out.lines().filter(|l| l.starts_with("  ")) {
        let parts: Vec<&str> = line.trim().split(" = ").collect();
        let (rhs, names) = parts.split_last().expect("an equation");
        for name in names {
            map.insert((*name).to_owned(), (*rhs).to_owned());
        }
    }
    map
}

/// A printed sum evaluated: numbers (`0.5`, `1/2`, `1.2e-5`), symbols with powers (`θ1'²`),
/// products and parenthesized sums; `symbol` gives each symbol's value.
fn evaluate(text: &str, symbol: &dyn Fn(&str) -> f64) -> f64 {
    let mut words = Vec::new();
    let mut word = String::new();
    for c in text.chars() {
        // A minus after a number's `e` is its exponent's.
        let exponent =
            c == '-' && word.ends_with('e') && word.starts_with(|d: char| d.is_ascii_digit());
        if !exponent && (c.is_whitespace() || "()+-".contains(c)) {
            if !word.is_empty() {
                words.push(std::mem::take(&mut word));
            }
            if !c.is_whitespace() {
                words.push(c.to_string());
            }
        } else {
            word.push(c);
        }
    }
    if !word.is_empty() {
        words.push(word);
    }
    let mut at = 0;
    let value = sum(&words, &mut at, symbol);
    assert_eq!(at, words.len(), "trailing words in {text}");
    value
}

fn sum(words: &[String], at: &mut usize, symbol: &dyn Fn(&str) -> f64) -> f64 {
    let mut total = 0.0;
    let mut sign = 1.0;
    loop {
        match words.get(*at).map(String::as_str) {
            Some("-") => {
                sign = -sign;
                *at += 1;
            }
            Some("+") => *at += 1,
            Some(")") | None => return total,
            Some(_) => {
                total += sign * product(words, at, symbol);
                sign = 1.0;
            }
        }
    }
}

fn product(words: &[String], at: &mut usize, symbol: &dyn Fn(&str) -> f64) -> f64 {
    let mut value = 1.0;
    while let Some(w) = words.get(*at) {
        match w.as_str() {
            "+" | "-" | ")" => break,
            "(" => {
                *at += 1;
                value *= sum(words, at, symbol);
                assert_eq!(words.get(*at).map(String::as_str), Some(")"));
            }
            w if w.starts_with(|c: char| c.is_ascii_digit()) => value *= number(w),
            w => value *= power(w, symbol),
        }
        *at += 1;
    }
    value
}

fn number(w: &str) -> f64 {
    match w.split_once('/') {
        Some((n, d)) => {
            n.parse::<f64>().expect("a numerator") / d.parse::<f64>().expect("a denominator")
        }
        None => w.parse().expect("a number"),
    }
}

/// `θ1'²`: the symbol's value to the superscript's power.
fn power(w: &str, symbol: &dyn Fn(&str) -> f64) -> f64 {
    const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let base = w.trim_end_matches(|c| SUPERSCRIPTS.contains(&c));
    let exponent = w[base.len()..].chars().fold(0, |e, c| {
        10 * e + SUPERSCRIPTS.iter().position(|&s| s == c).expect("a digit")
    });
    let exponent = if base.len() == w.len() { 1 } else { exponent };
    symbol(base).powi(i32::try_from(exponent).expect("small"))
}

/// The names of the velocity's coordinates: the base's, then `θ1` … `θn`.
fn coordinates(n: usize) -> Vec<String> {
    let base = ["vx", "vy", "vz", "ωx", "ωy", "ωz"].map(str::to_owned);
    base.into_iter()
        .chain((1..=n).map(|j| format!("θ{j}")))
        .collect()
}

/// The value of a symbol at the state `(q, v, a)`, `g_b` given.
fn symbol(name: &str, q: &[f64], v: &[f64], a: &[f64], g_b: [f64; 3]) -> f64 {
    let primes = name.len() - name.trim_end_matches('\'').len();
    let plain = name.trim_end_matches('\'');
    let base = ["vx", "vy", "vz", "ωx", "ωy", "ωz"];
    if let Some(k) = base.iter().position(|&b| b == plain) {
        return [v, a][primes][k];
    }
    if let Some(k) = ["qx", "qy", "qz", "qw"].iter().position(|&b| b == name) {
        return q[3 + k];
    }
    if let Some(k) = ["gbx", "gby", "gbz"].iter().position(|&b| b == name) {
        return g_b[k];
    }
    let joints = |list: &str| -> Vec<usize> {
        // `12` past nine joints is written `1,2`; below, one digit each.
        if list.contains(',') || q.len() - 7 > 9 {
            list.split(',')
                .map(|j| j.parse::<usize>().expect("a joint") - 1)
                .collect()
        } else {
            list.chars()
                .map(|c| c.to_digit(10).expect("a joint") as usize - 1)
                .collect()
        }
    };
    let angle = |list: &str| joints(list).iter().map(|&j| q[7 + j]).sum::<f64>();
    if let Some(rest) = plain.strip_prefix('θ') {
        let j = joints(rest)[0];
        return [q[7 + j], v[6 + j], a[6 + j]][primes];
    }
    if let Some(rest) = name.strip_prefix('S') {
        return angle(rest).sin();
    }
    if let Some(rest) = name.strip_prefix('C') {
        return angle(rest).cos();
    }
    panic!("an unknown symbol `{name}`")
}

/// Checks the printed equations of `urdf` against Pinocchio's data `data` at every sample.
fn check_against_pinocchio(urdf: &str, data: &str) {
    let out = inspect(&[urdf, "--floating"]).expect("inspect --floating");
    let printed = equations(&out);
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("..").join(data))
        .expect("reference data");
    let json: Value = serde_json::from_str(&text).expect("JSON");
    let vector = |v: &Value| -> Vec<f64> {
        let items = v.as_array().expect("an array");
        items
            .iter()
            .map(|x| x.as_f64().expect("a number"))
            .collect()
    };
    for (s, sample) in json["samples"]
        .as_array()
        .expect("samples")
        .iter()
        .enumerate()
    {
        let (q, v, a) = (
            vector(&sample["q"]),
            vector(&sample["v"]),
            vector(&sample["a"]),
        );
        let names = coordinates(v.len() - 6);
        let no_gravity = [f64::NAN; 3];
        let g_b = ["gbx", "gby", "gbz"].map(|g| {
            let rhs = &printed[g];
            evaluate(rhs, &|w| symbol(w, &q, &v, &a, no_gravity))
        });
        let value = |name: &str| -> Option<f64> {
            let rhs = printed.get(name)?;
            Some(evaluate(rhs, &|w| symbol(w, &q, &v, &a, g_b)))
        };
        for (key, letter) in [("h", "h"), ("g", "g"), ("tau", "τ")] {
            let want = vector(&sample[key]);
            let scale = want.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
            for (i, w) in want.iter().enumerate() {
                let name = format!("{letter}[{}]", names[i]);
                let got = value(&name).unwrap_or_else(|| panic!("{name} is not printed"));
                let e = (got - w).abs() / scale;
                assert!(e < 1e-5, "{urdf}: {name} at sample {s}: {got} for {w}");
            }
        }
        let m: Vec<Vec<f64>> = sample["M"]
            .as_array()
            .expect("rows")
            .iter()
            .map(vector)
            .collect();
        let scale = m.iter().flatten().fold(1.0_f64, |x, y| x.max(y.abs()));
        for (i, row) in m.iter().enumerate() {
            for (j, w) in row.iter().enumerate() {
                let name = format!("M[{}, {}]", names[i], names[j]);
                // Left out where the header names it zero (upper triangle).
                let upper = format!("M[{}, {}]", names[i.min(j)], names[i.max(j)]);
                let got = value(&name).unwrap_or_else(|| {
                    assert!(
                        out.contains(&format!(" {upper}")),
                        "{name} is neither printed nor named zero"
                    );
                    0.0
                });
                let e = (got - w).abs() / scale;
                assert!(e < 1e-5, "{urdf}: {name} at sample {s}: {got} for {w}");
            }
        }
    }
}

#[test]
fn solo12_printed_equations_are_pinocchios() {
    check_against_pinocchio(
        "robots/urdf/floating/solo12.urdf",
        "tests/data/floating/solo12.json",
    );
}

/// The configuration named as Pinocchio's, the sections in order, LaTeX's names; what a
/// floating base cannot be asked with, refused.
#[test]
fn floating_inspect_names_pinocchios_coordinates() {
    let out = inspect(&["robots/urdf/floating/solo12.urdf", "--floating"]).expect("runs");
    assert!(
        out.contains("configuration q = [x, y, z, qx, qy, qz, qw, θ1, θ2"),
        "{out}"
    );
    assert!(
        out.contains("velocity v = [vx, vy, vz, ωx, ωy, ωz, θ1', "),
        "{out}"
    );
    let order = [
        "\nGravity in base axes",
        "\nMass matrix",
        "\nBias h",
        "\nGeneralized gravity",
        "\nInverse dynamics",
    ];
    let at: Vec<usize> = order
        .iter()
        .map(|h| out.find(h).unwrap_or_else(|| panic!("{h}")))
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{at:?}");
    let latex =
        inspect(&["robots/urdf/floating/solo12.urdf", "--floating", "--latex"]).expect("runs");
    assert!(
        latex.contains("M_{v_x \\omega_y} = M_{\\omega_y v_x} &= "),
        "{latex}"
    );
    assert!(latex.contains("\\dot{\\omega}_x"), "{latex}");
    let kinematics = inspect(&[
        "robots/urdf/floating/solo12.urdf",
        "--floating",
        "--kinematics",
    ]);
    assert!(kinematics.unwrap_err().contains("cannot be used with"));
    let fixed = inspect(&["robots/puma560.toml", "--floating"]).unwrap_err();
    assert!(fixed.contains("no `[floating]` table"), "{fixed}");
}

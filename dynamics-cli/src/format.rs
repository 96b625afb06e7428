//! How `eval` prints numbers: text rows or JSON, with no negative zero in either.

use std::fmt::Write;

/// τ, M, C and g at one state.
pub struct Evaluation {
    pub tau: Vec<f64>,
    pub m: Vec<Vec<f64>>,
    pub c: Vec<Vec<f64>>,
    pub g: Vec<f64>,
}

/// `-0.0` as `0.0`: a sign on zero is an accident of the order of operations (`-(a·0)`), not
/// information, and `-0.000000e0` next to `0.000000e0` reads as a difference.
pub fn unsigned_zero(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

fn row(v: &[f64]) -> String {
    let s: Vec<String> = v
        .iter()
        .map(|&x| format!("{:>13.6e}", unsigned_zero(x)))
        .collect();
    format!("[{}]", s.join(" "))
}

/// Aligned rows, six significant digits.
pub fn text(e: &Evaluation) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "tau = {}", row(&e.tau));
    for (name, mat) in [("M", &e.m), ("C", &e.c)] {
        let _ = writeln!(out, "{name} =");
        for r in mat {
            let _ = writeln!(out, "  {}", row(r));
        }
    }
    let _ = writeln!(out, "g   = {}", row(&e.g));
    out
}

/// Every digit (shortest round trip), keys `tau`, `M`, `C` and `g`.
pub fn json(e: &Evaluation) -> String {
    let vector = |v: &[f64]| -> Vec<f64> { v.iter().map(|&x| unsigned_zero(x)).collect() };
    let matrix = |m: &[Vec<f64>]| -> Vec<Vec<f64>> { m.iter().map(|r| vector(r)).collect() };
    let doc = serde_json::json!({
        "tau": vector(&e.tau),
        "M": matrix(&e.m),
        "C": matrix(&e.c),
        "g": vector(&e.g),
    });
    format!("{doc:#}\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(x: f64) -> Evaluation {
        Evaluation {
            tau: vec![x],
            m: vec![vec![x]],
            c: vec![vec![x]],
            g: vec![x],
        }
    }

    #[test]
    fn negative_zero_prints_as_zero() {
        assert_eq!(text(&one(-0.0)), text(&one(0.0)));
        assert_eq!(json(&one(-0.0)), json(&one(0.0)));
        assert!(!text(&one(-0.0)).contains('-'));
        assert!(!json(&one(-0.0)).contains('-'));
        // Only zero loses its sign.
        assert!(text(&one(-1e-300)).contains("-1.000000e-300"));
    }
}

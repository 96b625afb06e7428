//! The coefficients of the relations as numbers. `ℤ/p` says exactly which coefficients are
//! zero and gives each one's residue; a coefficient that is a rational of moderate height (an
//! integer, a product of the description's decimals) is recovered from its residue exactly.
//! The others are the least-squares solution of `A_S β = a_c` in doubles, over the columns'
//! values at random states (`S`: the pivots with a nonzero coefficient), which agrees with the
//! exact relation to rounding; the residue then confirms a rational found.

use crate::symbolic::modular::{Fp, Points};
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::f64::consts::PI;

/// Numerators and denominators up to this are recovered exactly (`2·bound² < p`).
const HEIGHT: i128 = 1_000_000_000;

/// Per column, its coefficient on each pivot (`exact[c][r]`: on pivot r).
pub(super) fn numbers(
    graph: &Graph,
    columns: &[Vec<NodeId>],
    pivots: &[usize],
    exact: &[Vec<Fp>],
) -> Vec<Vec<Number>> {
    let values = samples(graph, columns, pivots.len());
    exact
        .iter()
        .enumerate()
        .map(|(c, residues)| {
            let support: Vec<usize> = (0..pivots.len())
                .filter(|&r| !residues[r].is_zero())
                .collect();
            let mut numbers = vec![Number::ZERO; pivots.len()];
            if support.is_empty() {
                return numbers;
            }
            let a: Vec<Vec<f64>> = values
                .iter()
                .map(|row| support.iter().map(|&r| row[pivots[r]]).collect())
                .collect();
            let b: Vec<f64> = values.iter().map(|row| row[c]).collect();
            let beta = least_squares(a, b);
            for (&r, &x) in support.iter().zip(&beta) {
                numbers[r] = exact_or_float(residues[r], x);
            }
            numbers
        })
        .collect()
}

/// The rational whose residue is `residue`, where it is `x` to rounding; else `x`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn exact_or_float(residue: Fp, x: f64) -> Number {
    let rational = residue
        .to_small_rational(HEIGHT)
        .and_then(|(a, b)| Number::ratio(a, b));
    match rational {
        Some(r) if (r.to_f64() - x).abs() <= 1e-9 * x.abs().max(1.0) => r,
        _ => Number::Float(x),
    }
}

/// The columns' rows at random states: enough rows for the widest support, and more.
fn samples(graph: &Graph, columns: &[Vec<NodeId>], pivots: usize) -> Vec<Vec<f64>> {
    let n = columns.first().map_or(1, Vec::len).max(1);
    let count = pivots / n + 12;
    let mut points = Points::new(0xc0ef_f1c1);
    let mut uniform = move || (points.bits() >> 11) as f64 / (1_u64 << 53) as f64 * 2.0 - 1.0;
    let mut rows = Vec::with_capacity(count * n);
    // The columns read some of the nodes before their last, not the rest of the graph (the
    // other families' nodes between them: the Panda's samples took 3.5 % of its derive).
    let outputs: Vec<NodeId> = columns.iter().flatten().copied().collect();
    let mut live = graph.live(&outputs);
    live.truncate(outputs.iter().map(|c| c.index() + 1).max().unwrap_or(0));
    for _ in 0..count {
        let angles: Vec<f64> = (0..n).map(|_| PI * uniform()).collect();
        let others: Vec<[f64; 3]> = (0..n).map(|_| [uniform(), uniform(), uniform()]).collect();
        // A robot with mimic joints keeps its joints' leaves past its coordinates in the
        // graph, read by no column: zero.
        let angle = |i: u16| angles.get(usize::from(i)).copied().unwrap_or(0.0);
        let other = |i: u16, k: usize| others.get(usize::from(i)).map_or(0.0, |o| o[k]);
        let values = graph.eval_marked(&live, |v| match v {
            Var::SinQ(i) => angle(i).sin(),
            Var::CosQ(i) => angle(i).cos(),
            Var::Q(i) => other(i, 0),
            Var::Qd(i) => other(i, 1),
            Var::Qdd(i) => other(i, 2),
            // The columns depend on the joint variables alone (`exact::relations`).
            _ => 0.0,
        });
        for i in 0..n {
            rows.push(columns.iter().map(|c| values[c[i].index()]).collect());
        }
    }
    rows
}

/// `argmin ‖A x − b‖` for `A` of full column rank (rows given), by Householder QR on columns
/// scaled to unit norm.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn least_squares(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
    let (m, k) = (a.len(), a.first().map_or(0, Vec::len));
    let scale: Vec<f64> = (0..k)
        .map(|j| {
            let norm = a.iter().map(|r| r[j] * r[j]).sum::<f64>().sqrt();
            if norm > 0.0 {
                norm
            } else {
                1.0
            }
        })
        .collect();
    for row in &mut a {
        for (x, s) in row.iter_mut().zip(&scale) {
            *x /= s;
        }
    }
    for j in 0..k {
        let norm = (j..m).map(|i| a[i][j] * a[i][j]).sum::<f64>().sqrt();
        if norm == 0.0 {
            continue;
        }
        let alpha = if a[j][j] > 0.0 { -norm } else { norm };
        let mut v: Vec<f64> = (j..m).map(|i| a[i][j]).collect();
        v[0] -= alpha;
        let vv: f64 = v.iter().map(|x| x * x).sum();
        if vv == 0.0 {
            continue;
        }
        for col in j..k {
            let dot: f64 = a[j..].iter().zip(&v).map(|(row, x)| x * row[col]).sum();
            let f = 2.0 * dot / vv;
            for (row, x) in a[j..].iter_mut().zip(&v) {
                row[col] -= f * x;
            }
        }
        let dot: f64 = (j..m).map(|i| v[i - j] * b[i]).sum();
        let f = 2.0 * dot / vv;
        for i in j..m {
            b[i] -= f * v[i - j];
        }
    }
    let mut x = vec![0.0; k];
    for j in (0..k).rev() {
        let s: f64 = (j + 1..k).map(|c| a[j][c] * x[c]).sum();
        x[j] = if a[j][j] == 0.0 {
            0.0
        } else {
            (b[j] - s) / a[j][j]
        };
    }
    x.iter().zip(&scale).map(|(x, s)| x / s).collect()
}

//! The forward dynamics' derivatives planned in lanes (`lane_solve`) on hand-built serial chains
//! and trees (a tree's M factored from the tips): each plan evaluated lane by lane against
//! central differences of `q̈ = M⁻¹(τ − C q̇ − g)` by the f64 algorithms, solved by Gaussian
//! elimination, and `M⁻¹` against that elimination; every lane due after what it reads.

use crate::unit::algo::tree_tests::{chain, robot, trees, At};
use dynamics_codegen::algo::{crba, rnea, RobotScalars};
use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::model::Robot;
use dynamics_codegen::pipeline::{equations, State, Values};
use dynamics_codegen::symbolic::{Of, Tangents};

const Q: [f64; 5] = [-0.4, 0.9, 0.15, -1.3, 0.7];
const QD: [f64; 5] = [0.3, -1.2, 0.6, 0.9, -0.5];
const TAU: [f64; 5] = [2.0, -1.5, 0.8, 0.3, -0.6];
/// Accelerations the forward derivatives must not read (they take the forward dynamics' q̈).
const STRAY_QDD: [f64; 5] = [40.0, -75.0, 13.0, 90.0, -22.0];

/// `x` with `A x = b`, by Gaussian elimination with partial pivoting.
fn gauss(a: &[Vec<f64>], b: &[f64]) -> Vec<f64> {
    let n = b.len();
    let mut m: Vec<Vec<f64>> = a
        .iter()
        .zip(b)
        .map(|(r, &v)| [&r[..], &[v]].concat())
        .collect();
    for j in 0..n {
        let p = (j..n)
            .max_by(|&x, &y| m[x][j].abs().total_cmp(&m[y][j].abs()))
            .expect("a row");
        m.swap(j, p);
        let pivot_row = m[j].clone();
        for row in &mut m[j + 1..] {
            let f = row[j] / pivot_row[j];
            for (x, p) in row[j..].iter_mut().zip(&pivot_row[j..]) {
                *x -= f * p;
            }
        }
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|k| m[i][k] * x[k]).sum();
        x[i] = (m[i][n] - s) / m[i][i];
    }
    x
}

/// The forward dynamics by the f64 algorithms.
fn forward(robot: &Robot, q: &[f64], qd: &[f64], tau: &[f64]) -> Vec<f64> {
    let c = chain(robot, q);
    let zeros = vec![0.0; q.len()];
    let bias = rnea(&c, qd, &zeros, At(&[]).gravity(robot));
    let rhs: Vec<f64> = tau.iter().zip(&bias).map(|(t, b)| t - b).collect();
    gauss(&crba(&c), &rhs)
}

/// Each lane of `plan` at `at`, checking that it is due after its factors and the lanes it reads.
fn evaluate(plan: &Tangents, at: &Values) -> Vec<Vec<f64>> {
    let mut lanes: Vec<Vec<f64>> = Vec::with_capacity(plan.lanes.len());
    for (index, lane) in plan.lanes.iter().enumerate() {
        let mut sum = vec![0.0; plan.directions];
        for term in &lane.terms {
            assert!(
                term.factors.iter().all(|&f| f <= lane.after),
                "lane {index}"
            );
            let scale = term.factors.iter().map(|&f| at.of(f)).product::<f64>();
            let scale = if term.negative { -scale } else { scale };
            match term.of {
                Of::Lane(k) => {
                    assert!(
                        k < index && plan.lanes[k].after <= lane.after,
                        "lane {index}"
                    );
                    for (s, x) in sum.iter_mut().zip(&lanes[k]) {
                        *s += scale * x;
                    }
                }
                Of::Unit(j) => sum[usize::from(j)] += scale,
            }
        }
        lanes.push(sum);
    }
    lanes
}

fn close(a: &[Vec<f64>], b: &[Vec<f64>], tol: f64, what: &str) {
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        for (j, (x, y)) in x.iter().zip(y).enumerate() {
            assert!(
                (x - y).abs() <= tol * (1.0 + y.abs()),
                "{what} ({i}, {j}): {x} vs {y}"
            );
        }
    }
}

/// `[∂q̈/∂q, ∂q̈/∂q̇, M⁻¹]` of `robot` from its plans in lanes, against independent values and
/// against the same matrices traced column by column.
fn check(robot: &Robot, what: &str) {
    let n = robot.dof();
    let (q, qd, tau) = (&Q[..n], &QD[..n], &TAU[..n]);
    let (eq, _) = equations(robot, FamilySet::default().with(Family::Derivatives), None);
    let d = eq.derivatives.as_ref().expect("derivatives traced");
    let state = State {
        fields: &[],
        q,
        qd,
        qdd: &STRAY_QDD[..n],
        tau,
    };
    let at = eq.evaluate(&state);
    let h = 1e-6;
    // Column k of each: by q_k, by q̇_k, M⁻¹ e_k.
    let column = |which: usize, k: usize| -> Vec<f64> {
        let shifted = |s: f64| {
            let (mut a, mut b) = (q.to_vec(), qd.to_vec());
            [&mut a, &mut b][which][k] += s;
            forward(robot, &a, &b, tau)
        };
        if which == 2 {
            let unit: Vec<f64> = (0..n).map(|i| f64::from(u8::from(i == k))).collect();
            return gauss(&crba(&chain(robot, q)), &unit);
        }
        let (p, m) = (shifted(h), shifted(-h));
        p.iter().zip(&m).map(|(x, y)| (x - y) / (2.0 * h)).collect()
    };
    assert_eq!(d.forward_lanes.len(), 3, "{what}");
    for (which, plan) in d.forward_lanes.iter().enumerate() {
        let plan = plan.as_ref().expect("planned");
        let lanes = evaluate(plan, &at);
        let rows: Vec<Vec<f64>> = (0..n)
            .map(|i| plan.outputs[i].map_or(vec![0.0; n], |k| lanes[k][..n].to_vec()))
            .collect();
        let columns: Vec<Vec<f64>> = (0..n).map(|k| column(which, k)).collect();
        let expected: Vec<Vec<f64>> = (0..n)
            .map(|i| columns.iter().map(|c| c[i]).collect())
            .collect();
        let tolerance = if which == 2 { 1e-12 } else { 1e-6 };
        let matrix = ["∂q̈/∂q", "∂q̈/∂q̇", "M⁻¹"][which];
        // ∂τ's tangents planned with one scalar factor to a term, as the solve's steps are.
        let most = plan
            .lanes
            .iter()
            .flat_map(|l| &l.terms)
            .map(|t| t.factors.len());
        let most = most.max().unwrap_or(0);
        assert!(most <= 1, "{what}: {matrix}: a term of {most} factors");
        close(&rows, &expected, tolerance, &format!("{what}: {matrix}"));
        let traced = at.matrix(&d.forward[which]);
        close(&rows, &traced, 1e-10, &format!("{what}: {matrix} traced"));
    }
}

#[test]
fn forward_derivatives_in_lanes_solve_with_the_factors() {
    for (k, specs) in trees().iter().enumerate() {
        check(&robot(specs, false), &format!("chain {k}"));
        check(&robot(specs, true), &format!("tree {k}"));
    }
}

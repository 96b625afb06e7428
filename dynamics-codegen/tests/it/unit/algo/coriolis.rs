use super::{parallel_chain, test_chain};
use dynamics_codegen::algo::coriolis_matrix;
use dynamics_codegen::algo::crba;

use dynamics_codegen::algo::Chain;

/// `coriolis_matrix` of `at(q)` against the Christoffel symbols of `M` by central
/// differences, for the chain as given and regrouped.
fn check(at: &dyn Fn(&[f64]) -> Chain<f64>, q: &[f64], qd: &[f64]) {
    let n = q.len();
    for (regroup, before) in [(false, false), (true, false), (true, true)] {
        let at = |q: &[f64]| {
            let c = at(q).moving_before_twist(before);
            if regroup {
                c.regrouped()
            } else {
                c
            }
        };
        let c = coriolis_matrix(&at(q), qd).expect("no sums of angles");
        let h = 1e-6;
        let dm: Vec<Vec<Vec<f64>>> = (0..n)
            .map(|k| {
                let (mut p, mut m) = (q.to_vec(), q.to_vec());
                p[k] += h;
                m[k] -= h;
                let (mp, mm) = (crba(&at(&p)), crba(&at(&m)));
                (0..n)
                    .map(|i| (0..n).map(|j| (mp[i][j] - mm[i][j]) / (2.0 * h)).collect())
                    .collect()
            })
            .collect();
        for i in 0..n {
            for j in 0..n {
                let want: f64 = (0..n)
                    .map(|k| 0.5 * (dm[k][i][j] + dm[j][i][k] - dm[i][j][k]) * qd[k])
                    .sum();
                assert!(
                    (c[i][j] - want).abs() < 1e-7,
                    "({i}, {j}): {} vs {want} (regrouped {regroup}, before {before})",
                    c[i][j]
                );
            }
        }
    }
}

/// A 6-joint all-revolute arm with general and quarter-turn twists and parallel axes.
#[test]
fn matches_christoffel_symbols_on_a_revolute_arm() {
    let q = [0.3, -1.1, 0.7, 2.0, -0.6, 1.4];
    let qd = [0.4, -0.9, 1.3, 0.2, -1.7, 0.8];
    check(&|q| parallel_chain(q, true), &q, &qd);
}

/// With prismatic joints: the 5-joint test arm (joint 3) and the 7-joint one (joint 7).
#[test]
fn matches_christoffel_symbols_with_prismatic_joints() {
    let (q, qd) = ([0.3, -1.1, 0.25, 2.0, -0.6], [0.4, -0.9, 1.3, 0.2, -1.7]);
    check(&test_chain, &q, &qd);
    let q = [0.3, -1.1, 0.7, 2.0, -0.6, 1.4, 0.35];
    let qd = [0.4, -0.9, 1.3, 0.2, -1.7, 0.8, -0.6];
    check(&|q| parallel_chain(q, false), &q, &qd);
}

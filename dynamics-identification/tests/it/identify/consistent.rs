//! The physically consistent estimate: pseudo-inertias, their eigenvectors, the cuts.

use dynamics_identification::identify::consistent::{
    cut, objective, solve, EIGEN_TOLERANCE, ROUNDS,
};
use dynamics_identification::identify::pseudo_inertia::{pseudo_inertia, smallest_eigenvalue};
use dynamics_identification::linear_algebra::eigen4 as eigen;

#[test]
fn the_pseudo_inertia_of_point_masses_is_their_second_moment() {
    // Two point masses: J = Σ m_k [r_k; 1][r_k; 1]ᵀ, and the parameters from their
    // definitions, with the products of inertia as −Σ m x y.
    let points = [(2.0, [0.1, -0.2, 0.3]), (0.5, [-0.4, 0.05, 0.2])];
    let mut pi = [0.0; 10];
    let mut want = [[0.0; 4]; 4];
    for (m, r) in points {
        let [x, y, z] = r;
        let moments = [
            m,
            m * x,
            m * y,
            m * z,
            m * (y * y + z * z),
            -m * x * y,
            m * (x * x + z * z),
            -m * x * z,
            -m * y * z,
            m * (x * x + y * y),
        ];
        pi.iter_mut().zip(moments).for_each(|(p, v)| *p += v);
        let e = [x, y, z, 1.0];
        for a in 0..4 {
            for b in 0..4 {
                want[a][b] += m * e[a] * e[b];
            }
        }
    }
    let j = pseudo_inertia(&pi);
    for a in 0..4 {
        for b in 0..4 {
            assert!((j[a][b] - want[a][b]).abs() < 1e-15, "{a} {b}: {j:?}");
        }
    }
    // Two points span a line: two zero eigenvalues, two positive.
    let (values, _) = eigen(j);
    let mut sorted = values;
    sorted.sort_by(f64::total_cmp);
    assert!(
        sorted[0].abs() < 1e-14 && sorted[1].abs() < 1e-14,
        "{sorted:?}"
    );
    assert!(sorted[2] > 1e-3, "{sorted:?}");
}

#[test]
fn eigenvectors_diagonalise_a_symmetric_matrix() {
    let a = [
        [4.0, 1.0, -2.0, 0.5],
        [1.0, 3.0, 0.0, 1.0],
        [-2.0, 0.0, -1.0, 2.0],
        [0.5, 1.0, 2.0, 0.1],
    ];
    let (values, vectors) = eigen(a);
    for (value, v) in values.iter().zip(&vectors) {
        for row in 0..4 {
            let av: f64 = (0..4).map(|k| a[row][k] * v[k]).sum();
            assert!((av - value * v[row]).abs() < 1e-12, "{values:?}");
        }
    }
    let trace: f64 = values.iter().sum();
    assert!((trace - 6.1).abs() < 1e-12);
}

/// A one-link problem whose unconstrained minimiser is a link with negative mass: the
/// consistent one has J ⪰ 0 and lies on the boundary.
#[test]
fn an_infeasible_minimiser_is_moved_onto_the_cone() {
    // The objective ‖π − t‖² (M = 1) with t: mass −0.1, an inertia of a 1 kg body.
    let t = [-0.1, 0.0, 0.0, 0.0, 0.1, 0.0, 0.1, 0.0, 0.0, 0.1];
    let m: Vec<Vec<f64>> = (0..10)
        .map(|i| (0..10).map(|k| f64::from(u8::from(i == k))).collect())
        .collect();
    let (q, c) = objective(&m, &t, &t);
    let mut cuts: Vec<Vec<f64>> = (0..4)
        .map(|e| {
            let mut v = [0.0; 4];
            v[e] = 1.0;
            cut(0, 10, &v)
        })
        .collect();
    let mut x = solve(&q, &c, &cuts).unwrap();
    for _ in 0..ROUNDS {
        let (values, vectors) = eigen(pseudo_inertia(&x));
        let before = cuts.len();
        for (value, v) in values.iter().zip(&vectors) {
            if *value < -EIGEN_TOLERANCE {
                cuts.push(cut(0, 10, v));
            }
        }
        if cuts.len() == before {
            break;
        }
        x = solve(&q, &c, &cuts).unwrap();
    }
    assert!(smallest_eigenvalue(&x) >= -1e-9, "{x:?}");
    // The nearest point has mass zero (J's last diagonal entry is the mass, decoupled from
    // Σ when h = 0) and keeps the inertia, which is feasible.
    assert!(x[0].abs() < 1e-8, "{x:?}");
    for k in [4, 6, 9] {
        assert!((x[k] - 0.1).abs() < 1e-8, "{x:?}");
    }
}

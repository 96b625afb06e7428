//! A link's parameters about its centre of mass.

use dynamics_identification::identify::about_com::about_com;

#[test]
fn the_parallel_axis_theorem_undoes_the_shift_to_the_origin() {
    // A 2 kg body at c = (0.1, −0.2, 0.3) with a full inertia about its centre, moved to
    // the origin as the regressor's parameters have it (I_o = I_c + m (|c|² 1 − c cᵀ)).
    let (m, c) = (2.0, [0.1, -0.2, 0.3]);
    let ic = [0.05, 0.04, 0.03, 0.001, -0.002, 0.003];
    let shift = |a: usize, b: usize| {
        let delta = if a == b {
            c.iter().map(|x| x * x).sum()
        } else {
            0.0
        };
        m * (delta - c[a] * c[b])
    };
    let pi = [
        m,
        m * c[0],
        m * c[1],
        m * c[2],
        ic[0] + shift(0, 0),
        ic[3] + shift(0, 1),
        ic[1] + shift(1, 1),
        ic[4] + shift(0, 2),
        ic[5] + shift(1, 2),
        ic[2] + shift(2, 2),
    ];
    let (mass, com, inertia) = about_com(&pi);
    assert!((mass - m).abs() < 1e-15);
    for k in 0..3 {
        assert!((com[k] - c[k]).abs() < 1e-15, "{com:?}");
    }
    for k in 0..6 {
        assert!((inertia[k] - ic[k]).abs() < 1e-15, "{inertia:?}");
    }
}

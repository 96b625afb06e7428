use super::{parallel_chain, test_chain as chain};
use dynamics_codegen::algo::{crba, crba_derivative};

/// Moments carried through the sums of parallel joints' angles give the same `M`.
#[test]
fn summing_angles_of_parallel_joints() {
    let q = [0.3, -1.1, 0.7, 2.0, -0.6, 1.4, 0.15];
    for symmetric_tip in [false, true] {
        let plain = parallel_chain(&q, symmetric_tip);
        let summed = plain.clone().summing_angles(true);
        assert!(summed.has_runs());
        let (a, b) = (crba(&plain), crba(&summed));
        for (x, y) in a.iter().flatten().zip(b.iter().flatten()) {
            assert!((x - y).abs() < 1e-12, "{a:?} vs {b:?}");
        }
    }
}

/// `∂M/∂q_k` by the carried commutators agrees with central differences of `M`, for the
/// chain as given and regrouped.
#[test]
fn derivative_matches_finite_differences() {
    let q = [0.3, -1.1, 0.25, 2.0, -0.6];
    let h = 1e-6;
    for (regroup, before) in [(false, false), (true, false), (true, true)] {
        let m_at = |q: &[f64]| {
            let c = chain(q).moving_before_twist(before);
            crba(&if regroup { c.regrouped() } else { c })
        };
        for k in 0..q.len() {
            let c = chain(&q).moving_before_twist(before);
            let c = if regroup { c.regrouped() } else { c };
            let Some(dm) = crba_derivative(&c, k) else {
                assert_eq!(k, 2, "only the prismatic joint has no analytic derivative");
                continue;
            };
            let (mut plus, mut minus) = (q, q);
            plus[k] += h;
            minus[k] -= h;
            let (mp, mm) = (m_at(&plus), m_at(&minus));
            for i in 0..q.len() {
                for j in 0..q.len() {
                    let fd = (mp[i][j] - mm[i][j]) / (2.0 * h);
                    assert!(
                        (dm[i][j] - fd).abs() < 1e-8,
                        "k {k} ({i}, {j}): {} vs {fd} (regrouped: {regroup})",
                        dm[i][j]
                    );
                }
            }
        }
    }
}

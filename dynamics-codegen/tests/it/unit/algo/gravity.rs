use super::test_chain;
use dynamics_codegen::algo::gravity_torques;
use dynamics_codegen::algo::{rnea, V3};

/// Equal to Newton-Euler at rest, for the chain as given and regrouped, with gravity along
/// no axis.
#[test]
fn equals_newton_euler_at_rest() {
    let gravity = V3::new(1.3, -4.1, -8.7);
    let zeros = [0.0; 5];
    for q in [[0.3, -1.1, 0.25, 2.0, -0.6], [2.9, 0.4, -0.3, -1.7, 1.2]] {
        for regroup in [false, true] {
            let chain = test_chain(&q);
            let chain = if regroup { chain.regrouped() } else { chain };
            let by_composites = gravity_torques(&chain, gravity);
            let by_newton_euler = rnea(&chain, &zeros, &zeros, gravity);
            for (a, b) in by_composites.iter().zip(&by_newton_euler) {
                assert!(
                    (a - b).abs() < 1e-12,
                    "{by_composites:?} vs {by_newton_euler:?}"
                );
            }
        }
    }
}

use super::test_chain;
use dynamics_codegen::algo::V3;
use std::ops::Add;

/// A wrench carried to the parent, the arm crossed before the twist or after it, equals
/// `(R f, R n + p × R f)` with the full rotation matrix.
#[test]
fn carrying_a_wrench() {
    let chain = test_chain(&[0.3, -1.1, 0.25, 2.0, -0.6]);
    let (f, n) = (V3::new(0.4, -1.3, 2.2), V3::new(-0.9, 0.15, 0.6));
    for joint in &chain.joints {
        let r = joint.rotation();
        let rf = r.mul_vec(f);
        let expected = (rf, r.mul_vec(n).add(joint.offset().cross(rf)));
        let carried = joint.wrench_to_parent(f, n);
        for (a, b) in [
            (carried.0.x, expected.0.x),
            (carried.0.y, expected.0.y),
            (carried.0.z, expected.0.z),
            (carried.1.x, expected.1.x),
            (carried.1.y, expected.1.y),
            (carried.1.z, expected.1.z),
        ] {
            assert!((a - b).abs() < 1e-14, "{a} vs {b}");
        }
    }
}

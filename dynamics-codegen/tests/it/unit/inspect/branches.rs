use dynamics_codegen::inspect::branches::{describe, related, zero_inertia};

/// A hand: a palm joint, then two fingers of two joints each off it.
#[test]
fn a_palm_with_two_fingers() {
    let a = [None, Some(0), Some(1), Some(0), Some(3)];
    assert_eq!(
        describe(&a),
        "joints 1-3 from the base; joints 4-5 from joint 1"
    );
    assert!(related(Some(&a), 0, 4) && related(Some(&a), 2, 1) && !related(Some(&a), 2, 3));
    assert_eq!(zero_inertia(&a), [(1, 3), (1, 4), (2, 3), (2, 4)]);
    assert!(related(None, 2, 3));
}

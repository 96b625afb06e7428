//! The joint terms of a base regressor, in words.

use dynamics_codegen::JointColumns;
use dynamics_identification::identify::base::describe;

#[test]
fn joint_terms_in_words() {
    let none = JointColumns::default();
    let rotor = JointColumns {
        actuator_inertia: true,
        ..none
    };
    let all = JointColumns {
        actuator_inertia: true,
        viscous: true,
        coulomb: true,
        offset: false,
    };
    assert_eq!(describe(&[none, none]), "none");
    assert_eq!(
        describe(&[all, rotor, all]),
        "actuator inertia (every joint), viscous (joints 1, 3), Coulomb (joints 1, 3)"
    );
    assert_eq!(describe(&[none, rotor]), "actuator inertia (joint 2)");
}

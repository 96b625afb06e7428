use crate::unit::algo::tree_tests::{at, robot, R};
use dynamics_codegen::check::tree;
use dynamics_codegen::model::Convention;

/// A joint carried by a later joint, and a tree in the standard convention, are refused
/// with the joint named; the hand-built trees pass.
#[test]
fn antecedents_come_first_and_trees_are_modified() {
    let good = robot(
        &[at(None, R, 0.0, 0.0, 0.0), at(None, R, 0.0, 0.0, 1.0)],
        true,
    );
    assert!(tree(&good).is_empty());
    let mut standard = good.clone();
    standard.convention = Convention::Standard;
    let problems = tree(&standard);
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].0, 1);
    assert!(problems[0].1.message.contains("modified D-H"));
    // Through the door's checks, named by its joint.
    let told = dynamics_codegen::pipeline::problems(&standard, true);
    assert!(told[0].starts_with("joint 2: a kinematic tree"), "{told:?}");
    let specs = [
        at(None, R, 0.0, 0.0, 0.0),
        at(Some(2), R, 0.0, 0.0, 1.0),
        at(Some(0), R, 0.0, 0.0, 2.0),
    ];
    let problems = tree(&robot(&specs, true));
    assert_eq!(problems.len(), 1);
    assert!(problems[0].1.message.contains("antecedent is joint 3"));
}

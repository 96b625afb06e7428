//! Property tests of the generator's closed forms on random kinematic trees
//! ([`dynamics_tests::random::tree`]: 2 to 9 joints, each joint's antecedent among the earlier
//! joints or the base, Khalil and Kleinfinger's γ, b, modified D-H rows, random gravity and
//! inertial data, actuator inertia and springs), against `dynamics-reference`, the book's
//! Lagrangian method summed over each joint's subtree. The system under test is the closed form
//! of [`dynamics_codegen::derive`], interpreted as in `properties.rs`.
//!
//! Checked: τ, M, C, g and both energies. The runs are deterministic (fixed seed and case count)
//! and write no failure-persistence files.

use std::cell::RefCell;

use dynamics_codegen::symbolic::NodeId;
use dynamics_reference::nalgebra::DMatrix;
use dynamics_reference::scaled_error;
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::{chain_as_tree, tree, tree_case, TreeCase, TreeSpec};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestError, TestRunner};

/// Cases per property.
const CASES: u32 = 48;
/// Tolerance on `max|a − b| / max(1, max|b|)` between the closed form and the reference.
const EXACT: f64 = 1e-9;

/// Runs `test` on [`CASES`] cases of `trees` with a fixed seed; panics with the shrunk case.
fn check(
    seed: u64,
    trees: impl Strategy<Value = TreeSpec>,
    test: impl Fn(&TreeCase) -> Result<(), TestCaseError>,
) {
    let config = Config {
        cases: CASES,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(seed),
        ..Config::default()
    };
    match TestRunner::new(config).run(&tree_case(trees), |c| test(&c)) {
        Ok(()) => {}
        Err(TestError::Fail(reason, case)) => panic!("{reason}\nminimal failing case: {case:#?}"),
        Err(TestError::Abort(reason)) => panic!("aborted: {reason}"),
    }
}

/// The quantities compared, by name.
const NAMES: [&str; 6] = ["tau", "M", "C", "g", "K", "P"];

/// The closed form's and the reference's τ, M, C, g, K and P at the case's state, each as a
/// list of numbers (matrices by rows).
fn both(c: &TreeCase) -> [(Vec<f64>, Vec<f64>); 6] {
    let eq = dynamics_codegen::derive(&c.tree.model());
    let reference = c.tree.reference();
    let (q, qd, qdd) = (&c.q[..], &c.qd[..], &c.qdd[..]);
    let tau = vec![0.0; eq.dof];
    let values = evaluate(
        &eq,
        State {
            q,
            qd,
            qdd,
            tau: &tau,
        },
    );
    let scalar = |id: &NodeId| values[id.index()];
    let list = |ids: &[NodeId]| ids.iter().map(scalar).collect::<Vec<f64>>();
    let matrix = |ids: &[Vec<NodeId>]| ids.iter().flat_map(|row| list(row)).collect::<Vec<f64>>();
    let rows = |m: DMatrix<f64>| m.transpose().as_slice().to_vec();
    // The mass matrix and gravity at q̇ = q̈ = 0 are the graph's own nodes; K at this q̇.
    [
        (
            list(&eq.tau),
            reference.inverse_dynamics(q, qd, qdd).as_slice().to_vec(),
        ),
        (matrix(&eq.mass), rows(reference.mass_matrix(q))),
        (matrix(&eq.coriolis), rows(reference.coriolis_matrix(q, qd))),
        (
            list(&eq.gravity),
            reference.gravity_torques(q).as_slice().to_vec(),
        ),
        (
            vec![scalar(&eq.kinetic_energy)],
            vec![reference.kinetic_energy(q, qd)],
        ),
        (
            vec![scalar(&eq.potential_energy)],
            vec![reference.potential_energy(q)],
        ),
    ]
}

/// Runs [`both`] on the cases of `trees` and fails on the first quantity off by more than
/// [`EXACT`]; prints the worst error of each.
fn generated_matches_reference(seed: u64, trees: impl Strategy<Value = TreeSpec>, what: &str) {
    let worst = RefCell::new([0.0f64; 6]);
    check(seed, trees, |c| {
        for (k, (got, want)) in both(c).iter().enumerate() {
            let e = scaled_error(got, want);
            prop_assert!(
                e < EXACT,
                "{} off by {e:e}\n got {got:?}\nwant {want:?}",
                NAMES[k]
            );
            let mut worst = worst.borrow_mut();
            worst[k] = worst[k].max(e);
        }
        Ok(())
    });
    for (name, e) in NAMES.iter().zip(worst.into_inner()) {
        eprintln!("{what}: worst scaled error of {name}: {e:.1e}");
    }
}

/// A chain written as a tree (every joint's antecedent the joint before, `γ = b = 0`, but
/// `branch: Some(..)`) is the modified D-H chain.
#[test]
fn chains_written_as_trees_match_the_reference() {
    generated_matches_reference(1, chain_as_tree(), "chains as trees");
}

/// The property: on random trees the closed form equals the book's method.
#[test]
fn generated_matches_reference_on_random_trees() {
    generated_matches_reference(2, tree(), "trees");
}

//! The tips' kinematics of random kinematic trees ([`dynamics_tests::random::tree`]) against
//! `dynamics-reference`, the book's method: a tree has the family without asking
//! (`Equations::add_families`; a random tree that is a chain asks), its tips are its leaves in
//! joint order, and each leaf's pose,
//! Jacobian in base axes, Jacobian in its own axes and `J̇ q̇` (central differences of the
//! reference's Jacobian along the motion) are the reference's link frame's. The runs are
//! deterministic (fixed seed and case count).

use std::cell::RefCell;

use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::symbolic::NodeId;
use dynamics_reference::nalgebra::{DMatrix, DVector, Matrix4};
use dynamics_reference::scaled_error;
use dynamics_tests::interpret::{evaluate, State};
use dynamics_tests::random::{tree, tree_case, TreeCase};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, RngSeed, TestRunner};

/// Tolerance on the scaled error, as `trees.rs`; `J̇ q̇` by differences within [`DIFFERENCES`].
const EXACT: f64 = 1e-9;
const DIFFERENCES: f64 = 1e-7;

/// Quantities compared: what, the closed form's, the reference's.
type Checks = Vec<(String, Vec<f64>, Vec<f64>)>;

/// The closed form's and the reference's pose, Jacobians and `J̇ q̇` of every leaf, by name.
fn both(c: &TreeCase) -> Result<Checks, TestCaseError> {
    let model = c.tree.model();
    let mut eq = dynamics_codegen::derive(&model);
    // A tree asks for nothing; a random tree that came out a chain asks.
    let asked = if model.is_tree() {
        FamilySet::default()
    } else {
        FamilySet::default().with(Family::Tips)
    };
    eq.add_families(&model, asked);
    let Some(tips) = eq.tips.clone() else {
        return Err(TestCaseError::fail("a tree without the tips' kinematics"));
    };
    let n = model.dof();
    let leaves: Vec<usize> = (0..n)
        .filter(|&i| (0..n).all(|j| model.parent(j) != Some(i)))
        .collect();
    let names: Vec<String> = leaves.iter().map(|i| format!("link{}", i + 1)).collect();
    prop_assert_eq!(&tips.names, &names);
    let reference = c.tree.reference();
    let (q, qd) = (&c.q[..], &c.qd[..]);
    let values = evaluate(
        &eq,
        State {
            q,
            qd,
            qdd: &c.qdd,
            tau: &vec![0.0; n],
        },
    );
    let list = |ids: &[NodeId]| {
        ids.iter()
            .map(|id| values[id.index()])
            .collect::<Vec<f64>>()
    };
    let matrix = |ids: &[Vec<NodeId>]| ids.iter().flat_map(|row| list(row)).collect::<Vec<f64>>();
    let mut out = Vec::new();
    for (t, &i) in leaves.iter().enumerate() {
        let [pose, j, local, bias, bias_local] = wanted(&reference, i, q, qd);
        let name = |what: &str| format!("{} {what}", names[t]);
        let got = [
            matrix(&tips.poses[t]),
            matrix(&tips.jacobians_in_base[t]),
            matrix(&tips.jacobians_in_tip[t]),
            list(&tips.biases_in_base[t]),
            list(&tips.biases_in_tip[t]),
        ];
        let what = [
            "pose",
            "J in base",
            "J in tip",
            "J'q' in base",
            "J'q' in tip",
        ];
        let want = [pose, j, local, bias, bias_local];
        for ((what, got), want) in what.iter().zip(got).zip(want) {
            out.push((name(what), got, want));
        }
    }
    Ok(out)
}

/// The reference's pose rows of link frame `i`, its Jacobian in base axes and in its own (by
/// rows), and `J̇ q̇` in both.
fn wanted(reference: &dynamics_reference::Robot, i: usize, q: &[f64], qd: &[f64]) -> [Vec<f64>; 5] {
    let frame = reference.frame(q, i);
    let j = reference.frame_jacobian(q, i, &Matrix4::identity());
    let r = frame.fixed_view::<3, 3>(0, 0).into_owned();
    let mut local = j.clone();
    for block in [0, 3] {
        let turned = r.transpose() * j.rows(block, 3);
        local.rows_mut(block, 3).copy_from(&turned);
    }
    let rows = |m: &DMatrix<f64>| m.transpose().as_slice().to_vec();
    let pose: Vec<f64> = (0..3)
        .flat_map(|row| (0..4).map(move |c| frame[(row, c)]))
        .collect();
    let bias = bias_by_differences(reference, i, q, qd);
    let bias_local: Vec<f64> = [0, 3]
        .iter()
        .flat_map(|&b| {
            (r.transpose() * bias.rows(b, 3))
                .iter()
                .copied()
                .collect::<Vec<_>>()
        })
        .collect();
    [
        pose,
        rows(&j),
        rows(&local),
        bias.as_slice().to_vec(),
        bias_local,
    ]
}

/// `J̇ q̇` of link frame `i` by central differences of the reference's Jacobian along
/// `q + t q̇`, Richardson-extrapolated (steps h and h/2).
fn bias_by_differences(
    robot: &dynamics_reference::Robot,
    i: usize,
    q: &[f64],
    qd: &[f64],
) -> DVector<f64> {
    let at = |t: f64| {
        let q: Vec<f64> = q.iter().zip(qd).map(|(q, v)| q + t * v).collect();
        robot.frame_jacobian(&q, i, &Matrix4::identity())
    };
    let rate = |h: f64| (at(h) - at(-h)) / (2.0 * h);
    let rate = (rate(5e-4) * 4.0 - rate(1e-3)) / 3.0;
    rate * DVector::from_column_slice(qd)
}

#[test]
fn every_leaf_of_random_trees_matches_the_reference() {
    let config = Config {
        cases: 48,
        failure_persistence: None,
        rng_algorithm: RngAlgorithm::ChaCha,
        rng_seed: RngSeed::Fixed(3),
        ..Config::default()
    };
    let worst = RefCell::new([0.0f64; 2]);
    let result = TestRunner::new(config).run(&tree_case(tree()), |c| {
        for (what, got, want) in both(&c)? {
            let e = scaled_error(&got, &want);
            let differences = what.contains("J'q'");
            let bound = if differences { DIFFERENCES } else { EXACT };
            prop_assert!(
                e < bound,
                "{what} off by {e:e}\n got {got:?}\nwant {want:?}"
            );
            let mut worst = worst.borrow_mut();
            worst[usize::from(differences)] = worst[usize::from(differences)].max(e);
        }
        Ok(())
    });
    if let Err(e) = result {
        panic!("{e}");
    }
    let [exact, differences] = worst.into_inner();
    eprintln!("random trees' tips: worst {exact:.1e} (J'q' by differences {differences:.1e})");
}

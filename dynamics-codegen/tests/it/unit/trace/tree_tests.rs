//! Hand-built kinematic trees through the whole trace (`pipeline::equations`, the graph
//! evaluated by `Equations::evaluate`), against the f64 algorithms that `algo`'s tree tests
//! check against independent values: every output, the opt-in families (derivatives by
//! central differences, the regressor and the base parameters against τ), and `M`'s entries
//! off the ancestry as exact zeros of the graph.

use crate::unit::algo::tree_tests::{chain, robot, symmetric_last, trees, At};
use dynamics_codegen::algo::{
    coriolis_matrix, crba, jacobian_in_base, kinematics, kinetic_energy, potential_energy, rnea,
    RobotScalars, V3,
};
use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::model::Robot;
use dynamics_codegen::pipeline::{equations, State};

const Q: [f64; 5] = [-0.4, 0.9, 0.15, -1.3, 0.7];
const QD: [f64; 5] = [0.3, -1.2, 0.6, 0.9, -0.5];
const QDD: [f64; 5] = [1.1, 0.2, -0.7, 0.4, 1.6];
const TAU: [f64; 5] = [2.0, -1.5, 0.8, 0.3, -0.6];

fn close(a: &[f64], b: &[f64], tol: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(
            (x - y).abs() <= tol * (1.0 + y.abs()),
            "{what} [{k}]: {x} vs {y}"
        );
    }
}

fn torques(robot: &Robot, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    rnea(&chain(robot, q), qd, qdd, At(&[]).gravity(robot))
}

fn check(robot: &Robot) {
    let n = robot.dof();
    let (q, qd, qdd, tau) = (&Q[..n], &QD[..n], &QDD[..n], &TAU[..n]);
    let families = FamilySet::default()
        .with(Family::Derivatives)
        .with(Family::Regressor)
        .with(Family::BaseParameters);
    let (eq, _) = equations(robot, families, None);
    let state = State {
        fields: &[],
        q,
        qd,
        qdd,
        tau,
    };
    let at = eq.evaluate(&state);
    let c = chain(robot, q);
    let g = At(&[]).gravity(robot);
    let m = crba(&c);
    close(&at.matrix(&eq.mass).concat(), &m.concat(), 1e-12, "M");
    for i in 0..n {
        for j in 0..n {
            let related = c.supports(i, j) || c.supports(j, i);
            assert_eq!(eq.graph.is_zero(eq.mass[i][j]), !related, "M({i}, {j})");
        }
    }
    let expected_tau = torques(robot, q, qd, qdd);
    close(&at.vector(&eq.tau), &expected_tau, 1e-12, "τ");
    let zeros = vec![0.0; n];
    close(
        &at.vector(&eq.gravity),
        &rnea(&c, &zeros, &zeros, g),
        1e-12,
        "g",
    );
    let coriolis = coriolis_matrix(&c, qd).expect("no runs in a tree");
    close(
        &at.matrix(&eq.coriolis).concat(),
        &coriolis.concat(),
        1e-12,
        "C",
    );
    let none = V3::zero(0.0);
    close(
        &at.vector(&eq.coriolis_torques),
        &rnea(&c, qd, &zeros, none),
        1e-12,
        "C q̇",
    );
    let k = kinetic_energy(&c, qd, 0.0);
    close(&[at.of(eq.kinetic_energy)], &[k], 1e-12, "K");
    close(
        &[at.of(eq.potential_energy)],
        &[potential_energy(&c, g)],
        1e-12,
        "P",
    );
    // M q̈ = τ − (C q̇ + g).
    let forward = at.vector(&eq.forward.qdd);
    let bias = rnea(&c, qd, &zeros, g);
    let m_qdd: Vec<f64> = (0..n)
        .map(|i| (0..n).map(|j| m[i][j] * forward[j]).sum::<f64>() + bias[i])
        .collect();
    close(&m_qdd, tau, 1e-10, "forward dynamics");
    let jacobian = jacobian_in_base(&kinematics(&mut At(q), robot));
    let traced = at.matrix(&eq.kinematics.jacobian_in_base).concat();
    close(&traced, &jacobian.concat(), 1e-12, "Jacobian");
    check_families(robot, &eq, &at, &expected_tau);
}

/// `∂τ/∂q`, `∂τ/∂q̇` by central differences, `∂q̈/∂τ = M⁻¹`; the regressor and the base
/// regressor times their parameters give τ.
fn check_families(
    robot: &Robot,
    eq: &dynamics_codegen::trace::Equations,
    at: &dynamics_codegen::pipeline::Values,
    tau: &[f64],
) {
    let n = robot.dof();
    let (q, qd, qdd) = (&Q[..n], &QD[..n], &QDD[..n]);
    let d = eq.derivatives.as_ref().expect("derivatives traced");
    let h = 1e-6;
    for (which, matrix) in d.inverse.iter().enumerate() {
        for k in 0..n {
            let shifted = |s: f64| {
                let (mut a, mut b) = (q.to_vec(), qd.to_vec());
                let moved = if which == 0 { &mut a } else { &mut b };
                moved[k] += s;
                torques(robot, &a, &b, qdd)
            };
            let (p, m) = (shifted(h), shifted(-h));
            let fd: Vec<f64> = p.iter().zip(&m).map(|(x, y)| (x - y) / (2.0 * h)).collect();
            let column: Vec<f64> = (0..n).map(|i| at.of(matrix[i][k])).collect();
            close(
                &column,
                &fd,
                1e-6,
                &format!("∂τ/∂{} column {k}", ["q", "q̇"][which]),
            );
        }
    }
    // The same derivatives planned in lanes of tangents (no smoothed friction: both planned).
    assert!(d.inverse_lanes.iter().all(Option::is_some));
    for (which, plan) in d.inverse_lanes.iter().enumerate() {
        let Some(plan) = plan else { continue };
        let lanes = tangent_lanes(plan, at);
        for i in 0..n {
            let row = plan.outputs[i].map_or(vec![0.0; n], |k| lanes[k].clone());
            let traced: Vec<f64> = d.inverse[which][i].iter().map(|&id| at.of(id)).collect();
            close(&row, &traced, 1e-12, &format!("lanes of ∂τ_{i}"));
        }
    }
    let inverse = at.matrix(&eq.forward.mass_inverse).concat();
    close(&at.matrix(&d.forward[2]).concat(), &inverse, 1e-12, "∂q̈/∂τ");
    let r = eq.regressor.as_ref().expect("regressor traced");
    let by_columns: Vec<f64> = (0..n)
        .map(|i| {
            let links: f64 = (0..n)
                .map(|j| {
                    let pairs = r.columns[i][j].iter().zip(&r.parameters[j]);
                    pairs.map(|(&y, &p)| at.of(y) * at.of(p)).sum::<f64>()
                })
                .sum();
            let joint = r.joint_columns[i].iter().zip(&r.joint_parameters[i]);
            links + joint.map(|(&y, &p)| at.of(y) * at.of(p)).sum::<f64>()
        })
        .collect();
    close(&by_columns, tau, 1e-10, "Y π");
    let base = eq.base_parameters.as_ref().expect("base parameters traced");
    let by_base: Vec<f64> = base
        .regressor
        .iter()
        .map(|row| {
            row.iter()
                .zip(&base.values)
                .map(|(&y, &p)| at.of(y) * at.of(p))
                .sum()
        })
        .collect();
    close(&by_base, tau, 1e-10, "Y_B π_B");
}

/// Each lane of a plan of tangents: the sum of its terms, `± Π factors · (lane or e_j)`.
fn tangent_lanes(
    plan: &dynamics_codegen::symbolic::Tangents,
    at: &dynamics_codegen::pipeline::Values,
) -> Vec<Vec<f64>> {
    use dynamics_codegen::symbolic::Of;
    let mut lanes: Vec<Vec<f64>> = Vec::with_capacity(plan.lanes.len());
    for lane in &plan.lanes {
        let mut sum = vec![0.0; plan.directions];
        for term in &lane.terms {
            let scale = term.factors.iter().map(|&f| at.of(f)).product::<f64>();
            let scale = if term.negative { -scale } else { scale };
            match term.of {
                Of::Lane(k) => {
                    for (s, x) in sum.iter_mut().zip(&lanes[k]) {
                        *s += scale * x;
                    }
                }
                Of::Unit(j) => sum[usize::from(j)] += scale,
            }
        }
        lanes.push(sum);
    }
    lanes
}

#[test]
fn traced_trees_equal_the_algorithms() {
    for specs in trees() {
        check(&robot(&specs, true));
        check(&symmetric_last(robot(&specs, true)));
    }
}

/// Two chains of eight joints off the base: every lane of ∂τ's tangents is kept in the one
/// block of eight directions of its chain (a chain's torques depend on its own joints alone),
/// not in both, and is exactly zero outside its block.
#[test]
fn a_chain_s_tangents_take_its_block_alone() {
    use crate::unit::algo::tree_tests::{at as joint, P, R};
    let specs: Vec<_> = (0..16)
        .map(|i| {
            let parent = (i % 8 != 0).then(|| i - 1);
            let kind = if i % 5 == 3 { P } else { R };
            let gamma = if i == 8 { 0.7 } else { 0.0 };
            joint(parent, kind, gamma, 0.0, 0.3 * i as f64)
        })
        .collect();
    let robot = robot(&specs, true);
    let (eq, _) = equations(&robot, FamilySet::default().with(Family::Derivatives), None);
    let d = eq.derivatives.as_ref().expect("derivatives traced");
    let values = |k: f64| -> Vec<f64> { (0..16).map(|i| (0.37 * i as f64 + k).sin()).collect() };
    let (q, qd, qdd, tau) = (values(0.1), values(1.3), values(2.2), values(3.1));
    let state = State {
        fields: &[],
        q: &q,
        qd: &qd,
        qdd: &qdd,
        tau: &tau,
    };
    let at = eq.evaluate(&state);
    for plan in d.inverse_lanes.iter().flatten() {
        // In blocks of eight, whichever the plan takes.
        let plan = &dynamics_codegen::symbolic::Tangents {
            group: dynamics_codegen::symbolic::BLOCK,
            ..plan.clone()
        };
        assert_eq!(plan.block_count(), 2);
        let lanes = tangent_lanes(plan, &at);
        let blocks = plan.blocks();
        for (k, (blocks, lane)) in blocks.iter().zip(&lanes).enumerate() {
            assert_eq!(blocks.len(), 1, "lane {k} in blocks {blocks:?}");
            let mut outside = (0..16).filter(|j| !blocks.contains(&(j / 8)));
            assert!(outside.all(|j| lane[j] == 0.0), "lane {k}: {lane:?}");
        }
        // τ_i's row in the block of i's chain.
        for (i, lane) in plan.outputs.iter().enumerate() {
            let lane = lane.expect("every torque depends on its chain");
            assert_eq!(blocks[lane], i / 8..i / 8 + 1, "∂τ_{i}");
        }
    }
}

/// The generated methods' operations (flops, as `dynamics stats` counts them) of `robot`.
fn flops(robot: &Robot, families: FamilySet) -> Vec<(String, usize)> {
    let (eq, _) = equations(robot, families, None);
    let generated = dynamics_codegen::emit::generate(&eq, Vec::new());
    let methods = generated.methods.iter();
    methods
        .map(|m| (m.name.to_string(), m.ops.flops()))
        .collect()
}

fn flops_of(table: &[(String, usize)], method: &str) -> usize {
    table
        .iter()
        .find(|(n, _)| n == method)
        .map_or(0, |&(_, f)| f)
}

/// Two chains off the base cost what the two chains cost apart, for `M` and τ: the zero block
/// between them costs nothing, and neither does it in the forward dynamics, factored from the
/// tips.
#[test]
fn zero_blocks_cost_nothing() {
    let specs = &trees()[2];
    let mut second = specs[3..].to_vec();
    second[1].gamma = 0.0;
    second[1].b = 0.0;
    let mut tree_specs = specs.clone();
    tree_specs[4] = second[1];
    tree_specs[4].parent = Some(3);
    let families = FamilySet::default();
    let tree = flops(&robot(&tree_specs, true), families);
    let apart = [
        flops(&robot(&specs[..3], false), families),
        flops(&robot(&second, false), families),
    ];
    for method in [
        "mass_matrix",
        "inverse_dynamics",
        "gravity_torques",
        "forward_dynamics",
    ] {
        let sum: usize = apart.iter().map(|t| flops_of(t, method)).sum();
        let together = flops_of(&tree, method);
        eprintln!("{method}: {together} flops together, {sum} apart");
        // Not more; one fewer where the two chains share a node.
        assert!(together <= sum, "{method}: {together} against {sum} apart");
    }
}

/// `cargo test -p dynamics-codegen --test it -- --ignored --nocapture operation_counts`: the
/// operations of τ, M and the forward dynamics of the hand-built trees.
#[test]
#[ignore = "prints the counts the report quotes"]
fn operation_counts() {
    for (k, specs) in trees().iter().enumerate() {
        let table = flops(&robot(specs, true), FamilySet::default());
        let serial: Vec<_> = specs
            .iter()
            .enumerate()
            .map(|(i, s)| crate::unit::algo::tree_tests::Spec {
                parent: i.checked_sub(1),
                ..*s
            })
            .collect();
        let chain = flops(&robot(&serial, true), FamilySet::default());
        for method in ["inverse_dynamics", "mass_matrix", "forward_dynamics"] {
            let (t, c) = (flops_of(&table, method), flops_of(&chain, method));
            eprintln!("tree {k}: {method}: {t} flops (the same links as a chain: {c})");
        }
    }
}

/// The simplified models of a tree: sampled over the envelope, each pruned element within its
/// proven bound of the exact one, something dropped, and `M`'s zeros still zero.
#[test]
fn simplified_models_of_a_tree_are_within_their_bounds() {
    use dynamics_codegen::method::Method;
    use dynamics_codegen::model::{Envelope, JointEnvelope, Simplification};
    use dynamics_codegen::trace::Elements;
    let tree = robot(&trees()[1], true);
    let n = tree.dof();
    let joint = JointEnvelope {
        lower: -2.0,
        upper: 1.5,
        speed: 1.5,
        acceleration: 4.0,
    };
    let request = Simplification {
        tolerance: vec![0.05; n],
        envelope: Envelope {
            joints: vec![joint; n],
        },
    };
    let families = FamilySet::default().with(Family::Simplified);
    let (eq, outcome) = equations(&tree, families, Some(&request));
    assert_eq!(outcome, Some(Ok(())));
    let s = eq.simplified.as_ref().expect("simplified");
    let exact = |m: Method| match m {
        Method::InverseDynamicsSimplified => Elements::Vector(eq.tau.clone()),
        Method::CoriolisTorquesSimplified => Elements::Vector(eq.coriolis_torques.clone()),
        Method::GravityTorquesSimplified => Elements::Vector(eq.gravity.clone()),
        _ => Elements::Matrix(eq.mass.clone()),
    };
    let mut seed = 7_u64;
    let mut next = |lo: f64, hi: f64| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        lo + (hi - lo) * ((seed >> 11) as f64 / (1u64 << 53) as f64)
    };
    let mut dropped = false;
    for _ in 0..200 {
        let q: Vec<f64> = (0..n).map(|_| next(joint.lower, joint.upper)).collect();
        let qd: Vec<f64> = (0..n).map(|_| next(-joint.speed, joint.speed)).collect();
        let a = joint.acceleration;
        let qdd: Vec<f64> = (0..n).map(|_| next(-a, a)).collect();
        let state = State {
            fields: &[],
            q: &q,
            qd: &qd,
            qdd: &qdd,
            tau: &[],
        };
        let at = eq.evaluate(&state);
        for o in &s.outputs {
            let whole = exact(o.method);
            let triples = whole.upper().zip(o.elements.upper()).zip(o.bounds.upper());
            for (((i, j, &e), (_, _, &p)), (_, _, b)) in triples {
                let error = (at.of(e) - at.of(p)).abs();
                assert!(
                    error <= b.bound + 1e-9,
                    "{:?} ({i}, {j:?}): {error}",
                    o.method
                );
                dropped |= b.kept < b.terms;
                if eq.graph.is_zero(e) {
                    assert!(eq.graph.is_zero(p), "M({i}, {j:?}) is zero");
                }
            }
        }
    }
    assert!(dropped, "nothing pruned, nothing tested");
}

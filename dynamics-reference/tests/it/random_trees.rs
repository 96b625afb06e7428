//! The Khalil-Kleinfinger form of a tree (antecedent, γ, b and a modified D-H row per joint)
//! against the same tree written URDF style (each row as a placement and the z axis, which is
//! exact: `Rotz(θ + q) Transz(d) = Rotz(θ) Transz(d) Rotz(q)`), on random trees of 2-9 joints,
//! and the Lagrangian identities on them.

use dynamics_reference::nalgebra::{DVector, Matrix4};
use dynamics_reference::{
    rot_x, rot_z, trans_x, trans_z, Convention, Joint, JointKind, Placement, Robot,
};
use dynamics_test_support::Rng;

use crate::common::{matrix4_error, matrix_error, scaled_error};

/// A random tree in the modified convention: each joint's antecedent among the earlier joints
/// or the base, revolute or prismatic, random γ, b, α, a, θ, d and inertial data.
fn random_tree(rng: &mut Rng) -> Robot {
    let n = 2 + rng.below(8);
    let angle = |rng: &mut Rng| {
        if rng.below(4) == 0 {
            [
                0.0,
                std::f64::consts::FRAC_PI_2,
                -std::f64::consts::FRAC_PI_2,
            ][rng.below(3)]
        } else {
            rng.range(-std::f64::consts::PI, std::f64::consts::PI)
        }
    };
    let joints = (0..n)
        .map(|i| {
            let parent = match rng.below(i + 1) {
                0 => None,
                k => Some(k - 1),
            };
            // Second moments a, b, c > 0.001 and products below 0.0005: a positive definite
            // inertia, diagonally dominant.
            let (a, b, c) = (
                rng.range(0.001, 0.2),
                rng.range(0.001, 0.2),
                rng.range(0.001, 0.2),
            );
            let off = rng.vector(3, -0.0005, 0.0005);
            Joint {
                kind: if rng.below(3) == 0 {
                    JointKind::Prismatic
                } else {
                    JointKind::Revolute
                },
                theta: angle(rng),
                d: rng.range(-1.0, 1.0),
                a: rng.range(-1.0, 1.0),
                alpha: angle(rng),
                parent,
                gamma: angle(rng),
                b: rng.range(-1.0, 1.0),
                placement: None,
                mass: rng.range(0.1, 5.0),
                com: [
                    rng.range(-0.5, 0.5),
                    rng.range(-0.5, 0.5),
                    rng.range(-0.5, 0.5),
                ],
                inertia: [b + c, a + c, a + b, off[0], off[1], off[2]],
                actuator_inertia: rng.range(0.0, 0.5),
                spring_stiffness: rng.range(0.0, 20.0),
                spring_rest: rng.range(-1.0, 1.0),
            }
        })
        .collect();
    let gravity = [
        rng.range(-10.0, 10.0),
        rng.range(-10.0, 10.0),
        rng.range(-10.0, 10.0),
    ];
    let robot = Robot {
        name: "random tree".into(),
        description: String::new(),
        convention: Convention::Modified,
        gravity,
        joints,
    };
    robot.check().expect("a valid tree");
    robot
}

/// The same tree URDF style: `X = Rotz(γ) Transz(b) Rotx(α) Transx(a) Rotz(θ) Transz(d)`, the
/// axis z.
fn as_placements(robot: &Robot) -> Robot {
    let joints = robot
        .joints
        .iter()
        .map(|j| {
            let x = rot_z(j.gamma)
                * trans_z(j.b)
                * rot_x(j.alpha)
                * trans_x(j.a)
                * rot_z(j.theta)
                * trans_z(j.d);
            Joint {
                theta: 0.0,
                d: 0.0,
                a: 0.0,
                alpha: 0.0,
                gamma: 0.0,
                b: 0.0,
                placement: Some(Placement {
                    rotation: [0, 1, 2].map(|r| [0, 1, 2].map(|c| x[(r, c)])),
                    xyz: [x[(0, 3)], x[(1, 3)], x[(2, 3)]],
                    axis: [0.0, 0.0, 1.0],
                }),
                ..j.clone()
            }
        })
        .collect();
    Robot {
        convention: Convention::Urdf,
        joints,
        ..robot.clone()
    }
}

fn state(robot: &Robot, rng: &mut Rng) -> [Vec<f64>; 3] {
    let n = robot.dof();
    [
        rng.vector(n, -3.0, 3.0),
        rng.vector(n, -2.0, 2.0),
        rng.vector(n, -2.0, 2.0),
    ]
}

#[test]
fn khalil_kleinfinger_rows_equal_their_placements() {
    let mut rng = Rng::new(41);
    let mut worst = 0.0_f64;
    let mut branched = 0;
    for _ in 0..40 {
        let tree = random_tree(&mut rng);
        let placed = as_placements(&tree);
        branched += usize::from((0..tree.dof()).any(|i| tree.antecedent(i) != i.checked_sub(1)));
        let [q, qd, qdd] = state(&tree, &mut rng);
        let mut errors = vec![
            scaled_error(
                tree.inverse_dynamics(&q, &qd, &qdd).as_slice(),
                placed.inverse_dynamics(&q, &qd, &qdd).as_slice(),
            ),
            matrix_error(&tree.mass_matrix(&q), &placed.mass_matrix(&q)),
            matrix_error(
                &tree.coriolis_matrix(&q, &qd),
                &placed.coriolis_matrix(&q, &qd),
            ),
            scaled_error(
                tree.gravity_torques(&q).as_slice(),
                placed.gravity_torques(&q).as_slice(),
            ),
            scaled_error(
                &[tree.kinetic_energy(&q, &qd)],
                &[placed.kinetic_energy(&q, &qd)],
            ),
            scaled_error(&[tree.potential_energy(&q)], &[placed.potential_energy(&q)]),
        ];
        for i in 0..tree.dof() {
            errors.push(matrix4_error(&tree.frame(&q, i), &placed.frame(&q, i)));
            let id = Matrix4::identity();
            errors.push(matrix_error(
                &tree.frame_jacobian(&q, i, &id),
                &placed.frame_jacobian(&q, i, &id),
            ));
        }
        let e = errors.iter().copied().fold(0.0, f64::max);
        assert!(e < 1e-12, "{tree:#?}: the two forms differ by {e:e}");
        worst = worst.max(e);
    }
    assert!(branched > 30, "only {branched} of 40 trees branch");
    eprintln!("K-K rows against their placements, 40 random trees: worst scaled error {worst:.1e}");
}

#[test]
fn lagrangian_identities_hold_on_random_trees() {
    let mut rng = Rng::new(42);
    let h = 1e-6;
    for _ in 0..20 {
        let tree = random_tree(&mut rng);
        let n = tree.dof();
        let [q, qd, qdd] = state(&tree, &mut rng);
        let along = |t: f64| -> Vec<f64> { q.iter().zip(&qd).map(|(a, b)| a + t * b).collect() };
        let m = tree.mass_matrix(&q);
        assert!(matrix_error(&m, &m.transpose()) < 1e-14, "M symmetric");
        assert!(
            m.clone().symmetric_eigen().eigenvalues.min() > 0.0,
            "M positive definite"
        );
        // Ṁ = C + Cᵀ along q̇, g = ∂P/∂q, τ = M q̈ + C q̇ + g, K = ½ q̇ᵀ M q̇.
        let m_dot = (tree.mass_matrix(&along(h)) - tree.mass_matrix(&along(-h))) / (2.0 * h);
        let c = tree.coriolis_matrix(&q, &qd);
        assert!(
            matrix_error(&(&c + c.transpose()), &m_dot) < 1e-7,
            "Mdot = C + C^T"
        );
        let dp: Vec<f64> = (0..n)
            .map(|k| {
                let mut up = q.clone();
                let mut down = q.clone();
                up[k] += h;
                down[k] -= h;
                (tree.potential_energy(&up) - tree.potential_energy(&down)) / (2.0 * h)
            })
            .collect();
        assert!(
            scaled_error(tree.gravity_torques(&q).as_slice(), &dp) < 1e-7,
            "g = dP/dq"
        );
        let v = DVector::from_column_slice(&qd);
        let tau = &m * DVector::from_column_slice(&qdd) + &c * &v + tree.gravity_torques(&q);
        assert!(
            scaled_error(
                tree.inverse_dynamics(&q, &qd, &qdd).as_slice(),
                tau.as_slice()
            ) < 1e-12
        );
        let ke = 0.5 * v.dot(&(&m * &v));
        assert!(scaled_error(&[tree.kinetic_energy(&q, &qd)], &[ke]) < 1e-12);
        // Joints on different branches do not couple.
        for i in 0..n {
            for j in 0..n {
                if !tree.moves(i, j) && !tree.moves(j, i) {
                    assert_eq!(
                        (m[(i, j)], c[(i, j)]),
                        (0.0, 0.0),
                        "M, C ({i}, {j}) of {tree:#?}"
                    );
                    assert_eq!(tree.u(&q, i, j), Matrix4::zeros());
                }
            }
        }
    }
}

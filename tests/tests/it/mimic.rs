//! Mimic joints in the attribute, through the generated code: a 4-joint arm whose third joint
//! follows the second (`q₃ = −0.7 q₂ + 0.3`, its own θ offset, friction, actuator inertia and
//! a spring) against the same arm derived with every joint free, projected by hand with
//! S (4 × 3: row 3 is −0.7 e₂): at `q_full = S q + o`, `q̇_full = S q̇`, `q̈_full = S q̈`, the
//! reduced τ, g, h, C q̇ and friction are `Sᵀ ·`, M, C, ∂τ/∂q and ∂τ/∂q̇ are `Sᵀ · S`, the energies
//! and the hand's pose equal, the hand's Jacobian is `J S`, and `M q̈ = τ − h − f` holds for the
//! forward dynamics. The sine of `k q + o + θ` is a node of the generated code, not an input's.

use dynamics_reference::scaled_error;
use dynamics_runtime::{Dynamics, DynamicsDerivatives};
use dynamics_tests::reference::TOLERANCE;

macro_rules! arm {
    ($name:ident $(, $($mimic:tt)*)?) => {
        #[derive(Dynamics)]
        #[dynamics(
            gravity = [0.3, -0.2, -9.81],
            derivatives = true,
            joints = [
                revolute(xyz = [0, 0, 0.3], rpy = [0, 0, 0.2]),
                revolute(name = "shoulder", xyz = [0.1, 0, 0.2], rpy = [90 deg, 0, 0]),
                revolute(xyz = [0.4, 0.05, 0], rpy = [0.1, 0.2, 0.3], axis = [0, 0.6, 0.8] $(, $($mimic)*)?),
                revolute(xyz = [0.3, 0, 0.02], rpy = [-90 deg, 0, 0], axis = [1, 0, 0]),
            ],
            link(mass = 2.0, com = [0, 0.01, -0.1], inertia = [0.05, 0.05, 0.02, 0, 0, 0.001]),
            link(mass = 1.5, com = [0.15, 0, 0.01], inertia = [0.01, 0.04, 0.04, 0.001, 0, 0]),
            link(mass = 1.1, com = [0.1, 0.02, 0], inertia = [0.008, 0.02, 0.02, 0, 0.001, 0],
                 actuator_inertia = 0.03, spring = (4.0, 0.2),
                 friction = (viscous = 0.5, coulomb = 0.3, smoothing = 0.4)),
            link(mass = 0.6, com = [0.05, 0, 0.02], inertia = [0.002, 0.003, 0.003, 0, 0, 0]),
        )]
        struct $name;
    };
}

arm!(Free);
arm!(
    Mimic,
    mimic = (joint = "shoulder", multiplier = -0.7, offset = 0.3)
);

const K: f64 = -0.7;
const O: f64 = 0.3;

/// `x` of the coordinates as the four joints' (`with_offset` for positions).
fn full(x: &[f64; 3], with_offset: bool) -> [f64; 4] {
    [
        x[0],
        x[1],
        K * x[1] + if with_offset { O } else { 0.0 },
        x[2],
    ]
}

/// `Sᵀ v`.
fn project(v: &[f64; 4]) -> Vec<f64> {
    vec![v[0], v[1] + K * v[2], v[3]]
}

/// `Sᵀ A S`, rows first.
fn sandwich(a: &[[f64; 4]; 4]) -> Vec<f64> {
    let rows: Vec<[f64; 4]> = [a[0], a[1], a[3]]
        .into_iter()
        .enumerate()
        .map(|(r, row)| match r {
            1 => std::array::from_fn(|j| row[j] + K * a[2][j]),
            _ => row,
        })
        .collect();
    rows.iter().flat_map(project).collect()
}

/// A matrix's elements, rows first.
fn flat<const C: usize>(rows: impl AsRef<[[f64; C]]>) -> Vec<f64> {
    rows.as_ref().iter().flatten().copied().collect()
}

fn check(what: &str, got: &[f64], want: &[f64]) {
    let e = scaled_error(got, want);
    assert!(
        e < TOLERANCE,
        "{what} off by {e:e}\n got {got:?}\nwant {want:?}"
    );
}

#[test]
fn a_mimic_joint_is_its_free_arm_projected() {
    let states = [
        ([0.4, -0.9, 1.3], [0.7, -1.1, 0.4], [1.2, 0.3, -0.8]),
        ([-2.1, 0.5, 0.05], [-0.2, 1.6, -1.3], [-0.4, 2.0, 0.9]),
    ];
    for (q, qd, qdd) in states {
        let (fq, fqd, fqdd) = (full(&q, true), full(&qd, false), full(&qdd, false));
        let (a, b) = (Mimic, Free);
        check(
            "τ",
            &a.inverse_dynamics(&q, &qd, &qdd),
            &project(&b.inverse_dynamics(&fq, &fqd, &fqdd)),
        );
        check(
            "g",
            &a.gravity_torques(&q),
            &project(&b.gravity_torques(&fq)),
        );
        check(
            "h",
            &a.bias_torques(&q, &qd),
            &project(&b.bias_torques(&fq, &fqd)),
        );
        check(
            "C q̇",
            &a.coriolis_torques(&q, &qd),
            &project(&b.coriolis_torques(&fq, &fqd)),
        );
        check(
            "friction",
            &a.friction_torques(&qd),
            &project(&b.friction_torques(&fqd)),
        );
        check(
            "M",
            &flat(a.mass_matrix(&q)),
            &sandwich(&b.mass_matrix(&fq)),
        );
        check(
            "C",
            &flat(a.coriolis_matrix(&q, &qd)),
            &sandwich(&b.coriolis_matrix(&fq, &fqd)),
        );
        let energies = |k: f64, p: f64| vec![k, p];
        check(
            "energies",
            &energies(a.kinetic_energy(&q, &qd), a.potential_energy(&q)),
            &energies(b.kinetic_energy(&fq, &fqd), b.potential_energy(&fq)),
        );
        let pose =
            |p: dynamics_runtime::Pose<f64>| [flat(p.rotation), p.position.to_vec()].concat();
        check("pose", &pose(a.hand_pose(&q)), &pose(b.hand_pose(&fq)));
        let j_free = b.hand_jacobian_in_base(&fq);
        let j_s: Vec<f64> = j_free
            .iter()
            .flat_map(|row| vec![row[0], row[1] + K * row[2], row[3]])
            .collect();
        check("J S", &flat(a.hand_jacobian_in_base(&q)), &j_s);
        let (d, d_free) = (
            a.inverse_dynamics_derivatives(&q, &qd, &qdd),
            b.inverse_dynamics_derivatives(&fq, &fqd, &fqdd),
        );
        check("∂τ/∂q", &flat(d.dtau_dq), &sandwich(&d_free.dtau_dq));
        check("∂τ/∂q̇", &flat(d.dtau_dqd), &sandwich(&d_free.dtau_dqd));
        // M q̈ = τ − h − f at the forward dynamics' q̈.
        let tau = [1.5, -2.0, 0.7];
        let forward = a
            .forward_dynamics(&q, &qd, &tau)
            .expect("M positive definite");
        let m = a.mass_matrix(&q);
        let (h, f) = (a.bias_torques(&q, &qd), a.friction_torques(&qd));
        let m_qdd: Vec<f64> = m
            .iter()
            .map(|row| row.iter().zip(&forward).map(|(x, y)| x * y).sum())
            .collect();
        let rhs: Vec<f64> = (0..3).map(|i| tau[i] - h[i] - f[i]).collect();
        check("forward dynamics", &m_qdd, &rhs);
    }
}

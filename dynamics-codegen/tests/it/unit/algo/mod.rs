//! The tests of `dynamics_codegen::algo`, by file.

mod aba_tests;
mod body;
mod chain;
mod coriolis;
mod crba;
pub(crate) mod floating_kinematics_tests;
pub(crate) mod floating_tests;
mod gravity;
mod ldlt;
mod projection;
mod rnea;
pub(crate) mod tree_tests;

use dynamics_codegen::algo::{Chain, DhRow, Inertial, JointKind, V3};

/// A 5-joint arm with arbitrary twists, offsets and inertias, joint 3 prismatic: the
/// algorithms' unit tests check each other on it.
pub(crate) fn test_chain(q: &[f64]) -> Chain<f64> {
    let kinds = [
        JointKind::Revolute,
        JointKind::Revolute,
        JointKind::Prismatic,
        JointKind::Revolute,
        JointKind::Revolute,
    ];
    let mut rows = Vec::new();
    let mut links = Vec::new();
    for (i, (&kind, &qi)) in kinds.iter().zip(q).enumerate() {
        let x = i as f64;
        let (theta, d) = match kind {
            JointKind::Revolute => (qi + 0.1 * x, 0.05 + 0.02 * x),
            JointKind::Prismatic => (0.4, qi + 0.1),
        };
        let alpha = 0.7 - 0.45 * x;
        rows.push(DhRow {
            kind,
            sin_theta: theta.sin(),
            cos_theta: theta.cos(),
            d,
            a: 0.3 - 0.05 * x,
            sin_alpha: alpha.sin(),
            cos_alpha: alpha.cos(),
        });
        links.push(Inertial {
            mass: 1.0 + 0.3 * x,
            com: V3::new(-0.1 + 0.02 * x, 0.03, 0.05 - 0.01 * x),
            inertia: [0.05, 0.04 + 0.01 * x, 0.03, 0.004, -0.002, 0.001 * x],
        });
    }
    Chain::standard(&rows, &links)
}

/// A 7-joint arm with runs of parallel revolute joints (2-3-4 and 5-6) and a prismatic
/// last joint; with `symmetric_tip`, it ends at joint 6, whose link is axially symmetric.
pub(crate) fn parallel_chain(q: &[f64], symmetric_tip: bool) -> Chain<f64> {
    let alphas = [std::f64::consts::FRAC_PI_2, 0.0, 0.0, -0.7, 0.0, 0.0, 0.3];
    let joints = if symmetric_tip { 6 } else { 7 };
    let mut rows = Vec::new();
    let mut links = Vec::new();
    for (i, (&alpha, &qi)) in alphas.iter().zip(q).take(joints).enumerate() {
        let x = i as f64;
        let kind = if i == 6 {
            JointKind::Prismatic
        } else {
            JointKind::Revolute
        };
        let (theta, d) = match kind {
            JointKind::Revolute => (qi + 0.2 * x, 0.04 * x),
            JointKind::Prismatic => (0.3, qi),
        };
        rows.push(DhRow {
            kind,
            sin_theta: theta.sin(),
            cos_theta: theta.cos(),
            d,
            a: 0.25 - 0.03 * x,
            sin_alpha: alpha.sin(),
            cos_alpha: alpha.cos(),
        });
        let tip = symmetric_tip && i == 5;
        links.push(Inertial {
            mass: 1.0 + 0.2 * x,
            com: if tip {
                V3::new(0.0, 0.0, 0.05)
            } else {
                V3::new(-0.1 + 0.02 * x, 0.03, 0.05)
            },
            inertia: if tip {
                [0.02, 0.02, 0.01, 0.0, 0.0, 0.0]
            } else {
                [0.05, 0.04 + 0.01 * x, 0.03, 0.004, -0.002, 0.001 * x]
            },
        });
    }
    // The standard table's last twist is not a joint's: the tip's link keeps its axes.
    if symmetric_tip {
        rows[5].sin_alpha = 0.0;
        rows[5].cos_alpha = 1.0;
    }
    Chain::standard(&rows, &links)
}

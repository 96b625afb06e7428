//! A quadruped standing on its four feet: Solo 12 from its URDF on a free-flying base
//! (`base = floating`), its feet (the URDF's leaf links) the frames of its kinematics and
//! contacts. The posture is example-robot-data's `standing` (`solo.srdf`), at rest.
//!
//! ```text
//! cargo run --release -p dynamics-examples --example solo12_standing
//! ```
//!
//! The method: with `v = a = 0`, inverse dynamics with the feet's forces `λ` is
//! `τ = g(q) − Jᵀ λ` (`inverse_dynamics_with_forces`). The base has no actuator, so its six
//! rows must vanish: `J_bᵀ λ = g_b`, six equations in the twelve force components (`J_b` the
//! feet's Jacobians' base columns). Of their solutions this takes the one of minimum norm,
//! `λ = J_b (J_bᵀ J_b)⁻¹ g_b` (the smallest forces that hold the robot; for feet placed
//! symmetrically about the centre of mass they stand nearly vertical), and the joint torques
//! are the joints' rows of `τ`. Then the constrained forward dynamics with the four feet held
//! (`contact_dynamics`, Pinocchio's `constraintDynamics`) at these torques gives `a = 0` and
//! the same forces: the posture is an equilibrium. Last, one linearisation of its dynamics for
//! an MPC step, from the floating base's first derivatives (`derivatives = true`). It checks
//! itself and fails otherwise.

use dynamics_runtime::{
    FloatingContacts, FloatingDynamics, FloatingDynamicsDerivatives, FloatingKinematics,
};
use nalgebra::{SMatrix, SVector};

#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/solo12.urdf",
    base = floating,
    derivatives = true,
    contacts = true
)]
struct Solo12;

const NV: usize = 18;
const G: f64 = 9.81;
/// The MPC's step [s].
const DT: f64 = 0.01;

/// example-robot-data's `standing` posture of Solo 12 (its `solo.srdf`), the joints in the
/// file's order: FL, FR, HL, HR, each HAA, HFE, KFE.
const STANDING: [f64; 19] = [
    0.0, 0.0, 0.235, 0.0, 0.0, 0.0, 1.0, // base: position, quaternion (x, y, z, w)
    0.1, 0.8, -1.6, // FL
    -0.1, 0.8, -1.6, // FR
    0.1, -0.8, 1.6, // HL
    -0.1, -0.8, 1.6, // HR
];

fn main() {
    let q = STANDING;
    let zero = [0.0; NV];
    let forces = standing_forces(&q);
    let tau = Solo12.inverse_dynamics_with_forces(&q, &zero, &zero, &forces);
    let poses = Solo12.frame_poses(&q);
    let com = Solo12.center_of_mass(&q);
    let mass = Solo12.centroidal_momentum_matrix(&q)[0][0];

    println!("Solo 12 standing (example-robot-data's `standing` posture), at rest");
    println!(
        "  mass {mass:.4} kg, centre of mass ({:.4}, {:.4}, {:.4}) m",
        com[0], com[1], com[2]
    );
    println!("\n  foot      position [m]                   force on the foot [N]        |f_t|/f_z");
    for (f, name) in Solo12::FRAME_NAMES.iter().enumerate() {
        let [x, y, z] = poses[f].position;
        let [fx, fy, fz] = forces[f];
        println!(
            "  {name:<8} ({x:7.4}, {y:7.4}, {z:7.4})   ({fx:7.4}, {fy:7.4}, {fz:7.4})   {:.4}",
            fx.hypot(fy) / fz
        );
    }
    println!(
        "\n  joint torques that hold it [N·m] (the base's six rows: {:.1e})",
        max_abs(&tau[..6])
    );
    for (leg, torques) in ["FL", "FR", "HL", "HR"].iter().zip(tau[6..].chunks(3)) {
        println!(
            "  {leg}  HAA {:8.4}  HFE {:8.4}  KFE {:8.4}",
            torques[0], torques[1], torques[2]
        );
    }

    // The feet's forces carry the weight, and the constrained dynamics at these torques
    // stays at rest with the same forces.
    let weight: f64 = forces.iter().map(|f| f[2]).sum();
    assert!(
        (weight - mass * G).abs() < 1e-9 * mass * G,
        "the feet carry {weight} N"
    );
    assert!(max_abs(&tau[..6]) < 1e-9, "the base needs {:?}", &tau[..6]);
    let held = Solo12
        .contact_dynamics(&q, &zero, &tau, &[true; 4])
        .expect("four independent contacts");
    let (acc, drift) = (
        max_abs(&held.acceleration),
        max_abs(&difference(&held.forces, &forces)),
    );
    println!("\n  constrained forward dynamics with the four feet held, at these torques:");
    println!("  |a| ≤ {acc:.1e}, the forces differ by ≤ {drift:.1e} N");
    assert!(acc < 1e-9 && drift < 1e-9);

    // At rest the centroidal momentum is zero; moving the base at 0.1 m/s forward (its own x,
    // the world's here) gives the whole robot's linear momentum, m · 0.1.
    let ag = Solo12.centroidal_momentum_matrix(&q);
    let mut v = zero;
    v[0] = 0.1;
    let momentum: [f64; 6] = core::array::from_fn(|i| (0..NV).map(|j| ag[i][j] * v[j]).sum());
    println!("\n  centroidal momentum at rest: 0; with the base at 0.1 m/s forward:");
    println!(
        "  linear ({:.4}, {:.4}, {:.4}) kg·m/s, angular ({:.4}, {:.4}, {:.4}) kg·m²/s",
        momentum[0], momentum[1], momentum[2], momentum[3], momentum[4], momentum[5]
    );
    assert!((momentum[0] - 0.1 * mass).abs() < 1e-12);

    linearise_for_one_mpc_step(&q);

    println!("\nchecks passed: the feet carry the weight, the base needs no wrench, the held");
    println!("feet keep the robot at rest (a = 0) with the same forces, the momentum is m v,");
    println!("the linearisation matches central differences");
}

/// The step of the MPC's model: `x⁺ = A x + B u`, `A` (36 × 36) over the state `x = (δq, v)`,
/// `δq` in the tangent (the base's position and rotation in its own frame, then the joints), `B`
/// (36 × 18) over the generalized force `u = τ + Σ J_fᵀ λ_f` (the joints' torques and the feet's
/// forces together, the feet's Jacobians held at the posture: the usual first-order model of
/// one step). Semi-implicit Euler, `v⁺ = v + dt a(q, v, u)`, `q⁺ = q ⊕ dt v⁺`; at `v = 0`
/// `∂(q ⊕ dt v⁺)/∂q` is the identity, so
/// `A = [[1 + dt² ∂a/∂q, dt 1 + dt² ∂a/∂v], [dt ∂a/∂q, 1 + dt ∂a/∂v]]`,
/// `B = [[dt² M⁻¹], [dt M⁻¹]]`, with `∂a/∂q`, `∂a/∂v`, `∂a/∂u = M⁻¹` Pinocchio's
/// `computeABADerivatives` (`derivatives = true`).
type StepMatrix = SMatrix<f64, { 2 * NV }, { 2 * NV }>;

/// One linearisation about the posture `q` at rest, for an MPC step of `DT`; it checks itself.
fn linearise_for_one_mpc_step(q: &[f64; 19]) {
    let zero = [0.0; NV];
    let u = Solo12.generalized_gravity(q);
    let d = Solo12
        .forward_dynamics_derivatives(q, &zero, &u)
        .expect("M is positive definite");
    let step = StepMatrix::from_fn(|r, c| {
        let (row, col) = (r % NV, c % NV);
        let da = if c < NV {
            d.dqdd_dq[row][col]
        } else {
            d.dqdd_dqd[row][col]
        };
        let identity = f64::from(u8::from(r == c)) + if r < NV && c == r + NV { DT } else { 0.0 };
        identity + if r < NV { DT * DT * da } else { DT * da }
    });
    let input = SMatrix::<f64, { 2 * NV }, NV>::from_fn(|r, c| {
        (if r < NV { DT * DT } else { DT }) * d.dqdd_dtau[r % NV][c]
    });
    println!("\n  one MPC step, linearised about the posture (dt = {DT} s): x⁺ = A x + B u,");
    let (a, b) = (step.shape(), input.shape());
    println!(
        "  A {}×{}, B {}×{}; a = {:.1e} at the posture",
        a.0,
        a.1,
        b.0,
        b.1,
        max_abs(&d.qdd)
    );
    // Tilting the base turns gravity in its frame and accelerates every body alike: the
    // rotation's columns of ∂a/∂q are [g_b]× in the base's linear rows and zero elsewhere.
    println!(
        "  ∂a/∂q, the base's linear rows by its rotation (gravity tilted with it) [m/s² per rad]:"
    );
    for row in &d.dqdd_dq[..3] {
        println!("    {:8.4} {:8.4} {:8.4}", row[3], row[4], row[5]);
    }
    let others: Vec<f64> = d.dqdd_dq[3..]
        .iter()
        .flat_map(|r| r[3..6].to_vec())
        .collect();
    assert!((d.dqdd_dq[0][4] - G).abs() < 1e-9 && (d.dqdd_dq[1][3] + G).abs() < 1e-9);
    assert!(max_abs(&others) < 1e-9);
    let error = central_differences_error(q, &u, &d.dqdd_dq);
    println!("  ∂a/∂q against central differences along integrate: {error:.1e}");
    assert!(
        error < 1e-5,
        "∂a/∂q is {error:e} from its central differences"
    );
    // One nonlinear step from the posture tilted about x, u held, beside A x: the gap is second
    // order in the tilt (a tenth of the tilt, a hundredth of the gap).
    let ((v_y, gap), (_, smaller)) = (one_step(q, &u, &step, 1e-2), one_step(q, &u, &step, 1e-3));
    println!(
        "  one step from a 0.01 rad tilt about x: v_y⁺ = {v_y:.6} m/s, |A x − step| = {gap:.1e}"
    );
    println!("  (from 0.001 rad: {smaller:.1e}, second order in the tilt)");
    assert!(
        smaller * 50.0 < gap && gap < 1e-4,
        "the linear step is {gap:e} from the nonlinear one"
    );
}

/// The largest gap between `∂a/∂q` and central differences of the forward dynamics at `u`
/// along `integrate`, at rest.
fn central_differences_error(q: &[f64; 19], u: &[f64; NV], dqdd_dq: &[[f64; NV]; NV]) -> f64 {
    let (zero, h) = ([0.0; NV], 1e-6);
    let at = |j: usize, h: f64| {
        let mut e = zero;
        e[j] = h;
        Solo12
            .forward_dynamics(&Solo12.integrate(q, &e), &zero, u)
            .unwrap()
    };
    (0..NV)
        .flat_map(|j| {
            let (plus, minus) = (at(j, h), at(j, -h));
            (0..NV).map(move |i| ((plus[i] - minus[i]) / (2.0 * h) - dqdd_dq[i][j]).abs())
        })
        .fold(0.0, f64::max)
}

/// One nonlinear step of `DT` from `q` tilted by `tilt` about the base's x, at rest, `u` held:
/// the base's `v_y⁺`, and the largest gap between `A x` and the step, `x` the tilt.
fn one_step(q: &[f64; 19], u: &[f64; NV], step: &StepMatrix, tilt: f64) -> (f64, f64) {
    let zero = [0.0; NV];
    let mut x = SVector::<f64, { 2 * NV }>::zeros();
    x[3] = tilt;
    let tilted = Solo12.integrate(q, &core::array::from_fn(|i| x[i]));
    let a = Solo12.forward_dynamics(&tilted, &zero, u).unwrap();
    let v_next: [f64; NV] = core::array::from_fn(|i| DT * a[i]);
    let q_next = Solo12.integrate(&tilted, &core::array::from_fn(|i| DT * v_next[i]));
    let dq_next = Solo12.difference(q, &q_next);
    let nonlinear =
        SVector::<f64, { 2 * NV }>::from_fn(
            |i, _| if i < NV { dq_next[i] } else { v_next[i - NV] },
        );
    (nonlinear[NV + 1], (step * x - nonlinear).amax())
}

/// The minimum-norm forces on the four feet, in world axes, whose wrench on the base is the
/// base's rows of `g(q)`: `λ = J_b (J_bᵀ J_b)⁻¹ g_b`, `J_b` (12 × 6) the feet's linear
/// Jacobians' base columns.
fn standing_forces(q: &[f64; 19]) -> [[f64; 3]; 4] {
    let jacobians = Solo12.frame_jacobians_world_aligned(q);
    let gravity = Solo12.generalized_gravity(q);
    let base = SMatrix::<f64, 12, 6>::from_fn(|r, c| jacobians[r / 3][r % 3][c]);
    let g_base = SVector::<f64, 6>::from_fn(|i, _| gravity[i]);
    let gram = base.transpose() * base;
    let lambda = base
        * gram
            .cholesky()
            .expect("the feet hold the base")
            .solve(&g_base);
    core::array::from_fn(|f| core::array::from_fn(|i| lambda[3 * f + i]))
}

fn max_abs(x: &[f64]) -> f64 {
    x.iter().fold(0.0, |m, &y| m.max(y.abs()))
}

fn difference(a: &[[f64; 3]; 4], b: &[[f64; 3]; 4]) -> [f64; 12] {
    core::array::from_fn(|k| a[k / 3][k % 3] - b[k / 3][k % 3])
}

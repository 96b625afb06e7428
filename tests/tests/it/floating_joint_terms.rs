//! Joint friction and actuator inertia on a floating base: PAL's Talos (`talos_reduced.urdf`,
//! 32 joints, 20 of them with `<dynamics damping friction>`) and Solo 12 given as a
//! description file with every joint's `actuator_inertia`, `friction_viscous` and
//! `friction_coulomb` (`solo12_joint_terms.toml`), against Pinocchio 4.1
//! (`talos_reduced.json`, `solo12_joint_terms.json`, by `make.py`'s `friction_data` and
//! `joint_terms`): M (Pinocchio's armature on its diagonal), h, τ = rnea + the joints' friction
//! (added by hand: Pinocchio's `rnea` reads neither `damping` nor `friction`), g, and the
//! forward dynamics `aba(q, v, τ − friction)`, to 1e-12 scaled (Talos's forward dynamics to
//! 1e-10: its M's condition number reaches 8.7e4).

use super::floating_base::{array, check_against_pinocchio, numbers, reference, TOLERANCE};
use super::floating_derivatives::{against_pinocchio, with_room, Solo12 as RigidSolo12};
use dynamics_reference::scaled_error;
use dynamics_runtime::{FloatingContacts, FloatingDynamics, FloatingDynamicsDerivatives};

/// Talos, its feet's soles the frames of its kinematics (not its 16 leaves).
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/floating/talos_reduced.urdf",
    base = floating,
    tips = ["left_sole_link", "right_sole_link"]
)]
struct Talos;

/// Solo 12 with joint terms, from its description file, and their derivatives.
#[derive(dynamics_runtime::Dynamics)]
#[dynamics(
    file = "data/floating/solo12_joint_terms.toml",
    base = floating,
    derivatives = true
)]
struct Solo12JointTerms;

/// `forward_dynamics` at each sample's `tau_in` against `a_fd` to `tolerance`, and `τ` back
/// from it; the largest error.
fn forward<R: FloatingDynamics<Q, V>, const Q: usize, const V: usize>(
    robot: &R,
    name: &str,
    tolerance: f64,
) -> f64 {
    let mut worst: f64 = 0.0;
    let data = reference(name);
    for (k, s) in data["samples"]
        .as_array()
        .expect("samples")
        .iter()
        .enumerate()
    {
        let (q, v, tau) = (
            array::<Q>(&s["q"]),
            array::<V>(&s["v"]),
            array::<V>(&s["tau_in"]),
        );
        let a = robot.forward_dynamics(&q, &v, &tau).expect("M");
        let error = scaled_error(&a, &numbers(&s["a_fd"]));
        worst = worst.max(error);
        assert!(error < tolerance, "{name} sample {k}: a off by {error:e}");
        let back = robot.inverse_dynamics(&q, &v, &a);
        let error = scaled_error(&back, &tau);
        assert!(error < 1e-10, "{name} sample {k}: τ(a) off by {error:e}");
    }
    worst
}

#[test]
fn talos_with_friction_against_pinocchio() {
    assert_eq!((Talos::NQ, Talos::NV), (39, 38));
    check_against_pinocchio(&Talos, "talos_reduced");
    // Talos's M has a condition number up to 8.7e4 on these states (the G1's reaches 3.5e5,
    // whose forward derivatives are checked to 1e-10): the LDLᵀ from the tips and Pinocchio's
    // `aba` are each as close to an exact solve as that allows, not to 1e-12 of each other.
    let worst = forward(&Talos, "talos_reduced", 1e-10);
    eprintln!("Talos forward dynamics: worst {worst:e}");
}

#[test]
fn joint_terms_against_pinocchio() {
    check_against_pinocchio(&Solo12JointTerms, "solo12_joint_terms");
    forward(&Solo12JointTerms, "solo12_joint_terms", TOLERANCE);
}

/// The derivatives beside actuator inertia and friction, against Pinocchio's with the armature
/// in its model and the friction's terms added by hand (`solo12_joint_terms_derivatives.json`):
/// `∂τ/∂v` has the viscous coefficients on its joints' diagonal, Coulomb's sign is flat (its
/// derivative 0 away from `v = 0`), `∂a/∂v = −M⁻¹ ∂τ/∂v`, M with the armature.
#[test]
fn joint_terms_derivatives_against_pinocchio() {
    with_room(|| {
        let [inverse, forward] =
            against_pinocchio(&Solo12JointTerms, "solo12_joint_terms", TOLERANCE);
        eprintln!(
            "Solo 12 with joint terms: largest scaled errors ∂τ {inverse:e}, a and ∂a {forward:e}"
        );
    });
}

/// The viscous coefficients are `∂τ/∂v`'s joints' diagonal beyond the rigid body's: the same
/// state's derivatives less those of Solo 12 without joint terms (its `∂τ/∂v` does not depend
/// on the armature, `a` held).
#[test]
fn viscous_friction_on_the_diagonal_of_dtau_dv() {
    with_room(|| {
        let data = reference("solo12_joint_terms");
        let s = &data["samples"][5];
        let (q, v, a) = (
            array::<19>(&s["q"]),
            array::<18>(&s["v"]),
            array::<18>(&s["a"]),
        );
        let with = Solo12JointTerms
            .inverse_dynamics_derivatives(&q, &v, &a)
            .dtau_dqd;
        let without = RigidSolo12
            .inverse_dynamics_derivatives(&q, &v, &a)
            .dtau_dqd;
        let damping = numbers(&data["damping"]);
        for i in 0..18 {
            for j in 0..18 {
                let expected = if i == j && i >= 6 {
                    damping[i - 6]
                } else {
                    0.0
                };
                let gap = with[i][j] - without[i][j] - expected;
                assert!(gap.abs() < 1e-12, "∂τ_{i}/∂v_{j}: {gap:e}");
            }
        }
    });
}

/// Friction is in τ and not in h: `τ(q, v, 0) − h(q, v)` is the joints' friction torque, zero
/// in the base's rows; and the contacts see it (their free acceleration is
/// `forward_dynamics`').
#[test]
fn friction_is_in_tau_not_in_h() {
    let data = reference("talos_reduced");
    let s = &data["samples"][4];
    let (q, v) = (array::<39>(&s["q"]), array::<38>(&s["v"]));
    let tau = Talos.inverse_dynamics(&q, &v, &[0.0; 38]);
    let h = Talos.bias_forces(&q, &v);
    let friction: Vec<f64> = tau.iter().zip(&h).map(|(t, h)| t - h).collect();
    let error = scaled_error(&friction, &numbers(&s["friction"]));
    assert!(error < TOLERANCE, "friction off by {error:e}");
    let tau_in = array::<38>(&s["tau_in"]);
    let free = Talos
        .contact_dynamics(&q, &v, &tau_in, &[false; 2])
        .expect("M");
    let error = scaled_error(&free.acceleration, &numbers(&s["a_fd"]));
    assert!(error < TOLERANCE, "free acceleration off by {error:e}");
}

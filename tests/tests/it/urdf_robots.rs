//! The URDF robots of `robots/urdf/` (example-robot-data 6.0.0), each derived from its file with
//! `#[derive(Dynamics)] #[dynamics(urdf = .., base = .., tip = ..)]` (in
//! `dynamics_tests::robots::urdf`, shared with `regressor.rs`), against Pinocchio 4.1.0's
//! URDF loader (`tests/data/urdf/<robot>.json`, by `make.py`: the chain from base to tip with
//! the links fixed to it, angles within 1e-5 rad of a quarter turn snapped): for every sample,
//! τ, M, C, C·q̇ + g, g and both energies match to 1e-10 (scaled). τ adds each joint's
//! `<dynamics damping friction>` (`damping · q̇ + friction · sign(q̇)`), which Pinocchio's τ
//! leaves out; C·q̇ + g does not.
//!
//! The UR5 and the Panda also match their D-H twins (`robots/<robot>_urdf_dh.toml`, by
//! `twins.py`, checked against the same data by `urdf_twins.rs`) sample by sample, and each
//! generated dynamics method of the URDF robot takes at most 5 % more operations than the
//! twin's. The hand frame (the tip link) and its Jacobian match Pinocchio's too.

use dynamics_codegen::method::Family;
use dynamics_codegen::{derive, front, generate};
use dynamics_reference::scaled_error;
use dynamics_runtime::Dynamics;
use dynamics_tests::reference::{check, flat, samples, vector, Friction, TOLERANCE};
use dynamics_tests::robots::urdf::{Panda, So101, Ur10, Ur5, Z1};
use dynamics_tests::robots::{PandaTwin, Ur5Twin};

#[test]
fn ur5_matches_pinocchio() {
    check(&Ur5, "urdf/ur5.json", Friction::Added);
}

#[test]
fn ur10_matches_pinocchio() {
    check(&Ur10, "urdf/ur10.json", Friction::Added);
}

/// Viscous damping 0.003 on every joint: τ includes it.
#[test]
fn panda_matches_pinocchio() {
    check(&Panda, "urdf/panda.json", Friction::Added);
}

/// Viscous and Coulomb friction of 1 and 2 on every joint: τ includes them.
#[test]
fn z1_matches_pinocchio() {
    check(&Z1, "urdf/z1.json", Friction::Added);
}

/// Five joints whose origins write 1.5708 and 3.14159: snapped, as the data's were.
#[test]
fn so101_matches_pinocchio() {
    check(&So101, "urdf/so101.json", Friction::Added);
}

/// The URDF robot and its twin (which declares the URDF's friction too) side by side on the
/// data's states.
fn matches_twin<R: Dynamics<N>, T: Dynamics<N>, const N: usize>(urdf: &R, twin: &T, file: &str) {
    for (k, s) in samples(file).iter().enumerate() {
        let (q, qd, qdd) = (
            vector::<N>(&s["q"]),
            vector::<N>(&s["qd"]),
            vector::<N>(&s["qdd"]),
        );
        let pairs = [
            (
                "tau",
                urdf.inverse_dynamics(&q, &qd, &qdd).to_vec(),
                twin.inverse_dynamics(&q, &qd, &qdd).to_vec(),
            ),
            (
                "friction",
                urdf.friction_torques(&qd).to_vec(),
                twin.friction_torques(&qd).to_vec(),
            ),
            ("M", flat(urdf.mass_matrix(&q)), flat(twin.mass_matrix(&q))),
            (
                "C",
                flat(urdf.coriolis_matrix(&q, &qd)),
                flat(twin.coriolis_matrix(&q, &qd)),
            ),
            (
                "h",
                urdf.bias_torques(&q, &qd).to_vec(),
                twin.bias_torques(&q, &qd).to_vec(),
            ),
            (
                "g",
                urdf.gravity_torques(&q).to_vec(),
                twin.gravity_torques(&q).to_vec(),
            ),
            (
                "kinetic energy",
                vec![urdf.kinetic_energy(&q, &qd)],
                vec![twin.kinetic_energy(&q, &qd)],
            ),
            (
                "potential energy",
                vec![urdf.potential_energy(&q)],
                vec![twin.potential_energy(&q)],
            ),
        ];
        for (what, got, want) in pairs {
            let e = scaled_error(&got, &want);
            assert!(
                e < TOLERANCE,
                "{file} sample {k}: {what} of the URDF robot off its twin's by {e:e}"
            );
        }
    }
}

#[test]
fn ur5_matches_its_dh_twin() {
    matches_twin(&Ur5, &Ur5Twin, "urdf/ur5.json");
}

#[test]
fn panda_matches_its_dh_twin() {
    matches_twin(&Panda, &PandaTwin, "urdf/panda.json");
}

/// Operations per generated dynamics method (`dynamics stats`' flops) of the robot of
/// `attribute`. The kinematic methods are left out: the URDF robot's hand is its tip link
/// (`tool0`, `panda_link8`), a tool transform after the D-H twin's last frame.
fn flops(attribute: &str, name: &str) -> Vec<(&'static str, usize)> {
    let source = format!("#[dynamics({attribute})] struct {name};");
    let input = front::parse_str(&source).unwrap_or_else(|e| panic!("{name}: {e}"));
    let generated = generate(&derive(&input.robot), Vec::new());
    generated
        .methods
        .iter()
        .filter(|m| m.method.family() == Family::Dynamics)
        .map(|m| (m.name, m.ops.flops()))
        .collect()
}

/// The issue's budget: a URDF robot's code as small as its D-H twin's, within 5 % per method.
fn counts_within_five_percent(urdf: &str, twin: &str) {
    let (got, want) = (flops(urdf, "Urdf"), flops(twin, "Twin"));
    assert_eq!(
        got.iter().map(|m| m.0).collect::<Vec<_>>(),
        want.iter().map(|m| m.0).collect::<Vec<_>>()
    );
    for ((method, ops), (_, twin_ops)) in got.iter().zip(&want) {
        eprintln!("{method}: {ops} operations from the URDF, {twin_ops} from the twin");
        assert!(
            *ops as f64 <= 1.05 * *twin_ops as f64,
            "{method}: {ops} operations from the URDF, {twin_ops} from the D-H twin (over 5 %)"
        );
    }
}

#[test]
fn ur5_costs_what_its_twin_costs() {
    counts_within_five_percent(
        r#"urdf = "../robots/urdf/ur5.urdf", base = "base_link", tip = "tool0""#,
        r#"file = "../robots/ur5_urdf_dh.toml""#,
    );
}

/// The URDF Panda's τ adds its damping (7 multiplications, 7 additions) to the twin's.
#[test]
fn panda_costs_what_its_twin_costs() {
    counts_within_five_percent(
        r#"urdf = "../robots/urdf/panda.urdf", base = "panda_link0", tip = "panda_link8""#,
        r#"file = "../robots/panda_urdf_dh.toml""#,
    );
}

/// The hand frame of a URDF robot is its tip link (`tool0` on the UR robots, a fixed frame
/// after the last joint): its pose and its Jacobian in base axes against Pinocchio's
/// (`ee_pose`, `jacobian` rows `[v; ω]` of the data) on every sample.
fn hand_matches_pinocchio<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) {
    for (k, s) in samples(file).iter().enumerate() {
        let q = vector::<N>(&s["q"]);
        let pose = robot.hand_pose(&q).homogeneous();
        let want_pose: Vec<f64> = (0..4)
            .flat_map(|i| (0..4).map(move |j| (i, j)))
            .map(|(i, j)| s["ee_pose"][i][j].as_f64().unwrap())
            .collect();
        let e = scaled_error(&flat(pose), &want_pose);
        assert!(e < TOLERANCE, "{file} sample {k}: hand pose off by {e:e}");
        let jacobian = robot.hand_jacobian_in_base(&q);
        let want: Vec<f64> = (0..6)
            .flat_map(|i| (0..N).map(move |j| (i, j)))
            .map(|(i, j)| s["jacobian"][i][j].as_f64().unwrap())
            .collect();
        let got: Vec<f64> = jacobian.iter().flatten().copied().collect();
        let e = scaled_error(&got, &want);
        assert!(
            e < TOLERANCE,
            "{file} sample {k}: hand Jacobian off by {e:e}"
        );
    }
}

#[test]
fn hands_match_pinocchio() {
    hand_matches_pinocchio(&Ur5, "urdf/ur5.json");
    hand_matches_pinocchio(&Ur10, "urdf/ur10.json");
    hand_matches_pinocchio(&Panda, "urdf/panda.json");
    hand_matches_pinocchio(&Z1, "urdf/z1.json");
    hand_matches_pinocchio(&So101, "urdf/so101.json");
}

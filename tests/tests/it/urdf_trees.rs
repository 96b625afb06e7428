//! Robots that branch, each derived from its URDF with every moving joint below the base (all
//! branches), against Pinocchio 4.1.0's URDF loader (`tests/data/trees/<robot>.json`, by
//! `make.py`, in the front end's joint order: depth first, a link's child joints in the file's
//! order): for every sample, τ (less the URDF's joint friction, which Pinocchio's τ leaves out),
//! M, C, h = C·q̇ + g, g, C·q̇, both energies and the forward dynamics (the data's torque plus
//! the friction).
//!
//! * The Allegro right hand: four fingers of four joints off the palm. Its masses are grams and
//!   its torques millinewton-metres, so each quantity is compared relative to its own largest
//!   element rather than to max(1, ·).
//! * The Panda with its gripper's fingers free (`panda_free_fingers.urdf`: the URDF with its
//!   `<mimic>` element removed, by `free_fingers.py`): a tree that branches below the base, the
//!   two fingers hanging off the last arm link.
//! * The Panda with its URDF's `<mimic>`: the second finger follows the first, 9 joints and 8
//!   coordinates, every output in the reduced coordinates (`panda_fingers.json`: Pinocchio 4.1's
//!   mimic model; C the projected `Gᵀ C G`, the forward dynamics the reduced solve).
//! * Baxter with its grippers' fingers free (`baxter_free_fingers.urdf`, by `free_fingers.py`):
//!   19 joints, past the serial limit of 16 (a tree is bounded along each path): the head and
//!   two arms of seven off the base, two fingers off each arm's last link; and with its
//!   `<mimic>` fingers (`baxter.json`), 17 coordinates.

use dynamics_reference::scaled_error;
use dynamics_runtime::Dynamics;
use dynamics_tests::reference::{quantities, samples, vector, Friction, TOLERANCE};

macro_rules! urdf_tree {
    ($name:ident, $file:literal, $base:literal) => {
        #[derive(Dynamics)]
        #[dynamics(urdf = $file, base = $base)]
        // Shared with `urdf_tips.rs` (one derive of each robot in the binary).
        pub(crate) struct $name;
    };
}

/// The hand's published inertias break the triangle inequality (Pinocchio takes them as given).
#[derive(Dynamics)]
#[dynamics(
    urdf = "../robots/urdf/trees/allegro_right_hand.urdf",
    base = "palm_link",
    check_inertia = false
)]
struct AllegroHand;
urdf_tree!(
    PandaFreeFingers,
    "../robots/urdf/trees/panda_free_fingers.urdf",
    "panda_link0"
);
urdf_tree!(
    BaxterFreeFingers,
    "../robots/urdf/trees/baxter_free_fingers.urdf",
    "base"
);

urdf_tree!(
    BaxterMimicFingers,
    "../robots/urdf/trees/baxter.urdf",
    "base"
);
urdf_tree!(
    PandaMimicFingers,
    "../robots/urdf/panda.urdf",
    "panda_link0"
);

/// How a quantity's error is measured: scaled by max(1, max|want|) as every other data file,
/// or relative to max|want| for a robot whose quantities are all far below 1.
#[derive(Clone, Copy)]
enum Measure {
    Scaled,
    Relative,
}

impl Measure {
    fn error(self, got: &[f64], want: &[f64]) -> f64 {
        let largest = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        match self {
            Measure::Scaled => scaled_error(got, want),
            // An all-zero quantity (C at rest) is compared absolutely.
            Measure::Relative if largest == 0.0 => scaled_error(got, want),
            Measure::Relative => scaled_error(got, want) * 1.0f64.max(largest) / largest,
        }
    }
}

/// `robot` against every sample of `tests/data/trees/<file>`, each quantity within `tolerance`
/// (the forward dynamics, a solve, within 100 times that); returns the worst error.
fn check<R: Dynamics<N>, const N: usize>(
    robot: &R,
    file: &str,
    measure: Measure,
    tolerance: f64,
) -> f64 {
    let mut worst = 0.0f64;
    for (k, s) in samples(&format!("trees/{file}")).iter().enumerate() {
        let v = |key: &str| vector::<N>(&s[key]);
        let (q, qd, friction) = (v("q"), v("qd"), v("friction"));
        let forward_tau = vector::<N>(&s["forward"]["tau"]);
        let torque: [f64; N] = core::array::from_fn(|i| forward_tau[i] + friction[i]);
        let forward = robot
            .forward_dynamics(&q, &qd, &torque)
            .unwrap_or_else(|_| panic!("{file} sample {k}: M not positive definite"));
        // τ less the URDF's joint friction, which the hand's swamps (25 N·m against 0.04).
        let mut checks = quantities(robot, s, Friction::Added);
        checks.push((
            "forward dynamics",
            forward.to_vec(),
            vector::<N>(&s["forward"]["qdd"]).to_vec(),
        ));
        for (what, got, want) in checks {
            let e = measure.error(&got, &want);
            // The forward dynamics is a solve: its error is M's condition number times larger.
            let tolerance = if what == "forward dynamics" {
                100.0 * tolerance
            } else {
                tolerance
            };
            assert!(
                e < tolerance,
                "{file} sample {k}: {what} off by {e:e}\n got {got:?}\nwant {want:?}"
            );
            worst = worst.max(e);
        }
    }
    eprintln!("trees/{file}: worst error {worst:.1e}");
    worst
}

/// M(i, j) is an exact zero where neither joint is an ancestor of the other (the two fingers,
/// and any two joints of different fingers): the data's `zero_blocks_checked` pairs.
fn zero_blocks<R: Dynamics<N>, const N: usize>(robot: &R, file: &str) {
    let path = format!("{}/data/trees/{file}", env!("CARGO_MANIFEST_DIR"));
    let data: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&path).expect("data")).expect("JSON");
    let parents: Vec<Option<usize>> = data["parents"]
        .as_array()
        .expect("parents")
        .iter()
        .map(|p| p.as_u64().map(|p| usize::try_from(p).expect("an index")))
        .collect();
    let ancestor = |a: usize, mut b: usize| loop {
        if a == b {
            return true;
        }
        match parents[b] {
            Some(p) => b = p,
            None => return false,
        }
    };
    let mut pairs = 0;
    for s in samples(&format!("trees/{file}")) {
        let m = robot.mass_matrix(&vector::<N>(&s["q"]));
        for (i, row) in m.iter().enumerate() {
            for (j, &element) in row.iter().enumerate() {
                if !ancestor(i, j) && !ancestor(j, i) {
                    assert_eq!(element, 0.0, "{file}: M[{i}][{j}]");
                    pairs += 1;
                }
            }
        }
    }
    assert!(pairs > 0, "{file}: no pair of joints on different branches");
    into_leaves_zero_blocks(robot, file, &ancestor);
}

/// `mass_matrix_into` writes M's elements along each branch, bit for bit the by-value
/// `mass_matrix`'s, and leaves the exact zeros between branches as the caller's matrix has them
/// (NaN stays NaN there): a matrix of zeros, or the previous sample's M, becomes M.
fn into_leaves_zero_blocks<R: Dynamics<N>, const N: usize>(
    robot: &R,
    file: &str,
    ancestor: &dyn Fn(usize, usize) -> bool,
) {
    let mut previous = [[0.0; N]; N];
    for s in samples(&format!("trees/{file}")) {
        let q = vector::<N>(&s["q"]);
        let want = robot.mass_matrix(&q);
        let mut nan = [[f64::NAN; N]; N];
        robot.mass_matrix_into(&q, &mut nan);
        for (i, (got, want)) in nan.iter().zip(&want).enumerate() {
            for (j, (&got, &want)) in got.iter().zip(want).enumerate() {
                if ancestor(i, j) || ancestor(j, i) {
                    // Written, unless zero at every state (some element along one branch may be).
                    let left = got.is_nan() && want == 0.0;
                    assert!(
                        got.to_bits() == want.to_bits() || left,
                        "{file}: M[{i}][{j}]"
                    );
                } else {
                    assert!(got.is_nan(), "{file}: M[{i}][{j}] between branches written");
                }
            }
        }
        let mut zeros = [[0.0; N]; N];
        robot.mass_matrix_into(&q, &mut zeros);
        robot.mass_matrix_into(&q, &mut previous);
        for m in [zeros, previous] {
            let bits = |m: [[f64; N]; N]| m.map(|row| row.map(f64::to_bits));
            assert_eq!(bits(m), bits(want), "{file}");
        }
    }
}

#[test]
fn allegro_hand_matches_pinocchio() {
    // The thumb's first axis is 9e-10 rad off parallel to the palm's frame 0 axis in the URDF:
    // the front end takes such axes as parallel (their common normal is ill-conditioned), a
    // change of the robot of that order, which the hand's quantities show relative to their size.
    check(
        &AllegroHand,
        "allegro_right_hand.json",
        Measure::Relative,
        1e-8,
    );
    zero_blocks(&AllegroHand, "allegro_right_hand.json");
}

#[test]
fn panda_with_free_fingers_matches_pinocchio() {
    check(
        &PandaFreeFingers,
        "panda_fingers_no_mimic.json",
        Measure::Scaled,
        TOLERANCE,
    );
    zero_blocks(&PandaFreeFingers, "panda_fingers_no_mimic.json");
}

#[test]
fn panda_with_mimic_fingers_matches_pinocchio() {
    check(
        &PandaMimicFingers,
        "panda_fingers.json",
        Measure::Scaled,
        TOLERANCE,
    );
}

#[test]
fn baxter_with_free_fingers_matches_pinocchio() {
    let worst = check(
        &BaxterFreeFingers,
        "baxter_no_mimic.json",
        Measure::Scaled,
        1e-12,
    );
    assert!(
        worst > 0.0,
        "every quantity exact: the check compares nothing"
    );
    zero_blocks(&BaxterFreeFingers, "baxter_no_mimic.json");
}

#[test]
fn baxter_with_mimic_fingers_matches_pinocchio() {
    // Each gripper's second finger follows its first: 19 joints, 17 coordinates.
    check(&BaxterMimicFingers, "baxter.json", Measure::Scaled, 1e-12);
}

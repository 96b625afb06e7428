//! `base = floating` in the derive: Solo 12's expansion implements `FloatingDynamics<19, 18>`
//! and `FloatingKinematics<19, 18, F>` and nothing else (`FloatingDynamicsDerivatives`,
//! `FloatingDynamicsRegressor`, `FloatingDynamicsBaseParameters` where it asks), and every key or family the floating base does not support is a compile error
//! naming it (never methods that would be wrong on a flying base); mimic joints reduce to the
//! coordinates.

use dynamics_codegen::derive_dynamics;

/// The derive's expansion of Solo 12 with the keys `keys` after its `urdf`.
fn solo(keys: &str) -> String {
    let urdf = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../robots/urdf/floating/solo12.urdf"
    );
    let source = format!("#[dynamics(urdf = {urdf:?}, {keys})] struct Solo;");
    derive_dynamics(source.parse().expect("tokens")).to_string()
}

#[test]
fn a_floating_base_implements_the_floating_traits_only() {
    for keys in ["base = floating", "base = floating(\"base_link\")"] {
        let out = solo(keys);
        assert!(!out.contains("compile_error"), "{keys}: {out}");
        assert!(
            out.contains("FloatingDynamics < 19usize , 18usize >"),
            "{out}"
        );
        assert!(!out.contains(":: Dynamics <"), "{out}");
        // The URDF's moving leaves, the feet, are the frames by default.
        assert!(
            out.contains("FloatingKinematics < 19usize , 18usize , 4usize >"),
            "{out}"
        );
        assert!(out.contains("FRAME_FL_FOOT"), "{out}");
        // No derivatives unless asked for.
        assert!(!out.contains("FloatingDynamicsDerivatives"), "{out}");
    }
    let feet = solo("base = floating, tips = [\"FL_FOOT\", \"HR_FOOT\"]");
    assert!(!feet.contains("compile_error"), "{feet}");
    assert!(
        feet.contains("FloatingKinematics < 19usize , 18usize , 2usize >"),
        "{feet}"
    );
    assert!(feet.contains("FRAME_HR_FOOT"), "{feet}");
}

/// `derivatives = true` implements `FloatingDynamicsDerivatives<19, 18>` beside the rest, its
/// module beside the struct (outside the `const _` block, compiled apart), and leaves the rest
/// of the expansion as it was.
#[test]
fn a_floating_base_asks_for_its_derivatives() {
    let plain = solo("base = floating");
    let out = solo("base = floating, derivatives = true");
    assert!(!out.contains("compile_error"), "{out}");
    assert!(
        out.contains("FloatingDynamicsDerivatives < 19usize , 18usize >"),
        "{out}"
    );
    assert!(!out.contains(":: DynamicsDerivatives <"), "{out}");
    let (beside, block) = out.split_once("const _ : () =").expect("the block");
    assert!(
        beside.contains("mod __floating_derivatives_of_Solo"),
        "{out}"
    );
    assert!(!block.contains("mod __floating_derivatives"), "{out}");
    // The floating family's module and the kinematics' as without the derivatives.
    let floating = |x: &str| {
        let start = x.find("mod __floating ").expect("the floating module");
        let end = x
            .find("mod __floating_forward")
            .expect("the forward module");
        x[start..end].to_owned()
    };
    assert_eq!(floating(&out), floating(&plain));
}

/// `regressor = true` and `base_parameters = true` implement `FloatingDynamicsRegressor<19, 18,
/// 13>` (the floating body and 12 links) and `FloatingDynamicsBaseParameters<19, 18, B, 13>`,
/// and leave the floating family's module as it was; `base_parameters` alone does not emit the
/// regressor it traces.
#[test]
fn a_floating_base_asks_for_its_regressor_and_base_parameters() {
    let plain = solo("base = floating");
    let out = solo("base = floating, regressor = true, base_parameters = true");
    assert!(!out.contains("compile_error"), "{out}");
    assert!(
        out.contains("FloatingDynamicsRegressor < 19usize , 18usize , 13usize >"),
        "{out}"
    );
    assert!(
        out.contains("FloatingDynamicsBaseParameters < 19usize , 18usize , 94usize , 13usize >"),
        "{out}"
    );
    assert!(!out.contains(":: DynamicsRegressor <"), "{out}");
    let floating = |x: &str| {
        let start = x.find("mod __floating ").expect("the floating module");
        let end = x
            .find("mod __floating_forward")
            .expect("the forward module");
        x[start..end].to_owned()
    };
    assert_eq!(floating(&out), floating(&plain));
    let alone = solo("base = floating, base_parameters = true");
    assert!(!alone.contains("FloatingDynamicsRegressor <"), "{alone}");
    assert!(
        alone.contains("FloatingDynamicsBaseParameters <"),
        "{alone}"
    );
}

/// The number of base parameters of the three robots equals the numerical rank of Pinocchio's
/// regressor stacked at 40 random states (`tests/data/floating/*_regressor.json`, `make.py`):
/// Solo 12 and ANYmal B 94 of 130, the G1 213 of 300.
#[test]
fn base_parameters_count_the_rank_of_pinocchios_regressor() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    for (robot, bodies) in [("solo12", 13), ("anymal_b", 13), ("g1_29dof", 30)] {
        let data =
            std::fs::read_to_string(format!("{root}/tests/data/floating/{robot}_regressor.json"))
                .expect("the data");
        let at = data.find("\"rank\": ").expect("rank") + "\"rank\": ".len();
        let rank: usize = data[at..]
            .split(|c: char| !c.is_ascii_digit())
            .next()
            .and_then(|x| x.parse().ok())
            .expect("a number");
        let urdf = format!("{root}/robots/urdf/floating/{robot}.urdf");
        let source = format!(
            "#[dynamics(urdf = {urdf:?}, base = floating, base_parameters = true)] struct R;"
        );
        let out = derive_dynamics(source.parse().expect("tokens")).to_string();
        let nv = (bodies - 1) + 6;
        let nq = nv + 1;
        let expected = format!(
            "FloatingDynamicsBaseParameters < {nq}usize , {nv}usize , {rank}usize , {bodies}usize >"
        );
        assert!(out.contains(&expected), "{robot}: {expected}");
    }
}

#[test]
fn what_a_floating_base_does_not_have_yet_is_refused() {
    for (keys, message) in [
        (
            "base = floating, tip_kinematics = true",
            "`tip_kinematics = true` is not supported on a floating base yet",
        ),
        (
            "base = floating, tip = \"FL_FOOT\"",
            "`tip` is not supported on a floating base: name the frames with `tips",
        ),
        (
            "base = floating, simplify(tolerance_percent = 1)",
            "`simplify(..)` is not supported on a floating base yet",
        ),
        (
            "base = flying",
            "unknown base `flying`: expected `base = \\\"base_link\\\"`",
        ),
        ("base = floating(\"trunk\")", "no link `trunk` for `base`"),
        (
            "base = floating(3)",
            "expected a string: `floating(\\\"trunk\\\")`",
        ),
        (
            "base = floating, base = floating",
            "duplicate dynamics attribute `base`",
        ),
    ] {
        let out = solo(keys);
        assert!(out.contains("compile_error"), "{keys}: {out}");
        assert!(
            out.contains(message),
            "{keys}: expected {message:?} in {out}"
        );
        assert!(!out.contains("FloatingDynamics <"), "{keys}: {out}");
    }
}

/// The derive's expansion of a one-joint arm on a floating base with the keys `keys`.
fn arm(keys: &str) -> String {
    let source = format!(
        "#[dynamics({keys}, gravity = [0, 0, -9.81], dh = [[q, 0, 1, 0]], \
         link(mass = 1, com = [0, 0, 0], inertia = [0.1, 0.1, 0.1, 0, 0, 0]))] struct Arm;"
    );
    derive_dynamics(source.parse().expect("tokens")).to_string()
}

#[test]
fn a_dh_table_on_a_floating_base_takes_its_body_from_the_attribute() {
    let out =
        arm("base = floating(mass = 2, com = [0, 0, 0.1], inertia = [0.1, 0.2, 0.3, 0, 0, 0])");
    assert!(!out.contains("compile_error"), "{out}");
    assert!(
        out.contains("FloatingDynamics < 8usize , 7usize >"),
        "{out}"
    );
    for (keys, message) in [
        (
            "base = floating",
            "`base = floating` without a URDF needs the floating body: `base = floating(mass = ..",
        ),
        (
            "base = floating(com = [0, 0, 0])",
            "the floating body has no `mass = ..`",
        ),
        (
            "base = floating(mass = 1, actuator_inertia = 0.1)",
            "`actuator_inertia` has no meaning on a floating body",
        ),
        (
            "base = floating(mass = 1, mas = 2)",
            "unknown link attribute `mas`",
        ),
        (
            "base = floating(\"trunk\")",
            "`floating(\\\"link\\\")` names a URDF's link",
        ),
    ] {
        let out = arm(keys);
        assert!(out.contains("compile_error"), "{keys}: {out}");
        assert!(
            out.contains(message),
            "{keys}: expected {message:?} in {out}"
        );
        assert!(!out.contains("FloatingDynamics <"), "{keys}: {out}");
    }
}

#[test]
fn a_urdf_gives_its_own_floating_body() {
    let out = solo("base = floating(mass = 1)");
    assert!(out.contains("the URDF gives the floating body"), "{out}");
}

/// A description file's `[floating]` table and `base = floating` go together.
#[test]
fn a_description_file_floats_with_its_floating_table() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/");
    let derive = |file: &str, keys: &str| {
        let source = format!(
            "#[dynamics(file = {:?}{keys})] struct Robot;",
            format!("{root}{file}")
        );
        derive_dynamics(source.parse().expect("tokens")).to_string()
    };
    let solo = derive("floating/solo12.toml", ", base = floating");
    assert!(!solo.contains("compile_error"), "{solo}");
    assert!(
        solo.contains("FloatingDynamics < 19usize , 18usize >"),
        "{solo}"
    );
    for (file, keys, message) in [
        (
            "puma560.toml",
            ", base = floating",
            "the file has no `[floating]` table",
        ),
        ("floating/solo12.toml", "", "add `base = floating`"),
        (
            "floating/solo12.toml",
            ", base = floating(mass = 1)",
            "a description file gives the floating body in its `[floating]` table",
        ),
    ] {
        let out = derive(file, keys);
        assert!(out.contains("compile_error"), "{file}{keys}: {out}");
        assert!(
            out.contains(message),
            "{file}{keys}: expected {message:?} in {out}"
        );
    }
}

/// Mimic joints on a floating base: the configuration and velocity are the coordinates'
/// (`7 + 1`, `6 + 1` for two joints of which one follows the other), the kinematics and
/// derivatives too; the regressor and base parameters, not projected yet, are refused naming
/// them.
#[test]
fn mimic_joints_float_in_their_coordinates() {
    let derive = |keys: &str| {
        let source = format!(
            "#[dynamics(base = floating(mass = 2, com = [0, 0, 0.1], inertia = [0.1, 0.2, 0.3, 0, 0, 0]), \
             gravity = [0, 0, -9.81]{keys}, joints = [revolute(xyz = [0.1, 0, 0], axis = [0, 1, 0]), \
             revolute(xyz = [0, 0, -0.2], mimic = (joint = 1, multiplier = -1, offset = 0.25))], \
             link(mass = 1, com = [0, 0, -0.1], inertia = [0.1, 0.1, 0.1, 0, 0, 0]), \
             link(mass = 0.5, com = [0, 0, -0.1], inertia = [0.01, 0.01, 0.01, 0, 0, 0]))] struct Leg;"
        );
        derive_dynamics(source.parse().expect("tokens")).to_string()
    };
    let out = derive(", derivatives = true");
    assert!(!out.contains("compile_error"), "{out}");
    for expected in [
        "FloatingDynamics < 8usize , 7usize >",
        "FloatingKinematics < 8usize , 7usize , 1usize >",
        "FloatingDynamicsDerivatives < 8usize , 7usize >",
    ] {
        assert!(out.contains(expected), "{expected}: {out}");
    }
    for family in ["regressor", "base_parameters"] {
        let out = derive(&format!(", {family} = true"));
        let message =
            format!("`{family} = true` is not supported on a floating base with mimic joints yet");
        assert!(out.contains(&message), "{family}: {out}");
        assert!(!out.contains("FloatingDynamics <"), "{family}: {out}");
    }
}

use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::pipeline::{load, Diagnostic, Loaded, Source};

/// The file at `path` from the workspace's root, named as the command line there names it.
fn loaded(path: &str) -> Loaded {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let text = std::fs::read_to_string(format!("{root}/{path}")).expect("readable");
    let source = Source {
        path,
        text: Some(&text),
        ..Source::default()
    };
    load(&source).unwrap_or_else(|e| panic!("{path}: {e:?}"))
}

fn golden(name: &str) -> String {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    std::fs::read_to_string(format!("{root}/dynamics-cli/tests/golden/{name}")).expect("golden")
}

/// What `dynamics emit --lang c` printed before it called this (its golden files, written
/// by the command line's own assembly of the header): a description file's and a URDF's.
#[test]
fn the_header_is_the_command_lines() {
    let families = FamilySet::default();
    let puma = loaded("robots/puma560.toml");
    let header = puma.c_header(families, None, None).expect("a header");
    assert!(
        header.text == golden("puma560.h"),
        "PUMA 560's header changed"
    );
    assert_eq!((header.robot.as_str(), header.dof), ("puma560", 6));
    assert!(header.fields.is_empty());
    let arm = loaded("dynamics-runtime/tests/ui/urdf/arm.urdf");
    let header = arm.c_header(families, None, None).expect("a header");
    assert!(
        header.text == golden("arm_urdf.h"),
        "the URDF's header changed"
    );
}

/// A URDF's chain, the inertia check and a tool are in the command too: without them it
/// would write another robot's header (or none).
#[test]
fn the_command_keeps_the_options_that_chose_the_robot() {
    let path = "robots/urdf/trees/allegro_right_hand.urdf";
    let tips = ["link_3.0_tip", "link_15.0_tip"];
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let text = std::fs::read_to_string(format!("{root}/{path}")).expect("readable");
    let source = Source {
        path,
        text: Some(&text),
        chain: dynamics_codegen::front::Chain {
            tips: &tips,
            ..Default::default()
        },
        check_inertia: false,
    };
    let hand = load(&source).expect("the hand, unchecked");
    let header = hand
        .c_header(FamilySet::default(), None, None)
        .expect("a header");
    let command = format!(
        "dynamics emit --lang c {path} --tips link_3.0_tip,link_15.0_tip --no-check-inertia`"
    );
    assert!(header.text.contains(&command), "{}", &header.text[..300]);
    let puma = loaded("robots/puma560.toml").with_tool([0.0, 0.0, 0.1, 0.0, 0.5, -1.0]);
    let header = puma
        .expect("a tool")
        .c_header(FamilySet::default(), None, None);
    let command = "dynamics emit --lang c robots/puma560.toml --tool 0,0,0.1,0,0.5,-1`";
    assert!(header.expect("a header").text.contains(command));
}

#[test]
fn the_functions_signatures_and_the_command_that_writes_it_again() {
    let puma = loaded("robots/puma560.toml");
    let families = FamilySet::default().with(Family::Derivatives);
    let header = puma
        .c_header(families, None, Some("arm"))
        .expect("a header");
    let f = header
        .functions
        .iter()
        .find(|f| f.name == "arm_inverse_dynamics_derivatives")
        .expect("the derivatives, with the prefix");
    assert_eq!(f.outputs[0].dims, [2, 6, 6]);
    assert!(header.text.contains(&format!(" {}(", f.name)));
    let command = "dynamics emit --lang c robots/puma560.toml --with derivatives --prefix arm`";
    assert!(header.text.contains(command), "{}", &header.text[..300]);
    let refused = puma
        .c_header(families, None, Some("2arm"))
        .expect_err("not a C name");
    assert_eq!((refused.file, refused.line), (None, None), "the caller's");
    assert!(
        refused.message.starts_with("prefix: "),
        "{}",
        refused.message
    );
}

/// The simplified models a file's `[simplify]` asks for; a mistake in the table is placed
/// at its key.
#[test]
fn the_files_simplified_models_and_its_mistakes_in_place() {
    let two_link = loaded("tests/data/simplify/two_link.toml");
    let asked = two_link.simplification(&[]).expect("resolves");
    let header = two_link
        .c_header(FamilySet::default(), asked.as_ref(), None)
        .expect("a header");
    assert!(header
        .functions
        .iter()
        .any(|f| f.name == "two_link_inverse_dynamics_simplified"));
    let text = "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\n\
                a = 1\nmass = 2\n\n[simplify]\ntolerance = 1\nqd_max = -3\n";
    let source = Source {
        path: "arm.toml",
        text: Some(text),
        ..Source::default()
    };
    let arm = load(&source).expect("loads");
    let problems = arm.simplification(&[]).expect_err("a negative speed");
    let d = Diagnostic::from(&problems[0]);
    let place = (d.file.as_deref(), d.line, d.column);
    assert_eq!(place, (Some("arm.toml"), Some(11), Some(10)), "{d}");
    assert!(d.message.starts_with("simplify: "), "{d}");
    assert_eq!(d.to_string(), problems[0].to_string());
    let overridden = arm.simplification(&[("qd_max", vec![-1.0])]);
    let d = Diagnostic::from(&overridden.expect_err("the caller's")[0]);
    assert_eq!((d.file, d.line), (None, None));
}

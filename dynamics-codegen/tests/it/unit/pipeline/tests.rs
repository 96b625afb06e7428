use dynamics_codegen::method::{Family, FamilySet, Method};
use dynamics_codegen::pipeline::{load, Diagnostic, Source};

fn robots(file: &str) -> String {
    format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn a_file_loads_and_gives_its_equations() {
    let path = robots("puma560.toml");
    let loaded = load(&Source::file(&path)).expect("loads");
    assert_eq!(loaded.robot.dof(), 6);
    let families = FamilySet::default().with(Family::Derivatives);
    let eq = loaded.equations(families, None).expect("traces");
    assert!(eq.families.has(Method::InverseDynamicsDerivatives));
    assert!(!eq.families.contains(Family::Simplified));
}

/// A value the checks refuse (an inertia no rigid body has: 1 + 1 < 3) is placed at its
/// line and column; an unreadable file names the file.
#[test]
fn errors_are_data_with_their_places() {
    let text = "name = \"arm\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\n\
                a = 1\nmass = 2\ninertia = [1, 1, 3, 0, 0, 0]\n";
    let source = Source {
        path: "arm.toml",
        text: Some(text),
        ..Source::default()
    };
    let errors = load(&source).err().expect("refused");
    let Diagnostic {
        file, line, column, ..
    } = &errors[0];
    assert_eq!(
        (file.as_deref(), *line, *column),
        (Some("arm.toml"), Some(8), Some(11))
    );
    assert!(
        errors[0].to_string().starts_with("arm.toml:8:11: "),
        "{}",
        errors[0]
    );
    let missing = load(&Source::file("no/such/robot.toml"))
        .err()
        .expect("refused");
    assert_eq!(missing[0].file.as_deref(), Some("no/such/robot.toml"));
    assert_eq!(missing[0].line, None);
    assert!(missing[0].to_string().starts_with("no/such/robot.toml: "));
}

#[test]
fn a_tool_only_where_the_file_has_none() {
    let path = robots("puma560.toml");
    let with = load(&Source::file(&path)).expect("loads");
    let with = with
        .with_tool([0.0, 0.0, 0.1, 0.0, 0.0, 0.0])
        .expect("no tool yet");
    assert!(with.robot.tool.is_some());
    let again = with.with_tool([0.0; 6]).err().expect("declared");
    assert!(again.contains("declares a `tool` already"), "{again}");
    let urdf = robots("urdf/ur5.urdf");
    let ur5 = load(&Source::file(&urdf)).expect("loads");
    let refused = ur5.with_tool([0.0; 6]).err().expect("a URDF's tip");
    assert!(refused.contains("is its tip link"), "{refused}");
}

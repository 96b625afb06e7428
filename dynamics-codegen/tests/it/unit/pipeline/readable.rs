use dynamics_codegen::inspect::Format;
use dynamics_codegen::pipeline::Readable;
use dynamics_codegen::pipeline::{load, Source};
use dynamics_codegen::trace::base_parameters::JointColumns;

const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/..");

fn golden(name: &str) -> String {
    std::fs::read_to_string(format!("{ROOT}/dynamics-cli/tests/golden/{name}")).expect("golden")
}

/// What `dynamics inspect` printed before it called this (its golden files).
#[test]
fn the_equations_as_the_command_line_printed_them() {
    let path = format!("{ROOT}/robots/puma560.toml");
    let puma = load(&Source::file(&path)).expect("loads");
    let text = puma.readable(Readable::Motion, Format::Text).expect("text");
    assert!(text == golden("puma560.txt"), "{text}");
    let latex = puma
        .readable(Readable::Motion, Format::Latex)
        .expect("LaTeX");
    assert!(latex == golden("puma560.tex"), "{latex}");
    let path = format!("{ROOT}/robots/niku_example_6_4.toml");
    let arm = load(&Source::file(&path)).expect("loads");
    let kinematics = arm.readable(Readable::Kinematics, Format::Text);
    assert!(kinematics.expect("text") == golden("niku_example_6_4.kinematics.txt"));
}

#[test]
fn base_parameters_need_numbers_and_say_so() {
    let path = format!("{ROOT}/robots/puma560.toml");
    let puma = load(&Source::file(&path)).expect("loads");
    let columns = [JointColumns::default(); 6];
    let base = puma.readable(Readable::BaseParameters(&columns), Format::Text);
    assert!(base.expect("numbers").contains("puma560"));
    let path = format!("{ROOT}/robots/articulated_3r.toml");
    let arm = load(&Source::file(&path)).expect("loads");
    let refused = arm
        .readable(Readable::BaseParameters(&columns[..3]), Format::Text)
        .expect_err("its lengths are parameters");
    assert_eq!(
        (refused.file.as_deref(), refused.line),
        (Some(&*path), None)
    );
    assert!(refused.message.contains("lengths and angles as numbers"));
    let help = refused.help.as_deref().expect("a hint");
    let printed = refused.to_string();
    assert!(
        printed.ends_with(&format!("struct fields\nhelp: {help}")),
        "{printed}"
    );
}

use dynamics_codegen::method::{Family, FamilySet};
use dynamics_codegen::pipeline::families;

#[test]
fn families_by_name_and_the_names_refused() {
    let set = families(&["derivatives", "regressor"]).expect("opt-in");
    let expected = FamilySet::default()
        .with(Family::Derivatives)
        .with(Family::Regressor);
    assert_eq!(set, expected);
    assert_eq!(families::<&str>(&[]), Ok(FamilySet::default()));
    let unknown = families(&["derivatives", "everything"]).expect_err("no such family");
    assert_eq!(
        (unknown.file.as_deref(), unknown.line),
        (None, None),
        "the caller's"
    );
    assert_eq!(
        unknown.message,
        "`everything` is not an opt-in family of methods"
    );
    let help = unknown.help.expect("the names");
    assert!(help.contains("derivatives") && help.contains("base_parameters"));
    assert!(!help.contains("simplif"), "{help}");
    let simplified = families(&["simplify"]).expect_err("needs an envelope");
    assert!(simplified.help.expect("where").contains("[simplify]"));
}

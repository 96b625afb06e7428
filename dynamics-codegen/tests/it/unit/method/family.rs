use dynamics_codegen::method::{Family, FamilySet};

#[test]
fn a_robot_has_every_family_but_those_it_must_ask_for() {
    let default = FamilySet::default();
    for &f in Family::ALL {
        assert_eq!(default.contains(f), !f.is_opt_in(), "{f:?}");
        assert!(default.with(f).contains(f));
        assert_eq!(Family::from_name(f.name()), Some(f));
    }
    assert_eq!(
        Family::opt_in_names(),
        [
            "derivatives",
            "regressor",
            "simplify",
            "base_parameters",
            "tip_kinematics"
        ]
    );
    assert_eq!(default.opt_in().count(), 0);
    let asked = default.with(Family::Derivatives);
    assert_eq!(asked.opt_in().collect::<Vec<_>>(), [Family::Derivatives]);
}

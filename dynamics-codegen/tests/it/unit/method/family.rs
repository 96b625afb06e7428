use dynamics_codegen::method::{Family, FamilySet};

#[test]
fn a_robot_has_every_family_but_those_it_must_ask_for() {
    let (default, floating) = (FamilySet::default(), FamilySet::floating());
    for &f in Family::ALL {
        let always = !f.is_opt_in();
        assert_eq!(default.contains(f), always && !f.is_floating(), "{f:?}");
        assert_eq!(floating.contains(f), always && f.is_floating(), "{f:?}");
        assert!(default.with(f).contains(f));
        if !f.is_floating() {
            assert_eq!(Family::from_name(f.name()), Some(f));
        }
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
    let floating: Vec<_> = Family::ALL.iter().filter(|f| f.is_floating()).collect();
    assert_eq!(
        floating,
        [
            &Family::Floating,
            &Family::FloatingForward,
            &Family::FloatingDerivatives,
            &Family::FloatingRegressor,
            &Family::FloatingBaseParameters
        ]
    );
    // A floating base's opt-in family answers a fixed base's name, which the attribute and the
    // command line read as the fixed base's.
    assert_eq!(
        Family::Derivatives.on_floating_base(),
        Some(Family::FloatingDerivatives)
    );
    assert_eq!(
        Family::Regressor.on_floating_base(),
        Some(Family::FloatingRegressor)
    );
    assert_eq!(
        Family::BaseParameters.on_floating_base(),
        Some(Family::FloatingBaseParameters)
    );
    assert_eq!(Family::Tips.on_floating_base(), None);
    assert_eq!(Family::from_name("derivatives"), Some(Family::Derivatives));
    let asked = default.with(Family::Derivatives);
    assert_eq!(asked.opt_in().collect::<Vec<_>>(), [Family::Derivatives]);
}

use dynamics_codegen::method::{Argument, Family, Method, Returns};

#[test]
fn elements_are_described_in_the_books_terms() {
    let table = [
        (Method::MassMatrix, 0, 1, "D12 = D21 (6.43)"),
        (Method::MassMatrix, 2, 2, "D33 (6.43) + actuator inertia"),
        (
            Method::CoriolisMatrix,
            1,
            0,
            "C21 = sum of D21k qd_k (6.44)",
        ),
        (
            Method::CoriolisTorques,
            3,
            0,
            "centripetal and Coriolis torque 4",
        ),
        (
            Method::GravityTorques,
            2,
            0,
            "D3 (6.45), gravity and spring",
        ),
        (
            Method::BiasTorques,
            0,
            0,
            "centripetal, Coriolis and gravity torque 1",
        ),
        (Method::InverseDynamics, 2, 0, "T3 (6.46)"),
        (Method::FrictionTorques, 1, 0, "friction torque 2"),
        (Method::PotentialEnergy, 0, 0, "potential energy"),
    ];
    for (method, i, j, text) in table {
        assert_eq!(method.describe(i, j), text);
    }
}

#[test]
fn a_floating_base_has_rows_of_its_own_named_as_its_trait_names_them() {
    let floating: Vec<Method> = Method::ALL
        .iter()
        .copied()
        .filter(|m| m.family().is_floating())
        .collect();
    let traits = [
        "FloatingDynamics",
        "FloatingDynamicsDerivatives",
        "FloatingDynamicsRegressor",
        "FloatingDynamicsBaseParameters",
    ];
    assert!(floating
        .iter()
        .all(|m| traits.contains(&m.family().trait_name())));
    assert_eq!(
        Method::from_name_on("inverse_dynamics_derivatives", true),
        Some(Method::FloatingInverseDynamicsDerivatives)
    );
    assert_eq!(
        Method::FloatingForwardDynamicsDerivatives.argument_names(),
        ["q", "v", "tau"]
    );
    assert_eq!(
        Method::FloatingForwardDynamics.argument_names(),
        ["q", "v", "tau"]
    );
    let tau = Method::FloatingInverseDynamics;
    assert_eq!(tau.argument_names(), ["q", "v", "a"]);
    assert_eq!(tau.arguments(), [Argument::Q, Argument::Qd, Argument::Qdd]);
    assert_eq!(Method::InverseDynamics.argument_names(), ["q", "qd", "qdd"]);
    assert_eq!(
        Method::from_name_on("inverse_dynamics", true),
        Some(Method::FloatingInverseDynamics)
    );
    assert_eq!(
        Method::from_name("inverse_dynamics"),
        Some(Method::InverseDynamics)
    );
    assert!(!Family::Dynamics.is_floating());
}

#[test]
fn every_method_is_complete() {
    for &m in Method::ALL {
        let floating = m.family().is_floating();
        assert_eq!(Method::from_name_on(m.name(), floating), Some(m));
        assert!(!m.doc().is_empty() && !m.summary().is_empty(), "{m:?}");
        // Every method reads q but friction's, the joints' regressor and the parameters.
        let reads_q = m.arguments().first() == Some(&Argument::Q);
        let without_q = [
            Method::FrictionTorques,
            Method::JointRegressor,
            Method::JointParameters,
            Method::StandardParameters,
            Method::BaseParameters,
            Method::BaseFromStandard,
            Method::BaseFromJoints,
            Method::FloatingStandardParameters,
            Method::FloatingBaseParameters,
            Method::FloatingBaseFromStandard,
        ];
        assert_eq!(reads_q, !without_q.contains(&m), "{m:?}");
        let template = [m.element_template(false), m.element_template(true)];
        let cites = template.iter().any(|t| t.contains("{equation}"));
        assert!(!cites || m.equation().is_some(), "{m:?} cites no equation");
        let indexed = |key| template.iter().all(|t| t.contains(key));
        assert_eq!(indexed("{i}"), m.returns() != Returns::Scalar, "{m:?}");
    }
}

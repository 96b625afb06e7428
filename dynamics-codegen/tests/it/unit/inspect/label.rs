use dynamics_codegen::algo::JointKind;
use dynamics_codegen::inspect::label::{Label, Quantity};
use dynamics_codegen::inspect::print::{Format, Printer};

#[test]
fn labels_print_themselves() {
    let kinds = [JointKind::Revolute; 2];
    let text = Printer {
        format: Format::Text,
        kinds: &kinds,
        factors_first: false,
        floating: false,
    };
    let latex = Printer {
        format: Format::Latex,
        kinds: &kinds,
        factors_first: false,
        floating: false,
    };
    let diagonal = Label::new(Quantity::Inertia, &[1, 1]).with_actuator_inertia();
    assert_eq!(diagonal.render(&text), "D22 + I2(act)");
    assert_eq!(diagonal.render(&latex), "D_{22} + I_{2}(\\mathrm{act})");
    let christoffel = Label::new(Quantity::Christoffel, &[0, 1, 0]);
    assert_eq!(christoffel.render(&text), "D121");
    assert_eq!(Label::new(Quantity::Torque, &[0]).render(&text), "T1");
    assert_eq!(Label::new(Quantity::HandPose, &[2, 1]).render(&text), "oz");
    assert_eq!(
        Label::new(Quantity::HandPose, &[0, 3]).render(&latex),
        "p_x"
    );
    let hand = Label::new(Quantity::JacobianInHand, &[5, 1]);
    assert_eq!(hand.render(&text), "ᴴJ62");
    assert_eq!(hand.render(&latex), "{}^{H}J_{62}");
    let ten = [JointKind::Revolute; 10];
    let wide = Printer {
        format: Format::Text,
        kinds: &ten,
        factors_first: false,
        floating: false,
    };
    assert_eq!(
        Label::new(Quantity::Coriolis, &[0, 9]).render(&wide),
        "C1,10"
    );
}

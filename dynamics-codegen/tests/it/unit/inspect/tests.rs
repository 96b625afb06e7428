//! Folding, arranging and printing of polynomials typed in [`Poly::parse`] syntax.

use dynamics_codegen::algo::JointKind;
use dynamics_codegen::inspect::arrange::{arrange, arrange_factored, without_rounding_noise};
use dynamics_codegen::inspect::print::{Format, Printer};
use dynamics_codegen::poly::{fold_trig, Poly};
use dynamics_codegen::symbolic::Number;

/// The readable text of a polynomial written in `Poly::parse` syntax.
fn readable(text: &str, format: Format) -> String {
    print(text, format, false)
}

/// As the kinematics print: common sines and cosines taken out, written before their group.
fn factored(text: &str) -> String {
    print(text, Format::Text, true)
}

fn print(text: &str, format: Format, kinematics: bool) -> String {
    let mut terms = Poly::parse(text).unwrap().into_terms();
    fold_trig(&mut terms, &mut |_| Some(())).unwrap();
    let kinds = [
        JointKind::Revolute,
        JointKind::Prismatic,
        JointKind::Revolute,
    ];
    let p = Printer {
        format,
        kinds: &kinds,
        factors_first: kinematics,
        floating: false,
    };
    let terms = terms.into_iter().collect();
    p.sum(&if kinematics {
        arrange_factored(terms)
    } else {
        arrange(terms)
    })
}

macro_rules! reads {
    ($($a:literal => $b:literal),* $(,)?) => {$(
        assert_eq!(readable($a, Format::Text), $b, "{}", $a);
    )*};
}

#[test]
fn sums_of_angles_fold() {
    reads! {
        "C12" => "C12",
        "S12" => "S12",
        "C13" => "C13",
        "2*S12 - C1*C2" => "2 S12 - C1 C2",
        "a*C1*C2 - a*S1*S2 + b*S1*S2" => "b S1 S2 + a C12",
        "3*C1*C2 - 2*S1*S2" => "C1 C2 + 2 C12",
        "m*C12*C3 - m*S12*S3" => "m C123",
    }
}

#[test]
fn grouping_and_common_factors() {
    reads! {
        // accelerations first, then velocities, then gravity with its common factor out
        "m*g*l*C1/2 + M*g*l*C1 + qdd1*a*C3 + qdd1*b + qd3^2*c*S3" =>
            "(b + a C3) θ1'' + c S3 θ3'² + (M + 1/2 m) g l C1",
        "-a*qd1*qd3 - b*C3*qd1*qd3" => "-(a + b C3) θ1' θ3'",
        "0" => "0",
        "-1/2*m2*l1*l2*S3*qd1^2" => "-1/2 m2 l1 l2 S3 θ1'²",
        "k*q2*qd2" => "k d2 d2'",
        // position, velocity and acceleration of a prismatic joint stay apart
        "m*q2*qdd2 + qd1*qd2" => "m d2 d2'' + θ1' d2'",
        // a prismatic position stays inside its sine's or cosine's group (Niku 6.14)
        "m1*g*l1*C1/2 + m2*g*q2*C1" => "(1/2 m1 l1 + m2 d2) g C1",
        "0.4318*17.4*C1 + 1/3" => "1/3 + 7.51332 C1",
        "x/7" => "0.142857 x",
        "0.0000584640*x" => "5.8464e-5 x",
    }
}

#[test]
fn latex() {
    assert_eq!(
        readable("-1/2*m2*l1*l2*S3*qd1^2 + I1act*qdd1 + payload*C12", Format::Latex),
        "I_{1act} \\ddot{\\theta}_{1} - \\frac{1}{2} m_{2} l_{1} l_{2} S_{3} \\dot{\\theta}_{1}^{2} + \\mathit{payload} C_{12}"
    );
}

/// The hand pose as chapter 3 writes it: the sines and cosines shared by most terms taken
/// out (the lowest joint's where several tie), again inside, positive terms first.
#[test]
fn kinematics_take_out_common_sines_and_cosines() {
    for (polynomial, printed) in [
        ("a*C1*C2 + b*C1*C3", "C1(a C2 + b C3)"),
        ("a*C1*C2 + b*C1*C3 + d*S1", "C1(a C2 + b C3) + d S1"),
        ("-a*S1*C2 - b*S1*C3", "-S1(a C2 + b C3)"),
        // C1 and S4 both in two terms: C1 first; inside, the positive term first
        ("C1*C2*C4 - C1*S3*S4 - S1*S4", "C1(C2 C4 - S3 S4) - S1 S4"),
        // nothing shared: as the dynamics print
        ("a*S1 + b*C2", "a S1 + b C2"),
        // a factor before a group of sines and cosines only: parameters alone go first
        ("a*C1 + b*C1", "(a + b) C1"),
        ("a*C1*C2 + a*C1*S2", "C1(a S2 + a C2)"),
        ("2*C1*C2*C3 + 2*C1*S2*S3", "C1(2 S2 S3 + 2 C2 C3)"),
    ] {
        assert_eq!(factored(polynomial), printed, "{polynomial}");
    }
}

/// Float constants that cancel exactly leave 2⁻⁶⁴-sized coefficients (Solo 12's
/// `5.42101e-20 S3 C1 C2` beside `0.00051738 S2,3 C1`): not printed. Small terms of the model
/// stay, and so does every exact coefficient.
#[test]
fn rounding_noise_is_not_printed() {
    let coefficients = [
        ("S2*S3*C1", Number::Float(0.00051738)),
        ("S3*C1*C2", Number::Float(5.42101e-20)),
        ("C1", Number::Float(3.29799e-7)),
        ("S1", Number::Rational(1, 1_000_000_000_000_000)),
    ];
    let terms = coefficients
        .iter()
        .map(|(monomial, coef)| {
            let mut terms = Poly::parse(monomial).unwrap().into_terms();
            let (monomial, _) = terms.pop_first().unwrap();
            (monomial, *coef)
        })
        .collect();
    let kept: Vec<Number> = without_rounding_noise(terms)
        .into_iter()
        .map(|(_, coef)| coef)
        .collect();
    assert_eq!(kept.len(), 3, "{kept:?}");
    assert!(!kept.contains(&Number::Float(5.42101e-20)));
}

//! The book's printed closed forms, term by term: the robot is parsed from its attributes, its
//! equations derived, and each output's exact canonical polynomial compared with the printed
//! expression (Niku ch. 6, corrected per `docs/errata.md`).

use dynamics_codegen::poly::Poly;
use dynamics_codegen::symbolic::NodeId;
use dynamics_codegen::{derive, front, Equations};

fn equations(source: &str) -> Equations {
    let input = front::parse_str(source).unwrap_or_else(|e| panic!("{e}"));
    derive(&input.robot)
}

fn assert_printed(eq: &Equations, id: NodeId, printed: &str, what: &str) {
    let got = Poly::from_graph(&eq.graph, id, &eq.fields, 10_000).expect("polynomial");
    let want = Poly::parse(printed).expect("printed form");
    let diff = got.sub(&want);
    assert!(
        diff.is_zero(),
        "{what}:\n  derived {got}\n  printed {want}\n  derived − printed = {diff}"
    );
}

/// Example 6.8: the 2R arm of Example 6.4 with equal links (a1 = a2 = l), rods whose centre of
/// mass is at −l/2 on x_i, gravity gᵀ = [0, −g, 0, 0], and actuator inertias.
const EXAMPLE_6_8: &str = "
    #[dynamics(
        gravity = [0, -g, 0],
        dh = [
            //  θ   d   a   α
            [   q,  0,  l,  0 ],
            [   q,  0,  l,  0 ],
        ],
        link(mass = m1, com = [-l / 2, 0, 0], inertia = [0, m1 * l^2 / 12, m1 * l^2 / 12, 0, 0, 0], actuator_inertia = I1act),
        link(mass = m2, com = [-l / 2, 0, 0], inertia = [0, m2 * l^2 / 12, m2 * l^2 / 12, 0, 0, 0], actuator_inertia = I2act),
    )]
    struct Example68 { l: f64, m1: f64, m2: f64, g: f64, I1act: f64, I2act: f64 }
";

#[test]
fn example_6_8_effective_and_coupling_inertia() {
    let eq = equations(EXAMPLE_6_8);
    // D_ij of the book; M adds the actuator inertia on the diagonal (eq. 6.39).
    let d11 = "1/3*m1*l^2 + 4/3*m2*l^2 + m2*l^2*C2";
    let d12 = "1/3*m2*l^2 + 1/2*m2*l^2*C2";
    let d22 = "1/3*m2*l^2";
    assert_printed(
        &eq,
        eq.mass[0][0],
        &format!("{d11} + I1act"),
        "D11 + I1(act)",
    );
    assert_printed(&eq, eq.mass[0][1], d12, "D12");
    assert_printed(&eq, eq.mass[1][0], d12, "D21");
    assert_printed(
        &eq,
        eq.mass[1][1],
        &format!("{d22} + I2act"),
        "D22 + I2(act)",
    );
}

#[test]
fn example_6_8_centripetal_and_coriolis_coefficients() {
    let eq = equations(EXAMPLE_6_8);
    let printed = [
        ((0, 0, 0), "0"),
        ((0, 0, 1), "-1/2*m2*l^2*S2"),
        ((0, 1, 0), "-1/2*m2*l^2*S2"),
        ((0, 1, 1), "-1/2*m2*l^2*S2"),
        ((1, 0, 0), "1/2*m2*l^2*S2"),
        ((1, 0, 1), "0"),
        ((1, 1, 0), "0"),
        ((1, 1, 1), "0"),
    ];
    for ((i, j, k), text) in printed {
        let what = format!("D{}{}{}", i + 1, j + 1, k + 1);
        assert_printed(&eq, eq.christoffel[i][j][k], text, &what);
    }
    // C_ij = Σ_k D_ijk q̇_k
    assert_printed(&eq, eq.coriolis[0][0], "-1/2*m2*l^2*S2*qd2", "C11");
    assert_printed(
        &eq,
        eq.coriolis[0][1],
        "-1/2*m2*l^2*S2*qd1 - 1/2*m2*l^2*S2*qd2",
        "C12",
    );
    assert_printed(&eq, eq.coriolis[1][0], "1/2*m2*l^2*S2*qd1", "C21");
    assert_printed(&eq, eq.coriolis[1][1], "0", "C22");
}

#[test]
fn example_6_8_gravity() {
    let eq = equations(EXAMPLE_6_8);
    assert_printed(
        &eq,
        eq.gravity[0],
        "1/2*m1*g*l*C1 + 1/2*m2*g*l*C12 + m2*g*l*C1",
        "D1",
    );
    assert_printed(&eq, eq.gravity[1], "1/2*m2*g*l*C12", "D2");
}

/// The final T1 and T2 of Example 6.8; T2 ends in I2(act) θ̈2, not the printed I2(act) θ̈1
/// (`docs/errata.md` #1).
#[test]
fn example_6_8_equations_of_motion() {
    let eq = equations(EXAMPLE_6_8);
    let t1 = "(1/3*m1*l^2 + 4/3*m2*l^2 + m2*l^2*C2)*qdd1 + (1/3*m2*l^2 + 1/2*m2*l^2*C2)*qdd2
              - 1/2*m2*l^2*S2*qd2^2 - m2*l^2*S2*qd1*qd2
              + 1/2*m1*g*l*C1 + 1/2*m2*g*l*C12 + m2*g*l*C1 + I1act*qdd1";
    let t2 = "(1/3*m2*l^2 + 1/2*m2*l^2*C2)*qdd1 + 1/3*m2*l^2*qdd2 + 1/2*m2*l^2*S2*qd1^2
              + 1/2*m2*g*l*C12 + I2act*qdd2";
    assert_printed(&eq, eq.tau[0], t1, "T1");
    assert_printed(&eq, eq.tau[1], t2, "T2");
    // The misprinted T2 is not what the method gives.
    let misprinted = t2.replace("I2act*qdd2", "I2act*qdd1");
    let got = Poly::from_graph(&eq.graph, eq.tau[1], &eq.fields, 10_000).unwrap();
    assert!(!got.sub(&Poly::parse(&misprinted).unwrap()).is_zero());
}

/// Example 6.4, eqs. (6.11)-(6.12) and the energies (6.9), (6.10), with unequal links.
#[test]
fn example_6_4_two_link_arm() {
    let eq = equations(
        "
        #[dynamics(
            gravity = [0, -g, 0],
            dh = [[q, 0, l1, 0], [q, 0, l2, 0]],
            link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0, m1 * l1^2 / 12, m1 * l1^2 / 12, 0, 0, 0]),
            link(mass = m2, com = [-l2 / 2, 0, 0], inertia = [0, m2 * l2^2 / 12, m2 * l2^2 / 12, 0, 0, 0]),
        )]
        struct Example64 { l1: f64, l2: f64, m1: f64, m2: f64, g: f64 }
    ",
    );
    let t1 = "(1/3*m1*l1^2 + m2*l1^2 + 1/3*m2*l2^2 + m2*l1*l2*C2)*qdd1 + (1/3*m2*l2^2 + 1/2*m2*l1*l2*C2)*qdd2
              - m2*l1*l2*S2*qd1*qd2 - 1/2*m2*l1*l2*S2*qd2^2 + (1/2*m1 + m2)*g*l1*C1 + 1/2*m2*g*l2*C12";
    let t2 = "(1/3*m2*l2^2 + 1/2*m2*l1*l2*C2)*qdd1 + 1/3*m2*l2^2*qdd2 + 1/2*m2*l1*l2*S2*qd1^2 + 1/2*m2*g*l2*C12";
    assert_printed(&eq, eq.tau[0], t1, "T1 (6.11)");
    assert_printed(&eq, eq.tau[1], t2, "T2 (6.12)");
    let k = "qd1^2*(1/6*m1*l1^2 + 1/6*m2*l2^2 + 1/2*m2*l1^2 + 1/2*m2*l1*l2*C2)
             + qd2^2*(1/6*m2*l2^2) + qd1*qd2*(1/3*m2*l2^2 + 1/2*m2*l1*l2*C2)";
    assert_printed(&eq, eq.kinetic_energy, k, "K (6.9)");
    assert_printed(
        &eq,
        eq.potential_energy,
        "m1*g*l1/2*S1 + m2*g*(l1*S1 + l2/2*S12)",
        "P (6.10)",
    );
}

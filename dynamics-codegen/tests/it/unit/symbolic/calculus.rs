use dynamics_codegen::symbolic::Graph;
use dynamics_codegen::symbolic::Var;

#[test]
fn derivative_of_trigonometric_leaves() {
    let mut g = Graph::new();
    let s = g.var(Var::SinQ(0));
    let c = g.var(Var::CosQ(0));
    let sc = g.mul(s, c);
    let d = g.derivative(&[sc], 0)[0];
    let values = g.eval(|v| match v {
        Var::SinQ(_) => 0.3f64.sin(),
        Var::CosQ(_) => 0.3f64.cos(),
        _ => 0.0,
    });
    assert!((values[d.index()] - (2.0 * 0.3f64).cos()).abs() < 1e-15);
    let independent = g.derivative(&[sc], 1)[0];
    assert!(g.is_zero(independent));
}

/// `π₁·s + π₂·q̇ + s·c`: the dependents on the placeholders are π₁, π₂, their products and
/// the sums above them, not `s·c`; substituting within them builds the nodes the whole
/// substitution builds, for each choice of the placeholder set to one.
#[test]
fn substitution_within_the_dependents_builds_the_same_nodes() {
    let mut g = Graph::new();
    let (p1, p2) = (g.var(Var::Inertial(0)), g.var(Var::Inertial(1)));
    let (s, c, qd) = (g.var(Var::SinQ(0)), g.var(Var::CosQ(0)), g.var(Var::Qd(0)));
    let (a, b, sc) = (g.mul(p1, s), g.mul(p2, qd), g.mul(s, c));
    let ab = g.add(a, b);
    let tau = [g.add(ab, sc), sc];
    let dependents = g.dependents(&tau, |v| matches!(v, Var::Inertial(_)));
    assert_eq!(dependents, vec![p1, p2, a, b, ab, tau[0]]);
    for chosen in 0..2 {
        let (zero, one) = (
            g.num(dynamics_codegen::symbolic::Number::ZERO),
            g.num(dynamics_codegen::symbolic::Number::ONE),
        );
        let leaf = |v| match v {
            Var::Inertial(p) => Some(if p == chosen { one } else { zero }),
            _ => None,
        };
        let whole = g.substitute(&tau, leaf);
        let nodes = g.len();
        let within = g.substitute_within(&tau, &dependents, leaf);
        assert_eq!(within, whole);
        assert_eq!(g.len(), nodes, "nothing new the second time");
        let expected = if chosen == 0 {
            g.add(s, sc)
        } else {
            g.add(qd, sc)
        };
        assert_eq!(whole, vec![expected, sc]);
    }
}

use dynamics_codegen::symbolic::modular::Fp;
use dynamics_codegen::symbolic::{Graph, Number, Var};
use dynamics_codegen::trace::base_parameters::exact::relations;

#[test]
fn finds_the_identity_of_sine_and_cosine() {
    // Columns s², c², 1, 2s + 3, s: the third is the sum of the first two, the fifth a
    // combination of the fourth and the third.
    let mut g = Graph::new();
    let (s, c) = (g.var(Var::SinQ(0)), g.var(Var::CosQ(0)));
    let (one, two, three) = (
        g.num(Number::ONE),
        g.num(Number::int(2)),
        g.num(Number::int(3)),
    );
    let s2 = g.mul(s, s);
    let c2 = g.mul(c, c);
    let two_s = g.mul(two, s);
    let affine = g.add(two_s, three);
    let columns: Vec<Vec<_>> = [s2, c2, one, affine, s].iter().map(|&x| vec![x]).collect();
    let r = relations(&g, &columns, &[]).unwrap();
    assert_eq!(r.pivots, vec![0, 1, 3]);
    assert_eq!(r.coefficients[2], vec![Fp::ONE, Fp::ONE, Fp::ZERO]);
    let half = Fp::int(2).recip().unwrap();
    // s = (2s + 3)/2 − (3/2)(s² + c²)
    let minus_three_halves = Fp::int(-3) * half;
    assert_eq!(
        r.coefficients[4],
        vec![minus_three_halves, minus_three_halves, half]
    );
}

#[test]
fn refuses_a_field() {
    let mut g = Graph::new();
    let p = g.var(Var::Param(0));
    let s = g.var(Var::SinQ(0));
    let x = g.mul(p, s);
    assert!(relations(&g, &[vec![x]], &[]).is_none());
}

use dynamics_codegen::symbolic::Tape;
use dynamics_codegen::symbolic::{Graph, NodeId, Number, Var};

/// `x·y + sin(x)`, `1/(y − 2)`, `sign(−x)`, `tanh(y)`, `cos(3)`, and a node no output needs.
fn graph() -> (Graph, Vec<NodeId>, NodeId) {
    let mut g = Graph::new();
    let x = g.var(Var::Qd(0));
    let unused_leaf = g.var(Var::Q(5));
    let y = g.var(Var::Param(1));
    let unused = g.mul(unused_leaf, x);
    let xy = g.mul(x, y);
    let s = g.sin(x);
    let first = g.add(xy, s);
    let two = g.num(Number::int(2));
    let y2 = g.sub(y, two);
    let second = g.recip(y2).expect("not a constant zero");
    let minus_x = g.neg(x);
    let third = g.sign(minus_x);
    let fourth = g.tanh(y);
    let three = g.num(Number::int(3));
    let three_plus_x = g.add(three, x);
    let fifth = g.cos(three_plus_x);
    (g, vec![first, second, third, fourth, fifth, x], unused)
}

#[test]
fn the_tape_gives_the_values_of_the_graph() {
    let (g, outputs, _) = graph();
    let tape = Tape::new(&g, &outputs);
    assert_eq!(tape.leaves(), &[Var::Qd(0), Var::Param(1)]);
    let (x, y) = (0.7, -1.3);
    let mut work = Vec::new();
    let mut out = vec![0.0; outputs.len()];
    tape.eval(&[x, y], &mut work, &mut out);
    // By hand, not through the graph.
    let expected = [
        x * y + x.sin(),
        1.0 / (y - 2.0),
        -1.0,
        y.tanh(),
        (3.0 + x).cos(),
        x,
    ];
    assert_eq!(out, expected);
    // The same bits as the whole graph's evaluation.
    let all = g.eval(|v| match v {
        Var::Qd(0) => x,
        Var::Param(1) => y,
        _ => f64::NAN,
    });
    let from_graph: Vec<f64> = outputs.iter().map(|id| all[id.index()]).collect();
    assert_eq!(out, from_graph);
}

#[test]
fn only_what_the_outputs_need_is_evaluated() {
    let (g, outputs, unused) = graph();
    let tape = Tape::new(&g, &outputs);
    let mut with_unused = outputs.clone();
    with_unused.push(unused);
    let bigger = Tape::new(&g, &with_unused);
    assert_eq!(bigger.operations(), tape.operations() + 1);
    assert_eq!(bigger.leaves().len(), 3);
    // Sign of zero is zero, as `Real::sign` has it; a second call reuses the scratch.
    let mut work = Vec::new();
    let mut out = vec![f64::NAN; outputs.len()];
    tape.eval(&[1.0, 5.0], &mut work, &mut out);
    tape.eval(&[0.0, 5.0], &mut work, &mut out);
    assert_eq!(out[2], 0.0);
    assert_eq!(out[0], 0.0);
}

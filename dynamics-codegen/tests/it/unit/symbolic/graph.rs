use dynamics_codegen::symbolic::Number;
use dynamics_codegen::symbolic::{Graph, Node, NodeId, Var};

#[test]
fn building_twice_shares() {
    let mut g = Graph::new();
    let x = g.var(Var::Param(0));
    let y = g.var(Var::Param(1));
    let a = g.mul(x, y);
    let b = g.mul(y, x);
    assert_eq!(a, b);
    assert_eq!(g.stats().nodes, 3);
}

#[test]
fn local_rules() {
    let mut g = Graph::new();
    let x = g.var(Var::Param(0));
    let zero = g.num(Number::ZERO);
    let two = g.num(Number::int(2));
    let three = g.num(Number::int(3));
    assert_eq!(g.add(x, zero), x);
    assert_eq!(g.mul(x, zero), zero);
    let nx = g.neg(x);
    assert_eq!(g.neg(nx), x);
    assert_eq!(g.add(x, nx), zero);
    let two_x = g.mul(two, x);
    let three_x = g.mul(x, three);
    let five = g.num(Number::int(5));
    let five_x = g.mul(five, x);
    assert_eq!(g.add(two_x, three_x), five_x);
    let six = g.num(Number::int(6));
    let six_x = g.mul(six, x);
    assert_eq!(g.mul(two, three_x), six_x);
    assert!(matches!(g.node(six_x), Node::Mul(..)));
    // A common constant factor comes out: 3x + 3y = 3(x + y), 3x − 3y = 3(x − y).
    let y = g.var(Var::Param(1));
    let three_y = g.mul(three, y);
    let x_plus_y = g.add(x, y);
    let factored = g.mul(three, x_plus_y);
    assert_eq!(g.add(three_x, three_y), factored);
    let minus_three_y = g.neg(three_y);
    let ny = g.neg(y);
    let x_minus_y = g.add(x, ny);
    let factored = g.mul(three, x_minus_y);
    assert_eq!(g.add(three_x, minus_three_y), factored);
    // Different factors stay apart: 2x + 3y keeps its two products.
    let sum = g.add(two_x, three_y);
    assert!(matches!(g.node(sum), Node::Add(..)));
}

/// A term that cancels one of a sum's terms leaves the other.
#[test]
fn cancelling_one_level_down() {
    let mut g = Graph::new();
    let x = g.var(Var::Param(0));
    let y = g.var(Var::Param(1));
    let two = g.num(Number::int(2));
    let two_x = g.mul(two, x);
    type Build = Box<dyn Fn(&mut Graph) -> NodeId>;
    let cases: [(&str, Build, NodeId); 5] = [
        (
            "x + (y − x)",
            Box::new(move |g| {
                let d = g.sub(y, x);
                g.add(x, d)
            }),
            y,
        ),
        (
            "(y − x) + x",
            Box::new(move |g| {
                let d = g.sub(y, x);
                g.add(d, x)
            }),
            y,
        ),
        (
            "x − (x + y)",
            Box::new(move |g| {
                let s = g.add(x, y);
                g.sub(x, s)
            }),
            g.neg(y),
        ),
        (
            "2x + (y − 2x)",
            Box::new(move |g| {
                let d = g.sub(y, two_x);
                g.add(two_x, d)
            }),
            y,
        ),
        (
            "−x + (x + y)",
            Box::new(move |g| {
                let s = g.add(x, y);
                let nx = g.neg(x);
                g.add(nx, s)
            }),
            y,
        ),
    ];
    for (name, build, expected) in cases {
        assert_eq!(build(&mut g), expected, "{name}");
    }
    // Terms that do not cancel stay a sum: x + (y − 2x) is not simplified.
    let d = g.sub(y, two_x);
    let r = g.add(x, d);
    assert!(matches!(g.node(r), Node::Add(..)));
}

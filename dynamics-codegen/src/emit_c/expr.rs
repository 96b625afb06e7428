//! Expressions as C: a node written where it is read (once) or by its name, with `a + (−b)`
//! written `a - b`, constants as exact decimal literals, and parentheses only where C's
//! precedence needs them to keep the graph's order of evaluation.

use crate::emit::{Sums, Written};
use crate::symbolic::{Graph, Node, NodeId, Var, WRENCH};
use crate::trace::Equations;
use std::cell::Cell;

/// Writes one function's body: its expressions here, its statements in `body.rs`.
pub(super) struct Writer<'a> {
    pub(super) eq: &'a Equations,
    pub(super) precision: Precision,
    /// The name of the header's sign function (Coulomb friction) in this precision.
    pub(super) sign: String,
    /// How many times each needed node is read (an output counts once).
    pub(super) uses: Vec<u32>,
    /// Whether each node is read, directly or not, by an output.
    pub(super) needed: Vec<bool>,
    /// The local each bound node is read by.
    pub(super) names: Vec<Option<String>>,
    /// What a named output element is, for its comment.
    pub(super) comments: Vec<Option<String>>,
    pub(super) temporaries: usize,
    /// Each node's depth as written ([`Sums::depth`]), `u32::MAX` until asked for.
    pub(super) depth: Vec<Cell<u32>>,
}

/// The floating-point type of a C function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Precision {
    /// `double`: the functions named after the method.
    Double,
    /// `float`: the same functions with `_f32` appended.
    Single,
}

impl Precision {
    /// Both, in the order the header writes them.
    pub const ALL: [Precision; 2] = [Precision::Double, Precision::Single];

    /// The C type, `double` or `float`.
    #[must_use]
    pub fn c_type(self) -> &'static str {
        match self {
            Precision::Double => "double",
            Precision::Single => "float",
        }
    }

    /// What the function's name ends in: nothing, or `_f32`.
    #[must_use]
    pub fn suffix(self) -> &'static str {
        match self {
            Precision::Double => "",
            Precision::Single => "_f32",
        }
    }

    /// The `<math.h>` function `name` of this type: `tanh`, or `tanhf` (so that the `float`
    /// code never widens to `double`).
    pub(super) fn math(self, name: &str) -> String {
        match self {
            Precision::Double => name.to_owned(),
            Precision::Single => format!("{name}f"),
        }
    }

    /// The header's multiply-add `x·y + a`, `dynamics_fma` or `dynamics_fma_f32`: fused
    /// where the Rust runtime's `mul_add` is.
    pub(super) fn fma(self) -> String {
        format!("dynamics_fma{}", self.suffix())
    }

    /// The header's function `name` (`sin`, `cos`, `sincos`) of this type: `dynamics_sin`,
    /// `dynamics_sin_f32` (`<math.h>`'s, or the header's own where `DYNAMICS_OWN_SINCOS` is
    /// defined).
    pub(super) fn trig(self, name: &str) -> String {
        format!("dynamics_{name}{}", self.suffix())
    }

    /// `x` as a literal of this type. A `double` is printed as the Rust emission prints it
    /// (the shortest decimal that reads back as the same `f64`, with a `.0` where it has no
    /// point); a `float` as the `f32` nearest that `f64` (Rust's `T::from_f64`, so both
    /// languages compute with the same constant), shortest, with an `f`.
    #[must_use]
    pub fn literal(self, x: f64) -> String {
        // A literal cannot spell a non-finite value: `<math.h>` names them (of type `float`,
        // which converts exactly to `double`).
        if x.is_nan() {
            return "NAN".to_owned();
        }
        // The nearest f32, as `f32::from_f64` rounds: the conversion is the point (a finite
        // `f64` beyond `f32`'s range becomes its infinity, as in Rust).
        #[allow(clippy::cast_possible_truncation)]
        let rounded = match self {
            Precision::Double => x,
            Precision::Single => f64::from(x as f32),
        };
        if rounded.is_infinite() {
            return if x > 0.0 { "INFINITY" } else { "-INFINITY" }.to_owned();
        }
        let mut text = match self {
            Precision::Double => format!("{x}"),
            #[allow(clippy::cast_possible_truncation)]
            Precision::Single => format!("{}", x as f32),
        };
        if !text.contains('.') {
            text.push_str(".0");
        }
        if self == Precision::Single {
            text.push('f');
        }
        text
    }
}

/// Where an expression is written, which decides whether it needs parentheses.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Place {
    /// A statement's right-hand side, or a function's argument.
    Top,
    /// Left of `+` or `-`.
    AddLeft,
    /// Right of `+` or `-`.
    AddRight,
    /// Left of `*` or `/`.
    MulLeft,
    /// Right of `*` or `/`.
    MulRight,
    /// Under a unary minus.
    Unary,
}

impl Writer<'_> {
    /// The nodes an emitted node reads, with `a + (−b)` read as `a − b`, and the angle
    /// offset that the sine and cosine of a joint read.
    pub(super) fn operands(&self, id: NodeId) -> Vec<NodeId> {
        match self.eq.graph.node(id) {
            Node::Add(a, b) => {
                let (a, b) = self.as_sub(a, b).unwrap_or((a, b));
                vec![a, b]
            }
            Node::Var(Var::SinQ(i) | Var::CosQ(i)) => {
                self.eq.angle_offsets[usize::from(i)].into_iter().collect()
            }
            node => node.operands().collect(),
        }
    }

    /// The magnitude of a negative constant, which a sum subtracts.
    fn negative_constant(&self, id: NodeId) -> Option<f64> {
        match self.eq.graph.node(id) {
            Node::Const(c) if c.is_negative() => Some(-c.to_f64()),
            _ => None,
        }
    }

    /// The name a leaf is read by, as the Rust emission names it (`q2`, `qd2`, `s2`, `c2`,
    /// `p_m2`, `fx`, `tau2`), but a parameter whose name C would not take as it is: `p_{k}`.
    pub(super) fn var_name(&self, v: Var) -> String {
        match v {
            Var::Q(i) => format!("q{}", i + 1),
            Var::Qd(i) => format!("qd{}", i + 1),
            Var::Qdd(i) => format!("qdd{}", i + 1),
            Var::SinQ(i) => format!("s{}", i + 1),
            Var::CosQ(i) => format!("c{}", i + 1),
            Var::Param(k) => {
                let k = usize::from(k);
                crate::identifiers::c_parameter(k, &self.eq.fields[k])
            }
            Var::Wrench(k) => WRENCH[usize::from(k)].to_owned(),
            Var::Tau(i) => format!("tau{}", i + 1),
            // Placeholders of the regressor's and the base parameters' analyses, which no
            // emitted output reads.
            Var::Inertial(k) => format!("pi{}_{}", k / 10 + 1, k % 10 + 1),
            Var::Exact(k) => format!("constant{k}"),
        }
    }

    /// Node `id` at `place`: its name if it has one, else written out, in parentheses where
    /// the place needs them.
    pub(super) fn expr(&self, id: NodeId, place: Place) -> String {
        if let Some(name) = &self.names[id.index()] {
            return name.clone();
        }
        let p = self.precision;
        if self.is_sum(id) {
            let (text, call) = self.sum(id);
            let wrap = matches!(
                place,
                Place::AddRight | Place::MulLeft | Place::MulRight | Place::Unary
            );
            return if wrap && !call {
                format!("({text})")
            } else {
                text
            };
        }
        let (text, wrap) = match self.eq.graph.node(id) {
            Node::Var(v) => return self.var_name(v),
            Node::Add(..) => unreachable!("a sum is written by `sum`"),
            Node::Const(c) => {
                let value = p.literal(c.to_f64());
                let bare = matches!(place, Place::Top | Place::AddLeft | Place::MulLeft);
                return if c.is_negative() && !bare {
                    format!("({value})")
                } else {
                    value
                };
            }
            Node::Mul(a, b) => (
                format!(
                    "{} * {}",
                    self.expr(a, Place::MulLeft),
                    self.expr(b, Place::MulRight)
                ),
                matches!(place, Place::MulRight | Place::Unary),
            ),
            Node::Recip(a) => (
                format!("{} / {}", p.literal(1.0), self.expr(a, Place::MulRight)),
                matches!(place, Place::MulRight | Place::Unary),
            ),
            Node::Neg(a) => (
                format!("-{}", self.expr(a, Place::Unary)),
                matches!(place, Place::AddRight | Place::MulRight | Place::Unary),
            ),
            Node::Sin(a) => (self.call(&p.trig("sin"), a), false),
            Node::Cos(a) => (self.call(&p.trig("cos"), a), false),
            Node::Tanh(a) => (self.call(&p.math("tanh"), a), false),
            Node::Sign(a) => (self.call(&self.sign, a), false),
        };
        if wrap {
            format!("({text})")
        } else {
            text
        }
    }

    /// The sum `id` as [`Sums::plan`] writes it, `a + b`, `a - b` and `dynamics_fma(x, y,
    /// a)`, and whether it is a call (which needs no parentheses).
    fn sum(&self, id: NodeId) -> (String, bool) {
        match self.plan(id) {
            (root @ Written::MulAdd { .. }, false) => (self.written(root, Place::Top), true),
            (root, false) => (self.written(root, Place::Top), false),
            (root, true) => (format!("-{}", self.written(root, Place::Unary)), false),
        }
    }

    /// A planned partial sum at `place`; `a + (−0.7)` written `a - 0.7` (negation is exact,
    /// so the value is the same).
    fn written(&self, w: Written, place: Place) -> String {
        let (a, b, minus) = match w {
            Written::Term(t) => return self.expr(t, place),
            Written::MulAdd {
                x,
                y,
                negate_x,
                addend,
                negate_addend,
            } => {
                let x = if negate_x {
                    format!("-{}", self.expr(x, Place::Unary))
                } else {
                    self.expr(x, Place::Top)
                };
                let rest = if negate_addend {
                    format!("-{}", self.written(*addend, Place::Unary))
                } else {
                    self.written(*addend, Place::Top)
                };
                let y = self.expr(y, Place::Top);
                return format!("{}({x}, {y}, {rest})", self.precision.fma());
            }
            Written::Add(a, b) => (a, b, false),
            Written::Sub(a, b) => (a, b, true),
        };
        let a = self.written(*a, Place::AddLeft);
        let (b, minus) = match *b {
            Written::Term(t) => match self.negative_constant(t) {
                Some(m) => (self.precision.literal(m), !minus),
                None => (self.expr(t, Place::AddRight), minus),
            },
            b => (self.written(b, Place::AddRight), minus),
        };
        let text = format!("{a} {} {b}", if minus { '-' } else { '+' });
        let wrap = matches!(
            place,
            Place::AddRight | Place::MulLeft | Place::MulRight | Place::Unary
        );
        if wrap {
            format!("({text})")
        } else {
            text
        }
    }

    fn call(&self, function: &str, a: NodeId) -> String {
        format!("{function}({})", self.expr(a, Place::Top))
    }
}

impl Sums for Writer<'_> {
    fn graph(&self) -> &Graph {
        &self.eq.graph
    }

    fn in_place(&self, c: NodeId) -> bool {
        self.names[c.index()].is_none() && self.uses[c.index()] <= 1
    }

    fn depths(&self) -> &[Cell<u32>] {
        &self.depth
    }
}

#[cfg(test)]
mod tests {
    use super::Precision;

    #[test]
    fn literals_are_exact_and_typed() {
        let table = [
            (0.1, "0.1", "0.1f"),
            (2.0, "2.0", "2.0f"),
            (-0.5, "-0.5", "-0.5f"),
            (1e-5, "0.00001", "0.00001f"),
            // The f32 nearest the f64 nearest 0.4318, printed shortest.
            (0.4318, "0.4318", "0.4318f"),
            (1.0 / 3.0, "0.3333333333333333", "0.33333334f"),
            (f64::INFINITY, "INFINITY", "INFINITY"),
            // Finite in `double`, beyond `float`'s range: its infinity, as `f32::from_f64`.
            (
                -1e39,
                "-1000000000000000000000000000000000000000.0",
                "-INFINITY",
            ),
        ];
        for (x, double, single) in table {
            assert_eq!(Precision::Double.literal(x), double);
            assert_eq!(Precision::Single.literal(x), single);
        }
    }
}

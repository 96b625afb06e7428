//! Expressions as C: the plan's (`emit::plan`, which the Rust emission prints too) printed in
//! C, a node written where it is read (once) or by its name, constants as exact decimal
//! literals of the function's precision.

use crate::emit::plan::{self, Function, Operator, Place, Precedence, Printer};
use crate::emit::Sums;
use crate::symbolic::{Graph, NodeId, Number, Var};
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

impl Writer<'_> {
    /// The nodes an emitted node reads ([`plan::operands`]).
    pub(super) fn operands(&self, id: NodeId) -> plan::Operands {
        plan::operands(self.eq, id)
    }

    /// The name a leaf is read by, as the Rust emission names it ([`plan::leaf_name`]: `q2`,
    /// `s2`, `p_m2`, `fx`), but a parameter whose name C would not take as it is: `p_{k}`.
    pub(super) fn var_name(&self, v: Var) -> String {
        plan::leaf_name(v, |k| {
            crate::identifiers::c_parameter(k, &self.eq.fields[k])
        })
    }

    /// Node `id` at `place`: its name if it has one, else written out, in parentheses where
    /// the place needs them ([`plan::expr`]).
    pub(super) fn expr(&self, id: NodeId, place: Place) -> String {
        plan::expr(self, id, place)
    }
}

/// The C printer of the plan: `a + b`, `dynamics_fma(x, y, a)`, `dynamics_sin(a)`, `1.0 / a`,
/// constants as exact literals of the precision (`0.4318`, `0.4318f`), a negative one bound
/// as a prefix minus.
impl Printer for Writer<'_> {
    type Code = String;
    const MUL_ADD_FIRST: Place = Place::Top;

    fn bound(&self, id: NodeId) -> Option<String> {
        self.names[id.index()].clone()
    }

    fn variable(&self, v: Var) -> String {
        self.var_name(v)
    }

    fn constant(&self, c: Number) -> (String, Precedence) {
        let precedence = if c.is_negative() {
            Precedence::Prefix
        } else {
            Precedence::Atom
        };
        (self.precision.literal(c.to_f64()), precedence)
    }

    fn binary(&self, a: String, op: Operator, b: String) -> String {
        match op {
            Operator::Add => format!("{a} + {b}"),
            Operator::Sub => format!("{a} - {b}"),
            Operator::Mul => format!("{a} * {b}"),
            Operator::Div => format!("{a} / {b}"),
        }
    }

    fn negate(&self, a: String) -> String {
        format!("-{a}")
    }

    fn call(&self, f: Function, a: String) -> String {
        let p = self.precision;
        let function = match f {
            Function::Sin => p.trig("sin"),
            Function::Cos => p.trig("cos"),
            Function::Tanh => p.math("tanh"),
            Function::Sign => self.sign.clone(),
        };
        format!("{function}({a})")
    }

    fn mul_add(&self, x: String, y: String, a: String) -> String {
        format!("{}({x}, {y}, {a})", self.precision.fma())
    }

    fn parenthesized(&self, a: String) -> String {
        format!("({a})")
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

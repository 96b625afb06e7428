//! The plan of an expression, which the Rust (`emit`) and the C (`emit_c`) printers both write:
//! what a node is written as (a bound name, a leaf by its role, an operator on operands at
//! their places, a sum as `Sums::plan` adds it), each form's precedence, and one table of
//! where a form needs parentheses. A printer only spells: `x.mul_add(y, a)` or
//! `dynamics_fma(x, y, a)`, `T::sin(a)` or `dynamics_sin(a)`, `p_m1` or `p_0`. One plan, two
//! printers: the C writes the Rust's expressions, operation for operation.

use super::sums::{as_sub, Sums, Written};
use crate::symbolic::{Node, NodeId, Number, Var, WRENCH};
use crate::trace::Equations;

/// Where an expression is written, which decides whether it needs parentheses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum Place {
    /// A statement's right-hand side, an array element, a function's argument.
    Top,
    /// Left of `+` or `−`.
    AddLeft,
    /// Right of `+` or `−`.
    AddRight,
    /// Left of `*` or `/`.
    MulLeft,
    /// Right of `*` or `/`, under a unary minus, or before a method call's dot.
    MulRight,
}

/// How tightly a written form binds, loosest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum Precedence {
    /// `a + b`, `a − b`, and a negated sum.
    Sum,
    /// `a * b`, `1 / a`.
    Product,
    /// `-a`, and a negative literal.
    Prefix,
    /// A name, a literal, a call.
    Atom,
}

/// Whether a form of precedence `p` needs parentheses at `place`: a sum anywhere but first in
/// a sum, a product right of `*` or `/`, and a prefix minus as a right operand (`a + (-b)`,
/// `a * (-b)`) or under another.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn needs_parentheses(p: Precedence, place: Place) -> bool {
    match (p, place) {
        (Precedence::Atom, _) | (_, Place::Top | Place::AddLeft) => false,
        (Precedence::Sum, _) => true,
        (Precedence::Product, place) => place == Place::MulRight,
        (Precedence::Prefix, place) => place != Place::MulLeft,
    }
}

/// A binary operator.
#[derive(Clone, Copy, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum Operator {
    Add,
    Sub,
    Mul,
    Div,
}

/// A function of one argument that the graph calls.
#[derive(Clone, Copy, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub enum Function {
    Sin,
    Cos,
    Tanh,
    Sign,
}

/// What a language spells; the plan ([`expr`]) decides the rest.
pub(crate) trait Printer: Sums {
    /// Written code: tokens, or text.
    type Code;
    /// Where the first factor of a fused multiply-add stands: a method's receiver in Rust
    /// (which binds as tightly as a unary minus's operand), a function's argument in C.
    const MUL_ADD_FIRST: Place;

    /// The name node `id` is read by, if it is bound to one.
    fn bound(&self, id: NodeId) -> Option<Self::Code>;
    /// Input `v` (its name, [`leaf_name`]).
    fn variable(&self, v: Var) -> Self::Code;
    /// The constant `c`, and its precedence (a negative literal's is [`Precedence::Prefix`]).
    fn constant(&self, c: Number) -> (Self::Code, Precedence);
    fn binary(&self, a: Self::Code, op: Operator, b: Self::Code) -> Self::Code;
    fn negate(&self, a: Self::Code) -> Self::Code;
    fn call(&self, f: Function, a: Self::Code) -> Self::Code;
    /// `x·y + a` in one fused multiply-add.
    fn mul_add(&self, x: Self::Code, y: Self::Code, a: Self::Code) -> Self::Code;
    fn parenthesized(&self, a: Self::Code) -> Self::Code;
}

/// The name of input `v` in both languages, as the book numbers the joints (`q2`, `qd2`, `s2`
/// for sin q₂, `c2`, `tau2`, `fx`), a struct field `k` by `parameter(k)`.
pub(crate) fn leaf_name(v: Var, parameter: impl FnOnce(usize) -> String) -> String {
    match v {
        Var::Q(i) => format!("q{}", i + 1),
        Var::Qd(i) => format!("qd{}", i + 1),
        Var::Qdd(i) => format!("qdd{}", i + 1),
        Var::SinQ(i) => format!("s{}", i + 1),
        Var::CosQ(i) => format!("c{}", i + 1),
        Var::Param(k) => parameter(usize::from(k)),
        Var::Wrench(k) => WRENCH[usize::from(k)].to_owned(),
        // Tip t's (from 1): `fx1`, `mz2`.
        Var::TipWrench(k) => format!("{}{}", WRENCH[usize::from(k % 6)], k / 6 + 1),
        Var::Tau(i) => format!("tau{}", i + 1),
        // Placeholders of the regressor's and the base parameters' analyses, which no emitted
        // output reads.
        Var::Inertial(k) => format!("pi{}_{}", k / 10 + 1, k % 10 + 1),
        Var::Exact(k) => format!("constant{k}"),
    }
}

/// The nodes an emitted node reads, as both printers read them: `a + (−b)` reads `a` and `b`
/// (written `a − b`), and a joint's sine and cosine read its angle offset.
pub(crate) fn operands(eq: &Equations, id: NodeId) -> Operands {
    match eq.graph.node(id) {
        Node::Add(a, b) => {
            let (a, b) = as_sub(&eq.graph, a, b).unwrap_or((a, b));
            Operands::two(a, b)
        }
        // Spelled out rather than `Node::operands`: the emitters call this for every node read.
        Node::Mul(a, b) => Operands::two(a, b),
        Node::Neg(a)
        | Node::Recip(a)
        | Node::Sin(a)
        | Node::Cos(a)
        | Node::Sign(a)
        | Node::Tanh(a) => Operands::one(a),
        // A joint's leaf past the coordinates (a mimic joint's, read by no output) has none.
        Node::Var(Var::SinQ(i) | Var::CosQ(i)) => {
            match eq.angle_offsets.get(usize::from(i)).copied().flatten() {
                Some(offset) => Operands::one(offset),
                None => Operands::NONE,
            }
        }
        Node::Const(_) | Node::Var(_) => Operands::NONE,
    }
}

/// At most two operands, without an allocation: the emitters ask for them at every node of
/// every walk.
#[derive(Clone, Copy)]
pub(crate) struct Operands {
    ids: [NodeId; 2],
    len: usize,
}

impl Operands {
    const NONE: Operands = Operands {
        ids: [NodeId(0); 2],
        len: 0,
    };

    fn one(a: NodeId) -> Operands {
        Operands {
            ids: [a, a],
            len: 1,
        }
    }

    fn two(a: NodeId, b: NodeId) -> Operands {
        Operands {
            ids: [a, b],
            len: 2,
        }
    }

    /// The operands in order.
    pub(crate) fn iter(&self) -> std::slice::Iter<'_, NodeId> {
        self.ids[..self.len].iter()
    }
}

impl IntoIterator for Operands {
    type Item = NodeId;
    type IntoIter = std::iter::Take<std::array::IntoIter<NodeId, 2>>;

    fn into_iter(self) -> Self::IntoIter {
        self.ids.into_iter().take(self.len)
    }
}

/// Node `id` at `place`: its name if it has one, else written out, in parentheses where the
/// place needs them.
pub(crate) fn expr<P: Printer>(p: &P, id: NodeId, place: Place) -> P::Code {
    if let Some(name) = p.bound(id) {
        return name;
    }
    let (code, precedence) = written(p, id);
    if needs_parentheses(precedence, place) {
        p.parenthesized(code)
    } else {
        code
    }
}

/// Node `id` written out (not by its own name), and its precedence.
pub(crate) fn written<P: Printer>(p: &P, id: NodeId) -> (P::Code, Precedence) {
    if p.is_sum(id) {
        return sum(p, id);
    }
    let call = |f: Function, a: NodeId| (p.call(f, expr(p, a, Place::Top)), Precedence::Atom);
    match p.graph().node(id) {
        Node::Var(v) => (p.variable(v), Precedence::Atom),
        Node::Const(c) => p.constant(c),
        Node::Add(..) => unreachable!("a sum is written by `sum`"),
        Node::Mul(a, b) => {
            let (a, b) = (expr(p, a, Place::MulLeft), expr(p, b, Place::MulRight));
            (p.binary(a, Operator::Mul, b), Precedence::Product)
        }
        Node::Recip(a) => {
            let one = p.constant(Number::ONE).0;
            let a = expr(p, a, Place::MulRight);
            (p.binary(one, Operator::Div, a), Precedence::Product)
        }
        Node::Neg(a) => (p.negate(expr(p, a, Place::MulRight)), Precedence::Prefix),
        Node::Sin(a) => call(Function::Sin, a),
        Node::Cos(a) => call(Function::Cos, a),
        Node::Tanh(a) => call(Function::Tanh, a),
        Node::Sign(a) => call(Function::Sign, a),
    }
}

/// The sum `id` as [`Sums::plan`] adds it: a fused multiply-add is a call, which needs no
/// parentheses; a negated sum is written `-(…)` and binds as a sum.
fn sum<P: Printer>(p: &P, id: NodeId) -> (P::Code, Precedence) {
    match p.plan(id) {
        (root @ Written::MulAdd { .. }, false) => (partial(p, root, Place::Top), Precedence::Atom),
        (root, false) => (partial(p, root, Place::Top), Precedence::Sum),
        (root, true) => {
            let root = partial(p, root, Place::MulRight);
            (p.negate(root), Precedence::Sum)
        }
    }
}

/// A planned partial sum at `place`; `a + (−c)` of a literal `c` written `a − c` (negation is
/// exact: the same value).
fn partial<P: Printer>(p: &P, w: Written, place: Place) -> P::Code {
    let (a, b, minus) = match w {
        Written::Term(t) => return expr(p, t, place),
        Written::MulAdd {
            x,
            y,
            negate_x,
            addend,
            negate_addend,
        } => {
            let x = if negate_x {
                let x = p.negate(expr(p, x, Place::MulRight));
                if needs_parentheses(Precedence::Prefix, P::MUL_ADD_FIRST) {
                    p.parenthesized(x)
                } else {
                    x
                }
            } else {
                expr(p, x, P::MUL_ADD_FIRST)
            };
            let y = expr(p, y, Place::Top);
            let rest = if negate_addend {
                p.negate(partial(p, *addend, Place::MulRight))
            } else {
                partial(p, *addend, Place::Top)
            };
            return p.mul_add(x, y, rest);
        }
        Written::Add(a, b) => (a, b, false),
        Written::Sub(a, b) => (a, b, true),
    };
    let a = partial(p, *a, Place::AddLeft);
    let (b, minus) = match *b {
        Written::Term(t) => match negative_literal(p, t) {
            Some(c) => (p.constant(-c).0, !minus),
            None => (expr(p, t, Place::AddRight), minus),
        },
        b => (partial(p, b, Place::AddRight), minus),
    };
    let op = if minus { Operator::Sub } else { Operator::Add };
    let code = p.binary(a, op, b);
    if needs_parentheses(Precedence::Sum, place) {
        p.parenthesized(code)
    } else {
        code
    }
}

/// The value of `t` if it is a negative constant written as a literal (not bound to a name).
fn negative_literal(p: &impl Printer, t: NodeId) -> Option<Number> {
    match p.graph().node(t) {
        Node::Const(c) if c.is_negative() && p.bound(t).is_none() => Some(c),
        _ => None,
    }
}

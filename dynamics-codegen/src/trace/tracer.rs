//! The symbolic side of [`RobotScalars`]: a robot's values as nodes of the shared graph, the
//! joint variables as [`Var`] leaves, and `sin(q_i + θ)`, `cos(q_i + θ)` of a revolute joint
//! from the leaves `sin q_i`, `cos q_i` where θ is a quarter turn
//! (`sin(q + kπ/2)`, `cos(q + kπ/2)` are `±sin q`, `±cos q`).

use super::expr::Expr;
use crate::algo::RobotScalars;
use crate::model::{Robot, Value};
use crate::symbolic::modular::Fp;
use crate::symbolic::{Graph, NodeId, Number, Var};
use std::cell::RefCell;
use std::ops::Mul;

/// Builds a robot's values into `graph`.
pub(super) struct Tracer<'g> {
    graph: &'g RefCell<Graph>,
    fields: &'g [String],
    /// Per revolute joint whose θ offset is not a quarter turn: the offset's node.
    angle_offsets: Vec<Option<NodeId>>,
    /// Where the description's constants are traced as leaves [`Var::Exact`] (for the base
    /// parameters' exact analysis): their values in `ℤ/p`, by leaf index.
    exact_leaves: Option<RefCell<Vec<Fp>>>,
    /// The index of joint 0 among the coordinates: 0, but 6 on a floating base, whose
    /// velocity's first six are the base's.
    shift: usize,
}

/// The index of joint `i` in a [`Var`].
pub(super) fn joint_index(i: usize) -> u16 {
    u16::try_from(i).unwrap_or(u16::MAX)
}

impl<'g> Tracer<'g> {
    /// A tracer into `graph` for `robot`, whose struct fields are `fields`.
    pub(super) fn new(graph: &'g RefCell<Graph>, fields: &'g [String], robot: &Robot) -> Self {
        Tracer {
            graph,
            fields,
            angle_offsets: vec![None; robot.dof()],
            exact_leaves: None,
            shift: 0,
        }
    }

    /// The same tracer with joint i's variables at index `i + shift` (a floating base's
    /// joints come after its six coordinates of velocity).
    pub(super) fn shifted(mut self, shift: usize) -> Self {
        self.angle_offsets = vec![None; self.angle_offsets.len() + shift];
        self.shift = shift;
        self
    }

    /// The coordinates before joint 0's: a floating base's six, else none.
    pub(super) fn shift(&self) -> usize {
        self.shift
    }

    /// The same tracer, tracing the description's numbers other than 0 and ±1, and the sines
    /// and cosines of its angles other than quarter turns, as leaves [`Var::Exact`]: exact in
    /// `ℤ/p`, where the graph would fold their products into floats once the rationals
    /// overflow, and where a float sine and cosine do not make `s² + c² = 1`.
    pub(super) fn with_exact_leaves(mut self) -> Self {
        self.exact_leaves = Some(RefCell::new(Vec::new()));
        self
    }

    /// The values of the leaves, by index.
    pub(super) fn exact_leaf_values(&self) -> Vec<Fp> {
        self.exact_leaves
            .as_ref()
            .map_or_else(Vec::new, |a| a.borrow().clone())
    }

    /// A leaf of value `x`, where the tracer has them.
    fn exact_leaf(&self, x: Fp) -> Option<Expr<'g>> {
        let mut leaves = self.exact_leaves.as_ref()?.borrow_mut();
        let k = u16::try_from(leaves.len()).ok()?;
        leaves.push(x);
        drop(leaves);
        Some(self.var(Var::Exact(k)))
    }

    /// The θ offsets recorded while tracing the chain (see [`super::Equations::angle_offsets`]).
    pub(super) fn angle_offsets(&self) -> Vec<Option<NodeId>> {
        self.angle_offsets.clone()
    }

    pub(super) fn expr(&self, id: NodeId) -> Expr<'g> {
        Expr::new(self.graph, id)
    }

    pub(super) fn num(&self, n: Number) -> Expr<'g> {
        let id = self.graph.borrow_mut().num(n);
        self.expr(id)
    }

    pub(super) fn var(&self, v: Var) -> Expr<'g> {
        let id = self.graph.borrow_mut().var(v);
        self.expr(id)
    }

    /// `sign x`, 0 at 0.
    pub(super) fn sign(&self, x: Expr<'g>) -> Expr<'g> {
        let id = self.graph.borrow_mut().sign(x.id());
        self.expr(id)
    }

    /// `tanh x`.
    pub(super) fn tanh(&self, x: Expr<'g>) -> Expr<'g> {
        let id = self.graph.borrow_mut().tanh(x.id());
        self.expr(id)
    }

    /// `1 / x`; zero for a literal zero, which the front end rejects.
    pub(super) fn reciprocal(&self, x: &Expr<'g>) -> Expr<'g> {
        let r = self.graph.borrow_mut().recip(x.id());
        r.map_or_else(|| self.num(Number::ZERO), |id| self.expr(id))
    }

    /// The variables of every joint: `q`, `q̇` or `q̈` as `kind` says.
    pub(super) fn joint_vars(&self, n: usize, kind: fn(u16) -> Var) -> Vec<Expr<'g>> {
        (0..n).map(|i| self.var(kind(joint_index(i)))).collect()
    }

    fn field(&self, name: &str) -> Expr<'g> {
        let k = self.fields.iter().position(|x| x == name).unwrap_or(0);
        self.var(Var::Param(u16::try_from(k).unwrap_or(u16::MAX)))
    }
}

impl<'g> RobotScalars for Tracer<'g> {
    type Scalar = Expr<'g>;

    fn value(&self, v: &Value) -> Expr<'g> {
        match v {
            Value::Num(n) if n.is_zero() || n.is_one() || n.is_minus_one() => self.num(*n),
            Value::Num(n) => Fp::from_number(*n)
                .and_then(|x| self.exact_leaf(x))
                .unwrap_or_else(|| self.num(*n)),
            Value::Pi => self.num(Number::Float(std::f64::consts::PI)),
            Value::Field(f) => self.field(f),
            // The joint variable was split off by the front end; it never reaches here.
            Value::Joint(_) => self.num(Number::ZERO),
            Value::Neg(a) => -self.value(a),
            Value::Add(a, b) => self.value(a) + self.value(b),
            Value::Sub(a, b) => self.value(a) - self.value(b),
            Value::Mul(a, b) => self.value(a) * self.value(b),
            Value::Div(a, b) => {
                let num = self.value(a);
                let den = self.value(b);
                let r = self.graph.borrow_mut().recip(den.id());
                // A literal zero divisor is rejected by the front end's check.
                num * r.map_or_else(|| self.num(Number::ZERO), |id| self.expr(id))
            }
        }
    }

    /// Exact where `v` is an exact multiple of π with rational sine and cosine.
    fn sin_cos(&self, v: &Value) -> (Expr<'g>, Expr<'g>) {
        if let Some((s, c)) = v.pi_multiple().and_then(exact_sin_cos) {
            return (self.num(s), self.num(c));
        }
        if self.exact_leaves.is_some() {
            if let Some(angle) = v.eval(&|_| None) {
                let (s, c) = rational_point(angle);
                if let (Some(s), Some(c)) = (self.exact_leaf(s), self.exact_leaf(c)) {
                    return (s, c);
                }
            }
        }
        let x = self.value(v);
        let mut g = self.graph.borrow_mut();
        let (s, c) = (g.sin(x.id()), g.cos(x.id()));
        drop(g);
        (self.expr(s), self.expr(c))
    }

    fn joint_variable(&self, joint: usize) -> Expr<'g> {
        self.var(Var::Q(joint_index(joint + self.shift)))
    }

    /// From the leaves `sin q_i`, `cos q_i`: turned by a quarter-turn offset, or with any other
    /// offset recorded for the emitter, which makes the leaves `sin(q_i + θ)`, `cos(q_i + θ)`.
    fn joint_sin_cos(&mut self, joint: usize, offset: &Value) -> (Expr<'g>, Expr<'g>) {
        let joint = joint + self.shift;
        let i = joint_index(joint);
        let (s, c) = (self.var(Var::SinQ(i)), self.var(Var::CosQ(i)));
        let quarter_turns = offset
            .pi_multiple()
            .and_then(|k| k.mul(Number::int(2)).as_integer());
        match quarter_turns {
            Some(k) => match k.rem_euclid(4) {
                0 => (s, c),
                1 => (c, -s),
                2 => (-s, -c),
                _ => (-c, s),
            },
            None => {
                self.angle_offsets[joint] = Some(self.value(offset).id());
                (s, c)
            }
        }
    }
}

/// `(sin θ', cos θ')` in `ℤ/p` of the angle θ' nearest θ whose `t = tan(θ'/2)` is a multiple
/// of 2⁻³⁰: `(2t/(1+t²), (1−t²)/(1+t²))`, exactly on the unit circle.
fn rational_point(angle: f64) -> (Fp, Fp) {
    let scale = f64::from(1 << 30);
    // Clamped far beyond any angle but ±π, whose sine and cosine the trace has exact.
    let t = ((angle / 2.0).tan() * scale).round().clamp(-1e27, 1e27);
    #[allow(clippy::cast_possible_truncation)]
    let t = Fp::int(t as i128) * Fp::int(1 << 30).recip().unwrap_or(Fp::ONE);
    let t2 = t * t;
    match (Fp::ONE + t2).recip() {
        Some(d) => ((t + t) * d, (Fp::ONE - t2) * d),
        None => (Fp::ZERO, Fp::ONE),
    }
}

/// Sine and cosine of an exact multiple `k` of π when they are rational.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn exact_sin_cos(k: Number) -> Option<(Number, Number)> {
    // Quarter turns give 0 and ±1; other angles (30°: cos = √3/2) are not rational in both.
    let quarter_turns = k.mul(Number::int(2)).as_integer()?;
    Some(match quarter_turns.rem_euclid(4) {
        0 => (Number::ZERO, Number::ONE),
        1 => (Number::ONE, Number::ZERO),
        2 => (Number::ZERO, Number::MINUS_ONE),
        _ => (Number::MINUS_ONE, Number::ZERO),
    })
}

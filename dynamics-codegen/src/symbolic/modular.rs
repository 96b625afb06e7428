//! Exact evaluation of a graph in the integers modulo the prime `p = 2⁶¹ − 1`.
//!
//! Every constant of a traced robot is a rational (a decimal of the description) or a float
//! (an exact dyadic rational `m·2ᵉ`), so it has an exact image in `ℤ/p`; sums, products,
//! negations and reciprocals are exact there. A joint's sine and cosine are taken at a rational
//! point of the unit circle, `(2t/(1+t²), (1−t²)/(1+t²))`, so that `s² + c² = 1` holds exactly.
//! Whether a linear combination of outputs vanishes identically is then decided exactly, up to
//! the chance that random points are roots of a nonzero polynomial (at most its degree over `p`,
//! about 10⁻¹⁷ per point for the degrees of a robot's equations).

use super::graph::Graph;
use super::node::{Node, NodeId, Var};
use super::number::Number;
use std::ops::{Add, Mul, Neg, Sub};

/// The prime modulus.
pub const P: u64 = (1 << 61) - 1;

/// An element of `ℤ/p`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Fp(#[doc(hidden)] pub u64); // The field public for the generator's tests.

impl Fp {
    pub const ZERO: Fp = Fp(0);
    pub const ONE: Fp = Fp(1);

    /// `x mod p`.
    #[must_use]
    pub fn new(x: u64) -> Fp {
        Fp(x % P)
    }

    /// The integer `x` (any sign).
    #[must_use]
    pub fn int(x: i128) -> Fp {
        let p = i128::from(P);
        // The remainder is in [0, p), which fits in u64.
        Fp(u64::try_from(x.rem_euclid(p)).unwrap_or(0))
    }

    /// The residue, in `[0, p)`.
    #[must_use]
    pub fn value(self) -> u64 {
        self.0
    }

    #[must_use]
    pub fn is_zero(self) -> bool {
        self.0 == 0
    }

    #[must_use]
    pub fn pow(self, mut e: u64) -> Fp {
        let (mut base, mut acc) = (self, Fp::ONE);
        while e > 0 {
            if e & 1 == 1 {
                acc = acc * base;
            }
            base = base * base;
            e >>= 1;
        }
        acc
    }

    /// `1 / x`, `None` for zero.
    #[must_use]
    pub fn recip(self) -> Option<Fp> {
        (!self.is_zero()).then(|| self.pow(P - 2))
    }

    /// The image of an exact number: a rational, or a float as the dyadic rational it is.
    #[must_use]
    pub fn from_number(n: Number) -> Option<Fp> {
        match n {
            Number::Rational(num, den) => Fp::int(den).recip().map(|d| Fp::int(num) * d),
            Number::Float(x) => Some(Fp::from_f64(x)),
        }
    }

    /// A finite float `m·2ᵉ`, exactly.
    #[must_use]
    pub fn from_f64(x: f64) -> Fp {
        if x == 0.0 || !x.is_finite() {
            return Fp::ZERO;
        }
        let bits = x.to_bits();
        let exponent = i64::try_from((bits >> 52) & 0x7ff).unwrap_or(0);
        let fraction = bits & ((1 << 52) - 1);
        let (mantissa, e) = if exponent == 0 {
            (fraction, -1074)
        } else {
            (fraction | (1 << 52), exponent - 1075)
        };
        let two = Fp(2);
        // 2 has order 61 modulo 2⁶¹ − 1: its powers repeat every 61.
        let power = two.pow(u64::try_from(e.rem_euclid(61)).unwrap_or(0));
        let m = Fp::new(mantissa) * power;
        if x < 0.0 {
            -m
        } else {
            m
        }
    }

    /// The rational `a / b` with `|a|, b ≤ bound` whose image is `self`, if there is one
    /// (Wang's rational reconstruction: the extended Euclidean algorithm stopped half way).
    #[must_use]
    pub fn to_small_rational(self, bound: i128) -> Option<(i128, i128)> {
        let p = i128::from(P);
        let (mut r0, mut r1) = (p, i128::from(self.0));
        let (mut t0, mut t1) = (0_i128, 1_i128);
        while r1 > bound {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        if t1 == 0 || t1.abs() > bound {
            return None;
        }
        let (a, b) = if t1 < 0 { (-r1, -t1) } else { (r1, t1) };
        (Fp::int(a) == self * Fp::int(b)).then_some((a, b))
    }
}

impl Add for Fp {
    type Output = Fp;
    fn add(self, o: Fp) -> Fp {
        let s = self.0 + o.0;
        Fp(if s >= P { s - P } else { s })
    }
}

impl Neg for Fp {
    type Output = Fp;
    fn neg(self) -> Fp {
        Fp(if self.0 == 0 { 0 } else { P - self.0 })
    }
}

impl Sub for Fp {
    type Output = Fp;
    fn sub(self, o: Fp) -> Fp {
        self + -o
    }
}

impl Mul for Fp {
    type Output = Fp;
    fn mul(self, o: Fp) -> Fp {
        let wide = u128::from(self.0) * u128::from(o.0);
        // 2⁶¹ ≡ 1: fold the high bits onto the low ones.
        let low = u64::try_from(wide & u128::from(P)).unwrap_or(0);
        let high = u64::try_from(wide >> 61).unwrap_or(0);
        Fp::new(low) + Fp::new(high)
    }
}

/// A deterministic stream of pseudo-random residues (splitmix64), so that what is decided from
/// random points is the same in every build.
#[derive(Clone, Debug)]
pub struct Points(u64);

impl Points {
    #[must_use]
    pub fn new(seed: u64) -> Points {
        Points(seed)
    }

    /// The next 64 random bits.
    pub fn bits(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// A random residue.
    pub fn residue(&mut self) -> Fp {
        Fp::new(self.bits())
    }

    /// A random rational point `(sin, cos)` of the unit circle.
    pub fn circle(&mut self) -> (Fp, Fp) {
        loop {
            let t = self.residue();
            let t2 = t * t;
            if let Some(d) = (Fp::ONE + t2).recip() {
                return ((t + t) * d, (Fp::ONE - t2) * d);
            }
        }
    }
}

/// The nodes that `outputs` depend on, as a mask over the graph's nodes.
#[must_use]
pub fn needed(graph: &Graph, outputs: &[NodeId]) -> Vec<bool> {
    let mut mask = vec![false; graph.len()];
    for o in outputs {
        mask[o.index()] = true;
    }
    for i in (0..graph.len()).rev() {
        if mask[i] {
            for operand in graph.nodes[i].operands() {
                mask[operand.index()] = true;
            }
        }
    }
    mask
}

/// Every node of `mask` evaluated in `ℤ/p`, leaves from `leaf`. A sine, cosine, sign or tanh
/// of an expression (a parameter's angle, a velocity's sign) is not a rational function: it is
/// taken as a leaf of its own from `opaque` (given the node and its operand), the sine and the
/// cosine of one operand a point of the unit circle. `None` where a reciprocal's operand is 0
/// at this point.
pub fn eval(
    graph: &Graph,
    mask: &[bool],
    mut leaf: impl FnMut(Var) -> Fp,
    mut opaque: impl FnMut(Node, NodeId) -> Fp,
) -> Option<Vec<Fp>> {
    let mut values = vec![Fp::ZERO; graph.len()];
    for (i, node) in graph.nodes.iter().enumerate() {
        if !mask[i] {
            continue;
        }
        let v = |id: NodeId| values[id.index()];
        values[i] = match *node {
            Node::Const(c) => Fp::from_number(c)?,
            Node::Var(x) => leaf(x),
            Node::Add(a, b) => v(a) + v(b),
            Node::Mul(a, b) => v(a) * v(b),
            Node::Neg(a) => -v(a),
            Node::Recip(a) => v(a).recip()?,
            Node::Sin(a) | Node::Cos(a) | Node::Sign(a) | Node::Tanh(a) => opaque(*node, a),
        };
    }
    Some(values)
}

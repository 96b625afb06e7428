//! The symbols of the readable equations: parameters, joint variables and the sines and
//! cosines of sums of joint angles (`S1 = sin θ1`, `C12 = cos(θ1 + θ2)`).
//!
//! One vocabulary for the polynomial ([`super::Poly`]) and the printer: the graph's leaves
//! ([`Var`]) map onto these, and folding turns products of single-joint sines and cosines into
//! ones of sums. The order of the variants is the order of printing.

use crate::symbolic::{Graph, Node, NodeId, Number, Var};
use std::cmp::Ordering;
use std::fmt;

/// A sum of joint angles `θ_a + θ_b + …`, as a set of 0-based joint indices (at most 64,
/// which covers `check::MAX_JOINTS`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct AngleSum(u64);

impl AngleSum {
    /// The angle of joint `i` alone; `None` past 64 joints.
    #[must_use]
    pub fn joint(i: u16) -> Option<AngleSum> {
        1u64.checked_shl(u32::from(i)).map(AngleSum)
    }

    /// The joints of the sum, in increasing order.
    pub fn joints(self) -> impl Iterator<Item = u16> {
        (0..64u16).filter(move |&j| self.0 & (1 << j) != 0)
    }

    /// Whether the two sums share no joint.
    #[must_use]
    pub fn is_disjoint(self, other: AngleSum) -> bool {
        self.0 & other.0 == 0
    }

    /// The sum of both.
    #[must_use]
    pub fn union(self, other: AngleSum) -> AngleSum {
        AngleSum(self.0 | other.0)
    }
}

/// As the lists of joints compare (`1 < 12 < 123 < 13 < 2`), so that `C1` prints before
/// `C12` and `C12` before `C2`.
impl Ord for AngleSum {
    fn cmp(&self, other: &AngleSum) -> Ordering {
        let differ = self.0 ^ other.0;
        if differ == 0 {
            return Ordering::Equal;
        }
        // Below the lowest differing joint both lists agree; the list holding that joint
        // continues with it, the other with a higher joint, or ends.
        let lowest = differ & differ.wrapping_neg();
        let above = !(lowest | (lowest - 1));
        let (with, without) = if self.0 & lowest != 0 {
            (Ordering::Less, other.0)
        } else {
            (Ordering::Greater, self.0)
        };
        if without & above != 0 {
            with
        } else {
            with.reverse()
        }
    }
}

impl PartialOrd for AngleSum {
    fn partial_cmp(&self, other: &AngleSum) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// A mimic joint's angle `k q_j + c` in its coordinate j (0-based): the multiplier k, and c its
/// offset plus its own θ offset. Its sine and cosine are symbols of their own, bounded over
/// q_j's range through k and c, as the coordinates' own `sin q_j` are over theirs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct MimicAngle {
    /// The coordinate followed.
    pub joint: u16,
    /// `k`.
    pub multiplier: Number,
    /// `c`.
    pub offset: Number,
}

impl MimicAngle {
    /// `k q_j + c` at the coordinate's position `q`.
    #[must_use]
    pub fn at(self, q: f64) -> f64 {
        self.multiplier.to_f64() * q + self.offset.to_f64()
    }

    /// The interval of `k q_j + c` over `q_j ∈ [lo, hi]`.
    #[must_use]
    pub fn range(self, lo: f64, hi: f64) -> (f64, f64) {
        let (a, b) = (self.at(lo), self.at(hi));
        (a.min(b), a.max(b))
    }
}

/// A symbol of a polynomial. The order of the variants is the order of printing.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Sym {
    /// A parameter (struct field) by name.
    Param(String),
    /// The position `q_i` of a prismatic joint (0-based).
    Q(u16),
    /// The sine of a sum of joint angles.
    Sin(AngleSum),
    /// The cosine of a sum of joint angles.
    Cos(AngleSum),
    /// The sine of a mimic joint's angle.
    MimicSin(MimicAngle),
    /// The cosine of a mimic joint's angle.
    MimicCos(MimicAngle),
    /// The acceleration `q̈_i`.
    Qdd(u16),
    /// The velocity `q̇_i`.
    Qd(u16),
    /// `sign q̇_i` of Coulomb friction.
    Sign(u16),
    /// `tanh(q̇_i / ε_i)` of smooth Coulomb friction, ε_i joint i's smoothing velocity.
    Tanh(u16),
}

use crate::symbolic::WRENCH;

impl Sym {
    /// The symbol of a graph input; `fields` names the parameters (`None` for an unknown
    /// one).
    #[must_use]
    pub fn of(v: Var, fields: &[String]) -> Option<Sym> {
        Some(match v {
            Var::Q(i) => Sym::Q(i),
            Var::SinQ(i) => Sym::Sin(AngleSum::joint(i)?),
            Var::CosQ(i) => Sym::Cos(AngleSum::joint(i)?),
            Var::Qd(i) => Sym::Qd(i),
            Var::Qdd(i) => Sym::Qdd(i),
            Var::Param(k) => Sym::Param(fields.get(usize::from(k))?.clone()),
            // Printed as the book names the wrench's components.
            Var::Wrench(k) => Sym::Param((*WRENCH.get(usize::from(k))?).to_owned()),
            Var::TipWrench(k) => Sym::Param(format!("{}{}", WRENCH[usize::from(k % 6)], k / 6 + 1)),
            Var::Tau(i) => Sym::Param(format!("T{}", i + 1)),
            Var::Inertial(k) => Sym::Param(format!("pi{}_{}", k / 10 + 1, k % 10 + 1)),
            Var::Exact(k) => Sym::Param(format!("constant{k}")),
        })
    }

    /// `cos angle` when `cos`, else `sin angle`.
    #[must_use]
    pub fn trig(cos: bool, angle: AngleSum) -> Sym {
        if cos {
            Sym::Cos(angle)
        } else {
            Sym::Sin(angle)
        }
    }

    /// Whether it is a cosine (`true`) or sine, and of which angle; `None` for other symbols.
    #[must_use]
    pub fn as_trig(&self) -> Option<(bool, AngleSum)> {
        match self {
            Sym::Sin(a) => Some((false, *a)),
            Sym::Cos(a) => Some((true, *a)),
            _ => None,
        }
    }

    /// The sine (`cos` false) or cosine of the angle of a graph node whose polynomial is `p`,
    /// if `p` is `k q_j + c` (a mimic joint's angle, k ≠ 0): no other sine is a polynomial's
    /// symbol.
    #[must_use]
    pub fn mimic_trig(cos: bool, p: &super::Poly) -> Option<Sym> {
        let mut offset = Number::ZERO;
        let mut linear = None;
        for (m, c) in p.terms() {
            match m.factors() {
                [] => offset = c,
                [(Sym::Q(j), 1)] if linear.is_none() => linear = Some((*j, c)),
                _ => return None,
            }
        }
        let (joint, multiplier) = linear?;
        let angle = MimicAngle {
            joint,
            multiplier,
            offset,
        };
        Some(if cos {
            Sym::MimicCos(angle)
        } else {
            Sym::MimicSin(angle)
        })
    }

    /// Whether it is a velocity or an acceleration, or friction's function of a velocity.
    #[must_use]
    pub fn is_motion(&self) -> bool {
        matches!(self, Sym::Qd(_) | Sym::Qdd(_) | Sym::Sign(_) | Sym::Tanh(_))
    }

    /// The symbol of friction's `sign` or `tanh` node of `graph` over the velocity of joint
    /// i (`tanh` of `q̇_i` times `1/ε_i`), if `node` is one.
    #[must_use]
    pub fn of_friction(graph: &Graph, node: Node) -> Option<Sym> {
        let velocity = |id: NodeId| match graph.node(id) {
            Node::Var(Var::Qd(i)) => Some(i),
            _ => None,
        };
        match node {
            Node::Sign(a) => Some(Sym::Sign(velocity(a)?)),
            Node::Tanh(a) => {
                let joint = match graph.node(a) {
                    Node::Mul(x, y) => velocity(x).or_else(|| velocity(y)),
                    _ => velocity(a),
                };
                Some(Sym::Tanh(joint?))
            }
            _ => None,
        }
    }

    /// The cosine of the same angle, if it is a sine (of joint angles or of a mimic joint's).
    #[must_use]
    pub fn cosine_of_sine(&self) -> Option<Sym> {
        match self {
            Sym::Sin(a) => Some(Sym::Cos(*a)),
            Sym::MimicSin(a) => Some(Sym::MimicCos(*a)),
            _ => None,
        }
    }

    /// Whether it is a sine or a cosine (of joint angles or of a mimic joint's angle).
    #[must_use]
    pub fn is_trig(&self) -> bool {
        matches!(self, Sym::MimicSin(_) | Sym::MimicCos(_)) || self.as_trig().is_some()
    }
}

/// The syntax of [`super::Poly::parse`]: `m1`, `q2`, `qd1`, `qdd1`, `S1`, `C12`.
impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let angle = |f: &mut fmt::Formatter<'_>, a: &AngleSum| {
            a.joints().try_for_each(|j| write!(f, "{}", j + 1))
        };
        match self {
            Sym::Param(p) => write!(f, "{p}"),
            Sym::Q(i) => write!(f, "q{}", i + 1),
            Sym::Sin(a) => {
                write!(f, "S")?;
                angle(f, a)
            }
            Sym::Cos(a) => {
                write!(f, "C")?;
                angle(f, a)
            }
            Sym::MimicSin(a) => write!(f, "sin({}*q{} + {})", a.multiplier, a.joint + 1, a.offset),
            Sym::MimicCos(a) => write!(f, "cos({}*q{} + {})", a.multiplier, a.joint + 1, a.offset),
            Sym::Qdd(i) => write!(f, "qdd{}", i + 1),
            Sym::Qd(i) => write!(f, "qd{}", i + 1),
            Sym::Sign(i) => write!(f, "sgn(qd{})", i + 1),
            Sym::Tanh(i) => write!(f, "tanh(qd{}/eps{})", i + 1, i + 1),
        }
    }
}

//! Printing of arranged terms as a person writes them, in the notation of Niku ch. 6: plain
//! text (`1/2 m2 l1 l2 S2 θ1'²`) or LaTeX (`\frac{1}{2} m_{2} … \dot{\theta}_{1}^{2}`).
//!
//! Plain text writes the book's dots as primes after the index (`θ1'` for θ̇1, `d2''` for
//! d̈2): a combining dot over `θ` is invisible or misplaced in rustdoc's code font, which made
//! `S2 θ̇2` read as `S2 θ2` (docs/design/emission.md, "Primes for dots").

use super::arrange::Term;
use super::number::{decimal, is_small_fraction};
use crate::algo::JointKind;
use crate::poly::{AngleSum, Sym};
use crate::symbolic::Number;
use crate::trace::BASE_GRAVITY;
use std::fmt::Write;

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Plain text (UTF-8): `1/2 m2 l1 l2 S2 θ1'²`, velocities and accelerations primed.
    Text,
    /// LaTeX math: `\frac{1}{2} m_{2} l_{1} l_{2} S_{2} \dot{\theta}_{1}^{2}`.
    Latex,
}

/// Prints terms in one format for a robot with the given joints.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Printer<'a> {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub format: Format,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub kinds: &'a [JointKind],
    /// Whether a group of sines and cosines has its factors before it, `C1(a2 C2 + a3 C23)`
    /// as chapter 3 writes the kinematics, rather than after, as chapter 6 writes the dynamics
    /// and any group of parameters alone: `(1/2 m1 + m2) g l1 C1`, `(l2 + 0.1) C12`.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub factors_first: bool,
    /// Whether the equations are a floating base's (`super::floating`): the coordinates'
    /// first six are the base's (`vx` … `ωz`), joint i's is `6 + i`, and `kinds` the joints'.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub floating: bool,
}

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

impl Printer<'_> {
    pub(super) fn latex(&self) -> bool {
        self.format == Format::Latex
    }

    /// Joint indices (0-based) as the book writes them: `12`, or `1,10` past nine joints.
    pub(super) fn indices(&self, joints: &[usize]) -> String {
        let sep = if self.kinds.len() > 9 { "," } else { "" };
        // Written into one string: a string per index, joined, was most of a symbol's cost.
        let mut s = String::from(if self.latex() { "_{" } else { "" });
        for (k, j) in joints.iter().enumerate() {
            if k > 0 {
                s.push_str(sep);
            }
            let _ = write!(s, "{}", j + 1);
        }
        if self.latex() {
            s.push('}');
        }
        s
    }

    /// The symbol of joint `i`'s variable: `d` for a prismatic joint, else `θ`.
    pub(super) fn joint_letter(&self, i: usize) -> &'static str {
        let prismatic = self.kinds.get(i) == Some(&JointKind::Prismatic);
        match (prismatic, self.latex()) {
            (true, _) => "d",
            (false, true) => "\\theta",
            (false, false) => "θ",
        }
    }

    fn power(&self, base: String, e: u32) -> String {
        if e == 1 {
            base
        } else if self.latex() {
            format!("{base}^{{{e}}}")
        } else {
            let sup: String = e
                .to_string()
                .chars()
                .filter_map(|d| d.to_digit(10).map(|d| SUPERSCRIPTS[d as usize]))
                .collect();
            format!("{base}{sup}")
        }
    }

    fn symbol(&self, s: &Sym) -> String {
        if self.floating {
            if let Some(name) = self.base_symbol(s) {
                return name;
            }
        }
        let joint = self.floating.then(|| joint_symbol(s));
        let s = joint.as_ref().unwrap_or(s);
        let index = |i: &u16| self.indices(&[usize::from(*i)]);
        match s {
            Sym::Param(p) if self.latex() => latex_name(p),
            Sym::Param(p) => p.clone(),
            // A revolute joint's own q appears where a mimic joint's spring reads it.
            Sym::Q(i) if self.kinds.get(usize::from(*i)) == Some(&JointKind::Revolute) => {
                format!("q{}", index(i))
            }
            Sym::Q(i) => format!("d{}", index(i)),
            Sym::Sin(a) | Sym::Cos(a) => {
                let joints: Vec<usize> = a.joints().map(usize::from).collect();
                let letter = if matches!(s, Sym::Cos(_)) { "C" } else { "S" };
                format!("{letter}{}", self.indices(&joints))
            }
            Sym::MimicSin(a) | Sym::MimicCos(a) => {
                let cos = matches!(s, Sym::MimicCos(_));
                let name = match (cos, self.latex()) {
                    (true, true) => "\\cos",
                    (false, true) => "\\sin",
                    (true, false) => "cos",
                    (false, false) => "sin",
                };
                // The coordinate's own q (without its θ offset): the rule reads q_j.
                let q = format!("q{}", index(&a.joint));
                match (a.offset.is_zero(), a.offset.is_negative()) {
                    (true, _) => format!("{name}({} {q})", a.multiplier),
                    (false, true) => format!("{name}({} {q} - {})", a.multiplier, -a.offset),
                    (false, false) => format!("{name}({} {q} + {})", a.multiplier, a.offset),
                }
            }
            Sym::Qd(i) | Sym::Qdd(i) => {
                let letter = self.joint_letter(usize::from(*i));
                let second = matches!(s, Sym::Qdd(_));
                match (second, self.latex()) {
                    (false, true) => format!("\\dot{{{letter}}}{}", index(i)),
                    (true, true) => format!("\\ddot{{{letter}}}{}", index(i)),
                    (false, false) => format!("{letter}{}'", index(i)),
                    (true, false) => format!("{letter}{}''", index(i)),
                }
            }
            Sym::Sign(i) | Sym::Tanh(i) => {
                let velocity = self.symbol(&Sym::Qd(*i));
                match (matches!(s, Sym::Sign(_)), self.latex()) {
                    (true, true) => format!("\\operatorname{{sgn}}({velocity})"),
                    (true, false) => format!("sgn({velocity})"),
                    (false, true) => format!("\\tanh({velocity}/\\varepsilon{})", index(i)),
                    (false, false) => format!("tanh({velocity}/ε{})", index(i)),
                }
            }
        }
    }

    /// A sum of terms.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn sum(&self, terms: &[Term]) -> String {
        if terms.is_empty() {
            return "0".into();
        }
        let mut s = String::new();
        for (k, t) in terms.iter().enumerate() {
            let negative = t.coef.is_negative();
            s.push_str(match (k, negative) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            s.push_str(&self.term(t));
        }
        s
    }

    /// A term without its sign.
    fn term(&self, t: &Term) -> String {
        let mut parts: Vec<String> = Vec::new();
        let abs = if t.coef.is_negative() {
            -t.coef
        } else {
            t.coef
        };
        if !abs.is_one() || (t.group.is_empty() && t.factors.is_one()) {
            parts.push(self.number(abs));
        }
        let group = (!t.group.is_empty()).then(|| {
            let inner = self.sum(&t.group);
            if self.latex() {
                format!("\\left({inner}\\right)")
            } else {
                format!("({inner})")
            }
        });
        let mut factors: Vec<&(Sym, u32)> = t.factors.factors().iter().collect();
        factors.sort_by_key(|(s, _)| person_order(s));
        let factors: Vec<String> = factors
            .into_iter()
            .map(|(s, e)| self.power(self.symbol(s), *e))
            .collect();
        match group {
            Some(group) if self.factors_first && !factors.is_empty() && has_trig(&t.group) => {
                parts.extend(factors);
                let last = parts.pop().unwrap_or_default();
                parts.push(format!("{last}{group}"));
            }
            Some(group) => {
                parts.push(group);
                parts.extend(factors);
            }
            None => parts.extend(factors),
        }
        parts.join(" ")
    }

    fn number(&self, x: Number) -> String {
        if let Number::Rational(n, d) = x {
            if d == 1 {
                return n.to_string();
            }
            if is_small_fraction(d) {
                return if self.latex() {
                    format!("\\frac{{{n}}}{{{d}}}")
                } else {
                    format!("{n}/{d}")
                };
            }
        }
        decimal(x)
    }

    /// A LaTeX sum broken into lines of four terms inside `align*`.
    pub(super) fn latex_lines(&self, terms: &[Term]) -> String {
        let mut s = String::new();
        for (k, chunk) in terms.chunks(4).enumerate() {
            let part = self.sum(chunk);
            if k == 0 {
                s.push_str(&part);
            } else {
                s.push_str(" \\\\\n  &\\quad ");
                if !part.starts_with('-') {
                    s.push_str("+ ");
                }
                s.push_str(&part);
            }
        }
        if s.is_empty() {
            s.push('0');
        }
        s
    }
}

/// Whether a sine or cosine appears in `terms`.
fn has_trig(terms: &[Term]) -> bool {
    terms
        .iter()
        .any(|t| t.factors.factors().iter().any(|(s, _)| s.is_trig()) || has_trig(&t.group))
}

/// Masses first, then gravity, then the rest in symbol order, as the book writes
/// `m2 g l2 C12`.
fn person_order(s: &Sym) -> (u8, &Sym) {
    let rank = match s {
        Sym::Param(p) if p.starts_with('m') => 0,
        Sym::Param(p) if p == "g" => 1,
        _ => 2,
    };
    (rank, s)
}

/// `m2` → `m_{2}`, `I1act` → `I_{1act}`, `payload` → `\mathit{payload}`.
fn latex_name(name: &str) -> String {
    let letters: String = name.chars().take_while(char::is_ascii_alphabetic).collect();
    let rest = &name[letters.len()..];
    let base = if letters.chars().count() > 1 {
        format!("\\mathit{{{letters}}}")
    } else {
        letters
    };
    let rest = rest.replace('_', "\\_");
    if rest.is_empty() {
        base
    } else if rest.starts_with(|c: char| c.is_ascii_digit()) {
        format!("{base}_{{{rest}}}")
    } else {
        format!("{base}\\mathit{{{rest}}}")
    }
}

// A floating base's symbols: the base's coordinates and `g_b` by name, the joints by their own
// index (`dynamics inspect --floating`).

/// The base's coordinates of `v`, in text and in LaTeX.
pub(super) const BASE: [(&str, &str); 6] = [
    ("vx", "v_x"),
    ("vy", "v_y"),
    ("vz", "v_z"),
    ("ωx", "\\omega_x"),
    ("ωy", "\\omega_y"),
    ("ωz", "\\omega_z"),
];

/// `q`'s entries `y` … `qw` as the graph's `Q(0..6)` reads them (`x` is read by nothing).
const CONFIGURATION: [(&str, &str); 6] = [
    ("y", "y"),
    ("z", "z"),
    ("qx", "q_x"),
    ("qy", "q_y"),
    ("qz", "q_z"),
    ("qw", "q_w"),
];

/// `g_b`'s components.
pub(super) const GRAVITY: [(&str, &str); 3] =
    [("gbx", "g_{b,x}"), ("gby", "g_{b,y}"), ("gbz", "g_{b,z}")];

/// A joint's symbol of a floating base's polynomial with the joint's own index (`Q(6 + i)` →
/// `Q(i)`, `S7` → `S1`), as the fixed base's printer names it; other symbols as they are.
fn joint_symbol(s: &Sym) -> Sym {
    let shift = |i: u16| i.saturating_sub(6);
    let angle = |a: &AngleSum| {
        let mut joints = a.joints().filter_map(|j| AngleSum::joint(shift(j)));
        let first = joints.next();
        first.map_or(*a, |first| joints.fold(first, AngleSum::union))
    };
    match s {
        Sym::Q(i) => Sym::Q(shift(*i)),
        Sym::Qd(i) => Sym::Qd(shift(*i)),
        Sym::Qdd(i) => Sym::Qdd(shift(*i)),
        Sym::Sin(a) => Sym::Sin(angle(a)),
        Sym::Cos(a) => Sym::Cos(angle(a)),
        other => other.clone(),
    }
}

impl Printer<'_> {
    /// One of `names`, in this printer's notation.
    pub(super) fn pick(&self, (text, latex): (&str, &str)) -> String {
        let name = if self.latex() { latex } else { text };
        name.to_owned()
    }

    /// The name of a symbol of the base: `g_b`'s components, the quaternion, the base's
    /// velocities (`vx`, `ωz`) and accelerations (`vx'`, `\dot{v}_x`); `None` for a joint's.
    fn base_symbol(&self, s: &Sym) -> Option<String> {
        let base = |i: &u16| BASE.get(usize::from(*i)).copied();
        match s {
            Sym::Param(p) => {
                let k = BASE_GRAVITY.iter().position(|g| g == p)?;
                Some(self.pick(GRAVITY[k]))
            }
            Sym::Q(i) => CONFIGURATION.get(usize::from(*i)).map(|&n| self.pick(n)),
            Sym::Qd(i) => base(i).map(|n| self.pick(n)),
            Sym::Qdd(i) => base(i).map(|(text, latex)| {
                if self.latex() {
                    // `\dot{v}_x`, `\dot{\omega}_x`.
                    let (letter, axis) = latex.split_at(latex.len() - 2);
                    format!("\\dot{{{letter}}}{axis}")
                } else {
                    format!("{text}'")
                }
            }),
            _ => None,
        }
    }
}

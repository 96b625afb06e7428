//! Readable closed forms: the equations of motion printed as a person writes them, in the
//! notation of Niku ch. 6, as plain text or LaTeX.
//!
//! Each output of the [`Equations`] is expanded into its exact canonical polynomial ([`Poly`]),
//! then rewritten for reading:
//!
//! * products of sines and cosines of joint angles fold back into those of sums
//!   (`C1 C2 − S1 S2` → `C12`, `S1 C2 + C1 S2` → `S12`);
//! * terms are grouped by their accelerations and velocities (`(…) θ̈1`, `… θ̇1 θ̇2`);
//! * terms sharing a sine or cosine are grouped with their common parameters taken out
//!   (`(1/2 m1 + m2) g l1 C1`).
//!
//! Expanded polynomials grow fast with the number of joints (the code is emitted from the
//! shared graph, never from these), so the expansion is bounded by [`Limits`] and what does not
//! fit is reported as too large instead of printed.

use crate::algo::JointKind;
use crate::derive::Equations;
use crate::model::Robot;
use crate::poly::{Poly, Sym};
use crate::symbolic::{Node, NodeId, Number};
use std::collections::BTreeMap;
use std::fmt::Write;

/// Bounds on the polynomial expansion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Most terms of any one polynomial, intermediate ones included.
    pub max_terms: usize,
    /// Most term operations in all (each product of two terms, each term added).
    pub max_work: u64,
}

impl Limits {
    /// For the derive, which runs on every build: small robots print in full, a 6-joint arm's
    /// gravity torques (and PUMA 560's D_ij and D_ijk) still do. A term operation costs a few
    /// microseconds (monomials are maps keyed by parameter names): measured with `dynamics
    /// stats`, the 7-joint `bench/robots/iiwa14_fields.toml` (70 parameters as fields) spends
    /// a median 62 ms here (51–133 ms on a loaded 2-core machine; 19 ms for the rest of the
    /// derive), against 1.1–1.6 s with a cap of 400 terms and 400,000 operations.
    pub const DERIVE: Limits = Limits {
        max_terms: 200,
        max_work: 20_000,
    };
    /// For the command-line tool: no bound.
    pub const UNBOUNDED: Limits = Limits {
        max_terms: usize::MAX,
        max_work: u64::MAX,
    };
}

/// A factor of a printed term. The order of the variants is the order of printing.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum F {
    /// A parameter (struct field).
    Param(String),
    /// The position of a prismatic joint.
    Q(u16),
    /// `sin` (`cos` when `cos`) of the sum of the joint angles `joints` (sorted, 0-based).
    Trig { cos: bool, joints: Vec<u16> },
    /// An acceleration.
    Qdd(u16),
    /// A velocity.
    Qd(u16),
}

impl F {
    fn is_motion(&self) -> bool {
        matches!(self, F::Qd(_) | F::Qdd(_))
    }

    fn is_trig(&self) -> bool {
        matches!(self, F::Trig { .. })
    }
}

type Mono = BTreeMap<F, u32>;

/// A printed term: `coef · (group) · factors`, with an empty group meaning none.
#[derive(Clone, Debug, PartialEq)]
struct Term {
    coef: Number,
    group: Vec<Term>,
    factors: Vec<(F, u32)>,
}

/// Expands graph nodes into polynomials, sharing the work between outputs.
struct Expander<'a> {
    eq: &'a Equations,
    memo: Vec<Option<Option<Poly>>>,
    limits: Limits,
    work: u64,
}

impl<'a> Expander<'a> {
    fn new(eq: &'a Equations, limits: Limits) -> Expander<'a> {
        Expander {
            eq,
            memo: vec![None; eq.graph.len()],
            limits,
            work: 0,
        }
    }

    /// The polynomial of node `id`; `None` when it exceeds the limits or is not a polynomial
    /// (a reciprocal or the sine of a parameter).
    fn poly(&mut self, id: NodeId) -> Option<Poly> {
        if let Some(p) = &self.memo[id.index()] {
            return p.clone();
        }
        let live = self.eq.graph.live(&[id]);
        for (n, node) in self.eq.graph.nodes().take(id.index() + 1) {
            if !live[n.index()] || self.memo[n.index()].is_some() {
                continue;
            }
            let p = self.node(node);
            self.memo[n.index()] = Some(p);
        }
        self.memo[id.index()].clone().flatten()
    }

    fn node(&mut self, node: Node) -> Option<Poly> {
        let get = |x: NodeId| self.memo[x.index()].clone().flatten();
        let p = match node {
            Node::Const(c) => Poly::constant(c),
            Node::Var(v) => Poly::sym(Sym::of(v, &self.eq.fields)?),
            Node::Add(a, b) => {
                let (a, b) = (get(a)?, get(b)?);
                self.charge((a.len() + b.len()) as u64)?;
                a.add(&b)
            }
            Node::Mul(a, b) => {
                let (a, b) = (get(a)?, get(b)?);
                self.charge((a.len() as u64).saturating_mul(b.len() as u64))?;
                a.mul(&b)
            }
            Node::Neg(a) => get(a)?.scale(Number::MINUS_ONE),
            Node::Recip(_) | Node::Sin(_) | Node::Cos(_) => return None,
        };
        (p.len() <= self.limits.max_terms).then_some(p)
    }

    fn charge(&mut self, cost: u64) -> Option<()> {
        self.work = self.work.saturating_add(cost);
        (self.work <= self.limits.max_work).then_some(())
    }

    /// The readable form of node `id`.
    fn terms(&mut self, id: NodeId) -> Option<Vec<Term>> {
        let p = self.poly(id)?;
        let mut terms: BTreeMap<Mono, Number> = BTreeMap::new();
        for (m, c) in p.terms() {
            let mono: Mono = m
                .iter()
                .map(|(s, e)| {
                    let f = match s {
                        Sym::Param(p) => F::Param(p.clone()),
                        Sym::Cos(i) => F::Trig {
                            cos: true,
                            joints: vec![*i],
                        },
                        Sym::Sin(i) => F::Trig {
                            cos: false,
                            joints: vec![*i],
                        },
                        Sym::Q(i) => F::Q(*i),
                        Sym::Qd(i) => F::Qd(*i),
                        Sym::Qdd(i) => F::Qdd(*i),
                    };
                    (f, *e)
                })
                .collect();
            terms.insert(mono, c);
        }
        // Each search for a pair to fold reads every term.
        let mut budget = |n: usize| self.charge(n as u64);
        fold_trig(&mut terms, &mut budget)?;
        Some(arrange(terms.into_iter().collect()))
    }
}

fn add_factor(m: &mut Mono, f: F, e: u32) {
    *m.entry(f).or_insert(0) += e;
}

fn remove_factor(m: &mut Mono, f: &F) {
    if let Some(e) = m.get_mut(f) {
        *e -= 1;
        if *e == 0 {
            m.remove(f);
        }
    }
}

fn add_term(terms: &mut BTreeMap<Mono, Number>, m: Mono, c: Number) {
    let entry = terms.entry(m.clone()).or_insert(Number::ZERO);
    *entry = *entry + c;
    if entry.is_zero() {
        terms.remove(&m);
    }
}

fn abs_f64(x: Number) -> f64 {
    x.to_f64().abs()
}

/// One fold: `k · rest · trig(union)` replaces `k` of term `m` and of its partner.
struct Fold {
    m: Mono,
    partner: Mono,
    /// Added to the partner's coefficient.
    partner_delta: Number,
    folded: Mono,
    k: Number,
}

/// Folds `c Ca Cb − c Sa Sb` into `c C(a+b)` and `c Sa Cb + c Ca Sb` into `c S(a+b)` until
/// no pair is left; where the two coefficients differ, the smaller is folded. `charge` is
/// told the number of terms before each search and stops the folding with `None`.
fn fold_trig(
    terms: &mut BTreeMap<Mono, Number>,
    charge: &mut dyn FnMut(usize) -> Option<()>,
) -> Option<()> {
    loop {
        charge(terms.len())?;
        let Some(fold) = find_fold(terms) else {
            return Some(());
        };
        add_term(terms, fold.m, -fold.k);
        add_term(terms, fold.partner, fold.partner_delta);
        add_term(terms, fold.folded, fold.k);
    }
}

fn find_fold(terms: &BTreeMap<Mono, Number>) -> Option<Fold> {
    for (m, &c) in terms {
        let trigs: Vec<(bool, &Vec<u16>)> = m
            .keys()
            .filter_map(|f| match f {
                F::Trig { cos, joints } => Some((*cos, joints)),
                _ => None,
            })
            .collect();
        for (x, &(ca, ja)) in trigs.iter().enumerate() {
            for &(cb, jb) in &trigs[x + 1..] {
                if !(ca || cb) || ja.iter().any(|j| jb.contains(j)) {
                    continue;
                }
                let trig = |cos: bool, joints: &Vec<u16>| F::Trig {
                    cos,
                    joints: joints.clone(),
                };
                let mut rest = m.clone();
                remove_factor(&mut rest, &trig(ca, ja));
                remove_factor(&mut rest, &trig(cb, jb));
                let mut partner = rest.clone();
                // cos-cos pairs with sin-sin of the opposite sign; sin-cos with cos-sin of the
                // same sign.
                add_factor(&mut partner, trig(!ca, ja), 1);
                add_factor(&mut partner, trig(!cb, jb), 1);
                let Some(&pc) = terms.get(&partner) else {
                    continue;
                };
                let same_sign = c.is_negative() == pc.is_negative();
                if same_sign == (ca && cb) {
                    continue;
                }
                let k = if abs_f64(c) <= abs_f64(pc) {
                    c
                } else if ca && cb {
                    -pc
                } else {
                    pc
                };
                let mut union: Vec<u16> = ja.iter().chain(jb).copied().collect();
                union.sort_unstable();
                let mut folded = rest;
                add_factor(&mut folded, trig(ca && cb, &union), 1);
                return Some(Fold {
                    m: m.clone(),
                    partner,
                    partner_delta: if ca && cb { k } else { -k },
                    folded,
                    k,
                });
            }
        }
    }
    None
}

/// Groups terms by their accelerations and velocities, then by their sines and cosines.
fn arrange(terms: Vec<(Mono, Number)>) -> Vec<Term> {
    let mut by_motion: BTreeMap<(u8, Mono), Vec<(Mono, Number)>> = BTreeMap::new();
    for (m, c) in terms {
        let (motion, rest): (Mono, Mono) = m.into_iter().partition(|(f, _)| f.is_motion());
        // accelerations first, then velocity products, then what has neither
        let rank = if motion.keys().any(|f| matches!(f, F::Qdd(_))) {
            0
        } else if motion.is_empty() {
            2
        } else {
            1
        };
        by_motion.entry((rank, motion)).or_default().push((rest, c));
    }
    let mut out = Vec::new();
    for ((_, motion), group) in by_motion {
        let inner = arrange_configuration(group);
        out.extend(wrap(inner, motion.into_iter().collect()));
    }
    out
}

/// Terms without accelerations or velocities, grouped by their sines and cosines with their
/// common factors taken out. A prismatic position stays inside the group, as the book writes
/// `(m1 g l1/2 + m2 g r) Cθ` (6.14).
fn arrange_configuration(terms: Vec<(Mono, Number)>) -> Vec<Term> {
    let mut by_config: BTreeMap<Mono, Vec<(Mono, Number)>> = BTreeMap::new();
    for (m, c) in terms {
        let (config, params): (Mono, Mono) = m.into_iter().partition(|(f, _)| f.is_trig());
        by_config.entry(config).or_default().push((params, c));
    }
    let mut out = Vec::new();
    for (config, group) in by_config {
        let flat = |params: Mono, coef: Number| Term {
            coef,
            group: Vec::new(),
            factors: params.into_iter().chain(config.clone()).collect(),
        };
        if config.is_empty() || group.len() == 1 {
            out.extend(group.into_iter().map(|(p, c)| flat(p, c)));
            continue;
        }
        // the parameters every term of the group has, to their lowest power
        let mut common: Mono = group[0].0.clone();
        for (p, _) in &group[1..] {
            common = common
                .into_iter()
                .filter_map(|(f, e)| p.get(&f).map(|&e2| (f, e.min(e2))))
                .collect();
        }
        let inner: Vec<Term> = group
            .into_iter()
            .map(|(mut p, c)| {
                for (f, e) in &common {
                    if let Some(x) = p.get_mut(f) {
                        *x -= e;
                    }
                }
                p.retain(|_, e| *e > 0);
                Term {
                    coef: c,
                    group: Vec::new(),
                    factors: p.into_iter().collect(),
                }
            })
            .collect();
        out.extend(wrap(inner, common.into_iter().chain(config).collect()));
    }
    out
}

/// `(inner) · factors`, written without parentheses when `inner` is one term, and with a
/// leading minus when all of it is negative.
fn wrap(mut inner: Vec<Term>, factors: Vec<(F, u32)>) -> Vec<Term> {
    if factors.is_empty() {
        return inner;
    }
    if inner.len() == 1 {
        let mut t = inner.remove(0);
        t.factors.extend(factors);
        return vec![t];
    }
    let negative = inner.iter().all(|t| t.coef.is_negative());
    if negative {
        for t in &mut inner {
            t.coef = -t.coef;
        }
    }
    vec![Term {
        coef: if negative {
            Number::MINUS_ONE
        } else {
            Number::ONE
        },
        group: inner,
        factors,
    }]
}

/// Output format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Plain text (UTF-8): `1/2 m2 l1 l2 S2 θ̇1²`.
    Text,
    /// LaTeX math: `\frac{1}{2} m_{2} l_{1} l_{2} S_{2} \dot{\theta}_{1}^{2}`.
    Latex,
}

struct Printer<'a> {
    format: Format,
    kinds: &'a [JointKind],
}

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

impl Printer<'_> {
    fn latex(&self) -> bool {
        self.format == Format::Latex
    }

    /// Joint indices as the book writes them: `12`, or `1,10` past nine joints.
    fn indices(&self, joints: &[usize]) -> String {
        let sep = if self.kinds.len() > 9 { "," } else { "" };
        let s: Vec<String> = joints.iter().map(|j| (j + 1).to_string()).collect();
        let s = s.join(sep);
        if self.latex() {
            format!("_{{{s}}}")
        } else {
            s
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

    fn joint_letter(&self, i: u16) -> &'static str {
        let prismatic = self.kinds.get(usize::from(i)) == Some(&JointKind::Prismatic);
        match (prismatic, self.latex()) {
            (true, _) => "d",
            (false, true) => "\\theta",
            (false, false) => "θ",
        }
    }

    fn factor(&self, f: &F) -> String {
        match f {
            F::Param(p) => {
                if self.latex() {
                    latex_name(p)
                } else {
                    p.clone()
                }
            }
            F::Q(i) => format!("d{}", self.indices(&[usize::from(*i)])),
            F::Trig { cos, joints } => {
                let j: Vec<usize> = joints.iter().map(|&j| usize::from(j)).collect();
                format!("{}{}", if *cos { "C" } else { "S" }, self.indices(&j))
            }
            F::Qd(i) | F::Qdd(i) => {
                let letter = self.joint_letter(*i);
                let idx = self.indices(&[usize::from(*i)]);
                match (matches!(f, F::Qdd(_)), self.latex()) {
                    (false, true) => format!("\\dot{{{letter}}}{idx}"),
                    (true, true) => format!("\\ddot{{{letter}}}{idx}"),
                    (false, false) => format!("{letter}\u{307}{idx}"),
                    (true, false) => format!("{letter}\u{308}{idx}"),
                }
            }
        }
    }

    /// A sum of terms.
    fn sum(&self, terms: &[Term]) -> String {
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
        if !abs.is_one() || (t.group.is_empty() && t.factors.is_empty()) {
            parts.push(self.number(abs));
        }
        if !t.group.is_empty() {
            let inner = self.sum(&t.group);
            parts.push(if self.latex() {
                format!("\\left({inner}\\right)")
            } else {
                format!("({inner})")
            });
        }
        let mut factors: Vec<&(F, u32)> = t.factors.iter().collect();
        factors.sort_by_key(|(f, _)| person_order(f));
        for (f, e) in factors {
            parts.push(self.power(self.factor(f), *e));
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
}

/// Masses first, then gravity, then the rest by name, as the book writes `m2 g l2 C12`.
fn person_order(f: &F) -> (u8, &F) {
    let rank = match f {
        F::Param(p) if p.starts_with('m') => 0,
        F::Param(p) if p == "g" => 1,
        _ => 2,
    };
    (rank, f)
}

/// Denominators the book writes as fractions: 2, 3, 4, 6, 12, … (only factors 2 and 3).
fn is_small_fraction(mut d: i128) -> bool {
    if d > 48 {
        return false;
    }
    for p in [2, 3] {
        while d % p == 0 {
            d /= p;
        }
    }
    d == 1
}

/// A number as a short decimal: exact where it has at most 8 decimals, else 6 significant
/// digits.
fn decimal(x: Number) -> String {
    if let Number::Rational(_, mut d) = x {
        let mut places = 0;
        let (mut twos, mut fives) = (0, 0);
        while d % 2 == 0 {
            d /= 2;
            twos += 1;
        }
        while d % 5 == 0 {
            d /= 5;
            fives += 1;
        }
        places = places.max(twos).max(fives);
        if d == 1 && places <= 8 {
            return trim(format!("{:.*}", places, x.to_f64()));
        }
    }
    let v = x.to_f64();
    if v == 0.0 {
        return "0".into();
    }
    let exponent = v.abs().log10().floor();
    if (-4.0..6.0).contains(&exponent) {
        // 6 significant digits
        let places = (5.0 - exponent).max(0.0) as usize;
        trim(format!("{v:.places$}"))
    } else {
        let s = format!("{v:.5e}");
        match s.split_once('e') {
            Some((mantissa, exp)) => format!("{}e{exp}", trim(mantissa.to_string())),
            None => s,
        }
    }
}

fn trim(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
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

/// One printed equation: its names (`D12 = D21`) and its right-hand side, `None` when it was
/// too large to expand.
struct Entry {
    labels: Vec<String>,
    value: Option<Vec<Term>>,
}

struct Section {
    title: &'static str,
    entries: Vec<Entry>,
}

/// The equations of motion of a robot, ready to print.
pub struct Inspection {
    name: String,
    kinds: Vec<JointKind>,
    offsets: bool,
    sections: Vec<Section>,
    limits: Limits,
}

/// Label text for `letter` with joint indices (0-based) in `format`.
fn label(printer: &Printer<'_>, letter: &str, joints: &[usize]) -> String {
    format!("{letter}{}", printer.indices(joints))
}

/// Expands and arranges every output of `eq` within `limits`.
#[must_use]
pub fn inspect(eq: &Equations, robot: &Robot, limits: Limits) -> Inspection {
    let mut x = Expander::new(eq, limits);
    let n = eq.dof;
    let actuated: Vec<bool> = robot
        .joints
        .iter()
        .map(|j| !j.actuator_inertia.is_zero())
        .collect();
    let mut sections = Vec::new();
    // Cheapest first, so that what fits the limits is printed.
    let gravity = (0..n)
        .map(|i| Entry {
            labels: vec![format!("D{}", i)],
            value: x.terms(eq.gravity[i]),
        })
        .collect();
    let mut mass = Vec::new();
    for (i, &has_actuator) in actuated.iter().enumerate() {
        for j in i..n {
            let mut labels = vec![format!("D{i},{j}")];
            if j != i {
                labels.push(format!("D{j},{i}"));
            } else if has_actuator {
                labels[0] = format!("D{i},{i}+act");
            }
            mass.push(Entry {
                labels,
                value: x.terms(eq.mass[i][j]),
            });
        }
    }
    let mut christoffel = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in j..n {
                let mut labels = vec![format!("D{i},{j},{k}")];
                if k != j {
                    labels.push(format!("D{i},{k},{j}"));
                }
                christoffel.push(Entry {
                    labels,
                    value: x.terms(eq.christoffel[i][j][k]),
                });
            }
        }
    }
    let mut coriolis = Vec::new();
    for i in 0..n {
        for j in 0..n {
            coriolis.push(Entry {
                labels: vec![format!("C{i},{j}")],
                value: x.terms(eq.coriolis[i][j]),
            });
        }
    }
    let tau = (0..n)
        .map(|i| Entry {
            labels: vec![format!("T{i}")],
            value: x.terms(eq.tau[i]),
        })
        .collect();
    sections.push(Section {
        title: "mass",
        entries: mass,
    });
    sections.push(Section {
        title: "christoffel",
        entries: christoffel,
    });
    sections.push(Section {
        title: "coriolis",
        entries: coriolis,
    });
    sections.push(Section {
        title: "gravity",
        entries: gravity,
    });
    sections.push(Section {
        title: "tau",
        entries: tau,
    });
    Inspection {
        name: robot.name.clone(),
        kinds: eq.kinds.clone(),
        offsets: eq.angle_offsets.iter().any(Option::is_some),
        sections,
        limits,
    }
}

/// Parses the internal label `D0,1` / `D0,0+act` into its letter, 0-based indices and whether
/// the actuator inertia is added.
fn parse_label(l: &str) -> (&str, Vec<usize>, bool) {
    let (letter, rest) = l.split_at(1);
    let (rest, act) = match rest.strip_suffix("+act") {
        Some(r) => (r, true),
        None => (rest, false),
    };
    let idx = rest.split(',').filter_map(|s| s.parse().ok()).collect();
    (letter, idx, act)
}

impl Inspection {
    /// Whether every equation fitted the limits.
    #[must_use]
    pub fn complete(&self) -> bool {
        self.sections
            .iter()
            .all(|s| s.entries.iter().all(|e| e.value.is_some()))
    }

    /// The equations in `format`.
    #[must_use]
    pub fn render(&self, format: Format) -> String {
        let p = Printer {
            format,
            kinds: &self.kinds,
        };
        let latex = format == Format::Latex;
        let mut out = String::new();
        let n = self.kinds.len();
        let joints: Vec<String> = (0..n)
            .map(|i| {
                let var = if self.kinds[i] == JointKind::Prismatic {
                    "d"
                } else if latex {
                    "\\theta"
                } else {
                    "θ"
                };
                format!("{var}{}", p.indices(&[i]))
            })
            .collect();
        let (comment, eqsign) = if latex { ("% ", " &= ") } else { ("", " = ") };
        let _ = writeln!(
            out,
            "{comment}{}: equations of motion in the notation of Niku, Introduction to Robotics, ch. 6",
            self.name
        );
        let _ = writeln!(out, "{comment}joint variables {}", joints.join(", "));
        let _ = writeln!(
            out,
            "{comment}Si = sin θi, Ci = cos θi, S12 = sin(θ1 + θ2), C12 = cos(θ1 + θ2), …; θ̇, θ̈: velocity, acceleration"
        );
        if self.offsets {
            let _ = writeln!(
                out,
                "{comment}θi in Si, Ci includes the joint's constant offset where it is not a multiple of 90°"
            );
        }
        for section in &self.sections {
            let title = match section.title {
                "mass" => "Inertia D_ij (eq. 6.43); M = D with the actuator inertia I_i(act) on the diagonal (6.39)",
                "christoffel" => "Centripetal and Coriolis coefficients D_ijk (eq. 6.44; D_ijk = D_ikj)",
                "coriolis" => "Coriolis matrix C_ij = Σ_k D_ijk θ̇_k",
                "gravity" => "Gravity D_i (eq. 6.45), with joint springs",
                _ => "Joint torques and forces T_i (eq. 6.46)",
            };
            out.push('\n');
            if latex {
                let _ = writeln!(out, "% {title}\n\\begin{{align*}}");
            } else {
                let _ = writeln!(out, "{title}:");
            }
            let too_large = section.entries.iter().any(|e| e.value.is_none());
            if too_large {
                let msg = format!(
                    "too large to print here (over {} terms or {} term operations): the `dynamics inspect` command prints it",
                    self.limits.max_terms, self.limits.max_work
                );
                if latex {
                    let _ = writeln!(out, "&\\text{{{msg}}}");
                } else {
                    let _ = writeln!(out, "  {msg}");
                }
            } else {
                let last = section.entries.len().saturating_sub(1);
                for (k, e) in section.entries.iter().enumerate() {
                    let names: Vec<String> = e
                        .labels
                        .iter()
                        .map(|l| {
                            let (letter, idx, act) = parse_label(l);
                            let base = label(&p, letter, &idx);
                            match (act, latex) {
                                (false, _) => base,
                                (true, true) => {
                                    format!("{base} + I{}(\\mathrm{{act}})", p.indices(&idx[..1]))
                                }
                                (true, false) => format!("{base} + I{}(act)", idx[0] + 1),
                            }
                        })
                        .collect();
                    let value = e.value.as_deref().unwrap_or(&[]);
                    let rhs = if latex {
                        latex_lines(&p, value)
                    } else {
                        p.sum(value)
                    };
                    if latex {
                        let end = if k == last { "" } else { " \\\\" };
                        let _ = writeln!(out, "{}{eqsign}{rhs}{end}", names.join(" = "));
                    } else {
                        let _ = writeln!(out, "  {}{eqsign}{rhs}", names.join(" = "));
                    }
                }
            }
            if latex {
                let _ = writeln!(out, "\\end{{align*}}");
            }
        }
        out
    }
}

/// A LaTeX sum broken into lines of four terms inside `align*`.
fn latex_lines(p: &Printer<'_>, terms: &[Term]) -> String {
    let mut s = String::new();
    for (k, chunk) in terms.chunks(4).enumerate() {
        let part = p.sum(chunk);
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

#[cfg(test)]
mod tests {
    use super::{arrange, fold_trig, Format, Mono, Printer, F};
    use crate::algo::JointKind;
    use crate::poly::{Poly, Sym};
    use crate::symbolic::Number;
    use std::collections::BTreeMap;

    /// The readable text of a polynomial written in `Poly::parse` syntax.
    fn readable(text: &str, format: Format) -> String {
        let p = Poly::parse(text).unwrap();
        let mut terms: BTreeMap<Mono, Number> = BTreeMap::new();
        for (m, c) in p.terms() {
            let mono = m
                .iter()
                .map(|(s, e)| {
                    let f = match s {
                        Sym::Param(p) => F::Param(p.clone()),
                        Sym::Cos(i) | Sym::Sin(i) => F::Trig {
                            cos: matches!(s, Sym::Cos(_)),
                            joints: vec![*i],
                        },
                        Sym::Q(i) => F::Q(*i),
                        Sym::Qd(i) => F::Qd(*i),
                        Sym::Qdd(i) => F::Qdd(*i),
                    };
                    (f, *e)
                })
                .collect();
            terms.insert(mono, c);
        }
        fold_trig(&mut terms, &mut |_| Some(())).unwrap();
        let kinds = [
            JointKind::Revolute,
            JointKind::Prismatic,
            JointKind::Revolute,
        ];
        let p = Printer {
            format,
            kinds: &kinds,
        };
        p.sum(&arrange(terms.into_iter().collect()))
    }

    macro_rules! reads {
        ($($a:literal => $b:literal),* $(,)?) => {$(
            assert_eq!(readable($a, Format::Text), $b, "{}", $a);
        )*};
    }

    #[test]
    fn sums_of_angles_fold() {
        reads! {
            "C12" => "C12",
            "S12" => "S12",
            "C13" => "C13",
            "2*S12 - C1*C2" => "2 S12 - C1 C2",
            "a*C1*C2 - a*S1*S2 + b*S1*S2" => "b S1 S2 + a C12",
            "3*C1*C2 - 2*S1*S2" => "C1 C2 + 2 C12",
            "m*C12*C3 - m*S12*S3" => "m C123",
        }
    }

    #[test]
    fn grouping_and_common_factors() {
        reads! {
            // accelerations first, then velocities, then gravity with its common factor out
            "m*g*l*C1/2 + M*g*l*C1 + qdd1*a*C3 + qdd1*b + qd3^2*c*S3" =>
                "(b + a C3) θ̈1 + c S3 θ̇3² + (M + 1/2 m) g l C1",
            "-a*qd1*qd3 - b*C3*qd1*qd3" => "-(a + b C3) θ̇1 θ̇3",
            "0" => "0",
            "-1/2*m2*l1*l2*S3*qd1^2" => "-1/2 m2 l1 l2 S3 θ̇1²",
            "k*q2*qd2" => "k d2 d\u{307}2",
            // a prismatic position stays inside its sine's or cosine's group (Niku 6.14)
            "m1*g*l1*C1/2 + m2*g*q2*C1" => "(1/2 m1 l1 + m2 d2) g C1",
            "0.4318*17.4*C1 + 1/3" => "1/3 + 7.51332 C1",
            "x/7" => "0.142857 x",
            "0.0000584640*x" => "5.8464e-5 x",
        }
    }

    #[test]
    fn latex() {
        assert_eq!(
            readable("-1/2*m2*l1*l2*S3*qd1^2 + I1act*qdd1 + payload*C12", Format::Latex),
            "I_{1act} \\ddot{\\theta}_{1} - \\frac{1}{2} m_{2} l_{1} l_{2} S_{3} \\dot{\\theta}_{1}^{2} + \\mathit{payload} C_{12}"
        );
    }
}

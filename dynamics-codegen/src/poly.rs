//! A canonical form for closed forms: sparse polynomials in `sin q_i` (`S1`), `cos q_i` (`C1`),
//! prismatic positions, velocities, accelerations and parameters, with exact rational
//! coefficients and `S_i²` rewritten as `1 − C_i²`. Two expressions are equal exactly when their
//! canonical forms are. For display and tests on small robots; code is emitted from the graph.

use crate::symbolic::{Graph, Node, NodeId, Number, Var};
use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg};

/// A variable of a polynomial.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Sym {
    /// A parameter (struct field) by name.
    Param(String),
    /// `cos q_i` (0-based).
    Cos(u16),
    /// `sin q_i`.
    Sin(u16),
    /// `q_i` of a prismatic joint.
    Q(u16),
    /// `q̇_i`.
    Qd(u16),
    /// `q̈_i`.
    Qdd(u16),
}

impl Sym {
    /// The variable of a graph input; `fields` names the parameters (`None` for an unknown
    /// one).
    #[must_use]
    pub fn of(v: Var, fields: &[String]) -> Option<Sym> {
        Some(match v {
            Var::Q(i) => Sym::Q(i),
            Var::SinQ(i) => Sym::Sin(i),
            Var::CosQ(i) => Sym::Cos(i),
            Var::Qd(i) => Sym::Qd(i),
            Var::Qdd(i) => Sym::Qdd(i),
            Var::Param(k) => Sym::Param(fields.get(usize::from(k))?.clone()),
        })
    }
}

type Monomial = Vec<(Sym, u32)>;

/// A polynomial with exact coefficients.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Poly {
    terms: BTreeMap<Monomial, Number>,
}

impl Poly {
    /// The constant `c`.
    #[must_use]
    pub fn constant(c: Number) -> Poly {
        let mut p = Poly::default();
        if !c.is_zero() {
            p.terms.insert(Vec::new(), c);
        }
        p
    }

    /// The variable `s`.
    #[must_use]
    pub fn sym(s: Sym) -> Poly {
        let mut p = Poly::default();
        p.terms.insert(vec![(s, 1)], Number::ONE);
        p
    }

    /// Whether the polynomial is zero.
    #[must_use]
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Number of terms.
    #[must_use]
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The terms in canonical order: each monomial (variables with exponents) and its
    /// coefficient.
    pub fn terms(&self) -> impl Iterator<Item = (&[(Sym, u32)], Number)> + '_ {
        self.terms.iter().map(|(m, c)| (m.as_slice(), *c))
    }

    fn add_term(&mut self, m: Monomial, c: Number) {
        let entry = self.terms.entry(m).or_insert(Number::ZERO);
        *entry = entry.add(c);
        if entry.is_zero() {
            self.terms.retain(|_, v| !v.is_zero());
        }
    }

    /// `self + o`.
    #[must_use]
    pub fn add(&self, o: &Poly) -> Poly {
        let mut r = self.clone();
        for (m, c) in &o.terms {
            r.add_term(m.clone(), *c);
        }
        r
    }

    /// `k · self`.
    #[must_use]
    pub fn scale(&self, k: Number) -> Poly {
        let mut r = Poly::default();
        if k.is_zero() {
            return r;
        }
        for (m, c) in &self.terms {
            r.terms.insert(m.clone(), c.mul(k));
        }
        r
    }

    /// `self − o`.
    #[must_use]
    pub fn sub(&self, o: &Poly) -> Poly {
        self.add(&o.scale(Number::MINUS_ONE))
    }

    /// `self · o`, with `S_i² = 1 − C_i²`.
    #[must_use]
    pub fn mul(&self, o: &Poly) -> Poly {
        let mut r = Poly::default();
        for (ma, ca) in &self.terms {
            for (mb, cb) in &o.terms {
                let mut m: BTreeMap<Sym, u32> = BTreeMap::new();
                for (s, e) in ma.iter().chain(mb) {
                    *m.entry(s.clone()).or_insert(0) += e;
                }
                for (mono, c) in reduce(m) {
                    r.add_term(mono, c.mul(ca.mul(*cb)));
                }
            }
        }
        r
    }

    /// The canonical form of graph node `id`; `None` where the graph holds a reciprocal or the
    /// sine of a parameter, or the form exceeds `max_terms`.
    #[must_use]
    pub fn from_graph(
        graph: &Graph,
        id: NodeId,
        fields: &[String],
        max_terms: usize,
    ) -> Option<Poly> {
        let live = graph.live(&[id]);
        let mut memo: Vec<Option<Poly>> = vec![None; id.index() + 1];
        for (n, node) in graph.nodes().take(id.index() + 1) {
            if !live[n.index()] {
                continue;
            }
            let get = |x: NodeId| memo[x.index()].clone();
            let p = match node {
                Node::Const(c) => Poly::constant(c),
                Node::Var(v) => Poly::sym(Sym::of(v, fields)?),
                Node::Add(a, b) => get(a)?.add(&get(b)?),
                Node::Mul(a, b) => get(a)?.mul(&get(b)?),
                Node::Neg(a) => get(a)?.scale(Number::MINUS_ONE),
                Node::Recip(_) | Node::Sin(_) | Node::Cos(_) => return None,
            };
            if p.len() > max_terms {
                return None;
            }
            memo[n.index()] = Some(p);
        }
        memo[id.index()].clone()
    }

    /// Parses a polynomial written as a person would, for tests: numbers, `+ − * / ^`,
    /// parentheses, `S1`, `C1`, `S12` (= sin(q1 + q2), expanded), `C12`, `qd1`, `qdd1`, `q1`
    /// (prismatic), and parameter names. Juxtaposition is not multiplication: write `*`.
    ///
    /// # Errors
    /// A message when the text cannot be read.
    pub fn parse(text: &str) -> Result<Poly, String> {
        let tokens = tokenize(text)?;
        let mut pos = 0;
        let p = parse_sum(&tokens, &mut pos)?;
        if pos != tokens.len() {
            return Err(format!("unexpected `{}` in `{text}`", tokens[pos]));
        }
        Ok(p)
    }
}

/// Rewrites `S_i^e` with `e ≥ 2` through `S_i² = 1 − C_i²`.
fn reduce(m: BTreeMap<Sym, u32>) -> Vec<(Monomial, Number)> {
    let mut out: Vec<(BTreeMap<Sym, u32>, Number)> = vec![(m, Number::ONE)];
    let is_square = |(s, e): (&Sym, &u32)| matches!(s, Sym::Sin(_)) && *e >= 2;
    while let Some(pos) = out.iter().position(|(m, _)| m.iter().any(is_square)) {
        let (m, c) = out.swap_remove(pos);
        let Some((&Sym::Sin(i), _)) = m.iter().find(|x| is_square(*x)) else {
            break;
        };
        let mut base = m.clone();
        if let Some(e) = base.get_mut(&Sym::Sin(i)) {
            *e -= 2;
        }
        base.retain(|_, e| *e > 0);
        let mut with_cos = base.clone();
        *with_cos.entry(Sym::Cos(i)).or_insert(0) += 2;
        out.push((base, c));
        out.push((with_cos, -c));
    }
    out.into_iter()
        .map(|(m, c)| (m.into_iter().collect(), c))
        .collect()
}

fn tokenize(text: &str) -> Result<Vec<String>, String> {
    let mut tokens = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_alphanumeric() || c == '_' || c == '.' {
            let start = i;
            while i < chars.len()
                && (chars[i].is_ascii_alphanumeric() || chars[i] == '_' || chars[i] == '.')
            {
                i += 1;
            }
            tokens.push(chars[start..i].iter().collect());
        } else if "+-*/^()".contains(c) {
            tokens.push(c.to_string());
            i += 1;
        } else {
            return Err(format!("unexpected character `{c}` in `{text}`"));
        }
    }
    Ok(tokens)
}

fn parse_sum(t: &[String], pos: &mut usize) -> Result<Poly, String> {
    let mut p = parse_product(t, pos)?;
    while *pos < t.len() && (t[*pos] == "+" || t[*pos] == "-") {
        let minus = t[*pos] == "-";
        *pos += 1;
        let r = parse_product(t, pos)?;
        p = if minus { p.sub(&r) } else { p.add(&r) };
    }
    Ok(p)
}

fn parse_product(t: &[String], pos: &mut usize) -> Result<Poly, String> {
    let mut p = parse_power(t, pos)?;
    while *pos < t.len() && (t[*pos] == "*" || t[*pos] == "/") {
        let div = t[*pos] == "/";
        *pos += 1;
        let r = parse_power(t, pos)?;
        p = if div {
            let c = r
                .terms
                .get(&Vec::new())
                .copied()
                .filter(|_| r.len() == 1)
                .ok_or("division by a non-number")?;
            p.scale(c.recip().ok_or("division by zero")?)
        } else {
            p.mul(&r)
        };
    }
    Ok(p)
}

fn parse_power(t: &[String], pos: &mut usize) -> Result<Poly, String> {
    let base = parse_atom(t, pos)?;
    if *pos < t.len() && t[*pos] == "^" {
        *pos += 1;
        let e: u32 = t
            .get(*pos)
            .and_then(|s| s.parse().ok())
            .ok_or("expected an integer exponent")?;
        *pos += 1;
        let mut r = Poly::constant(Number::ONE);
        for _ in 0..e {
            r = r.mul(&base);
        }
        return Ok(r);
    }
    Ok(base)
}

fn joint_sum(digits: &str) -> Option<Vec<u16>> {
    digits
        .chars()
        .map(|d| {
            d.to_digit(10)
                .and_then(|x| u16::try_from(x).ok()?.checked_sub(1))
        })
        .collect()
}

fn parse_atom(t: &[String], pos: &mut usize) -> Result<Poly, String> {
    let tok = t.get(*pos).ok_or("unexpected end")?.clone();
    *pos += 1;
    if tok == "-" {
        return Ok(parse_power(t, pos)?.scale(Number::MINUS_ONE));
    }
    if tok == "(" {
        let p = parse_sum(t, pos)?;
        if t.get(*pos).map(String::as_str) != Some(")") {
            return Err("expected `)`".into());
        }
        *pos += 1;
        return Ok(p);
    }
    if let Some(n) = Number::parse_decimal(&tok) {
        return Ok(Poly::constant(n));
    }
    let index = |prefix: &str| {
        tok.strip_prefix(prefix)
            .and_then(|d| d.parse::<u16>().ok())
            .and_then(|i| i.checked_sub(1))
    };
    if let Some(i) = index("qdd") {
        return Ok(Poly::sym(Sym::Qdd(i)));
    }
    if let Some(i) = index("qd") {
        return Ok(Poly::sym(Sym::Qd(i)));
    }
    if let Some(i) = index("q") {
        return Ok(Poly::sym(Sym::Q(i)));
    }
    for (prefix, is_sin) in [("S", true), ("C", false)] {
        if let Some(joints) = tok
            .strip_prefix(prefix)
            .filter(|d| !d.is_empty())
            .and_then(joint_sum)
        {
            // sin and cos of a sum of joint angles, by the addition formulas
            let (mut s, mut c) = (Poly::constant(Number::ZERO), Poly::constant(Number::ONE));
            for j in joints {
                let (sj, cj) = (Poly::sym(Sym::Sin(j)), Poly::sym(Sym::Cos(j)));
                let ns = s.mul(&cj).add(&c.mul(&sj));
                let nc = c.mul(&cj).sub(&s.mul(&sj));
                s = ns;
                c = nc;
            }
            return Ok(if is_sin { s } else { c });
        }
    }
    if tok
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
    {
        return Ok(Poly::sym(Sym::Param(tok)));
    }
    Err(format!("unexpected `{tok}`"))
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Sym::Param(p) => write!(f, "{p}"),
            Sym::Cos(i) => write!(f, "C{}", i + 1),
            Sym::Sin(i) => write!(f, "S{}", i + 1),
            Sym::Q(i) => write!(f, "q{}", i + 1),
            Sym::Qd(i) => write!(f, "qd{}", i + 1),
            Sym::Qdd(i) => write!(f, "qdd{}", i + 1),
        }
    }
}

impl fmt::Display for Poly {
    /// Terms in canonical order, e.g. `1/3*m1*l^2 + m2*l^2*C2`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        for (k, (m, c)) in self.terms.iter().enumerate() {
            let negative = c.is_negative();
            let abs = if negative { c.neg() } else { *c };
            match (k, negative) {
                (0, true) => write!(f, "-")?,
                (0, false) => {}
                (_, true) => write!(f, " - ")?,
                (_, false) => write!(f, " + ")?,
            }
            let mut parts: Vec<String> = Vec::new();
            if !abs.is_one() || m.is_empty() {
                parts.push(abs.to_string());
            }
            for (s, e) in m {
                parts.push(if *e == 1 {
                    s.to_string()
                } else {
                    format!("{s}^{e}")
                });
            }
            write!(f, "{}", parts.join("*"))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::Poly;

    macro_rules! same {
        ($($a:literal => $b:literal),* $(,)?) => {$(
            assert_eq!(Poly::parse($a).unwrap(), Poly::parse($b).unwrap(), "{} != {}", $a, $b);
        )*};
    }

    #[test]
    fn canonical_forms() {
        same! {
            "S1^2 + C1^2" => "1",
            "C12" => "C1*C2 - S1*S2",
            "S12" => "S1*C2 + C1*S2",
            "(m + m)/2" => "m",
            "1/3*m*l^2 + m*l^2/6" => "m*l^2/2",
            "x - x" => "0",
        }
        assert_eq!(
            Poly::parse("2*m*l^2*C2 - 1/2*g").unwrap().to_string(),
            "-1/2*g + 2*l^2*m*C2"
        );
    }
}

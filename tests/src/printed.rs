//! The book's printed equations as data: a parser of printed sums
//! (`-1/2 m2 l1 l2 S2 θ̇2² + (1/2 m1 + m2) g l1 C1`, or the generator's `θ2'²`) into
//! [`Term`]s, their expansion into
//! monomials with exact rational coefficients ([`expand`]) and their grouped form ([`form`]),
//! so that `tests/tests/it/readable_book.rs` can compare the generator's readable equations with
//! the book's, blind to the order of terms.

use std::collections::BTreeMap;

// ---------------------------------------------------------------------------------------------
// Exact rationals

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Q(i128, i128);

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

impl Q {
    fn new(n: i128, d: i128) -> Q {
        assert!(d != 0, "zero denominator");
        let g = gcd(n, d).max(1) * d.signum();
        Q(n / g, d / g)
    }
    const ONE: Q = Q(1, 1);
    fn is_zero(self) -> bool {
        self.0 == 0
    }
    fn add(self, o: Q) -> Q {
        Q::new(self.0 * o.1 + o.0 * self.1, self.1 * o.1)
    }
    fn mul(self, o: Q) -> Q {
        Q::new(self.0 * o.0, self.1 * o.1)
    }
    fn neg(self) -> Q {
        Q(-self.0, self.1)
    }
    /// `3`, `1/2`, `7.51332` (exact).
    fn parse(s: &str) -> Q {
        if let Some((n, d)) = s.split_once('/') {
            return Q::new(n.parse().expect(s), d.parse().expect(s));
        }
        match s.split_once('.') {
            Some((i, f)) => {
                let d = 10i128.pow(u32::try_from(f.len()).expect(s));
                Q::new(format!("{i}{f}").parse().expect(s), d)
            }
            None => Q::new(s.parse().expect(s), 1),
        }
    }
}

impl std::fmt::Display for Q {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.1 == 1 {
            write!(f, "{}", self.0)
        } else {
            write!(f, "{}/{}", self.0, self.1)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Printed sums: `-1/2 m2 l1 l2 S2 θ̇2² + (1/2 m1 + m2) g l1 C1`
//
// Time derivatives come in two notations: the book's dots over the letter (`θ̇2`, `ẍ`) and
// the generator's primes after the index (`θ2'`, `x''`). Both parse to the primed name.

/// A printed term: coefficient, groups in parentheses and factors with exponents.
#[derive(Clone, Debug)]
pub struct Term {
    coef: Q,
    groups: Vec<Vec<Term>>,
    factors: BTreeMap<String, u32>,
}

pub type Mono = BTreeMap<String, u32>;

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Open,
    Close,
    Plus,
    Minus,
    Word(String),
}

fn tokens(text: &str) -> Vec<Token> {
    // Letters with a precomposed dot as letter + combining dot, which `primed` rewrites.
    let text = text
        .replace('ẋ', "x\u{307}")
        .replace('ẍ', "x\u{308}")
        .replace('ṙ', "r\u{307}")
        .replace('ḋ', "d\u{307}")
        .replace('−', "-");
    let mut out = Vec::new();
    let mut word = String::new();
    for c in text.chars() {
        let t = match c {
            '(' | '[' => Some(Token::Open),
            ')' | ']' => Some(Token::Close),
            '+' => Some(Token::Plus),
            '-' => Some(Token::Minus),
            _ => None,
        };
        if t.is_some() || c.is_whitespace() {
            if !word.is_empty() {
                out.push(Token::Word(std::mem::take(&mut word)));
            }
            out.extend(t);
        } else {
            word.push(c);
        }
    }
    if !word.is_empty() {
        out.push(Token::Word(word));
    }
    out
}

struct Parser {
    tokens: Vec<Token>,
    at: usize,
    text: String,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }

    fn sum(&mut self) -> Vec<Term> {
        let mut terms = Vec::new();
        let mut sign = Q::ONE;
        if self.peek() == Some(&Token::Minus) {
            sign = sign.neg();
            self.at += 1;
        }
        loop {
            let mut t = self.term();
            t.coef = t.coef.mul(sign);
            terms.push(t);
            match self.peek() {
                Some(Token::Plus) => sign = Q::ONE,
                Some(Token::Minus) => sign = Q::ONE.neg(),
                _ => break,
            }
            self.at += 1;
        }
        terms
    }

    fn term(&mut self) -> Term {
        let mut t = Term {
            coef: Q::ONE,
            groups: Vec::new(),
            factors: BTreeMap::new(),
        };
        let start = self.at;
        while let Some(tok) = self.peek().cloned() {
            match tok {
                Token::Open => {
                    self.at += 1;
                    let g = self.sum();
                    assert_eq!(
                        self.peek(),
                        Some(&Token::Close),
                        "unclosed in {}",
                        self.text
                    );
                    self.at += 1;
                    t.groups.push(g);
                }
                Token::Word(w) => {
                    self.at += 1;
                    if w.starts_with(|c: char| c.is_ascii_digit()) {
                        t.coef = t.coef.mul(Q::parse(&w));
                    } else {
                        let (base, e) = power(&w);
                        *t.factors.entry(base).or_insert(0) += e;
                    }
                }
                _ => break,
            }
        }
        assert!(self.at > start, "empty term in {}", self.text);
        t
    }
}

/// A dotted name in primes: `θ̇2` → `θ2'`, `x\u{308}` → `x''`; primed names unchanged.
fn primed(name: &str) -> String {
    let order: usize = name
        .chars()
        .map(|c| match c {
            '\u{307}' => 1,
            '\u{308}' => 2,
            _ => 0,
        })
        .sum();
    let plain: String = name
        .chars()
        .filter(|c| !matches!(c, '\u{307}' | '\u{308}'))
        .collect();
    assert!(
        order == 0 || !plain.contains('\''),
        "dots and primes in {name}"
    );
    plain + &"'".repeat(order)
}

/// `l1²` → (`l1`, 2), `θ̇2²` → (`θ2'`, 2).
fn power(w: &str) -> (String, u32) {
    let base = w.trim_end_matches(|c| SUPERSCRIPTS.contains(&c));
    let sup = &w[base.len()..];
    let base = primed(base);
    if sup.is_empty() {
        return (base, 1);
    }
    let digits: String = sup
        .chars()
        .map(|c| {
            let d = SUPERSCRIPTS
                .iter()
                .position(|&s| s == c)
                .expect("superscript");
            char::from(b'0' + u8::try_from(d).expect("digit"))
        })
        .collect();
    (base, digits.parse().expect("exponent"))
}

pub fn parse(text: &str) -> Vec<Term> {
    let mut p = Parser {
        tokens: tokens(text),
        at: 0,
        text: text.to_string(),
    };
    let s = p.sum();
    assert_eq!(p.at, p.tokens.len(), "trailing tokens in {text}");
    s
}

/// Renames factors (the book's variables to the generator's), with their derivatives:
/// `("x", "d1")` also renames `x'` to `d1'` and `x''` to `d1''`.
pub fn rename(terms: &mut [Term], names: &[(&str, &str)]) {
    for t in terms {
        t.factors = std::mem::take(&mut t.factors)
            .into_iter()
            .map(|(f, e)| {
                let base = f.trim_end_matches('\'');
                let primes = &f[base.len()..];
                let f = names
                    .iter()
                    .find(|(from, _)| *from == base)
                    .map_or(f.clone(), |(_, to)| format!("{to}{primes}"));
                (f, e)
            })
            .fold(BTreeMap::new(), |mut m, (f, e)| {
                *m.entry(f).or_insert(0) += e;
                m
            });
        for g in &mut t.groups {
            rename(g, names);
        }
    }
}

/// The sum expanded into monomials with their coefficients, zeros dropped.
pub fn expand(terms: &[Term]) -> BTreeMap<Mono, Q> {
    let mut out: BTreeMap<Mono, Q> = BTreeMap::new();
    for t in terms {
        let mut acc: BTreeMap<Mono, Q> = BTreeMap::from([(t.factors.clone(), t.coef)]);
        for g in &t.groups {
            let g = expand(g);
            let mut next: BTreeMap<Mono, Q> = BTreeMap::new();
            for (ma, ca) in &acc {
                for (mb, cb) in &g {
                    let mut m = ma.clone();
                    for (f, e) in mb {
                        *m.entry(f.clone()).or_insert(0) += e;
                    }
                    let c = next.entry(m).or_insert(Q(0, 1));
                    *c = c.add(ca.mul(*cb));
                }
            }
            acc = next;
        }
        for (m, c) in acc {
            let e = out.entry(m).or_insert(Q(0, 1));
            *e = e.add(c);
        }
    }
    out.retain(|_, c| !c.is_zero());
    out
}

/// The sum as printed, with every group's terms (and the sum's) in a canonical order.
pub fn form(terms: &[Term]) -> Vec<String> {
    let mut out: Vec<String> = terms
        .iter()
        .filter(|t| !t.coef.is_zero())
        .map(|t| {
            let mut groups: Vec<String> = t
                .groups
                .iter()
                .map(|g| format!("({})", form(g).join(" + ")))
                .collect();
            groups.sort();
            let factors: Vec<String> = t.factors.iter().map(|(f, e)| format!("{f}^{e}")).collect();
            format!("{} {} {}", t.coef, groups.join(" "), factors.join(" "))
        })
        .collect();
    out.sort();
    out
}

pub fn show(m: &BTreeMap<Mono, Q>) -> String {
    let terms: Vec<String> = m
        .iter()
        .map(|(m, c)| {
            let f: Vec<String> = m.iter().map(|(f, e)| format!("{f}^{e}")).collect();
            format!("{c} {}", f.join(" "))
        })
        .collect();
    terms.join("\n    ")
}

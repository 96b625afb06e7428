//! Trajectories as streams of samples `(t, q, q̇, q̈)`: read from a CSV file, or a built-in
//! quintic point-to-point move.
//!
//! **CSV.** A header line names the columns: `t,q1,..,qn`, then optionally `qd1,..,qdn`, then
//! optionally `qdd1,..,qddn` (t in s; q in rad or m). Blank lines and lines starting with `#`
//! are skipped; every other line holds as many finite numbers as the header, with t strictly
//! increasing.
//!
//! **Missing derivatives** come from the quadratic through three neighbouring samples (central
//! differences on non-uniform time, second order): at `t_1` between `t_0` and `t_2`,
//! `ẋ_1 = Σ_k L_k'(t_1) x_k` and `ẍ_1 = Σ_k L_k'' x_k` with `L_k` the Lagrange basis of
//! `t_0, t_1, t_2`; the first and the last sample take the same quadratic's derivatives at their
//! own time. q̈ is differentiated from q̇ when the file gives q̇, else from q directly. Only three
//! samples are held at once, so a file of any length streams.
//!
//! **Quintic move.** `q(t) = q_0 + (q_f − q_0)(10 s³ − 15 s⁴ + 6 s⁵)`, `s = t / T`: rest to rest
//! with zero acceleration at both ends (the fifth-order polynomial of trajectory planning).

use std::collections::VecDeque;
use std::io::BufRead;

/// One sample of a trajectory.
#[derive(Clone, Debug, Default)]
pub struct Sample {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
}

/// A CSV error: the line (1-based) and, for a value, its column (1-based) and name.
#[derive(Debug, PartialEq)]
pub struct CsvError {
    pub line: usize,
    pub column: Option<(usize, String)>,
    pub message: String,
}

impl std::fmt::Display for CsvError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.column {
            Some((c, name)) => write!(
                f,
                "line {}, column {c} ({name}): {}",
                self.line, self.message
            ),
            None => write!(f, "line {}: {}", self.line, self.message),
        }
    }
}

/// Which derivatives a file gives.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Given {
    Positions,
    Velocities,
    Accelerations,
}

/// The header's expected names, for `n` joints and what is given.
fn header_names(n: usize, given: Given) -> Vec<String> {
    let mut names = vec!["t".to_string()];
    let groups: &[&str] = match given {
        Given::Positions => &["q"],
        Given::Velocities => &["q", "qd"],
        Given::Accelerations => &["q", "qd", "qdd"],
    };
    for g in groups {
        names.extend((1..=n).map(|i| format!("{g}{i}")));
    }
    names
}

fn parse_header(line: usize, text: &str, n: usize) -> Result<Given, CsvError> {
    let found: Vec<&str> = text.split(',').map(str::trim).collect();
    let given = match found.len() {
        k if k == 1 + n => Given::Positions,
        k if k == 1 + 2 * n => Given::Velocities,
        k if k == 1 + 3 * n => Given::Accelerations,
        k => {
            return Err(CsvError {
                line,
                column: None,
                message: format!(
                    "the header has {k} columns; the robot has {n} joints: expected t,q1..q{n}, \
                     optionally qd1..qd{n} and qdd1..qdd{n} ({}, {} or {} columns)",
                    1 + n,
                    1 + 2 * n,
                    1 + 3 * n
                ),
            })
        }
    };
    for (c, (want, got)) in header_names(n, given).iter().zip(&found).enumerate() {
        if want != got {
            return Err(CsvError {
                line,
                column: Some((c + 1, (*got).to_string())),
                message: format!("expected the header name `{want}`"),
            });
        }
    }
    Ok(given)
}

/// The values of one data line, checked: count, finite numbers, time after `previous`.
fn parse_row(
    line: usize,
    text: &str,
    names: &[String],
    previous: Option<f64>,
) -> Result<Vec<f64>, CsvError> {
    let fields: Vec<&str> = text.split(',').collect();
    if fields.len() != names.len() {
        return Err(CsvError {
            line,
            column: None,
            message: format!(
                "{} values; the header has {} columns",
                fields.len(),
                names.len()
            ),
        });
    }
    let mut row = Vec::with_capacity(fields.len());
    for (c, field) in fields.iter().enumerate() {
        let at = || Some((c + 1, names[c].clone()));
        let value: f64 = field.trim().parse().map_err(|_| CsvError {
            line,
            column: at(),
            message: format!("`{}` is not a number", field.trim()),
        })?;
        if !value.is_finite() {
            return Err(CsvError {
                line,
                column: at(),
                message: format!("`{}` is not a finite number", field.trim()),
            });
        }
        row.push(value);
    }
    if let Some(before) = previous.filter(|&p| row[0] <= p) {
        return Err(CsvError {
            line,
            column: Some((1, "t".into())),
            message: format!("time does not increase: {} after {before}", row[0]),
        });
    }
    Ok(row)
}

/// Reads the trajectory of an `n`-joint robot from `reader`, calling `each` on every sample in
/// order, and `progress` with the count of bytes read every so often; the number of samples
/// and how their derivatives were had.
///
/// # Errors
/// The first bad line, or fewer than three samples where derivatives must be estimated.
pub fn read_csv(
    reader: impl BufRead,
    n: usize,
    mut each: impl FnMut(&Sample),
    mut progress: impl FnMut(u64),
) -> Result<(usize, &'static str), CsvError> {
    let mut given = None;
    let mut names = Vec::new();
    let mut window = Window::new(n);
    let (mut bytes, mut previous, mut last_line) = (0u64, None, 0);
    for (index, text) in reader.lines().enumerate() {
        let line = index + 1;
        last_line = line;
        let text = text.map_err(|e| CsvError {
            line,
            column: None,
            message: e.to_string(),
        })?;
        bytes += text.len() as u64 + 1;
        if index % 4096 == 0 {
            progress(bytes);
        }
        let trimmed = text.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        if given.is_none() {
            let g = parse_header(line, trimmed, n)?;
            (given, names, window.given) = (Some(g), header_names(n, g), g);
            continue;
        }
        let row = parse_row(line, trimmed, &names, previous)?;
        previous = Some(row[0]);
        window.push(row, &mut each);
    }
    if given.is_none() {
        return Err(CsvError {
            line: last_line.max(1),
            column: None,
            message: "no header: expected t,q1..qn".into(),
        });
    }
    let count = window.finish(&mut each).map_err(|message| CsvError {
        line: last_line,
        column: None,
        message,
    })?;
    let method = match window.given {
        Given::Positions => "q̇ and q̈ by central differences",
        Given::Velocities => "q̈ by central differences of q̇",
        Given::Accelerations => "q̇ and q̈ given",
    };
    Ok((count, method))
}

/// The last three rows, for derivatives by the quadratic through them.
struct Window {
    n: usize,
    rows: VecDeque<Vec<f64>>,
    given: Given,
    count: usize,
    sample: Sample,
}

impl Window {
    fn new(n: usize) -> Window {
        Window {
            n,
            rows: VecDeque::with_capacity(3),
            given: Given::Positions,
            count: 0,
            sample: Sample {
                t: 0.0,
                q: vec![0.0; n],
                qd: vec![0.0; n],
                qdd: vec![0.0; n],
            },
        }
    }

    fn push(&mut self, row: Vec<f64>, each: &mut impl FnMut(&Sample)) {
        self.count += 1;
        if self.given == Given::Accelerations {
            let n = self.n;
            self.sample.t = row[0];
            self.sample.q.copy_from_slice(&row[1..=n]);
            self.sample.qd.copy_from_slice(&row[n + 1..=2 * n]);
            self.sample.qdd.copy_from_slice(&row[2 * n + 1..]);
            each(&self.sample);
            return;
        }
        if self.rows.len() == 3 {
            self.rows.pop_front();
        }
        self.rows.push_back(row);
        if self.rows.len() == 3 {
            if self.count == 3 {
                self.emit(0, each);
            }
            self.emit(1, each);
        }
    }

    fn finish(&mut self, each: &mut impl FnMut(&Sample)) -> Result<usize, String> {
        if self.count == 0 {
            return Err("no samples after the header".into());
        }
        if self.given != Given::Accelerations {
            if self.count < 3 {
                return Err(format!(
                    "{} samples: estimating q̇ and q̈ takes at least 3 (or give the qd and qdd \
                     columns)",
                    self.count
                ));
            }
            self.emit(2, each);
        }
        Ok(self.count)
    }

    /// Sample `k` of the window, with the derivatives of the quadratic through the window.
    fn emit(&mut self, k: usize, each: &mut impl FnMut(&Sample)) {
        let n = self.n;
        let t = [self.rows[0][0], self.rows[1][0], self.rows[2][0]];
        let (first, second) = lagrange_derivatives(t, t[k]);
        let s = &mut self.sample;
        s.t = t[k];
        s.q.copy_from_slice(&self.rows[k][1..=n]);
        for j in 0..n {
            let x = [
                self.rows[0][1 + j],
                self.rows[1][1 + j],
                self.rows[2][1 + j],
            ];
            match self.given {
                Given::Positions => {
                    s.qd[j] = dot(first, x);
                    s.qdd[j] = dot(second, x);
                }
                _ => {
                    let v = [
                        self.rows[0][1 + n + j],
                        self.rows[1][1 + n + j],
                        self.rows[2][1 + n + j],
                    ];
                    s.qd[j] = v[k];
                    s.qdd[j] = dot(first, v);
                }
            }
        }
        each(s);
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The weights of the first and second derivative at `x` of the quadratic through
/// `(t_k, x_k)`: `L_k'(x)` and `L_k''`.
pub fn lagrange_derivatives(t: [f64; 3], x: f64) -> ([f64; 3], [f64; 3]) {
    let mut first = [0.0; 3];
    let mut second = [0.0; 3];
    for k in 0..3 {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let denominator = (t[k] - t[i]) * (t[k] - t[j]);
        first[k] = ((x - t[i]) + (x - t[j])) / denominator;
        second[k] = 2.0 / denominator;
    }
    (first, second)
}

/// The quintic rest-to-rest move from `from` to `to` in `duration` seconds, `samples` samples
/// evenly spaced (both ends included), each passed to `each`.
pub fn quintic(
    from: &[f64],
    to: &[f64],
    duration: f64,
    samples: usize,
    mut each: impl FnMut(&Sample),
) {
    let n = from.len();
    let mut s = Sample {
        t: 0.0,
        q: vec![0.0; n],
        qd: vec![0.0; n],
        qdd: vec![0.0; n],
    };
    let last = samples.max(2) - 1;
    for k in 0..=last {
        let x = k as f64 / last as f64;
        let shape = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
        let rate = 30.0 * x * x * (1.0 - x) * (1.0 - x) / duration;
        let curvature = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (duration * duration);
        s.t = x * duration;
        for j in 0..n {
            let d = to[j] - from[j];
            s.q[j] = from[j] + d * shape;
            s.qd[j] = d * rate;
            s.qdd[j] = d * curvature;
        }
        each(&s);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str, n: usize) -> Result<Vec<Sample>, CsvError> {
        let mut out = Vec::new();
        read_csv(text.as_bytes(), n, |s| out.push(s.clone()), |_| {})?;
        Ok(out)
    }

    #[test]
    fn quadratics_are_differentiated_exactly_on_uneven_time() {
        // q = 1 + 2t + 3t², at uneven times: q̇ = 2 + 6t, q̈ = 6 everywhere.
        let times = [0.0, 0.1, 0.25, 0.3, 0.7];
        let mut text = String::from("# a comment\nt,q1\n");
        for t in times {
            text += &format!("{t},{}\n\n", 1.0 + 2.0 * t + 3.0 * t * t);
        }
        let samples = read(&text, 1).unwrap();
        assert_eq!(samples.len(), times.len());
        for (s, t) in samples.iter().zip(times) {
            assert_eq!(s.t, t);
            assert!((s.qd[0] - (2.0 + 6.0 * t)).abs() < 1e-9, "{s:?}");
            assert!((s.qdd[0] - 6.0).abs() < 1e-8, "{s:?}");
        }
    }

    #[test]
    fn velocities_given_are_kept_and_differentiated_once() {
        let text = "t,q1,q2,qd1,qd2\n0,0,0,1,0\n1,1,0,3,0\n3,9,0,7,0\n";
        let samples = read(text, 2).unwrap();
        assert_eq!(samples[1].qd, vec![3.0, 0.0]);
        // qd = 1 + 2t: q̈ = 2.
        for s in &samples {
            assert!((s.qdd[0] - 2.0).abs() < 1e-12);
        }
    }

    #[test]
    fn errors_name_the_line_and_column() {
        let cases = [
            (
                "t,q1\n0,1\n1,2,3\n",
                3,
                None,
                "3 values; the header has 2 columns",
            ),
            ("t,q1\n0,1\n1,x\n", 3, Some(2), "`x` is not a number"),
            (
                "t,q1\n0,1\n1,NaN\n",
                3,
                Some(2),
                "`NaN` is not a finite number",
            ),
            (
                "t,q1\n0,1\n0,2\n",
                3,
                Some(1),
                "time does not increase: 0 after 0",
            ),
            ("t,q1,q2,q3,q4\n", 1, None, "the header has 5 columns"),
            ("t,x1\n", 1, Some(2), "expected the header name `q1`"),
            ("t,q1\n0,1\n1,2\n", 3, None, "2 samples"),
        ];
        for (text, line, column, message) in cases {
            let e = read(text, 1).unwrap_err();
            assert_eq!(e.line, line, "{text}");
            assert_eq!(e.column.as_ref().map(|c| c.0), column, "{text}");
            assert!(e.message.starts_with(message), "{text}: {e}");
        }
    }

    #[test]
    fn the_quintic_starts_and_ends_at_rest() {
        let mut out = Vec::new();
        quintic(&[0.0, 1.0], &[1.0, -1.0], 2.0, 101, |s| out.push(s.clone()));
        let (first, last) = (&out[0], &out[100]);
        assert_eq!(
            (first.q.clone(), last.q.clone()),
            (vec![0.0, 1.0], vec![1.0, -1.0])
        );
        assert_eq!(last.t, 2.0);
        for s in [first, last] {
            assert!(s.qd.iter().chain(&s.qdd).all(|x| x.abs() < 1e-12));
        }
        // Peak speed at the middle: 15/8 · Δq / T.
        assert!((out[50].qd[0] - 15.0 / 8.0 / 2.0).abs() < 1e-12);
    }
}

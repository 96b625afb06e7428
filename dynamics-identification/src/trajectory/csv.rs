//! The CSV layer of a trajectory file: the header and the data lines, checked one by one, each
//! error naming its line and, for a value, its column.
//!
//! Lines are read as bytes, at most [`LONGEST_LINE`] of them (a file without line breaks is
//! refused, not held whole), and must be UTF-8 text (else the column of the first byte that is
//! not is named). A byte-order mark before the header, as spreadsheets write, is skipped, and
//! `\r\n` line ends are accepted.

use std::io::{BufRead, Read};

/// The longest line read, in bytes: far more than any robot's line of numbers (16 joints in
/// four groups and a time, each written out in full, 300 digits for the smallest doubles,
/// are 20 kB).
pub const LONGEST_LINE: usize = 1 << 20;

/// A byte-order mark, as some programs start UTF-8 text.
const BYTE_ORDER_MARK: char = '\u{feff}';

/// At most this many characters of a bad value are repeated in its error.
const SHOWN: usize = 40;

/// What a file must hold: the joints' count, whether joint torques end each line, and the base.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Columns {
    pub joints: usize,
    /// `tau1..taun` after the positions and derivatives (`dynamics identify`).
    pub torques: bool,
    pub base: Base,
}

/// The robot's base, which sets the widths of a file's groups of columns.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Base {
    /// `q`, `qd`, `qdd` and `tau` of `n` columns each.
    #[default]
    Fixed,
    /// A free-flying base (Pinocchio's free flyer): `q1..q{n+7}` (`x, y, z, qx, qy, qz, qw`,
    /// then the joints), `v1..v{n+6}` and `a1..a{n+6}` (the base's twist in its frame, then the
    /// joint rates), `tau1..tau{n+6}` (the wrench on the base in its frame, then the joint
    /// torques); with `joint_rows` the torques may be the joints' alone, `tau7..tau{n+6}`.
    Floating { joint_rows: bool },
}

impl Columns {
    /// The count of `q` columns.
    #[must_use]
    pub fn positions(&self) -> usize {
        match self.base {
            Base::Fixed => self.joints,
            Base::Floating { .. } => self.joints + 7,
        }
    }

    /// The count of columns of each derivative (`qd` or `v`, `qdd` or `a`) and of `tau`.
    #[must_use]
    pub fn rates(&self) -> usize {
        match self.base {
            Base::Fixed => self.joints,
            Base::Floating { .. } => self.joints + 6,
        }
    }

    /// The derivatives' names: `qd`, `qdd`, or a floating base's `v`, `a`.
    #[must_use]
    pub fn derivative_names(&self) -> [&'static str; 2] {
        match self.base {
            Base::Fixed => ["qd", "qdd"],
            Base::Floating { .. } => ["v", "a"],
        }
    }

    /// The torques' columns a file may end with, by the number of the first (1-based): every
    /// row's, or with a floating base's `joint_rows` also the joints' alone.
    fn torque_starts(&self) -> &'static [usize] {
        match (self.torques, self.base) {
            (false, _) => &[],
            (true, Base::Floating { joint_rows: true }) => &[1, 7],
            (true, _) => &[1],
        }
    }
}

/// Which derivatives a file gives.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Given {
    #[default]
    Positions,
    Velocities,
    Accelerations,
}

impl Given {
    /// The groups of joint columns after `t`, each of `n` columns.
    pub fn groups(self) -> usize {
        match self {
            Given::Positions => 1,
            Given::Velocities => 2,
            Given::Accelerations => 3,
        }
    }
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
            Some((c, name)) if name.is_empty() => {
                write!(f, "line {}, column {c}: {}", self.line, self.message)
            }
            Some((c, name)) => write!(
                f,
                "line {}, column {c} ({name}): {}",
                self.line, self.message
            ),
            None => write!(f, "line {}: {}", self.line, self.message),
        }
    }
}

/// The header's expected names, for the columns and what is given, the torques from
/// `tau{first}` (1 but for a floating base's joints' rows alone).
pub fn header_names(columns: Columns, given: Given, first: usize) -> Vec<String> {
    let mut names = vec!["t".to_string()];
    names.extend((1..=columns.positions()).map(|i| format!("q{i}")));
    let (rates, [qd, qdd]) = (columns.rates(), columns.derivative_names());
    for g in [qd, qdd].iter().take(given.groups() - 1) {
        names.extend((1..=rates).map(|i| format!("{g}{i}")));
    }
    if columns.torques {
        names.extend((first..=rates).map(|i| format!("tau{i}")));
    }
    names
}

/// What a header of `k` names gives, for these columns: the derivatives, and the number of
/// the first torque's column.
fn layout(line: usize, k: usize, columns: Columns) -> Result<(Given, usize), CsvError> {
    let (nq, nv) = (columns.positions(), columns.rates());
    let starts = columns.torque_starts();
    let width = |g: Given, first: usize| {
        let torques = if columns.torques { nv + 1 - first } else { 0 };
        1 + nq + (g.groups() - 1) * nv + torques
    };
    let layouts = [Given::Positions, Given::Velocities, Given::Accelerations]
        .into_iter()
        .flat_map(|g| {
            starts
                .iter()
                .copied()
                .chain((!columns.torques).then_some(1))
                .map(move |s| (g, s))
        });
    let found = layouts.clone().find(|&(g, s)| k == width(g, s));
    found.ok_or_else(|| {
        let [qd, qdd] = columns.derivative_names();
        let tail: Vec<String> = starts.iter().map(|s| format!("tau{s}..tau{nv}")).collect();
        let (tail, torques) = if columns.torques {
            (format!(", then {}", tail.join(" or ")), " and torques")
        } else {
            (String::new(), "")
        };
        let mut counts: Vec<String> = layouts.map(|(g, s)| width(g, s).to_string()).collect();
        let last = counts.pop().unwrap_or_default();
        let robot = match columns.base {
            Base::Fixed => format!("the robot has {} joints", columns.joints),
            Base::Floating { .. } => format!(
                "the robot has {} joints on a floating base (q: the base's 7, x, y, z, qx, qy, \
                 qz, qw, then the joints'; v, a and tau: the base's 6, then the joints')",
                columns.joints
            ),
        };
        CsvError {
            line,
            column: None,
            message: format!(
                "the header has {k} columns; {robot}: expected t,q1..q{nq}, optionally \
                 {qd}1..{qd}{nv} and {qdd}1..{qdd}{nv}{tail} ({} or {last} columns{torques})",
                counts.join(", ")
            ),
        }
    })
}

/// `x` as a decimal, or with an exponent where the decimal would be long (`1e300`, `1e-5`).
#[must_use]
pub fn decimal(x: f64) -> String {
    if x == 0.0 || (1e-4..1e16).contains(&x.abs()) {
        x.to_string()
    } else {
        format!("{x:e}")
    }
}

/// `text`, or its first [`SHOWN`] characters and an ellipsis.
fn shown(text: &str) -> String {
    match text.char_indices().nth(SHOWN) {
        Some((end, _)) => format!("{}…", &text[..end]),
        None => text.to_string(),
    }
}

/// What the header gives, and its names.
fn parse_header(
    line: usize,
    text: &str,
    columns: Columns,
) -> Result<(Given, Vec<String>), CsvError> {
    let found: Vec<&str> = text.split(',').map(str::trim).collect();
    let (given, first) = layout(line, found.len(), columns)?;
    let names = header_names(columns, given, first);
    for (c, (want, got)) in names.iter().zip(&found).enumerate() {
        if want != got {
            return Err(CsvError {
                line,
                column: Some((c + 1, shown(got))),
                message: format!("expected the header name `{want}`"),
            });
        }
    }
    Ok((given, names))
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
        // The first value too many, or the first missing.
        let (column, name) = match names.get(fields.len()) {
            None => (names.len() + 1, String::new()),
            Some(name) => (fields.len() + 1, name.clone()),
        };
        return Err(CsvError {
            line,
            column: Some((column, name)),
            message: format!(
                "{} value{}; the header has {} columns",
                fields.len(),
                if fields.len() == 1 { "" } else { "s" },
                names.len()
            ),
        });
    }
    let mut row = Vec::with_capacity(fields.len());
    for (c, field) in fields.iter().enumerate() {
        let error = |message: String| CsvError {
            line,
            column: Some((c + 1, names[c].clone())),
            message,
        };
        let field = field.trim();
        if field.is_empty() {
            return Err(error("no value".into()));
        }
        let value: f64 = field
            .parse()
            .map_err(|_| error(format!("`{}` is not a number", shown(field))))?;
        if !value.is_finite() {
            return Err(error(format!("`{}` is not a finite number", shown(field))));
        }
        row.push(value);
    }
    if let Some(before) = previous.filter(|&p| row[0] <= p) {
        return Err(CsvError {
            line,
            column: Some((1, "t".into())),
            message: format!(
                "time does not increase: {} after {}",
                decimal(row[0]),
                decimal(before)
            ),
        });
    }
    Ok(row)
}

/// What a whole file held.
#[derive(Clone, Copy, Debug)]
pub struct Rows {
    pub given: Given,
    /// The file's last line (1-based), where an error about the whole file is placed.
    pub last_line: usize,
}

/// Reads the lines of `reader`, calling `each` with every data line's number and values, in
/// order, and `progress` with the count of bytes read every so often. Blank lines and lines
/// starting with `#` are skipped; the first other line is the header.
///
/// # Errors
/// The first bad line, a file without a header, or the first error of `each`.
pub fn read_rows(
    mut reader: impl BufRead,
    columns: Columns,
    mut each: impl FnMut(usize, Given, Vec<f64>) -> Result<(), CsvError>,
    mut progress: impl FnMut(u64),
) -> Result<Rows, CsvError> {
    let mut header: Option<(Given, Vec<String>)> = None;
    let (mut bytes, mut previous, mut line) = (0u64, None, 0);
    let mut buffer = Vec::new();
    loop {
        buffer.clear();
        let read = next_line(&mut reader, &mut buffer, line + 1)?;
        if read == 0 {
            break;
        }
        line += 1;
        bytes += read as u64;
        if line % 4096 == 1 {
            progress(bytes);
        }
        let names = header.as_ref().map(|(_, names)| names.as_slice());
        let text = utf8(&buffer, line, names)?;
        let text = if line == 1 {
            text.strip_prefix(BYTE_ORDER_MARK).unwrap_or(text)
        } else {
            text
        };
        let trimmed = text.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let Some((given, names)) = &header else {
            header = Some(parse_header(line, trimmed, columns)?);
            continue;
        };
        let row = parse_row(line, trimmed, names, previous)?;
        previous = Some(row[0]);
        each(line, *given, row)?;
    }
    let Some((given, _)) = header else {
        let tail = if columns.torques { ",tau1..taun" } else { "" };
        return Err(CsvError {
            line: line.max(1),
            column: None,
            message: format!("no header: expected t,q1..qn{tail}"),
        });
    };
    Ok(Rows {
        given,
        last_line: line,
    })
}

/// Reads the next line of `reader` (number `line`), its end included, into `buffer`: the
/// bytes read, 0 at the end.
fn next_line(
    reader: &mut impl BufRead,
    buffer: &mut Vec<u8>,
    line: usize,
) -> Result<usize, CsvError> {
    let error = |message: String| CsvError {
        line,
        column: None,
        message,
    };
    let limit = LONGEST_LINE as u64 + 1;
    let read = reader
        .by_ref()
        .take(limit)
        .read_until(b'\n', buffer)
        .map_err(|e| error(e.to_string()))?;
    if read > LONGEST_LINE {
        return Err(error(format!(
            "longer than {LONGEST_LINE} bytes: not a line of numbers (is the file text, one \
             sample a line?)"
        )));
    }
    Ok(read)
}

/// The line's text; else where its first byte that is not UTF-8 is: the column (comma
/// separated) it falls in, named as the header names it.
fn utf8<'a>(bytes: &'a [u8], line: usize, names: Option<&[String]>) -> Result<&'a str, CsvError> {
    std::str::from_utf8(bytes).map_err(|e| {
        let at = e.valid_up_to();
        let c = bytes[..at].iter().filter(|&&b| b == b',').count();
        let name = names.and_then(|n| n.get(c)).cloned().unwrap_or_default();
        let message =
            if line == 1 && at == 0 && matches!(bytes, [0xff, 0xfe, ..] | [0xfe, 0xff, ..]) {
                "the file is UTF-16 text (its byte-order mark): save it as UTF-8".to_string()
            } else {
                format!(
                    "the byte 0x{:02x} is not UTF-8 text (a number is ASCII)",
                    bytes[at]
                )
            };
        CsvError {
            line,
            column: Some((c + 1, name)),
            message,
        }
    })
}

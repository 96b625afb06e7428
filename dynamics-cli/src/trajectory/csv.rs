//! The CSV layer of a trajectory file: the header and the data lines, checked one by one, each
//! error naming its line and, for a value, its column.

use std::io::BufRead;

/// What a file must hold: the joints' count, and whether joint torques end each line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Columns {
    pub joints: usize,
    /// `tau1..taun` after the positions and derivatives (`dynamics identify`).
    pub torques: bool,
}

/// Which derivatives a file gives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Given {
    Positions,
    Velocities,
    Accelerations,
}

impl Given {
    /// The groups of joint columns after `t`, each of `n` columns.
    fn groups(self) -> usize {
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
            Some((c, name)) => write!(
                f,
                "line {}, column {c} ({name}): {}",
                self.line, self.message
            ),
            None => write!(f, "line {}: {}", self.line, self.message),
        }
    }
}

/// The header's expected names, for the columns and what is given.
pub fn header_names(columns: Columns, given: Given) -> Vec<String> {
    let mut names = vec!["t".to_string()];
    let groups = ["q", "qd", "qdd"];
    let torques = if columns.torques { &["tau"][..] } else { &[] };
    for g in groups[..given.groups()].iter().chain(torques) {
        names.extend((1..=columns.joints).map(|i| format!("{g}{i}")));
    }
    names
}

/// What a header of `k` names gives, for these columns.
fn layout(line: usize, k: usize, columns: Columns) -> Result<Given, CsvError> {
    let n = columns.joints;
    let extra = usize::from(columns.torques) * n;
    let given = [Given::Positions, Given::Velocities, Given::Accelerations]
        .into_iter()
        .find(|g| k == 1 + g.groups() * n + extra);
    given.ok_or_else(|| {
        let (tail, torques) = if columns.torques {
            (format!(", then tau1..tau{n}"), " and torques")
        } else {
            (String::new(), "")
        };
        CsvError {
            line,
            column: None,
            message: format!(
                "the header has {k} columns; the robot has {n} joints: expected t,q1..q{n}, \
                 optionally qd1..qd{n} and qdd1..qdd{n}{tail} ({}, {} or {} columns{torques})",
                1 + n + extra,
                1 + 2 * n + extra,
                1 + 3 * n + extra
            ),
        }
    })
}

fn parse_header(line: usize, text: &str, columns: Columns) -> Result<Given, CsvError> {
    let found: Vec<&str> = text.split(',').map(str::trim).collect();
    let given = layout(line, found.len(), columns)?;
    for (c, (want, got)) in header_names(columns, given).iter().zip(&found).enumerate() {
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

/// What a whole file held.
#[derive(Clone, Copy, Debug)]
pub struct Rows {
    pub given: Given,
    /// The file's last line (1-based), where an error about the whole file is placed.
    pub last_line: usize,
}

/// Reads the lines of `reader`, calling `each` with every data line's values and its line
/// number, in order, and `progress` with the count of bytes read every so often. Blank lines
/// and lines starting with `#` are skipped; the first other line is the header.
///
/// # Errors
/// The first bad line, or a file without a header.
pub fn read_rows(
    reader: impl BufRead,
    columns: Columns,
    mut each: impl FnMut(Given, Vec<f64>),
    mut progress: impl FnMut(u64),
) -> Result<Rows, CsvError> {
    let mut header: Option<(Given, Vec<String>)> = None;
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
        let Some((given, names)) = &header else {
            let given = parse_header(line, trimmed, columns)?;
            header = Some((given, header_names(columns, given)));
            continue;
        };
        let row = parse_row(line, trimmed, names, previous)?;
        previous = Some(row[0]);
        each(*given, row);
    }
    let Some((given, _)) = header else {
        let tail = if columns.torques { ",tau1..taun" } else { "" };
        return Err(CsvError {
            line: last_line.max(1),
            column: None,
            message: format!("no header: expected t,q1..qn{tail}"),
        });
    };
    Ok(Rows { given, last_line })
}

//! Robot description files: the JSON format of the reference data, unchanged, and the same
//! content as TOML. Numbers may also be written as strings holding a value (`"90 deg"`,
//! `"m2 * l2^2 / 12"`), which TOML makes pleasant to write by hand.

use super::{parse_value, Convention, Joint, JointKind, Robot, Spring, Value};
use serde::Deserialize;
use std::collections::BTreeMap;

/// A value in a description file: a number, or a string holding a value (`"90 deg"`). It is
/// read and checked while the file is parsed, so that its errors carry a line and column.
struct FileValue(Value);

impl<'de> Deserialize<'de> for FileValue {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(ValueVisitor)
    }
}

struct ValueVisitor;

impl serde::de::Visitor<'_> for ValueVisitor {
    type Value = FileValue;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a number, or a string holding a value such as \"90 deg\" or \"m * l^2 / 12\"")
    }

    fn visit_f64<E: serde::de::Error>(self, x: f64) -> Result<FileValue, E> {
        if x.is_finite() {
            Ok(FileValue(Value::from_f64(x)))
        } else {
            Err(E::custom(format!("{x} is not a finite number")))
        }
    }

    fn visit_i64<E: serde::de::Error>(self, x: i64) -> Result<FileValue, E> {
        Ok(FileValue(Value::Num(crate::symbolic::Number::int(x))))
    }

    fn visit_u64<E: serde::de::Error>(self, x: u64) -> Result<FileValue, E> {
        match i64::try_from(x) {
            Ok(x) => self.visit_i64(x),
            #[allow(clippy::cast_precision_loss)]
            Err(_) => self.visit_f64(x as f64),
        }
    }

    fn visit_str<E: serde::de::Error>(self, text: &str) -> Result<FileValue, E> {
        let v = parse_value(text).map_err(E::custom)?;
        if v.joint_occurrences() > 0 {
            return Err(E::custom(
                "the joint variable `q` has no place in a description file; `theta` (revolute) \
                 or `d` (prismatic) is the offset added to it",
            ));
        }
        if v.exact().is_some_and(|n| !n.to_f64().is_finite()) {
            return Err(E::custom(format!("`{text}` is not a finite number")));
        }
        Ok(FileValue(v))
    }
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
enum FileConvention {
    Standard,
    Modified,
}

#[derive(Deserialize)]
#[serde(rename_all = "lowercase")]
enum FileKind {
    Revolute,
    Prismatic,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileRobot {
    #[serde(default)]
    name: Option<String>,
    #[serde(default)]
    #[allow(dead_code)]
    description: Option<String>,
    #[serde(default)]
    convention: Option<FileConvention>,
    gravity: [FileValue; 3],
    joints: Vec<FileJoint>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileJoint {
    #[serde(rename = "type")]
    kind: FileKind,
    #[serde(default)]
    theta: Option<FileValue>,
    #[serde(default)]
    d: Option<FileValue>,
    #[serde(default)]
    a: Option<FileValue>,
    #[serde(default)]
    alpha: Option<FileValue>,
    mass: FileValue,
    #[serde(default)]
    com: Option<[FileValue; 3]>,
    #[serde(default)]
    inertia: Option<[FileValue; 6]>,
    #[serde(default)]
    actuator_inertia: Option<FileValue>,
    #[serde(default)]
    spring_stiffness: Option<FileValue>,
    #[serde(default)]
    spring_rest: Option<FileValue>,
    /// `false` keeps an inertia tensor that fails the physical checks.
    #[serde(default)]
    check_inertia: Option<bool>,
}

/// A robot read from a description file, with what the file says about checking it.
pub struct Loaded {
    /// The robot.
    pub robot: Robot,
    /// Per joint, whether its inertia tensor is checked (`"check_inertia": false` opts out).
    pub check_inertia: Vec<bool>,
    /// Per joint, where the value of each key is written (1-based line and column), so that
    /// checks after loading can point into the file.
    pub positions: Vec<BTreeMap<String, (usize, usize)>>,
}

impl Loaded {
    /// `path:line:col: ` where the file gives joint `joint`'s `key`, or `path: ` when it does
    /// not say: the prefix of a message about that value.
    #[must_use]
    pub fn at(&self, path: &str, joint: usize, key: &str) -> String {
        self.positions
            .get(joint)
            .and_then(|p| p.get(key))
            .map_or_else(
                || format!("{path}: "),
                |(line, column)| format!("{path}:{line}:{column}: "),
            )
    }
}

/// An error in a description file, with the 1-based line and column where known.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FileError {
    /// What is wrong.
    pub message: String,
    /// Line, 1-based.
    pub line: Option<usize>,
    /// Column, 1-based.
    pub column: Option<usize>,
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => write!(f, "{l}:{c}: {}", self.message),
            _ => write!(f, "{}", self.message),
        }
    }
}

fn plain(message: String) -> FileError {
    FileError {
        message,
        line: None,
        column: None,
    }
}

fn value(v: Option<&FileValue>) -> Value {
    v.map_or_else(Value::zero, |v| v.0.clone())
}

fn convert(file: FileRobot, default_name: &str) -> Result<Loaded, FileError> {
    let convention = match file.convention {
        None | Some(FileConvention::Standard) => Convention::Standard,
        Some(FileConvention::Modified) => Convention::Modified,
    };
    if file.joints.is_empty() {
        return Err(plain(
            "`joints` is empty: give one entry per joint, base to tip".to_string(),
        ));
    }
    let gravity = file.gravity.map(|g| g.0);
    let mut joints = Vec::with_capacity(file.joints.len());
    let mut check_inertia = Vec::with_capacity(file.joints.len());
    for j in file.joints {
        let kind = match j.kind {
            FileKind::Revolute => JointKind::Revolute,
            FileKind::Prismatic => JointKind::Prismatic,
        };
        let stiffness = value(j.spring_stiffness.as_ref());
        let spring = (!stiffness.is_zero()).then(|| Spring {
            stiffness,
            rest: value(j.spring_rest.as_ref()),
        });
        check_inertia.push(j.check_inertia.unwrap_or(true));
        joints.push(Joint {
            kind,
            theta: value(j.theta.as_ref()),
            d: value(j.d.as_ref()),
            a: value(j.a.as_ref()),
            alpha: value(j.alpha.as_ref()),
            mass: j.mass.0,
            com: j.com.map_or_else(Default::default, |c| c.map(|v| v.0)),
            inertia: j.inertia.map_or_else(Default::default, |c| c.map(|v| v.0)),
            actuator_inertia: value(j.actuator_inertia.as_ref()),
            spring,
        });
    }
    Ok(Loaded {
        robot: Robot {
            name: file.name.unwrap_or_else(|| default_name.to_string()),
            convention,
            gravity,
            joints,
        },
        check_inertia,
        positions: Vec::new(),
    })
}

impl Default for Value {
    fn default() -> Value {
        Value::zero()
    }
}

fn json(text: &str, default_name: &str) -> Result<Loaded, FileError> {
    let file: FileRobot = serde_json::from_str(text).map_err(|e| FileError {
        message: e
            .to_string()
            .split(" at line")
            .next()
            .unwrap_or_default()
            .to_string(),
        line: Some(e.line()),
        column: Some(e.column()),
    })?;
    let mut loaded = convert(file, default_name)?;
    loaded.positions = json_positions(text);
    Ok(loaded)
}

fn toml(text: &str, default_name: &str) -> Result<Loaded, FileError> {
    let file: FileRobot = toml::from_str(text).map_err(|e| {
        let (line, column) = e
            .span()
            .map_or((None, None), |s| line_column(text, s.start));
        let mut message = e.message().trim_end().to_string();
        // toml does not say which key is repeated; it is the one its span starts at.
        if let (true, Some(s)) = (message == "duplicate key", e.span()) {
            let key = text.get(s.start..).unwrap_or_default();
            let key = key
                .split(['=', '\n', ']'])
                .next()
                .unwrap_or_default()
                .trim();
            if !key.is_empty() {
                message = format!("duplicate key `{key}`");
            }
        }
        FileError {
            message,
            line,
            column,
        }
    })?;
    let mut loaded = convert(file, default_name)?;
    loaded.positions = toml_positions(text);
    Ok(loaded)
}

/// The 1-based line and column (in characters) of a byte offset.
fn line_column(text: &str, offset: usize) -> (Option<usize>, Option<usize>) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.chars().count()
        - before
            .rfind('\n')
            .map_or(0, |p| before[..=p].chars().count())
        + 1;
    (Some(line), Some(column))
}

fn positions_at(
    text: &str,
    joints: impl IntoIterator<Item = Vec<(String, usize)>>,
) -> Vec<BTreeMap<String, (usize, usize)>> {
    joints
        .into_iter()
        .map(|keys| {
            keys.into_iter()
                .filter_map(|(key, offset)| match line_column(text, offset) {
                    (Some(l), Some(c)) => Some((key, (l, c))),
                    _ => None,
                })
                .collect()
        })
        .collect()
}

/// Where each joint's values are in TOML text (read a second time, with spans).
fn toml_positions(text: &str) -> Vec<BTreeMap<String, (usize, usize)>> {
    #[derive(Deserialize)]
    struct Joints {
        #[serde(default)]
        joints: Vec<BTreeMap<String, toml::Spanned<serde::de::IgnoredAny>>>,
    }
    let Ok(file) = toml::from_str::<Joints>(text) else {
        return Vec::new();
    };
    let offsets = file.joints.into_iter().map(|joint| {
        joint
            .into_iter()
            .map(|(key, value)| (key, value.span().start))
            .collect()
    });
    positions_at(text, offsets)
}

/// Where each joint's values are in JSON text: a scan of the text that the parser has already
/// accepted (serde_json keeps no positions of values).
fn json_positions(text: &str) -> Vec<BTreeMap<String, (usize, usize)>> {
    let mut scan = JsonScan {
        bytes: text.as_bytes(),
        at: 0,
    };
    let mut joints = Vec::new();
    scan.object(&mut |scan, key| {
        if key == "joints" && scan.peek() == Some(b'[') {
            scan.at += 1;
            loop {
                scan.space();
                match scan.peek() {
                    Some(b'{') => {
                        let mut keys = Vec::new();
                        scan.object(&mut |scan, key| {
                            keys.push((key.to_string(), scan.at));
                            scan.value();
                        });
                        joints.push(keys);
                    }
                    Some(b',') => scan.at += 1,
                    Some(b']') | None => break,
                    Some(_) => scan.value(),
                }
            }
            scan.at += 1;
        } else {
            scan.value();
        }
    });
    positions_at(text, joints)
}

/// A cursor over valid JSON.
struct JsonScan<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl JsonScan<'_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.at).copied()
    }

    fn space(&mut self) {
        while self.peek().is_some_and(|b| b.is_ascii_whitespace()) {
            self.at += 1;
        }
    }

    /// A string's raw content; the cursor is on its opening quote.
    fn string(&mut self) -> &str {
        self.at += 1;
        let start = self.at;
        while let Some(b) = self.peek() {
            match b {
                b'\\' => self.at += 2,
                b'"' => break,
                _ => self.at += 1,
            }
        }
        let end = self.at.min(self.bytes.len());
        self.at += 1;
        std::str::from_utf8(self.bytes.get(start..end).unwrap_or_default()).unwrap_or_default()
    }

    /// Skips one value (and the space before it).
    fn value(&mut self) {
        self.space();
        match self.peek() {
            Some(b'"') => {
                self.string();
            }
            Some(b'{' | b'[') => {
                let mut depth = 0usize;
                while let Some(b) = self.peek() {
                    match b {
                        b'"' => {
                            self.string();
                            continue;
                        }
                        b'{' | b'[' => depth += 1,
                        b'}' | b']' => depth = depth.saturating_sub(1),
                        _ => {}
                    }
                    self.at += 1;
                    if depth == 0 {
                        break;
                    }
                }
            }
            _ => {
                while self
                    .peek()
                    .is_some_and(|b| !matches!(b, b',' | b'}' | b']') && !b.is_ascii_whitespace())
                {
                    self.at += 1;
                }
            }
        }
    }

    /// Walks an object, calling `each` with the cursor on each key's value.
    fn object(&mut self, each: &mut dyn FnMut(&mut Self, &str)) {
        self.space();
        if self.peek() != Some(b'{') {
            return;
        }
        self.at += 1;
        loop {
            self.space();
            match self.peek() {
                Some(b'"') => {
                    let key = self.string().to_string();
                    self.space();
                    if self.peek() == Some(b':') {
                        self.at += 1;
                    }
                    self.space();
                    each(self, &key);
                }
                Some(b',') => self.at += 1,
                _ => break,
            }
        }
        self.at += 1;
    }
}

/// Reads a robot from JSON text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_json(text: &str, default_name: &str) -> Result<Robot, FileError> {
    json(text, default_name).map(|l| l.robot)
}

/// Reads a robot from TOML text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_toml(text: &str, default_name: &str) -> Result<Robot, FileError> {
    toml(text, default_name).map(|l| l.robot)
}

/// Reads a robot from a file's text, as JSON or TOML by the file's extension.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_text(path: &str, text: &str) -> Result<Robot, FileError> {
    load(path, text).map(|l| l.robot)
}

/// Reads a robot and its per-joint check flags from a file's text, as JSON or TOML by the
/// file's extension.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn load(path: &str, text: &str) -> Result<Loaded, FileError> {
    let stem = std::path::Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("robot");
    if path.ends_with(".toml") {
        toml(text, stem)
    } else if path.ends_with(".json") {
        json(text, stem)
    } else {
        Err(plain(
            "cannot tell the format from the file's extension: name it *.json or *.toml"
                .to_string(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::{from_json, from_toml, load};
    use crate::model::{Convention, JointKind};

    #[test]
    fn json_and_toml_agree() {
        let json = r#"{"name": "arm", "convention": "standard", "gravity": [0, -9.81, 0],
          "joints": [{"type": "revolute", "theta": 0.0, "d": 0.0, "a": 0.7, "alpha": 1.5707963267948966,
                      "mass": 2.0, "com": [-0.35, 0, 0], "inertia": [0, 0.1, 0.1, 0, 0, 0]}]}"#;
        let toml = r#"
            name = "arm"
            gravity = [0, -9.81, 0]
            [[joints]]
            type = "revolute"
            a = 0.7
            alpha = "90 deg"
            mass = 2
            com = [-0.35, 0, 0]
            inertia = [0, 0.1, 0.1, 0, 0, 0]
        "#;
        let a = from_json(json, "x").unwrap();
        let b = from_toml(toml, "x").unwrap();
        assert_eq!(a.convention, Convention::Standard);
        assert_eq!(a.joints[0].kind, JointKind::Revolute);
        assert_eq!(
            a.joints[0].alpha.pi_multiple(),
            b.joints[0].alpha.pi_multiple()
        );
        assert_eq!(a.joints[0].mass, b.joints[0].mass);
        assert_eq!(a.joints[0].com, b.joints[0].com);
    }

    #[test]
    fn errors_have_positions() {
        let e = from_json(
            "{\n \"gravity\": [0, 0, -9.81],\n \"joints\": [{\"type\": \"revolut\"}]}",
            "x",
        )
        .unwrap_err();
        assert!(e.message.contains("revolut"), "{e}");
        let e = from_json("{\n \"gravity\": [0, 0, -9.81],\n \"jionts\": []}", "x").unwrap_err();
        assert_eq!(e.line, Some(3));
        assert!(e.message.contains("jionts"));
        let e = from_toml("gravity = [0, 0]\njoints = []", "x").unwrap_err();
        assert_eq!(e.line, Some(1));
    }

    #[test]
    fn values_have_positions_for_later_checks() {
        let json = "{\"gravity\": [0, 0, -9.81], \"name\": \"a{[\\\"\",\n \"joints\": [\n  {\"type\": \"revolute\", \"mass\": 1},\n  {\"type\": \"revolute\",\n   \"mass\": 2, \"inertia\": [1, 2, 3, 0, 0, 0]}]}";
        let loaded = load("a.json", json).expect("json");
        assert_eq!(loaded.positions.len(), 2);
        assert_eq!(loaded.positions[0]["mass"], (3, 32));
        assert_eq!(loaded.positions[1]["mass"], (5, 12));
        assert_eq!(loaded.positions[1]["inertia"], (5, 26));
        let toml = "gravity = [0, 0, -9.81]\n[[joints]]\ntype = \"revolute\"\nmass = 1\n\n[[joints]]\ntype = \"prismatic\"\nmass = 2\ninertia = [1, 2, 3, 0, 0, 0]\n";
        let loaded = load("a.toml", toml).expect("toml");
        assert_eq!(loaded.positions[0]["mass"], (4, 8));
        assert_eq!(loaded.positions[1]["inertia"], (9, 11));
    }
}

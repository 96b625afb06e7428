//! Robot description files: the JSON format of the reference data, unchanged, and the same
//! content as TOML. Numbers may also be written as strings holding a value (`"90 deg"`,
//! `"m2 * l2^2 / 12"`), which TOML makes pleasant to write by hand.

use super::{parse_value, Convention, Joint, JointKind, Robot, Spring, Value};
use serde::Deserialize;

#[derive(Deserialize)]
#[serde(untagged)]
enum FileValue {
    Number(f64),
    Text(String),
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
    convention: Option<String>,
    gravity: [FileValue; 3],
    joints: Vec<FileJoint>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileJoint {
    #[serde(rename = "type")]
    kind: String,
    #[serde(default)]
    theta: Option<FileValue>,
    #[serde(default)]
    d: Option<FileValue>,
    #[serde(default)]
    a: Option<FileValue>,
    #[serde(default)]
    alpha: Option<FileValue>,
    #[serde(default)]
    mass: Option<FileValue>,
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

fn value(v: Option<&FileValue>, what: &str) -> Result<Value, FileError> {
    match v {
        None => Ok(Value::zero()),
        Some(FileValue::Number(x)) => {
            if x.is_finite() {
                Ok(Value::from_f64(*x))
            } else {
                Err(plain(format!("`{what}` is not a finite number")))
            }
        }
        Some(FileValue::Text(t)) => {
            let v = parse_value(t).map_err(|e| plain(format!("`{what}`: {e}")))?;
            if v.joint_occurrences() > 0 {
                return Err(plain(format!(
                    "`{what}`: the joint variable `q` has no place in a description file; \
                     `theta` (revolute) or `d` (prismatic) is the offset added to it"
                )));
            }
            Ok(v)
        }
    }
}

fn convert(file: FileRobot, default_name: &str) -> Result<Robot, FileError> {
    let convention = match file.convention.as_deref() {
        None | Some("standard") => Convention::Standard,
        Some("modified") => Convention::Modified,
        Some(other) => {
            return Err(plain(format!(
                "unknown convention `{other}`: expected \"standard\" or \"modified\""
            )))
        }
    };
    let gravity = [
        value(Some(&file.gravity[0]), "gravity[0]")?,
        value(Some(&file.gravity[1]), "gravity[1]")?,
        value(Some(&file.gravity[2]), "gravity[2]")?,
    ];
    let mut joints = Vec::with_capacity(file.joints.len());
    for (i, j) in file.joints.iter().enumerate() {
        let n = i + 1;
        let kind = match j.kind.as_str() {
            "revolute" => JointKind::Revolute,
            "prismatic" => JointKind::Prismatic,
            other => {
                return Err(plain(format!(
                "joint {n}: unknown joint type `{other}`: expected \"revolute\" or \"prismatic\""
            )))
            }
        };
        let com = match &j.com {
            Some(c) => [
                value(Some(&c[0]), "com")?,
                value(Some(&c[1]), "com")?,
                value(Some(&c[2]), "com")?,
            ],
            None => [Value::zero(), Value::zero(), Value::zero()],
        };
        let inertia = match &j.inertia {
            Some(c) => {
                let mut out: [Value; 6] = Default::default();
                for (o, x) in out.iter_mut().zip(c) {
                    *o = value(Some(x), "inertia")?;
                }
                out
            }
            None => Default::default(),
        };
        let stiffness = value(j.spring_stiffness.as_ref(), "spring_stiffness")?;
        let spring = if stiffness.is_zero() {
            None
        } else {
            Some(Spring {
                stiffness,
                rest: value(j.spring_rest.as_ref(), "spring_rest")?,
            })
        };
        joints.push(Joint {
            kind,
            theta: value(j.theta.as_ref(), "theta")?,
            d: value(j.d.as_ref(), "d")?,
            a: value(j.a.as_ref(), "a")?,
            alpha: value(j.alpha.as_ref(), "alpha")?,
            mass: value(j.mass.as_ref(), "mass")?,
            com,
            inertia,
            actuator_inertia: value(j.actuator_inertia.as_ref(), "actuator_inertia")?,
            spring,
        });
    }
    Ok(Robot {
        name: file.name.unwrap_or_else(|| default_name.to_string()),
        convention,
        gravity,
        joints,
    })
}

impl Default for Value {
    fn default() -> Value {
        Value::zero()
    }
}

/// Reads a robot from JSON text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_json(text: &str, default_name: &str) -> Result<Robot, FileError> {
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
    convert(file, default_name)
}

/// Reads a robot from TOML text.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_toml(text: &str, default_name: &str) -> Result<Robot, FileError> {
    let file: FileRobot = toml::from_str(text).map_err(|e| {
        let (line, column) = e.span().map_or((None, None), |s| {
            let before = &text[..s.start.min(text.len())];
            let line = before.matches('\n').count() + 1;
            let column = before.len() - before.rfind('\n').map_or(0, |p| p + 1) + 1;
            (Some(line), Some(column))
        });
        FileError {
            message: e.message().to_string(),
            line,
            column,
        }
    })?;
    convert(file, default_name)
}

/// Reads a robot from a file's text, as JSON or TOML by the file's extension.
///
/// # Errors
/// The first problem found, with its line and column.
pub fn from_text(path: &str, text: &str) -> Result<Robot, FileError> {
    let stem = std::path::Path::new(path)
        .file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("robot");
    if path.ends_with(".toml") {
        from_toml(text, stem)
    } else if path.ends_with(".json") {
        from_json(text, stem)
    } else {
        Err(plain(format!(
            "cannot tell the format of `{path}`: name it *.json or *.toml"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::{from_json, from_toml};
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
}

//! The values of the options: finite and positive numbers, whole numbers within a range, lists
//! of numbers, `NAME=VALUE` settings; each refused with what was expected.
//!
//! Every option that takes a number is declared `allow_hyphen_values`, so that a negative
//! number (`--tolerance -1`) reaches these parsers, which say why it is wrong, instead of clap
//! reading it as an option.

use std::str::FromStr;

/// A positive finite number.
pub fn positive(text: &str) -> Result<f64, String> {
    let x = finite(text)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(format!(
            "`{text}` is not positive: expected a number above 0"
        ))
    }
}

/// A fraction: a number above 0 and below 1.
pub fn fraction(text: &str) -> Result<f64, String> {
    let x = finite(text)?;
    if x > 0.0 && x < 1.0 {
        Ok(x)
    } else {
        Err(format!(
            "`{text}` is not a fraction: expected a number above 0 and below 1"
        ))
    }
}

/// A file's path, not empty: the robot's (which starts with `-` only after `--`).
pub fn path(text: &str) -> Result<String, String> {
    if text.is_empty() {
        Err("an empty path: expected a file".into())
    } else {
        Ok(text.to_string())
    }
}

/// An option's file: a [`path`] not starting with `-`, which is an option where a file was
/// expected (`--csv --json`); `./-x` names a file of that name.
pub fn file(text: &str) -> Result<String, String> {
    if text.starts_with('-') {
        Err(format!(
            "`{text}` starts with `-`: expected a file (`./{text}` for a file of that name)"
        ))
    } else {
        path(text)
    }
}

/// A whole number from `MIN` to `MAX`.
pub fn whole<const MIN: u64, const MAX: u64>(text: &str) -> Result<u64, String> {
    text.trim()
        .parse::<u64>()
        .ok()
        .filter(|n| (MIN..=MAX).contains(n))
        .ok_or_else(|| format!("`{text}` is not a whole number from {MIN} to {MAX}"))
}

/// A comma-separated list of finite numbers: `1,2.5,-3`.
#[derive(Clone, Debug, PartialEq)]
pub struct Numbers(pub Vec<f64>);

impl FromStr for Numbers {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        if text.trim().is_empty() {
            return Err("an empty list: expected numbers separated by commas".into());
        }
        text.split(',')
            .enumerate()
            .map(|(k, item)| {
                if item.trim().is_empty() {
                    Err(format!(
                        "`{text}`: number {} of the list is missing: expected numbers \
                         separated by commas",
                        k + 1
                    ))
                } else {
                    finite(item)
                }
            })
            .collect::<Result<_, _>>()
            .map(Numbers)
    }
}

/// `--set NAME=VALUE`.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    pub name: String,
    pub value: f64,
}

impl FromStr for Setting {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let (name, value) = text
            .split_once('=')
            .filter(|(name, _)| !name.trim().is_empty())
            .ok_or_else(|| format!("`{text}`: expected NAME=VALUE"))?;
        Ok(Setting {
            name: name.trim().to_string(),
            value: finite(value)?,
        })
    }
}

/// A finite number.
pub fn finite(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("`{text}` is not a finite number"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_and_settings() {
        assert_eq!("1, -2.5,3e1".parse(), Ok(Numbers(vec![1.0, -2.5, 30.0])));
        assert_eq!(
            "1,,2".parse::<Numbers>(),
            Err(
                "`1,,2`: number 2 of the list is missing: expected numbers separated by commas"
                    .into()
            )
        );
        assert!("".parse::<Numbers>().unwrap_err().contains("empty list"));
        assert!("1,inf".parse::<Numbers>().is_err());
        assert_eq!(
            "m=-3".parse(),
            Ok(Setting {
                name: "m".into(),
                value: -3.0
            })
        );
        for bad in ["m", "=3", "m=", "m=x", "m=NaN"] {
            assert!(bad.parse::<Setting>().is_err(), "{bad}");
        }
    }

    #[test]
    fn numbers_in_range() {
        assert_eq!(positive("1e-3"), Ok(1e-3));
        assert_eq!(
            positive("-1"),
            Err("`-1` is not positive: expected a number above 0".into())
        );
        assert_eq!(
            positive("-inf"),
            Err("`-inf` is not a finite number".into())
        );
        assert_eq!(fraction("0.5"), Ok(0.5));
        for bad in ["1", "0", "-1", "1e308"] {
            assert!(
                fraction(bad).unwrap_err().contains("not a fraction"),
                "{bad}"
            );
        }
        assert_eq!(file("a.csv"), Ok("a.csv".into()));
        assert!(file("").unwrap_err().contains("empty path"));
        assert_eq!(path("-x.json"), Ok("-x.json".into()));
        assert!(file("--json").unwrap_err().contains("`./--json`"));
        assert_eq!(whole::<1, 10>("10"), Ok(10));
        for bad in ["0", "11", "-1", "1.5", "abc", ""] {
            assert_eq!(
                whole::<1, 10>(bad),
                Err(format!("`{bad}` is not a whole number from 1 to 10"))
            );
        }
    }
}

//! Physical checks on the values of a link that are known at compile time: the mass is finite
//! and not negative, and the inertia tensor is one a rigid body can have (positive
//! semi-definite, principal moments obeying the triangle inequality). The front end places
//! each problem on the tokens (or the description-file joint) it comes from.

use crate::model::Value;

/// The most joints a robot may have.
///
/// Generated code grows about as n³: measured with the `stats` example on generic chains,
/// 6 joints expand in 10 ms to 54 kB of code, 12 in 52 ms to 0.31 MB, 16 in 0.15 s to
/// 0.74 MB, 24 in 0.36 s to 2.0 MB and 32 in 0.8 s to 3.7 MB, which rustc then compiles twice
/// (f32 and f64). Sixteen keeps a derive in the time of an ordinary build.
pub const MAX_JOINTS: usize = 16;

/// The part of a link a problem is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// `mass`.
    Mass,
    /// `inertia`.
    Inertia,
}

/// A physical problem with one link.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// Which value is wrong.
    pub part: Part,
    /// What is wrong and how to fix it.
    pub message: String,
}

/// The problems of one link's mass and (unless `check_inertia` is false) inertia tensor
/// `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`. Values that name struct fields are not known yet and pass.
#[must_use]
pub fn link(mass: &Value, inertia: &[Value; 6], check_inertia: bool) -> Vec<Problem> {
    let mut problems = Vec::new();
    if let Some(m) = mass.exact() {
        let x = m.to_f64();
        if !x.is_finite() {
            problems.push(Problem {
                part: Part::Mass,
                message: "the mass is not a finite number".into(),
            });
        } else if m.is_negative() {
            problems.push(Problem {
                part: Part::Mass,
                message: format!("the mass is negative ({}): a mass is 0 or more", short(x)),
            });
        }
    }
    if !check_inertia {
        return problems;
    }
    let Some(i) = inertia
        .iter()
        .map(|v| v.exact().map(crate::symbolic::Number::to_f64))
        .collect::<Option<Vec<f64>>>()
    else {
        return problems;
    };
    if i.iter().any(|x| !x.is_finite()) {
        problems.push(Problem {
            part: Part::Inertia,
            message: "the inertia tensor has an entry that is not a finite number".into(),
        });
        return problems;
    }
    let tensor = [[i[0], i[3], i[4]], [i[3], i[1], i[5]], [i[4], i[5], i[2]]];
    let [l1, l2, l3] = eigenvalues(tensor);
    // Relative tolerance: the data are decimals rounded far above f64's rounding error.
    let tol = 1e-9 * i.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let opt_out = "or add `check_inertia = false` to this link to keep the values as they are";
    if l1 < -tol {
        problems.push(Problem {
            part: Part::Inertia,
            message: format!(
                "the inertia tensor is not positive semi-definite (its principal moments are \
                 {}, {}, {}), so no rigid body has it: check the signs of Ixy, Ixz, Iyz (they \
                 are tensor entries, −∫xy dm), {opt_out}",
                short(l1),
                short(l2),
                short(l3)
            ),
        });
    } else if l1 + l2 < l3 - tol {
        problems.push(Problem {
            part: Part::Inertia,
            message: format!(
                "the principal moments of inertia {}, {}, {} break the triangle inequality \
                 ({} + {} < {}) that every rigid body obeys: check the values, {opt_out} \
                 (some published tables, such as PUMA 560's, have such links)",
                short(l1),
                short(l2),
                short(l3),
                short(l1),
                short(l2),
                short(l3)
            ),
        });
    }
    problems
}

/// The eigenvalues of a symmetric 3×3 matrix, ascending (cyclic Jacobi rotations, a bounded
/// number of sweeps).
#[must_use]
pub fn eigenvalues(mut a: [[f64; 3]; 3]) -> [f64; 3] {
    for _ in 0..64 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        let diag = a[0][0].abs() + a[1][1].abs() + a[2][2].abs();
        if off <= f64::EPSILON * diag * 1e-3 || off == 0.0 || !off.is_finite() {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let theta = 0.5 * (2.0 * a[p][q]).atan2(a[q][q] - a[p][p]);
            let (s, c) = theta.sin_cos();
            // A ← Jᵀ A J with J the rotation in the (p, q) plane.
            for row in &mut a {
                let (x, y) = (row[p], row[q]);
                row[p] = c * x - s * y;
                row[q] = s * x + c * y;
            }
            let (row_p, row_q) = (a[p], a[q]);
            a[p] = std::array::from_fn(|k| c * row_p[k] - s * row_q[k]);
            a[q] = std::array::from_fn(|k| s * row_p[k] + c * row_q[k]);
        }
    }
    let mut l = [a[0][0], a[1][1], a[2][2]];
    l.sort_by(f64::total_cmp);
    l
}

/// A number with four significant digits, for messages.
fn short(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    #[allow(clippy::cast_possible_truncation)]
    let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 17);
    let text = format!("{x:.*}", usize::try_from(digits).unwrap_or(0));
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

#[cfg(test)]
mod tests {
    use super::{eigenvalues, link, short, Part};
    use crate::model::{parse_value, Value};

    fn values(text: [&str; 6]) -> [Value; 6] {
        text.map(|t| parse_value(t).expect("value"))
    }

    #[test]
    fn eigenvalues_of_known_matrices() {
        // [[2, 1, 0], [1, 2, 0], [0, 0, 5]] has eigenvalues 1, 3, 5.
        let l = eigenvalues([[2.0, 1.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 5.0]]);
        for (a, b) in l.iter().zip([1.0, 3.0, 5.0]) {
            assert!((a - b).abs() < 1e-12, "{l:?}");
        }
        // [[2, -1, 0], [-1, 2, -1], [0, -1, 2]]: 2 - √2, 2, 2 + √2.
        let l = eigenvalues([[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 2.0]]);
        let r = std::f64::consts::SQRT_2;
        for (a, b) in l.iter().zip([2.0 - r, 2.0, 2.0 + r]) {
            assert!((a - b).abs() < 1e-12, "{l:?}");
        }
    }

    #[test]
    fn physical_links_pass() {
        let zero = Value::zero();
        // A thin rod (0, I, I) is the edge of the triangle inequality and passes.
        let rod = values(["0", "0.08", "0.08", "0", "0", "0"]);
        assert!(link(&parse_value("2").unwrap(), &rod, true).is_empty());
        // Products of inertia that keep the tensor positive definite.
        let tilted = values(["0.1", "0.12", "0.15", "0.01", "-0.005", "0.002"]);
        assert!(link(&zero, &tilted, true).is_empty());
        // Fields are unknown at compile time and pass.
        let fields = values(["m * l^2", "0", "0", "0", "0", "0"]);
        assert!(link(&parse_value("m").unwrap(), &fields, true).is_empty());
    }

    #[test]
    fn unphysical_links_fail_unless_unchecked() {
        let mass = parse_value("4.8").unwrap();
        // PUMA 560 link 3: 0.0125 + 0.066 < 0.086.
        let puma3 = values(["0.066", "0.086", "0.0125", "0", "0", "0"]);
        let p = link(&mass, &puma3, true);
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].part, Part::Inertia);
        assert!(
            p[0].message.contains("0.0125 + 0.066 < 0.086"),
            "{}",
            p[0].message
        );
        assert!(link(&mass, &puma3, false).is_empty());
        // |Ixy| > √(Ixx Iyy): an eigenvalue of [[1, 2], [2, 1]] is −1.
        let indefinite = values(["1", "1", "1", "2", "0", "0"]);
        let p = link(&mass, &indefinite, true);
        assert!(
            p[0].message.contains("positive semi-definite"),
            "{}",
            p[0].message
        );
        assert!(p[0].message.contains("-1,"), "{}", p[0].message);
        let p = link(&parse_value("-0.5").unwrap(), &Default::default(), true);
        assert_eq!(p[0].part, Part::Mass);
        assert!(p[0].message.contains("negative (-0.5)"), "{}", p[0].message);
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short(0.0125), "0.0125");
        assert_eq!(short(0.086_000_000_000_01), "0.086");
        assert_eq!(short(-1.0), "-1");
        assert_eq!(short(12345.6), "12346");
        assert_eq!(short(4e-5), "0.00004");
    }
}

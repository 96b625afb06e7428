//! A floating base's samples (`Base::Floating`): v and a by central differences along the
//! configuration space, against those of Pinocchio's data (`tests/data/floating/
//! make_identify.py`: Solo 12's base twist in its frame and its derivative in closed form,
//! checked there against `pin.difference`), and the quaternion's unit norm checked.

use dynamics_identification::trajectory::{read_csv, Base, Columns, Sample};

fn columns() -> Columns {
    Columns {
        joints: 12,
        torques: true,
        base: Base::Floating { joint_rows: false },
    }
}

fn read(text: &str) -> Result<Vec<Sample>, String> {
    let mut out = Vec::new();
    read_csv(text.as_bytes(), columns(), |s| out.push(s.clone()), |_| {})
        .map_err(|e| e.to_string())?;
    Ok(out)
}

/// The data file's text, and the same without its v and a columns.
fn data() -> (String, String) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../tests/data/floating/solo12_identify.csv"
    );
    let text = std::fs::read_to_string(path).expect("the data");
    let keep: Vec<bool> = text
        .lines()
        .find(|l| !l.starts_with('#'))
        .expect("a header")
        .split(',')
        .map(|c| !(c.starts_with('v') || c.starts_with('a')))
        .collect();
    let positions = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let kept: Vec<&str> = l
                .split(',')
                .zip(&keep)
                .filter(|(_, k)| **k)
                .map(|(x, _)| x)
                .collect();
            kept.join(",") + "\n"
        })
        .collect();
    (text, positions)
}

/// The largest difference of `a` and `b` relative to the largest of `b`, over the samples `k`.
fn scaled(
    a: &[Sample],
    b: &[Sample],
    k: std::ops::Range<usize>,
    pick: fn(&Sample) -> &[f64],
) -> f64 {
    let scale = b[k.clone()]
        .iter()
        .flat_map(|s| pick(s).iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let worst = k
        .flat_map(|i| {
            pick(&a[i])
                .iter()
                .zip(pick(&b[i]))
                .map(|(x, y)| (x - y).abs())
                .collect::<Vec<_>>()
        })
        .fold(0.0f64, f64::max);
    worst / scale
}

#[test]
fn v_and_a_by_differences_are_the_twist_in_the_base_frame_and_its_derivative() {
    let (given, positions) = data();
    let exact = read(&given).expect("the data");
    let estimated = read(&positions).expect("positions");
    assert_eq!(exact.len(), 1001);
    assert_eq!(estimated.len(), exact.len());
    let inner = 1..exact.len() - 1;
    // (ω h)² / 6 and / 12 at 500 Hz, ω up to 2π 2 Hz: about 5e-5 of the twist's size.
    let v = scaled(&estimated, &exact, inner.clone(), |s| &s.qd);
    let a = scaled(&estimated, &exact, inner, |s| &s.qdd);
    assert!(v < 2e-4 && a < 2e-4, "{v:e} {a:e}");
    // The ends: the same quadratic's derivatives at their own time, first order in h.
    let ends = [0..1, exact.len() - 1..exact.len()];
    for k in ends {
        let v = scaled(&estimated, &exact, k.clone(), |s| &s.qd);
        let a = scaled(&estimated, &exact, k, |s| &s.qdd);
        assert!(v < 1e-3 && a < 5e-2, "{v:e} {a:e}");
    }
    // q and τ as the file gives them, the torques every row's.
    assert_eq!(estimated[5].q, exact[5].q);
    assert_eq!(estimated[5].tau.len(), 18);
}

#[test]
fn a_quaternion_not_of_unit_norm_is_an_error_at_its_line() {
    let (given, _) = data();
    let mut lines: Vec<String> = given.lines().take(5).map(String::from).collect();
    // The quaternion's w (q7, the file's column 8) of sample 1 (line 4) made longer.
    let mut values: Vec<String> = lines[3].split(',').map(String::from).collect();
    let w: f64 = values[7].parse().unwrap();
    values[7] = format!("{:?}", w * 1.001 + 1e-3);
    lines[3] = values.join(",");
    let error = read(&(lines.join("\n") + "\n")).expect_err("not a unit quaternion");
    assert!(
        error.starts_with("line 4, column 5 (q4): the base's orientation"),
        "{error}"
    );
    // Within 1e-6 of unit norm: normalised.
    let mut values: Vec<String> = lines[3].split(',').map(String::from).collect();
    values[7] = format!("{:?}", w * (1.0 + 1e-7));
    lines[3] = values.join(",");
    let samples = read(&(lines.join("\n") + "\n")).expect("normalised");
    let norm: f64 = samples[1].q[3..7].iter().map(|x| x * x).sum();
    assert!((norm - 1.0).abs() < 1e-15, "{norm}");
}

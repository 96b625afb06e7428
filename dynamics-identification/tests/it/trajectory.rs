//! Trajectories read from CSV (derivatives by differences, errors by line and column), and
//! the quintic move.

use dynamics_identification::trajectory::{
    quintic, read_csv, Columns, CsvError, Sample, LONGEST_LINE,
};

fn read(text: &str, n: usize) -> Result<Vec<Sample>, CsvError> {
    let mut out = Vec::new();
    read_csv(
        text.as_bytes(),
        Columns {
            joints: n,
            torques: false,
            base: Default::default(),
        },
        |s| out.push(s.clone()),
        |_| {},
    )?;
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
            Some(3),
            "3 values; the header has 2 columns",
        ),
        (
            "t,q1\n0,1\n1\n",
            3,
            Some(2),
            "1 value; the header has 2 columns",
        ),
        ("t,q1\n0,1\n1, \n", 3, Some(2), "no value"),
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

fn read_bytes(bytes: &[u8]) -> Result<Vec<Sample>, CsvError> {
    let mut out = Vec::new();
    let columns = Columns {
        joints: 1,
        torques: false,
        base: Default::default(),
    };
    read_csv(bytes, columns, |s| out.push(s.clone()), |_| {})?;
    Ok(out)
}

/// What other programs write: a byte-order mark, `\r\n`; and what no program should: bytes
/// that are not text, a line without end, times too close for their values' changes.
#[test]
fn bytes_that_are_not_lines_of_numbers() {
    let plain = read_bytes(b"t,q1\n0,0\n1,1\n2,4\n").unwrap();
    for text in [
        &b"\xef\xbb\xbft,q1\n0,0\n1,1\n2,4\n"[..],
        b"t,q1\r\n0,0\r\n1,1\r\n2,4",
    ] {
        let samples = read_bytes(text).unwrap();
        assert_eq!(samples.len(), 3);
        for (a, b) in samples.iter().zip(&plain) {
            assert_eq!((a.t, &a.q, &a.qd, &a.qdd), (b.t, &b.q, &b.qd, &b.qdd));
        }
    }
    let long = [&b"t,q1\n0,"[..], &vec![b'1'; LONGEST_LINE][..]].concat();
    let cases: [(&[u8], usize, Option<usize>, &str); 5] = [
        (
            b"t,q1\n0,1\n1,2\xff\n",
            3,
            Some(2),
            "the byte 0xff is not UTF-8 text",
        ),
        (b"\xff\xfet\x00", 1, Some(1), "the file is UTF-16 text"),
        // A byte-order mark is skipped before the header only.
        (
            b"t,q1\n\xef\xbb\xbf0,1\n",
            2,
            Some(1),
            "`\u{feff}0` is not a number",
        ),
        (&long, 2, None, "longer than 1048576 bytes"),
        // Steps of 10⁻³⁰⁰ s: q̇ of 10³⁰⁰, q̈ of 10⁶⁰⁰.
        (
            b"t,q1\n0,0\n1e-300,1\n2e-300,0\n",
            2,
            Some(2),
            "central differences give",
        ),
    ];
    for (text, line, column, message) in cases {
        let e = read_bytes(text).unwrap_err();
        assert_eq!(e.line, line, "{e}");
        assert_eq!(e.column.as_ref().map(|c| c.0), column, "{e}");
        assert!(e.message.starts_with(message), "{e}");
    }
}

fn read_with_torques(text: &str, n: usize) -> Result<Vec<Sample>, CsvError> {
    let mut out = Vec::new();
    let columns = Columns {
        joints: n,
        torques: true,
        base: Default::default(),
    };
    read_csv(text.as_bytes(), columns, |s| out.push(s.clone()), |_| {})?;
    Ok(out)
}

#[test]
fn torques_end_each_line_whatever_derivatives_are_given() {
    let positions = "t,q1,q2,tau1,tau2\n0,0,1,5,6\n1,1,1,7,8\n2,4,1,9,10\n";
    let samples = read_with_torques(positions, 2).unwrap();
    let taus: Vec<Vec<f64>> = samples.iter().map(|s| s.tau.clone()).collect();
    assert_eq!(taus, [[5.0, 6.0], [7.0, 8.0], [9.0, 10.0]]);
    // q1 = t²: q̇1 = 2t and q̈1 = 2 exactly; q2 never moves: exact zeros, not round-off.
    assert_eq!(samples[1].qd, [2.0, 0.0]);
    assert_eq!(samples[1].qdd, [2.0, 0.0]);
    let all = "t,q1,qd1,qdd1,tau1\n0,1,2,3,4\n";
    let samples = read_with_torques(all, 1).unwrap();
    assert_eq!(
        (samples[0].qd[0], samples[0].qdd[0], samples[0].tau[0]),
        (2.0, 3.0, 4.0)
    );
    let e = read_with_torques("t,q1,q2\n", 2).unwrap_err();
    assert_eq!(e.line, 1);
    assert!(
        e.message.contains("then tau1..tau2 (5, 7 or 9 columns"),
        "{e}"
    );
    let e = read_with_torques("t,q1,qd1,tau\n", 1).unwrap_err();
    assert_eq!(e.column, Some((4, "tau".into())));
    assert!(e.message.contains("`tau1`"), "{e}");
}

/// A joint at rest at an awkward value, on uneven time: the weights times equal values would
/// leave round-off, whose sign Coulomb friction would read.
#[test]
fn a_joint_at_rest_has_exactly_zero_derivatives() {
    let mut text = String::from("t,q1\n");
    for t in [0.0, 0.013, 0.02, 0.0371, 0.05] {
        text += &format!("{t},0.3000000000000001\n");
    }
    for s in read(&text, 1).unwrap() {
        assert_eq!((s.qd[0], s.qdd[0]), (0.0, 0.0), "{s:?}");
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

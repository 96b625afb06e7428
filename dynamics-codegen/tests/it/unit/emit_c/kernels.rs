use dynamics_codegen::emit_c::kernels::*;

/// A C hexadecimal literal's value (`[-]0x1[.hhh]p[+-]e[f]`), read independently of
/// [`hexadecimal`].
fn read_hex(text: &str) -> f64 {
    let text = text.trim_end_matches('f');
    let (sign, text) = match text.strip_prefix('-') {
        Some(rest) => (-1.0, rest),
        None => (1.0, text),
    };
    let text = text
        .strip_prefix("0x1")
        .expect("a normal hexadecimal literal");
    let (fraction, exponent) = text.split_once('p').expect("an exponent");
    let mut value = 1.0;
    let mut scale = 1.0 / 16.0;
    for digit in fraction.trim_start_matches('.').chars() {
        value += f64::from(digit.to_digit(16).expect("a hexadecimal digit")) * scale;
        scale /= 16.0;
    }
    let exponent: i32 = exponent.parse().expect("an exponent");
    sign * value * 2f64.powi(exponent)
}

/// Every constant's C literal is the runtime's value: read as C reads it (a decimal to the
/// nearest `double`, then to `float` where the literal says so), it gives the same bits.
#[test]
fn the_c_literals_are_the_runtimes_values() {
    let all = [
        SHIFT_F64, SHIFT_F32, TINY_F64, BOUND_F64, TINY_F32, BOUND_F32, P1_F64, P2_F64, P3_F64,
        P1_F32, P2_F32, P3_F32, P4_F32, S1_F64, S2_F64, S3_F64, S4_F64, S5_F64, S6_F64, C1_F64,
        C2_F64, C3_F64, C4_F64, C5_F64, C6_F64, S1_F32, S2_F32, S3_F32, S4_F32, C1_F32, C2_F32,
        C3_F32,
    ];
    for k in all {
        assert_eq!(read_hex(&k.hex()), k.value, "{}", k.hex());
        let decimal = k.decimal();
        assert!(!decimal.contains('_'), "{decimal}");
        let digits = decimal.trim_start_matches("(float)").trim_end_matches('f');
        let double: f64 = digits.parse().expect("a decimal literal");
        #[allow(clippy::cast_possible_truncation)]
        let read = match (k.single, decimal.starts_with("(float)")) {
            (false, _) => double,
            // `(float)` of the `double`: rounded twice, as the runtime's `as f32`.
            (true, true) => f64::from(double as f32),
            // A `float` literal: the decimal to the nearest `float`, once.
            (true, false) => f64::from(digits.parse::<f32>().expect("a float")),
        };
        assert_eq!(read, k.value, "{decimal}");
    }
}

#[test]
fn hexadecimal_literals_are_printfs() {
    assert_eq!(hexadecimal(1.5), "0x1.8p+0");
    assert_eq!(hexadecimal(-0.75), "-0x1.8p-1");
    assert_eq!(hexadecimal(65_536.0), "0x1p16");
    assert_eq!(hexadecimal(2f64.powi(-27)), "0x1p-27");
    assert_eq!(hexadecimal(1.0 + f64::EPSILON), "0x1.0000000000001p+0");
    assert_eq!(P1_F64.hex(), "0x1.921fb5444p+0");
    assert_eq!(P4_F32.hex(), "0x1.184698p-44f");
}

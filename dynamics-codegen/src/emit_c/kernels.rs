//! The runtime's sine and cosine kernels in C, one argument without a branch: the text that
//! `trig.rs` writes into `dynamics_sincos` and `dynamics_sincos4`'s loop. The constants are the
//! runtime's own: its table (`dynamics-runtime/src/trig/constants.rs`, symlinked here as
//! `trig_constants.rs`) is read here as there, so that the C cannot hold another value. A
//! coefficient is spelled as the runtime's source spells it (the published decimal; a `float`
//! one `(float)` of its `double`, as the runtime's `as f32`), a part of π/2 exactly, in
//! hexadecimal. The operations are written out in C: `dynamics-cli/tests/c_trig.rs` checks
//! that they give the runtime's results, bit for bit.

// The runtime's table of constants: `reduction_constants!` and `kernel_coefficients!`.
include!("trig_constants.rs");

/// One constant of the runtime's kernels: its value, and its literal in the runtime's source.
#[derive(Clone, Copy)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Constant {
    /// The value, in the runtime's type (a `float` one widened exactly).
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub value: f64,
    /// The literal as the runtime spells it, `-1.666_666_666_666_663_243_48e-1`.
    source: &'static str,
    /// Whether the runtime's type is `f32`.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub single: bool,
    /// Whether the literal is a `double` rounded to the type (`… _f64 as f32`).
    rounded: bool,
}

/// Declares the rows of a table of the runtime's `constants.rs` as [`Constant`]s.
macro_rules! define_constants {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $value:literal $(as $cast:ty)?;)*) => {
        $(
            $(#[$doc])*
            #[allow(clippy::cast_possible_truncation, clippy::unnecessary_cast, clippy::excessive_precision)]
            #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
            pub const $name: Constant = Constant {
                value: {
                    const VALUE: $ty = $value $(as $cast)?;
                    VALUE as f64
                },
                source: stringify!($value),
                single: core::mem::size_of::<$ty>() == 4,
                rounded: !<[&str]>::is_empty(&[$(stringify!($cast))?]),
            };
        )*
    };
}

reduction_constants!(define_constants);
kernel_coefficients!(define_constants);

impl Constant {
    /// The C literal of the runtime's: its sign and digits without the `_` that group them
    /// (nor the space `stringify!` may put after a minus) and without the Rust suffix, `f`
    /// after a `float`'s, `(float)` before a `double` rounded to `float`.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn decimal(self) -> String {
        let digits: String = self
            .source
            .chars()
            .filter(|&c| c != '_' && !c.is_whitespace())
            .collect();
        let digits = digits.trim_end_matches("f64").trim_end_matches("f32");
        match (self.single, self.rounded) {
            (true, true) => format!("(float){digits}"),
            (true, false) => format!("{digits}f"),
            (false, _) => digits.to_owned(),
        }
    }

    /// The value exactly, as [`hexadecimal`] writes it, `f` after a `float`'s.
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fn hex(self) -> String {
        let text = hexadecimal(self.value);
        if self.single {
            text + "f"
        } else {
            text
        }
    }
}

/// A normal `x` as a hexadecimal literal, exact: printf's `%a` (`0x1.921fb5444p+0`,
/// `-0x1.2aep-18`), but a power of two as `0x1p16`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn hexadecimal(x: f64) -> String {
    debug_assert!(x.is_normal(), "{x} is not a normal number");
    let bits = x.to_bits();
    let sign = if x < 0.0 { "-" } else { "" };
    let exponent = i64::try_from((bits >> 52) & 0x7ff).unwrap_or(0) - 1023;
    let fraction = format!("{:013x}", bits & ((1 << 52) - 1));
    let fraction = fraction.trim_end_matches('0');
    if fraction.is_empty() {
        format!("{sign}0x1p{exponent}")
    } else {
        format!("{sign}0x1.{fraction}p{exponent:+}")
    }
}

/// The `double` kernel of one argument `x` of the fast range into `s` and `c`, one statement a
/// line, each indented four spaces.
pub(super) fn lane_f64(x: &str, s: &str, c: &str) -> String {
    format!(
        "    const double shift = {shift}; /* 1.5 * 2^52: x * 2/pi rounded to an integer */
    /* x = n pi/2 + r, pi/2 in three parts, the first two's products with n exact. */
    const double shifted = {x} * {two_over_pi} + shift;
    const double n = shifted - shift;
    const double a = {x} - n * {p1};
    const double t = a - n * {p2};
    const double r = t - n * {p3};
    /* fdlibm's k_sin.c and k_cos.c, a depth of three multiply-adds from z2. */
    const double z = t * t;
    const double z2 = z * z;
    const double z4 = z2 * z2;
    const double sin_poly = z2 * (z2 * (z * {s6} + {s5})
            + (z * {s4} + {s3}))
        + (z * {s2} + {s1});
    const double cos_poly = z4 * (z2 * {c6} + (z * {c5} + {c4}))
        + (z2 * (z * {c3} + {c2}) + (z * {c1} + -0.5));
    const double sin_r = (r * z) * sin_poly + r;
    const double cos_r = z * cos_poly + 1.0;
    /* The quadrant n mod 4 from d = n/4 - round(n/4), exactly 0, 1/4, +-1/2 or -1/4. */
    const double m = n * 0.25;
    const double d = m - ((m + shift) - shift);
    const double p = d * d == 0.0625 ? cos_r : sin_r;
    const double q = d * d == 0.0625 ? sin_r : cos_r;
    {s} = d * d == 0.25 || d == -0.25 ? -p : p;
    {c} = d * d == 0.25 || d == 0.25 ? -q : q;
",
        shift = SHIFT_F64.decimal(),
        two_over_pi = hexadecimal(core::f64::consts::FRAC_2_PI),
        p1 = P1_F64.hex(),
        p2 = P2_F64.hex(),
        p3 = P3_F64.hex(),
        s1 = S1_F64.decimal(),
        s2 = S2_F64.decimal(),
        s3 = S3_F64.decimal(),
        s4 = S4_F64.decimal(),
        s5 = S5_F64.decimal(),
        s6 = S6_F64.decimal(),
        c1 = C1_F64.decimal(),
        c2 = C2_F64.decimal(),
        c3 = C3_F64.decimal(),
        c4 = C4_F64.decimal(),
        c5 = C5_F64.decimal(),
        c6 = C6_F64.decimal(),
    )
}

/// The `float` kernel, as [`lane_f64`].
pub(super) fn lane_f32(x: &str, s: &str, c: &str) -> String {
    format!(
        "    const float shift = {shift}; /* 1.5 * 2^23 */
    /* pi/2 in four parts; Fast2Sum, TwoSum and Fast2Sum recover the roundings. */
    const float shifted = {x} * {two_over_pi} + shift;
    const float n = shifted - shift;
    const float a = {x} - n * {p1};
    const float b = n * {p2};
    const float cc = n * {p3};
    const float d4 = n * {p4};
    const float t0 = a - n * {p2};
    const float e1 = (a - t0) - b;
    const float t = t0 - n * {p3};
    const float t_s = t - t0;
    const float e2 = (t0 - (t - t_s)) - (cc + t_s);
    const float r = t - d4;
    const float r_lo = ((t - r) - d4) + (e1 + e2);
    /* FreeBSD's k_sinf.c and k_cosf.c, rounded to float. */
    const float z = t * t;
    const float z2 = z * z;
    const float sin_poly = z2 * (z * {s4} + {s3})
        + (z * {s2} + {s1});
    const float cos_poly = z2 * {c3}
        + (z * {c2} + {c1});
    const float half_z = 0.5f * z;
    const float w = 1.0f - half_z;
    const float sin_r = r + ((r * z) * sin_poly + r_lo * w);
    const float cos_r = w + ((z2 * cos_poly + ((1.0f - w) - half_z)) - r * r_lo);
    const float m = n * 0.25f;
    const float d = m - ((m + shift) - shift);
    const float p = d * d == 0.0625f ? cos_r : sin_r;
    const float q = d * d == 0.0625f ? sin_r : cos_r;
    {s} = d * d == 0.25f || d == -0.25f ? -p : p;
    {c} = d * d == 0.25f || d == 0.25f ? -q : q;
",
        shift = SHIFT_F32.decimal(),
        two_over_pi = hexadecimal(f64::from(core::f32::consts::FRAC_2_PI)) + "f",
        p1 = P1_F32.hex(),
        p2 = P2_F32.hex(),
        p3 = P3_F32.hex(),
        p4 = P4_F32.hex(),
        s1 = S1_F32.decimal(),
        s2 = S2_F32.decimal(),
        s3 = S3_F32.decimal(),
        s4 = S4_F32.decimal(),
        c1 = C1_F32.decimal(),
        c2 = C2_F32.decimal(),
        c3 = C3_F32.decimal(),
    )
}

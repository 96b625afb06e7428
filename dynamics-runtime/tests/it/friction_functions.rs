//! `Real::sign` and `Real::tanh`, the functions of the friction torque
//! `f_v q̇ + f_c sign(q̇) + f_0` (smooth form `f_c tanh(q̇ / ε)`), against std: tanh within
//! 2 ulp in `f64` (musl's `libm` against glibc, each within about 1 ulp of the exact value),
//! 1 ulp of the exact value in `f32`, at random arguments of every magnitude and a dense sweep of
//! [−20, 20]; sign exactly, with 0 at ±0 and NaN through.

use dynamics_runtime::Real;
use dynamics_test_support::Rng;

use crate::ulp::{err_f32, err_f64};

/// Arguments: a sweep of [−20, 20] (tanh's whole curve and its saturation), random ones of
/// every magnitude and sign, and the special values.
fn arguments() -> Vec<f64> {
    let mut rng = Rng::new(16);
    let sweep = (-20_000..=20_000).map(|i| f64::from(i) * 1e-3);
    // Biased exponents 2^-60 to 2^10, either sign.
    let random: Vec<f64> = (0..20_000).map(|_| rng.log_uniform(963..=1033)).collect();
    let special = [
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        1e-310,
        1e300,
        -1e300,
        f64::INFINITY,
    ];
    sweep.chain(random).chain(special).collect()
}

#[test]
fn tanh_is_within_one_ulp_of_std() {
    let (mut worst64, mut worst32) = (0.0f64, 0.0f64);
    for x in arguments() {
        worst64 = worst64.max(err_f64(Real::tanh(x), x.tanh()));
        #[allow(clippy::cast_possible_truncation)]
        let xf = x as f32;
        worst32 = worst32.max(err_f32(Real::tanh(xf), f64::from(xf).tanh()));
    }
    println!("tanh: worst {worst64} ulp (f64), {worst32} ulp (f32)");
    assert!(worst64 <= 2.0, "f64 tanh off by {worst64} ulp");
    assert!(worst32 <= 1.0, "f32 tanh off by {worst32} ulp");
    assert!(Real::tanh(f64::NAN).is_nan() && Real::tanh(f32::NAN).is_nan());
    assert_eq!(Real::tanh(f64::NEG_INFINITY), -1.0);
}

#[test]
fn sign_is_zero_at_rest_and_std_signum_elsewhere() {
    for x in arguments() {
        let want = if x == 0.0 { 0.0 } else { x.signum() };
        assert_eq!(Real::sign(x), want, "{x}");
        #[allow(clippy::cast_possible_truncation)]
        let xf = x as f32;
        let want = if xf == 0.0 { 0.0 } else { xf.signum() };
        assert_eq!(Real::sign(xf), want, "{xf}");
    }
    assert_eq!(Real::sign(-0.0f64), 0.0);
    assert_eq!(Real::sign(f64::NEG_INFINITY), -1.0);
    assert_eq!(Real::sign(5e-324f64), 1.0);
    assert!(Real::sign(f64::NAN).is_nan() && Real::sign(f32::NAN).is_nan());
}

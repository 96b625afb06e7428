//! Sine and cosine of one argument together, for `f64` and `f32`: one range reduction shared
//! by both, two polynomial kernels evaluated side by side, and a branch-free choice of quadrant (by a
//! table of 0 and ±1 coefficients).
//!
//! `x = k·π/2 + r` with `k` the integer nearest `|x|·2/π` and `|r| ≤ π/4` (a hair more when
//! `|x|·2/π` rounds across a half-integer, which the kernels tolerate). Then `sin |x|` and
//! `cos |x|` are `±sin r` or `±cos r`, chosen by `k mod 4`, and the sign of `x` goes onto the
//! sine: `sin_cos(−x)` is `(−sin x, cos x)` bit for bit, `sin(−0) = −0`, with no test.
//!
//! **Reduction (Cody-Waite).** π/2 is split into parts `P1 + P2 + … ≈ π/2` whose leading
//! parts have so few significant bits that `k·P1`, `k·P2`, … are exact for every `k` of the
//! fast range; `x − k·P1` is then exact too (Sterbenz: `x` and `k·P1` are within a factor of
//! two). For `f64`, `r = (x − k·P1 − k·P2) − k·P3` is rounded twice, not tracked as a sum:
//! within an ulp of the exact reduced argument, relatively, where `r` is small (the subtraction
//! of `k·P2` is exact there, and `|r| > 400·|k·P3|`). For `f32`, the rounding errors are
//! recovered exactly with Fast2Sum or TwoSum, so `r` comes out as an unevaluated sum
//! `r + r_lo`. The parts, the bound and the exactness conditions were checked with exact
//! rational arithmetic over every `k` of the fast range, at the double nearest each `k·π/2`
//! (where `|r|` is smallest; the smallest of all is 2^-60.5, at `x ≈ 45.55`, for `f64` and
//! 2^-27.8, at `x ≈ 252.9`, for `f32`).
//!
//! * `f64`: parts of 35, 35 and 53 bits, fast for `|x| ≤ 2^16` (`|k| < 2^16`), 0 and
//!   subnormals included.
//! * `f32`: parts of 12, 12, 12 and 22 bits, fast for `2^-12 ≤ |x| ≤ 2^12` (`|k| < 2^12`),
//!   computed in `f32` throughout, for single-precision FPUs without `f64` hardware.
//!
//! **Kernels.** The minimax polynomials of fdlibm on [−π/4, π/4]: for `f64`, those of Sun's
//! `k_sin.c` and `k_cos.c` (fdlibm 5.3, 1993; both accurate to 2^-58), for `f32`, those of
//! FreeBSD's `k_sinf.c` and `k_cosf.c` (Bruce D. Evans, 2005), rounded to `f32`. Both are in
//! `z = r²`, evaluated on shared powers of `z`. For `f64`, `sin r = r + r·z·p(z)` and
//! `cos r = (1 − z/2) + z²·q(z)`, each one multiply-add at the end; for `f32` they carry
//! `r_lo` to first order (`sin(r + r_lo) ≈ sin r + r_lo·(1 − z/2)`, `cos(r + r_lo) ≈ cos r −
//! r·r_lo`) and `cos r = 1 − z/2 + …` adds the rounding error of `1 − z/2` back in. Where the
//! build has FMA (x86-64 with `-C target-cpu=native` or `+fma`), the polynomials' multiply-adds
//! are fused, and so are the products `k·P1`, `k·P2`, `k·P3` with their subtractions (the
//! first two exact, which changes no bit there), and `x·2/π` with the shift that rounds it to an
//! integer: a shorter chain of dependent operations, the same on the scalar and the vector
//! paths. The generated code waits for the sines and cosines before anything else, so each step
//! off the chain counts.
//!
//! **Outside the fast range.** Larger arguments than the bound, `±∞` and NaN go to `libm` (NaN
//! in, NaN out). For `f32`, tiny arguments (`|x| < 2^-12`) return `(x, 1)`, which is the
//! correctly rounded result, keeps the sign of `±0` and never squares a subnormal.
//!
//! **Accuracy.** `f64`: within two ulps of std's (glibc's) results over the fast range (one on
//! the joint angles' [−4π, 4π] where the build fuses multiply-adds), and the hardest reductions
//! correctly rounded. Until 2026-11-29 the kernel carried `r_lo` for 0.76 ulp against correctly
//! rounded values: a third fewer operations a vector for an error (4.4e-16 relatively) that the
//! robots' 1e-12 checks cannot see. `f32`: within an
//! ulp of the correctly rounded values on every argument. `tests/it/trig.rs` holds the bounds
//! and the hardest cases. The measured errors and costs are in `docs/performance.md`.
//!
//! **Four at once** (`Real::sin_cos_4`, which generated code calls for groups of up to four
//! joints, and `Real::sin_cos_8`, two such groups behind one range test, for five to eight):
//! on x86-64 the same operations run in vector lanes, bit for bit the results of one at a time.
//! `f64` uses the four lanes of AVX2 where the build enables it (`-C target-cpu=native`), else
//! two SSE2 registers of two lanes, which every x86-64 build has; `f32` uses the four lanes of
//! SSE. Elsewhere, and whenever an argument is outside the fast range, one at a time.
//!
//! The files, by job: `constants.rs` (the constants' table, which `dynamics-codegen` writes the C
//! header's kernels from), [`reduction`] (the constants of the reduction), [`kernels`] (the
//! polynomials and the one body of reduction and kernels that every path expands), [`scalar`]
//! (one argument), [`four`] (four arguments: the choice of path), and the vector lanes
//! `avx2_f64`, `sse2_f64` and `sse_f32`.

// Constants are written as published (kernels) or as exact decimal expansions (parts of π/2).
#![allow(clippy::excessive_precision)]

// The constants' table (shared with `dynamics-codegen`'s C kernels), then the modules that
// declare them with `declare_constants!`.
#[macro_use]
mod constants;
/// Declares the rows of a table of `constants.rs` as constants of the module that reads it.
macro_rules! declare_constants {
    ($($(#[$doc:meta])* $name:ident: $ty:ty = $value:literal $(as $cast:ty)?;)*) => {
        $(
            $(#[$doc])*
            #[allow(clippy::cast_possible_truncation)]
            pub(super) const $name: $ty = $value $(as $cast)?;
        )*
    };
}
#[macro_use]
mod kernels;
mod four;
mod reduction;
mod scalar;

// `pub(crate)`: the lane types (`crate::lanes`) call their register forms.
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
#[allow(unsafe_code)]
pub(crate) mod avx2_f64;
// In every x86-64 build: `F64x2` uses it with AVX2 too, where `sin_cos_4` does not.
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
#[cfg_attr(target_feature = "avx2", allow(dead_code))]
pub(crate) mod sse2_f64;
#[cfg(target_arch = "x86_64")]
#[allow(unsafe_code)]
pub(crate) mod sse_f32;

pub(crate) use four::{sin_cos_4_f32, sin_cos_4_f64, sin_cos_8_f32, sin_cos_8_f64};
pub(crate) use scalar::{sin_cos_f32, sin_cos_f64};

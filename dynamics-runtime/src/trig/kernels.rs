//! The polynomial kernels on [−π/4, π/4] and the one body of reduction and kernels that
//! every path (scalar, SSE2, AVX2) expands, so that all of them run the same operations in
//! the same order and agree bit for bit.

// The coefficients, as published (`constants.rs`, which the C back end reads too).
kernel_coefficients!(declare_constants);

/// The reduction and the kernels of `f64`, written once for the scalar and the vector paths:
/// `$x` is the argument's magnitude `|x|` (a number or a register), `$k` makes a constant of
/// that kind, and `$sub`, `$mul` are its operations and `$fma` its `a·b + c` (one rounding where
/// the build has FMA, two elsewhere, on every path alike). Gives `(shifted, sin r, cos r)`:
/// `k mod 4` is in the low bits of `shifted`. Every path runs these operations in this order,
/// which is why their results agree bit for bit.
macro_rules! reduce_and_evaluate_f64 {
    ($x:expr, $k:expr, $sub:expr, $mul:expr, $fma:expr) => {{
        let (x, k, sub, mul, fma) = ($x, $k, $sub, $mul, $fma);
        // One rounding where the build has FMA: the integer nearest the exact x·(2/π).
        let shifted = fma(x, k(core::f64::consts::FRAC_2_PI), k(SHIFT_F64));
        let n = sub(shifted, k(SHIFT_F64));

        // x − n·P1 and n·P2 are exact (`a`, then `s` exact below 2^-20, where r is small and
        // every bit counts; above, rounded once). n·P3 is rounded, but |r| > 400·|n·P3|: r is
        // within an ulp of x − k·π/2, relatively, over the whole fast range, even at the
        // hardest reductions (2^-60.5). Fusing the exact products with their subtractions
        // changes no bit, only the chain.
        let a = fma(n, k(-P1_F64), x);
        let s = fma(n, k(-P2_F64), a);
        let r = fma(n, k(-P3_F64), s);

        // fdlibm's polynomials, `z` squared from `s`, a step before `r` (it only feeds terms of
        // order r³ and r², which |r·n·P3| < 4e-19 changes by under 0.003 ulp of the result),
        // evaluated as (p1 + z·p2) + z²·((p3 + z·p4) + z²·(p5 + z·p6)): a depth of two
        // multiply-adds from `z²` as in Estrin's form, without its z⁴, and one more for the
        // result.
        let z = mul(s, s);
        let z2 = mul(z, z);
        let pair = |p: f64, q: f64| fma(z, k(q), k(p));
        let sin_poly = fma(
            z2,
            fma(z2, pair(S5_F64, S6_F64), pair(S3_F64, S4_F64)),
            pair(S1_F64, S2_F64),
        );
        // cos r = 1 + z·(−1/2 + C1·z + … + C6·z⁶): one rounding at the result's scale, where
        // 1 − z/2 rounded apart would be a second. Its seven terms in Estrin's form, with z⁴
        // (one multiplication more): as deep as the sine's, where nesting in z² took one
        // multiply-add more, which the generated code, waiting for its sines and cosines,
        // waited for too (`docs/performance.md`, 2026-11-30).
        let z4 = mul(z2, z2);
        let cos_poly = fma(
            z4,
            fma(z2, k(C6_F64), pair(C4_F64, C5_F64)),
            fma(z2, pair(C2_F64, C3_F64), pair(-0.5, C1_F64)),
        );
        let sin_r = fma(mul(r, z), sin_poly, r);
        let cos_r = fma(z, cos_poly, k(1.0));
        (shifted, sin_r, cos_r)
    }};
}

/// [`reduce_and_evaluate_f64`] for `f32`.
macro_rules! reduce_and_evaluate_f32 {
    ($x:expr, $k:expr, $add:expr, $sub:expr, $mul:expr, $fma:expr) => {{
        let (x, k, add, sub, mul, fma) = ($x, $k, $add, $sub, $mul, $fma);
        // One rounding where the build has FMA: the integer nearest the exact x·(2/π).
        let shifted = fma(x, k(core::f32::consts::FRAC_2_PI), k(SHIFT_F32));
        let n = sub(shifted, k(SHIFT_F32));

        // x − n·P1, n·P2, n·P3 are exact. a − b is exact below 2^-5 (grid 2^-29), and above it
        // |a| > |b|: Fast2Sum. s − c has no such margin: TwoSum. |r| > 400·|n·P4|: Fast2Sum.
        // The errors go into `r_lo`, off the critical path.
        // Exact products: fusing them with their subtraction changes no bit, only the chain.
        let a = fma(n, k(-P1_F32), x);
        let b = mul(n, k(P2_F32));
        let c = mul(n, k(P3_F32));
        let d = mul(n, k(P4_F32));
        let s = fma(n, k(-P2_F32), a);
        let e1 = sub(sub(a, s), b);
        let t = fma(n, k(-P3_F32), s);
        let t_s = sub(t, s);
        let e2 = sub(sub(s, sub(t, t_s)), add(c, t_s));
        let r = sub(t, d);
        let r_lo = add(sub(sub(t, r), d), add(e1, e2));

        // `z` from `t`, a step before `r = t − n·P4`: a change under |r·n·P4| < 2e-10, 0.003
        // ulp of the result (as for f64).
        let z = mul(t, t);
        let z2 = mul(z, z);
        let pair = |p: f32, q: f32| fma(z, k(q), k(p));
        let sin_poly = fma(z2, pair(S3_F32, S4_F32), pair(S1_F32, S2_F32));
        let cos_poly = fma(z2, k(C3_F32), pair(C1_F32, C2_F32));
        let half_z = mul(k(0.5), z);
        let w = sub(k(1.0), half_z);
        let sin_r = add(r, fma(mul(r, z), sin_poly, mul(r_lo, w)));
        let cos_r = add(
            w,
            sub(
                fma(z2, cos_poly, sub(sub(k(1.0), w), half_z)),
                mul(r, r_lo),
            ),
        );
        (shifted, sin_r, cos_r)
    }};
}

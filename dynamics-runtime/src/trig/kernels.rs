//! The polynomial kernels on [−π/4, π/4] and the one body of reduction and kernels that
//! every path (scalar, SSE2, AVX2) expands, so that all of them run the same operations in
//! the same order and agree bit for bit.

// The coefficients, as published (`constants.rs`, which the C back end reads too).
kernel_coefficients!(declare_constants);

/// The reduction and the kernels of `f64`, written once for the scalar and the vector paths:
/// `$x` is the argument (a number or a register), `$k` makes a constant of that kind, and
/// `$add`, `$sub`, `$mul` are its operations and `$fma` its `a·b + c` (one rounding where the
/// build has FMA, two elsewhere, on every path alike). Gives `(shifted, sin r, cos r)`:
/// `k mod 4` is in the low bits of `shifted`. Every path runs these operations in this order,
/// which is why their results agree bit for bit.
macro_rules! reduce_and_evaluate_f64 {
    ($x:expr, $k:expr, $add:expr, $sub:expr, $mul:expr, $fma:expr) => {{
        let (x, k, add, sub, mul, fma) = ($x, $k, $add, $sub, $mul, $fma);
        // One rounding where the build has FMA: the integer nearest the exact x·(2/π).
        let shifted = fma(x, k(core::f64::consts::FRAC_2_PI), k(SHIFT_F64));
        let n = sub(shifted, k(SHIFT_F64));

        // x − n·P1, n·P2 are exact. Their difference is exact below 2^-20 (both lie on the
        // grid 2^-73); above, |x − n·P1| > |n·P2|, so Fast2Sum recovers its rounding error `e`.
        // Then |r| > 400·|n·P3| over the whole range, so the second Fast2Sum is valid too. `e`
        // goes into `r_lo` rather than `r`, off the critical path (|r_lo| stays below an ulp
        // of `r`).
        // Exact products: fusing them with their subtraction changes no bit, only the chain.
        let a = fma(n, k(-P1_F64), x);
        let b = mul(n, k(P2_F64));
        let c = mul(n, k(P3_F64));
        let s = fma(n, k(-P2_F64), a);
        let e = sub(sub(a, s), b);
        let r = sub(s, c);
        let r_lo = add(sub(sub(s, r), c), e);

        // The polynomials in Estrin's scheme, `fma(a, b, c) = a·b + c` fused where the build
        // has FMA: a shorter chain from the argument to the result. `z` is squared from `s`, a
        // step before `r = s − n·P3`: it only feeds terms of order r³ and r², which it changes by
        // |r·n·P3| < 4e-19, under 0.003 ulp of the result.
        let z = mul(s, s);
        let z2 = mul(z, z);
        let z4 = mul(z2, z2);
        let pair = |p: f64, q: f64| fma(z, k(q), k(p));
        let sin_poly = fma(
            z4,
            pair(S5_F64, S6_F64),
            fma(z2, pair(S3_F64, S4_F64), pair(S1_F64, S2_F64)),
        );
        let cos_poly = fma(
            z4,
            pair(C5_F64, C6_F64),
            fma(z2, pair(C3_F64, C4_F64), pair(C1_F64, C2_F64)),
        );
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

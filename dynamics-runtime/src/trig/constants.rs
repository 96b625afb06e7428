// The constants of the sine and cosine kernels: the one place that spells them.
//
// `reduction_constants!(callback)` and `kernel_coefficients!(callback)` call `callback! { rows }`,
// a row `/// doc` then `NAME: type = literal;`, or `NAME: f32 = literal as f32;` for a coefficient
// published in double and rounded to float. The runtime declares them as constants
// (`reduction.rs`, `kernels.rs`); `dynamics-codegen` reads the same file (a symlink, `include!`d,
// hence no inner doc comment here) to write the C header's kernels (`emit_c/trig.rs`) with the
// same values, the decimal ones spelled as they are here.

/// The constants of Cody-Waite range reduction: `x = k·π/2 + r` with `k` the integer nearest
/// `x·2/π`, π/2 split into parts whose products with every `k` of the fast range are exact.
macro_rules! reduction_constants {
    ($callback:ident) => {
        $callback! {
            /// `1.5·2^52`: adding it rounds a double of magnitude below 2^51 to an integer, which
            /// lands in the low bits of the sum's representation (`2^51 + k`, so the two lowest
            /// bits are `k mod 4`).
            SHIFT_F64: f64 = 6_755_399_441_055_744.0;
            /// `1.5·2^23`, the same for `f32`.
            SHIFT_F32: f32 = 12_582_912.0;

            /// `f64`: below this, `(x, 1)` is the correctly rounded result (`x³/6` and `x²/2` are
            /// under half an ulp of `x` and of 1). 2^-27. The C header's branch for tiny
            /// arguments; the runtime's kernel gives the same results without one.
            #[allow(dead_code)]
            TINY_F64: f64 = 7.450_580_596_923_828e-9;
            /// `f64`: the fast path's bound, 2^16 (`|k| ≤ 41722 < 2^16`).
            BOUND_F64: f64 = 65_536.0;
            /// `f32`: 2^-12, as [`TINY_F64`].
            TINY_F32: f32 = 2.441_406_25e-4;
            /// `f32`: the fast path's bound, 2^12 (`|k| ≤ 2608 < 2^12`).
            BOUND_F32: f32 = 4_096.0;

            // π/2 = P1 + P2 + P3 + 5.3e-40 for f64. P1 and P2 have 35 significant bits, so k·P1
            // and k·P2 are exact for |k| < 2^18.
            /// `0x1.921fb5444p+0`
            P1_F64: f64 = 1.570_796_326_792_333_3;
            /// `0x1.68c234c4cp-39`
            P2_F64: f64 = 2.563_344_151_583_955_8e-12;
            /// `0x1.98a2e03707345p-77`
            P3_F64: f64 = 1.056_299_906_698_742_8e-23;

            // π/2 = P1 + P2 + P3 + P4 + 2.0e-21 for f32. P1, P2 and P3 have 12 significant bits,
            // so their products with |k| < 2^12 are exact.
            /// `0x1.922p+0`
            P1_F32: f32 = 1.570_800_781_25;
            /// `-0x1.2aep-18`
            P2_F32: f32 = -4.453_584_551_811_218e-6;
            /// `-0x1.deap-31`
            P3_F32: f32 = -8.706_138_032_721_356e-10;
            /// `0x1.184698p-44`
            P4_F32: f32 = 6.223_371_969_669_989e-14;
        }
    };
}

/// The coefficients of the polynomial kernels on [−π/4, π/4], as published.
macro_rules! kernel_coefficients {
    ($callback:ident) => {
        $callback! {
            // fdlibm k_sin.c: sin r ≈ r + S1·r³ + … + S6·r¹³ on [−π/4, π/4].
            S1_F64: f64 = -1.666_666_666_666_663_243_48e-1;
            S2_F64: f64 = 8.333_333_333_322_489_461_24e-3;
            S3_F64: f64 = -1.984_126_982_985_794_931_34e-4;
            S4_F64: f64 = 2.755_731_370_707_006_767_89e-6;
            S5_F64: f64 = -2.505_076_025_340_686_341_95e-8;
            S6_F64: f64 = 1.589_690_995_211_550_102_21e-10;
            // fdlibm k_cos.c: cos r ≈ 1 − r²/2 + C1·r⁴ + … + C6·r¹² on [−π/4, π/4].
            C1_F64: f64 = 4.166_666_666_666_660_190_37e-2;
            C2_F64: f64 = -1.388_888_888_887_410_957_49e-3;
            C3_F64: f64 = 2.480_158_728_947_672_941_78e-5;
            C4_F64: f64 = -2.755_731_435_139_066_330_35e-7;
            C5_F64: f64 = 2.087_572_321_298_174_827_90e-9;
            C6_F64: f64 = -1.135_964_755_778_819_482_65e-11;

            // FreeBSD k_sinf.c (|sin(x)/x − s(x)| < 2^-37.5) and k_cosf.c (|cos(x) − c(x)| <
            // 2^-34.1), rounded to f32; their C0 = −0.4999999973 rounds to −1/2.
            S1_F32: f32 = -0.166_666_666_416_265_235_595_f64 as f32;
            S2_F32: f32 = 0.008_333_329_385_889_463_175_6_f64 as f32;
            S3_F32: f32 = -0.000_198_393_348_360_966_317_347_f64 as f32;
            S4_F32: f32 = 0.000_002_718_311_493_989_821_906_4_f64 as f32;
            C1_F32: f32 = 0.041_666_623_323_739_063_189_4_f64 as f32;
            C2_F32: f32 = -0.001_388_676_377_460_992_946_92_f64 as f32;
            C3_F32: f32 = 0.000_024_390_448_796_277_409_065_4_f64 as f32;
        }
    };
}

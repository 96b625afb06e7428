//! Cody-Waite range reduction's constants: `x = k·π/2 + r` with `k` the integer nearest
//! `x·2/π`, π/2 split into parts whose products with every `k` of the fast range are exact.
//! The reduction itself is written once, with the kernels, in [`super::kernels`]; the constants
//! are spelled in `constants.rs`, which `dynamics-codegen` writes the C header's kernels from.

// The constants are spelled in `constants.rs`, which the C back end reads too.
reduction_constants!(declare_constants);

#[cfg(test)]
mod tests {
    use super::*;

    /// Significant bits of a finite, nonzero `f64` (its `f32`s are exactly `f64`s).
    fn significant_bits(x: f64) -> u32 {
        let mantissa = (x.to_bits() & ((1 << 52) - 1)) | (1 << 52);
        53 - mantissa.trailing_zeros()
    }

    #[test]
    fn parts_of_half_pi_are_the_analysed_ones() {
        // The bit patterns the exhaustive analysis used.
        assert_eq!(P1_F64.to_bits(), 0x3FF9_21FB_5444_0000);
        assert_eq!(P2_F64.to_bits(), 0x3D86_8C23_4C4C_0000);
        assert_eq!(P3_F64.to_bits(), 0x3B29_8A2E_0370_7345);
        assert_eq!(P1_F32.to_bits(), 0x3FC9_1000);
        assert_eq!(P2_F32.to_bits(), 0xB695_7000);
        assert_eq!(P3_F32.to_bits(), 0xB06F_5000);
        assert_eq!(P4_F32.to_bits(), 0x298C_234C);
        // k·P is exact for |k| < 2^16 (f64) and 2^12 (f32).
        assert!(significant_bits(P1_F64) + 16 <= 53 && significant_bits(P2_F64) + 16 <= 53);
        for p in [P1_F32, P2_F32, P3_F32] {
            assert!(significant_bits(f64::from(p)) + 12 <= 24);
        }
        // The largest k of the fast range stays below those limits.
        assert!((BOUND_F64 * core::f64::consts::FRAC_2_PI).round() < 65_536.0);
        assert!((BOUND_F32 * core::f32::consts::FRAC_2_PI).round() < 4_096.0);
        // And the sum is π/2 to the working precision.
        assert_eq!(P1_F64 + P2_F64, core::f64::consts::FRAC_PI_2);
        assert_eq!(P1_F32 + P2_F32 + P3_F32, core::f32::consts::FRAC_PI_2);
    }

    #[test]
    fn thresholds_are_powers_of_two() {
        assert_eq!(TINY_F64, 2f64.powi(-27));
        assert_eq!(TINY_F32, 2f32.powi(-12));
        assert_eq!(SHIFT_F64, 1.5 * 2f64.powi(52));
        assert_eq!(SHIFT_F32, 1.5 * 2f32.powi(23));
    }
}

//! Cody-Waite range reduction's constants: `x = k·π/2 + r` with `k` the integer nearest
//! `x·2/π`, π/2 split into parts whose products with every `k` of the fast range are exact.
//! The reduction itself is written once, with the kernels, in [`super::kernels`].

/// `1.5·2^52`: adding it rounds a double of magnitude below 2^51 to an integer, which lands
/// in the low bits of the sum's representation (`2^51 + k`, so the two lowest bits are
/// `k mod 4`).
pub(super) const SHIFT_F64: f64 = 6_755_399_441_055_744.0;
/// `1.5·2^23`, the same for `f32`.
pub(super) const SHIFT_F32: f32 = 12_582_912.0;

/// `f64`: below this, `(x, 1)` is the correctly rounded result (`x³/6` and `x²/2` are under
/// half an ulp of `x` and of 1).
pub(super) const TINY_F64: f64 = 7.450_580_596_923_828e-9; // 2^-27
/// `f64`: the fast path's bound, 2^16 (`|k| ≤ 41722 < 2^16`).
pub(super) const BOUND_F64: f64 = 65_536.0;
/// `f32`: 2^-12, as [`TINY_F64`].
pub(super) const TINY_F32: f32 = 2.441_406_25e-4;
/// `f32`: the fast path's bound, 2^12 (`|k| ≤ 2608 < 2^12`).
pub(super) const BOUND_F32: f32 = 4_096.0;

// π/2 = P1 + P2 + P3 + 5.3e-40 for f64. P1 and P2 have 35 significant bits, so k·P1 and k·P2
// are exact for |k| < 2^18.
pub(super) const P1_F64: f64 = 1.570_796_326_792_333_3; // 0x1.921fb5444p+0
pub(super) const P2_F64: f64 = 2.563_344_151_583_955_8e-12; // 0x1.68c234c4cp-39
pub(super) const P3_F64: f64 = 1.056_299_906_698_742_8e-23; // 0x1.98a2e03707345p-77

// π/2 = P1 + P2 + P3 + P4 + 2.0e-21 for f32. P1, P2 and P3 have 12 significant bits, so their
// products with |k| < 2^12 are exact.
pub(super) const P1_F32: f32 = 1.570_800_781_25; // 0x1.922p+0
pub(super) const P2_F32: f32 = -4.453_584_551_811_218e-6; // -0x1.2aep-18
pub(super) const P3_F32: f32 = -8.706_138_032_721_356e-10; // -0x1.deap-31
pub(super) const P4_F32: f32 = 6.223_371_969_669_989e-14; // 0x1.184698p-44

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

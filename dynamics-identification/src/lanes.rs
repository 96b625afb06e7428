//! Four samples at once: the tapes of the command line (the regressor of `identify` and
//! `excite`) evaluated on the runtime's [`F64x4`], one sample per lane, each operation one
//! vector instruction where the build has AVX2 (two SSE2 instructions without).
//!
//! Each lane computes what `f64` computes for its sample, operation for operation, but for the
//! sines and cosines: the runtime's kernels (those of the generated code) rather than the
//! platform's `libm`, which may differ in the last bit.

use dynamics_codegen::pipeline::TapeScalar;
use dynamics_runtime::{F64x4, Real};
use std::ops::{Add, Mul, Neg};

/// The number of samples evaluated at once.
pub const LANES: usize = 4;

/// Four `f64`, one per sample.
#[derive(Clone, Copy, Debug)]
pub struct Four(pub F64x4);

impl Four {
    /// Lane `l` of each sample's value `x(l)`.
    pub fn from_fn(x: impl FnMut(usize) -> f64) -> Four {
        Four(F64x4::from_array(core::array::from_fn(x)))
    }
    /// The four values.
    pub fn lanes(self) -> [f64; LANES] {
        self.0.to_array()
    }
}

impl Add for Four {
    type Output = Four;
    fn add(self, other: Four) -> Four {
        Four(self.0 + other.0)
    }
}

impl Mul for Four {
    type Output = Four;
    fn mul(self, other: Four) -> Four {
        Four(self.0 * other.0)
    }
}

impl Neg for Four {
    type Output = Four;
    fn neg(self) -> Four {
        Four(-self.0)
    }
}

impl TapeScalar for Four {
    fn splat(x: f64) -> Four {
        Four(F64x4::splat(x))
    }
    fn recip(self) -> Four {
        Four(F64x4::ONE / self.0)
    }
    fn sin(self) -> Four {
        Four(Real::sin(self.0))
    }
    fn cos(self) -> Four {
        Four(Real::cos(self.0))
    }
    fn sign(self) -> Four {
        Four(Real::sign(self.0))
    }
    fn tanh(self) -> Four {
        Four(Real::tanh(self.0))
    }
}

//! The results of the opt-in [`DynamicsDerivatives`](crate::DynamicsDerivatives) methods, for
//! model-predictive control and optimal control: the derivatives of
//! `τ = M(q) q̈ + C(q, q̇) q̇ + g(q) + f(q̇)` (eq. 6.46) and of `q̈ = M⁻¹(τ − C q̇ − g − f)`.
//!
//! Generic over the matrix type `Mat` (and vector type `Vec`), so that the nalgebra wrappers
//! return the same fields as `SMatrix` and `SVector`.

/// `∂τ/∂q` and `∂τ/∂q̇` at `(q, q̇, q̈)`: row `i`, column `j` is `∂τ_i/∂q_j` (Pinocchio's
/// `computeRNEADerivatives`). `∂τ/∂q̈` is `M(q)`, [`Dynamics::mass_matrix`](crate::Dynamics).
/// In memory (`repr(C)`): `dtau_dq`, then `dtau_dqd`, as a C caller's `double[2][N][N]`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C)]
pub struct InverseDynamicsDerivatives<Mat> {
    /// `∂τ/∂q`.
    pub dtau_dq: Mat,
    /// `∂τ/∂q̇`: `2 C(q, q̇)` plus the friction's slope on the diagonal.
    pub dtau_dqd: Mat,
}

impl<Mat> InverseDynamicsDerivatives<Mat> {
    /// From the generated code's blocks `[∂τ/∂q, ∂τ/∂q̇]`.
    #[doc(hidden)]
    #[inline(always)]
    pub fn from_blocks([dtau_dq, dtau_dqd]: [Mat; 2]) -> Self {
        Self { dtau_dq, dtau_dqd }
    }

    /// Both matrices through `f` (to nalgebra's types, for instance).
    #[inline]
    pub fn map<U>(self, mut f: impl FnMut(Mat) -> U) -> InverseDynamicsDerivatives<U> {
        InverseDynamicsDerivatives {
            dtau_dq: f(self.dtau_dq),
            dtau_dqd: f(self.dtau_dqd),
        }
    }
}

/// `q̈` and its derivatives at `(q, q̇, τ)`: row `i`, column `j` of a matrix is `∂q̈_i/∂x_j`
/// (Pinocchio's `computeABADerivatives`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ForwardDynamicsDerivatives<Vec, Mat> {
    /// `q̈ = M⁻¹(τ − C q̇ − g − f)`, as `forward_dynamics` gives it.
    pub qdd: Vec,
    /// `∂q̈/∂q = −M⁻¹ ∂τ/∂q` at this `q̈`.
    pub dqdd_dq: Mat,
    /// `∂q̈/∂q̇ = −M⁻¹ ∂τ/∂q̇`.
    pub dqdd_dqd: Mat,
    /// `∂q̈/∂τ = M⁻¹`.
    pub dqdd_dtau: Mat,
}

impl<Vec, Mat> ForwardDynamicsDerivatives<Vec, Mat> {
    /// From the generated code's `q̈` and blocks `[∂q̈/∂q, ∂q̈/∂q̇, ∂q̈/∂τ]`.
    #[doc(hidden)]
    #[inline(always)]
    pub fn from_parts((qdd, [dqdd_dq, dqdd_dqd, dqdd_dtau]): (Vec, [Mat; 3])) -> Self {
        Self {
            qdd,
            dqdd_dq,
            dqdd_dqd,
            dqdd_dtau,
        }
    }

    /// The vector through `v` and the three matrices through `m`.
    #[inline]
    pub fn map<V, U>(
        self,
        v: impl FnOnce(Vec) -> V,
        mut m: impl FnMut(Mat) -> U,
    ) -> ForwardDynamicsDerivatives<V, U> {
        ForwardDynamicsDerivatives {
            qdd: v(self.qdd),
            dqdd_dq: m(self.dqdd_dq),
            dqdd_dqd: m(self.dqdd_dqd),
            dqdd_dtau: m(self.dqdd_dtau),
        }
    }
}

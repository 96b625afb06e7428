//! From states to lanes and back: [`gather`] puts `L` states side by side, [`SplitLanes`]
//! takes a result of lanes apart into `L` results.

use super::{F32x4, F32x8, F64x2, F64x4, F64x8, Lanes};
use crate::{ForwardDynamicsDerivatives, InverseDynamicsDerivatives, Pose};

/// `L` states of `N` joint values (`states[l]` is lane `l`'s) as `N` lane values, the
/// argument of a generated method: lane `l` of element `j` is `states[l][j]`.
///
/// ```
/// use dynamics_runtime::lanes::{gather, F64x4, SplitLanes};
/// let q: [F64x4; 2] = gather(&[[0.0, 1.0], [0.1, 1.1], [0.2, 1.2], [0.3, 1.3]]);
/// assert_eq!(q[1].to_array(), [1.0, 1.1, 1.2, 1.3]);
/// assert_eq!(q.split_lanes()[2], [0.2, 1.2]);
/// ```
#[must_use]
#[inline(always)]
pub fn gather<V: Lanes<L>, const L: usize, const N: usize>(states: &[[V::Scalar; N]; L]) -> [V; N] {
    core::array::from_fn(|j| V::from_array(core::array::from_fn(|l| states[l][j])))
}

/// A value of lanes (a lane type, or arrays, poses or derivatives of them) taken apart into
/// one value per lane, of the same shape in the lanes' scalar.
pub trait SplitLanes<const L: usize> {
    /// The value of one lane: `f64` for `F64x4`, `[[f64; N]; N]` for `[[F64x4; N]; N]`, ….
    type Single: Copy;
    /// The value of lane `l` (`l < L`).
    fn lane(&self, l: usize) -> Self::Single;
    /// The value of each lane, first to last.
    #[inline(always)]
    fn split_lanes(self) -> [Self::Single; L]
    where
        Self: Sized,
    {
        core::array::from_fn(|l| self.lane(l))
    }
    /// Writes lane `l` into `outs[l]`, for every lane.
    #[inline(always)]
    fn write_lanes(&self, outs: [&mut Self::Single; L]) {
        for (l, out) in outs.into_iter().enumerate() {
            *out = self.lane(l);
        }
    }
    /// Writes lane `l` of `items[j]` into `outs[l][j]`: an array of these, each lane's part
    /// gathered into its own array (a lane type overrides it with whole rows at a time).
    #[inline(always)]
    fn write_array<const N: usize>(items: &[Self; N], mut outs: [&mut [Self::Single; N]; L])
    where
        Self: Sized,
    {
        for (j, item) in items.iter().enumerate() {
            item.write_lanes(outs.each_mut().map(|out| &mut out[j]));
        }
    }
    /// Whether it holds a value for every lane: false for an `Err` (a solve whose pivot test
    /// failed in at least one lane, which then holds no value for any).
    #[inline(always)]
    fn is_complete(&self) -> bool {
        true
    }
}

/// A solve's result: `Ok` split lane by lane; `Err` (at least one lane's pivot not positive)
/// the same error for every lane ([`SplitLanes::is_complete`] tells it apart).
impl<X: SplitLanes<L>, E: Copy, const L: usize> SplitLanes<L> for Result<X, E> {
    type Single = Result<X::Single, E>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        match self {
            Ok(x) => Ok(x.lane(l)),
            Err(e) => Err(*e),
        }
    }
    /// `Ok` written in place where every output already holds an `Ok` (a group's results
    /// written over again, whole rows at a time), else lane by lane.
    #[inline(always)]
    fn write_lanes(&self, outs: [&mut Self::Single; L]) {
        match (self, outs.iter().all(|out| out.is_ok())) {
            (Ok(x), true) => x.write_lanes(outs.map(|out| match out {
                Ok(out) => out,
                Err(_) => unreachable!("every output holds an `Ok`"),
            })),
            _ => {
                for (l, out) in outs.into_iter().enumerate() {
                    *out = self.lane(l);
                }
            }
        }
    }
    #[inline(always)]
    fn is_complete(&self) -> bool {
        self.is_ok()
    }
}

/// [`SplitLanes`] of a lane type: its array.
macro_rules! split_lane_type {
    ($($name:ident: $e:ident x $lanes:literal),*) => {$(
        impl SplitLanes<$lanes> for $name {
            type Single = $e;
            #[inline(always)]
            fn lane(&self, l: usize) -> $e {
                self.to_array()[l]
            }
            #[inline(always)]
            fn split_lanes(self) -> [$e; $lanes] {
                self.to_array()
            }
            #[inline(always)]
            fn write_array<const N: usize>(items: &[Self; N], mut outs: [&mut [$e; N]; $lanes]) {
                // Blocks of as many elements as lanes, transposed whole (`Lanes::transpose`),
                // each lane's row then one store; the last, partial block padded with its last
                // element, and only its elements stored.
                for j in (0..N).step_by($lanes) {
                    let block = core::array::from_fn(|i| items[(j + i).min(N - 1)]);
                    let rows = <Self as Lanes<$lanes>>::transpose(block);
                    let end = (j + $lanes).min(N);
                    for (out, row) in outs.iter_mut().zip(rows) {
                        out[j..end].copy_from_slice(&row.to_array()[..end - j]);
                    }
                }
            }
        }
    )*};
}

split_lane_type!(F64x8: f64 x 8, F64x4: f64 x 4, F64x2: f64 x 2, F32x8: f32 x 8, F32x4: f32 x 4);

impl<X: SplitLanes<L>, const L: usize, const N: usize> SplitLanes<L> for [X; N] {
    type Single = [X::Single; N];
    #[inline(always)]
    fn lane(&self, l: usize) -> [X::Single; N] {
        core::array::from_fn(|j| self[j].lane(l))
    }
    #[inline(always)]
    fn write_lanes(&self, outs: [&mut [X::Single; N]; L]) {
        X::write_array(self, outs);
    }
}

impl<X: SplitLanes<L>, const L: usize> SplitLanes<L> for Pose<X> {
    type Single = Pose<X::Single>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Pose<X::Single> {
        Pose {
            rotation: self.rotation.lane(l),
            position: self.position.lane(l),
        }
    }
    #[inline(always)]
    fn write_lanes(&self, mut outs: [&mut Self::Single; L]) {
        self.rotation
            .write_lanes(outs.each_mut().map(|out| &mut out.rotation));
        self.position.write_lanes(outs.map(|out| &mut out.position));
    }
}

impl<X: SplitLanes<L>, const L: usize> SplitLanes<L> for InverseDynamicsDerivatives<X> {
    type Single = InverseDynamicsDerivatives<X::Single>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        InverseDynamicsDerivatives::from_blocks([self.dtau_dq.lane(l), self.dtau_dqd.lane(l)])
    }
    #[inline(always)]
    fn write_lanes(&self, mut outs: [&mut Self::Single; L]) {
        self.dtau_dq
            .write_lanes(outs.each_mut().map(|out| &mut out.dtau_dq));
        self.dtau_dqd.write_lanes(outs.map(|out| &mut out.dtau_dqd));
    }
}

impl<Y: SplitLanes<L>, X: SplitLanes<L>, const L: usize> SplitLanes<L>
    for ForwardDynamicsDerivatives<Y, X>
{
    type Single = ForwardDynamicsDerivatives<Y::Single, X::Single>;
    #[inline(always)]
    fn lane(&self, l: usize) -> Self::Single {
        let blocks = [
            self.dqdd_dq.lane(l),
            self.dqdd_dqd.lane(l),
            self.dqdd_dtau.lane(l),
        ];
        ForwardDynamicsDerivatives::from_parts((self.qdd.lane(l), blocks))
    }
    #[inline(always)]
    fn write_lanes(&self, mut outs: [&mut Self::Single; L]) {
        self.qdd
            .write_lanes(outs.each_mut().map(|out| &mut out.qdd));
        self.dqdd_dq
            .write_lanes(outs.each_mut().map(|out| &mut out.dqdd_dq));
        self.dqdd_dqd
            .write_lanes(outs.each_mut().map(|out| &mut out.dqdd_dqd));
        self.dqdd_dtau
            .write_lanes(outs.map(|out| &mut out.dqdd_dtau));
    }
}

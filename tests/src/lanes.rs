//! Lane types against the single-state path, bit for bit: every method of a robot evaluated
//! once on `L` states in lanes and `L` times on one state, each lane's result compared with its
//! state's by the bits of every number (`to_bits`), a NaN as NaN (its sign is the compiler's).

use dynamics_runtime::lanes::{gather, Lanes, SplitLanes};
use dynamics_runtime::{
    Dynamics, DynamicsDerivatives, DynamicsRegressor, ForwardDynamicsDerivatives,
    InverseDynamicsDerivatives, NotPositiveDefinite, Pose, Real,
};
use dynamics_test_support::Rng;

/// The bits of every number of a result, in order.
pub trait Bits {
    /// Appends the bits of every number to `out`.
    fn bits(&self, out: &mut Vec<u64>);
    /// Appends every number to `out`.
    fn values(&self, out: &mut Vec<f64>);
}

// A NaN as the one NaN: its sign is the compiler's choice, which may differ between the lanes'
// code and the scalar's (`dynamics_runtime::lanes`).
impl Bits for f64 {
    fn bits(&self, out: &mut Vec<u64>) {
        out.push(if self.is_nan() { f64::NAN } else { *self }.to_bits());
    }
    fn values(&self, out: &mut Vec<f64>) {
        out.push(*self);
    }
}

impl Bits for f32 {
    fn bits(&self, out: &mut Vec<u64>) {
        out.push(u64::from(
            if self.is_nan() { f32::NAN } else { *self }.to_bits(),
        ));
    }
    fn values(&self, out: &mut Vec<f64>) {
        out.push(f64::from(*self));
    }
}

impl<X: Bits, const N: usize> Bits for [X; N] {
    fn bits(&self, out: &mut Vec<u64>) {
        self.iter().for_each(|x| x.bits(out));
    }
    fn values(&self, out: &mut Vec<f64>) {
        self.iter().for_each(|x| x.values(out));
    }
}

impl<X: Bits> Bits for Pose<X> {
    fn bits(&self, out: &mut Vec<u64>) {
        self.rotation.iter().for_each(|r| r.bits(out));
        self.position.bits(out);
    }
    fn values(&self, out: &mut Vec<f64>) {
        self.rotation.iter().for_each(|r| r.values(out));
        self.position.values(out);
    }
}

impl<X: Bits> Bits for InverseDynamicsDerivatives<X> {
    fn bits(&self, out: &mut Vec<u64>) {
        self.dtau_dq.bits(out);
        self.dtau_dqd.bits(out);
    }
    fn values(&self, out: &mut Vec<f64>) {
        self.dtau_dq.values(out);
        self.dtau_dqd.values(out);
    }
}

impl<Y: Bits, X: Bits> Bits for ForwardDynamicsDerivatives<Y, X> {
    fn bits(&self, out: &mut Vec<u64>) {
        self.qdd.bits(out);
        [&self.dqdd_dq, &self.dqdd_dqd, &self.dqdd_dtau]
            .iter()
            .for_each(|m| m.bits(out));
    }
    fn values(&self, out: &mut Vec<f64>) {
        self.qdd.values(out);
        [&self.dqdd_dq, &self.dqdd_dqd, &self.dqdd_dtau]
            .iter()
            .for_each(|m| m.values(out));
    }
}

/// The bits of every number of `x`.
fn bits<X: Bits>(x: &X) -> Vec<u64> {
    let mut out = Vec::new();
    x.bits(&mut out);
    out
}

/// Each lane of `lanes` has the bits of its state's `singles`.
///
/// # Panics
/// If a lane differs from its state's result.
pub fn same<X: SplitLanes<L>, const L: usize>(what: &str, lanes: X, singles: &[X::Single; L])
where
    X::Single: Bits,
{
    for (l, (lane, single)) in lanes.split_lanes().iter().zip(singles).enumerate() {
        assert_eq!(bits(lane), bits(single), "{what}, lane {l}");
    }
}

/// Whether a build computes the inverse dynamics' derivatives on the lanes of `V` by another
/// route than on one state (`Real::TANGENTS_IN_LANES`: tangents in lanes for `f64` and `f32`
/// with AVX-512, the columns one by one on the lane types), so that its lanes agree with their
/// states' results to rounding rather than bit for bit.
#[must_use]
pub fn routes_differ<V: Lanes<L>, const L: usize>() -> bool {
    <V::Scalar as Real>::TANGENTS_IN_LANES != <V as Real>::TANGENTS_IN_LANES
}

/// Each number of `a` within `tolerance · max(1, |b|)` of `b`'s.
///
/// # Panics
/// If one is not.
pub fn close_values<X: Bits>(what: &str, a: &X, b: &X, tolerance: f64) {
    let (mut x, mut y) = (Vec::new(), Vec::new());
    a.values(&mut x);
    b.values(&mut y);
    assert_eq!(x.len(), y.len(), "{what}");
    for (i, (x, y)) in x.iter().zip(&y).enumerate() {
        assert!(
            (x - y).abs() <= tolerance * y.abs().max(1.0),
            "{what}, number {i}: {x} against {y}"
        );
    }
}

/// Each lane of `lanes` within `tolerance` of its state's `singles` ([`close_values`]).
///
/// # Panics
/// If a lane is not.
pub fn close<X: SplitLanes<L>, const L: usize>(
    what: &str,
    lanes: X,
    singles: &[X::Single; L],
    tolerance: f64,
) where
    X::Single: Bits,
{
    for (l, (lane, single)) in lanes.split_lanes().iter().zip(singles).enumerate() {
        close_values(&format!("{what}, lane {l}"), lane, single, tolerance);
    }
}

/// A result of the methods that solve with `M`: `Ok` on lanes where every lane's state is
/// `Ok` (and then each lane equal to its state's), `Err` where at least one lane's is.
///
/// # Panics
/// If the lanes' result is not that.
pub fn same_solved<X: SplitLanes<L>, const L: usize>(
    what: &str,
    lanes: Result<X, NotPositiveDefinite>,
    singles: &[Result<X::Single, NotPositiveDefinite>; L],
) where
    X::Single: Bits,
{
    let failed = singles.iter().filter(|s| s.is_err()).count();
    match lanes {
        Ok(lanes) => {
            assert_eq!(failed, 0, "{what}: Ok on lanes where a lane fails");
            same(what, lanes, &singles.map(Result::unwrap));
        }
        Err(NotPositiveDefinite) => assert!(failed > 0, "{what}: Err on lanes, no lane fails"),
    }
}

/// [`same_solved`] where the lanes take another route than one state ([`routes_differ`]): each
/// `Ok` lane within `tolerance` times its state's largest number (at least 1) of that state's.
///
/// # Panics
/// If the lanes' result is not that.
pub fn close_solved<X: SplitLanes<L>, const L: usize>(
    what: &str,
    lanes: Result<X, NotPositiveDefinite>,
    singles: &[Result<X::Single, NotPositiveDefinite>; L],
    tolerance: f64,
) where
    X::Single: Bits,
{
    let failed = singles.iter().filter(|s| s.is_err()).count();
    let Ok(lanes) = lanes else {
        assert!(failed > 0, "{what}: Err on lanes, no lane fails");
        return;
    };
    assert_eq!(failed, 0, "{what}: Ok on lanes where a lane fails");
    for (l, (lane, single)) in lanes.split_lanes().iter().zip(singles).enumerate() {
        let single = single.as_ref().expect("checked Ok");
        let mut values = Vec::new();
        single.values(&mut values);
        let largest = values.iter().fold(1.0f64, |m, v| m.max(v.abs()));
        let scaled = tolerance * largest;
        close_values(&format!("{what}, lane {l}"), lane, single, scaled);
    }
}

/// `L` states of `N` values each, and the same as lanes.
pub struct States<V: Lanes<L>, const L: usize, const N: usize> {
    /// The states, one per lane.
    pub singles: [[V::Scalar; N]; L],
    /// The lanes.
    pub lanes: [V; N],
}

impl<V: Lanes<L>, const L: usize, const N: usize> States<V, L, N> {
    /// From the states.
    pub fn new(singles: [[V::Scalar; N]; L]) -> Self {
        Self {
            lanes: gather(&singles),
            singles,
        }
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(rng: &mut Rng, lo: f64, hi: f64) -> Self {
        let mut draw = || V::Scalar::from_f64(rng.range(lo, hi));
        Self::new(core::array::from_fn(|_| core::array::from_fn(|_| draw())))
    }
}

/// Positions, velocities, accelerations and a wrench of `L` random states, with lanes that take
/// the rarer paths: a velocity of +0 and one of −0 (friction's sign), and a position of 1e5
/// rad (the sines and cosines outside their fast range, one lane alone).
pub struct Motion<V: Lanes<L>, const L: usize, const N: usize> {
    /// `q`.
    pub q: States<V, L, N>,
    /// `q̇`.
    pub qd: States<V, L, N>,
    /// `q̈`.
    pub qdd: States<V, L, N>,
    /// A wrench at the hand.
    pub wrench: States<V, L, 6>,
}

impl<V: Lanes<L>, const L: usize, const N: usize> Motion<V, L, N> {
    /// Random states from `seed`.
    pub fn new(seed: u64) -> Self {
        let mut rng = Rng::new(seed);
        let mut q = States::<V, L, N>::uniform(&mut rng, -3.2, 3.2).singles;
        let mut qd = States::<V, L, N>::uniform(&mut rng, -2.0, 2.0).singles;
        let qdd = States::uniform(&mut rng, -3.0, 3.0);
        let wrench = States::uniform(&mut rng, -10.0, 10.0);
        qd[0][0] = V::Scalar::ZERO;
        qd[1][N - 1] = -V::Scalar::ZERO;
        q[L - 1][0] = V::Scalar::from_f64(1e5);
        Self {
            q: States::new(q),
            qd: States::new(qd),
            qdd,
            wrench,
        }
    }
}

/// `$robot.$method(args)` on the lanes and on each lane's state, compared with [`same`] (or
/// `$compare`).
macro_rules! compare {
    ($compare:ident, $robot:expr, $method:ident($($arg:expr),*)) => {{
        let lanes = $robot.$method($(&$arg.lanes),*);
        let singles: [_; L] = core::array::from_fn(|l| $robot.$method($(&$arg.singles[l]),*));
        $compare(stringify!($method), lanes, &singles);
    }};
    ($robot:expr, $method:ident($($arg:expr),*)) => {
        compare!(same, $robot, $method($($arg),*))
    };
}

/// Every method of [`Dynamics`] on lanes against one state at a time, with the forward
/// dynamics at the torques of the inverse dynamics.
///
/// # Panics
/// If a lane differs from its state's result.
pub fn dynamics<R, V, const L: usize, const N: usize>(robot: &R, m: &Motion<V, L, N>)
where
    R: Dynamics<N>,
    V: Lanes<L> + SplitLanes<L, Single = <V as Lanes<L>>::Scalar>,
    V::Scalar: Bits,
{
    let (q, qd, qdd, wrench) = (&m.q, &m.qd, &m.qdd, &m.wrench);
    compare!(robot, mass_matrix(q));
    compare!(robot, coriolis_matrix(q, qd));
    compare!(robot, coriolis_torques(q, qd));
    compare!(robot, gravity_torques(q));
    compare!(robot, bias_torques(q, qd));
    compare!(robot, inverse_dynamics(q, qd, qdd));
    compare!(robot, friction_torques(qd));
    compare!(robot, kinetic_energy(q, qd));
    compare!(robot, potential_energy(q));
    compare!(robot, hand_pose(q));
    compare!(robot, link_poses(q));
    compare!(robot, hand_jacobian_in_base(q));
    compare!(robot, hand_jacobian_in_hand(q));
    compare!(robot, hand_acceleration_bias_in_base(q, qd));
    compare!(robot, hand_acceleration_bias_in_hand(q, qd));
    compare!(robot, joint_torques_for_hand_wrench(q, wrench));
    compare!(robot, joint_torques_for_base_wrench(q, wrench));
    compare!(same_solved, robot, mass_matrix_inverse(q));
    let tau = States::<V, L, N>::new(
        robot
            .inverse_dynamics(&q.lanes, &qd.lanes, &qdd.lanes)
            .split_lanes(),
    );
    compare!(same_solved, robot, forward_dynamics(q, qd, tau));
}

/// [`DynamicsDerivatives`] on lanes against one state at a time.
///
/// # Panics
/// If a lane differs from its state's result.
pub fn derivatives<R, V, const L: usize, const N: usize>(robot: &R, m: &Motion<V, L, N>)
where
    R: DynamicsDerivatives<N>,
    V: Lanes<L> + SplitLanes<L, Single = <V as Lanes<L>>::Scalar>,
    V::Scalar: Bits,
{
    let (q, qd, qdd) = (&m.q, &m.qd, &m.qdd);
    // Relative to the largest entry's size; f32 to its precision.
    let tolerance = if core::mem::size_of::<V::Scalar>() == 8 {
        1e-12
    } else {
        1e-4
    };
    if routes_differ::<V, L>() {
        let lanes = robot.inverse_dynamics_derivatives(&q.lanes, &qd.lanes, &qdd.lanes);
        let singles: [_; L] = core::array::from_fn(|l| {
            robot.inverse_dynamics_derivatives(&q.singles[l], &qd.singles[l], &qdd.singles[l])
        });
        close("inverse_dynamics_derivatives", lanes, &singles, tolerance);
    } else {
        compare!(robot, inverse_dynamics_derivatives(q, qd, qdd));
    }
    let tau = States::<V, L, N>::new(
        robot
            .inverse_dynamics(&q.lanes, &qd.lanes, &qdd.lanes)
            .split_lanes(),
    );
    if routes_differ::<V, L>() {
        // A solve: M's condition number times the rounding of ∂τ.
        let within = |what: &str, lanes, singles: &[_; L]| {
            close_solved(what, lanes, singles, 1e3 * tolerance);
        };
        compare!(within, robot, forward_dynamics_derivatives(q, qd, tau));
    } else {
        compare!(same_solved, robot, forward_dynamics_derivatives(q, qd, tau));
    }
}

/// [`DynamicsRegressor`] on lanes against one state at a time.
///
/// # Panics
/// If a lane differs from its state's result.
pub fn regressor<R, V, const L: usize, const N: usize>(robot: &R, m: &Motion<V, L, N>)
where
    R: DynamicsRegressor<N>,
    V: Lanes<L> + SplitLanes<L, Single = <V as Lanes<L>>::Scalar>,
    V::Scalar: Bits,
{
    let (q, qd, qdd) = (&m.q, &m.qd, &m.qdd);
    compare!(robot, regressor(q, qd, qdd));
    compare!(robot, joint_regressor(qd, qdd));
}

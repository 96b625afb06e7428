//! A derivative-free minimisation of `f(x)`, x in `[−1, 1]^D` (a box the caller maps onto its
//! variables), within a budget of evaluations, deterministic for a seed:
//!
//! 1. **Random restarts**: a quarter of the budget (at least one) on points drawn uniformly in
//!    the box (xorshift64*, seeded); the first is the *initial guess* the report compares with.
//! 2. **Compass search** (Kolda, Lewis and Torczon, *Optimization by direct search*, SIAM Review
//!    45(3), 2003) from the best of them: each coordinate in turn is moved by `±Δ` (clamped to
//!    the box), and a move is kept if it lowers f; after a pass over every coordinate with no
//!    move kept, Δ is halved. It stops when the budget is spent or Δ falls below
//!    [`SMALLEST_STEP`].
//!
//! The condition number of a motion is not smooth (its extreme singular values cross) and has
//! many local minima: the restarts look widely, the compass search improves the best locally,
//! and neither needs a gradient. The budget is counted in evaluations, not seconds, so that a
//! seed gives the same result on any machine, however loaded.

/// The compass search's first step, in the box's units.
const FIRST_STEP: f64 = 0.25;

/// The step below which the compass search has converged.
pub const SMALLEST_STEP: f64 = 1e-3;

/// Uniform deviates from a seed (xorshift64*, Vigna 2016).
pub struct Random(u64);

impl Random {
    #[must_use]
    pub fn new(seed: u64) -> Random {
        // SplitMix64 of the seed: any seed, 0 included, gives a non-zero, well-mixed state.
        let mut z = seed.wrapping_add(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        Random((z ^ (z >> 31)).max(1))
    }

    /// Uniform in [−1, 1).
    pub fn symmetric(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        2.0 * (bits as f64 / (1u64 << 53) as f64) - 1.0
    }
}

/// What the search found.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The first point drawn, and f there.
    pub initial: (Vec<f64>, f64),
    /// The best point, and f there.
    pub best: (Vec<f64>, f64),
    /// Evaluations spent in the random restarts and in the compass search.
    pub restarts: usize,
    pub compass: usize,
    /// The compass step at the end (below [`SMALLEST_STEP`]: converged).
    pub step: f64,
}

/// Minimises `f` over `[−1, 1]^dimension` with at most `budget` evaluations (at least 1).
pub fn minimise(
    dimension: usize,
    seed: u64,
    budget: usize,
    mut f: impl FnMut(&[f64]) -> f64,
) -> Outcome {
    let mut random = Random::new(seed);
    let restarts = (budget / 4).max(1);
    let mut initial = None;
    let mut best: Option<(Vec<f64>, f64)> = None;
    for _ in 0..restarts {
        let x: Vec<f64> = (0..dimension).map(|_| random.symmetric()).collect();
        let value = f(&x);
        initial.get_or_insert_with(|| (x.clone(), value));
        if best.as_ref().map_or(true, |(_, b)| value < *b) {
            best = Some((x, value));
        }
    }
    let initial = initial.expect("at least one restart");
    let (mut x, mut value) = best.expect("at least one restart");
    let (mut step, mut compass) = (FIRST_STEP, 0);
    'search: while step >= SMALLEST_STEP {
        let mut moved = false;
        for j in 0..dimension {
            for direction in [1.0, -1.0] {
                if restarts + compass >= budget {
                    break 'search;
                }
                let old = x[j];
                x[j] = (old + direction * step).clamp(-1.0, 1.0);
                if x[j] == old {
                    continue;
                }
                compass += 1;
                let trial = f(&x);
                if trial < value {
                    value = trial;
                    moved = true;
                    break;
                }
                x[j] = old;
            }
        }
        if !moved {
            step /= 2.0;
        }
    }
    Outcome {
        initial,
        best: (x, value),
        restarts,
        compass,
        step,
    }
}

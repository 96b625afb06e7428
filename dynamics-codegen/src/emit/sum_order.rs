//! The order in which the terms of a sum are added, weighed by a latency model: the sum is
//! ready when its last addition is, so the terms ready first are added first (Huffman's
//! algorithm with the maximum in place of the sum), and a product is fused into a multiply-add
//! with the partial sum it meets.

/// Latencies in cycles, roughly those of current x86-64 and aarch64 cores, by which
/// [`sum_order`] weighs the orders of a sum's additions.
pub(super) const ADD_LATENCY: u32 = 3;
/// See [`ADD_LATENCY`].
const MUL_LATENCY: u32 = 3;
/// See [`ADD_LATENCY`].
const FMA_LATENCY: u32 = 4;

/// A term of a sum for [`sum_order`]: ready after `depth` operations (a product's own
/// included), subtracted or added, and whether it is a product that a fused multiply-add can
/// take.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct SumTerm {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub depth: u32,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub negative: bool,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fusable: bool,
}

/// One addition of [`sum_order`]: partial sums `a` and `b` (indices: the terms, then each
/// addition's result in turn), with `b` a product that a fused multiply-add takes if `fused`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub struct Addition {
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub a: usize,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub b: usize,
    #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
    pub fused: bool,
}

/// The order in which the terms of a sum are added: repeatedly the two that are ready first
/// (the first in the list among equals), as in Huffman's algorithm with the maximum in place
/// of the sum, weighed in cycles ([`ADD_LATENCY`]). A pair is one fused multiply-add if either
/// is a fusable product, which is then ready when its operands are: of two products, the
/// negative one if their signs differ (either sign fuses, `Emitter::combine` negating an
/// operand; fusing the negative one runs faster than choosing by the operands alone), else
/// the one whose operands come later. Gives the additions and the sum's depth in operations
/// (a fused multiply-add counting two, as in the flop counts).
///
/// Every order of n terms takes n − 1 additions. This one makes the last wait little, where
/// the order in which the algorithm met the terms may start with the latest and carry it
/// through all the others, and a chain of n terms ready together waits n − 1 operations where
/// pairs wait about log₂ n.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn sum_order(terms: &[SumTerm]) -> (Vec<Addition>, u32) {
    let mut additions = Vec::with_capacity(terms.len().saturating_sub(1));
    let depth = order(terms, |addition| additions.push(addition));
    (additions, depth)
}

/// The depth of [`sum_order`] alone, without its additions: what every sum's depth asks.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn sum_depth(terms: &[SumTerm]) -> u32 {
    order(terms, |_| {})
}

/// The indices of the two partial sums ready first, by `(cycles, index)` (at least two).
fn ready_first(ready: &[Partial]) -> (usize, usize) {
    let key = |p: &Partial| (p.cycles, p.index);
    let (mut first, mut second) = if key(&ready[0]) <= key(&ready[1]) {
        (0, 1)
    } else {
        (1, 0)
    };
    for (k, p) in ready.iter().enumerate().skip(2) {
        if key(p) < key(&ready[first]) {
            second = first;
            first = k;
        } else if key(p) < key(&ready[second]) {
            second = k;
        }
    }
    (first, second)
}

/// The two partial sums `x` (ready first) and `y` as added, `(a, b)`: `b` the product fused
/// if either is one (of two, the negative one where the signs differ, else the one whose
/// operands come later).
fn fused_last(x: Partial, y: Partial) -> (Partial, Partial) {
    match (x.operands, y.operands) {
        (Some(_), Some(_)) if x.negative != y.negative => {
            if x.negative {
                (y, x)
            } else {
                (x, y)
            }
        }
        (Some(i), Some(j)) if i > j => (y, x),
        (Some(_), None) => (y, x),
        _ => (x, y),
    }
}

/// A partial sum of [`order`]: ready after `cycles`, the `index`th of the terms and the
/// additions' results.
#[derive(Clone, Copy)]
struct Partial {
    cycles: u32,
    index: usize,
    depth: u32,
    negative: bool,
    /// When a fusable product's operands are ready.
    operands: Option<u32>,
}

/// The partial sums a sum of this many terms or fewer keeps on the stack.
const INLINE: usize = 16;

/// [`sum_order`]'s additions, each handed to `add` in turn, and the sum's depth. The two
/// partial sums ready first are found by a scan: their order is that of `(cycles, index)`,
/// unique per partial sum, so the list's own order does not matter.
fn order(terms: &[SumTerm], mut add: impl FnMut(Addition)) -> u32 {
    let partial = |(t, index): (&SumTerm, usize)| {
        let cycles = ADD_LATENCY * t.depth;
        Partial {
            cycles,
            index,
            depth: t.depth,
            negative: t.negative,
            operands: t.fusable.then(|| cycles.saturating_sub(MUL_LATENCY)),
        }
    };
    let empty = Partial {
        cycles: 0,
        index: 0,
        depth: 0,
        negative: false,
        operands: None,
    };
    let mut inline = [empty; INLINE];
    let mut spilled = Vec::new();
    let ready: &mut [Partial] = if terms.len() <= INLINE {
        &mut inline[..terms.len()]
    } else {
        spilled.extend(terms.iter().zip(0..).map(partial));
        &mut spilled
    };
    if terms.len() <= INLINE {
        for (slot, term) in ready.iter_mut().zip(terms.iter().zip(0..)) {
            *slot = partial(term);
        }
    }
    let mut len = ready.len();
    let mut next = terms.len();
    while len > 1 {
        let (first, second) = ready_first(&ready[..len]);
        let (a, b) = fused_last(ready[first], ready[second]);
        let fused = b.operands.is_some();
        let cycles = if fused {
            a.cycles.max(b.operands.unwrap_or(b.cycles)) + FMA_LATENCY
        } else {
            a.cycles.max(b.cycles) + ADD_LATENCY
        };
        add(Addition {
            a: a.index,
            b: b.index,
            fused,
        });
        // The sum in the first's place, the last partial sum in the second's.
        ready[first] = Partial {
            cycles,
            index: next,
            depth: 1 + a.depth.max(b.depth),
            negative: a.negative && b.negative,
            operands: None,
        };
        next += 1;
        len -= 1;
        ready[second] = ready[len];
    }
    ready.first().map_or(0, |p| p.depth)
}

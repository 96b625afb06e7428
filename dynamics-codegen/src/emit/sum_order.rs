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

#[cfg(test)]
mod tests {
    use super::{sum_order, Addition, SumTerm};

    fn term(depth: u32, negative: bool, fusable: bool) -> SumTerm {
        SumTerm {
            depth,
            negative,
            fusable,
        }
    }

    fn add(a: usize, b: usize, fused: bool) -> Addition {
        Addition { a, b, fused }
    }

    #[test]
    fn sums_add_their_terms_in_the_order_they_are_ready() {
        let plain = |d: u32| term(d, false, false);
        // (terms, additions, depth in operations)
        let table: Vec<(Vec<SumTerm>, Vec<Addition>, u32)> = vec![
            // The latest term, met first, is added last.
            (
                vec![plain(6), plain(0), plain(3)],
                vec![add(1, 2, false), add(3, 0, false)],
                7,
            ),
            // Four terms ready together: two pairs, two operations deep rather than three.
            (
                vec![plain(2); 4],
                vec![add(0, 1, false), add(2, 3, false), add(4, 5, false)],
                4,
            ),
            // A product is fused, with the other term as the addend, whichever comes first.
            (
                vec![term(1, false, true), plain(2)],
                vec![add(1, 0, true)],
                3,
            ),
            (
                vec![plain(1), term(2, false, true)],
                vec![add(0, 1, true)],
                3,
            ),
            // Of two products, the one whose operands come later is fused.
            (
                vec![term(3, false, true), term(2, false, true)],
                vec![add(1, 0, true)],
                4,
            ),
            // Of two products of opposite signs, the negative one.
            (
                vec![term(2, true, true), term(2, false, true)],
                vec![add(1, 0, true)],
                3,
            ),
            // One term: nothing to add.
            (vec![plain(5)], vec![], 5),
        ];
        for (terms, additions, depth) in table {
            assert_eq!(sum_order(&terms), (additions, depth), "{terms:?}");
        }
    }

    /// The rule of `sum_order`'s doc spelled out the plain way, as it was first written:
    /// sort the partial sums by when they are ready (then by index) and add the first two.
    fn sorted_each_time(terms: &[SumTerm]) -> (Vec<Addition>, u32) {
        // (cycles, index, depth, negative, operands ready)
        let mut ready: Vec<(u32, usize, u32, bool, Option<u32>)> = terms
            .iter()
            .zip(0..)
            .map(|(t, i)| {
                let cycles = 3 * t.depth;
                (
                    cycles,
                    i,
                    t.depth,
                    t.negative,
                    t.fusable.then(|| cycles.saturating_sub(3)),
                )
            })
            .collect();
        let mut additions = Vec::new();
        while ready.len() > 1 {
            ready.sort_by_key(|p| (p.0, p.1));
            let (x, y) = (ready.remove(0), ready.remove(0));
            let (a, b) = match (x.4, y.4) {
                (Some(_), Some(_)) if x.3 != y.3 => {
                    if x.3 {
                        (y, x)
                    } else {
                        (x, y)
                    }
                }
                (Some(i), Some(j)) if i > j => (y, x),
                (Some(_), None) => (y, x),
                _ => (x, y),
            };
            let fused = b.4.is_some();
            let cycles = if fused {
                a.0.max(b.4.unwrap_or(b.0)) + 4
            } else {
                a.0.max(b.0) + 3
            };
            additions.push(add(a.1, b.1, fused));
            let index = terms.len() + additions.len() - 1;
            ready.push((cycles, index, 1 + a.2.max(b.2), a.3 && b.3, None));
        }
        (additions, ready.first().map_or(0, |p| p.2))
    }

    /// The scan for the two partial sums ready first adds in the same order as sorting them
    /// at every step, on the stack and past it (more than `INLINE` terms), and `sum_depth` is
    /// its depth.
    #[test]
    fn the_scan_adds_as_sorting_would() {
        let mut rng = dynamics_test_support::Rng::new(42);
        for case in 0..2000 {
            let n = if case % 10 == 0 {
                17 + rng.below(30)
            } else {
                rng.below(12)
            };
            // Few distinct depths, so that ties (broken by index) are common.
            let terms: Vec<SumTerm> = (0..n)
                .map(|_| {
                    let depth = u32::try_from(rng.below(6)).expect("small");
                    term(depth, rng.below(2) == 0, rng.below(3) == 0)
                })
                .collect();
            let expected = sorted_each_time(&terms);
            assert_eq!(sum_order(&terms), expected, "{terms:?}");
            assert_eq!(super::sum_depth(&terms), expected.1, "{terms:?}");
        }
    }
}

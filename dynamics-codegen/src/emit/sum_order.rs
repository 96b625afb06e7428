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
pub(crate) struct SumTerm {
    pub(crate) depth: u32,
    pub(crate) negative: bool,
    pub(crate) fusable: bool,
}

/// One addition of [`sum_order`]: partial sums `a` and `b` (indices: the terms, then each
/// addition's result in turn), with `b` a product that a fused multiply-add takes if `fused`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Addition {
    pub(super) a: usize,
    pub(super) b: usize,
    pub(super) fused: bool,
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
pub(super) fn sum_order(terms: &[SumTerm]) -> (Vec<Addition>, u32) {
    #[derive(Clone, Copy)]
    struct Partial {
        cycles: u32,
        index: usize,
        depth: u32,
        negative: bool,
        /// When a fusable product's operands are ready.
        operands: Option<u32>,
    }
    let mut ready: Vec<Partial> = terms
        .iter()
        .zip(0..)
        .map(|(t, index)| {
            let cycles = ADD_LATENCY * t.depth;
            Partial {
                cycles,
                index,
                depth: t.depth,
                negative: t.negative,
                operands: t.fusable.then(|| cycles.saturating_sub(MUL_LATENCY)),
            }
        })
        .collect();
    let mut additions = Vec::with_capacity(terms.len().saturating_sub(1));
    while ready.len() > 1 {
        ready.sort_unstable_by_key(|p| (p.cycles, p.index));
        let (x, y) = (ready.remove(0), ready.remove(0));
        let (a, b) = match (x.operands, y.operands) {
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
        };
        let fused = b.operands.is_some();
        let (cycles, depth, negative) = if fused {
            let cycles = a.cycles.max(b.operands.unwrap_or(b.cycles)) + FMA_LATENCY;
            (cycles, 1 + a.depth.max(b.depth), a.negative && b.negative)
        } else {
            let cycles = a.cycles.max(b.cycles) + ADD_LATENCY;
            (cycles, 1 + a.depth.max(b.depth), a.negative && b.negative)
        };
        additions.push(Addition {
            a: a.index,
            b: b.index,
            fused,
        });
        ready.push(Partial {
            cycles,
            index: terms.len() + additions.len() - 1,
            depth,
            negative,
            operands: None,
        });
    }
    (additions, ready.first().map_or(0, |p| p.depth))
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
}

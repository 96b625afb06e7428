use dynamics_codegen::emit::sum_order::{sum_order, Addition, SumTerm};

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
        assert_eq!(
            dynamics_codegen::emit::sum_order::sum_depth(&terms),
            expected.1,
            "{terms:?}"
        );
    }
}

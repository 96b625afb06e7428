//! The derivative plans' blocks of tangent directions.

use dynamics_codegen::symbolic::tangent::FETCH_BOUND_OPERATIONS;
use dynamics_codegen::symbolic::{Lane, NodeId, Of, Tangents, Term, BLOCK};

/// A lane of the unit vectors `directions`, read `reads` times by lanes of one term each.
fn plan(directions: usize, units: &[u16], reads: usize) -> Tangents {
    let term = |of| Term {
        of,
        factors: vec![NodeId(0)],
        negative: false,
    };
    let mut lanes = vec![Lane {
        after: NodeId(0),
        terms: units.iter().map(|&j| term(Of::Unit(j))).collect(),
    }];
    lanes.extend((0..reads).map(|_| Lane {
        after: NodeId(1),
        terms: vec![term(Of::Lane(0))],
    }));
    Tangents {
        directions,
        lanes,
        outputs: vec![Some(1)],
        group: BLOCK,
    }
}

#[test]
fn blocks_of_four_where_lanes_fit_them() {
    // Directions 0..3 of six: one block of four (one half) against one of eight (two).
    let narrow = plan(6, &[0, 1, 2, 3], 10);
    assert_eq!(narrow.block_operations(8), 11);
    assert_eq!(narrow.block_operations(4), 11);
    assert!(narrow.prefer_groups_of_four());
    // Directions 2..5: two blocks of four, two halves either way; eight kept.
    let across = plan(6, &[2, 5], 10);
    assert_eq!(across.block_operations(4), 22);
    assert!(!across.prefer_groups_of_four());
    // Directions 1..9 of 19: two blocks of eight (four halves), three of four.
    let arm = plan(19, &[1, 9], 10);
    assert_eq!((arm.block_operations(8), arm.block_operations(4)), (22, 33));
    assert!(arm.prefer_groups_of_four());
}

#[test]
fn blocks_of_eight_where_the_code_is_fetch_bound() {
    let big = plan(6, &[0, 1], FETCH_BOUND_OPERATIONS);
    assert_eq!(big.block_operations(8), FETCH_BOUND_OPERATIONS + 1);
    assert!(!big.prefer_groups_of_four());
    let just = plan(6, &[0, 1], FETCH_BOUND_OPERATIONS - 1);
    assert!(just.prefer_groups_of_four());
}

#[test]
fn a_lane_is_kept_in_the_blocks_of_its_group() {
    let mut arm = plan(19, &[1, 9], 1);
    assert_eq!(arm.blocks(), vec![0..2, 0..2]);
    arm.group = 4;
    assert_eq!((arm.blocks(), arm.block_count()), (vec![0..3, 0..3], 5));
}

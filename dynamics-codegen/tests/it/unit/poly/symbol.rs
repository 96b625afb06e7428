use dynamics_codegen::poly::AngleSum;

fn sum(joints: &[u16]) -> AngleSum {
    joints
        .iter()
        .map(|&j| AngleSum::joint(j).unwrap())
        .reduce(AngleSum::union)
        .unwrap()
}

/// The order is that of the sorted joint lists.
#[test]
fn angle_sums_order_as_lists() {
    let lists: [&[u16]; 7] = [&[0], &[0, 1], &[0, 1, 2], &[0, 2], &[1], &[1, 2], &[5]];
    for (x, a) in lists.iter().enumerate() {
        for (y, b) in lists.iter().enumerate() {
            assert_eq!(sum(a).cmp(&sum(b)), x.cmp(&y), "{a:?} vs {b:?}");
            assert_eq!(sum(a).cmp(&sum(b)), a.cmp(b));
        }
    }
}

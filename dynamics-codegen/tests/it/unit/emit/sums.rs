use dynamics_codegen::emit::sums::Inline;

/// A list longer than its stack slots keeps every item, in order.
#[test]
fn an_inline_list_spills_in_order() {
    for n in [0, 1, 7, 8, 9, 30] {
        let mut list = Inline::new(0_usize);
        list.extend(0..n);
        assert_eq!(
            list.as_slice(),
            (0..n).collect::<Vec<_>>().as_slice(),
            "{n} items"
        );
    }
}

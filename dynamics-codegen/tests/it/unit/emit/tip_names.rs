use dynamics_codegen::emit::tip_names::index_names;

#[test]
fn tips_are_named_in_capitals_and_apart() {
    let names = ["left_hand", "link_3.0_tip", "link-3.0-tip", "names"].map(String::from);
    let idents: Vec<String> = index_names(&names, "TIP")
        .iter()
        .map(ToString::to_string)
        .collect();
    assert_eq!(
        idents,
        [
            "TIP_LEFT_HAND",
            "TIP_LINK_3_0_TIP",
            "TIP_LINK_3_0_TIP_2",
            "TIP_NAMES_3"
        ]
    );
}

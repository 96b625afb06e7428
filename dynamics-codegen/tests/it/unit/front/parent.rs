use dynamics_codegen::front::parent::{resolve, ParentRef};
use std::collections::BTreeMap;

#[test]
fn parents_by_number_and_name_and_their_mistakes() {
    let names = BTreeMap::from([("palm", 0), ("thumb", 2)]);
    let at = |i, p| resolve(i, p, 3, &names);
    assert_eq!(at(1, ParentRef::Number(0)), Ok(None));
    assert_eq!(at(1, ParentRef::Number(1)), Ok(Some(0)));
    assert_eq!(at(2, ParentRef::Name("palm")), Ok(Some(0)));
    for (i, parent, message) in [
        (
            1,
            ParentRef::Number(4),
            "parent 4: there is no joint 4 (3 are given; 0 is the base)",
        ),
        (
            1,
            ParentRef::Number(2),
            "parent joint 2: a joint cannot hang from itself (a cycle)",
        ),
        (
            1,
            ParentRef::Name("thumb"),
            "parent `thumb` (joint 3) comes after it",
        ),
        (
            1,
            ParentRef::Name("wrist"),
            "parent `wrist`: no joint has that name (the joints named are `palm`, `thumb`)",
        ),
    ] {
        let error = at(i, parent).unwrap_err();
        assert!(error.starts_with(message), "{error}");
    }
    let none = resolve(1, ParentRef::Name("palm"), 3, &BTreeMap::new()).unwrap_err();
    assert!(none.ends_with("(no joint has a `name`)"), "{none}");
}

//! Compile-fail tests: each file under `ui/` makes one mistake, and its `.stderr` holds the
//! error the derive must give, on the offending token. Refresh with `TRYBUILD=overwrite`.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}

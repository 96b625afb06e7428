//! Compile-fail tests of the derive: each file under `ui/<category>/` makes one mistake, and
//! its `.stderr` holds the error the derive must give, on the offending token. They derive
//! through the runtime, as users do, and live with it: trybuild's crate takes the tested
//! crate's dependencies, and the derive's own (the generator) would be type-checked a second
//! time. The categories are `attributes` (keys of `#[dynamics(...)]`), `values` (the D-H table
//! and its values), `fields` (struct fields named by values), `physics` (mass, inertia,
//! actuator inertia, springs), `friction` (joint friction and geared drives, in attributes and
//! files), `files` (description files, which live next to their tests), `frames` (joints given
//! by placements and axes, in the attribute and in files), `trees` (parents, antecedent
//! columns, URDF `tips` and trees) and `floating` (`base = floating` and what it does not
//! support yet). A case names its file relative to itself: trybuild's crate,
//! somewhere inside the target directory, has no such file, so the derive finds it beside the
//! case, and the cases pass wherever `CARGO_TARGET_DIR` points. Refresh with
//! `TRYBUILD=overwrite`, then read every changed `.stderr`.

#[test]
fn ui() {
    // trybuild's crate has the workspace's dependencies but not its profiles: without debug
    // info (nobody steps through them) they build in less time.
    std::env::set_var("CARGO_PROFILE_DEV_DEBUG", "false");
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*/*.rs");
}

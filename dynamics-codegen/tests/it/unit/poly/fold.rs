use dynamics_codegen::poly::fold::{add_term, find_fold, fold_trig};
use dynamics_codegen::poly::{Expander, Limits, Monomial};
use dynamics_codegen::symbolic::Number;
use std::collections::BTreeMap;

/// The folding as first written: each search from the start.
fn from_the_start(terms: &mut BTreeMap<Monomial, Number>) {
    while let Some(fold) = find_fold(terms) {
        add_term(terms, fold.m, -fold.k);
        add_term(terms, fold.partner, fold.partner_delta);
        add_term(terms, fold.folded, fold.k);
    }
}

/// Resuming the search gives the very terms a search from the start gives, on robots'
/// torques, mass matrices and gravity torques.
#[test]
fn resumed_as_from_the_start() {
    for file in [
        "robots/puma560.toml",
        "robots/stanford.toml",
        "tests/data/reference/robots/random2.json",
        "robots/two_link_friction.toml",
    ] {
        let path = format!("{}/../{file}", env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(&path).expect("the robot file");
        let eq = dynamics_codegen::trace::derive(
            &dynamics_codegen::front::load(&path, &text)
                .expect("a robot")
                .robot,
        );
        let mut expander = Expander::new(&eq, Limits::UNBOUNDED);
        let ids = eq
            .tau
            .iter()
            .chain(&eq.gravity)
            .chain(eq.mass.iter().flatten());
        for &id in ids {
            let mut unfolded = expander.expanded(id).expect("a polynomial");
            let mut resumed = unfolded.clone();
            from_the_start(&mut unfolded);
            fold_trig(&mut resumed, &mut |_| Some(())).expect("no budget");
            assert_eq!(resumed, unfolded, "{file}");
        }
    }
}

//! The exciting motion's problem: the search's cost against the condition number reported.

use dynamics_codegen::JointColumns;
use dynamics_identification::excite::condition::Gram;
use dynamics_identification::excite::design::Problem;
use dynamics_identification::excite::fourier::{Grid, Limits};
use dynamics_identification::identify::base;
use dynamics_identification::identify::model::LinearModel;

/// The search's cost, by the Gram matrix's eigenvalues, against the condition number the
/// report gives, by the regressor's factor and its singular values, over the same samples.
#[test]
fn the_search_s_cost_is_the_condition_number_reported() {
    let text = include_str!("../../../../robots/puma560.toml");
    let robot = dynamics_codegen::load(&dynamics_codegen::Source {
        path: "puma560.toml",
        text: Some(text),
        ..dynamics_codegen::Source::default()
    })
    .expect("reads")
    .robot;
    let mut eq = dynamics_codegen::derive(&robot);
    let base = eq
        .base_parameters(&robot, &[JointColumns::default(); 6])
        .expect("numbers only");
    let model = LinearModel::new(&base::entries(&eq, &base, &[])).expect("a model");
    let limits = Limits {
        lower: -1.0,
        upper: 1.0,
        velocity: 1.0,
        acceleration: 4.0,
    };
    let problem = Problem {
        model: &model,
        grid: Grid::new(8.0, 4, 400),
        limits: vec![limits; 6],
    };
    let mut random = dynamics_identification::excite::search::Random::new(3);
    let x: Vec<f64> = (0..6 * 7).map(|_| random.symmetric()).collect();
    let series = problem.decode(&x).expect("it moves");
    let all: Vec<usize> = (0..400).collect();
    let cost = problem.condition(&mut Gram::new(&model), &series, &all);
    let reported = problem.accurate_condition(&series);
    assert!(
        (cost - reported).abs() < 1e-9 * reported,
        "{cost} {reported}"
    );
    assert!(reported > 1.0 && reported.is_finite());
}

//! The regressor four samples at a time, against one at a time and Newton-Euler.

use dynamics_codegen::JointColumns;
use dynamics_codegen::Numeric;
use dynamics_identification::identify::base;
use dynamics_identification::identify::model::{JointValues, LinearModel, Work};
use dynamics_identification::lanes::LANES;

/// PUMA 560's base regressor in four lanes: each state's entries the same bits alone as in
/// a group (a partial one too), and `Y_B π_B` the torques of the numeric Newton-Euler.
#[test]
fn four_states_at_once_as_one_at_a_time() {
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
    let values: Vec<[Vec<f64>; 3]> = (0..5)
        .map(|k| {
            let x = |i: usize, scale: f64| (0.37 * (k * 6 + i) as f64).sin() * scale;
            [
                (0..6).map(|i| x(i, 2.0)).collect(),
                (0..6).map(|i| x(i + 40, 1.5)).collect(),
                (0..6).map(|i| x(i + 80, 3.0)).collect(),
            ]
        })
        .collect();
    let states: Vec<JointValues> = values
        .iter()
        .map(|[q, qd, qdd]| JointValues { q, qd, qdd })
        .collect();
    let entries = model.entries();
    let mut work = Work::default();
    let mut together = vec![0.0; 2 * LANES * entries];
    model.rows(&states[..4], &mut work, &mut together);
    model.rows(&states[4..], &mut work, &mut together[4 * entries..]);
    let numeric = Numeric::new(&robot, &[]).expect("no fields");
    for (k, s) in states.iter().enumerate() {
        let mut alone = vec![0.0; LANES * entries];
        model.rows(&[*s], &mut work, &mut alone);
        let ours = &together[k * entries..(k + 1) * entries];
        assert_eq!(ours, &alone[..entries], "state {k}");
        let tau = numeric.inverse_dynamics(s.q, s.qd, s.qdd);
        let mut start = 0;
        for (i, columns) in model.columns.iter().enumerate() {
            let row = &ours[start..start + columns.len()];
            let y_pi: f64 = row
                .iter()
                .zip(columns)
                .map(|(y, &c)| y * model.described[c])
                .sum();
            assert!(
                (y_pi - tau[i]).abs() < 1e-10 * (1.0 + tau[i].abs()),
                "state {k}, joint {i}"
            );
            start += columns.len();
        }
    }
}

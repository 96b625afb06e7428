//! Four samples in the lanes of one value.

use dynamics_codegen::pipeline::TapeScalar;
use dynamics_identification::lanes::Four;

#[test]
fn each_lane_is_its_samples() {
    let x = Four::from_fn(|l| [0.5, -2.0, 0.0, 3.0][l]);
    let y = Four::splat(2.0);
    assert_eq!((x * y + -x).lanes(), [0.5, -2.0, 0.0, 3.0]);
    assert_eq!(x.sign().lanes(), [1.0, -1.0, 0.0, 1.0]);
    assert_eq!(y.recip().lanes(), [0.5; 4]);
    assert!((x.sin().lanes()[1] - (-2.0_f64).sin()).abs() < 1e-15);
    assert!((x.cos().lanes()[3] - 3.0_f64.cos()).abs() < 1e-15);
    assert!((x.tanh().lanes()[0] - 0.5_f64.tanh()).abs() < 1e-15);
}

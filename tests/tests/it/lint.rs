//! Generated code is lint-clean and hygienic: robots derived from attributes and from a
//! description file, in a crate that denies warnings and clippy's `all` and `pedantic` groups
//! (CI runs clippy on every target), next to user items named like what the generated code
//! uses: `sin`, `cos`, `M`, `T`, `param`, `core`, a `f64` type alias, and struct fields
//! named like its temporaries (`t1`, `s1`, `c1`, `k1`, `p_m1`, `param`).
//!
//! Constants named `q`, `qd` and `qdd` (the trait's argument names) are in scope too: a
//! pattern cannot shadow a constant, so the generated methods name their arguments `q_`, `qd_`
//! and `qdd_`. So are constants and a static named like the generated locals (`x`, `t1`, `k1`,
//! `s2`, `m1_1`, `tau1`, `g1`, `p_m1`, `p_`): the generated functions live in a module, which
//! sees none of them.
#![deny(warnings, clippy::all, clippy::pedantic)]

use dynamics_runtime::Dynamics;

/// Traps in the module where the robots are derived.
#[allow(dead_code, non_upper_case_globals)]
mod traps {
    pub fn sin(v: f64) -> f64 {
        v
    }
    pub fn cos(v: f64) -> f64 {
        v
    }
    pub struct M;
    pub struct T;
    pub fn param(v: f64) -> f64 {
        v
    }
    pub const q: f64 = 1.0;
    pub const qd: f64 = 2.0;
    pub const qdd: f64 = 3.0;
    // Named like generated locals: a `let` pattern cannot shadow a constant, so the generated
    // functions live in a module that does not see these.
    pub const x: f64 = 4.0;
    pub const t1: f64 = 5.0;
    pub const k1: f64 = 6.0;
    pub const s2: f64 = 7.0;
    pub const c2: f64 = 8.0;
    pub const m1_1: f64 = 9.0;
    pub const tau1: f64 = 10.0;
    pub static g1: f64 = 11.0;
    pub const p_m1: f64 = 12.0;
    pub const p_: f64 = 13.0;
}
#[allow(unused_imports)]
use traps::*;

/// A planar RRP arm whose parameters are fields named like generated temporaries.
#[derive(Dynamics)]
#[dynamics(
    gravity = [0, -g, 0],
    dh = [
        [q, 0, t1, 0],
        [q + 30 deg, 0, s1, 90 deg],
        [0.1, q, 0, 0],
    ],
    link(mass = p_m1, com = [-t1 / 2, 0, 0], inertia = [0, k1, k1, 0, 0, 0]),
    link(mass = c1, com = [-s1 / 2, 0.01, 0], inertia = [0.01, 0.02, 0.02, 0.001, 0, 0], actuator_inertia = param),
    link(mass = 0.5, com = [0, 0, -0.1], inertia = [0.003, 0.003, 0.001, 0, 0, 0], spring = (k1, 0.2)),
)]
struct Traps {
    g: f64,
    t1: f64,
    s1: f64,
    c1: f32,
    k1: f64,
    p_m1: f64,
    param: f64,
}

/// In a module that shadows `f64` (legal: primitive types are not keywords) and `core`.
mod shadowed {
    #![allow(non_camel_case_types)]
    use dynamics_runtime::Dynamics;

    #[allow(dead_code)]
    type f64 = f32;
    #[allow(dead_code)]
    mod core {}

    #[derive(Dynamics)]
    #[dynamics(
        gravity = [0, 0, -9.81],
        dh = [[q, 0.5, l, 90 deg], [q, 0, 0.4, 0]],
        link(mass = 2, com = [-0.25, 0, 0], inertia = [0.01, 0.05, 0.05, 0, 0, 0]),
        link(mass = m, com = [-0.2, 0, 0]),
    )]
    pub struct Arm {
        pub l: f64,
        pub m: f64,
    }
}

/// PUMA 560 from its description file (links 1 and 3 opt out of the inertia checks there).
#[derive(Dynamics)]
#[dynamics(file = "../robots/puma560.toml")]
struct Puma560;

/// The Stanford arm from the reference data, opting out for every link.
#[derive(Dynamics)]
#[dynamics(file = "data/reference/robots/stanford.json", check_inertia = false)]
struct Stanford;

/// One prismatic joint moving across gravity.
#[derive(Dynamics)]
#[dynamics(gravity = [-9.81, 0, 0], dh = [[0, q, 0, 90 deg]], link(mass = 1))]
struct Slider;

#[test]
fn derived_robots_compute() {
    let arm = Traps {
        g: 9.81,
        t1: 0.5,
        s1: 0.4,
        c1: 1.5,
        k1: 0.2,
        p_m1: 2.0,
        param: 0.01,
    };
    let angles = [0.1, -0.4, 0.05];
    let tau = arm.inverse_dynamics(&angles, &[0.3; 3], &[1.0; 3]);
    let m = arm.mass_matrix(&angles);
    let h = arm.bias_torques(&angles, &[0.3; 3]);
    // τ = M q̈ + h, computed by separate generated methods.
    for i in 0..3 {
        let sum: f64 = m[i].iter().sum::<f64>() + h[i];
        assert!((tau[i] - sum).abs() < 1e-12, "{tau:?} vs {m:?} {h:?}");
    }
    let shadowed = shadowed::Arm { l: 0.3, m: 1.0 };
    let g = shadowed.gravity_torques(&[0.2f32, 0.1]);
    assert!(g.iter().all(|v| v.is_finite()));
    assert!(Puma560.mass_matrix(&[0.0; 6])[0][0] > 0.0);
    assert!(Stanford.kinetic_energy(&[0.0; 6], &[1.0; 6]) > 0.0);
    // The traps are still what the user defined.
    assert!((sin(2.0) - 2.0).abs() < f64::EPSILON && (cos(1.0) - 1.0).abs() < f64::EPSILON);
    assert!(param(1.0) > 0.0);
    assert!((std::hint::black_box(q) + qd + qdd - 6.0).abs() < f64::EPSILON);
    // A robot whose outputs do not depend on q or qd: unused arguments raise no warning.
    let slider = Slider;
    assert!(slider.coriolis_matrix(&[1.0f64], &[2.0])[0][0].abs() < f64::EPSILON);
    assert!(slider.gravity_torques(&[1.0f64])[0].abs() < f64::EPSILON);
}

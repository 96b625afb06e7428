//! A derive on a generic struct: the impls take the struct's lifetime, type and const
//! parameters and its where clause, and the generated methods' scalar type parameter takes a
//! name the struct does not use (here `T` and `S` are the struct's).

use dynamics_runtime::Dynamics;

/// A pendulum: a point mass `m1` at the tip of a link of length `l1` (D-H frame 1 is at the
/// tip), gravity along −y. By hand: M = m1 l1², g(q) = ∂(m1 9.81 l1 sin q)/∂q = 9.81 m1 l1 cos q.
#[derive(Dynamics)]
#[dynamics(gravity = [0, -9.81, 0], dh = [[q, 0, l1, 0]], link(mass = m1))]
struct Pendulum<'a, T, S: Copy, const N: usize>
where
    T: Clone + Default,
{
    l1: f64,
    m1: f32,
    label: &'a str,
    tag: T,
    extra: [S; N],
}

#[test]
fn generic_struct_derives_and_computes() {
    let arm = Pendulum {
        l1: 2.0,
        m1: 3.0,
        label: "pendulum",
        tag: String::new(),
        extra: [0u8; 2],
    };
    assert_eq!(arm.label, "pendulum");
    assert!(arm.tag.is_empty() && arm.extra.len() == 2);
    // M = 3 · 2² = 12 whatever q.
    assert_eq!(arm.mass_matrix::<f64>(&[0.7]), [[12.0]]);
    // g(0) = 9.81 · 3 · 2 = 58.86; g(π/2) = 0.
    let g = arm.gravity_torques::<f64>(&[0.0])[0];
    assert!((g - 58.86).abs() < 1e-12, "{g}");
    assert!(arm.gravity_torques::<f64>(&[std::f64::consts::FRAC_PI_2])[0].abs() < 1e-12);
    assert!(Pendulum::<String, u8, 2>::EQUATIONS.contains('M'));
}

/// With derivatives, their module goes beside the struct, named after it
/// (`__derivatives_of_loop`): a struct named by a raw identifier, in a function body, works too.
#[test]
fn derivatives_of_a_struct_named_by_a_raw_identifier() {
    use dynamics_runtime::DynamicsDerivatives;
    #[allow(non_camel_case_types)]
    #[derive(Dynamics)]
    #[dynamics(gravity = [0, -9.81, 0], dh = [[q, 0, 2, 0]], link(mass = 3), derivatives = true)]
    struct r#loop;
    // τ = 12 q̈ + 58.86 cos q, so ∂τ/∂q = −58.86 sin q and ∂τ/∂q̇ = 0.
    let d = r#loop.inverse_dynamics_derivatives::<f64>(&[0.5], &[0.3], &[0.2]);
    assert!(
        (d.dtau_dq[0][0] + 58.86 * 0.5f64.sin()).abs() < 1e-12,
        "{d:?}"
    );
    assert!(d.dtau_dqd[0][0].abs() < 1e-12, "{d:?}");
    // The forward derivatives are the function compiled apart, in that module: ∂q̈/∂τ = 1/12.
    let f = r#loop
        .forward_dynamics_derivatives::<f64>(&[0.5], &[0.3], &[1.0])
        .expect("M = 12");
    assert!((f.dqdd_dtau[0][0] - 1.0 / 12.0).abs() < 1e-15, "{f:?}");
}

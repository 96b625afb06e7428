use crate::unit::emit_c::function::arm_with_every_family;
use dynamics_codegen::emit_c::batch::definition;
use dynamics_codegen::emit_c::{functions, Precision};
use dynamics_codegen::method::Method;

fn batch_of(method: Method, precision: Precision) -> String {
    let eq = arm_with_every_family();
    let f = functions(&eq, "arm")
        .into_iter()
        .find(|f| f.method == method && f.precision == precision)
        .expect("the function");
    definition(&f)
}

/// A matrix result is addressed as the array of rows the single-state function takes.
#[test]
fn a_matrix_is_passed_as_its_rows() {
    let text = batch_of(Method::MassMatrix, Precision::Double);
    assert!(
        text.contains("void arm_mass_matrix_batch(size_t n, const double *q, double *m)"),
        "{text}"
    );
    assert!(
        text.contains("arm_mass_matrix(q + 2 * i, (double (*)[2])(m + 4 * i));"),
        "{text}"
    );
}

/// A scalar goes into an array; a solve counts its failures and reports each state's.
#[test]
fn scalars_and_statuses_become_arrays() {
    let energy = batch_of(Method::KineticEnergy, Precision::Single);
    assert!(energy.contains("float *value)"), "{energy}");
    assert!(
        energy.contains("value[i] = arm_kinetic_energy_f32("),
        "{energy}"
    );
    let solve = batch_of(Method::ForwardDynamics, Precision::Double);
    assert!(
        solve.contains("size_t arm_forward_dynamics_batch("),
        "{solve}"
    );
    assert!(solve.contains("if (status) status[i] = failed;"), "{solve}");
    assert!(solve.contains("return failures;"), "{solve}");
}

//! A floating base's configuration space on NumPy arrays: the runtime's `integrate` and
//! `difference` (Pinocchio's, `dynamics-runtime/src/configuration.rs`), state by state over
//! flat arrays of `f64` (the bytes of C-contiguous `float64` arrays, as `_configuration.py`
//! passes them). The base's seven entries of `q` and six of `v` are the runtime's; a joint's
//! are added or subtracted, as the runtime does; the Jacobians (`dIntegrate`, `dDifference`)
//! the runtime's base block, the joints' the identity (`−1` for `∂/∂q0`).

use dynamics_runtime::configuration;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBytes;

/// The numbers of `bytes`, native-endian `f64`s, in `count` rows of `width` (at least a
/// free flyer's 7 or 6).
fn rows(bytes: &[u8], count: usize, width: usize, name: &str) -> PyResult<Vec<f64>> {
    if width < 6 || bytes.len() != count * width * 8 {
        let message = format!(
            "{name}: {} bytes for {count} rows of {width} numbers",
            bytes.len()
        );
        return Err(PyValueError::new_err(message));
    }
    let each = bytes.chunks_exact(8);
    Ok(each
        .map(|b| f64::from_ne_bytes(b.try_into().unwrap_or([0; 8])))
        .collect())
}

/// The bytes of `values`, native-endian.
fn bytes<'py>(py: Python<'py>, values: &[f64]) -> Bound<'py, PyBytes> {
    let raw: Vec<u8> = values.iter().flat_map(|x| x.to_ne_bytes()).collect();
    PyBytes::new(py, &raw)
}

/// `integrate(q, v)` at `count` states: `q` rows of `nv + 1`, `v` rows of `nv` (`nv ≥ 6`); the
/// configurations reached, rows of `nv + 1`.
#[pyfunction]
pub fn integrate<'py>(
    py: Python<'py>,
    q: &[u8],
    v: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let nq = nv + 1;
    let (q, v) = (rows(q, count, nq, "q")?, rows(v, count, nv, "v")?);
    let mut out = vec![0.0; count * nq];
    for ((q, v), out) in q
        .chunks_exact(nq)
        .zip(v.chunks_exact(nv))
        .zip(out.chunks_exact_mut(nq))
    {
        let base_q: [f64; 7] = std::array::from_fn(|i| q[i]);
        let base_v: [f64; 6] = std::array::from_fn(|i| v[i]);
        out[..7].copy_from_slice(&configuration::integrate(&base_q, &base_v));
        for ((out, q), v) in out[7..].iter_mut().zip(&q[7..]).zip(&v[6..]) {
            *out = q + v;
        }
    }
    Ok(bytes(py, &out))
}

/// `difference(q0, q1)` at `count` states: rows of `nv + 1` each; the velocities, rows of
/// `nv`.
#[pyfunction]
pub fn difference<'py>(
    py: Python<'py>,
    q0: &[u8],
    q1: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let nq = nv + 1;
    let (q0, q1) = (rows(q0, count, nq, "q0")?, rows(q1, count, nq, "q1")?);
    let mut out = vec![0.0; count * nv];
    for ((q0, q1), out) in q0
        .chunks_exact(nq)
        .zip(q1.chunks_exact(nq))
        .zip(out.chunks_exact_mut(nv))
    {
        let base = |q: &[f64]| -> [f64; 7] { std::array::from_fn(|i| q[i]) };
        let twist: [f64; 6] = configuration::difference(&base(q0), &base(q1));
        out[..6].copy_from_slice(&twist);
        for ((out, q0), q1) in out[6..].iter_mut().zip(&q0[7..]).zip(&q1[7..]) {
            *out = q1 - q0;
        }
    }
    Ok(bytes(py, &out))
}

/// The base's 6 × 6 block of a Jacobian of the runtime's, from a state's two inputs.
type BaseJacobian = fn(&[f64], &[f64]) -> [[f64; 6]; 6];

/// A Jacobian of `integrate` or `difference` at `count` states: `first` rows of `nv + 1`,
/// `second` rows of `width`; the `nv × nv` matrices, rows first, the base's block `base`'s,
/// the joints' `diagonal` times the identity (as the runtime's).
fn jacobians<'py>(
    py: Python<'py>,
    (first, second): (&[u8], &[u8]),
    (count, nv, width): (usize, usize, usize),
    base: BaseJacobian,
    diagonal: f64,
) -> PyResult<Bound<'py, PyBytes>> {
    let names = if width == nv {
        ("q", "v")
    } else {
        ("q0", "q1")
    };
    let first = rows(first, count, nv + 1, names.0)?;
    let second = rows(second, count, width, names.1)?;
    let mut out = vec![0.0; count * nv * nv];
    for ((a, b), out) in first
        .chunks_exact(nv + 1)
        .zip(second.chunks_exact(width))
        .zip(out.chunks_exact_mut(nv * nv))
    {
        for (i, row) in base(a, b).iter().enumerate() {
            out[nv * i..nv * i + 6].copy_from_slice(row);
        }
        for i in 6..nv {
            out[nv * i + i] = diagonal;
        }
    }
    Ok(bytes(py, &out))
}

fn base_q(q: &[f64]) -> [f64; 7] {
    std::array::from_fn(|i| q[i])
}

fn base_v(v: &[f64]) -> [f64; 6] {
    std::array::from_fn(|i| v[i])
}

/// `∂ integrate(q, v) / ∂v` (Pinocchio's `dIntegrate`, `ARG1`) at `count` states.
#[pyfunction]
pub fn integrate_jacobian_v<'py>(
    py: Python<'py>,
    q: &[u8],
    v: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let base: BaseJacobian = |_, v| configuration::integrate_jacobian(&base_v(v));
    jacobians(py, (q, v), (count, nv, nv), base, 1.0)
}

/// `∂ integrate(q, v) / ∂q` (Pinocchio's `dIntegrate`, `ARG0`) at `count` states.
#[pyfunction]
pub fn integrate_jacobian_q<'py>(
    py: Python<'py>,
    q: &[u8],
    v: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let base: BaseJacobian = |_, v| configuration::integrate_jacobian_q(&base_v(v));
    jacobians(py, (q, v), (count, nv, nv), base, 1.0)
}

/// `∂ difference(q0, q1) / ∂q0` (Pinocchio's `dDifference`, `ARG0`) at `count` states.
#[pyfunction]
pub fn difference_jacobian_q0<'py>(
    py: Python<'py>,
    q0: &[u8],
    q1: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let base: BaseJacobian = |a, b| configuration::difference_jacobian_q0(&base_q(a), &base_q(b));
    jacobians(py, (q0, q1), (count, nv, nv + 1), base, -1.0)
}

/// `∂ difference(q0, q1) / ∂q1` (Pinocchio's `dDifference`, `ARG1`) at `count` states.
#[pyfunction]
pub fn difference_jacobian_q1<'py>(
    py: Python<'py>,
    q0: &[u8],
    q1: &[u8],
    count: usize,
    nv: usize,
) -> PyResult<Bound<'py, PyBytes>> {
    let base: BaseJacobian = |a, b| configuration::difference_jacobian_q1(&base_q(a), &base_q(b));
    jacobians(py, (q0, q1), (count, nv, nv + 1), base, 1.0)
}

//! `dh_dynamics._native`: the generator inside the Python package. It reads a robot's
//! description as the `dynamics` command does and gives back the robot's C header with the
//! signatures of its functions, which the package compiles and calls
//! (`dh_dynamics/_compiled.py`), or what any `dynamics` command prints (the readable
//! equations), and the method table's families (for the hint of a method a robot lacks).
//! Nothing of an algorithm is here: both are `dynamics-cli`'s.

use dynamics_codegen::emit_c::{Function, Precision, Returns};
use dynamics_codegen::method::{Family, Method};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyDict;

create_exception!(
    _native,
    GeneratorError,
    PyException,
    "A description the generator refused, or a command's usage error: the message as the \
     `dynamics` command prints it (`file:line:col: message`, one line per problem)."
);

/// The C header of the robot `words` name (`dynamics emit`'s words after `--lang c`), as a
/// dict: `robot`, `dof`, `fields`, `text`, and `functions`, each a dict of its signature.
#[pyfunction]
fn c_header(py: Python<'_>, words: Vec<String>) -> PyResult<Bound<'_, PyDict>> {
    let header = py
        .detach(|| dynamics_cli::c_header(words))
        .map_err(GeneratorError::new_err)?;
    let out = PyDict::new(py);
    out.set_item("robot", &header.robot)?;
    out.set_item("dof", header.dof)?;
    out.set_item("fields", &header.fields)?;
    out.set_item("text", &header.text)?;
    let functions = header
        .functions
        .iter()
        .map(|f| signature(py, f))
        .collect::<PyResult<Vec<_>>>()?;
    out.set_item("functions", functions)?;
    Ok(out)
}

/// One function's signature: its name, the method and its summary, its precision, its number
/// of parameters, its inputs `(name, length)`, its output arrays `(name, dims)`, and what it
/// returns (`nothing`, `value`, `status`).
fn signature<'py>(py: Python<'py>, f: &Function) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("name", &f.name)?;
    out.set_item("method", f.method.name())?;
    out.set_item("summary", f.method.summary())?;
    let dtype = match f.precision {
        Precision::Double => "float64",
        Precision::Single => "float32",
    };
    out.set_item("dtype", dtype)?;
    out.set_item("parameters", f.parameters)?;
    let arguments: Vec<(&str, usize)> = f.arguments.iter().map(|&(a, n)| (a.name(), n)).collect();
    out.set_item("arguments", arguments)?;
    let outputs: Vec<(&str, Vec<usize>)> = f
        .outputs
        .iter()
        .map(|a| (a.name.as_str(), a.dims.clone()))
        .collect();
    out.set_item("outputs", outputs)?;
    let returns = match f.returns {
        Returns::Nothing => "nothing",
        Returns::Value => "value",
        Returns::Status => "status",
    };
    out.set_item("returns", returns)?;
    Ok(out)
}

/// The method table: each method's name, its family's name, and whether that family is
/// opt-in (a robot has it only when asked for), for the hint of a method a robot lacks.
#[pyfunction]
fn methods() -> Vec<(&'static str, &'static str, bool)> {
    Method::ALL
        .iter()
        .map(|m| {
            let family: Family = m.family();
            (m.name(), family.name(), family.is_opt_in())
        })
        .collect()
}

/// What the `dynamics` command `words` prints (`["inspect", "robots/puma560.toml",
/// "--latex"]`).
#[pyfunction]
fn run(py: Python<'_>, words: Vec<String>) -> PyResult<String> {
    py.detach(|| dynamics_cli::run(words))
        .map_err(GeneratorError::new_err)
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(c_header, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(methods, m)?)?;
    m.add("GeneratorError", m.py().get_type::<GeneratorError>())?;
    Ok(())
}

//! `dh_dynamics._native`: the generator inside the Python package, through its front door
//! (`dynamics_codegen::pipeline`). It reads a robot's description as the derive does and gives
//! back the robot's C header with the signatures of its functions, which the package compiles
//! and calls (`dh_dynamics/_compiled.py`), or its readable equations, and the method table's
//! families (for the hint of a method a robot lacks). Nothing of an algorithm is here.
//!
//! Errors are data: a `GeneratorError` whose `diagnostics` are the door's, each a dict of
//! `file`, `line`, `column`, `message` and `help` (`file` is `None` for a mistake in the
//! arguments); `dh_dynamics/_errors.py` raises the package's exceptions from them.

mod configuration;
mod source;

use dynamics_codegen::method::{Family, Method};
use dynamics_codegen::pipeline::{
    self, Diagnostic, Format, Function, Precision, Readable, Returns,
};
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use source::Described;

create_exception!(
    _native,
    GeneratorError,
    PyException,
    "A description the generator refused, or arguments it cannot take: `diagnostics` lists \
     each problem as a dict of `file`, `line`, `column`, `message` and `help` (`None` where \
     it has none; `file` is `None` for a mistake in the arguments); the message prints them \
     as `file:line:col: message`, one per line."
);

/// The C header of the robot described at `path` (a URDF's chain from `base` to `tip`, or its branches to `tips`; the
/// hand frame `tool` of a description file) with the opt-in `families`, and the simplified
/// models its file asks for (`[simplify]`), as a dict: `robot`, `dof`, `fields`, `joint_rows`, `text`, and
/// `functions`, each a dict of its signature. With `floating`, the robot on a free-flying base
/// (the derive's `base = floating`; no simplified models): `dof` is then the velocity's length,
/// `n + 6`, and the header has the kinematics of its `frames` too (and with `contacts` their
/// contacts).
#[pyfunction]
// One argument per keyword of the Python signature, as pyo3 maps them.
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (path, *, base=None, tip=None, tips=Vec::new(), tool=None, check_inertia=true, families=Vec::new(), floating=false, contacts=false))]
fn c_header(
    py: Python<'_>,
    path: String,
    base: Option<String>,
    tip: Option<String>,
    tips: Vec<String>,
    tool: Option<[f64; 6]>,
    check_inertia: bool,
    families: Vec<String>,
    floating: bool,
    contacts: bool,
) -> PyResult<Bound<'_, PyDict>> {
    let described = Described {
        path,
        base,
        tip,
        tips,
        tool,
        check_inertia,
    };
    let header = py
        .detach(|| {
            let families =
                pipeline::families(&families).map_err(|d| vec![source::argument("families", d)])?;
            let loaded = described.load()?;
            if floating {
                // The kinematics too (Python's users, MPC, ask for them), the contacts where
                // asked (their closed form triples the header's compile time).
                let extra = pipeline::FloatingC {
                    kinematics: true,
                    contacts,
                    configuration: false,
                };
                return loaded.floating_c_header_with(families, extra, None);
            }
            let asked = loaded
                .simplification(&[])
                .map_err(|problems| problems.iter().map(Diagnostic::from).collect::<Vec<_>>())?;
            loaded
                .c_header(families, asked.as_ref(), None)
                .map_err(|d| vec![d])
        })
        .map_err(|diagnostics| generator_error(py, &diagnostics))?;
    let out = PyDict::new(py);
    out.set_item("robot", &header.robot)?;
    out.set_item("dof", header.dof)?;
    out.set_item("floating", header.floating)?;
    out.set_item("fields", &header.fields)?;
    out.set_item("joint_rows", &header.joint_rows)?;
    out.set_item("frames", &header.frames)?;
    out.set_item("text", &header.text)?;
    let functions = header
        .functions
        .iter()
        .map(|f| signature(py, f))
        .collect::<PyResult<Vec<_>>>()?;
    out.set_item("functions", functions)?;
    Ok(out)
}

/// The equations of motion of the robot described at `path` (as [`c_header`] reads it) in
/// the book's notation, or with `kinematics` its hand pose and Jacobians, or with `floating`
/// its M, h, g and τ on a free-flying base in Pinocchio's coordinates; as LaTeX with `latex`.
#[pyfunction]
// One argument per keyword of the Python signature, as pyo3 maps them.
#[allow(clippy::too_many_arguments)]
#[pyo3(signature = (path, *, base=None, tip=None, tips=Vec::new(), tool=None, check_inertia=true, latex=false, kinematics=false, floating=false))]
fn equations(
    py: Python<'_>,
    path: String,
    base: Option<String>,
    tip: Option<String>,
    tips: Vec<String>,
    tool: Option<[f64; 6]>,
    check_inertia: bool,
    latex: bool,
    kinematics: bool,
    floating: bool,
) -> PyResult<String> {
    let described = Described {
        path,
        base,
        tip,
        tips,
        tool,
        check_inertia,
    };
    let format = if latex { Format::Latex } else { Format::Text };
    let what = if kinematics {
        Readable::Kinematics
    } else {
        Readable::Motion
    };
    py.detach(|| {
        let loaded = described.load()?;
        if floating {
            return loaded.floating_readable(format);
        }
        loaded.readable(what, format).map_err(|d| vec![d])
    })
    .map_err(|diagnostics| generator_error(py, &diagnostics))
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

/// A `GeneratorError` of `diagnostics`: its message their lines, its `diagnostics` their data.
fn generator_error(py: Python<'_>, diagnostics: &[Diagnostic]) -> PyErr {
    let lines: Vec<String> = diagnostics.iter().map(ToString::to_string).collect();
    let error = GeneratorError::new_err(lines.join("\n"));
    let data = diagnostics.iter().map(|d| {
        let out = PyDict::new(py);
        out.set_item("file", &d.file)?;
        out.set_item("line", d.line)?;
        out.set_item("column", d.column)?;
        out.set_item("message", &d.message)?;
        out.set_item("help", &d.help)?;
        Ok(out)
    });
    let attached = data
        .collect::<PyResult<Vec<_>>>()
        .and_then(|data| error.value(py).setattr("diagnostics", data));
    match attached {
        Ok(()) => error,
        // Only if Python cannot make a dict or set an attribute (out of memory).
        Err(failure) => failure,
    }
}

/// The method table: each method's name, its family's name, and whether that family is
/// opt-in (a robot has it only when asked for), for the hint of a method a robot lacks; a
/// floating base's methods left out (Python does not load one yet).
#[pyfunction]
fn methods() -> Vec<(&'static str, &'static str, bool)> {
    Method::ALL
        .iter()
        .filter(|m| !m.family().is_floating())
        .map(|m| {
            let family: Family = m.family();
            (m.name(), family.name(), family.is_opt_in())
        })
        .collect()
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(c_header, m)?)?;
    m.add_function(wrap_pyfunction!(equations, m)?)?;
    m.add_function(wrap_pyfunction!(methods, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::integrate, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::difference, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::integrate_jacobian_v, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::integrate_jacobian_q, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::difference_jacobian_q0, m)?)?;
    m.add_function(wrap_pyfunction!(configuration::difference_jacobian_q1, m)?)?;
    m.add("GeneratorError", m.py().get_type::<GeneratorError>())?;
    Ok(())
}

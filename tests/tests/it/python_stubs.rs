//! The Python package's type stub of `Robot` (`python/dh_dynamics/robot.pyi`) declares every
//! method of the method table, which the package attaches at run time from the robot's C
//! header. Its methods are rendered here from `Method::ALL` (name, arguments, result, summary,
//! family) and compared with the block of the checked-in stub between its two marker comments,
//! so that a new row of the table fails this test until the stub is refreshed:
//!
//! ```text
//! DYNAMICS_BLESS=1 cargo test -p dynamics-tests --test it python_stubs
//! ```
//!
//! which rewrites that block (the rest of the stub, the constructors and attributes, is written
//! by hand); review the change with `git diff`.

use dynamics_codegen::method::{Family, Method, Returns};
use std::path::{Path, PathBuf};

/// The first and last lines of the generated block.
const BEGIN: &str = "    # The methods, generated from the method table";
const END: &str = "    # End of the generated methods.";

const ARRAY: &str = "NDArray[np.floating[Any]]";

fn stub_path() -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root");
    root.join("python/dh_dynamics/robot.pyi")
}

/// What the package returns for a result (`dh_dynamics/_methods.py`): an energy is a float for
/// one state and an array for a batch, the derivatives' structs are named tuples of the same
/// fields, anything else one array.
fn python_type(returns: Returns) -> String {
    match returns {
        Returns::Scalar => format!("float | {ARRAY}"),
        Returns::InverseDerivatives => "InverseDynamicsDerivatives".to_owned(),
        Returns::ForwardDerivatives => "ForwardDynamicsDerivatives".to_owned(),
        Returns::Matrix
        | Returns::Vector
        | Returns::Pose
        | Returns::Poses
        | Returns::Jacobian
        | Returns::Spatial
        | Returns::SolvedMatrix
        | Returns::SolvedVector
        | Returns::LinkColumns
        | Returns::JointColumns
        | Returns::LinkParameters
        | Returns::BaseColumns
        | Returns::BaseVector
        | Returns::BaseLinkMap
        | Returns::BaseJointMap
        | Returns::TipPoses
        | Returns::TipJacobians
        | Returns::TipSpatials => ARRAY.to_owned(),
    }
}

/// A method's declaration, its summary as its docstring, and how a robot gets it if it must
/// ask for it.
fn declaration(method: Method) -> String {
    let mut parameters = vec!["self".to_owned()];
    parameters.extend(
        method
            .arguments()
            .iter()
            .map(|a| format!("{}: ArrayLike", a.name())),
    );
    let (name, parameters) = (method.name(), parameters.join(", "));
    let returns = python_type(method.returns());
    let mut text = format!("    def {name}({parameters}) -> {returns}:\n");
    // Past 99 columns, wrapped as black wraps a signature.
    if text.trim_end().chars().count() > 99 {
        text = format!("    def {name}(\n        {parameters}\n    ) -> {returns}:\n");
    }
    let family = method.family();
    let mut doc = method.summary().replace('\\', "\\\\").replace('"', "\\\"");
    if family == Family::Simplified {
        doc += "\n\n        Only for a description file with a ``[simplify]`` table.\n        ";
    } else if family.is_opt_in() {
        let name = family.name();
        doc += &format!("\n\n        Opt-in: ``families=['{name}']``.\n        ");
    }
    text + &format!("        \"\"\"{doc}\"\"\"\n")
}

/// The generated block, from its first marker line to its last.
fn render() -> String {
    let mut text = format!(
        "{BEGIN} (`dynamics-runtime/src/methods.rs`) by\n    \
         # `tests/tests/it/python_stubs.rs`: `DYNAMICS_BLESS=1 cargo test -p dynamics-tests\n    \
         # --test it python_stubs` rewrites them to the end marker. Each input is one state, shape\n    \
         # (n,), or a batch, shape (N, n); the result has (N,) before one state's shape for a batch.\n"
    );
    // Python loads no floating base yet: its rows are left out.
    for &method in Method::ALL.iter().filter(|m| !m.family().is_floating()) {
        text += &declaration(method);
    }
    text + END
}

/// The byte range of the generated block in the stub's text.
fn block(stub: &str) -> std::ops::Range<usize> {
    let start = stub
        .find(BEGIN)
        .expect("robot.pyi: the generated block's first line");
    let end = stub[start..].find(END).expect("robot.pyi: its end marker") + start + END.len();
    start..end
}

#[test]
fn the_python_stub_declares_every_method_of_the_table() {
    let path = stub_path();
    let stub = std::fs::read_to_string(&path).expect("python/dh_dynamics/robot.pyi");
    let range = block(&stub);
    let rendered = render();
    if std::env::var_os("DYNAMICS_BLESS").is_some_and(|v| v != "0") {
        let mut refreshed = stub.clone();
        refreshed.replace_range(range, &rendered);
        std::fs::write(&path, refreshed).expect("write robot.pyi");
        return;
    }
    let committed = &stub[range.clone()];
    if committed != rendered {
        let old: Vec<&str> = committed.lines().collect();
        let new: Vec<&str> = rendered.lines().collect();
        let i = (0..)
            .find(|&i| old.get(i) != new.get(i))
            .expect("a line differs");
        let first_line = stub[..range.start].lines().count() + 1;
        panic!(
            "{} is stale from line {}:\n  committed: {}\n  now:       {}\n\nIf the method \
             table changed, refresh the stub with\n  DYNAMICS_BLESS=1 cargo test -p \
             dynamics-tests --test it python_stubs\nand review `git diff`.",
            path.display(),
            first_line + i,
            old.get(i).unwrap_or(&"(none)"),
            new.get(i).unwrap_or(&"(none)"),
        );
    }
}

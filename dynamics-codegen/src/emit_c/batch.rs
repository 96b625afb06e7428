//! The header's batch functions: each function over `n` states in one call, for callers that
//! hold many states in flat arrays (NumPy's `(N, n)` arrays, a horizon of knots).
//!
//! `{name}_batch(size_t n, [params,] q, .., out..)` reads state `i` at `q + dof * i` and writes
//! its result at `out + len * i`, where `len` is the number of elements of one result (36 for
//! M of 6 joints): row-major arrays of `n` rows, each the single-state function's array. The
//! parameters are the same for every state. A scalar result becomes an array of `n`; a solve's
//! status an array of `n` (which may be `NULL`), and the batch returns how many states failed.
//!
//! They sit behind `DYNAMICS_BATCH`, with `DYNAMICS_BATCH_API` (default `static inline`) before
//! each, so that a shared library can export them (`-DDYNAMICS_BATCH_API=` in a `.c` file that
//! includes the header) while a header-only user pays nothing.

use super::function::{Function, Returns};

/// The batch section of the header: the guard, the linkage macro, and one batch function per
/// single-state function.
pub(super) fn section(functions: &[Function]) -> String {
    let mut text = String::from(
        "#ifdef DYNAMICS_BATCH\n\
         /* Each function over n states: row i of every array at (elements of one state) * i. */\n\
         #include <stddef.h>\n\
         #ifndef DYNAMICS_BATCH_API\n\
         #define DYNAMICS_BATCH_API static inline\n\
         #endif\n\n",
    );
    for f in functions {
        text.push_str(&definition(f));
        text.push('\n');
    }
    text.push_str("#endif /* DYNAMICS_BATCH */\n\n");
    text
}

/// One batch function: a loop over the states that calls the single-state function.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn definition(f: &Function) -> String {
    let ty = f.precision.c_type();
    let mut parameters = vec!["size_t n".to_owned()];
    let mut call = Vec::new();
    if f.parameters > 0 {
        parameters.push(format!("const {ty} *params"));
        call.push("params".to_owned());
    }
    for &(argument, len) in &f.arguments {
        let name = argument.name();
        parameters.push(format!("const {ty} *{name}"));
        call.push(format!("{name} + {len} * i"));
    }
    for array in &f.outputs {
        parameters.push(format!("{ty} *{}", array.name));
        let len: usize = array.dims.iter().product();
        // `double m[6][6]` is a `double (*)[6]`: the row type of the array after its first
        // dimension.
        let rows: String = array.dims[1..].iter().map(|d| format!("[{d}]")).collect();
        let at = format!("{} + {len} * i", array.name);
        call.push(if rows.is_empty() {
            at
        } else {
            format!("({ty} (*){rows})({at})")
        });
    }
    let call = format!("{}({})", f.name, call.join(", "));
    let (returns, body) = match f.returns {
        Returns::Nothing => ("void", format!("        {call};\n")),
        Returns::Value => {
            parameters.push(format!("{ty} *value"));
            ("void", format!("        value[i] = {call};\n"))
        }
        Returns::Status => {
            parameters.push("int *status".to_owned());
            (
                "size_t",
                format!(
                    "        int failed = {call};\n        \
                     if (status) status[i] = failed;\n        \
                     failures += failed != 0;\n"
                ),
            )
        }
    };
    let (open, close) = if f.returns == Returns::Status {
        ("    size_t failures = 0;\n", "    return failures;\n")
    } else {
        ("", "")
    };
    format!(
        "/* {name} at each of n states. */\n\
         DYNAMICS_BATCH_API {returns} {name}_batch({parameters}) {{\n\
         {open}    size_t i;\n    for (i = 0; i < n; ++i) {{\n{body}    }}\n{close}}}\n",
        name = f.name,
        parameters = parameters.join(", "),
    )
}

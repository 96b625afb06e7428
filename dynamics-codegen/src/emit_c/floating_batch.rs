//! The batch twins of a floating base's functions beyond the table's (`floating_extras.rs`),
//! as `batch.rs` writes the table's: `{name}_batch(size_t n, [params,] inputs.., outputs..
//! [, int *status])`, state `i` of each flat array at `len * i`, the parameters the same for
//! every state, a status per state (`NULL` allowed) and the count of failures returned where
//! the function returns a status. Behind `DYNAMICS_BATCH`, `DYNAMICS_BATCH_API` before each
//! (the Python package exports them from its shared library).
//! The parameters' argument of every such function is spelled here too ([`parameters`]).

use super::expr::Precision;
use crate::trace::Equations;

/// One single-state function's signature, as its batch twin reads it.
pub(super) struct Signature {
    /// Its name after the prefix, without the precision's suffix.
    pub(super) name: &'static str,
    /// Its inputs after the parameters: name, elements per state, dimensions after the first
    /// (`[6]` of `wrenches[F][6]`), and whether they are `int`s.
    pub(super) inputs: Vec<(&'static str, usize, Vec<usize>, bool)>,
    /// Its output arrays: name and dimensions.
    pub(super) outputs: Vec<(&'static str, Vec<usize>)>,
    /// Whether it returns a status.
    pub(super) status: bool,
}

/// The batch section of `signatures` in both precisions, for functions `{prefix}_*` taking
/// `parameters` parameters first.
pub(super) fn section(signatures: &[Signature], prefix: &str, parameters: usize) -> String {
    let mut text = "#ifdef DYNAMICS_BATCH\n#include <stddef.h>\n#ifndef DYNAMICS_BATCH_API\n\
                    #define DYNAMICS_BATCH_API static inline\n#endif\n\n"
        .to_owned();
    for p in Precision::ALL {
        for s in signatures {
            text.push_str(&definition(s, prefix, parameters, p));
        }
    }
    text.push_str("#endif /* DYNAMICS_BATCH */\n\n");
    text
}

/// `(double (*)[6])(x + 24 * i)`, or `x + 6 * i` for a vector.
fn at(ty: &str, name: &str, dims: &[usize], len: usize, constant: bool) -> String {
    let at = format!("{name} + {len} * i");
    if dims.is_empty() {
        return at;
    }
    let rows: String = dims.iter().map(|d| format!("[{d}]")).collect();
    let constant = if constant { "const " } else { "" };
    format!("({constant}{ty} (*){rows})({at})")
}

fn definition(s: &Signature, prefix: &str, parameters: usize, p: Precision) -> String {
    let ty = p.c_type();
    let name = format!("{prefix}_{}{}", s.name, p.suffix());
    let mut arguments = vec!["size_t n".to_owned()];
    let mut call = Vec::new();
    if parameters > 0 {
        arguments.push(format!("const {ty} *params"));
        call.push("params".to_owned());
    }
    for (input, len, dims, int) in &s.inputs {
        let t = if *int { "int" } else { ty };
        arguments.push(format!("const {t} *{input}"));
        call.push(at(t, input, dims, *len, true));
    }
    for (output, dims) in &s.outputs {
        arguments.push(format!("{ty} *{output}"));
        let len: usize = dims.iter().product();
        call.push(at(ty, output, &dims[1..], len, false));
    }
    let call = format!("{name}({})", call.join(", "));
    let (returns, open, body, close) = if s.status {
        arguments.push("int *status".to_owned());
        (
            "size_t",
            "    size_t failures = 0;\n",
            format!(
                "        int failed = {call};\n        if (status) status[i] = failed;\n        \
                 failures += failed != 0;\n"
            ),
            "    return failures;\n",
        )
    } else {
        ("void", "", format!("        {call};\n"), "")
    };
    format!(
        "/* {name} at each of n states. */\n\
         DYNAMICS_BATCH_API {returns} {name}_batch({}) {{\n\
         {open}    size_t i;\n    for (i = 0; i < n; ++i) {{\n{body}    }}\n{close}}}\n\n",
        arguments.join(", ")
    )
}

/// `const double params[K]` where the robot has parameters (struct fields).
pub(super) fn parameters(eq: &Equations, p: Precision) -> Vec<String> {
    if eq.fields.is_empty() {
        vec![]
    } else {
        vec![format!("const {} params[{}]", p.c_type(), eq.fields.len())]
    }
}

//! The driver's calls of the batch functions (`DYNAMICS_BATCH`): every function over all the
//! states in one call, each state's result printed as `{name}_batch:{part}`, for the check that
//! it is the single-state call's, bit for bit.

use super::Robot;
use dynamics_codegen::emit_c::{Function, Precision, Returns};
use dynamics_codegen::method::Argument;

/// The block after the per-state loop: the inputs of every state in both precisions, then a
/// batch call per function and its results printed state by state.
pub fn calls(robot: &Robot, states: usize) -> String {
    let n = robot.eq.dof;
    let nq = n + super::q_shift(&robot.eq);
    let mut c = format!(
        "    {{\n        static double wrench_all[{states}][6];\n        \
         static float q_all_f[{states}][{nq}], qd_all_f[{states}][{n}], \
         qdd_all_f[{states}][{n}], tau_all_f[{states}][{n}], wrench_all_f[{states}][6];\n        \
         for (s = 0; s < {states}; ++s) {{\n            for (i = 0; i < 6; ++i) {{\n                \
         wrench_all[s][i] = wrench[i];\n                wrench_all_f[s][i] = (float)wrench[i];\n            }}\n            \
         for (i = 0; i < {nq}; ++i) q_all_f[s][i] = (float)q[s][i];\n            \
         for (i = 0; i < {n}; ++i) {{\n                \
         qd_all_f[s][i] = (float)qd[s][i];\n                qdd_all_f[s][i] = (float)qdd[s][i];\n                \
         tau_all_f[s][i] = (float)tau[s][i];\n            }}\n        }}\n        \
         (void)wrench_all;\n        (void)wrench_all_f;\n"
    );
    if let Some(w) = super::tip_wrenches_length(robot) {
        c.push_str(&format!(
            "        static double wrenches_all[{states}][{w}];\n        \
             static float wrenches_all_f[{states}][{w}];\n        \
             for (s = 0; s < {states}; ++s) for (i = 0; i < {w}; ++i) {{\n            \
             wrenches_all[s][i] = wrenches[i];\n            \
             wrenches_all_f[s][i] = (float)wrenches[i];\n        }}\n"
        ));
    }
    for f in &robot.functions {
        c.push_str(&call(f, states));
    }
    c.push_str("    }\n");
    c
}

/// The block calling `f`'s batch over the `states` and printing each state's result.
fn call(f: &Function, states: usize) -> String {
    let (ty, show, suffix, params) = match f.precision {
        Precision::Double => ("double", "show", "", "params"),
        Precision::Single => ("float", "show_f32", "_f", "params_f"),
    };
    let mut args = vec![states.to_string()];
    if f.parameters > 0 {
        args.push(params.to_owned());
    }
    for &(a, _) in &f.arguments {
        let name = a.name();
        args.push(match (a, f.precision) {
            (Argument::Wrench, _) => format!("&wrench_all{suffix}[0][0]"),
            (Argument::Wrenches, _) => format!("&wrenches_all{suffix}[0][0]"),
            (_, Precision::Double) => format!("&{name}[0][0]"),
            (_, Precision::Single) => format!("&{name}_all_f[0][0]"),
        });
    }
    let mut block = format!("        {{\n            static int status[{states}];\n");
    for (k, array) in f.outputs.iter().enumerate() {
        let len: usize = array.dims.iter().product();
        block.push_str(&format!(
            "            static {ty} out{k}[{states}][{len}];\n"
        ));
        args.push(format!("&out{k}[0][0]"));
    }
    match f.returns {
        Returns::Nothing => {}
        Returns::Value => {
            block.push_str(&format!("            static {ty} value[{states}];\n"));
            args.push("value".to_owned());
        }
        Returns::Status => args.push("status".to_owned()),
    }
    let call = format!("{}_batch({})", f.name, args.join(", "));
    if f.returns == Returns::Status {
        block.push_str(&format!("            (void){call};\n"));
    } else {
        block.push_str(&format!("            {call};\n"));
    }
    block.push_str(&format!("            for (s = 0; s < {states}; ++s) {{\n"));
    if f.returns == Returns::Value {
        block.push_str(&format!(
            "                {show}(\"{}_batch:0\", s, status[s], &value[s], 1);\n",
            f.name
        ));
    }
    for (k, array) in f.outputs.iter().enumerate() {
        let len: usize = array.dims.iter().product();
        block.push_str(&format!(
            "                {show}(\"{}_batch:{k}\", s, status[s], out{k}[s], {len});\n",
            f.name
        ));
    }
    block.push_str("            }\n        }\n");
    block
}

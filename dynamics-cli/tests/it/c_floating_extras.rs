//! A floating base's C functions beyond the method table's (`dynamics emit --lang c ROBOT
//! --floating --kinematics --contacts --configuration`), called by the driver of Solo 12's
//! header that `c_floating.rs` compiles anyway (one header, one build per compiler), at the 12
//! states of Pinocchio 4.1's data: the kinematics against `solo12_kinematics.json`
//! (`centerOfMass`, `jacobianCenterOfMass`, `computeCentroidalMap`, its time variation times
//! `v`, `oMf`, `getFrameJacobian` and `getFrameClassicalAcceleration` in LOCAL_WORLD_ALIGNED and
//! LOCAL), the contacts against `solo12_contacts.json` (`rnea` and `aba` with `fext`,
//! `constraintDynamics` with the data's feet held) and `integrate`/`difference` and their
//! Jacobians (`dIntegrate`, `dDifference`, ARG0 and ARG1) against `solo12.json`, each `double` result to 1e-12 scaled (by its largest element, at least 1, as
//! `dynamics_reference::scaled_error`), each `float` one against the `double` one. ANYmal B's
//! and the G1's headers the same, against `<robot>_extras.json` (`make.py`'s `extras`), the
//! G1's solves to 1e-10 (its M's condition number reaches 3.5e5).

use crate::c_support::{c_array, printed, root, Printed};
use dynamics_reference::scaled_error;
use serde_json::Value;
use std::collections::BTreeMap;

/// The data: per state, its `solo12.json`, `solo12_kinematics.json` and `solo12_contacts.json`
/// samples, and the frames' names.
pub struct Data {
    states: Vec<Value>,
    kinematics: Vec<Value>,
    contacts: Vec<Value>,
    frames: Vec<String>,
    /// How far the solves' `double` results (the accelerations with wrenches, the constrained
    /// `a` and `λ`) may be from Pinocchio's, scaled: 1e-12, more where M's condition number
    /// amplifies the rounding (the G1's).
    pub solve_tolerance: f64,
}

/// The keys of [`check`]'s results that solve with M's factors.
const SOLVES: [&str; 4] = ["aw", "af", "ac", "lambda"];

fn samples(file: &str) -> Value {
    let text = std::fs::read_to_string(root().join("tests/data/floating").join(file))
        .expect("reference data");
    serde_json::from_str(&text).expect("JSON")
}

/// Solo 12's data.
pub fn solo12() -> Data {
    let (states, kinematics, contacts) = (
        samples("solo12.json"),
        samples("solo12_kinematics.json"),
        samples("solo12_contacts.json"),
    );
    let list = |v: &Value| v["samples"].as_array().expect("samples").clone();
    let frames = kinematics["frames"]
        .as_array()
        .expect("frames")
        .iter()
        .map(|f| f.as_str().expect("a name").to_owned())
        .collect();
    Data {
        states: list(&states),
        kinematics: list(&kinematics),
        contacts: list(&contacts),
        frames,
        solve_tolerance: 1e-12,
    }
}

/// The data of a robot beyond Solo 12, `<robot>_extras.json` (`make.py`'s `extras`): each
/// sample holds what Solo 12's three files hold (the kinematics, the contacts, the
/// configuration space and the state's `tau`), joints in the file's order.
pub fn extras(robot: &str) -> Data {
    let data = samples(&format!("{robot}_extras.json"));
    let list = data["samples"].as_array().expect("samples").clone();
    let frames = data["frames"]
        .as_array()
        .expect("frames")
        .iter()
        .map(|f| f.as_str().expect("a name").to_owned())
        .collect();
    Data {
        states: list.clone(),
        kinematics: list.clone(),
        contacts: list,
        frames,
        solve_tolerance: 1e-12,
    }
}

/// A JSON number, vector or matrix, rows first.
fn flat(value: &Value) -> Vec<f64> {
    match value {
        Value::Array(items) => items.iter().flat_map(flat).collect(),
        Value::Bool(b) => vec![f64::from(u8::from(*b))],
        x => vec![x.as_f64().expect("a number")],
    }
}

/// `static const TYPE NAME[..] = {..}`: every state's `pick` one after the other.
fn table(ty: &str, name: &str, data: &[Value], pick: impl Fn(&Value) -> Vec<f64>) -> String {
    let values: Vec<f64> = data.iter().flat_map(pick).collect();
    let text = if ty == "int" {
        let items: Vec<String> = values.iter().map(|x| format!("{x}")).collect();
        format!("{{{}}}", items.join(", "))
    } else {
        c_array(&values)
    };
    format!(
        "            static const {ty} {name}[{}] = {text};\n",
        values.len()
    )
}

/// The frames' wrenches `[f, m]` of contact sample `c` under `key`: forces with zero moments.
fn wrenches(c: &Value, key: &str) -> Vec<f64> {
    c[key]
        .as_array()
        .expect("a row per frame")
        .iter()
        .flat_map(|row| {
            let mut w = flat(row);
            w.resize(6, 0.0);
            w
        })
        .collect()
}

/// The driver's statements at state `s`: each function of the header `name`, `double` and
/// `float`, its results printed as `c_support::parse` reads them.
pub fn calls(name: &str, data: &Data, nv: usize) -> String {
    let (nq, frames) = (nv + 1, data.frames.len());
    let mut c = declarations(data, nv);
    for (call, out, len, status) in called(nv, frames) {
        let call = call
            .replace("{nv}", &nv.to_string())
            .replace("{nq}", &nq.to_string())
            .replace("{frames}", &frames.to_string());
        let assign = if status { "r = " } else { "r = 0; " };
        let show = if out.ends_with("_f") {
            "show_f32"
        } else {
            "show"
        };
        let ty = if out.ends_with("_f") {
            "float"
        } else {
            "double"
        };
        c.push_str(&format!(
            "            {assign}{name}_{call};\n            \
             {show}(\"{out}:0\", s, r, (const {ty} *){out}, {len});\n"
        ));
    }
    c.push_str(&format!(
        "            show(\"lambda:0\", s, r, (const double *)lambda, {});\n            \
         show_f32(\"lambda_f:0\", s, r, (const float *)lambda_f, {});\n",
        3 * frames,
        3 * frames
    ));
    c.push_str(&batches(name, data.states.len(), nv));
    c.push_str("        }\n");
    c
}

/// The configuration space's Jacobians' batch twins over every state, state `s`'s printed as
/// `{key}_batch` (checked bit for bit against the single state's).
fn batches(name: &str, states: usize, nv: usize) -> String {
    let size = states * nv * nv;
    let mut c = String::new();
    for (function, key, second) in [
        ("integrate_jacobian_v", "jv", "dv"),
        ("integrate_jacobian_q", "jq", "dv"),
        ("difference_jacobian_q0", "j0", "q1"),
        ("difference_jacobian_q1", "j1", "q1"),
    ] {
        c.push_str(&format!(
            "            {{\n                static double all[{size}];\n                \
             {name}_{function}_batch({states}, &q[0][0], {second}, all);\n                \
             show(\"{key}_batch:0\", s, 0, all + {} * s, {});\n            }}\n",
            nv * nv,
            nv * nv
        ));
    }
    c
}

/// The block's opening: the data's inputs beyond the driver's and the results' arrays.
fn declarations(data: &Data, nv: usize) -> String {
    let (nq, frames) = (nv + 1, data.frames.len());
    let mut c = "        {\n".to_owned();
    c.push_str(&table("double", "tau_rnea", &data.states, |s| {
        flat(&s["tau"])
    }));
    c.push_str(&table("double", "dv", &data.states, |s| flat(&s["dv"])));
    c.push_str(&table("double", "q1", &data.states, |s| flat(&s["q1"])));
    c.push_str(&table("double", "wrenches", &data.contacts, |c| {
        wrenches(c, "wrenches")
    }));
    c.push_str(&table("double", "forces", &data.contacts, |c| {
        wrenches(c, "forces")
    }));
    c.push_str(&table("int", "held", &data.contacts, |c| {
        flat(&c["in_contact"])
    }));
    c.push_str(&format!(
        "            double com[3], jcom[3][{nv}], ag[6][{nv}], agd[6], poses[{frames}][3][4];
            double jw[{frames}][6][{nv}], jl[{frames}][6][{nv}], bw[{frames}][6], bl[{frames}][6];
            double tw[{nv}], tf[{nv}], aw[{nv}], af[{nv}], ac[{nv}], lambda[{frames}][3], qn[{nq}], dq[{nv}];
            float com_f[3], jw_f[{frames}][6][{nv}], bw_f[{frames}][6], ac_f[{nv}], lambda_f[{frames}][3];
            float tau_rnea_f[{nv}], dv_f[{nv}], q1_f[{nq}], qn_f[{nq}], dq_f[{nv}];
            double jv[{nv}][{nv}], jq[{nv}][{nv}], j0[{nv}][{nv}], j1[{nv}][{nv}];
            float jv_f[{nv}][{nv}], jq_f[{nv}][{nv}], j0_f[{nv}][{nv}], j1_f[{nv}][{nv}];
            const double (*w)[6] = (const double (*)[6])(wrenches + {w} * s);
            const double (*fo)[6] = (const double (*)[6])(forces + {w} * s);
            int r;
            for (i = 0; i < {nv}; ++i) {{
                tau_rnea_f[i] = (float)tau_rnea[{nv} * s + i];
                dv_f[i] = (float)dv[{nv} * s + i];
            }}
            for (i = 0; i < {nq}; ++i) q1_f[i] = (float)q1[{nq} * s + i];
",
        w = 6 * frames
    ));
    c
}

/// Each call (its text after the prefix, `{nv}`, `{nq}`, `{frames}` to fill in), the array it
/// prints, its length, and whether it returns a status.
#[allow(clippy::too_many_lines)] // A table, one call a row.
fn called(nv: usize, frames: usize) -> [(&'static str, &'static str, usize, bool); 30] {
    let nq = nv + 1;
    [
        ("center_of_mass(q[s], com)", "com", 3, false),
        ("center_of_mass_jacobian(q[s], jcom)", "jcom", 3 * nv, false),
        ("centroidal_momentum_matrix(q[s], ag)", "ag", 6 * nv, false),
        (
            "centroidal_momentum_bias(q[s], qd[s], agd)",
            "agd",
            6,
            false,
        ),
        ("frame_poses(q[s], poses)", "poses", 12 * frames, false),
        (
            "frame_jacobians_world_aligned(q[s], jw)",
            "jw",
            6 * nv * frames,
            false,
        ),
        (
            "frame_jacobians_local(q[s], jl)",
            "jl",
            6 * nv * frames,
            false,
        ),
        (
            "frame_acceleration_biases_world_aligned(q[s], qd[s], bw)",
            "bw",
            6 * frames,
            false,
        ),
        (
            "frame_acceleration_biases_local(q[s], qd[s], bl)",
            "bl",
            6 * frames,
            false,
        ),
        (
            "inverse_dynamics_with_wrenches(q[s], qd[s], qdd[s], w, tw)",
            "tw",
            nv,
            false,
        ),
        (
            "inverse_dynamics_with_wrenches(q[s], qd[s], qdd[s], fo, tf)",
            "tf",
            nv,
            false,
        ),
        (
            "forward_dynamics_with_wrenches(q[s], qd[s], tau_rnea + {nv} * s, w, aw)",
            "aw",
            nv,
            true,
        ),
        (
            "forward_dynamics_with_wrenches(q[s], qd[s], tau_rnea + {nv} * s, fo, af)",
            "af",
            nv,
            true,
        ),
        (
            "contact_dynamics(q[s], qd[s], tau_rnea + {nv} * s, held + {frames} * s, ac, lambda)",
            "ac",
            nv,
            true,
        ),
        ("integrate(q[s], dv + {nv} * s, qn)", "qn", nq, false),
        ("difference(q[s], q1 + {nq} * s, dq)", "dq", nv, false),
        (
            "integrate_jacobian_v(q[s], dv + {nv} * s, jv)",
            "jv",
            nv * nv,
            false,
        ),
        (
            "integrate_jacobian_q(q[s], dv + {nv} * s, jq)",
            "jq",
            nv * nv,
            false,
        ),
        (
            "difference_jacobian_q0(q[s], q1 + {nq} * s, j0)",
            "j0",
            nv * nv,
            false,
        ),
        (
            "difference_jacobian_q1(q[s], q1 + {nq} * s, j1)",
            "j1",
            nv * nv,
            false,
        ),
        ("center_of_mass_f32(q_f, com_f)", "com_f", 3, false),
        (
            "frame_jacobians_world_aligned_f32(q_f, jw_f)",
            "jw_f",
            6 * nv * frames,
            false,
        ),
        (
            "frame_acceleration_biases_world_aligned_f32(q_f, qd_f, bw_f)",
            "bw_f",
            6 * frames,
            false,
        ),
        (
            "contact_dynamics_f32(q_f, qd_f, tau_rnea_f, held + {frames} * s, ac_f, lambda_f)",
            "ac_f",
            nv,
            true,
        ),
        ("integrate_f32(q_f, dv_f, qn_f)", "qn_f", nq, false),
        ("difference_f32(q_f, q1_f, dq_f)", "dq_f", nv, false),
        (
            "integrate_jacobian_v_f32(q_f, dv_f, jv_f)",
            "jv_f",
            nv * nv,
            false,
        ),
        (
            "integrate_jacobian_q_f32(q_f, dv_f, jq_f)",
            "jq_f",
            nv * nv,
            false,
        ),
        (
            "difference_jacobian_q0_f32(q_f, q1_f, j0_f)",
            "j0_f",
            nv * nv,
            false,
        ),
        (
            "difference_jacobian_q1_f32(q_f, q1_f, j1_f)",
            "j1_f",
            nv * nv,
            false,
        ),
    ]
}

/// Checks what the driver of [`calls`] printed (by compiler `label`).
pub fn check(out: &Printed, label: &str, data: &Data) {
    // The largest error of each `double` result, printed for the docs.
    let mut worst = BTreeMap::<String, f64>::new();
    for (s, ((state, kin), contact)) in data
        .states
        .iter()
        .zip(&data.kinematics)
        .zip(&data.contacts)
        .enumerate()
    {
        let frame = |key: &str| -> Vec<f64> {
            data.frames
                .iter()
                .flat_map(|f| flat(&kin["frames"][f][key]))
                .collect()
        };
        let poses: Vec<f64> = data
            .frames
            .iter()
            .flat_map(|f| {
                let (r, p) = (
                    &kin["frames"][f]["rotation"],
                    &kin["frames"][f]["translation"],
                );
                (0..3).flat_map(move |i| {
                    let mut row = flat(&r[i]);
                    row.push(p[i].as_f64().expect("a number"));
                    row
                })
            })
            .collect();
        let wants = [
            ("com", flat(&kin["com"])),
            ("jcom", flat(&kin["Jcom"])),
            ("ag", flat(&kin["Ag"])),
            ("agd", flat(&kin["dAg_v"])),
            ("poses", poses),
            ("jw", frame("J_world_aligned")),
            ("jl", frame("J_local")),
            ("bw", frame("dJv_world_aligned")),
            ("bl", frame("dJv_local")),
            ("tw", flat(&contact["tau_wrenches"])),
            ("tf", flat(&contact["tau_forces"])),
            ("aw", flat(&contact["a_wrenches"])),
            ("af", flat(&contact["a_forces"])),
            ("ac", flat(&contact["a_contact"])),
            ("lambda", flat(&contact["lambda"])),
            ("qn", flat(&state["q_next"])),
            ("dq", flat(&state["dq"])),
            ("jv", flat(&state["dintegrate_dv"])),
            ("jq", flat(&state["dintegrate_dq"])),
            ("j0", flat(&state["ddifference_dq0"])),
            ("j1", flat(&state["ddifference_dq1"])),
        ];
        check_jacobians(out, label, s);
        for (key, want) in &wants {
            let (status, got) = printed(out, key, 0, s);
            assert_eq!(*status, 0, "{label}: {key} at sample {s}");
            let e = scaled_error(got, want);
            let tolerance = if SOLVES.contains(key) {
                data.solve_tolerance
            } else {
                1e-12
            };
            assert!(e <= tolerance, "{label}: {key} at sample {s}: off by {e:e}");
            let largest = worst.entry((*key).to_owned()).or_insert(0.0);
            *largest = largest.max(e);
        }
        check_float(out, label, s, &mut worst);
    }
    let worst: Vec<String> = worst.iter().map(|(k, e)| format!("{k} {e:.1e}")).collect();
    eprintln!("{label}: the largest scaled errors: {}", worst.join(", "));
}

/// The `float` results at state `s` against the `double` ones (the contacts solve with M's
/// factors, whose condition number costs digits), each's largest error kept in `worst`.
fn check_float(out: &Printed, label: &str, s: usize, worst: &mut BTreeMap<String, f64>) {
    for (key, tolerance) in [
        ("com", 1e-5),
        ("jw", 1e-5),
        ("bw", 1e-4),
        ("ac", 1e-2),
        ("lambda", 1e-2),
        ("qn", 1e-5),
        ("dq", 1e-4),
    ] {
        let (_, want) = printed(out, key, 0, s);
        let (status, got) = printed(out, &format!("{key}_f"), 0, s);
        assert_eq!(*status, 0, "{label}: {key}_f at sample {s}");
        let e = scaled_error(got, want);
        assert!(
            e <= tolerance,
            "{label}: {key}_f at sample {s}: off by {e:e}"
        );
        let largest = worst.entry(format!("{key}_f")).or_insert(0.0);
        *largest = largest.max(e);
    }
}

/// The configuration space's Jacobians at state `s` beyond their check against Pinocchio's:
/// the batch twins bit for bit the single state's, `float` against `double`.
fn check_jacobians(out: &Printed, label: &str, s: usize) {
    for key in ["jv", "jq", "j0", "j1"] {
        let (_, single) = printed(out, key, 0, s);
        let (_, batch) = printed(out, &format!("{key}_batch"), 0, s);
        assert_eq!(single, batch, "{label}: {key}'s batch twin at sample {s}");
        let (_, got) = printed(out, &format!("{key}_f"), 0, s);
        let e = scaled_error(got, single);
        assert!(e <= 1e-5, "{label}: {key}_f at sample {s}: off by {e:e}");
    }
}

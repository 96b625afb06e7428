//! Names from user text in the code `dynamics emit` writes: a robot's name and its parameters'
//! that Rust or C reserve give code that compiles (a raw field `r#type`, a struct `RobotSelf`,
//! a C local `p_2`) or a clear error where they are written; two robots whose names give one C
//! prefix (`arm-a`, `arm_a`) cannot be included together, and `--prefix` separates them.

use crate::c_support;
use crate::compile_support;

use compile_support::{c_compile, dynamics_in, emitted, rustc_check, scratch};
use std::path::Path;

/// A one-joint robot file named `file` in `dir`: the robot `name`, its link length `a` and mass
/// `mass` (a number or a parameter's name), as written in TOML strings.
fn robot(dir: &Path, file: &str, name: &str, a: &str, mass: &str) {
    // A TOML basic string: `"`, `\` and control characters escaped.
    let name: String = name
        .chars()
        .map(|c| match c {
            '"' | '\\' => format!("\\{c}"),
            c if c.is_control() => format!("\\u{:04X}", u32::from(c)),
            c => c.to_string(),
        })
        .collect();
    let text = format!(
        "name = \"{name}\"\ngravity = [0, 0, -9.81]\n\n[[joints]]\ntype = \"revolute\"\n\
         a = {a}\nmass = \"{mass}\"\n"
    );
    std::fs::write(dir.join(file), text).expect("write");
}

/// Robot names Rust reserves or the generated code could mistake, and parameter names that
/// are keywords (of some edition), not ASCII or not snake case.
const ROBOT_NAMES: [&str; 16] = [
    "self",
    "Self",
    "type",
    "crate",
    "super",
    "1arm",
    "ñ",
    "-/-",
    "none",
    "some",
    "option",
    "t",
    "dynamics",
    "configuration",
    "arm\nfn x() {}",
    "a\u{0}b",
];
const PARAMETERS: [&str; 11] = [
    "type",
    "int",
    "gen",
    "async",
    "r#match",
    "self.fn",
    "ñ",
    "L1",
    "union",
    "r#abstract",
    "_m",
];

#[test]
fn reserved_names_give_rust_that_compiles() {
    let dir = scratch("names_rust");
    let mut modules = Vec::new();
    for (k, name) in ROBOT_NAMES.iter().enumerate() {
        robot(&dir, &format!("r{k}.toml"), name, "1", "m");
        let text = emitted(&dir, &["emit", &format!("r{k}.toml")]);
        modules.push((format!("robot{k}"), text));
    }
    for (k, parameter) in PARAMETERS.iter().enumerate() {
        robot(
            &dir,
            &format!("p{k}.toml"),
            "arm",
            "1",
            &format!("2 * {parameter}"),
        );
        let text = emitted(&dir, &["emit", &format!("p{k}.toml")]);
        modules.push((format!("parameter{k}"), text));
    }
    let text = |k: usize| &modules[k].1;
    assert!(text(0).contains("pub struct RobotSelf"), "{}", text(0));
    assert!(text(1).contains("pub struct RobotSelf"));
    assert!(text(5).contains("pub struct Robot1arm"));
    let fields = ROBOT_NAMES.len();
    assert!(text(fields).contains("pub r#type: f64"), "{}", text(fields));
    assert!(text(fields + 2).contains("pub r#gen: f64"));
    assert!(text(fields + 4).contains("pub r#match: f64"));
    assert!(text(fields + 5).contains("pub r#fn: f64"));
    if let Err(errors) = rustc_check(&dir, &modules) {
        panic!("the emitted Rust does not compile:\n{errors}");
    }
}

#[test]
fn names_no_field_can_have_are_refused_where_written() {
    let dir = scratch("names_refused");
    for (k, parameter) in [
        "self",
        "Self",
        "super",
        "crate",
        "_",
        "self.Self",
        "r#type + Self",
    ]
    .iter()
    .enumerate()
    {
        let file = format!("p{k}.toml");
        robot(&dir, &file, "arm", "1", parameter);
        for lang in ["rust", "c"] {
            let out = dynamics_in(&dir, &["emit", "--lang", lang, &file]);
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(1), "{parameter}: {stderr}");
            // The value's line and column: `mass = "..."` on line 7.
            assert!(
                stderr.contains(&format!("{file}:7:8: "))
                    && stderr.contains("cannot name a parameter"),
                "{parameter}: {stderr}"
            );
        }
    }
}

/// The compilers found, each with its language flags.
fn compilers() -> Vec<(&'static str, &'static [&'static str])> {
    let found: Vec<_> = c_support::compilers()
        .into_iter()
        .map(|(cc, flags, _)| (cc, flags))
        .collect();
    if found.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C headers are not checked");
    }
    found
}

#[test]
fn two_robots_with_one_c_prefix_do_not_compile_together() {
    let dir = scratch("names_prefix");
    // Link lengths 1 and 3: the hand at q = 0 is at x = 1 and x = 3.
    robot(&dir, "arm-a.toml", "arm-a", "1", "2");
    robot(&dir, "arm_a.toml", "arm_a", "3", "2");
    robot(&dir, "UR5e.toml", "UR5e", "1", "2");
    robot(&dir, "ur5e.toml", "ur5e", "3", "2");
    for (file, out) in [
        ("arm-a.toml", "arm-a.h"),
        ("arm_a.toml", "arm_a.h"),
        ("UR5e.toml", "UR5e.h"),
        ("ur5e.toml", "ur5e.h"),
    ] {
        let header = emitted(&dir, &["emit", "--lang", "c", file]);
        std::fs::write(dir.join(out), header).expect("write");
    }
    let header = emitted(
        &dir,
        &["emit", "--lang", "c", "arm_a.toml", "--prefix", "arm_b"],
    );
    assert!(header.contains("static inline void arm_b_hand_pose("));
    std::fs::write(dir.join("arm_b.h"), header).expect("write");
    let main = "int main(void) { return 0; }\n";
    for (cc, flags) in compilers() {
        let program = |name: &str| format!("{name}_{cc}").replace('+', "x");
        for (first, second) in [("arm-a", "arm_a"), ("UR5e", "ur5e")] {
            let source = format!("#include \"{first}.h\"\n#include \"{second}.h\"\n{main}");
            let errors = c_compile(&dir, cc, flags, &source, &program("clash"))
                .expect_err("two robots' headers with one prefix compiled together");
            let prefix = first.to_lowercase().replace('-', "_");
            assert!(
                errors.contains(&format!("also names its functions {prefix}_*"))
                    && errors.contains("--prefix NAME"),
                "{cc}: {errors}"
            );
        }
        let twice = format!("#include \"arm-a.h\"\n#include \"arm-a.h\"\n{main}");
        c_compile(&dir, cc, flags, &twice, &program("twice")).expect("the same header twice");
        // With --prefix, each robot's own functions: the hand at x = 1 and at x = 3.
        let both = "#include <stdio.h>\n#include \"arm-a.h\"\n#include \"arm_b.h\"\n\
             int main(void) {\n    const double q[1] = {0.0};\n    double a[3][4], b[3][4];\n    \
             arm_a_hand_pose(q, a);\n    arm_b_hand_pose(q, b);\n    \
             printf(\"%.17g %.17g\\n\", a[0][3], b[0][3]);\n    return 0;\n}\n";
        c_compile(&dir, cc, flags, both, &program("both")).expect("two prefixes");
        let run = std::process::Command::new(dir.join(program("both")))
            .output()
            .expect("run");
        assert_eq!(String::from_utf8_lossy(&run.stdout), "1 3\n", "{cc}");
    }
}

#[test]
fn a_prefix_must_make_plain_c_names() {
    let dir = scratch("names_prefix_option");
    robot(&dir, "arm.toml", "arm", "1", "2");
    for bad in ["_arm", "1arm", "arm_", "arm__b", "arm-b", "", "ñ"] {
        let out = dynamics_in(&dir, &["emit", "--lang", "c", "arm.toml", "--prefix", bad]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{bad}: {stderr}");
        assert!(
            stderr.contains("cannot prefix the C functions"),
            "{bad}: {stderr}"
        );
    }
    let out = dynamics_in(&dir, &["emit", "arm.toml", "--prefix", "arm"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--prefix names the C functions: it needs --lang c"));
}

/// The identifiers of C `text` outside its comments and strings.
fn c_identifiers(text: &str) -> Vec<String> {
    let mut code = String::new();
    let mut rest = text;
    while let Some(start) = rest.find(['/', '"']) {
        code.push_str(&rest[..start]);
        let after = &rest[start..];
        let end = if after.starts_with("/*") {
            after.find("*/").map(|e| e + 2)
        } else if let Some(string) = after.strip_prefix('"') {
            string.find('"').map(|e| e + 2)
        } else {
            Some(1)
        };
        let end = end.unwrap_or(after.len());
        code.push(' ');
        rest = &after[end..];
    }
    code.push_str(rest);
    code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_'))
        .map(str::to_owned)
        .collect()
}

#[test]
fn c_names_from_user_text_compile_and_stay_out_of_the_reserved() {
    let dir = scratch("names_c");
    let parameters = "int + _m + m__2 + ñ + class + double + type + _Bool";
    let mut headers = Vec::new();
    for (k, name) in ["int", "_Bool", "-arm", "1arm", "ñ", "dynamics", "arm--a--"]
        .iter()
        .enumerate()
    {
        robot(&dir, &format!("r{k}.toml"), name, "1", parameters);
        let header = emitted(&dir, &["emit", "--lang", "c", &format!("r{k}.toml")]);
        // The compiler's own names (`__GNUC__`, `__builtin_fma`) start with `__`; none of the
        // header's may start with `_` or hold `__`, which C and C++ reserve.
        for ident in c_identifiers(&header) {
            assert!(
                ident.starts_with("__") || !(ident.starts_with('_') || ident.contains("__")),
                "{name}: `{ident}`"
            );
        }
        std::fs::write(dir.join(format!("r{k}.h")), &header).expect("write");
        headers.push(format!("r{k}.h"));
    }
    // All in one file: their prefixes differ (`int`, `bool`, `arm`, `robot_1arm`, `robot`,
    // `dynamics`, `arm_a`), and each function reads the eight parameters.
    let includes: String = headers
        .iter()
        .map(|h| format!("#include \"{h}\"\n"))
        .collect();
    let source = format!(
        "{includes}int main(void) {{\n    const double p[8] = {{1, 2, 3, 4, 5, 6, 7, 8}};\n    \
         const double q[1] = {{0}};\n    double m[1][1];\n    arm_a_mass_matrix(p, q, m);\n    \
         return m[0][0] == 0.0;\n}}\n"
    );
    for (cc, flags) in compilers() {
        let program = format!("all_{cc}").replace('+', "x");
        if let Err(errors) = c_compile(&dir, cc, flags, &source, &program) {
            panic!("{cc}: {errors}");
        }
    }
}

//! The documented round trip emit → compile, for every description file in `robots/` and
//! every URDF file in `robots/urdf/`: `dynamics emit` writes a Rust module that rustc accepts
//! (one with every opt-in family too), and `dynamics emit --lang c` a header that every C
//! compiler found accepts under strict flags, included once and twice. (`c_header.rs` runs some
//! of the headers against reference data; this checks that all of them build.)

use crate::c_support;
use crate::compile_support;

use compile_support::{c_compile, emitted, root, rustc_check, scratch};
use dynamics_codegen::Family;

/// The `dynamics` arguments naming each robot file: `robots/*.toml` and `*.json`, and
/// `robots/urdf/*.urdf` (the Panda's up to its flange, where the hand branches).
fn robot_files() -> Vec<Vec<String>> {
    let mut files = Vec::new();
    for dir in ["robots", "robots/urdf"] {
        let mut names: Vec<String> = std::fs::read_dir(root().join(dir))
            .expect("robots/")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .filter(|f| [".toml", ".json", ".urdf"].iter().any(|e| f.ends_with(e)))
            .collect();
        names.sort();
        files.extend(names.into_iter().map(|f| vec![format!("{dir}/{f}")]));
    }
    for args in &mut files {
        if args[0] == "robots/urdf/panda.urdf" {
            args.extend(["--tip".into(), "panda_link8".into()]);
        }
    }
    assert!(files.len() >= 19, "robot files: {files:?}");
    files
}

fn strs(args: &[String]) -> Vec<&str> {
    args.iter().map(String::as_str).collect()
}

#[test]
fn every_robot_file_emits_rust_that_compiles() {
    let dir = scratch("round_trip_rust");
    let mut modules = Vec::new();
    for (k, args) in robot_files().iter().enumerate() {
        let mut words = vec!["emit"];
        words.extend(strs(args));
        modules.push((format!("robot{k}"), emitted(&root(), &words)));
    }
    // Every opt-in family, on a robot with parameters and one with friction.
    let every = Family::opt_in_names()
        .into_iter()
        .filter(|&f| f != Family::Simplified.name())
        .collect::<Vec<_>>()
        .join(",");
    for file in [
        "robots/articulated_3r.toml",
        "robots/two_link_friction.toml",
    ] {
        let text = emitted(&root(), &["emit", file, "--with", &every]);
        modules.push((format!("every{}", modules.len()), text));
    }
    if let Err(errors) = rustc_check(&dir, &modules) {
        panic!("the emitted Rust does not compile:\n{errors}");
    }
}

#[test]
fn every_robot_file_emits_a_c_header_that_compiles() {
    let compilers = c_support::compilers();
    if compilers.is_empty() {
        eprintln!("no C compiler (gcc, clang, g++) found: the C headers are not checked");
        return;
    }
    let dir = scratch("round_trip_c");
    for (k, args) in robot_files().iter().enumerate() {
        let mut words = vec!["emit", "--lang", "c"];
        words.extend(strs(args));
        let header = emitted(&root(), &words);
        std::fs::write(dir.join(format!("robot{k}.h")), &header).expect("write");
        // Twice: the guard makes the second inclusion nothing.
        let source = format!(
            "#include \"robot{k}.h\"\n#include \"robot{k}.h\"\nint main(void) {{ return 0; }}\n"
        );
        for (cc, flags, _) in &compilers {
            let program = format!("robot{k}_{cc}").replace('+', "x");
            if let Err(errors) = c_compile(&dir, cc, flags, &source, &program) {
                panic!("{cc}: the header of {args:?} does not compile:\n{errors}");
            }
        }
    }
}

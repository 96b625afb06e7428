//! The round trip `docs/identification.md` promises: `identify --consistent --description-out`
//! writes a description that `dynamics inspect` and the derive read back. On PUMA 560 and the
//! Panda, along motions of `dynamics excite`, with torques of 1 N m of noise (far more than
//! their wrists' torques, so that the consistent estimate leaves some links on the edge of the
//! cone `J ⪰ 0`: point masses, rods, zero friction): the file written passes `dynamics
//! inspect`'s checks, the derive's expansion of `#[dynamics(file = "...")]` on it has no error,
//! and the module `dynamics emit` writes from it type-checks against `dynamics-runtime`.

use crate::synthetic;

use std::path::{Path, PathBuf};
use synthetic::{dynamics, normal, scratch, torques, write_csv, State};

const FRICTION: [&str; 3] = ["--rotors", "--friction", "viscous,coulomb"];

fn robot_file(name: &str) -> String {
    format!("{}/../robots/{name}.toml", env!("CARGO_MANIFEST_DIR"))
}

/// A successful run's standard output; a failure's standard error fails the test.
fn run(args: &[&str]) -> String {
    let out = dynamics(args);
    assert!(
        out.status.success(),
        "dynamics {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// `excite`'s motion of seed `seed` for the robot at `path` (`n` joints), its torques with
/// 1 N m of noise: the measurements' file.
fn measured(name: &str, path: &str, n: usize, seed: u64) -> String {
    let motion = scratch(&format!("{name}_excited_{seed}.csv"));
    let motion = motion.to_string_lossy();
    let seed_text = seed.to_string();
    let words = ["excite", path, "--seed", &seed_text, "--evaluations", "300"];
    run(&[&words[..], &["--csv", &motion]].concat());
    let text = std::fs::read_to_string(&*motion).expect("the motion");
    let states: Vec<State> = text
        .lines()
        .skip(1)
        .map(|line| {
            let v: Vec<f64> = line
                .split(',')
                .map(|x| x.parse().expect("a number"))
                .collect();
            State {
                t: v[0],
                q: v[1..=n].to_vec(),
                qd: v[n + 1..=2 * n].to_vec(),
                qdd: v[2 * n + 1..=3 * n].to_vec(),
            }
        })
        .collect();
    let text = std::fs::read_to_string(path).expect("the robot");
    let robot = dynamics_codegen::front::load(path, &text)
        .expect("reads")
        .robot;
    let mut noise = seed * 7919 + 1;
    let tau = torques(&robot, &states, |_| normal(&mut noise));
    write_csv(&format!("{name}_measured_{seed}.csv"), &states, &tau, true)
}

/// Identifies the robot `name` from the measurements of `seed` with the options `terms`,
/// writes the consistent description, and checks that `inspect` and the derive take it; the
/// module `dynamics emit` writes from it.
fn written(name: &str, n: usize, seed: u64, terms: &[&str]) -> String {
    let path = robot_file(name);
    let csv = measured(name, &path, n, seed);
    let out = scratch(&format!("{name}_fit_{seed}_{}.toml", terms.len()));
    let out = out.to_string_lossy();
    let words = ["identify", &path, "--csv", &csv, "--consistent"];
    run(&[&words[..], terms, &["--description-out", &out]].concat());
    run(&["inspect", &out]);
    let expansion = dynamics_codegen::derive_dynamics(quote::quote! {
        #[dynamics(file = #out)]
        struct Fitted;
    })
    .to_string();
    assert!(
        !expansion.contains("compile_error"),
        "the derive refuses {out}: {}",
        &expansion[..expansion.len().min(2000)]
    );
    run(&["emit", &out])
}

/// Type-checks the modules `(name, text)` in a crate of their own on `dynamics-runtime`.
fn type_checks(dir: &Path, modules: &[(String, String)]) {
    let src = dir.join("src");
    std::fs::create_dir_all(&src).expect("a crate");
    let runtime = Path::new(env!("CARGO_MANIFEST_DIR")).join("../dynamics-runtime");
    let manifest = format!(
        "[package]\nname = \"round_trip\"\nversion = \"0.0.0\"\nedition = \"2021\"\n\
         [dependencies]\ndynamics-runtime = {{ path = {:?}, default-features = false }}\n\
         [workspace]\n",
        runtime.display().to_string()
    );
    std::fs::write(dir.join("Cargo.toml"), manifest).expect("a manifest");
    // The workspace's versions, so that the check needs no registry.
    let lock = Path::new(env!("CARGO_MANIFEST_DIR")).join("../Cargo.lock");
    std::fs::copy(lock, dir.join("Cargo.lock")).expect("the lock file");
    let mut lib = String::from("#![no_std]\n");
    for (name, text) in modules {
        std::fs::write(src.join(format!("{name}.rs")), text).expect("a module");
        lib += &format!("pub mod {name};\n");
    }
    std::fs::write(src.join("lib.rs"), lib).expect("lib.rs");
    let out = std::process::Command::new(env!("CARGO"))
        .args(["check", "--offline", "--quiet", "--manifest-path"])
        .arg(dir.join("Cargo.toml"))
        .env("CARGO_TARGET_DIR", dir.join("target"))
        .output()
        .expect("run cargo");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn crate_dir(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("round_trip_{name}"))
}

#[test]
fn puma560_with_noise_round_trips() {
    let module = written("puma560", 6, 2, &FRICTION);
    type_checks(&crate_dir("puma560"), &[("puma560".into(), module)]);
}

#[test]
fn panda_with_noise_round_trips() {
    let module = written("panda", 7, 1, &FRICTION);
    type_checks(&crate_dir("panda"), &[("panda".into(), module)]);
}

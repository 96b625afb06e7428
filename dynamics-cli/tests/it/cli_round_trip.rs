//! The round trip `docs/identification.md` promises: `identify --consistent --description-out`
//! writes a description that `dynamics inspect` and the derive read back. On PUMA 560 and the
//! Panda, along motions of `dynamics excite`, with torques of 1 N m of noise (far more than
//! their wrists' torques, so that the consistent estimate leaves some links on the edge of the
//! cone `J ⪰ 0`: point masses, rods, zero friction): the file written passes `dynamics
//! inspect`'s checks, the derive's expansion of `#[dynamics(file = "...")]` on it has no error,
//! and the module `dynamics emit` writes from it type-checks against `dynamics-runtime`.

use crate::{compile_support, synthetic};

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

/// Type-checks the module `dynamics emit` wrote for `name` against `dynamics-runtime`.
fn type_checks(name: &str, module: String) {
    let dir = compile_support::scratch(&format!("round_trip_{name}"));
    if let Err(errors) = compile_support::rustc_check(&dir, &[(name.to_owned(), module)]) {
        panic!("the module written for {name} does not compile:\n{errors}");
    }
}

#[test]
fn puma560_with_noise_round_trips() {
    type_checks("puma560", written("puma560", 6, 2, &FRICTION));
}

#[test]
fn panda_with_noise_round_trips() {
    type_checks("panda", written("panda", 7, 1, &FRICTION));
}

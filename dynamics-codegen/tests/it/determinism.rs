//! Expanding the same robot gives byte-identical code: twice in this process (each expansion
//! hashes with fresh random keys) and once in a child process (another address space and
//! hash seed), for a robot from attributes and one from a description file.

use dynamics_codegen::derive_dynamics;

const ROBOTS: [&str; 2] = [
    "#[dynamics(gravity = [0, -g, 0],
       dh = [[q, 0, l1, 90 deg], [q + 0.3, 0, l2, 0], [0.2, q, 0, -90 deg], [q, 0.1, 0.2, 30 deg]],
       link(mass = m1, com = [-l1 / 2, 0, 0], inertia = [0.01, 0.1, 0.1, 0.001, 0, 0]),
       link(mass = m2, com = [-l2 / 2, 0.1, 0], inertia = [0.2, 0.1, 0.15, 0, 0.02, 0]),
       link(mass = 1.5, com = [0, 0, 0.1], inertia = [0.01, 0.01, 0.015, 0, 0, 0.001], spring = (k, 0.1)),
       link(mass = 0.5, com = [0.01, 0, 0.05], actuator_inertia = 0.02))]
     struct Arm { l1: f64, l2: f64, m1: f64, m2: f64, g: f64, k: f64 }",
    "#[dynamics(file = \"../robots/puma560.toml\")] struct Puma560;",
];

fn expand_all() -> String {
    ROBOTS
        .iter()
        .map(|source| derive_dynamics(source.parse().expect("tokens")).to_string())
        .collect::<Vec<_>>()
        .join("\n")
}

const CHILD: &str = "DYNAMICS_DETERMINISM_CHILD";
const MARK: &str = "=== expansion ===";

/// Run by the test below in a child process: prints the expansions.
#[test]
#[ignore = "run by same_code_in_another_process"]
fn print_expansion() {
    if std::env::var_os(CHILD).is_some() {
        println!("{MARK}\n{}\n{MARK}", expand_all());
    }
}

#[test]
fn same_code_twice_in_one_process() {
    let first = expand_all();
    let head = first.get(..first.len().min(400)).unwrap_or_default();
    assert!(!first.contains("compile_error"), "{head}");
    assert!(first.contains("impl"), "{head}");
    assert!(first == expand_all(), "two expansions differ");
}

/// The name libtest runs [`print_expansion`] by: its path in the test binary, which is this
/// module's path without the crate's name.
fn print_expansion_name() -> String {
    match module_path!().split_once("::") {
        Some((_, module)) => format!("{module}::print_expansion"),
        None => "print_expansion".to_owned(),
    }
}

#[test]
fn same_code_in_another_process() {
    let here = expand_all();
    let out = std::process::Command::new(std::env::current_exe().expect("test binary"))
        .args([
            print_expansion_name().as_str(),
            "--exact",
            "--ignored",
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD, "1")
        .output()
        .expect("child process");
    let stdout = String::from_utf8(out.stdout).expect("utf-8");
    let there = stdout
        .split(MARK)
        .nth(1)
        .unwrap_or_else(|| panic!("no expansion from the child: {stdout}"))
        .trim_matches('\n');
    assert!(here == there, "the child process expanded different code");
}

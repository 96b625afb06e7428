//! A reader that stops early: `dynamics emit robot | head -1` closes the pipe before the
//! command has written everything, which is not the command's error (and no panic).

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};

#[test]
fn a_closed_pipe_ends_the_command_quietly() {
    let robot = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots/panda.toml");
    let mut child = Command::new(env!("CARGO_BIN_EXE_dynamics"))
        .args(["emit", "--lang", "c", "--with", "derivatives"])
        .arg(&robot)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run dynamics");
    let stdout = child.stdout.take().expect("stdout");
    let mut first = String::new();
    BufReader::new(stdout)
        .read_line(&mut first)
        .expect("a line");
    // The reader is gone: the rest of the header (about 750 kB) meets a closed pipe.
    let out = child.wait_with_output().expect("wait");
    assert_eq!(first, "/*\n");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{:?}: {stderr}", out.status);
    assert!(stderr.is_empty(), "{stderr}");
}

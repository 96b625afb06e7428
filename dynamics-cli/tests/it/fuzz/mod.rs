//! The runs of `cli_fuzz.rs`: each case a process of the binary with a timeout, two at a time,
//! and what a run may and may not do.

use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The longest a run may take: the slowest case takes well under a second.
const TIMEOUT: Duration = Duration::from_secs(10);

/// The most output a run may print (what a command prints for these lines is far less).
const MAX_OUTPUT: usize = 16 << 20;

/// One run: a command line, and the option and value it tries.
pub struct Case {
    pub command: String,
    pub option: String,
    pub value: String,
    pub words: Vec<String>,
}

impl Case {
    pub fn new(command: &str, option: &str, value: &str, words: Vec<String>) -> Case {
        let mut all = vec![command.to_string()];
        all.extend(words);
        Case {
            command: command.to_string(),
            option: option.to_string(),
            value: value.to_string(),
            words: all,
        }
    }
}

/// How a run ended.
pub struct Outcome {
    /// The exit code; `None` if a signal ended it (or the timeout did).
    pub code: Option<i32>,
    pub timed_out: bool,
    pub stdout: String,
    pub stderr: String,
}

impl Outcome {
    /// The exit and the first line of the error, for the log.
    pub fn summary(&self) -> String {
        let first = self.stderr.lines().next().unwrap_or("");
        format!("{:?} {}", self.code, first)
    }
}

/// Runs every case of `cases` with the binary `exe`, each in a directory of its own under `dir`
/// (what one writes, another does not read), as many at a time as there are cores; their
/// outcomes, in order.
pub fn run_all(exe: &str, dir: &Path, cases: &[Case]) -> Vec<Outcome> {
    let next = AtomicUsize::new(0);
    let outcomes: Mutex<Vec<Option<Outcome>>> =
        Mutex::new(std::iter::repeat_with(|| None).take(cases.len()).collect());
    let threads = std::thread::available_parallelism().map_or(2, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(case) = cases.get(i) else { break };
                let own = dir.join(format!("run{i}"));
                std::fs::create_dir_all(&own).expect("a directory of its own");
                let outcome = run(exe, &own, &case.words);
                outcomes.lock().expect("no panic holding it")[i] = Some(outcome);
            });
        }
    });
    let outcomes = outcomes.into_inner().expect("no panic holding it");
    outcomes.into_iter().map(|o| o.expect("run")).collect()
}

/// One run, killed at the timeout.
fn run(exe: &str, dir: &Path, words: &[String]) -> Outcome {
    let mut child = Command::new(exe)
        .args(words)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start dynamics");
    let stdout = reader(child.stdout.take().expect("piped"));
    let stderr = reader(child.stderr.take().expect("piped"));
    let (status, timed_out) = wait(&mut child);
    let text = |h: std::thread::JoinHandle<Vec<u8>>| {
        String::from_utf8_lossy(&h.join().expect("reader")).into_owned()
    };
    Outcome {
        code: status.and_then(|s| s.code()),
        timed_out,
        stdout: text(stdout),
        stderr: text(stderr),
    }
}

/// A thread reading a pipe to its end, keeping the first [`MAX_OUTPUT`] bytes.
fn reader(mut pipe: impl Read + Send + 'static) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let (mut kept, mut buffer) = (Vec::new(), [0_u8; 1 << 16]);
        while let Ok(n) = pipe.read(&mut buffer) {
            if n == 0 {
                break;
            }
            let room = MAX_OUTPUT.saturating_sub(kept.len()).min(n);
            kept.extend_from_slice(&buffer[..room]);
        }
        kept
    })
}

/// The child's exit, or `None` and `true` once it ran past the timeout (then killed).
fn wait(child: &mut Child) -> (Option<std::process::ExitStatus>, bool) {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().expect("wait") {
            return (Some(status), false);
        }
        if start.elapsed() > TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            return (None, true);
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// Words of an error that say what was expected (or what was wrong with the value).
const EXPECTATIONS: [&str; 25] = [
    "expected",
    "is not",
    "not a",
    "must",
    "at most",
    "at least",
    "between",
    "takes",
    "possible values",
    "give",
    "name it",
    "no such file",
    "is a directory",
    "values given",
    "values;",
    "cannot be used",
    "not in",
    "more than once",
    "required",
    "go together",
    "is above",
    "is empty",
    "no run can",
    "already",
    "or more",
];

/// Errors that leave the user guessing.
const UNHELPFUL: [&str; 4] = [
    "unexpected argument '",
    "invalid digit",
    "out of bounds",
    "panicked",
];

/// What went wrong with `case`'s run, if anything.
pub fn check(case: &Case, outcome: &Outcome) -> Option<String> {
    let line = case.words.join(" ");
    let problem = |what: &str| Some(format!("`dynamics {line}`: {what}\n{}", outcome.stderr));
    if outcome.timed_out {
        return problem(&format!("still running after {TIMEOUT:?}"));
    }
    let stderr = outcome.stderr.to_lowercase();
    if let Some(bad) = UNHELPFUL.iter().find(|b| stderr.contains(*b)) {
        return problem(&format!("an unhelpful error ({bad})"));
    }
    match outcome.code {
        Some(0) => {
            let nan = |text: &str| {
                text.split(|c: char| !c.is_ascii_alphanumeric())
                    .any(|word| word.eq_ignore_ascii_case("nan"))
            };
            (nan(&outcome.stdout) || nan(&outcome.stderr))
                .then(|| problem("succeeded and printed NaN"))
                .flatten()
        }
        Some(1 | 2) => {
            let named = outcome.stderr.contains(&case.option)
                || (case.option == "ROBOT" && outcome.stderr.contains("<ROBOT>"))
                || (!case.value.is_empty() && outcome.stderr.contains(&format!("{}:", case.value)));
            if !named {
                problem(&format!("the error does not name {}", case.option))
            } else if !EXPECTATIONS.iter().any(|e| stderr.contains(e)) {
                problem("the error does not say what was expected")
            } else {
                None
            }
        }
        code => problem(&format!("ended with {code:?}")),
    }
}

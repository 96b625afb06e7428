//! What the fuzz tests share: a seeded proptest runner whose case count the environment can
//! raise (`DYNAMICS_FUZZ_CASES`), each case on its own thread under a time bound, and the
//! `compile_error!`s of an expansion with the position of their span; for the file fuzzers,
//! where the numbers and lines of a text are, whether a position is inside it, and temporary
//! files for the derive to read (`bytes`: the mutations that know nothing of a text's format;
//! `xml`: the tags and attributes of an XML text; `urdf`: what the URDF fuzzer puts in).

pub mod bytes;
pub mod urdf;
pub mod xml;

use dynamics_codegen::front;
use proc_macro2::{TokenStream, TokenTree};
use proptest::sample::Index;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Time allowed for one case. Cases run in milliseconds; the bound leaves room for a loaded
/// 2-core machine, and is far below what a hang takes.
pub const BOUND: Duration = Duration::from_secs(10);

/// Words a mutation puts in: every word the attribute's keys are written with (so that a new
/// key is fuzzed as soon as it exists), then `others`.
pub fn words(others: &[&'static str]) -> Vec<&'static str> {
    front::attribute_words()
        .chain(others.iter().copied())
        .collect()
}

/// A runner with a fixed seed (so that a failure is reproducible) and `default` cases, or the
/// number in `DYNAMICS_FUZZ_CASES` for a long run.
pub fn runner(seed: u8, default: u32) -> TestRunner {
    let cases = std::env::var("DYNAMICS_FUZZ_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(default);
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 2000,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}

static CASES: AtomicUsize = AtomicUsize::new(0);

/// Runs `f` on a thread with rustc's 8 MiB proc-macro stack (rustc runs proc macros on such a
/// thread): `Err` if it panicked. A case that takes longer than [`BOUND`] fails the test at
/// once (a hang is not worth shrinking).
pub fn bounded<T: Send + 'static>(
    what: &str,
    f: impl FnOnce() -> T + Send + 'static,
) -> Result<T, String> {
    // Progress of a long run (shown with `--nocapture`).
    let n = CASES.fetch_add(1, Ordering::Relaxed) + 1;
    if n % 10_000 == 0 {
        eprintln!("{n} cases");
    }
    let (tx, rx) = mpsc::channel();
    let start = Instant::now();
    std::thread::Builder::new()
        .stack_size(8 << 20)
        .spawn(move || {
            let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
            let _ = tx.send(result);
        })
        .expect("thread");
    match rx.recv_timeout(BOUND) {
        Ok(Ok(value)) => Ok(value),
        Ok(Err(payload)) => {
            let message = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_string()))
                .unwrap_or_default();
            Err(format!("panicked ({message}) on:\n{what}"))
        }
        // proptest would catch a panic and shrink, re-running the hang: stop the process.
        Err(_) => {
            eprintln!("took more than {:?} on:\n{what}", start.elapsed());
            std::process::abort()
        }
    }
}

/// One `compile_error!` of an expansion: its message, and the line and column its span starts
/// at (`None` for the call site, which has no position).
pub struct CompileError {
    pub message: String,
    pub at: Option<(usize, usize)>,
}

/// Every `compile_error!{ "..." }` in `tokens`, at any depth.
pub fn compile_errors(tokens: TokenStream) -> Vec<CompileError> {
    let mut found = Vec::new();
    let mut pending: Option<Option<(usize, usize)>> = None;
    for tree in tokens {
        match &tree {
            TokenTree::Ident(i) if i == "compile_error" => {
                // The call site has no bytes of the input (its `start()` says 1:0).
                let start = i.span().start();
                let site = i.span().byte_range().is_empty();
                pending = Some((!site).then_some((start.line, start.column)));
            }
            TokenTree::Group(g) => {
                if let Some(at) = pending.take() {
                    let message = g.stream().to_string();
                    found.push(CompileError { message, at });
                } else {
                    found.extend(compile_errors(g.stream()));
                }
            }
            TokenTree::Punct(p) if p.as_char() == '!' => {}
            _ => pending = None,
        }
    }
    found
}

/// The byte ranges of the numbers in `text` (not the digits of a word: `link1`).
pub fn numbers(text: &[u8]) -> Vec<(usize, usize)> {
    let mut found = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let starts = text[i].is_ascii_digit()
            || (text[i] == b'-' && text.get(i + 1).is_some_and(u8::is_ascii_digit));
        let word = i > 0 && (text[i - 1].is_ascii_alphanumeric() || text[i - 1] == b'_');
        if starts && !word {
            let end = (i + 1..text.len())
                .find(|&j| !(text[j].is_ascii_alphanumeric() || b".+-_".contains(&text[j])))
                .unwrap_or(text.len());
            found.push((i, end));
            i = end;
        } else {
            i += 1;
        }
    }
    found
}

/// The byte offset where line `line` starts.
pub fn line_start(text: &[u8], line: Index) -> usize {
    let starts: Vec<usize> = std::iter::once(0)
        .chain(
            text.iter()
                .enumerate()
                .filter(|(_, b)| **b == b'\n')
                .map(|(i, _)| i + 1),
        )
        .collect();
    *line.get(&starts)
}

/// The length in characters of each line of a text (split at `\n`): where a position may be.
pub struct Lines(Vec<usize>);

impl Lines {
    pub fn of(text: &str) -> Lines {
        Lines(text.split('\n').map(|line| line.chars().count()).collect())
    }

    /// Whether (line, column) is inside the text (or just past its end).
    pub fn inside(&self, line: usize, column: usize) -> bool {
        line >= 1 && line <= self.0.len() && column >= 1 && column <= self.0[line - 1] + 1
    }

    /// `path:line:col: ` at the start of `message` (after `path:`), inside the text.
    pub fn pointed_at(&self, message: &str, path: &str) -> bool {
        let Some(rest) = message.split_once(&format!("{path}:")).map(|(_, r)| r) else {
            return false;
        };
        let mut parts = rest.splitn(3, ':');
        let (Some(l), Some(c)) = (parts.next(), parts.next()) else {
            return false;
        };
        matches!((l.parse(), c.parse()), (Ok(l), Ok(c)) if self.inside(l, c))
    }
}

static FILES: AtomicUsize = AtomicUsize::new(0);

/// `text` written to a new file of the temporary directory, named after `name`: what the
/// derive reads. The caller removes it.
pub fn temp_file(name: &str, text: &str) -> std::io::Result<PathBuf> {
    let n = FILES.fetch_add(1, Ordering::Relaxed);
    let file =
        std::env::temp_dir().join(format!("dynamics-fuzz-{}-{n}-{name}", std::process::id()));
    std::fs::write(&file, text)?;
    Ok(file)
}

//! A scratch directory for a test's files, removed when the test ends.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A fresh directory under the system's temporary directory, removed with what it holds when
/// dropped, also when the test fails (the panic unwinds through the drop). Named after the
/// test, the process and a counter, so tests running at once never share one.
pub struct Scratch {
    path: PathBuf,
}

impl Scratch {
    /// Creates `dynamics-{name}-{process}-{n}` in the temporary directory.
    ///
    /// # Panics
    /// If the directory cannot be created (a test cannot go on without it).
    #[must_use]
    pub fn new(name: &str) -> Self {
        static CREATED: AtomicUsize = AtomicUsize::new(0);
        let n = CREATED.fetch_add(1, Ordering::Relaxed);
        let path = std::env::temp_dir().join(format!("dynamics-{name}-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&path).expect("a scratch directory");
        Scratch { path }
    }

    /// The directory.
    #[must_use]
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// `file` in the directory, written with `text`.
    ///
    /// # Panics
    /// If the file cannot be written.
    #[must_use]
    pub fn write(&self, file: &str, text: &str) -> PathBuf {
        let path = self.path.join(file);
        std::fs::write(&path, text).expect("a scratch file");
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        // Nothing to do about a failure here: the directory is in the temporary directory.
        let _ = std::fs::remove_dir_all(&self.path);
    }
}

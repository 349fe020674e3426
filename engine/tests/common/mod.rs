//! Helpers the CLI tests of every machine share: running `hashigo` as a
//! process and files in a temporary folder.

#![allow(dead_code)] // each test crate uses its own subset of these

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

/// The seed test program's machine and panel as `hashigo run` arguments:
/// T0 at 1.1 s, T1 at 1 s, the counter set to 10 (the book's settings).
pub const SEED_PANEL: [&str; 8] = [
    "--machine",
    "minasec-u",
    "--set",
    "T0=1.1s",
    "--set",
    "T1=1s",
    "--set",
    "C0=10",
];

/// Runs `hashigo` with `args`, `stdin` on its standard input.
pub fn hashigo(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_hashigo"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("hashigo starts");
    // hashigo may exit before reading its input (a bad argument): a broken
    // pipe here is expected then, and the exit status tells the story.
    let _ = child
        .stdin
        .take()
        .expect("stdin")
        .write_all(stdin.as_bytes());
    child.wait_with_output().expect("hashigo ends")
}

/// Output bytes as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A temporary folder, removed when dropped.
pub struct Temp {
    dir: PathBuf,
}

impl Temp {
    /// A fresh folder whose name includes `name` and the process id.
    pub fn new(name: &str) -> Temp {
        let dir = std::env::temp_dir().join(format!("hashigo-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        Temp { dir }
    }

    /// Writes `contents` to `name` in the folder and returns its path.
    pub fn file(&self, name: &str, contents: &str) -> String {
        let path = self.dir.join(name);
        std::fs::write(&path, contents).expect("write temp file");
        path.to_string_lossy().into_owned()
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// The files of the workplace's fixture folder `dir` ending in `ext`, in
/// order; `None` (said) where the folder is absent: the real files are
/// never committed, and their tests pass without them.
pub fn fixture_names(dir: &str, ext: &str) -> Option<Vec<String>> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        eprintln!("no {dir}: skipped");
        return None;
    };
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(ext))
        .collect();
    names.sort();
    Some(names)
}

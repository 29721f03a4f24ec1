//! Running the `behavior` binary as a user does, for the command-line tests.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

pub fn behavior(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_behavior"))
        .args(args)
        .output()
        .expect("the behavior binary runs")
}

/// Runs the binary and requires success, showing its stderr otherwise.
pub fn behavior_ok(args: &[&str]) -> Output {
    let output = behavior(args);
    assert!(
        output.status.success(),
        "behavior {}: {}",
        args.join(" "),
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

pub fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// A path for a test's file in the target's scratch directory.
pub fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cli-tests");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

//! A run never loses work, run as a process: a second run into a used directory is
//! refused (exit 2) and leaves the previous run's checkpoint, history and summary as
//! they were; `--overwrite` clears it; SIGINT mid-run finishes the step, writes a
//! checkpoint and a partial summary and exits with 130, and `--resume` then writes what
//! the uninterrupted run writes, to the bit.
//!
//! `cargo test -p sph-impact --test run_directory -- --nocapture` prints the messages.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

fn exe() -> Command {
    Command::new(env!("CARGO_BIN_EXE_sph-impact"))
}

fn scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/smoke_rz.toml")
}

/// A fresh directory of this test binary.
fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("run-directory")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn run(dir: &Path, extra: &[&str]) -> Output {
    exe()
        .arg("run")
        .arg(scene())
        .arg("--out")
        .arg(dir)
        .args(["--quiet", "--threads", "1"])
        .args(extra)
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn bytes(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn a_used_directory_is_refused_unless_resumed_or_overwritten() {
    let dir = fresh("used");
    let first = run(&dir, &["--checkpoint", "--end-time", "0.5e-6"]);
    assert!(first.status.success(), "{}", stderr(&first));
    let kept: Vec<(PathBuf, Vec<u8>)> = ["history.csv", "summary.json", "run.pvd"]
        .iter()
        .map(|f| dir.join(f))
        .chain(
            std::fs::read_dir(dir.join("checkpoints"))
                .unwrap()
                .map(|e| e.unwrap().path()),
        )
        .map(|p| {
            let b = bytes(&p);
            (p, b)
        })
        .collect();
    assert!(kept.len() > 3, "no checkpoint written");
    // The same command again: refused before any work, nothing touched.
    let again = run(&dir, &["--checkpoint", "--end-time", "0.5e-6"]);
    let message = stderr(&again);
    println!("{message}");
    assert_eq!(again.status.code(), Some(2), "{message}");
    assert!(
        message.contains("--overwrite") && message.contains("--resume"),
        "{message}"
    );
    assert_eq!(message.lines().count(), 1, "{message}");
    for (path, b) in &kept {
        assert!(bytes(path) == *b, "{} changed", path.display());
    }
    // --resume with --overwrite is refused by the parser.
    let both = run(&dir, &["--resume", "--overwrite"]);
    assert_eq!(both.status.code(), Some(2), "{}", stderr(&both));
    // --overwrite clears the previous run; the files of the new one are all its own.
    let over = run(&dir, &["--overwrite", "--end-time", "0.25e-6"]);
    assert!(over.status.success(), "{}", stderr(&over));
    assert!(!dir.join("checkpoints").exists());
    let snapshots = std::fs::read_dir(dir.join("snapshots")).unwrap().count();
    assert_eq!(snapshots, 2, "snapshots at 0 and 0.25 µs only");
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"end_time_s\": 2.5e-7"), "{summary}");
}

#[cfg(unix)]
#[test]
fn sigint_mid_run_checkpoints_and_a_resume_repeats_the_uninterrupted_run() {
    let whole = fresh("whole");
    let done = run(&whole, &[]);
    assert!(done.status.success(), "{}", stderr(&done));
    let dir = fresh("interrupted");
    let mut child = exe()
        .arg("run")
        .arg(scene())
        .arg("--out")
        .arg(&dir)
        .args(["--quiet", "--threads", "1"])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // Once the first snapshot after t = 0 is in place, the run is between snapshots.
    let start = Instant::now();
    while !dir.join("snapshots/00001.vtu").exists() {
        assert!(start.elapsed() < Duration::from_secs(120), "no snapshot");
        if child.try_wait().unwrap().is_some() {
            panic!("the run ended before it could be interrupted");
        }
        std::thread::sleep(Duration::from_millis(2));
    }
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let message = stderr(&out);
    println!("{message}");
    assert_eq!(out.status.code(), Some(130), "{message}");
    assert!(
        message.starts_with("error: interrupted at t = ") && message.contains("--resume"),
        "{message}"
    );
    assert_eq!(message.lines().count(), 1, "{message}");
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"complete\": false"), "{summary}");
    let history = std::fs::read_to_string(dir.join("history.csv")).unwrap();
    assert!(history.ends_with('\n'), "history ends mid-row");
    assert!(std::fs::read_dir(dir.join("checkpoints")).unwrap().count() == 1);
    let resumed = run(&dir, &["--resume"]);
    assert!(resumed.status.success(), "{}", stderr(&resumed));
    for file in ["history.csv", "run.pvd", "snapshots/00004.vtu"] {
        assert!(
            bytes(&whole.join(file)) == bytes(&dir.join(file)),
            "{file} differs from the uninterrupted run's"
        );
    }
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"complete\": true"), "{summary}");
}

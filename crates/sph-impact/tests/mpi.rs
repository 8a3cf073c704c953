//! `mpirun -n N sph-impact run SCENE` (the `mpi` feature; docs/mpi.md): the same run
//! directory, to the bit, on 1, 2 and 4 ranks (4 oversubscribed on a small machine) for
//! the 3-D, 3-D quarter and RZ smoke scenes; a checkpoint written on 2 ranks resumes on 1
//! and on 4 to the uninterrupted run; an error on a rank stops every rank with its
//! message.
//!
//! Needs an MPI (`.ci/install-mpi`):
//! `cargo test -p sph-impact --features mpi --test mpi`.
#![cfg(feature = "mpi")]

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/scenes")
        .join(name)
}

fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// `mpirun -n ranks sph-impact run ARGS…` (as root too, and with more ranks than cores).
fn mpirun(ranks: usize, args: &[&str]) -> Output {
    Command::new("mpirun")
        .args(["--oversubscribe", "-n", &ranks.to_string()])
        .arg(env!("CARGO_BIN_EXE_sph-impact"))
        .args(args)
        .env("OMPI_ALLOW_RUN_AS_ROOT", "1")
        .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        .output()
        .expect("mpirun (.ci/install-mpi installs it)")
}

/// Runs `scene` on `ranks` into `dir` with `extra` arguments; panics unless it succeeds.
fn run(ranks: usize, scene: &Path, dir: &Path, extra: &[&str]) {
    let mut args = vec![
        "run",
        scene.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
        "--threads",
        "1",
        "--quiet",
    ];
    args.extend_from_slice(extra);
    let out = mpirun(ranks, &args);
    assert!(
        out.status.success(),
        "{ranks} ranks: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The run directory's files that hold results: the snapshots, history.csv, run.pvd, and
/// summary.json without the wall times and the ranks' gather time.
fn results(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files = vec![];
    let mut names: Vec<PathBuf> = std::fs::read_dir(dir.join("snapshots"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    names.sort();
    names.push(dir.join("history.csv"));
    names.push(dir.join("run.pvd"));
    for p in names {
        files.push((p.display().to_string(), std::fs::read(&p).unwrap()));
    }
    let mut summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.join("summary.json")).unwrap()).unwrap();
    for key in [
        "wall_time_s",
        "particle_steps_per_s",
        "timings",
        "resumed_from_s",
    ] {
        summary.as_object_mut().unwrap().remove(key);
    }
    files.push(("summary.json".into(), summary.to_string().into_bytes()));
    files
        .into_iter()
        .map(|(name, bytes)| {
            let short = name.rsplit('/').take(2).collect::<Vec<_>>().join("<");
            (short, bytes)
        })
        .collect()
}

fn assert_same(a: &Path, b: &Path) {
    let (ra, rb) = (results(a), results(b));
    assert_eq!(ra.len(), rb.len(), "{} and {}", a.display(), b.display());
    for ((name, x), (_, y)) in ra.iter().zip(&rb) {
        assert!(
            x == y,
            "{name} differs: {} and {}",
            a.display(),
            b.display()
        );
    }
}

/// The 3-D quarter smoke scene (tests/common), written beside the tests' outputs.
fn quarter_scene() -> PathBuf {
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("mpi-smoke-quarter.toml");
    std::fs::write(&path, common::quarter_smoke_text()).unwrap();
    path
}

#[test]
fn the_smoke_scenes_give_the_same_bits_on_1_2_and_4_ranks() {
    for (name, path) in [
        ("3d", scene("smoke.toml")),
        ("3d-quarter", quarter_scene()),
        ("rz", scene("smoke_rz.toml")),
    ] {
        let one = fresh(&format!("mpi-{name}-1"));
        run(1, &path, &one, &[]);
        for ranks in [2, 4] {
            let dir = fresh(&format!("mpi-{name}-{ranks}"));
            run(ranks, &path, &dir, &[]);
            assert_same(&one, &dir);
        }
    }
}

#[test]
fn a_checkpoint_written_on_2_ranks_resumes_on_1_and_on_4() {
    let s = scene("smoke.toml");
    let whole = fresh("mpi-ck-whole");
    run(1, &s, &whole, &[]);
    let part = fresh("mpi-ck-part");
    run(2, &s, &part, &["--checkpoint", "--end-time", "0.6e-6"]);
    for ranks in [1, 4] {
        let dir = fresh(&format!("mpi-ck-resumed-{ranks}"));
        let copy = Command::new("cp")
            .args(["-r", part.to_str().unwrap(), dir.to_str().unwrap()])
            .status()
            .unwrap();
        assert!(copy.success());
        run(ranks, &s, &dir, &["--resume", "--end-time", "1e-6"]);
        assert_same(&whole, &dir);
    }
}

#[test]
fn an_error_on_a_rank_stops_every_rank_with_its_message() {
    // Rank 0 refuses a directory that holds a run; the other rank, waiting for its
    // first step, is stopped too (the test would hang otherwise).
    let dir = fresh("mpi-refused");
    run(1, &scene("smoke_rz.toml"), &dir, &["--end-time", "1e-8"]);
    let out = mpirun(
        2,
        &[
            "run",
            scene("smoke_rz.toml").to_str().unwrap(),
            "--out",
            dir.to_str().unwrap(),
            "--quiet",
        ],
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.contains("error (rank 0 of 2): the run directory") && stderr.contains("--overwrite"),
        "{stderr}"
    );
    // Commands other than `run` refuse several ranks.
    let out = mpirun(2, &["check", scene("smoke_rz.toml").to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("only `run` runs over several MPI ranks")
    );
}

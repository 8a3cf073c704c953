//! `mpirun -n N sph-impact run SCENE` (the `mpi` feature; docs/mpi.md): the same results,
//! to the bit, on 1, 2 and 4 ranks (4 oversubscribed on a small machine) for the 3-D,
//! 3-D quarter and RZ smoke scenes, the last also with free flight and the summation
//! density (history, summary, and every snapshot's arrays: one
//! `.vtu` on one rank, a `.pvtu` of a piece per rank on several); a checkpoint written on
//! 2 ranks resumes on 1 and on 4 to the uninterrupted run; an error on a rank stops every
//! rank with its message.
//!
//! Needs an MPI (`.ci/install-mpi`):
//! `cargo test -p sph-impact --features mpi --test mpi`.
#![cfg(feature = "mpi")]

mod common;

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
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

/// The point-data arrays and the points of a `.vtu` file, (name, decoded values), in
/// the file's order (the cells, which number a piece's own points, left out).
fn vtu_arrays(path: &Path) -> Vec<(String, Vec<u8>)> {
    let xml = std::fs::read_to_string(path).unwrap();
    let mut arrays = vec![];
    for part in xml.split("<DataArray ").skip(1) {
        let name = part
            .split("Name=\"")
            .nth(1)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        if matches!(name, "connectivity" | "offsets" | "types") {
            continue;
        }
        let body = &part[part.find('>').unwrap() + 1..part.find("</DataArray>").unwrap()];
        let bytes = STANDARD.decode(body.trim()).unwrap();
        arrays.push((name.to_string(), bytes[8..].to_vec()));
    }
    arrays
}

/// The pieces a `.pvtu` lists (file names relative to it).
fn pieces(pvtu: &Path) -> Vec<String> {
    std::fs::read_to_string(pvtu)
        .unwrap()
        .split("Source=\"")
        .skip(1)
        .map(|s| s.split('"').next().unwrap().to_string())
        .collect()
}

/// A snapshot's arrays: those of its `.vtu`, or those of the pieces its `.pvtu` lists
/// joined in order (checking that the `.pvtu` declares the arrays they hold).
fn snapshot_arrays(path: &Path) -> Vec<(String, Vec<u8>)> {
    if path.extension().unwrap() == "vtu" {
        return vtu_arrays(path);
    }
    let mut joined: Vec<(String, Vec<u8>)> = vec![];
    for source in pieces(path) {
        let piece = vtu_arrays(&path.parent().unwrap().join(source));
        if joined.is_empty() {
            joined = piece;
        } else {
            for ((name, all), (other, values)) in joined.iter_mut().zip(piece) {
                assert_eq!(*name, other);
                all.extend(values);
            }
        }
    }
    let xml = std::fs::read_to_string(path).unwrap();
    for (name, _) in &joined {
        if name != "Points" {
            assert!(xml.contains(&format!("Name=\"{name}\"")), "{name}");
        }
    }
    joined
}

/// The snapshots run.pvd lists, (time as written, file relative to `dir`).
fn snapshots(dir: &Path) -> Vec<(String, String)> {
    let pvd = std::fs::read_to_string(dir.join("run.pvd")).unwrap();
    pvd.split("<DataSet ")
        .skip(1)
        .map(|entry| {
            let attr = |key: &str| entry.split(key).nth(1).unwrap().split('"').next().unwrap();
            (attr("timestep=\"").to_string(), attr("file=\"").to_string())
        })
        .collect()
}

/// How many pieces each snapshot of `dir` has (1 for a `.vtu`).
fn piece_counts(dir: &Path) -> Vec<usize> {
    snapshots(dir)
        .iter()
        .map(|(_, file)| match file.strip_suffix(".pvtu") {
            Some(_) => pieces(&dir.join(file)).len(),
            None => 1,
        })
        .collect()
}

/// What a run directory holds as results: each snapshot's time and arrays, history.csv,
/// and summary.json without the wall times and the ranks' gather time.
fn results(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files = vec![];
    for (time, file) in snapshots(dir) {
        for (name, values) in snapshot_arrays(&dir.join(file)) {
            files.push((format!("t = {time} s: {name}"), values));
        }
    }
    files.push((
        "history.csv".into(),
        std::fs::read(dir.join("history.csv")).unwrap(),
    ));
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
}

/// The results of the runs in `a` and `b` are the same bits, and `b`'s snapshots directory
/// holds nothing that its run.pvd does not list (directly or as a piece).
fn assert_same(a: &Path, b: &Path) {
    let (ra, rb) = (results(a), results(b));
    let names = |r: &[(String, Vec<u8>)]| r.iter().map(|x| x.0.clone()).collect::<Vec<_>>();
    assert_eq!(
        names(&ra),
        names(&rb),
        "{} and {}",
        a.display(),
        b.display()
    );
    for ((name, x), (_, y)) in ra.iter().zip(&rb) {
        assert!(
            x == y,
            "{name} differs: {} and {}",
            a.display(),
            b.display()
        );
    }
    let mut listed = vec![];
    for (_, file) in snapshots(b) {
        let file = file.strip_prefix("snapshots/").unwrap().to_string();
        if file.ends_with(".pvtu") {
            listed.extend(pieces(&b.join("snapshots").join(&file)));
        }
        listed.push(file);
    }
    listed.sort();
    let mut held: Vec<String> = std::fs::read_dir(b.join("snapshots"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    held.sort();
    assert_eq!(held, listed, "{}", b.display());
}

/// The 3-D quarter smoke scene (tests/common), written beside the tests' outputs.
fn quarter_scene() -> PathBuf {
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("mpi-smoke-quarter.toml");
    std::fs::write(&path, common::quarter_smoke_text()).unwrap();
    path
}

/// The RZ smoke scene with free flight above the target's surface and the summation
/// density: ten rings are in flight at the end, so the snapshots' pieces are written with
/// the particles in flight joined, and the last after the density is synchronised and
/// free flight ended, on every rank.
fn free_flight_scene() -> PathBuf {
    let text = std::fs::read_to_string(scene("smoke_rz.toml")).unwrap();
    let solver = "[solver]\n";
    assert!(text.contains(solver));
    let text = text.replace(
        solver,
        "[solver]\nfree_flight_above = 0.0\ndensity = \"summation\"\n",
    );
    let path = Path::new(env!("CARGO_TARGET_TMPDIR")).join("mpi-smoke-rz-flight.toml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn the_smoke_scenes_give_the_same_bits_on_1_2_and_4_ranks() {
    for (name, path) in [
        ("3d", scene("smoke.toml")),
        ("3d-quarter", quarter_scene()),
        ("rz", scene("smoke_rz.toml")),
        ("rz-flight", free_flight_scene()),
    ] {
        let one = fresh(&format!("mpi-{name}-1"));
        run(1, &path, &one, &[]);
        for ranks in [2, 4] {
            let dir = fresh(&format!("mpi-{name}-{ranks}"));
            run(ranks, &path, &dir, &[]);
            assert_same(&one, &dir);
            // One .vtu per snapshot on one rank; a .pvtu of a piece per rank on several.
            let n = piece_counts(&one).len();
            assert!(n > 1 && piece_counts(&one) == vec![1; n]);
            assert!(snapshots(&one).iter().all(|(_, f)| f.ends_with(".vtu")));
            assert_eq!(piece_counts(&dir), vec![ranks; n]);
            if name == "rz-flight" {
                let summary: serde_json::Value =
                    serde_json::from_slice(&std::fs::read(one.join("summary.json")).unwrap())
                        .unwrap();
                assert!(summary["free_flight_particles"].as_u64().unwrap() > 0);
            }
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
        // The snapshots before the checkpoint in two pieces, the later ones as written
        // on `ranks`.
        let counts = piece_counts(&dir);
        assert_eq!((counts[0], *counts.last().unwrap()), (2, ranks));
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

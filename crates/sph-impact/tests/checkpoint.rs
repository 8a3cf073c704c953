//! Checkpoints: a run resumed from its checkpoint writes what the uninterrupted run
//! writes, to the bit (history, snapshots, collection, summary physics), in RZ with
//! particles in free flight, in 3-D, in plane strain and in 1-D, on another thread count, and when extended to a
//! later end time; a checkpoint that does not fit is refused with a one-line reason.
//!
//! `cargo test -p sph-impact --test checkpoint -- --nocapture` prints the refusals.

use sph_impact::run::{RunError, RunOptions, RunSummary, StopFlag, checkpoints, run};
use sph_impact::scene::{Scene, SceneSimulation};
use std::path::{Path, PathBuf};

fn scene_file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/scenes")
        .join(name)
}

/// The RZ smoke scene with its jet in free flight above 0.5 mm.
fn rz_scene() -> Scene {
    let text = std::fs::read_to_string(scene_file("smoke_rz.toml")).unwrap();
    let text = text.replacen("[solver]\n", "[solver]\nfree_flight_above = 0.5e-3\n", 1);
    assert!(text.contains("free_flight_above"));
    Scene::from_toml_str(&text, "smoke_rz.toml").unwrap()
}

/// A fresh run directory under the test's temporary directory.
fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn copy_dir(from: &Path, to: &Path) {
    let _ = std::fs::remove_dir_all(to);
    std::fs::create_dir_all(to.join("snapshots")).unwrap();
    std::fs::create_dir_all(to.join("checkpoints")).unwrap();
    for sub in ["", "snapshots", "checkpoints"] {
        for e in std::fs::read_dir(from.join(sub)).unwrap() {
            let e = e.unwrap();
            if e.file_type().unwrap().is_file() {
                std::fs::copy(e.path(), to.join(sub).join(e.file_name())).unwrap();
            }
        }
    }
}

fn options(threads: usize, end_time: Option<f64>, checkpoint: bool, resume: bool) -> RunOptions {
    RunOptions {
        threads: Some(threads),
        end_time,
        quiet: true,
        checkpoint,
        resume,
        ..RunOptions::default()
    }
}

fn bytes(dir: &Path, file: &str) -> Vec<u8> {
    std::fs::read(dir.join(file)).unwrap_or_else(|e| panic!("{}: {e}", dir.join(file).display()))
}

/// The two runs wrote the same history, collection and last snapshot, byte for byte,
/// and the same physics in the summary.
fn assert_same_outputs(a: (&Path, &RunSummary), b: (&Path, &RunSummary), last_snapshot: &str) {
    for file in ["history.csv", "run.pvd", last_snapshot] {
        assert!(bytes(a.0, file) == bytes(b.0, file), "{file} differs");
    }
    let (s, r) = (a.1, b.1);
    let same = |x: f64, y: f64| x.to_bits() == y.to_bits();
    assert!(same(s.beta, r.beta) && same(s.beta_target, r.beta_target));
    assert!(same(s.crater_depth_m, r.crater_depth_m));
    assert!(same(s.crater_diameter_m, r.crater_diameter_m));
    assert!(same(s.crater_axis_depth_m, r.crater_axis_depth_m));
    assert!(same(s.ejecta_mass_kg, r.ejecta_mass_kg));
    assert!(same(s.energy_error, r.energy_error));
    // Read from the history's rows, which the resumed run read back from the file.
    assert!(same(s.beta_change_last_half, r.beta_change_last_half));
    assert_eq!(
        (s.steps, s.particles, s.free_flight_particles),
        (r.steps, r.particles, r.free_flight_particles)
    );
    assert_eq!(s.damage_events, r.damage_events);
}

#[test]
fn a_resumed_rz_run_repeats_the_uninterrupted_one_bit_for_bit() {
    let scene = rz_scene();
    let whole = fresh("checkpoint-rz-whole");
    let a = run(&scene, &whole, &options(2, None, true, false)).unwrap();
    assert!(a.resumed_from_s.is_empty());
    assert!(a.free_flight_particles > 0, "nothing in free flight");
    // The last checkpoint is the snapshot before the end (0.75 µs of 1 µs); the copy's
    // history runs on to the end, as a run stopped later would have left it.
    let resumed = fresh("checkpoint-rz-resumed");
    copy_dir(&whole, &resumed);
    let b = run(&scene, &resumed, &options(1, None, false, true)).unwrap();
    println!(
        "resumed from {:?} s: beta {} (whole run {}), {} steps",
        b.resumed_from_s, b.beta, a.beta, b.steps
    );
    assert_eq!(b.resumed_from_s.len(), 1);
    assert!((b.resumed_from_s[0] - 0.75e-6).abs() < 1e-15);
    assert_same_outputs((&whole, &a), (&resumed, &b), "snapshots/00004.vtu");
}

/// With one neighbour search per step (`neighbour_search = "each-step"`) too: the list
/// and ghosts kept for the midpoint live within a step, so a checkpoint holds nothing
/// more.
#[test]
fn a_resumed_run_with_one_search_per_step_repeats_the_uninterrupted_one() {
    let text = std::fs::read_to_string(scene_file("smoke_rz.toml")).unwrap();
    let text = text.replacen(
        "[solver]\n",
        "[solver]\nneighbour_search = \"each-step\"\n",
        1,
    );
    let scene = Scene::from_toml_str(&text, "smoke_rz.toml").unwrap();
    assert_eq!(
        scene.scheme().neighbour_search,
        sph_impact::solver::NeighbourSearch::EachStep
    );
    resumed_repeats_whole(&scene, "each-step", 1);
}

/// With a Verlet list (`neighbour_search = "verlet"`): a checkpoint holds no list, so the
/// resumed run searches at its first step where the whole run kept its list; the list
/// gives every stage the pairs of a search of its own (simulation/verlet.rs), so the two
/// still agree to the bit.
#[test]
fn a_resumed_run_with_a_verlet_list_repeats_the_uninterrupted_one() {
    let text = std::fs::read_to_string(scene_file("smoke_rz.toml")).unwrap();
    let text = text.replacen("[solver]\n", "[solver]\nneighbour_search = \"verlet\"\n", 1);
    let scene = Scene::from_toml_str(&text, "smoke_rz.toml").unwrap();
    assert_eq!(
        scene.scheme().neighbour_search,
        sph_impact::solver::NeighbourSearch::Verlet
    );
    resumed_repeats_whole(&scene, "verlet", 1);
}

#[test]
fn a_finished_run_extended_to_a_later_end_equals_one_run_to_it() {
    let scene = rz_scene();
    let short = fresh("checkpoint-rz-short");
    run(&scene, &short, &options(2, Some(0.5e-6), true, false)).unwrap();
    let long = fresh("checkpoint-rz-long");
    let a = run(&scene, &long, &options(2, Some(1.0e-6), false, false)).unwrap();
    // Resumed from 0.25 µs, the snapshot before the short run's end.
    let b = run(&scene, &short, &options(2, Some(1.0e-6), false, true)).unwrap();
    assert_eq!(b.resumed_from_s.len(), 1);
    assert_same_outputs((&long, &a), (&short, &b), "snapshots/00004.vtu");
}

#[test]
fn a_resumed_3d_run_repeats_the_uninterrupted_one_bit_for_bit() {
    let text = std::fs::read_to_string(scene_file("smoke.toml")).unwrap();
    let scene = Scene::from_toml_str(&text, "smoke.toml").unwrap();
    resumed_repeats_whole(&scene, "3d", 2);
}

/// Runs `scene` to 0.5 µs with checkpoints on two threads, resumes a copy of its
/// directory on `threads` (from 0.25 µs: snapshots at 0, 0.25 and 0.5 µs), checks that
/// the two wrote the same outputs, and returns the resumed directory.
fn resumed_repeats_whole(scene: &Scene, name: &str, threads: usize) -> PathBuf {
    let end = Some(0.5e-6);
    let whole = fresh(&format!("checkpoint-{name}-whole"));
    let a = run(scene, &whole, &options(2, end, true, false)).unwrap();
    let resumed = fresh(&format!("checkpoint-{name}-resumed"));
    copy_dir(&whole, &resumed);
    let b = run(scene, &resumed, &options(threads, end, false, true)).unwrap();
    assert_eq!(b.resumed_from_s.len(), 1, "{name}");
    assert_same_outputs((&whole, &a), (&resumed, &b), "snapshots/00002.vtu");
    resumed
}

/// In plane strain and in 1-D too (the example scenes to 0.5 µs, resumed from 0.25 µs);
/// a 1-D checkpoint is refused for the same bodies in plane strain.
#[test]
fn resumed_plane_and_1d_runs_repeat_the_uninterrupted_ones_bit_for_bit() {
    for (file, name) in [("smoke_plane.toml", "plane"), ("flyer_plate_1d.toml", "1d")] {
        let scene = Scene::from_toml_file(scene_file(file)).unwrap();
        let resumed = resumed_repeats_whole(&scene, name, 1);
        if name == "1d" {
            let mut plane = scene.clone();
            plane.geometry = sph_impact::scene::GeometryKind::Plane;
            let message = refused(&plane, &resumed, &options(1, Some(0.5e-6), false, true));
            assert!(
                message.contains("geometry = \"1d\" run") && message.contains("\"plane\""),
                "{message}"
            );
        }
    }
}

/// The one-line message of a refused resume, printed.
fn refused(scene: &Scene, dir: &Path, options: &RunOptions) -> String {
    let e = run(scene, dir, options).unwrap_err();
    assert!(matches!(e, RunError::Resume { .. }), "{e:?}");
    assert!(e.is_bad_input());
    let message = e.to_string();
    println!("{message}");
    assert!(!message.contains('\n'));
    message
}

#[test]
fn a_checkpoint_that_does_not_fit_is_refused() {
    let scene = rz_scene();
    let dir = fresh("checkpoint-refused");
    let resume = options(2, None, false, true);
    // Nothing to resume from.
    std::fs::create_dir_all(&dir).unwrap();
    assert!(refused(&scene, &dir, &resume).contains("--checkpoint"));
    run(&scene, &dir, &options(2, Some(0.5e-6), true, false)).unwrap();
    assert_eq!(checkpoints(&dir).len(), 1);
    // Another scene (another seed deals other flaws).
    let text = std::fs::read_to_string(scene_file("smoke_rz.toml")).unwrap();
    let other = Scene::from_toml_str(
        &text
            .replacen("[solver]\n", "[solver]\nfree_flight_above = 0.5e-3\n", 1)
            .replacen("seed = 1", "seed = 2", 1),
        "smoke_rz.toml",
    )
    .unwrap();
    assert!(refused(&other, &dir, &resume).contains("another scene"));
    // Another resolution.
    let finer = RunOptions {
        resolution_scale: 2.0,
        ..resume.clone()
    };
    assert!(refused(&scene, &dir, &finer).contains("--resolution-scale"));
    // An end time before the checkpoint (0.25 µs).
    let early = options(2, Some(0.2e-6), false, true);
    assert!(refused(&scene, &dir, &early).contains("past the end time"));
    // A history cut short before the checkpoint's row.
    let history = dir.join("history.csv");
    let text = std::fs::read_to_string(&history).unwrap();
    let cut: String = text.lines().take(3).map(|l| format!("{l}\n")).collect();
    std::fs::write(&history, cut).unwrap();
    assert!(refused(&scene, &dir, &resume).contains("rows"));
    // Not a checkpoint at all.
    let newest = checkpoints(&dir).pop().unwrap().1;
    std::fs::write(&newest, b"not cbor").unwrap();
    assert!(refused(&scene, &dir, &resume).contains("not a checkpoint"));
    // A fresh run into the used directory is refused and leaves it as it was; with
    // --overwrite it clears the previous run (and writes no checkpoint without
    // --checkpoint).
    let e = run(&scene, &dir, &options(2, Some(0.5e-6), false, false)).unwrap_err();
    assert!(
        matches!(e, RunError::DirectoryInUse { .. }) && e.is_bad_input(),
        "{e}"
    );
    println!("{e}");
    assert_eq!(std::fs::read(&newest).unwrap(), b"not cbor");
    let overwrite = RunOptions {
        overwrite: true,
        ..options(2, Some(0.5e-6), false, false)
    };
    run(&scene, &dir, &overwrite).unwrap();
    assert!(checkpoints(&dir).is_empty());
    assert!(!newest.exists());
}

/// The frame and payload of a checkpoint file.
fn unframe(bytes: &[u8]) -> (Vec<u8>, ciborium::Value) {
    assert_eq!(&bytes[..8], sph_impact::run::CHECKPOINT_MAGIC);
    let value = ciborium::from_reader(&bytes[24..]).unwrap();
    (bytes[..24].to_vec(), value)
}

/// `value` framed as a checkpoint with a correct length and checksum.
fn reframe(frame: &[u8], value: &ciborium::Value) -> Vec<u8> {
    let mut payload = Vec::new();
    ciborium::into_writer(value, &mut payload).unwrap();
    let mut out = frame[..12].to_vec();
    out.extend((payload.len() as u64).to_le_bytes());
    out.extend(crc32fast::hash(&payload).to_le_bytes());
    out.extend(payload);
    out
}

/// The entry `key` of a CBOR map.
fn entry<'a>(v: &'a mut ciborium::Value, key: &str) -> &'a mut ciborium::Value {
    let ciborium::Value::Map(m) = v else {
        panic!("not a map")
    };
    &mut m
        .iter_mut()
        .find(|(k, _)| k.as_text() == Some(key))
        .unwrap_or_else(|| panic!("no {key}"))
        .1
}

/// A checkpoint with a flipped bit, cut short, or holding times no run has (a negative
/// time, a NaN next snapshot, a zero first step) is refused with its reason; an earlier
/// checkpoint of the series can be resumed from instead, and the later ones are
/// removed.
#[test]
fn a_corrupt_checkpoint_is_refused_and_an_earlier_one_resumes() {
    let scene = rz_scene();
    let whole = fresh("checkpoint-corrupt-whole");
    let a = run(&scene, &whole, &options(2, None, true, false)).unwrap();
    let dir = fresh("checkpoint-corrupt");
    copy_dir(&whole, &dir);
    let series = checkpoints(&dir);
    // Snapshots every 0.25 µs to 1 µs: checkpoints at 0.25, 0.5 and 0.75 µs, the
    // default three kept.
    assert_eq!(series.len(), 3, "{series:?}");
    let (_, newest) = series.last().unwrap().clone();
    let good = std::fs::read(&newest).unwrap();
    let resume = options(2, None, false, true);
    let mut flipped = good.clone();
    let k = flipped.len() / 2;
    flipped[k] ^= 0x10;
    std::fs::write(&newest, &flipped).unwrap();
    assert!(refused(&scene, &dir, &resume).contains("checksum"));
    std::fs::write(&newest, &good[..good.len() - 100]).unwrap();
    assert!(refused(&scene, &dir, &resume).contains("truncated"));
    let (frame, value) = unframe(&good);
    let set = |path: &[&str], x: ciborium::Value| {
        let mut v = value.clone();
        let mut slot = &mut v;
        for key in path {
            slot = entry(slot, key);
        }
        *slot = x;
        std::fs::write(&newest, reframe(&frame, &v)).unwrap();
    };
    set(&["solver", "state", "time"], ciborium::Value::Float(-1e-7));
    assert!(refused(&scene, &dir, &resume).contains("not a run's"));
    set(&["next_snapshot"], ciborium::Value::Float(f64::NAN));
    assert!(refused(&scene, &dir, &resume).contains("next snapshot"));
    set(&["solver", "first_dt"], ciborium::Value::Float(0.0));
    assert!(refused(&scene, &dir, &resume).contains("first time step"));
    // The checkpoint before it resumes, removes the bad one and repeats the run.
    let earlier = series[1].1.file_name().unwrap().to_owned();
    let from = RunOptions {
        resume_from: Some(earlier.into()),
        ..resume.clone()
    };
    let b = run(&scene, &dir, &from).unwrap();
    assert!(
        (b.resumed_from_s[0] - 0.5e-6).abs() < 1e-15,
        "{:?}",
        b.resumed_from_s
    );
    assert!(!newest.exists() || std::fs::read(&newest).unwrap() != flipped);
    assert_same_outputs((&whole, &a), (&dir, &b), "snapshots/00004.vtu");
}

/// A stop request (what SIGINT and SIGTERM raise) mid-run finishes the step, writes a
/// checkpoint and a partial summary, and returns `Interrupted`; resumed, the run writes
/// what the uninterrupted run writes, to the bit.
#[test]
fn a_run_stopped_mid_way_resumes_to_the_uninterrupted_result() {
    let scene = rz_scene();
    let whole = fresh("checkpoint-stop-whole");
    let a = run(&scene, &whole, &options(2, None, false, false)).unwrap();
    assert!(a.complete);
    let dir = fresh("checkpoint-stop");
    let stop = StopFlag::new();
    let raise = stop.clone();
    let stopped = RunOptions {
        stop,
        ..options(2, None, false, false)
    };
    // Raised from another thread while the run steps, at an arbitrary step between
    // snapshots.
    let watcher = std::thread::spawn({
        let dir = dir.clone();
        move || {
            // Snapshots appear whole (renamed into place) as the run passes them.
            while !dir.join("snapshots/00001.vtu").exists() {
                std::thread::sleep(std::time::Duration::from_millis(2));
            }
            raise.request();
        }
    });
    let e = run(&scene, &dir, &stopped).unwrap_err();
    watcher.join().unwrap();
    assert!(e.is_interrupted() && !e.is_bad_input(), "{e}");
    println!("{e}");
    let summary = std::fs::read_to_string(dir.join("summary.json")).unwrap();
    assert!(summary.contains("\"complete\": false"), "{summary}");
    assert_eq!(checkpoints(&dir).len(), 1);
    let b = run(&scene, &dir, &options(1, None, false, true)).unwrap();
    assert!(b.complete);
    assert_eq!(b.resumed_from_s.len(), 1);
    assert_same_outputs((&whole, &a), (&dir, &b), "snapshots/00004.vtu");
}

/// The solver refuses the state of another set-up and keeps its own.
#[test]
fn a_solver_checkpoint_of_another_set_up_is_refused_and_changes_nothing() {
    let scene = rz_scene();
    let rz = |scale: f64| match scene.build_scaled(scale).unwrap().simulation {
        SceneSimulation::Rz(sim) => sim,
        _ => panic!("the scene is RZ"),
    };
    let mut sim = rz(1.0);
    sim.step(1e-9).unwrap();
    let position = sim.state.particles.position.clone();
    let coarser = rz(0.5).checkpoint();
    let e = sim.restore(coarser).unwrap_err().to_string();
    println!("{e}");
    assert!(e.contains("particles"), "{e}");
    assert_eq!(sim.state.particles.position, position);
    let mut heavier = sim.checkpoint();
    heavier.state.particles.mass[7] *= 2.0;
    let e = sim.restore(heavier).unwrap_err().to_string();
    println!("{e}");
    assert!(e.contains("mass"), "{e}");
    let mut twice = sim.checkpoint();
    twice.state.particles.id[1] = twice.state.particles.id[0];
    let e = sim.restore(twice).unwrap_err().to_string();
    println!("{e}");
    assert!(e.contains("twice"), "{e}");
    let own = sim.checkpoint();
    sim.restore(own).unwrap();
    assert_eq!(sim.state.particles.position, position);
}

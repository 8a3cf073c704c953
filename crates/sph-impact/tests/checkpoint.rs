//! Checkpoints: a run resumed from its checkpoint writes what the uninterrupted run
//! writes, to the bit (history, snapshots, collection, summary physics), in RZ with
//! particles in free flight, in 3-D, in plane strain and in 1-D, on another thread count, and when extended to a
//! later end time; a checkpoint that does not fit is refused with a one-line reason.
//!
//! `cargo test -p sph-impact --test checkpoint -- --nocapture` prints the refusals.

use sph_impact::run::{CHECKPOINT_FILE, RunError, RunOptions, RunSummary, run};
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
    for sub in ["", "snapshots"] {
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
    let end = Some(0.5e-6);
    let whole = fresh("checkpoint-3d-whole");
    let a = run(&scene, &whole, &options(2, end, true, false)).unwrap();
    let resumed = fresh("checkpoint-3d-resumed");
    copy_dir(&whole, &resumed);
    let b = run(&scene, &resumed, &options(2, end, false, true)).unwrap();
    assert_eq!(b.resumed_from_s.len(), 1);
    // Snapshots at 0, 0.25 and 0.5 µs; resumed from 0.25 µs.
    assert_same_outputs((&whole, &a), (&resumed, &b), "snapshots/00002.vtu");
}

/// In plane strain and in 1-D too (the example scenes to 0.5 µs, resumed from 0.25 µs);
/// a 1-D checkpoint is refused for the same bodies in plane strain.
#[test]
fn resumed_plane_and_1d_runs_repeat_the_uninterrupted_ones_bit_for_bit() {
    for (file, name) in [("smoke_plane.toml", "plane"), ("flyer_plate_1d.toml", "1d")] {
        let scene = Scene::from_toml_file(scene_file(file)).unwrap();
        let end = Some(0.5e-6);
        let whole = fresh(&format!("checkpoint-{name}-whole"));
        let a = run(&scene, &whole, &options(2, end, true, false)).unwrap();
        let resumed = fresh(&format!("checkpoint-{name}-resumed"));
        copy_dir(&whole, &resumed);
        let b = run(&scene, &resumed, &options(1, end, false, true)).unwrap();
        assert_eq!(b.resumed_from_s.len(), 1, "{name}");
        assert_same_outputs((&whole, &a), (&resumed, &b), "snapshots/00002.vtu");
        if name == "1d" {
            let mut plane = scene.clone();
            plane.geometry = sph_impact::scene::GeometryKind::Plane;
            let message = refused(&plane, &resumed, &options(1, end, false, true));
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
    assert!(dir.join(CHECKPOINT_FILE).is_file());
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
    std::fs::write(dir.join(CHECKPOINT_FILE), b"not cbor").unwrap();
    assert!(refused(&scene, &dir, &resume).contains("not a checkpoint"));
    // A fresh run without --checkpoint removes a checkpoint an earlier run left.
    run(&scene, &dir, &options(2, Some(0.5e-6), false, false)).unwrap();
    assert!(!dir.join(CHECKPOINT_FILE).exists());
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

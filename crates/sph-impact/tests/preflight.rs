//! One validation for `check` and `run`: every scene `run` rejects before stepping,
//! `check` rejects with the same message; what a run cannot measure (β of a scene that
//! does not move) is a warning, not a failed run after the work.
//!
//! `cargo test -p sph-impact --test preflight -- --nocapture` prints the messages.

use sph_impact::run::{RunError, RunOptions, run};
use sph_impact::scene::Scene;
use std::path::{Path, PathBuf};

fn base(name: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../examples/scenes")
            .join(name),
    )
    .unwrap()
}

fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("preflight")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn options(end_time: Option<f64>, resolution_scale: f64) -> RunOptions {
    RunOptions {
        threads: Some(1),
        end_time,
        resolution_scale,
        quiet: true,
        ..RunOptions::default()
    }
}

/// `check` and `run` both refuse `text` (at `scale`, to `end`), with one and the same
/// one-line message holding `needle` (or it is refused as it is read); the run leaves no
/// output behind.
fn both_refuse(label: &str, text: &str, scale: f64, end: Option<f64>, needle: &str) {
    // What the scene's own keys show is refused when it is read, by both commands.
    let scene = match Scene::from_toml_str(text, "scene.toml") {
        Ok(scene) => scene,
        Err(e) => {
            let e = e.to_string();
            println!("{label} (read): {e}");
            assert!(e.contains(needle) && !e.contains('\n'), "{label}: {e}");
            return;
        }
    };
    let checked = scene.check_report(scale, 1, end).unwrap_err().to_string();
    let dir = fresh(label);
    let e = run(&scene, &dir, &options(end, scale)).unwrap_err();
    assert!(e.is_bad_input(), "{label}: {e}");
    let ran = match e {
        RunError::Scene(s) => s.to_string(),
        other => panic!("{label}: {other}"),
    };
    println!("{label}: {checked}");
    assert_eq!(checked, ran, "{label}");
    assert!(checked.contains(needle), "{label}: {checked}");
    assert!(!checked.contains('\n'), "{label}");
    assert!(
        !dir.join("history.csv").exists(),
        "{label}: a refused run wrote"
    );
}

#[test]
fn check_refuses_what_run_refuses_before_stepping() {
    let rz = base("smoke_rz.toml");
    let smoke = base("smoke.toml");
    let sub = |text: &str, from: &str, to: &str| {
        assert!(text.contains(from), "{from}");
        text.replacen(from, to, 1)
    };
    let cases = [
        (
            "tiny-interval",
            sub(
                &rz,
                "snapshot_interval = 0.25e-6",
                "snapshot_interval = 1e-300",
            ),
            1.0,
            None,
            "output.snapshot_interval",
        ),
        (
            "flood",
            sub(
                &rz,
                "snapshot_interval = 0.25e-6",
                "snapshot_interval = 1e-25",
            ),
            1.0,
            None,
            "first time step",
        ),
        (
            "max-snapshots",
            sub(
                &rz,
                "snapshot_interval = 0.25e-6",
                "snapshot_interval = 0.25e-6\nmax_snapshots = 3",
            ),
            1.0,
            None,
            "max_snapshots = 3",
        ),
        (
            "crater-bin",
            sub(
                &rz,
                "surface_z = 0.0",
                "surface_z = 0.0\ncrater_bin = 1e-12",
            ),
            1.0,
            None,
            "diagnostics.crater_bin",
        ),
        (
            "ejecta-bin",
            sub(&rz, "surface_z = 0.0", "surface_z = 0.0\nejecta_bin = 1e-9"),
            1.0,
            None,
            "diagnostics.ejecta_bin",
        ),
        (
            "fast",
            sub(
                &rz,
                "velocity = [0.0, 0.0, -3900.0]",
                "velocity = [0.0, 0.0, -1e300]",
            ),
            1.0,
            None,
            "`velocity`",
        ),
        ("end-nan", rz.clone(), 1.0, Some(f64::NAN), "end time"),
        ("end-inf", rz.clone(), 1.0, Some(f64::INFINITY), "end time"),
        ("coarse", rz.clone(), 0.2, None, "across"),
        (
            "mass",
            sub(&smoke, "mass_tolerance = 0.25", "mass_tolerance = 0.1"),
            1.0,
            None,
            "mass_tolerance",
        ),
        (
            "mass-negative",
            sub(&smoke, "mass_tolerance = 0.25", "mass_tolerance = -1.0"),
            1.0,
            None,
            "mass_tolerance",
        ),
    ];
    for (label, text, scale, end, needle) in cases {
        both_refuse(label, &text, scale, end, needle);
    }
}

/// A fourth velocity component is an error, not dropped.
#[test]
fn a_velocity_of_four_components_is_refused() {
    let text = base("smoke_rz.toml").replacen(
        "velocity = [0.0, 0.0, -3900.0]",
        "velocity = [0.0, 0.0, -3900.0, 1.0]",
        1,
    );
    let e = Scene::from_toml_str(&text, "scene.toml")
        .unwrap_err()
        .to_string();
    println!("{e}");
    assert!(e.contains("velocity") && e.contains("length 4"), "{e}");
}

/// A scene that does not move has no β: the run ends with 0, β null in the summary and
/// warnings for the figures' series left out.
#[test]
fn a_run_without_an_impact_ends_with_warnings_not_an_error() {
    let text = base("smoke_rz.toml").replacen(
        "velocity = [0.0, 0.0, -3900.0]",
        "velocity = [0.0, 0.0, 0.0]",
        1,
    );
    let scene = Scene::from_toml_str(&text, "scene.toml").unwrap();
    scene.check_report(1.0, 1, Some(0.1e-6)).unwrap();
    let dir = fresh("at-rest");
    let s = run(&scene, &dir, &options(Some(0.1e-6), 1.0)).unwrap();
    assert!(s.beta.is_nan() && s.complete);
    assert!(!s.warnings.is_empty());
    println!("{:#?}", s.warnings);
    assert!(s.warnings.iter().any(|w| w.contains("beta")));
    assert!(dir.join("history.png").is_file() && dir.join("summary.json").is_file());
}

/// A single body needs no diagnostics keys.
#[test]
fn a_single_body_scene_checks_without_diagnostics_keys() {
    let text = base("smoke_rz.toml");
    let cut = text.find("[[body]]\nname = \"target\"").unwrap();
    let end = text.find("[solver]").unwrap();
    let single = format!("{}{}", &text[..cut], &text[end..]);
    let single = single[..single.find("[diagnostics]").unwrap()].to_owned();
    let scene = Scene::from_toml_str(&single, "scene.toml").unwrap();
    assert_eq!(scene.bodies.len(), 1);
    scene.check_report(1.0, 1, None).unwrap();
    let dir = fresh("single");
    let s = run(&scene, &dir, &options(Some(0.1e-6), 1.0)).unwrap();
    assert!(s.complete);
}

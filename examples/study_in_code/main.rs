//! A parameter study and a fit built in Rust instead of a study file (docs/studies.md).
//!
//! The study runs the RZ smoke scene (`examples/scenes/smoke_rz.toml`, cut to 0.2 µs) at
//! two values of n_target and two projectile speeds (the speed linked with the
//! diagnostics' impact speed) and prints its table; the fit then finds the projectile
//! speed whose initial kinetic energy is that of −3500 m/s, within the speed bounds, once
//! with the targets' squared relative error and once with an objective written here.
//! Both write into a directory under the system's temporary directory.
//!
//! Run: `cargo run --release -p sph-examples --example study_in_code`.

use sph_impact::study::{
    Axis, Fit, Free, Spacing, Study, StudyOptions, Target, run_fit, run_fit_with, run_study,
};
use std::error::Error;
use std::path::Path;
use toml::Value;

fn main() -> Result<(), Box<dyn Error>> {
    let scene_file = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/smoke_rz.toml");
    let scene = std::fs::read_to_string(&scene_file)?;
    let out = std::env::temp_dir().join("sph-study-in-code");
    let options = StudyOptions {
        jobs: 2,
        quiet: true,
        ..StudyOptions::default()
    };

    let mut study = Study::new(scene.clone(), scene_file.display().to_string());
    study.description = "n_target × speed on the RZ smoke scene, 0.2 µs".into();
    study.end_time = Some(0.2e-6);
    study
        .axes
        .push(Axis::list("solver.n_target", [2.0, 2.5].map(Value::Float)));
    study.axes.push(Axis::linked(
        vec![
            "body.projectile.velocity[2]".into(),
            "diagnostics.impact_speed".into(),
        ],
        vec![
            vec![Value::Float(-3900.0), Value::Float(3900.0)],
            vec![Value::Float(-2300.0), Value::Float(2300.0)],
        ],
    ));
    study.metrics = vec!["beta".into(), "initial.kinetic".into(), "steps".into()];
    study.check()?;
    let table = run_study(&study, &out.join("study"), &options)?;
    print!("{}", table.to_markdown());

    // The fit: the speed whose initial kinetic energy is that of point 2 (n_target 2.5 at
    // 3900 m/s) scaled to 3500 m/s, E ∝ v².
    let kinetic_3900 = table.rows[2].metrics[1];
    let target = kinetic_3900 * (3500.0f64 / 3900.0).powi(2);
    let mut base = Study::new(scene, scene_file.display().to_string());
    base.end_time = Some(1e-8);
    base.metrics = vec!["initial.kinetic".into()];
    let fit = Fit {
        study: base,
        free: vec![Free {
            path: "body.projectile.velocity[2]".into(),
            min: -4500.0,
            max: -3000.0,
            scale: Spacing::Linear,
            start: Some(-4200.0),
        }],
        targets: vec![Target {
            metric: "initial.kinetic".into(),
            value: target,
            weight: 1.0,
            case: None,
        }],
        constraints: Vec::new(),
        budget: 16,
        cases: Vec::new(),
    };
    fit.check()?;
    let report = run_fit(&fit, &out.join("fit"), &options)?;
    let best = &report.runs[report.best.ok_or("no run finished")?];
    println!(
        "\nfit: {} runs ({}); best speed {:.1} m/s (sought −3500), objective {:.2e}",
        report.runs.len(),
        report.ended,
        best.values[0],
        best.objective
    );

    // The same search with the user's own objective: the absolute relative error of the
    // target metrics (given in the order of `fit.targets`).
    let own = |metrics: &[f64]| (metrics[0] / target - 1.0).abs();
    let report = run_fit_with(&fit, &out.join("fit_own_objective"), &options, &own)?;
    let best = &report.runs[report.best.ok_or("no run finished")?];
    println!(
        "fit, own objective: {} runs; best speed {:.1} m/s, |E/E_target − 1| = {:.2e}",
        report.runs.len(),
        best.values[0],
        best.objective
    );
    println!("directories under {}", out.display());
    Ok(())
}

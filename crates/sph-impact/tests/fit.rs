//! `sph-impact fit`: the inverse search finds a parameter that a metric determines, keeps
//! every run inside the constraints, and resumes to the same search.

use sph_impact::study::{Fit, PointStatus, Study, StudyOptions, run_fit, run_fit_with, run_study};
use std::path::{Path, PathBuf};

fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes")
}

fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn quiet() -> StudyOptions {
    StudyOptions {
        quiet: true,
        ..StudyOptions::default()
    }
}

/// The initial kinetic energy of the RZ smoke scene with the projectile at `speed`.
/// The initial kinetic energy at `speed`, from a one-point study in its own directory
/// (`dir`: tests that run side by side must not share one).
fn kinetic_at(speed: f64, dir: &str) -> f64 {
    let text = format!(
        "scene = \"smoke_rz.toml\"\nend_time = 1e-8\nmetrics = [\"initial.kinetic\"]\n\
         [[parameter]]\npath = \"body.projectile.velocity[2]\"\nvalues = [{speed:?}]\n"
    );
    let s = Study::from_toml_str(&text, "ke.toml", &scenes()).unwrap();
    let t = run_study(&s, &fresh(dir), &quiet()).unwrap();
    t.rows[0].metrics[0]
}

/// The fit's file: the projectile's speed and the target's Weibull k free, the initial
/// kinetic energy of −3500 m/s as the target, the Brazilian disc's static strength held
/// within ±11 % of 9.8 MPa.
fn fit_text(target: f64, budget: usize) -> String {
    format!(
        r#"
description = "test fit"
scene = "smoke_rz.toml"
end_time = 1e-8
budget = {budget}

[[free]]
path = "body.projectile.velocity[2]"
min = -4500.0
max = -3000.0
start = -4200.0

[[free]]
path = "body.target.material.damage.k"
min = 1e38
max = 1e44
scale = "log"
start = 2.7e41

[[target]]
metric = "initial.kinetic"
value = {target:e}

[[derived]]
name = "sigma_b_disc"
static_strength = {{ body = "target", volume = 9.817e-5 }}

[[constraint]]
derived = "sigma_b_disc"
min = 8.722e6
max = 10.878e6
"#
    )
}

#[test]
fn a_fit_with_the_users_own_objective_records_it_and_finds_the_speed() {
    let target = kinetic_at(-3500.0, "fit_reference_own_objective");
    let fit = Fit::from_toml_str(&fit_text(target, 24), "fit.toml", &scenes()).unwrap();
    let dir = fresh("fit_own_objective");
    // Not the default squared relative error: the absolute one.
    let own = |m: &[f64]| (m[0] / target - 1.0).abs();
    let report = run_fit_with(&fit, &dir, &quiet(), &own).unwrap();
    for e in &report.runs {
        if e.status == PointStatus::Done {
            assert_eq!(e.objective, own(&e.metrics[..1]), "run {}", e.index);
        } else {
            assert!(e.objective.is_nan(), "run {}", e.index);
        }
    }
    let best = &report.runs[report.best.unwrap()];
    assert!(
        (best.values[0] / -3500.0 - 1.0).abs() < 0.01,
        "{:?} after {} runs",
        best.values,
        report.runs.len()
    );
    // fit.csv's last column is this objective, not the default squared error.
    let csv = std::fs::read_to_string(dir.join("fit.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    assert_eq!(rows.len(), report.runs.len());
    for (row, e) in rows.iter().zip(&report.runs) {
        let last: f64 = row.rsplit(',').next().unwrap().parse().unwrap();
        assert!(
            last == e.objective || (last.is_nan() && e.objective.is_nan()),
            "{row}"
        );
    }
}

#[test]
fn a_fit_finds_the_speed_inside_the_constraint_and_resumes_to_the_same_search() {
    let target = kinetic_at(-3500.0, "fit_reference");
    let fit = Fit::from_toml_str(&fit_text(target, 24), "fit.toml", &scenes()).unwrap();
    let dir = fresh("fit_whole");
    let report = run_fit(&fit, &dir, &quiet()).unwrap();
    assert!(report.runs.len() <= 24, "{}", report.runs.len());
    let best = &report.runs[report.best.unwrap()];
    assert_eq!(best.status, PointStatus::Done);
    assert!(
        (best.values[0] / -3500.0 - 1.0).abs() < 0.003,
        "{:?} after {} runs",
        best.values,
        report.runs.len()
    );
    assert!(best.objective < 1e-3, "{}", best.objective);
    // No run outside the constraint: a point against it is not run at all.
    for e in &report.runs {
        let sb = e.metrics[1];
        assert!(
            (8.722e6..=10.878e6).contains(&sb),
            "run {}: σ_b {sb}",
            e.index
        );
    }
    // One sensitivity run per free parameter: the kinetic energy goes as v², so its
    // elasticity to the speed is about 2, and k does not change it.
    assert_eq!(report.sensitivity.len(), 2);
    assert!(
        (report.sensitivity[0].1[0] - 2.0).abs() < 0.1,
        "{:?}",
        report.sensitivity
    );
    assert!(
        report.sensitivity[1].1[0].abs() < 1e-9,
        "{:?}",
        report.sensitivity
    );
    let md = std::fs::read_to_string(dir.join("fit.md")).unwrap();
    assert!(md.contains("Best: run"), "{md}");
    // A plot per free parameter: the runs' metrics and objective against it.
    let plots = [
        "plot_body.projectile.velocity_2_.png",
        "plot_body.target.material.damage.k.png",
    ];
    let drawn: Vec<Vec<u8>> = plots
        .iter()
        .map(|p| std::fs::read(dir.join(p)).unwrap())
        .collect();
    for (plot, bytes) in plots.iter().zip(&drawn) {
        assert_eq!(&bytes[1..4], b"PNG", "{plot}");
        std::fs::remove_file(dir.join(plot)).unwrap();
    }
    // Drawn again from fit.csv alone (`fit --plots`): the same images.
    sph_impact::study::redraw_fit_plots(&fit, &dir).unwrap();
    for (plot, bytes) in plots.iter().zip(&drawn) {
        assert!(std::fs::read(dir.join(plot)).unwrap() == *bytes, "{plot}");
    }
    // Another fit's file does not read these runs.
    let other = fit_text(target, 5).replace(
        "body.target.material.damage.k",
        "body.target.material.damage.m",
    );
    let other = other.replace(
        "min = 1e38\nmax = 1e44\nscale = \"log\"\nstart = 2.7e41",
        "min = 8.0\nmax = 12.0\nstart = 10.0",
    );
    let other = Fit::from_toml_str(&other, "other.toml", &scenes()).unwrap();
    let e = sph_impact::study::redraw_fit_plots(&other, &dir).unwrap_err();
    assert!(e.to_string().contains("not this fit's runs"), "{e}");

    // The same search cut short by a smaller budget, then continued with the full one,
    // makes the same runs.
    let pieces = fresh("fit_pieces");
    let short = Fit::from_toml_str(&fit_text(target, 5), "fit.toml", &scenes()).unwrap();
    let r = run_fit(&short, &pieces, &quiet()).unwrap();
    assert_eq!(r.runs.len(), 5);
    assert!(r.ended.contains("budget"), "{}", r.ended);
    run_fit(&fit, &pieces, &quiet()).unwrap();
    assert_eq!(
        std::fs::read_to_string(pieces.join("fit.csv")).unwrap(),
        std::fs::read_to_string(dir.join("fit.csv")).unwrap()
    );

    // Two at a time (the starting simplex's three runs, then the two sensitivity runs):
    // the same runs, numbers and sensitivities.
    let two = fresh("fit_two_jobs");
    let r2 = run_fit(&fit, &two, &StudyOptions { jobs: 2, ..quiet() }).unwrap();
    assert_eq!(
        std::fs::read_to_string(two.join("fit.csv")).unwrap(),
        std::fs::read_to_string(dir.join("fit.csv")).unwrap()
    );
    for (a, b) in r2.sensitivity.iter().zip(&report.sensitivity) {
        assert_eq!(a.1, b.1);
    }
}

/// A stop request before the first runs (Ctrl-C during the starting simplex) ends the
/// fit with its report, not a panic, and the same command then runs the whole search.
#[test]
fn a_fit_stopped_in_its_starting_simplex_ends_cleanly_and_resumes() {
    let fit = Fit::from_toml_str(&fit_text(1.0e4, 4), "fit.toml", &scenes()).unwrap();
    let dir = fresh("fit_stopped");
    let stopped = StudyOptions {
        stop: sph_impact::run::StopFlag::new(),
        ..quiet()
    };
    stopped.stop.request();
    let r = run_fit(&fit, &dir, &stopped).unwrap();
    assert!(r.ended.contains("stopped"), "{}", r.ended);
    assert!(r.runs.is_empty() && r.sensitivity.is_empty());
    let r = run_fit(&fit, &dir, &quiet()).unwrap();
    assert_eq!(r.runs.len(), 4);
    assert!(r.runs.iter().all(|e| e.status == PointStatus::Done));
}

#[test]
fn bad_fit_files_name_the_key() {
    let good = fit_text(1.0, 10);
    let cases = [
        (
            good.replace("min = -4500.0", "min = -2000.0"),
            "`free[0].max`: the bounds are empty or reversed",
        ),
        (
            good.replace("start = -4200.0", "start = -5000.0"),
            "`free[0].start`: -5000 is outside the bounds",
        ),
        (
            good.replace("derived = \"sigma_b_disc\"", "derived = \"sigma\""),
            "`constraint[0].derived`: `sigma` is not one of the `[[derived]]` metrics",
        ),
        (
            good.replace("max = 10.878e6", "max = 9.0e6"),
            "the start point (body.projectile.velocity[2] = -4200.0, body.target.material.damage.k = 2.7e41) violates the constraints",
        ),
        (
            good.replace("budget = 10", "budget = 2"),
            "`budget`: must allow at least the starting simplex, 3 runs",
        ),
        (
            good.replace("metric = \"initial.kinetic\"", "metric = \"kinetic\""),
            "`target[0].metric`: `kinetic` is not a key of summary.json",
        ),
        (
            format!("{good}\n[[target]]\nmetric = \"beta\"\nvalue = 2.0\ncase = \"slow\"\n"),
            "`target[1].case`: `slow` is not the name of a `[[case]]`",
        ),
        (
            format!("{good}\n[[case]]\nname = \"slow\"\nscene = \"smoke_rz.toml\"\n"),
            "`case[0]`: no `[[target]]` names case `slow`: its runs would count for nothing",
        ),
        (
            format!(
                "{good}\n[[case]]\nname = \"a/b\"\nscene = \"smoke_rz.toml\"\n\
                 [[target]]\nmetric = \"beta\"\nvalue = 2.0\ncase = \"a/b\"\n"
            ),
            "`case[0].name`: `a/b` cannot name a directory",
        ),
        (
            format!("{good}\n[[case]]\nname = \"slow\"\nscene = \"missing.toml\"\n"),
            "`case[0].scene`:",
        ),
        (
            format!("{good}\n[[set]]\npath = \"body.asteroid.velocity[2]\"\nvalue = 1.0\n"),
            "`set[0].path`: the scene has no body named `asteroid`",
        ),
        (
            format!(
                "{good}\n[[set]]\npath = \"body.target.material.strength\"\n\
                 value = {{ model = \"von-mises\" }}\n"
            ),
            "`set[0].value`: the scene",
        ),
    ];
    for (text, expected) in cases {
        let e = Fit::from_toml_str(&text, "fit.toml", &scenes()).unwrap_err();
        let line = e.to_string();
        assert!(line.starts_with("fit.toml:"), "{line}");
        assert!(line.contains(expected), "{line}\n expected: {expected}");
    }
}

/// `[[set]]` fixes a scene value for the whole fit: here the target's strength model,
/// swapped for a constant strength, in the fit's scene and in its case's.
#[test]
fn a_fit_file_sets_fixed_values_in_its_scene_and_every_case() {
    let set = "\n[[set]]\npath = \"body.target.material.strength\"\n\
               value = { model = \"von-mises\", yield_strength = 1.0e8 }\n\
               [[case]]\nname = \"slow\"\nscene = \"smoke_rz.toml\"\n\
               [[target]]\nmetric = \"beta\"\nvalue = 2.0\ncase = \"slow\"\n";
    let fit = Fit::from_toml_str(
        &format!("{}{set}", fit_text(1.0, 10)),
        "fit.toml",
        &scenes(),
    )
    .unwrap();
    for scene in [&fit.study.scene, &fit.cases[0].study.scene] {
        let scene = sph_impact::scene::Scene::from_toml_str(scene, "scene.toml").unwrap();
        let target = scene.bodies.iter().find(|b| b.name == "target").unwrap();
        let text = format!("{:?}", target.material);
        assert!(
            text.contains("von-mises") || text.contains("VonMises"),
            "{text}"
        );
    }
}

/// The fit of a speed to two scenes at once, with a third held out: the squared relative
/// errors of E(v) against E(−3300 m/s) in the fit's own scene and against E(−3700 m/s) in
/// case `fast` are least at v*² = (1/a² + 1/b²)/(1/a⁴ + 1/b⁴) (a = 3300, b = 3700, since
/// E ∝ v²), which neither target alone gives; case `held` is run once at the best point
/// and compared with E(−3500 m/s).
fn cases_text(e: impl Fn(f64) -> f64, budget: usize) -> String {
    format!(
        r#"
scene = "smoke_rz.toml"
end_time = 1e-8
budget = {budget}

[[free]]
path = "body.projectile.velocity[2]"
min = -4500.0
max = -3000.0
start = -4200.0

[[case]]
name = "fast"
scene = "smoke_rz.toml"

[[case]]
name = "held"
scene = "smoke_rz.toml"
hold_out = true

[[target]]
metric = "initial.kinetic"
value = {:e}

[[target]]
metric = "initial.kinetic"
value = {:e}
case = "fast"

[[target]]
metric = "initial.kinetic"
value = {:e}
case = "held"
"#,
        e(-3300.0),
        e(-3700.0),
        e(-3500.0)
    )
}

#[test]
fn a_fit_over_two_scenes_finds_their_compromise_and_reports_the_hold_out() {
    let e3500 = kinetic_at(-3500.0, "fit_cases_reference");
    let e = |v: f64| e3500 * (v / 3500.0).powi(2);
    let fit = Fit::from_toml_str(&cases_text(e, 14), "fit.toml", &scenes()).unwrap();
    assert_eq!(fit.fitted_targets().count(), 2);
    let dir = fresh("fit_cases");
    let report = run_fit(&fit, &dir, &quiet()).unwrap();
    let (a, b) = (3300.0f64.powi(2), 3700.0f64.powi(2));
    let v_star = -((1.0 / a + 1.0 / b) / (1.0 / (a * a) + 1.0 / (b * b))).sqrt();
    let best = &report.runs[report.best.unwrap()];
    assert!(
        (best.values[0] / v_star - 1.0).abs() < 0.005,
        "best {:?}, sought {v_star} after {} runs",
        best.values,
        report.runs.len()
    );
    // Each run has both fitted targets' metrics, each from its own scene's run.
    for r in report.runs.iter().filter(|r| r.status == PointStatus::Done) {
        assert_eq!(r.metrics.len(), 2);
        let expected = e(r.values[0]);
        for m in &r.metrics {
            assert!(
                (m / expected - 1.0).abs() < 1e-9,
                "run {}: {m} against {expected}",
                r.index
            );
        }
        let case_run = dir.join(format!(
            "search/cases/fast/points/{:04}/run/summary.json",
            r.index
        ));
        assert!(case_run.exists(), "{}", case_run.display());
    }
    // The hold-out case ran once, at the best point, and is compared, not fitted.
    assert_eq!(report.hold_out.len(), 1);
    let h = &report.hold_out[0];
    assert_eq!((h.case.as_str(), h.status), ("held", PointStatus::Done));
    assert!(
        (h.metrics[0] / e(best.values[0]) - 1.0).abs() < 1e-9,
        "{h:?}"
    );
    assert!(!dir.join("search/cases/held").exists());
    let md = std::fs::read_to_string(dir.join("fit.md")).unwrap();
    assert!(
        md.contains("Hold-out cases") && md.contains("| held | done |"),
        "{md}"
    );
    let csv = std::fs::read_to_string(dir.join("fit.csv")).unwrap();
    assert!(
        csv.starts_with("run,body.projectile.velocity[2],status,initial.kinetic,initial.kinetic@fast,objective\n"),
        "{csv}"
    );

    // Cut short, then continued with the cases run side by side: the same search.
    let pieces = fresh("fit_cases_pieces");
    let short = Fit::from_toml_str(&cases_text(e, 3), "fit.toml", &scenes()).unwrap();
    run_fit(&short, &pieces, &quiet()).unwrap();
    let two = StudyOptions { jobs: 2, ..quiet() };
    run_fit(&fit, &pieces, &two).unwrap();
    assert_eq!(
        std::fs::read_to_string(pieces.join("fit.csv")).unwrap(),
        csv
    );
}

#[test]
fn every_bundled_study_and_fit_file_reads_and_checks() {
    let dir = scenes().join("../studies");
    let mut read = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let is_fit = text.lines().any(|l| l.starts_with("budget"));
        let result = if is_fit {
            Fit::from_toml_file(&path).map(|_| ())
        } else {
            Study::from_toml_file(&path).map(|_| ())
        };
        assert!(
            result.is_ok(),
            "{}: {}",
            path.display(),
            result.unwrap_err()
        );
        read += 1;
    }
    assert!(read >= 5, "{read} files under {}", dir.display());
}

/// `--resolution-scale` (`Fit::set_resolution_scale`) sets the scale of the fit's scene
/// and of every case, the hold-outs included; a scale that is not a positive number is
/// refused.
#[test]
fn a_resolution_scale_given_to_a_fit_applies_to_every_case() {
    let file =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/studies/table2_fit_rz.toml");
    let mut fit = Fit::from_toml_file(&file).unwrap();
    assert_eq!(fit.study.resolution_scale, 0.5);
    assert_eq!(fit.cases.len(), 2);
    fit.set_resolution_scale(1.0).unwrap();
    assert_eq!(fit.study.resolution_scale, 1.0);
    for case in &fit.cases {
        assert_eq!(case.study.resolution_scale, 1.0, "{}", case.name);
    }
    let e = fit.set_resolution_scale(0.0).unwrap_err();
    assert!(
        e.to_string()
            .contains("--resolution-scale must be a positive number"),
        "{e}"
    );
}

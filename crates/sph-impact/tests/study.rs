//! `sph-impact study`: a study's points, its table, resuming, failures and bad study files.

use sph_impact::study::{PointStatus, Study, StudyOptions, metric, run_study};
use std::path::{Path, PathBuf};

fn scenes() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes")
}

fn fresh(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Two values of n_target × two projectile speeds (linked with the diagnostics' impact
/// speed) on the RZ smoke scene, cut to 0.2 µs.
const STUDY: &str = r#"
description = "smoke: n_target × speed"
scene = "smoke_rz.toml"
end_time = 0.2e-6
metrics = ["beta", "crater_depth_m", "steps", "last.kinetic"]

[[parameter]]
path = "solver.n_target"
values = [2.0, 2.5]

[[parameter]]
paths = ["body.projectile.velocity[2]", "diagnostics.impact_speed"]
tuples = [[-3900.0, 3900.0], [-2300.0, 2300.0]]

[[reference]]
metric = "beta"
value = 1.5
source = "made up for the test"
"#;

fn study() -> Study {
    Study::from_toml_str(STUDY, "smoke.study.toml", &scenes()).unwrap()
}

fn options() -> StudyOptions {
    StudyOptions {
        jobs: 2,
        quiet: true,
        ..StudyOptions::default()
    }
}

/// Every point runs, the table holds its values and metrics, and a study stopped after
/// one point and continued (twice: one more point, then the rest, with one point's
/// record lost as if the study were killed after its run) gives the same table, byte for
/// byte, as the study run in one go; finished points are not run again.
#[test]
fn a_study_resumed_in_pieces_gives_the_table_of_one_run() {
    let s = study();
    assert_eq!(s.points().len(), 4);
    let whole = fresh("study_whole");
    let table = run_study(&s, &whole, &options()).unwrap();
    assert_eq!(
        table.parameters,
        [
            "solver.n_target",
            "body.projectile.velocity[2]",
            "diagnostics.impact_speed"
        ]
    );
    for row in &table.rows {
        assert_eq!(row.status, PointStatus::Done, "{row:?}");
        assert!(row.metrics.iter().all(|m| m.is_finite()), "{row:?}");
        assert_eq!(row.errors.len(), 1);
        assert!((row.errors[0] - (row.metrics[0] - 1.5) / 1.5).abs() < 1e-15);
    }
    // The speeds differ, so do the kinetic energies; n_target changes the run.
    let ke: Vec<f64> = table.rows.iter().map(|r| r.metrics[3]).collect();
    assert!(ke[0] > ke[1] && ke[2] > ke[3], "{ke:?}");
    assert_ne!(table.rows[0].metrics[2], table.rows[2].metrics[2]);
    for plot in [
        "plot_solver.n_target.png",
        "plot_body.projectile.velocity_2_.png",
        "plot_diagnostics.impact_speed.png",
    ] {
        let bytes = std::fs::read(whole.join(plot)).unwrap();
        assert_eq!(&bytes[1..4], b"PNG", "{plot}");
    }
    let csv = std::fs::read_to_string(whole.join("study.csv")).unwrap();
    assert!(csv.starts_with("point,solver.n_target,body.projectile.velocity[2],diagnostics.impact_speed,status,beta,crater_depth_m,steps,last.kinetic,error(beta)\n"), "{csv}");
    assert!(csv.contains("\n1,2.0,-2300.0,2300.0,done,"), "{csv}");

    let pieces = fresh("study_pieces");
    let one = StudyOptions {
        max_points: Some(1),
        ..options()
    };
    let t = run_study(&s, &pieces, &one).unwrap();
    let status: Vec<PointStatus> = t.rows.iter().map(|r| r.status).collect();
    assert_eq!(
        status,
        [
            PointStatus::Done,
            PointStatus::Pending,
            PointStatus::Pending,
            PointStatus::Pending
        ]
    );
    let first = std::fs::read_to_string(pieces.join("points/0000/result.json")).unwrap();
    run_study(&s, &pieces, &one).unwrap();
    // Point 1 finished, then its record is lost: it runs again, over its run directory.
    std::fs::remove_file(pieces.join("points/0001/result.json")).unwrap();
    run_study(&s, &pieces, &options()).unwrap();
    assert_eq!(
        std::fs::read_to_string(pieces.join("study.csv")).unwrap(),
        csv
    );
    // Point 0 was not run again: its record (with its wall time) is the first one.
    assert_eq!(
        std::fs::read_to_string(pieces.join("points/0000/result.json")).unwrap(),
        first
    );

    // The metric names checked before a study runs are the keys a run writes.
    let summary: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(whole.join("points/0000/run/summary.json")).unwrap(),
    )
    .unwrap();
    let keys: Vec<&str> = summary
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    let mut expected = metric::SUMMARY_KEYS.to_vec();
    let mut got = keys.clone();
    expected.sort_unstable();
    got.sort_unstable();
    assert_eq!(got, expected);

    // A study directory is not reused for a changed study.
    let changed = STUDY.replace("values = [2.0, 2.5]", "values = [2.0, 3.0]");
    let s2 = Study::from_toml_str(&changed, "smoke.study.toml", &scenes()).unwrap();
    let e = run_study(&s2, &whole, &options()).unwrap_err();
    assert!(e.to_string().contains("was run with another scene"), "{e}");
    assert!(e.bad_input);
    // Nor for the same points run to another end time.
    let longer = STUDY.replace("end_time = 0.2e-6", "end_time = 0.3e-6");
    let s3 = Study::from_toml_str(&longer, "smoke.study.toml", &scenes()).unwrap();
    let e = run_study(&s3, &whole, &options()).unwrap_err();
    assert!(e.to_string().contains("was run with another scene"), "{e}");
    // Another metric needs no run: the table is made from the stored summaries.
    let more = STUDY.replace("\"last.kinetic\"]", "\"last.kinetic\", \"particles\"]");
    let s4 = Study::from_toml_str(&more, "smoke.study.toml", &scenes()).unwrap();
    let quick = StudyOptions {
        max_points: Some(0),
        ..options()
    };
    let t = run_study(&s4, &whole, &quick).unwrap();
    assert!(
        t.rows
            .iter()
            .all(|r| r.status == PointStatus::Done && r.metrics[4] > 0.0)
    );
}

/// A point whose run fails is recorded with its error; the other points run; the failed
/// one is run again only when asked.
#[test]
fn a_failed_point_is_recorded_and_the_study_goes_on() {
    let text = r#"
scene = "smoke_rz.toml"
end_time = 0.1e-6
metrics = ["beta"]
[[parameter]]
path = "body.projectile.placement.spacing"
values = [0.25e-3, 1.0]
"#;
    let s = Study::from_toml_str(text, "fail.study.toml", &scenes()).unwrap();
    let dir = fresh("study_failure");
    let t = run_study(&s, &dir, &options()).unwrap();
    assert_eq!(t.rows[0].status, PointStatus::Done);
    assert_eq!(t.rows[1].status, PointStatus::Failed);
    let error = t.rows[1].error.clone().unwrap();
    assert!(!error.is_empty());
    assert!(t.rows[1].metrics[0].is_nan());
    let md = std::fs::read_to_string(dir.join("study.md")).unwrap();
    assert!(md.contains(&format!("Point 1: {error}")), "{md}");
    // Not run again unless asked; asked, it fails again the same way.
    let again = run_study(&s, &dir, &options()).unwrap();
    assert_eq!(again.rows[1].error.as_deref(), Some(error.as_str()));
    let retry = StudyOptions {
        retry_failed: true,
        ..options()
    };
    let t = run_study(&s, &dir, &retry).unwrap();
    assert_eq!(t.rows[1].status, PointStatus::Failed);
}

/// Bad study files give one line naming the file, line and key.
#[test]
fn bad_study_files_name_file_line_and_key() {
    let base = "scene = \"smoke_rz.toml\"\nmetrics = [\"beta\"]\n";
    let cases: &[(&str, &str)] = &[
        (
            "[[parameter]]\npath = \"solver.n_targt\"\nvalues = [2.0]\n",
            "bad.toml:5:11: `parameter[0].values[0]`: the scene refuses it: `solver.n_targt`: unknown key",
        ),
        (
            "[[parameter]]\npath = \"body.asteroid.velocity\"\nvalues = [2.0]\n",
            "bad.toml:4:8: `parameter[0].path`: the scene has no body named `asteroid`",
        ),
        (
            "[[parameter]]\npath = \"solver.n_target\"\nrange = { from = 3.0, to = 2.0, count = 3 }\n",
            "bad.toml:5:28: `parameter[0].range.to`: the range is empty or reversed",
        ),
        (
            "[[parameter]]\npath = \"solver.n_target\"\nvalues = []\n",
            "bad.toml:5:10: `parameter[0].values`: the list is empty",
        ),
        (
            "[[parameter]]\npath = \"solver.n_target\"\nrange = { from = 2.0, to = 3.0, count = 1 }\n",
            "`parameter[0].range.count`: a range needs at least 2 values",
        ),
        (
            "[[parameter]]\npaths = [\"solver.n_target\", \"seed\"]\ntuples = [[2.0]]\n",
            "`parameter[0].tuples[0]`: has 1 values for 2 paths",
        ),
        (
            "[[parameter]]\npath = \"solver.n_target\"\nvalues = [2.0]\n[[parameter]]\npath = \"solver.n_target\"\nvalues = [3.0]\n",
            "`parameter[1].path`: `solver.n_target` is set by two parameters",
        ),
        (
            "[[reference]]\nmetric = \"crater_diameter_m\"\nvalue = 0.05\n",
            "bad.toml:4:10: `reference[0].metric`: `crater_diameter_m` is not one of the study's metrics",
        ),
        (
            "[[parameter]]\npath = \"solver.n_target\"\nvalue = [2.0]\n",
            "bad.toml:5:1: `parameter[0].value`: unknown key `value`",
        ),
    ];
    for (extra, expected) in cases {
        let text = format!("{base}{extra}");
        let e = Study::from_toml_str(&text, "bad.toml", &scenes()).unwrap_err();
        let line = e.to_string();
        assert!(!line.contains('\n'), "{line}");
        assert!(
            line.contains(expected),
            "{extra}\n  got:      {line}\n  expected: {expected}"
        );
    }
    let unknown_metric = "scene = \"smoke_rz.toml\"\nmetrics = [\"beta\", \"crater_diamter_m\"]\n";
    let e = Study::from_toml_str(unknown_metric, "bad.toml", &scenes()).unwrap_err();
    assert!(
        e.to_string().starts_with(
            "bad.toml:2:20: `metrics[1]`: `crater_diamter_m` is not a key of summary.json"
        ),
        "{e}"
    );
    let no_scene = "scene = \"nowhere.toml\"\nmetrics = [\"beta\"]\n";
    let e = Study::from_toml_str(no_scene, "bad.toml", &scenes()).unwrap_err();
    assert!(e.to_string().starts_with("bad.toml:1:9: `scene`: "), "{e}");
}

/// The Slurm export: each task of the emitted script, run as the scheduler would run it
/// (the script executed with `SLURM_ARRAY_TASK_ID` set), runs its point; `--collect`
/// then gives the table of the study run locally, byte for byte.
#[test]
fn the_slurm_tasks_run_locally_reproduce_the_local_table() {
    let work = fresh("study_slurm");
    std::fs::create_dir_all(&work).unwrap();
    let scene = scenes().join("smoke_rz.toml");
    let text = STUDY.replace(
        "scene = \"smoke_rz.toml\"",
        &format!("scene = {:?}", scene.display().to_string()),
    );
    let file = work.join("smoke.study.toml");
    std::fs::write(&file, &text).unwrap();
    let local = work.join("local");
    let s = Study::from_toml_file(&file).unwrap();
    run_study(&s, &local, &options()).unwrap();

    let exe = env!("CARGO_BIN_EXE_sph-impact");
    let array = work.join("array");
    let out = std::process::Command::new(exe)
        .args([
            "study",
            file.to_str().unwrap(),
            "--out",
            array.to_str().unwrap(),
            "--emit",
            "slurm",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let script = array.join("study.sbatch");
    let body = std::fs::read_to_string(&script).unwrap();
    assert!(body.contains("#SBATCH --array=0-3\n"), "{body}");
    assert!(body.contains("#SBATCH --cpus-per-task=1\n"), "{body}");
    for k in 0..4 {
        assert!(array.join(format!("points/{k:04}/scene.toml")).is_file());
        let task = std::process::Command::new("bash")
            .arg(&script)
            .env("SLURM_ARRAY_TASK_ID", k.to_string())
            .env("SPH_IMPACT", exe)
            .output()
            .unwrap();
        assert!(
            task.status.success(),
            "task {k}: {}",
            String::from_utf8_lossy(&task.stderr)
        );
        // A task writes no table: the tasks run side by side.
        assert!(!array.join("study.csv").exists());
    }
    let collect = std::process::Command::new(exe)
        .args([
            "study",
            file.to_str().unwrap(),
            "--out",
            array.to_str().unwrap(),
            "--collect",
            "--quiet",
        ])
        .output()
        .unwrap();
    assert!(
        collect.status.success(),
        "{}",
        String::from_utf8_lossy(&collect.stderr)
    );
    assert_eq!(
        std::fs::read_to_string(array.join("study.csv")).unwrap(),
        std::fs::read_to_string(local.join("study.csv")).unwrap()
    );
    // A point that does not exist is bad input (exit code 2).
    let bad = std::process::Command::new(exe)
        .args([
            "study",
            file.to_str().unwrap(),
            "--out",
            array.to_str().unwrap(),
            "--point",
            "4",
        ])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("no point 4"));
}

/// A derived metric, the static strength of the study's Brazilian disc (Ø50 × 50 mm), is
/// computed from each point's material without a run: 9.62 MPa for the bundled basalt
/// (paper §3.3), and E (kV)^(−1/m) for the other (m, k); it takes a reference.
#[test]
fn the_static_strength_of_a_volume_is_a_derived_metric() {
    let disc = std::f64::consts::PI * 0.025f64.powi(2) * 0.05;
    let text = format!(
        r#"
scene = "smoke_rz.toml"
metrics = ["beta"]
[[parameter]]
paths = ["body.target.material.damage.m", "body.target.material.damage.k"]
tuples = [[10.0, 2.7e41], [9.0, 1.0e38]]
[[derived]]
name = "sigma_b_disc"
static_strength = {{ body = "target", volume = {disc:e} }}
[[reference]]
metric = "sigma_b_disc"
value = 9.8e6
"#
    );
    let s = Study::from_toml_str(&text, "derived.toml", &scenes()).unwrap();
    let dir = fresh("study_derived");
    let none = StudyOptions {
        max_points: Some(0),
        ..options()
    };
    let t = run_study(&s, &dir, &none).unwrap();
    assert_eq!(t.metrics, ["beta", "sigma_b_disc"]);
    let sb: Vec<f64> = t.rows.iter().map(|r| r.metrics[1]).collect();
    assert!((sb[0] / 9.62e6 - 1.0).abs() < 2e-3, "{sb:?}");
    // E (kV)^(−1/m): the ratio of the two points follows from their (m, k) alone.
    let e_young = sb[0] * (2.7e41 * disc).powf(0.1);
    let expected = e_young * (1.0e38 * disc).powf(-1.0 / 9.0);
    assert!((sb[1] / expected - 1.0).abs() < 1e-12, "{sb:?} {expected}");
    assert!(t.rows[0].metrics[0].is_nan() && t.rows[0].status == PointStatus::Pending);
    assert!((t.rows[0].errors[0] - (sb[0] - 9.8e6) / 9.8e6).abs() < 1e-15);

    let bad = text.replace("body = \"target\"", "body = \"rock\"");
    let e = Study::from_toml_str(&bad, "derived.toml", &scenes()).unwrap_err();
    assert!(e.to_string().contains("`derived[0]`: point 0 (body.target.material.damage.m = 10.0, body.target.material.damage.k = 2.7e41): the scene has no body named `rock`"), "{e}");
}

/// `--resolution-scale` runs every point at that scale in place of the file's: the
/// points' scenes and summaries record it, the Slurm script passes it to every task, a
/// study directory made at one scale is refused at another, and a scale that is not a
/// positive number is bad input.
#[test]
fn a_resolution_scale_on_the_command_line_runs_every_point_at_it() {
    let work = fresh("study_resolution_scale");
    std::fs::create_dir_all(&work).unwrap();
    let scene = scenes().join("smoke_rz.toml");
    let file = work.join("one.study.toml");
    std::fs::write(
        &file,
        format!(
            "scene = {:?}\nend_time = 0.05e-6\nmetrics = [\"steps\"]\n\n[[parameter]]\n\
             path = \"solver.n_target\"\nvalues = [2.5]\n",
            scene.display().to_string()
        ),
    )
    .unwrap();
    let exe = env!("CARGO_BIN_EXE_sph-impact");
    let study = |dir: &Path, extra: &[&str]| {
        std::process::Command::new(exe)
            .args([
                "study",
                file.to_str().unwrap(),
                "--out",
                dir.to_str().unwrap(),
            ])
            .args(extra)
            .arg("--quiet")
            .output()
            .unwrap()
    };
    let dir = work.join("fine");
    let out = study(&dir, &["--resolution-scale", "2"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stored = std::fs::read_to_string(dir.join("points/0000/scene.toml")).unwrap();
    assert!(stored.contains("resolution_scale = 2.0,"), "{stored}");
    let summary: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("points/0000/run/summary.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(summary["resolution_scale"], 2.0);
    // The report says the scale the points ran at, beside the file's.
    let report = std::fs::read_to_string(dir.join("study.md")).unwrap();
    assert!(
        report.contains("[run at resolution scale 2.0, the file's 1.0]"),
        "{report}"
    );
    // Continued at the file's own scale: refused, not mixed.
    let again = study(&dir, &[]);
    assert_eq!(again.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&again.stderr).contains("another scene"),
        "{}",
        String::from_utf8_lossy(&again.stderr)
    );
    // The job array's tasks and its collection run at the scale given.
    let array = work.join("array");
    let out = study(&array, &["--resolution-scale", "2", "--emit", "slurm"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let script = std::fs::read_to_string(array.join("study.sbatch")).unwrap();
    assert_eq!(
        script.matches(" --resolution-scale 2.0 ").count(),
        2,
        "{script}"
    );
    // Not a positive number: bad input, said as such.
    for bad in ["0", "-1", "nan"] {
        // A negative number is the option's value, not an unknown flag.
        let out = study(&work.join("bad"), &["--resolution-scale", bad]);
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("--resolution-scale must be a positive number"),
            "{err}"
        );
    }
}

//! The `sph-impact` program's behaviour at its edges, run as a process: a closed standard
//! output, `--threads` out of range, `verify` with bad input or a resolution too large
//! for memory, names with control characters, and scene files without end.
//!
//! Exit codes: 0 ok, 1 a failed run, 2 bad input.

use sph_impact::cli::MAX_THREADS;
use sph_impact::input::MAX_INPUT_BYTES;
use sph_impact::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn exe() -> Command {
    Command::new(env!("CARGO_BIN_EXE_sph-impact"))
}

fn smoke_scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/smoke.toml")
}

/// A scratch directory of this test binary.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cli")
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `sph-impact args`; its standard error as text.
fn run(args: &[&str]) -> (Output, String) {
    let out = exe().args(args).output().unwrap();
    let err = String::from_utf8(out.stderr.clone()).unwrap();
    (out, err)
}

/// A bad-input failure: exit code 2 and one line `error: …` holding `needle`.
fn assert_bad_input(args: &[&str], needle: &str) -> String {
    let (out, err) = run(args);
    println!("{args:?}: {err}");
    assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: ") && err.contains(needle),
        "{args:?}: {err}"
    );
    err
}

/// `sph-impact materials | head -1`: every command that prints ends with exit code 0
/// when its standard output is a pipe nobody reads any more, without a panic.
#[test]
fn a_closed_pipe_is_a_clean_exit() {
    let smoke = smoke_scene();
    let smoke = smoke.to_str().unwrap();
    for args in [
        vec!["materials"],
        vec!["materials", "--json"],
        vec!["check", smoke],
        vec!["check", "--json", smoke],
        vec!["verify", "sod", "--resolution", "16"],
    ] {
        // The reading end is closed before the program starts: its first write fails
        // with EPIPE, whatever the timing.
        let (reader, writer) = std::io::pipe().unwrap();
        drop(reader);
        let out = exe()
            .args(&args)
            .stdout(writer)
            .stderr(Stdio::piped())
            .output()
            .unwrap();
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn threads_out_of_range_are_bad_input() {
    let smoke = smoke_scene();
    let smoke = smoke.to_str().unwrap();
    let limit = format!("1 to {MAX_THREADS}");
    for threads in ["0", "100000", &(MAX_THREADS + 1).to_string()] {
        assert_bad_input(&["check", smoke, "--threads", threads], &limit);
    }
    assert_bad_input(&["--threads", "100000", "materials"], &limit);
    let (out, err) = run(&["check", smoke, "--threads", "1"]);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let (out, _) = run(&["--help"]);
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(help.contains(&format!("Worker threads, {limit}")), "{help}");
}

#[test]
fn verify_refuses_bad_input_with_exit_code_2() {
    // Too large for memory: refused at once, naming the largest resolution accepted.
    let t = std::time::Instant::now();
    assert_bad_input(
        &["verify", "sod", "--resolution", "8000000000"],
        "the largest resolution accepted is 49468592",
    );
    assert_bad_input(
        &["verify", "sedov-3d", "--resolution", "100000"],
        "the largest resolution accepted is ",
    );
    assert_bad_input(
        &[
            "verify",
            "taylor",
            "--geometry",
            "rz",
            "--resolution",
            "1000000",
        ],
        "above the limit of 6.40e10 bytes",
    );
    assert!(t.elapsed().as_secs_f64() < 30.0);
    assert_bad_input(&["verify", "sod", "--resolution", "2"], "at least 4");
    assert_bad_input(&["verify", "sod", "--resolution", "12"], "multiple of 8");
    assert_bad_input(
        &["verify", "sod", "--scheme", "{bogus"],
        "--scheme: not JSON",
    );
    assert_bad_input(&["verify", "sod", "--scheme", r#"{"cfl": -1}"#], "cfl");
    assert_bad_input(
        &[
            "verify",
            "sedov-2d",
            "--geometry",
            "plane",
            "--deposit",
            "kernel",
        ],
        "--deposit is for the Sedov problems",
    );
    assert_bad_input(
        &["verify", "sod", "--geometry", "rz"],
        "no axisymmetric (RZ) form",
    );
}

/// A scene whose second body has the name `name` (TOML basic-string escapes allowed).
fn scene_named(name: &str, material: &str) -> String {
    format!(
        r#"end_time = 1.0e-6

[[body]]
name = "projectile"
material = "aluminium-2024-jc"
shape = {{ kind = "sphere", centre = [0.0, 0.0, 2.0e-3], radius = 1.5e-3 }}
placement = {{ kind = "lattice", spacing = 0.5e-3 }}
velocity = [0.0, 0.0, -3900.0]

[[body]]
name = "{name}"
material = {material}
shape = {{ kind = "cuboid", min = [-4.0e-3, -4.0e-3, -4.0e-3], max = [4.0e-3, 4.0e-3, 0.0] }}
placement = {{ kind = "lattice", spacing = 0.5e-3 }}
"#
    )
}

/// Body and material names with control characters are refused at reading, naming the
/// key; no message carries the raw character.
#[test]
fn names_with_control_characters_are_refused() {
    let text = scene_named(r"red\u001b[31m target", r#""basalt-study""#);
    let e = Scene::from_toml_str(&text, "scene.toml").unwrap_err();
    assert_eq!(e.key.as_deref(), Some("body[1].name"));
    let m = e.to_string();
    assert!(
        m.starts_with(r#"scene.toml:11:8: body "red\u{1b}[31m target": `name`: "#)
            && m.contains("must not contain control characters (found U+001B)"),
        "{m}"
    );
    // An inline material's own name.
    let text = scene_named(
        "target",
        r#"{ base = "basalt-study", name = "basalt\u0007" }"#,
    );
    let m = Scene::from_toml_str(&text, "scene.toml")
        .unwrap_err()
        .to_string();
    assert!(
        m.contains("`material.name`") && m.contains(r"basalt\u{7}") && !m.contains('\u{7}'),
        "{m}"
    );
    // Through the program: exit code 2, the character escaped on the terminal.
    let path = scratch("names").join("escape.toml");
    std::fs::write(&path, scene_named(r"\u001b[2Jtarget", r#""basalt-study""#)).unwrap();
    let err = assert_bad_input(&["check", path.to_str().unwrap()], "`name`");
    assert!(
        !err.contains('\u{1b}') && err.contains(r"\u{1b}[2Jtarget"),
        "{err}"
    );
    // A key with one (unknown keys are quoted in the parser's message).
    std::fs::write(
        &path,
        scene_named("target", r#""basalt-study""#) + "\"\\u001b[2J\" = 1\n",
    )
    .unwrap();
    let err = assert_bad_input(&["check", path.to_str().unwrap()], "unknown key");
    assert!(!err.contains('\u{1b}'), "{err}");
}

/// A scene without end (`/dev/zero`) or larger than the limit is refused after reading
/// at most the limit.
#[test]
fn scene_files_are_read_up_to_the_limit() {
    let limit = MAX_INPUT_BYTES.to_string();
    #[cfg(unix)]
    {
        let t = std::time::Instant::now();
        assert_bad_input(&["check", "/dev/zero"], &limit);
        assert!(t.elapsed().as_secs_f64() < 30.0);
    }
    // A sparse file one byte over: refused from its size.
    let big = scratch("large").join("big.toml");
    let file = std::fs::File::create(&big).unwrap();
    file.set_len(MAX_INPUT_BYTES + 1).unwrap();
    drop(file);
    assert_bad_input(&["check", big.to_str().unwrap()], &limit);
    assert_bad_input(&["run", big.to_str().unwrap()], &limit);
    std::fs::remove_file(&big).unwrap();
    let e = sph_impact::materials::MaterialSpec::from_toml_file("/dev/zero").unwrap_err();
    assert!(e.to_string().contains(&limit), "{e}");
}

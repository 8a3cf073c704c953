//! The bad-input corpus in `tests/fuzz/` (written by `tests/fuzz/generate.py`; see
//! docs/scenes.md, "Bad input (fuzz corpus)"):
//!
//! * every scene of `tests/fuzz/scenes/` must be refused, without a panic, within
//!   [`SCENE_LIMIT`], by `Scene::from_toml_file` or else by `Scene::preflight` (what
//!   `sph-impact run` validates before stepping), with one line holding the text of its
//!   `# expect:` line, and `Scene::check_report` (what `sph-impact check` runs) must
//!   refuse it with the same line;
//! * every command line of `tests/fuzz/cli.txt` must end, within [`CLI_LIMIT`], with its
//!   exit code, without a panic, and a failure with one line `error: …` on standard
//!   error (clap's own usage errors: `error: …` first, then its usage lines), leaving
//!   the scene it was given and the scratch directory as they were.
//!
//! Cases listed in `tests/fuzz/known_gaps.txt` are ones the code does not yet refuse
//! cleanly: they are run and counted like the others, and the test fails if one of them
//! is refused cleanly (then it is to be taken off the list) or if any other case is not.
//!
//! `cargo test -p sph-impact --test fuzz -- --nocapture` prints the table of outcomes and
//! every case that is not a clean error.

use sph_impact::scene::Scene;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// How long one scene's validation may take before it counts as a hang.
const SCENE_LIMIT: Duration = Duration::from_secs(10);

/// How long one command line may run before it is killed and counts as a hang.
const CLI_LIMIT: Duration = Duration::from_secs(60);

/// What a case came to.
#[derive(Clone, Debug, PartialEq)]
enum Outcome {
    /// Refused as it should be.
    Clean,
    /// A panic (or, for a process, death by a signal).
    Panic(String),
    /// Still running at the time limit.
    Hang,
    /// Accepted (a scene that validates, a command that exits with 0).
    Accepted,
    /// Refused, but not as it should be: another exit code, a message of several lines,
    /// without the expected text, a disagreement between `check` and `run`, or files
    /// left behind.
    Other(String),
}

impl Outcome {
    fn column(&self) -> usize {
        match self {
            Outcome::Clean => 0,
            Outcome::Panic(_) => 1,
            Outcome::Hang => 2,
            Outcome::Accepted => 3,
            Outcome::Other(_) => 4,
        }
    }
}

fn fuzz_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz")
}

fn smoke_scene() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/smoke.toml")
}

/// The known gaps: `scene NAME` (the file name without its number and `.toml`) and
/// `cli ARGS` (the JSON array exactly as in cli.txt).
fn known_gaps() -> (Vec<String>, Vec<String>) {
    let text = std::fs::read_to_string(fuzz_dir().join("known_gaps.txt")).unwrap();
    let (mut scenes, mut cli) = (Vec::new(), Vec::new());
    for line in text.lines() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        if let Some(name) = line.strip_prefix("scene ") {
            scenes.push(name.trim().to_owned());
        } else if let Some(args) = line.strip_prefix("cli ") {
            cli.push(args.trim().to_owned());
        } else {
            panic!("known_gaps.txt: `{line}` is neither `scene NAME` nor `cli ARGS`");
        }
    }
    (scenes, cli)
}

/// What is wrong with `message` as a one-line error, if anything.
fn one_line_problem(message: &str) -> Option<String> {
    if message.contains('\n') || message.contains('\r') {
        return Some("the message has more than one line".into());
    }
    if message.chars().any(char::is_control) {
        return Some("the message holds a control character".into());
    }
    None
}

/// What reading and validating the scene at `path` gives: `Ok(None)` accepted,
/// `Ok(Some(message))` refused (by the reader, or by preflight and check alike),
/// `Err(why)` refused differently by preflight and check.
fn validate(path: &Path) -> Result<Option<String>, String> {
    let scene = match Scene::from_toml_file(path) {
        Ok(scene) => scene,
        Err(e) => return Ok(Some(e.to_string())),
    };
    let preflight = scene
        .preflight(1.0, None)
        .map(|_| ())
        .map_err(|e| e.to_string());
    let check = scene
        .check_report(1.0, 1, None)
        .map(|_| ())
        .map_err(|e| e.to_string());
    match (preflight, check) {
        (Ok(()), Ok(())) => Ok(None),
        (Err(p), Err(c)) if p == c => Ok(Some(p)),
        (p, c) => Err(format!("preflight gave {p:?}, check_report {c:?}")),
    }
}

/// One scene case, on its own thread so that a hang is seen.
fn scene_case(path: &Path, expect: &str) -> Outcome {
    let (tx, rx) = mpsc::channel();
    let p = path.to_owned();
    std::thread::spawn(move || {
        let result = std::panic::catch_unwind(|| validate(&p));
        let _ = tx.send(result);
    });
    let result = match rx.recv_timeout(SCENE_LIMIT) {
        Ok(Ok(result)) => result,
        Ok(Err(payload)) => {
            let what = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                .unwrap_or_default();
            return Outcome::Panic(what);
        }
        // The thread is left running; the process ends with the test.
        Err(_) => return Outcome::Hang,
    };
    let message = match result {
        Ok(None) => return Outcome::Accepted,
        Ok(Some(m)) => m.replace(&path.display().to_string(), "scene.toml"),
        Err(why) => return Outcome::Other(why),
    };
    if let Some(why) = one_line_problem(&message) {
        return Outcome::Other(format!("{why}: {message}"));
    }
    if !message.contains(expect) {
        return Outcome::Other(format!("expected `{expect}` in: {message}"));
    }
    Outcome::Clean
}

/// The scene cases: (short name, path, expected text).
fn scene_cases() -> Vec<(String, PathBuf, String)> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(fuzz_dir().join("scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths
        .into_iter()
        .map(|path| {
            let bytes = std::fs::read(&path).unwrap();
            let first = bytes.split(|&b| b == b'\n').next().unwrap();
            let first = std::str::from_utf8(first).unwrap();
            let expect = first
                .strip_prefix("# expect: ")
                .unwrap_or_else(|| panic!("{}: no `# expect:` first line", path.display()))
                .to_owned();
            let stem = path.file_stem().unwrap().to_str().unwrap();
            let name = stem.split_once('-').map_or(stem, |(_, n)| n).to_owned();
            (name, path, expect)
        })
        .collect()
}

/// The command lines: (expected exit code, JSON text of the arguments, arguments).
fn cli_cases() -> Vec<(i32, String, Vec<String>)> {
    let text = std::fs::read_to_string(fuzz_dir().join("cli.txt")).unwrap();
    text.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let (code, args) = l
                .split_once('\t')
                .unwrap_or_else(|| panic!("cli.txt: no tab in `{l}`"));
            let parsed: Vec<String> = serde_json::from_str(args)
                .unwrap_or_else(|e| panic!("cli.txt: `{args}` is not a JSON array: {e}"));
            (code.parse().unwrap(), args.to_owned(), parsed)
        })
        .collect()
}

/// Runs one command line in the fresh scratch directory `root`.
fn cli_case(root: &Path, code: i32, args: &[String]) -> Outcome {
    if root.exists() {
        std::fs::remove_dir_all(root).unwrap();
    }
    let dir = root.join("dir");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = root.join("smoke.toml");
    let original = std::fs::read(smoke_scene()).unwrap();
    std::fs::write(&scene, &original).unwrap();
    let (scene_text, dir_text) = (scene.display().to_string(), dir.display().to_string());
    let args: Vec<String> = args
        .iter()
        .map(|a| {
            a.replace("{scene}", &scene_text)
                .replace("{dir}", &dir_text)
        })
        .collect();
    let (out_path, err_path) = (root.join("stdout"), root.join("stderr"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_sph-impact"))
        .args(&args)
        .current_dir(root)
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out_path).unwrap())
        .stderr(std::fs::File::create(&err_path).unwrap())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > CLI_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return Outcome::Hang;
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let err = String::from_utf8_lossy(&std::fs::read(&err_path).unwrap())
        .replace(&scene_text, "{scene}")
        .replace(&dir_text, "{dir}");
    let Some(got) = status.code() else {
        return Outcome::Panic(format!("killed by a signal ({status}): {err}"));
    };
    if got == 101 || err.contains("panicked at") {
        return Outcome::Panic(err);
    }
    if got == 0 && code != 0 {
        return Outcome::Accepted;
    }
    if got != code {
        return Outcome::Other(format!("exit code {got}, not {code}: {err}"));
    }
    let lines: Vec<&str> = err.lines().collect();
    let clap_usage = lines.len() > 1
        && lines
            .last()
            .is_some_and(|l| l.starts_with("For more information, try '--help'"));
    if !lines.first().is_some_and(|l| l.starts_with("error: ")) {
        return Outcome::Other(format!(
            "standard error does not start with `error: `: {err}"
        ));
    }
    if lines.len() != 1 && !clap_usage {
        return Outcome::Other(format!("{} lines on standard error: {err}", lines.len()));
    }
    if err.chars().any(|c| c.is_control() && c != '\n') {
        return Outcome::Other(format!("a control character on standard error: {err:?}"));
    }
    if std::fs::read(&scene).ok().as_deref() != Some(&original[..]) {
        return Outcome::Other("the scene file was changed".into());
    }
    let left: Vec<String> = std::fs::read_dir(&dir)
        .map(|d| {
            d.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_else(|_| vec!["(the directory is gone)".into()]);
    if !left.is_empty() {
        return Outcome::Other(format!("left {left:?} in the scratch directory: {err}"));
    }
    Outcome::Clean
}

/// Counts per column: clean, panics, hangs, silent acceptances, other.
#[derive(Default)]
struct Tally {
    inputs: usize,
    columns: [usize; 5],
}

impl Tally {
    fn add(&mut self, o: &Outcome) {
        self.inputs += 1;
        self.columns[o.column()] += 1;
    }

    fn row(&self, label: &str) -> String {
        let c = &self.columns;
        format!(
            "| {label} | {} | {} | {} | {} | {} | {} |",
            self.inputs, c[0], c[1], c[2], c[3], c[4]
        )
    }
}

#[test]
fn the_fuzz_corpus_is_refused_cleanly() {
    let t0 = Instant::now();
    let (known_scenes, known_cli) = known_gaps();
    let mut failures = Vec::new();
    let mut gaps: BTreeMap<String, Outcome> = BTreeMap::new();

    let scenes = scene_cases();
    assert!(scenes.len() >= 300, "{} scene cases", scenes.len());
    for name in &known_scenes {
        assert!(
            scenes.iter().any(|(n, _, _)| n == name),
            "known_gaps.txt: no scene case `{name}`"
        );
    }
    let mut scene_tally = Tally::default();
    for (name, path, expect) in &scenes {
        let outcome = scene_case(path, expect);
        scene_tally.add(&outcome);
        let label = format!("scene {name}");
        let known = known_scenes.contains(name);
        match (&outcome, known) {
            (Outcome::Clean, false) => {}
            (Outcome::Clean, true) => failures.push(format!(
                "{label}: now refused cleanly: take it off known_gaps.txt"
            )),
            (o, true) => {
                gaps.insert(label, o.clone());
            }
            (o, false) => failures.push(format!("{label} ({}): {o:?}", path.display())),
        }
    }
    let scene_time = t0.elapsed();

    let t1 = Instant::now();
    let cli = cli_cases();
    assert!(cli.len() >= 40, "{} command lines", cli.len());
    for args in &known_cli {
        assert!(
            cli.iter().any(|(_, a, _)| a == args),
            "known_gaps.txt: no command line {args}"
        );
    }
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-cli");
    let mut cli_tally = Tally::default();
    for (i, (code, text, args)) in cli.iter().enumerate() {
        let outcome = cli_case(&scratch.join(format!("{i:03}")), *code, args);
        cli_tally.add(&outcome);
        let label = format!("cli {text}");
        let known = known_cli.contains(text);
        match (&outcome, known) {
            (Outcome::Clean, false) => {}
            (Outcome::Clean, true) => failures.push(format!(
                "{label}: now fails cleanly: take it off known_gaps.txt"
            )),
            (o, true) => {
                gaps.insert(label, o.clone());
            }
            (o, false) => failures.push(format!("{label}: {o:?}")),
        }
    }
    let cli_time = t1.elapsed();

    let mut total = Tally::default();
    for t in [&scene_tally, &cli_tally] {
        total.inputs += t.inputs;
        for (a, b) in total.columns.iter_mut().zip(t.columns) {
            *a += b;
        }
    }
    println!(
        "| inputs | tried | clean errors | panics | hangs | silent acceptances | other |\n\
         |---|---|---|---|---|---|---|\n{}\n{}\n{}",
        scene_tally.row("bad scenes"),
        cli_tally.row("bad command lines"),
        total.row("total")
    );
    println!(
        "known gaps (tests/fuzz/known_gaps.txt), counted above: {} scenes, {} command lines",
        known_scenes.len(),
        known_cli.len()
    );
    for (label, outcome) in &gaps {
        println!("  known gap: {label}: {outcome:?}");
    }
    println!(
        "wall time: scenes {:.1} s, command lines {:.1} s",
        scene_time.as_secs_f64(),
        cli_time.as_secs_f64()
    );
    assert!(
        failures.is_empty(),
        "{} case(s) not as expected:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

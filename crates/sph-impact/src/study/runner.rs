//! Running a study's points side by side, resumably.
//!
//! The study directory holds one directory per point, `points/NNNN/`, with
//!
//! - `scene.toml`: the point's scene (the base scene with its values set),
//! - `run/`: its run directory (docs/scenes.md, "Outputs of `run`"),
//! - `result.json`: written once the run has ended, `{"status": "done"}` or
//!   `{"status": "failed", "error": …}`, with its wall time.
//!
//! A point with a `result.json` is finished and never runs again (a failed one does with
//! `retry_failed`); one without it runs, from its newest checkpoint when a stop request
//! left one. The metrics are read from each point's `summary.json` when the table is
//! made, so a metric added to the study file later needs no run. A point whose stored
//! scene differs from the study's (the study file changed) is refused rather than mixed
//! into the table.

use crate::run::{RunOptions, StopFlag, checkpoints};
use crate::scene::Scene;
use crate::study::axis::Point;
use crate::study::error::StudyError;
use crate::study::study::{Study, describe};
use crate::study::table::{PointStatus, StudyTable};
use serde::{Deserialize, Serialize};
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

/// How a study runs.
#[derive(Clone, Debug)]
pub struct StudyOptions {
    /// Points run at a time (each with the study's `threads_per_run`).
    pub jobs: usize,
    /// Run again the points that failed before.
    pub retry_failed: bool,
    /// Run at most this many points this time, then stop (a study cut into pieces, e.g.
    /// within a batch job's time limit).
    pub max_points: Option<usize>,
    /// Run only this point (a job-array task: study::slurm), and leave the table to a
    /// later call (`--collect`), since the tasks run side by side.
    pub only: Option<usize>,
    /// No progress lines.
    pub quiet: bool,
    /// Raised to stop: the running points stop after their current step and write a
    /// checkpoint, which the next call continues from.
    pub stop: StopFlag,
}

impl Default for StudyOptions {
    fn default() -> Self {
        Self {
            jobs: 1,
            retry_failed: false,
            max_points: None,
            only: None,
            quiet: false,
            stop: StopFlag::new(),
        }
    }
}

/// What `result.json` holds.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub(crate) struct PointRecord {
    pub status: PointStatus,
    #[serde(default)]
    pub error: Option<String>,
    pub wall_time_s: f64,
}

/// The directory of point `index`.
pub fn point_dir(study_dir: &Path, index: usize) -> PathBuf {
    study_dir.join("points").join(format!("{index:04}"))
}

/// Runs the points of `study` that are not finished into `dir` (created if needed), then
/// writes the table (`study.csv`, `study.json`, `study.md`) of every point, finished or
/// not, and returns it.
pub fn run_study(
    study: &Study,
    dir: &Path,
    options: &StudyOptions,
) -> Result<StudyTable, StudyError> {
    if !(1..=crate::cli::MAX_THREADS).contains(&options.jobs) {
        return Err(StudyError::bad(format!(
            "--jobs must be 1 to {}, not {}",
            crate::cli::MAX_THREADS,
            options.jobs
        )));
    }
    std::fs::create_dir_all(dir).map_err(|e| StudyError::io(dir, e))?;
    let points = study.points();
    if let Some(k) = options.only
        && k >= points.len()
    {
        return Err(StudyError::bad(format!(
            "the study has {} points (0 to {}): no point {k}",
            points.len(),
            points.len() - 1
        )));
    }
    let mut pending = Vec::new();
    let mut before = Before::default();
    for point in &points {
        if options.only.is_some_and(|k| k != point.index) {
            continue;
        }
        let scene = stored_scene(study, point)?;
        let pdir = point_dir(dir, point.index);
        check_stored_scene(&pdir, &scene, point)?;
        match read_record(&pdir)? {
            Some(r) if r.status == PointStatus::Done => before.done += 1,
            Some(r) if r.status == PointStatus::Failed && !options.retry_failed => {
                before.failed += 1
            }
            _ => pending.push((point.clone(), scene)),
        }
    }
    if let Some(n) = options.max_points {
        before.later = pending.len().saturating_sub(n);
        pending.truncate(n);
    }
    if !options.quiet {
        eprintln!("{}", before.announce(pending.len(), points.len()));
    }
    let progress = Progress::new(options.quiet, pending.len(), points.len());
    let next = AtomicUsize::new(0);
    let first_error: Mutex<Option<StudyError>> = Mutex::new(None);
    let workers = options.jobs.min(pending.len());
    std::thread::scope(|s| {
        for _ in 0..workers {
            s.spawn(|| {
                loop {
                    if options.stop.requested() || first_error.lock().unwrap().is_some() {
                        return;
                    }
                    let k = next.fetch_add(1, Ordering::SeqCst);
                    let Some((point, scene)) = pending.get(k) else {
                        return;
                    };
                    progress.started(point);
                    match run_point(study, dir, point, scene, options) {
                        Ok(outcome) => progress.ended(point, &outcome),
                        Err(e) => {
                            first_error.lock().unwrap().get_or_insert(e);
                            return;
                        }
                    }
                }
            });
        }
    });
    if let Some(e) = first_error.into_inner().unwrap() {
        return Err(e);
    }
    let table = StudyTable::collect(study, dir)?;
    if options.only.is_none() {
        table.write(dir)?;
    }
    Ok(table)
}

/// How one point's run ended.
pub(crate) enum Outcome {
    Done(f64),
    Failed(String),
    Stopped,
}

/// Runs one point and records how it ended. `Err` only when the study directory cannot be
/// written: a run that fails is recorded in `result.json` and the study goes on.
pub(crate) fn run_point(
    study: &Study,
    dir: &Path,
    point: &Point,
    scene_text: &str,
    options: &StudyOptions,
) -> Result<Outcome, StudyError> {
    let pdir = point_dir(dir, point.index);
    std::fs::create_dir_all(&pdir).map_err(|e| StudyError::io(&pdir, e))?;
    let scene_file = pdir.join("scene.toml");
    write_whole(&scene_file, scene_text.as_bytes())?;
    let run_dir = pdir.join("run");
    let resume = !checkpoints(&run_dir).is_empty();
    let run_options = RunOptions {
        threads: Some(study.threads_per_run),
        end_time: study.end_time,
        resolution_scale: study.resolution_scale,
        quiet: true,
        resume,
        overwrite: !resume,
        stop: options.stop.clone(),
        ..RunOptions::default()
    };
    let wall = Instant::now();
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let scene = Scene::from_toml_str(scene_text, &scene_file.display().to_string())
            .map_err(|e| e.to_string())?;
        crate::run::run(&scene, &run_dir, &run_options).map_err(|e| {
            if e.is_interrupted() {
                String::new()
            } else {
                e.to_string()
            }
        })
    }));
    let seconds = wall.elapsed().as_secs_f64();
    let outcome = match result {
        Ok(Ok(summary)) if summary.complete => Outcome::Done(seconds),
        Ok(Ok(_)) => Outcome::Stopped,
        Ok(Err(e)) if e.is_empty() => Outcome::Stopped,
        Ok(Err(e)) => Outcome::Failed(e),
        Err(panic) => Outcome::Failed(format!("the run panicked: {}", panic_text(&panic))),
    };
    let record = match &outcome {
        Outcome::Done(_) => PointRecord {
            status: PointStatus::Done,
            error: None,
            wall_time_s: seconds,
        },
        Outcome::Failed(e) => PointRecord {
            status: PointStatus::Failed,
            error: Some(e.clone()),
            wall_time_s: seconds,
        },
        Outcome::Stopped => return Ok(outcome),
    };
    let text =
        serde_json::to_string_pretty(&record).map_err(|e| StudyError::failed(e.to_string()))?;
    write_whole(&pdir.join("result.json"), text.as_bytes())?;
    Ok(outcome)
}

fn panic_text(panic: &Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = panic.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = panic.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".into()
    }
}

/// `result.json` of a point directory, if any.
pub(crate) fn read_record(pdir: &Path) -> Result<Option<PointRecord>, StudyError> {
    let path = pdir.join("result.json");
    match std::fs::read_to_string(&path) {
        Ok(text) => serde_json::from_str(&text)
            .map(Some)
            .map_err(|e| StudyError::failed(format!("{}: {e}", path.display()))),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(StudyError::io(&path, e)),
    }
}

/// The `scene.toml` of a point: its scene, headed by comments that say which point it is
/// and the run options it runs with, so that a study whose resolution or end time changed
/// does not continue in the old directory either.
pub(crate) fn stored_scene(study: &Study, point: &Point) -> Result<String, StudyError> {
    let end = study
        .end_time
        .map_or_else(|| "the scene's".to_owned(), |t| format!("{t:?} s"));
    Ok(format!(
        "# Point {} of a study: {}\n# Run with resolution_scale = {:?}, end_time = {end}.\n{}",
        point.index,
        describe(point),
        study.resolution_scale,
        study.point_scene(point)?
    ))
}

/// A point directory that holds a scene other than the study's for that point belongs to
/// another study (or to this one before its file changed): refused.
pub(crate) fn check_stored_scene(
    pdir: &Path,
    scene: &str,
    point: &Point,
) -> Result<(), StudyError> {
    match std::fs::read_to_string(pdir.join("scene.toml")) {
        Ok(stored) if stored != scene => Err(StudyError::bad(format!(
            "{}: point {} ({}) was run with another scene than the study gives it now \
             (the study file or its scene changed): use a new study directory",
            pdir.display(),
            point.index,
            describe(point)
        ))),
        _ => Ok(()),
    }
}

/// Writes `path` whole, through the run's atomic writer (`NAME.part` and a rename), so a
/// killed study leaves the old file or none.
pub(crate) fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), StudyError> {
    crate::run::atomic::write_bytes(path, bytes).map_err(|e| StudyError::failed(e.to_string()))
}

/// What a study's points were when it started: finished by an earlier run, failed in
/// one (and not retried), left for a later run (`--max-points`, `--collect`).
#[derive(Clone, Copy, Debug, Default)]
struct Before {
    done: usize,
    failed: usize,
    later: usize,
}

impl Before {
    /// The line that opens the study's progress: how many of its `total` points it runs
    /// now (`to_run`) and why the others are not run.
    fn announce(&self, to_run: usize, total: usize) -> String {
        let mut why = vec![format!("{} finished before", self.done)];
        if self.failed > 0 {
            why.push(format!(
                "{} failed before, run again with --retry-failed",
                self.failed
            ));
        }
        if self.later > 0 {
            why.push(format!("{} left for a later run", self.later));
        }
        let others = total - to_run - self.done - self.failed - self.later;
        if others > 0 {
            why.push(format!("{others} not this task's (--point)"));
        }
        format!(
            "study: {to_run} of {total} points to run ({})",
            why.join(", ")
        )
    }
}

/// The study's progress on standard error: a bar over its points (ended of those to run,
/// failed, running, the time left from the time per point finished so far). On
/// a terminal the bar is redrawn in place and a failed point's error is printed above it;
/// to a file (a log) each point's start and end is a line with the bar.
struct Progress {
    quiet: bool,
    terminal: bool,
    start: Instant,
    to_run: usize,
    total: usize,
    /// (ended, failed, running).
    state: Mutex<(usize, usize, usize)>,
}

impl Progress {
    fn new(quiet: bool, to_run: usize, total: usize) -> Self {
        Self {
            quiet,
            terminal: std::io::stderr().is_terminal(),
            start: Instant::now(),
            to_run,
            total,
            state: Mutex::new((0, 0, 0)),
        }
    }

    /// The bar and its counts. The time left is estimated from the points that finished:
    /// a point that failed early says nothing of how long the others take, so until one
    /// has finished the estimate is "?".
    fn line(&self, (ended, failed, running): (usize, usize, usize)) -> String {
        let done = ended - failed;
        let left = if done > 0 {
            let elapsed = self.start.elapsed().as_secs_f64();
            let left = (elapsed / done as f64) * (self.to_run - ended) as f64;
            crate::scene::estimate_human_seconds(left)
        } else {
            "?".into()
        };
        format!(
            "study: {} {ended} of {} points ended ({failed} failed), {running} running, about {left} left",
            crate::run::progress::bar(ended as f64 / self.to_run.max(1) as f64),
            self.to_run,
        )
    }

    /// Prints `event` (a line of its own on a file, above the bar on a terminal; none
    /// when empty) and the bar.
    fn show(&self, event: &str, state: (usize, usize, usize)) {
        let line = self.line(state);
        let mut err = std::io::stderr().lock();
        if self.terminal {
            if !event.is_empty() {
                let _ = writeln!(err, "\r{event}\x1b[K");
            }
            let _ = write!(err, "\r{line}\x1b[K");
            if state.0 == self.to_run {
                let _ = writeln!(err);
            }
        } else {
            if !event.is_empty() {
                let _ = writeln!(err, "{event}");
            }
            let _ = writeln!(err, "{line}");
        }
        let _ = err.flush();
    }

    fn started(&self, point: &Point) {
        let mut s = self.state.lock().unwrap();
        s.2 += 1;
        if self.quiet {
            return;
        }
        // A point starting is news in a log, not on a terminal, where the bar counts it.
        let event = if self.terminal {
            String::new()
        } else {
            format!(
                "study: point {} of {} started: {}",
                point.index,
                self.total,
                describe(point)
            )
        };
        self.show(&event, *s);
    }

    fn ended(&self, point: &Point, outcome: &Outcome) {
        let mut s = self.state.lock().unwrap();
        s.0 += 1;
        s.2 -= 1;
        if matches!(outcome, Outcome::Failed(_)) {
            s.1 += 1;
        }
        if self.quiet {
            return;
        }
        let event = match outcome {
            Outcome::Failed(e) => format!("study: point {} FAILED: {e}", point.index),
            Outcome::Stopped => format!(
                "study: point {} stopped (resumes from its checkpoint)",
                point.index
            ),
            Outcome::Done(t) if !self.terminal => format!(
                "study: point {} done in {}",
                point.index,
                crate::scene::estimate_human_seconds(*t)
            ),
            Outcome::Done(_) => String::new(),
        };
        self.show(&event, *s);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_opening_line_says_why_points_are_not_run() {
        let fresh = Before::default();
        assert_eq!(
            fresh.announce(3, 3),
            "study: 3 of 3 points to run (0 finished before)"
        );
        // `--max-points 0` on a fresh study (`--collect`): nothing finished.
        assert_eq!(
            Before { later: 3, ..fresh }.announce(0, 3),
            "study: 0 of 3 points to run (0 finished before, 3 left for a later run)"
        );
        assert_eq!(
            Before {
                done: 4,
                failed: 1,
                later: 2
            }
            .announce(3, 10),
            "study: 3 of 10 points to run (4 finished before, 1 failed before, run again with \
             --retry-failed, 2 left for a later run)"
        );
        // `--point 2` of five, not run before.
        assert_eq!(
            fresh.announce(1, 5),
            "study: 1 of 5 points to run (0 finished before, 4 not this task's (--point))"
        );
    }

    #[test]
    fn the_study_bar_counts_points_ended_failed_and_running() {
        let p = Progress::new(true, 8, 10);
        assert_eq!(
            p.line((0, 0, 2)),
            "study: [------------------------] 0 of 8 points ended (0 failed), 2 running, about ? left"
        );
        let line = p.line((2, 1, 2));
        assert!(
            line.starts_with("study: [######------------------] 2 of 8 points ended (1 failed), 2 running, about "),
            "{line}"
        );
        assert!(
            p.line((8, 1, 0))
                .contains("[########################] 8 of 8")
        );
        // Only failed points ended: no estimate from them.
        assert!(p.line((3, 3, 2)).ends_with("2 running, about ? left"));
    }
}

//! The inverse search (`sph-impact fit`, paper §3.7): free parameters within bounds, found
//! by Nelder–Mead (argmin) to bring chosen metrics of the run to their targets, under
//! constraints on derived metrics (the static strength of the Brazilian disc within ±11 %
//! of the measured 9.8 MPa, as the study required).
//!
//! The search runs in the unit cube: each free parameter maps [0, 1] onto its bounds,
//! linearly or logarithmically. The objective is Σ w (y − t)²/t² over the targets, or a
//! function of the target metrics written in Rust ([`run_fit_with`]). A point
//! outside the bounds or against a constraint is not run: its objective is a penalty that
//! grows with the violation, so the simplex turns back. A run that fails counts as a large
//! objective and is recorded.
//!
//! A fit may span several scenes, its **cases** (the same impact at several speeds): the
//! free parameters are set in each, a target names the case whose run it is read from,
//! and each point of the search runs every fitted case. A case marked `hold_out` is not
//! fitted: it runs once, at the best point, and its targets are compared, not sought
//! (the study's Table 2 fitted at 3.9 km/s and checked at 2.3 and 3.47 km/s).
//!
//! Every run is a point of the fit's directory (`search/points/NNNN/`, as a study's; a
//! case's under `search/cases/NAME/points/NNNN/`), in the order the search asks for them. The search is deterministic, so a stopped or killed
//! fit run again replays it: the runs already done are read back and the search goes on
//! from there; a larger `budget` continues a finished one. After the search, one run per
//! free parameter a small step from the best point (`sensitivity/run-BEST/points/K/`) gives the
//! local sensitivity of each target metric to each parameter; then the hold-out cases run
//! at the best point (`hold_out/run-BEST/cases/NAME/points/0000/`).

use crate::scene::Scene;
use crate::study::axis::{Point, Spacing};
use crate::study::derived::Derived;
use crate::study::error::StudyError;
use crate::study::runner::{
    Outcome, check_stored_scene, point_dir, read_record, run_point, stored_scene,
};
use crate::study::study::{
    RunSettings, Study, base_study, locate, read_file, read_path, scene_message,
};
use crate::study::table::PointStatus;
use crate::study::{StudyOptions, metric};
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The objective of a point that is not run (outside the bounds, against a constraint):
/// above any objective of a run, growing with the violation.
const PENALTY: f64 = 1.0e6;

/// The step of the sensitivity runs, as a share of each parameter's (scaled) range.
const SENSITIVITY_STEP: f64 = 0.05;

/// Two points of the search closer than this in every unit coordinate (a share of each
/// parameter's scaled range) are the same run. Nelder–Mead's reflections come back to a
/// point it has run only to round-off (through the logarithm of a log-scale parameter,
/// 9.8e6 returns as 9.799999999999996e6); no run of a simulation tells such points apart.
const SAME_POINT: f64 = 1.0e-9;

/// Whether unit coordinates `a` and `b` are the same point of the search ([`SAME_POINT`]).
fn same_point(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= SAME_POINT)
}

/// A free parameter: a scene path (study::scene_path) and its bounds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Free {
    /// The scene path.
    pub path: String,
    /// Lower bound.
    pub min: f64,
    /// Upper bound (above `min`).
    pub max: f64,
    /// Linear (default) or log (both bounds positive: a Weibull k).
    #[serde(default)]
    pub scale: Spacing,
    /// Where the search starts (default: the middle of the range, geometric for log).
    #[serde(default)]
    pub start: Option<f64>,
}

impl Free {
    /// The value at unit coordinate `u` (0 at `min`, 1 at `max`; the start as written at
    /// its own coordinate, which the round trip through the logarithm would perturb).
    pub fn value(&self, u: f64) -> f64 {
        if let Some(s) = self.start
            && self.unit(s) == u
        {
            return s;
        }
        match self.scale {
            Spacing::Linear => self.min + (self.max - self.min) * u,
            Spacing::Log => self.min * (self.max / self.min).powf(u),
        }
    }

    /// The unit coordinate of `value`.
    pub fn unit(&self, value: f64) -> f64 {
        match self.scale {
            Spacing::Linear => (value - self.min) / (self.max - self.min),
            Spacing::Log => (value / self.min).ln() / (self.max / self.min).ln(),
        }
    }
}

/// A target: a metric of the run (a key of summary.json), its value and weight.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Target {
    /// The metric.
    pub metric: String,
    /// The value sought (non-zero).
    pub value: f64,
    /// Weight in the objective (default 1; not used for a hold-out case's target).
    #[serde(default = "one")]
    pub weight: f64,
    /// The [`Case`] whose run the metric is read from, by name; `None` (the default):
    /// the fit's own scene.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub case: Option<String>,
}

impl Target {
    /// Its column in fit.csv and fit.md: the metric, followed by `@case` for a case's.
    pub fn column(&self) -> String {
        match &self.case {
            Some(c) => format!("{}@{c}", self.metric),
            None => self.metric.clone(),
        }
    }
}

/// Another scene of a fit, run with the same free parameters: the same impact at another
/// speed, say. Its study holds its scene and the fit's run options (resolution scale,
/// end time, threads per run).
#[derive(Clone, Debug)]
pub struct Case {
    /// Its name, as targets give it (letters, digits, `-`, `_`, `.`: it names the case's
    /// directory).
    pub name: String,
    /// Its scene and run options.
    pub study: Study,
    /// Not fitted: run once at the best point, its targets compared with the run.
    pub hold_out: bool,
}

fn one() -> f64 {
    1.0
}

/// A constraint on a derived metric: `min ≤ value ≤ max` (either bound may be left out).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Constraint {
    /// The derived metric's name.
    pub derived: String,
    /// Lower bound.
    #[serde(default)]
    pub min: Option<f64>,
    /// Upper bound.
    #[serde(default)]
    pub max: Option<f64>,
}

impl Constraint {
    /// How far `value` is outside the bounds, relative to the bound (0 inside).
    fn violation(&self, value: f64) -> f64 {
        if !value.is_finite() {
            return 1.0;
        }
        let below = self.min.map_or(0.0, |m| ((m - value) / m.abs()).max(0.0));
        let above = self.max.map_or(0.0, |m| ((value - m) / m.abs()).max(0.0));
        below + above
    }
}

/// A fit: the base scene and run options (a [`Study`] without axes: its metrics are the
/// targets' and its derived metrics those the constraints name), the free parameters,
/// the targets, the constraints, the run budget and the other cases.
#[derive(Clone, Debug)]
pub struct Fit {
    /// The base scene, run options and derived metrics (the constraints are evaluated on
    /// its scene).
    pub study: Study,
    /// The free parameters.
    pub free: Vec<Free>,
    /// The targets.
    pub targets: Vec<Target>,
    /// The constraints.
    pub constraints: Vec<Constraint>,
    /// The most points of the search (each runs the base scene and every fitted case;
    /// the sensitivity and hold-out runs come on top).
    pub budget: usize,
    /// Other scenes the free parameters apply to (default none).
    pub cases: Vec<Case>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseFile {
    name: String,
    scene: String,
    #[serde(default)]
    hold_out: bool,
}

/// `[[set]]`: a scene value fixed for the whole fit, in its scene and every case.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SetFile {
    path: String,
    value: toml::Value,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FitFile {
    #[serde(default)]
    description: String,
    scene: String,
    resolution_scale: Option<f64>,
    end_time: Option<f64>,
    threads_per_run: Option<usize>,
    budget: usize,
    free: Vec<Free>,
    target: Vec<Target>,
    #[serde(default)]
    constraint: Vec<Constraint>,
    #[serde(default)]
    derived: Vec<Derived>,
    #[serde(default)]
    case: Vec<CaseFile>,
    #[serde(default)]
    set: Vec<SetFile>,
}

/// Sets `value` at `path` in `study`'s scene for good (a fit's `[[set]]`); `Err` is the
/// key at fault (`path` or `value`) and why.
fn fix(study: &mut Study, path: &str, value: &toml::Value) -> Result<(), (&'static str, String)> {
    let mut table: toml::Table = toml::from_str(&study.scene)
        .map_err(|e| ("path", format!("{}: {}", study.scene_origin, e.message())))?;
    crate::study::scene_path::set(&mut table, path, value.clone()).map_err(|m| ("path", m))?;
    let text = toml::to_string(&table).map_err(|e| ("value", e.to_string()))?;
    if let Err(e) = Scene::from_toml_str(&text, &study.scene_origin) {
        return Err((
            "value",
            format!(
                "the scene {} refuses it: {}",
                study.scene_origin,
                scene_message(&e)
            ),
        ));
    }
    study.scene = text;
    Ok(())
}

impl Fit {
    /// Runs the fit's scene and every case at `scale` in place of the file's
    /// `resolution_scale` (the command line's `--resolution-scale`); as
    /// [`Study::set_resolution_scale`].
    pub fn set_resolution_scale(&mut self, scale: f64) -> Result<(), StudyError> {
        self.study.set_resolution_scale(scale)?;
        for case in &mut self.cases {
            case.study.set_resolution_scale(scale)?;
        }
        Ok(())
    }

    /// Reads and checks a fit file; its `scene` is relative to the file's directory.
    pub fn from_toml_file(path: impl AsRef<Path>) -> Result<Self, StudyError> {
        let (text, origin, dir) = read_path(path.as_ref())?;
        Self::from_toml_str(&text, &origin, &dir)
    }

    /// Reads and checks a fit from TOML text (`origin` names it in messages; `dir` is where
    /// its scene path is relative to).
    pub fn from_toml_str(text: &str, origin: &str, dir: &Path) -> Result<Self, StudyError> {
        let (file, map): (FitFile, _) = read_file(text, origin)?;
        let settings = RunSettings {
            description: file.description,
            resolution_scale: file.resolution_scale,
            end_time: file.end_time,
            threads_per_run: file.threads_per_run,
        };
        let mut study = base_study(&map, dir, ("scene", &file.scene), settings.clone())?;
        study.derived = file.derived;
        let mut cases = Vec::new();
        for (i, c) in file.case.into_iter().enumerate() {
            let key = format!("case[{i}].scene");
            let study = base_study(&map, dir, (&key, &c.scene), settings.clone())?;
            cases.push(Case {
                name: c.name,
                study,
                hold_out: c.hold_out,
            });
        }
        // The fixed values go into the scene of the fit and of every case, one at a time,
        // each checked by the scene reader as it is set.
        for (i, set) in file.set.iter().enumerate() {
            for s in std::iter::once(&mut study).chain(cases.iter_mut().map(|c| &mut c.study)) {
                fix(s, &set.path, &set.value).map_err(|(k, m)| {
                    locate(&map, StudyError::at_key(format!("set[{i}].{k}"), m))
                })?;
            }
        }
        let fit = Fit {
            study,
            free: file.free,
            targets: file.target,
            constraints: file.constraint,
            budget: file.budget,
            cases,
        };
        fit.check().map_err(|e| locate(&map, e))?;
        Ok(fit)
    }

    /// Checks the fit: the targets (their metrics and cases), the cases, the study part
    /// (options, derived), the bounds and start of each free parameter, the constraints,
    /// and that the start point's scene reads in every case and satisfies the constraints.
    pub fn check(&self) -> Result<(), StudyError> {
        for (i, t) in self.targets.iter().enumerate() {
            metric::check_name(&t.metric)
                .map_err(|m| StudyError::at_key(format!("target[{i}].metric"), m))?;
            if let Some(c) = &t.case
                && !self.cases.iter().any(|k| k.name == *c)
            {
                return Err(StudyError::at_key(
                    format!("target[{i}].case"),
                    format!("`{c}` is not the name of a `[[case]]`"),
                ));
            }
        }
        if !self.targets.iter().any(|t| t.case.is_none()) {
            return Err(StudyError::at_key(
                "target",
                "give at least one target of the fit's own scene (a `[[target]]` without `case`)",
            ));
        }
        self.with_metrics(&self.study, None).check()?;
        for (i, c) in self.cases.iter().enumerate() {
            let key = |k: &str| format!("case[{i}].{k}");
            if c.name.is_empty()
                || crate::study::plain_name(&c.name) != c.name
                || c.name.chars().all(|x| x == '.')
            {
                return Err(StudyError::at_key(
                    key("name"),
                    format!(
                        "`{}` cannot name a directory: use letters, digits, `-`, `_` and `.`",
                        c.name
                    ),
                ));
            }
            if self.cases[..i].iter().any(|k| k.name == c.name) {
                return Err(StudyError::at_key(
                    key("name"),
                    format!("`{}` names two cases", c.name),
                ));
            }
            if !self
                .targets
                .iter()
                .any(|t| t.case.as_ref() == Some(&c.name))
            {
                return Err(StudyError::at_key(
                    format!("case[{i}]"),
                    format!(
                        "no `[[target]]` names case `{}`: its runs would {}",
                        c.name,
                        if c.hold_out {
                            "compare nothing"
                        } else {
                            "count for nothing"
                        }
                    ),
                ));
            }
            self.with_metrics(&c.study, Some(&c.name))
                .check()
                .map_err(|e| StudyError::at_key(format!("case[{i}]"), e.message))?;
        }
        if self.budget < self.free.len() + 1 {
            return Err(StudyError::at_key(
                "budget",
                format!(
                    "must allow at least the starting simplex, {} runs, not {}",
                    self.free.len() + 1,
                    self.budget
                ),
            ));
        }
        if self.free.is_empty() {
            return Err(StudyError::at_key(
                "free",
                "give at least one free parameter",
            ));
        }
        for (i, f) in self.free.iter().enumerate() {
            let key = |k: &str| format!("free[{i}].{k}");
            if !(f.min.is_finite() && f.max.is_finite()) || f.min >= f.max {
                return Err(StudyError::at_key(
                    key("max"),
                    format!(
                        "the bounds are empty or reversed: min {} max {}",
                        f.min, f.max
                    ),
                ));
            }
            if f.scale == Spacing::Log && f.min <= 0.0 {
                return Err(StudyError::at_key(
                    key("min"),
                    format!("a log scale needs positive bounds, not {}", f.min),
                ));
            }
            if let Some(s) = f.start
                && !(f.min..=f.max).contains(&s)
            {
                return Err(StudyError::at_key(
                    key("start"),
                    format!("{s} is outside the bounds [{}, {}]", f.min, f.max),
                ));
            }
            if self.free[..i].iter().any(|g| g.path == f.path) {
                return Err(StudyError::at_key(
                    key("path"),
                    format!("`{}` is free twice", f.path),
                ));
            }
        }
        for (i, t) in self.targets.iter().enumerate() {
            if !(t.value.is_finite() && t.value != 0.0) {
                return Err(StudyError::at_key(
                    format!("target[{i}].value"),
                    format!(
                        "must be a finite, non-zero number (errors are relative), not {}",
                        t.value
                    ),
                ));
            }
            if !(t.weight.is_finite() && t.weight > 0.0) {
                return Err(StudyError::at_key(
                    format!("target[{i}].weight"),
                    format!("must be positive, not {}", t.weight),
                ));
            }
        }
        for (i, c) in self.constraints.iter().enumerate() {
            if !self.study.derived.iter().any(|d| d.name == c.derived) {
                return Err(StudyError::at_key(
                    format!("constraint[{i}].derived"),
                    format!("`{}` is not one of the `[[derived]]` metrics", c.derived),
                ));
            }
            match (c.min, c.max) {
                (None, None) => {
                    return Err(StudyError::at_key(
                        format!("constraint[{i}]"),
                        "give `min`, `max` or both",
                    ));
                }
                (Some(a), Some(b)) if a >= b => {
                    return Err(StudyError::at_key(
                        format!("constraint[{i}].max"),
                        format!("the bounds are empty or reversed: min {a} max {b}"),
                    ));
                }
                _ => {}
            }
        }
        let start = self.start();
        let point = self.point(0, &start);
        for (i, c) in self.cases.iter().enumerate() {
            let text = c.study.point_scene(&point)?;
            Scene::from_toml_str(&text, &c.study.scene_origin).map_err(|mut e| {
                e.location = None;
                StudyError::at_key(
                    format!("case[{i}].scene"),
                    format!("the start point's scene is refused: {e}"),
                )
            })?;
        }
        let text = self.study.point_scene(&point)?;
        let scene = Scene::from_toml_str(&text, &self.study.scene_origin).map_err(|e| {
            let mut e = e;
            e.location = None;
            StudyError::at_key("free", format!("the start point's scene is refused: {e}"))
        })?;
        let violation = self.violation(&scene);
        if violation > 0.0 {
            return Err(StudyError::at_key(
                "constraint",
                format!(
                    "the start point ({}) violates the constraints (by {violation:.3} relative): give a `start` inside them",
                    crate::study::study::describe(&point)
                ),
            ));
        }
        Ok(())
    }

    /// `study` with the metrics of the targets of `case` (`None`: the fit's own scene),
    /// each once: what its runs are read for.
    fn with_metrics(&self, study: &Study, case: Option<&str>) -> Study {
        let mut s = study.clone();
        s.metrics.clear();
        for t in self.targets.iter().filter(|t| t.case.as_deref() == case) {
            if !s.metrics.contains(&t.metric) {
                s.metrics.push(t.metric.clone());
            }
        }
        s
    }

    /// The index in [`Fit::cases`] of the case `target` is read from (`None`: the fit's
    /// own scene).
    fn case_of(&self, target: &Target) -> Option<usize> {
        target
            .case
            .as_ref()
            .and_then(|c| self.cases.iter().position(|k| k.name == *c))
    }

    /// The study of `case` (`None`: the fit's own).
    fn case_study(&self, case: Option<usize>) -> &Study {
        case.map_or(&self.study, |c| &self.cases[c].study)
    }

    /// Where the points of `case` lie under a search's `root`: `root` for the fit's own
    /// scene, `root/cases/NAME` for a case.
    fn case_root(&self, root: &Path, case: Option<usize>) -> std::path::PathBuf {
        match case {
            None => root.to_owned(),
            Some(c) => root.join("cases").join(&self.cases[c].name),
        }
    }

    /// Whether `target` is sought by the search (of the fit's own scene or of a case that
    /// is not held out).
    fn fitted(&self, target: &Target) -> bool {
        target
            .case
            .as_ref()
            .is_none_or(|c| self.cases.iter().any(|k| k.name == *c && !k.hold_out))
    }

    /// The targets the search seeks, in file order: those whose metrics an
    /// [`Objective`] receives.
    pub fn fitted_targets(&self) -> impl Iterator<Item = &Target> {
        self.targets.iter().filter(|t| self.fitted(t))
    }

    /// The start in unit coordinates.
    fn start(&self) -> Vec<f64> {
        self.free
            .iter()
            .map(|f| f.start.map_or(0.5, |s| f.unit(s)))
            .collect()
    }

    /// The point of run `index` at unit coordinates `u`.
    fn point(&self, index: usize, u: &[f64]) -> Point {
        Point {
            index,
            settings: self
                .free
                .iter()
                .zip(u)
                .map(|(f, &u)| (f.path.clone(), toml::Value::Float(f.value(u))))
                .collect(),
        }
    }

    /// The summed relative violation of the constraints by a scene.
    fn violation(&self, scene: &Scene) -> f64 {
        self.constraints
            .iter()
            .map(|c| {
                let v = self
                    .study
                    .derived
                    .iter()
                    .find(|d| d.name == c.derived)
                    .and_then(|d| d.value(scene).ok())
                    .unwrap_or(f64::NAN);
                c.violation(v)
            })
            .sum()
    }

    /// Σ w (y − t)²/t² over the fitted targets.
    fn objective(&self, metrics: &[f64]) -> f64 {
        self.fitted_targets()
            .zip(metrics)
            .map(|(t, y)| t.weight * ((y - t.value) / t.value).powi(2))
            .sum()
    }
}

/// One run of a fit.
#[derive(Clone, Debug, Serialize)]
pub struct Evaluation {
    /// Its number in the search (or among the sensitivity runs).
    pub index: usize,
    /// The free parameters' values.
    pub values: Vec<f64>,
    /// How it ended.
    pub status: PointStatus,
    /// The fitted targets' metrics ([`Fit::fitted_targets`]), then the derived metrics.
    pub metrics: Vec<f64>,
    /// The objective (NaN for a failed run).
    pub objective: f64,
}

/// The outcome of a fit.
#[derive(Clone, Debug, Serialize)]
pub struct FitReport {
    /// Every run of the search, in order.
    pub runs: Vec<Evaluation>,
    /// The run with the smallest objective.
    pub best: Option<usize>,
    /// For each free parameter, the sensitivity run and, for each target metric, the
    /// elasticity (Δy/y)/(Δp/p) between the best point and it.
    pub sensitivity: Vec<(Evaluation, Vec<f64>)>,
    /// Why the search ended.
    pub ended: String,
    /// The hold-out cases' runs at the best point, in the order of [`Fit::cases`].
    pub hold_out: Vec<HoldOut>,
}

/// A hold-out case run at the best point.
#[derive(Clone, Debug, Serialize)]
pub struct HoldOut {
    /// The case's name.
    pub case: String,
    /// How its run ended.
    pub status: PointStatus,
    /// The metrics of its targets, in the order of [`Fit::targets`] (NaN unless done).
    pub metrics: Vec<f64>,
}

/// A fit's objective written in Rust: the value to minimise, from one finished point's
/// fitted target metrics in the order of [`Fit::fitted_targets`] (all of [`Fit::targets`]
/// when no case is held out). It must be deterministic (a resumed fit replays the search
/// from the stored runs).
pub type Objective<'a> = dyn Fn(&[f64]) -> f64 + 'a;

/// One run still to do: a case's study, its directory, the point's scene and the point.
struct PendingRun<'s> {
    study: &'s Study,
    case_root: PathBuf,
    scene: String,
    point: Point,
}

/// The search's state behind argmin's `&self` cost function.
struct Search<'a> {
    fit: &'a Fit,
    objective: &'a Objective<'a>,
    dir: &'a Path,
    options: &'a StudyOptions,
    runs: RefCell<Vec<Evaluation>>,
    /// (unit coordinates, objective) of every point asked for; a point within
    /// [`SAME_POINT`] of one of them is not run again.
    seen: RefCell<Vec<(Vec<f64>, f64)>>,
    failure: RefCell<Option<StudyError>>,
}

impl Search<'_> {
    /// Runs (or reads back) the point at `u` as run `index` under `root`: the fit's own
    /// scene and every fitted case.
    fn evaluate(
        &self,
        root: &Path,
        index: usize,
        u: &[f64],
    ) -> Result<Option<Evaluation>, StudyError> {
        let fit = self.fit;
        let point = fit.point(index, u);
        let cases = self.fitted_cases();
        let Some(status) = self.run_cases(root, &point, &cases)? else {
            return Ok(None);
        };
        let all = combined(&status);
        let mut metrics = Vec::new();
        for t in fit.fitted_targets() {
            let c = fit.case_of(t);
            let k = cases.iter().position(|&x| x == c).unwrap_or(0);
            metrics.push(self.metric(root, c, index, status[k], &t.metric)?);
        }
        // A point that did not finish has no objective, whatever its metrics.
        let objective = if all == PointStatus::Done {
            (self.objective)(&metrics)
        } else {
            f64::NAN
        };
        metrics.extend(fit.study.derived_values(&point));
        Ok(Some(Evaluation {
            index,
            values: point
                .settings
                .iter()
                .map(|(_, v)| v.as_float().unwrap_or(f64::NAN))
                .collect(),
            status: all,
            metrics,
            objective,
        }))
    }

    /// The value of `metric` in the run of `case` at point `index` under `root`; NaN
    /// unless that run is done.
    fn metric(
        &self,
        root: &Path,
        case: Option<usize>,
        index: usize,
        status: PointStatus,
        metric: &str,
    ) -> Result<f64, StudyError> {
        if status != PointStatus::Done {
            return Ok(f64::NAN);
        }
        let pdir = point_dir(&self.fit.case_root(root, case), index);
        Ok(metric::read_point(&pdir, [metric])?.0[0])
    }

    /// The runs of `point` in each of `cases` (`None`: the fit's own scene) that are not
    /// finished under `root`.
    fn pending(
        &self,
        root: &Path,
        point: &Point,
        cases: &[Option<usize>],
    ) -> Result<Vec<PendingRun<'_>>, StudyError> {
        let fit = self.fit;
        let mut pending = Vec::new();
        for &c in cases {
            let study = fit.case_study(c);
            let scene = stored_scene(study, point)?;
            let case_root = fit.case_root(root, c);
            let pdir = point_dir(&case_root, point.index);
            check_stored_scene(&pdir, &scene, point).map_err(|_| {
                StudyError::bad(format!(
                    "{}: run {} of this directory was made for another point than the search asks for now (the fit file or its scene changed): use a new directory",
                    pdir.display(),
                    point.index
                ))
            })?;
            if !read_record(&pdir)?.is_some_and(|r| r.status != PointStatus::Pending) {
                pending.push(PendingRun {
                    study,
                    case_root,
                    scene,
                    point: point.clone(),
                });
            }
        }
        Ok(pending)
    }

    /// Runs `pending`, `options.jobs` at a time; false when a stop request stopped one.
    fn execute(&self, pending: &[PendingRun<'_>]) -> Result<bool, StudyError> {
        let options = self.options;
        for chunk in pending.chunks(options.jobs.max(1)) {
            let outcomes: Vec<Result<Outcome, StudyError>> = std::thread::scope(|s| {
                let handles: Vec<_> = chunk
                    .iter()
                    .map(|r| {
                        s.spawn(move || {
                            run_point(r.study, &r.case_root, &r.point, &r.scene, options)
                        })
                    })
                    .collect();
                handles
                    .into_iter()
                    .map(|h| {
                        h.join().unwrap_or_else(|_| {
                            Err(StudyError::failed("a case's run thread panicked"))
                        })
                    })
                    .collect()
            });
            for o in outcomes {
                if let Outcome::Stopped = o? {
                    return Ok(false);
                }
            }
        }
        Ok(true)
    }

    /// Runs `point` in each of `cases` (`None`: the fit's own scene) whose run is not
    /// finished, `options.jobs` at a time, and returns each one's status; `None` when a
    /// stop request stopped one.
    fn run_cases(
        &self,
        root: &Path,
        point: &Point,
        cases: &[Option<usize>],
    ) -> Result<Option<Vec<PointStatus>>, StudyError> {
        if !self.execute(&self.pending(root, point, cases)?)? {
            return Ok(None);
        }
        let mut status = Vec::new();
        for &c in cases {
            let pdir = point_dir(&self.fit.case_root(root, c), point.index);
            status.push(read_record(&pdir)?.map_or(PointStatus::Pending, |r| r.status));
        }
        Ok(Some(status))
    }

    /// Runs every (root, point, cases) of `batch` that is not finished, all of them
    /// `options.jobs` at a time (runs the search would otherwise ask for one point after
    /// another); false when a stop request stopped one. Their results are read back when
    /// the search asks for them.
    fn run_batch(
        &self,
        batch: &[(PathBuf, Point, Vec<Option<usize>>)],
    ) -> Result<bool, StudyError> {
        let mut all = Vec::new();
        for (root, point, cases) in batch {
            all.extend(self.pending(root, point, cases)?);
        }
        self.execute(&all)
    }

    /// The cases every point of the search runs: the fit's own scene and the fitted cases.
    fn fitted_cases(&self) -> Vec<Option<usize>> {
        let fit = self.fit;
        std::iter::once(None)
            .chain(
                (0..fit.cases.len())
                    .filter(|&c| !fit.cases[c].hold_out)
                    .map(Some),
            )
            .collect()
    }

    /// The penalty of the point at `u`: 0 inside the bounds and the constraints (a point
    /// that is run), else above any run's objective and growing with the violation.
    fn penalty(&self, u: &[f64]) -> f64 {
        let outside: f64 = u.iter().map(|&x| (-x).max(0.0) + (x - 1.0).max(0.0)).sum();
        if outside > 0.0 {
            return PENALTY * (1.0 + outside);
        }
        if !self.fit.constraints.is_empty() {
            let point = self.fit.point(0, u);
            let violation = self
                .fit
                .study
                .point_scene(&point)
                .ok()
                .and_then(|t| Scene::from_toml_str(&t, &self.fit.study.scene_origin).ok())
                .map_or(1.0, |s| self.fit.violation(&s));
            if violation > 0.0 {
                return PENALTY * (1.0 + violation);
            }
        }
        0.0
    }

    fn cost(&self, u: &[f64]) -> Result<f64, String> {
        if let Some((_, c)) = self.seen.borrow().iter().find(|(k, _)| same_point(k, u)) {
            return Ok(*c);
        }
        // Outside the bounds or the constraints: not run.
        let penalty = self.penalty(u);
        let cost = if penalty > 0.0 {
            penalty
        } else {
            let index = self.runs.borrow().len();
            if index >= self.fit.budget {
                return Err("budget".into());
            }
            let e = match self.evaluate(self.dir, index, u) {
                Ok(Some(e)) => e,
                Ok(None) => return Err("stopped".into()),
                Err(e) => {
                    self.failure.borrow_mut().replace(e);
                    return Err("failure".into());
                }
            };
            // A failed run: far worse than any run, but below the penalties.
            let c = if e.objective.is_finite() {
                e.objective
            } else {
                PENALTY / 2.0
            };
            if !self.options.quiet {
                let best = self
                    .runs
                    .borrow()
                    .iter()
                    .map(|r| r.objective)
                    .chain([e.objective])
                    .filter(|x| x.is_finite())
                    .fold(f64::INFINITY, f64::min);
                eprintln!(
                    "fit: run {index} of at most {} ({}): {}, objective {:.4e} (best {best:.4e})",
                    self.fit.budget,
                    crate::study::study::describe(&self.fit.point(index, u)),
                    format!("{:?}", e.status).to_lowercase(),
                    e.objective
                );
            }
            self.runs.borrow_mut().push(e);
            c
        };
        self.seen.borrow_mut().push((u.to_vec(), cost));
        Ok(cost)
    }
}

/// A point's status from its runs': done when every run is, failed when one failed.
fn combined(status: &[PointStatus]) -> PointStatus {
    if status.iter().all(|&s| s == PointStatus::Done) {
        PointStatus::Done
    } else if status.contains(&PointStatus::Failed) {
        PointStatus::Failed
    } else {
        PointStatus::Pending
    }
}

struct Problem<'a, 'b>(&'b Search<'a>);

impl argmin::core::CostFunction for Problem<'_, '_> {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, u: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        self.0.cost(u).map_err(argmin::core::Error::msg)
    }
}

/// Runs the fit into `dir` (created if needed), writes `fit.csv`, `fit.json`, `fit.md`
/// and a plot per free parameter (`plot_<parameter>.png`: every run's metrics against
/// it), and returns the report. `options.jobs` runs side by side the runs that do
/// not wait on each other: the starting simplex's points, the cases of one point, and
/// the sensitivity and hold-out runs; the search's later points, each chosen from the
/// runs before it, come one at a time. `options.stop` stops it at a checkpoint, which
/// the next call resumes.
pub fn run_fit(fit: &Fit, dir: &Path, options: &StudyOptions) -> Result<FitReport, StudyError> {
    run_fit_with(fit, dir, options, &|metrics: &[f64]| fit.objective(metrics))
}

/// [`run_fit`] with the user's own objective instead of Σ w (y − t)²/t²: `objective`
/// receives each finished run's target metrics in the order of [`Fit::targets`] (whose
/// `value` and `weight` it may ignore) and returns the value to minimise. A value that is
/// not finite counts as a failed run. The files and the report are those of `run_fit`,
/// with this objective in their `objective` column.
pub fn run_fit_with(
    fit: &Fit,
    dir: &Path,
    options: &StudyOptions,
    objective: &Objective<'_>,
) -> Result<FitReport, StudyError> {
    if !(1..=crate::cli::MAX_THREADS).contains(&options.jobs) {
        return Err(StudyError::bad(format!(
            "--jobs must be 1 to {}, not {}",
            crate::cli::MAX_THREADS,
            options.jobs
        )));
    }
    let search_dir = dir.join("search");
    std::fs::create_dir_all(&search_dir).map_err(|e| StudyError::io(&search_dir, e))?;
    let search = Search {
        fit,
        objective,
        dir: &search_dir,
        options,
        runs: RefCell::new(Vec::new()),
        seen: RefCell::new(Vec::new()),
        failure: RefCell::new(None),
    };
    // The starting simplex: the start and a step of a fifth of the range along each
    // axis (inward from a bound).
    let start = fit.start();
    let mut simplex = vec![start.clone()];
    for k in 0..start.len() {
        let mut v = start.clone();
        v[k] = if v[k] + 0.2 <= 1.0 {
            v[k] + 0.2
        } else {
            v[k] - 0.2
        };
        simplex.push(v);
    }
    // The starting simplex's runs side by side, with the numbers the search gives them
    // (the vertices in order, those against a constraint not run); the search then reads
    // them back. A stop request among them ends the fit before the search begins (argmin
    // evaluates the simplex where a cost cannot fail).
    let mut first = Vec::new();
    for u in &simplex {
        if search.penalty(u) == 0.0 && first.len() < fit.budget {
            first.push((
                search_dir.clone(),
                fit.point(first.len(), u),
                search.fitted_cases(),
            ));
        }
    }
    let started = search.run_batch(&first)?;
    let solver = argmin::solver::neldermead::NelderMead::new(simplex)
        // The spread of the simplex's objectives (squared relative errors) below which the
        // search ends: about 1e-4 in the relative errors. The budget usually ends it first.
        .with_sd_tolerance(1e-8)
        .map_err(|e| StudyError::failed(e.to_string()))?;
    let result = if started {
        argmin::core::Executor::new(Problem(&search), solver)
            .configure(|s| s.max_iters(10 * fit.budget as u64))
            .run()
    } else {
        Err(argmin::core::Error::msg("stopped"))
    };
    if let Some(e) = search.failure.borrow_mut().take() {
        return Err(e);
    }
    let stopped = options.stop.requested();
    let ended = match &result {
        _ if stopped => "stopped on request; the same command continues it".to_owned(),
        Ok(r) => format!("the search converged ({:?})", r.state().termination_status),
        Err(e) if e.to_string() == "budget" => {
            format!("the budget of {} runs was spent", fit.budget)
        }
        Err(e) => format!("the search stopped: {e}"),
    };
    let runs = search.runs.take();
    let best = runs
        .iter()
        .filter(|e| e.status == PointStatus::Done && e.objective.is_finite())
        .min_by(|a, b| a.objective.total_cmp(&b.objective))
        .map(|e| e.index);
    let mut sensitivity = Vec::new();
    let mut hold_out = Vec::new();
    if let (Some(b), false) = (best, stopped) {
        let u_best: Vec<f64> = fit
            .free
            .iter()
            .zip(&runs[b].values)
            .map(|(f, &v)| f.unit(v))
            .collect();
        // Per best run, so that a search continued with a larger budget, whose best
        // point may move, does not meet the steps of another point.
        let root = dir.join("sensitivity").join(format!("run-{b:04}"));
        let steps: Vec<Vec<f64>> = (0..fit.free.len())
            .map(|k| {
                let mut u = u_best.clone();
                u[k] += if u[k] + SENSITIVITY_STEP <= 1.0 {
                    SENSITIVITY_STEP
                } else {
                    -SENSITIVITY_STEP
                };
                u
            })
            .collect();
        let held: Vec<Option<usize>> = (0..fit.cases.len())
            .filter(|&c| fit.cases[c].hold_out)
            .map(Some)
            .collect();
        let held_root = dir.join("hold_out").join(format!("run-{b:04}"));
        let point = fit.point(0, &u_best);
        // Every sensitivity and hold-out run side by side; read back below.
        let mut batch: Vec<(PathBuf, Point, Vec<Option<usize>>)> = steps
            .iter()
            .enumerate()
            .map(|(k, u)| (root.clone(), fit.point(k, u), search.fitted_cases()))
            .collect();
        batch.push((held_root.clone(), point.clone(), held.clone()));
        search.run_batch(&batch)?;
        for (k, u) in steps.iter().enumerate() {
            let Some(e) = search.evaluate(&root, k, u)? else {
                break;
            };
            let dp = (e.values[k] - runs[b].values[k]) / runs[b].values[k];
            let elasticity = (0..fit.fitted_targets().count())
                .map(|m| ((e.metrics[m] - runs[b].metrics[m]) / runs[b].metrics[m]) / dp)
                .collect();
            sensitivity.push((e, elasticity));
        }
        let root = held_root;
        if let Some(status) = search.run_cases(&root, &point, &held)? {
            for (&c, &st) in held.iter().zip(&status) {
                let mut metrics = Vec::new();
                for t in fit.targets.iter().filter(|t| fit.case_of(t) == c) {
                    metrics.push(search.metric(&root, c, 0, st, &t.metric)?);
                }
                hold_out.push(HoldOut {
                    case: c.map_or_else(String::new, |c| fit.cases[c].name.clone()),
                    status: st,
                    metrics,
                });
            }
        }
    }
    let report = FitReport {
        runs,
        best,
        sensitivity,
        ended,
        hold_out,
    };
    write_report(fit, &report, dir)?;
    Ok(report)
}

fn write_report(fit: &Fit, report: &FitReport, dir: &Path) -> Result<(), StudyError> {
    let fitted: Vec<&Target> = fit.fitted_targets().collect();
    let columns: Vec<String> = fitted
        .iter()
        .map(|t| t.column())
        .chain(fit.study.derived.iter().map(|d| d.name.clone()))
        .collect();
    let mut csv = String::new();
    let mut header: Vec<String> = vec!["run".into()];
    header.extend(fit.free.iter().map(|f| f.path.clone()));
    header.push("status".into());
    header.extend(columns.iter().cloned());
    header.push("objective".into());
    let _ = writeln!(csv, "{}", header.join(","));
    let exact = crate::study::table::exact;
    for e in &report.runs {
        let mut f = vec![e.index.to_string()];
        f.extend(e.values.iter().map(|v| exact(*v)));
        f.push(format!("{:?}", e.status).to_lowercase());
        f.extend(e.metrics.iter().map(|v| exact(*v)));
        f.push(exact(e.objective));
        let _ = writeln!(csv, "{}", f.join(","));
    }
    let mut md = String::new();
    if !fit.study.description.is_empty() {
        let _ = writeln!(md, "{}\n", fit.study.description);
    }
    let _ = writeln!(md, "{} runs; {}.\n", report.runs.len(), report.ended);
    if let Some(b) = report.best {
        let e = &report.runs[b];
        let _ = writeln!(md, "Best: run {b}, objective {:.4e}.\n", e.objective);
        let _ = writeln!(md, "| parameter | value | bounds |\n|---|---|---|");
        for (f, v) in fit.free.iter().zip(&e.values) {
            let _ = writeln!(
                md,
                "| `{}` | {v:.4e} | {:e} – {:e} ({:?}) |",
                f.path, f.min, f.max, f.scale
            );
        }
        let _ = writeln!(
            md,
            "\n| metric | value | target | error | weight |\n|---|---|---|---|---|"
        );
        for (t, y) in fitted.iter().zip(&e.metrics) {
            let _ = writeln!(
                md,
                "| `{}` | {y:.4e} | {:.4e} | {:+.1} % | {} |",
                t.column(),
                t.value,
                100.0 * (y - t.value) / t.value,
                t.weight
            );
        }
        for (d, v) in fit.study.derived.iter().zip(&e.metrics[fitted.len()..]) {
            let _ = writeln!(md, "| `{}` (derived) | {v:.4e} | | | |", d.name);
        }
        if !report.sensitivity.is_empty() {
            let _ = write!(
                md,
                "\nLocal sensitivity (Δy/y)/(Δp/p), one run a step of {SENSITIVITY_STEP} of the scaled range from the best point:\n\n| parameter |"
            );
            for t in &fitted {
                let _ = write!(md, " `{}` |", t.column());
            }
            let _ = writeln!(md, "\n|---|{}", "---|".repeat(fitted.len()));
            for (f, (_, el)) in fit.free.iter().zip(&report.sensitivity) {
                let cells: Vec<String> = el.iter().map(|x| format!("{x:+.3}")).collect();
                let _ = writeln!(md, "| `{}` | {} |", f.path, cells.join(" | "));
            }
        }
        if !report.hold_out.is_empty() {
            let _ = writeln!(
                md,
                "\nHold-out cases, run once at the best point (not fitted):\n\n| case | status | metric | value | target | error |\n|---|---|---|---|---|---|"
            );
            for h in &report.hold_out {
                let targets = fit
                    .targets
                    .iter()
                    .filter(|t| t.case.as_ref() == Some(&h.case));
                for (t, y) in targets.zip(&h.metrics) {
                    let _ = writeln!(
                        md,
                        "| {} | {} | `{}` | {y:.4e} | {:.4e} | {:+.1} % |",
                        h.case,
                        format!("{:?}", h.status).to_lowercase(),
                        t.metric,
                        t.value,
                        100.0 * (y - t.value) / t.value
                    );
                }
            }
        }
    }
    let json =
        serde_json::to_string_pretty(report).map_err(|e| StudyError::failed(e.to_string()))?;
    for (name, text) in [("fit.csv", csv), ("fit.md", md), ("fit.json", json + "\n")] {
        let path = dir.join(name);
        crate::study::runner::write_whole(&path, text.as_bytes())?;
    }
    crate::study::fit_plots::write_fit_plots(fit, report, dir)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Weibull threshold of the model-pair fits: log scale, the search's reflection
    /// back to its start.
    fn threshold() -> Free {
        Free {
            path: "body.target.material.damage.sigma_b".into(),
            min: 1.0e6,
            max: 1.0e8,
            scale: Spacing::Log,
            start: Some(9.8e6),
        }
    }

    #[test]
    fn a_point_back_at_a_run_one_to_round_off_is_that_run() {
        let f = threshold();
        let u0 = f.unit(9.8e6);
        // Nelder–Mead's reflection of the simplex [u0, u0 + 0.2] about u0 + 0.2 and back,
        // as the search computes it: the start to round-off, not to the bit.
        let back = (u0 + 0.2) + ((u0 + 0.2) - (u0 + 0.4));
        assert_ne!(back.to_bits(), u0.to_bits());
        assert!(same_point(&[u0], &[back]));
        assert!((f.value(back) / 9.8e6 - 1.0).abs() < 1e-12);
        // A real step of the search, however small against the range, is a new point.
        assert!(!same_point(&[u0], &[u0 + 1e-6]));
        assert!(!same_point(&[u0, 0.5], &[u0, 0.5 + 1e-6]));
        assert!(!same_point(&[u0], &[u0, 0.5]));
    }
}

//! A study: a base scene, the axes of parameters it varies, the metrics it collects and
//! the reference values it compares them with; read from a study file (TOML,
//! docs/studies.md) or built in Rust.

use crate::scene::Scene;
use crate::scene::spans::SourceMap;
use crate::study::axis::{Axis, Point, Range, points};
use crate::study::derived::Derived;
use crate::study::error::StudyError;
use crate::study::{metric, scene_path};
use serde::Deserialize;
use std::path::Path;

/// A reference value of a metric (a measurement, or another code's result), against which
/// each point's value is given as a relative error.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// The metric (one of the study's).
    pub metric: String,
    /// The value (non-zero, in the metric's units).
    pub value: f64,
    /// Where it comes from (for the table's caption).
    pub source: String,
}

/// A parameter study.
#[derive(Clone, Debug)]
pub struct Study {
    /// What the study is for (the table's caption).
    pub description: String,
    /// The base scene, as TOML text (docs/scenes.md).
    pub scene: String,
    /// The base scene's file name, for messages.
    pub scene_origin: String,
    /// Every point's particle spacings are divided by this (`run --resolution-scale`).
    pub resolution_scale: f64,
    /// The simulated end time of every point instead of the scene's (`run --end-time`).
    pub end_time: Option<f64>,
    /// Worker threads of each point's run (points run side by side: `--jobs`).
    pub threads_per_run: usize,
    /// The axes; the points are every combination of one value of each.
    pub axes: Vec<Axis>,
    /// The numbers collected from each point's `summary.json` (study::metric).
    pub metrics: Vec<String>,
    /// Numbers of each point computed from its scene (study::derived), tabulated after
    /// the metrics.
    pub derived: Vec<Derived>,
    /// Reference values of some of the metrics (or derived metrics).
    pub references: Vec<Reference>,
    /// The study file's keys and their places (none for a study built in Rust).
    source: Option<SourceMap>,
    /// The scale before [`Self::set_resolution_scale`] first replaced it (the file's).
    file_scale: Option<f64>,
}

/// How the description of a study run at another scale than its file's begins to say so
/// (`Study::set_resolution_scale`).
const SCALE_NOTE: &str = "[run at resolution scale ";

/// The study file as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StudyFile {
    #[serde(default)]
    description: String,
    scene: String,
    resolution_scale: Option<f64>,
    end_time: Option<f64>,
    threads_per_run: Option<usize>,
    metrics: Vec<String>,
    #[serde(default)]
    parameter: Vec<ParameterFile>,
    #[serde(default)]
    derived: Vec<Derived>,
    #[serde(default)]
    reference: Vec<ReferenceFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ParameterFile {
    path: Option<String>,
    paths: Option<Vec<String>>,
    values: Option<Vec<toml::Value>>,
    range: Option<Range>,
    tuples: Option<Vec<Vec<toml::Value>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ReferenceFile {
    metric: String,
    value: f64,
    #[serde(default)]
    source: String,
}

impl Study {
    /// A study of the scene `scene` (TOML text; `origin` names it in messages) with no
    /// axes, no metrics and no references yet, run at resolution scale 1, one thread per
    /// point.
    pub fn new(scene: impl Into<String>, origin: impl Into<String>) -> Self {
        Self {
            description: String::new(),
            scene: scene.into(),
            scene_origin: origin.into(),
            resolution_scale: 1.0,
            end_time: None,
            threads_per_run: 1,
            axes: Vec::new(),
            metrics: Vec::new(),
            derived: Vec::new(),
            references: Vec::new(),
            source: None,
            file_scale: None,
        }
    }

    /// Reads and [checks](Self::check) a study file; its `scene` is read relative to the
    /// file's directory.
    pub fn from_toml_file(path: impl AsRef<Path>) -> Result<Self, StudyError> {
        let (text, origin, dir) = read_path(path.as_ref())?;
        Self::from_toml_str(&text, &origin, &dir)
    }

    /// Reads and checks a study from TOML text; `origin` names it in messages and `dir` is
    /// where its `scene` path is relative to.
    pub fn from_toml_str(text: &str, origin: &str, dir: &Path) -> Result<Self, StudyError> {
        let (file, map): (StudyFile, _) = read_file(text, origin)?;
        let locate = |e: StudyError| locate(&map, e);
        let mut study = base_study(
            &map,
            dir,
            ("scene", &file.scene),
            RunSettings {
                description: file.description,
                resolution_scale: file.resolution_scale,
                end_time: file.end_time,
                threads_per_run: file.threads_per_run,
            },
        )?;
        study.metrics = file.metrics;
        study.derived = file.derived;
        for (i, p) in file.parameter.into_iter().enumerate() {
            study.axes.push(axis_of(p, i).map_err(locate)?);
        }
        study.references = file
            .reference
            .into_iter()
            .map(|r| Reference {
                metric: r.metric,
                value: r.value,
                source: r.source,
            })
            .collect();
        study.source = Some(map);
        study.check()?;
        Ok(study)
    }

    /// The points: every combination of one value of each axis, the first axis slowest.
    pub fn points(&self) -> Vec<Point> {
        points(&self.axes)
    }

    /// The scene of `point` (TOML text): the base scene with the point's values set.
    pub fn point_scene(&self, point: &Point) -> Result<String, StudyError> {
        let mut table: toml::Table = toml::from_str(&self.scene)
            .map_err(|e| StudyError::bad(format!("{}: {}", self.scene_origin, e.message())))?;
        for (path, value) in &point.settings {
            scene_path::set(&mut table, path, value.clone())
                .map_err(|m| self.locate(StudyError::at_key(self.key_of_path(path), m)))?;
        }
        toml::to_string(&table).map_err(|e| StudyError::failed(e.to_string()))
    }

    /// Runs every point at `scale` in place of the file's `resolution_scale` (the
    /// command line's `--resolution-scale`): a positive number. A study directory keeps
    /// the scale its points ran at (`points/NNNN/scene.toml`), so continuing it at
    /// another scale is refused. The description is the file's own words (e.g. "RZ,
    /// A_res 1 mm"), so where the scale differs from the file's it gains a note of both,
    /// which the reports and plot titles carry.
    pub fn set_resolution_scale(&mut self, scale: f64) -> Result<(), StudyError> {
        if !(scale.is_finite() && scale > 0.0) {
            return Err(StudyError::bad(format!(
                "--resolution-scale must be a positive number, not {scale}"
            )));
        }
        let file = *self.file_scale.get_or_insert(self.resolution_scale);
        if let Some(at) = self.description.find(SCALE_NOTE) {
            self.description.truncate(at);
            self.description.truncate(self.description.trim_end().len());
        }
        if scale != file {
            if !self.description.is_empty() {
                self.description.push(' ');
            }
            self.description
                .push_str(&format!("{SCALE_NOTE}{scale:?}, the file's {file:?}]"));
        }
        self.resolution_scale = scale;
        Ok(())
    }

    /// Checks the study before anything runs: the options, the metrics, the references,
    /// each axis' values on the base scene (an error names the parameter and the value),
    /// then every point's scene as a whole.
    pub fn check(&self) -> Result<(), StudyError> {
        let at = |key: &str, m: String| self.locate(StudyError::at_key(key, m));
        if !(self.resolution_scale.is_finite() && self.resolution_scale > 0.0) {
            return Err(at(
                "resolution_scale",
                format!("must be a positive number, not {}", self.resolution_scale),
            ));
        }
        if let Some(t) = self.end_time
            && !(t.is_finite() && t > 0.0)
        {
            return Err(at(
                "end_time",
                format!("must be a positive time in s, not {t}"),
            ));
        }
        if !(1..=crate::cli::MAX_THREADS).contains(&self.threads_per_run) {
            return Err(at(
                "threads_per_run",
                format!(
                    "must be 1 to {}, not {}",
                    crate::cli::MAX_THREADS,
                    self.threads_per_run
                ),
            ));
        }
        if self.metrics.is_empty() {
            return Err(at(
                "metrics",
                "name at least one metric (a key of summary.json)".into(),
            ));
        }
        for (i, m) in self.metrics.iter().enumerate() {
            metric::check_name(m).map_err(|e| at(&format!("metrics[{i}]"), e))?;
            if self.metrics[..i].contains(m) {
                return Err(at(
                    &format!("metrics[{i}]"),
                    format!("`{m}` is listed twice"),
                ));
            }
        }
        for (i, d) in self.derived.iter().enumerate() {
            if self.metrics.contains(&d.name) || self.derived[..i].iter().any(|e| e.name == d.name)
            {
                return Err(at(
                    &format!("derived[{i}].name"),
                    format!("`{}` names another column already", d.name),
                ));
            }
        }
        for (i, r) in self.references.iter().enumerate() {
            if !self.columns().contains(&r.metric) {
                return Err(at(
                    &format!("reference[{i}].metric"),
                    format!(
                        "`{}` is not one of the study's metrics or derived metrics",
                        r.metric
                    ),
                ));
            }
            if !(r.value.is_finite() && r.value != 0.0) {
                return Err(at(
                    &format!("reference[{i}].value"),
                    format!(
                        "must be a finite, non-zero number (errors are relative), not {}",
                        r.value
                    ),
                ));
            }
        }
        let mut seen: Vec<&str> = Vec::new();
        for (a, axis) in self.axes.iter().enumerate() {
            if axis.values.is_empty() {
                return Err(at(&format!("parameter[{a}]"), "has no values".into()));
            }
            for (p, path) in axis.paths.iter().enumerate() {
                if seen.contains(&path.as_str()) {
                    return Err(at(
                        &self.axis_path_key(a, p),
                        format!("`{path}` is set by two parameters"),
                    ));
                }
                seen.push(path);
            }
            for (v, tuple) in axis.values.iter().enumerate() {
                if tuple.len() != axis.paths.len() {
                    return Err(at(
                        &format!("parameter[{a}].tuples[{v}]"),
                        format!("has {} values for {} paths", tuple.len(), axis.paths.len()),
                    ));
                }
                let point = Point {
                    index: 0,
                    settings: axis
                        .paths
                        .iter()
                        .cloned()
                        .zip(tuple.iter().cloned())
                        .collect(),
                };
                let text = self.point_scene(&point)?;
                if let Err(e) = Scene::from_toml_str(&text, &self.scene_origin) {
                    let key = if axis.paths.len() == 1 {
                        if self.source_has(&format!("parameter[{a}].values")) {
                            format!("parameter[{a}].values[{v}]")
                        } else {
                            format!("parameter[{a}]")
                        }
                    } else {
                        format!("parameter[{a}].tuples[{v}]")
                    };
                    return Err(at(
                        &key,
                        format!("the scene refuses it: {}", scene_message(&e)),
                    ));
                }
            }
        }
        for point in self.points() {
            let text = self.point_scene(&point)?;
            let scene = Scene::from_toml_str(&text, &self.scene_origin).map_err(|e| {
                self.locate(StudyError::bad(format!(
                    "point {} ({}): the scene refuses it: {}",
                    point.index,
                    describe(&point),
                    scene_message(&e)
                )))
            })?;
            for (i, d) in self.derived.iter().enumerate() {
                d.value(&scene).map_err(|m| {
                    at(
                        &format!("derived[{i}]"),
                        format!("point {} ({}): {m}", point.index, describe(&point)),
                    )
                })?;
            }
        }
        Ok(())
    }

    /// The table's columns: the metrics, then the derived metrics.
    pub fn columns(&self) -> Vec<String> {
        self.metrics
            .iter()
            .cloned()
            .chain(self.derived.iter().map(|d| d.name.clone()))
            .collect()
    }

    /// The derived metrics of `point`, in order (NaN where one has no value).
    pub fn derived_values(&self, point: &Point) -> Vec<f64> {
        let scene = self
            .point_scene(point)
            .ok()
            .and_then(|t| Scene::from_toml_str(&t, &self.scene_origin).ok());
        self.derived
            .iter()
            .map(|d| {
                scene
                    .as_ref()
                    .and_then(|s| d.value(s).ok())
                    .unwrap_or(f64::NAN)
            })
            .collect()
    }

    /// The study-file key of the parameter that sets `path` (`parameter[2].path`), or
    /// `path` itself for a study built in Rust.
    fn key_of_path(&self, path: &str) -> String {
        self.axes
            .iter()
            .enumerate()
            .find_map(|(a, axis)| {
                let p = axis.paths.iter().position(|q| q == path)?;
                Some(self.axis_path_key(a, p))
            })
            .unwrap_or_else(|| path.to_owned())
    }

    /// The study-file key of path `p` of axis `a`: `parameter[a].path` or
    /// `parameter[a].paths[p]` (the path itself for a study built in Rust).
    fn axis_path_key(&self, a: usize, p: usize) -> String {
        if self.source_has(&format!("parameter[{a}].paths")) {
            format!("parameter[{a}].paths[{p}]")
        } else if self.source.is_some() {
            format!("parameter[{a}].path")
        } else {
            self.axes[a].paths[p].clone()
        }
    }

    fn source_has(&self, key: &str) -> bool {
        self.source
            .as_ref()
            .is_some_and(|m| m.locate_key(key).is_some())
    }

    /// Adds the study file's location of the error's key.
    fn locate(&self, e: StudyError) -> StudyError {
        match &self.source {
            Some(map) => locate(map, e),
            None => e,
        }
    }
}

/// "path = value, …" of a point.
pub(crate) fn describe(point: &Point) -> String {
    point
        .settings
        .iter()
        .map(|(p, v)| format!("{p} = {}", crate::study::axis::cell(v).replace('\n', " ")))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A scene error's text without the scene file's own location (the point's scene is not
/// a file the user wrote).
pub(crate) fn scene_message(e: &crate::scene::SceneError) -> String {
    let mut e = e.clone();
    e.location = None;
    e.to_string()
}

/// A study or fit file's text, its name for messages and the directory its scene path
/// is relative to.
pub(crate) fn read_path(path: &Path) -> Result<(String, String, std::path::PathBuf), StudyError> {
    let text = crate::input::read_text(path, crate::input::MAX_INPUT_BYTES)
        .map_err(|e| StudyError::bad(format!("{}: {e}", path.display())))?;
    let dir = path.parent().unwrap_or(Path::new(".")).to_owned();
    Ok((text, path.display().to_string(), dir))
}

/// Parses a study or fit file: its keys' places and its contents, with a parser error
/// located at file, line and key.
pub(crate) fn read_file<T: serde::de::DeserializeOwned>(
    text: &str,
    origin: &str,
) -> Result<(T, SourceMap), StudyError> {
    let map = SourceMap::new(origin, text).map_err(|e| parse_error(&e, origin, text))?;
    let file: T = toml::from_str(text).map_err(|e| {
        let mut err = parse_error(&e, origin, text);
        if let Some(k) = e.span().and_then(|s| map.path_at(s.start)) {
            err.key = Some(k);
        }
        err
    })?;
    Ok((file, map))
}

/// The run options a study or fit file gives beside its scene.
#[derive(Clone)]
pub(crate) struct RunSettings {
    pub description: String,
    pub resolution_scale: Option<f64>,
    pub end_time: Option<f64>,
    pub threads_per_run: Option<usize>,
}

/// A study of the scene file `scene` (relative to `dir`) with the file's run options and
/// nothing else yet; a scene that cannot be read is an error at the file's key `key`
/// (`scene`, or a fit case's `case[i].scene`).
pub(crate) fn base_study(
    map: &SourceMap,
    dir: &Path,
    (key, scene): (&str, &str),
    settings: RunSettings,
) -> Result<Study, StudyError> {
    let scene_path = dir.join(scene);
    let text =
        crate::input::read_text(&scene_path, crate::input::MAX_INPUT_BYTES).map_err(|e| {
            locate(
                map,
                StudyError::at_key(key, format!("{}: {e}", scene_path.display())),
            )
        })?;
    let mut study = Study::new(text, scene_path.display().to_string());
    study.description = settings.description;
    study.resolution_scale = settings.resolution_scale.unwrap_or(1.0);
    study.end_time = settings.end_time;
    study.threads_per_run = settings.threads_per_run.unwrap_or(1);
    Ok(study)
}

pub(crate) fn locate(map: &SourceMap, mut e: StudyError) -> StudyError {
    if e.location.is_none() {
        e.location = Some(Box::new(match &e.key {
            Some(k) => map.locate(k),
            None => map.locate(""),
        }));
    }
    e
}

fn parse_error(e: &toml::de::Error, origin: &str, text: &str) -> StudyError {
    let offset = e.span().map_or(0, |s| s.start);
    let mut err = StudyError::bad(e.message().replace("unknown field", "unknown key"));
    err.location = Some(Box::new(crate::materials::Location::at_offset(
        origin, text, offset,
    )));
    err
}

/// The axis of `[[parameter]]` number `i`.
fn axis_of(p: ParameterFile, i: usize) -> Result<Axis, StudyError> {
    let key = |k: &str| format!("parameter[{i}].{k}");
    match (p.path, p.paths) {
        (Some(path), None) => {
            if p.tuples.is_some() {
                return Err(StudyError::at_key(
                    key("tuples"),
                    "`tuples` go with `paths` (several paths set together); one `path` takes `values` or `range`",
                ));
            }
            let values = match (p.values, p.range) {
                (Some(v), None) => {
                    if v.is_empty() {
                        return Err(StudyError::at_key(key("values"), "the list is empty"));
                    }
                    v
                }
                (None, Some(r)) => r
                    .values()
                    .map_err(|(k, m)| StudyError::at_key(key(&format!("range.{k}")), m))?
                    .into_iter()
                    .map(toml::Value::Float)
                    .collect(),
                (Some(_), Some(_)) => {
                    return Err(StudyError::at_key(
                        key("range"),
                        "give `values` or `range`, not both",
                    ));
                }
                (None, None) => {
                    return Err(StudyError::at_key(
                        format!("parameter[{i}]"),
                        "give the values: `values = [...]` or `range = { from, to, count }`",
                    ));
                }
            };
            Ok(Axis::list(path, values))
        }
        (None, Some(paths)) => {
            if p.values.is_some() || p.range.is_some() {
                return Err(StudyError::at_key(
                    key("paths"),
                    "several `paths` take `tuples` (one value per path in each); `values` and `range` go with one `path`",
                ));
            }
            if paths.is_empty() {
                return Err(StudyError::at_key(key("paths"), "the list is empty"));
            }
            let Some(tuples) = p.tuples else {
                return Err(StudyError::at_key(
                    format!("parameter[{i}]"),
                    "give the `tuples` the `paths` take together",
                ));
            };
            if tuples.is_empty() {
                return Err(StudyError::at_key(key("tuples"), "the list is empty"));
            }
            Ok(Axis::linked(paths, tuples))
        }
        (Some(_), Some(_)) => Err(StudyError::at_key(
            key("paths"),
            "give `path` (one) or `paths` (set together), not both",
        )),
        (None, None) => Err(StudyError::at_key(
            format!("parameter[{i}]"),
            "give the scene key it sets: `path = \"solver.n_target\"`",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The description names a scale given in place of the file's, once, whatever the
    /// number of calls, and loses the note when the file's scale is given back.
    #[test]
    fn a_scale_in_place_of_the_files_is_noted_once_in_the_description() {
        let mut study = Study::new("", "scene.toml");
        study.description = "RZ, A_res 1 mm".to_string();
        study.set_resolution_scale(2.0).unwrap();
        assert_eq!(
            study.description,
            "RZ, A_res 1 mm [run at resolution scale 2.0, the file's 1.0]"
        );
        study.set_resolution_scale(0.5).unwrap();
        assert_eq!(
            study.description,
            "RZ, A_res 1 mm [run at resolution scale 0.5, the file's 1.0]"
        );
        study.set_resolution_scale(1.0).unwrap();
        assert_eq!(study.description, "RZ, A_res 1 mm");
        let mut bare = Study::new("", "scene.toml");
        bare.set_resolution_scale(4.0).unwrap();
        assert_eq!(
            bare.description,
            "[run at resolution scale 4.0, the file's 1.0]"
        );
        assert!(bare.set_resolution_scale(0.0).is_err());
        assert_eq!(bare.resolution_scale, 4.0);
    }
}

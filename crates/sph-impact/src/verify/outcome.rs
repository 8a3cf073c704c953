//! The result of a verification run.

use serde::Serialize;
use serde_json::{Map, Value};

/// A table with named columns: one row per particle at the end time (the profile), or
/// one row per sample time (a history).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Profile {
    /// Column names (the first is the coordinate: `x` or `r`).
    pub columns: Vec<String>,
    /// Rows: one per particle sorted by the coordinate, or one per sample time.
    pub rows: Vec<Vec<f64>>,
}

impl Profile {
    /// The profile as CSV text with a header line.
    pub fn to_csv(&self) -> String {
        let mut s = self.columns.join(",");
        s.push('\n');
        for r in &self.rows {
            let cells: Vec<String> = r.iter().map(|v| format!("{v:.9e}")).collect();
            s.push_str(&cells.join(","));
            s.push('\n');
        }
        s
    }

    /// The values of one column.
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.columns.iter().position(|c| c == name)?;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }
}

/// One panel of a [`Picture`]: particle clouds and curves on shared axes.
#[derive(Clone, Debug, Default)]
pub struct Panel {
    /// Panel title.
    pub title: String,
    /// Axis labels (x, y).
    pub labels: (String, String),
    /// Particle clouds: (label, x, y).
    pub points: Vec<(String, Vec<f64>, Vec<f64>)>,
    /// Curves: (label, x, y).
    pub lines: Vec<(String, Vec<f64>, Vec<f64>)>,
    /// Same scale on both axes (particle snapshots).
    pub equal_aspect: bool,
}

/// A figure a problem is judged by by eye (particle snapshots, histories), written by
/// `sph-impact verify --out DIR` as `DIR/<name>.png`.
#[derive(Clone, Debug, Default)]
pub struct Picture {
    /// File stem.
    pub name: String,
    /// Figure title.
    pub title: String,
    /// Panels, laid out in a grid of `columns` columns.
    pub panels: Vec<Panel>,
    /// Grid columns.
    pub columns: usize,
}

/// Metrics, the profile, and exact curves for plotting.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Outcome {
    /// Problem name.
    pub problem: String,
    /// Named metrics (error norms, star states, shock positions, conservation...).
    pub metrics: Map<String, Value>,
    /// End-time particle profile.
    #[serde(skip)]
    pub profile: Profile,
    /// Exact solution sampled densely: (coordinate, field name, value) curves for the
    /// plot, as (field, points).
    #[serde(skip)]
    pub exact: Vec<(String, Vec<(f64, f64)>)>,
    /// Further pictures (snapshots, histories).
    #[serde(skip)]
    pub pictures: Vec<Picture>,
    /// Quantities against time (first column `t`), for the problems that sample them;
    /// empty otherwise. Written as `history.csv` by `verify --out`.
    #[serde(skip)]
    pub history: Profile,
}

impl Outcome {
    /// An outcome with the run's bookkeeping metrics already set: particle count,
    /// resolution, end time (when the problem has one), steps and wall time.
    pub fn for_run(
        problem: &str,
        particles: usize,
        resolution: usize,
        t_end: Option<f64>,
        steps: u64,
        wall_time_s: f64,
    ) -> Self {
        let mut out = Outcome {
            problem: problem.to_string(),
            ..Default::default()
        };
        out.set("particles", particles as f64);
        out.set("resolution", resolution as f64);
        if let Some(t) = t_end {
            out.set("t_end", t);
        }
        out.set("steps", steps as f64);
        out.set("wall_time_s", wall_time_s);
        out
    }

    /// RZ runs: records `axis_crossings` and `axis_crossings_midpoint`, the rings the
    /// axis mirror brought back to r > 0 and the RK2 midpoints found across the axis
    /// over the run (`Simulation::axis_crossing_counts`; issue 6 asks for none). `None`
    /// (other geometries) records nothing.
    pub fn set_axis_crossings(&mut self, counts: Option<(u64, u64)>) {
        if let Some((end, mid)) = counts {
            self.set("axis_crossings", end as f64);
            self.set("axis_crossings_midpoint", mid as f64);
        }
    }

    /// Records a metric.
    pub fn set(&mut self, key: &str, value: impl Into<Value>) {
        self.metrics.insert(key.to_string(), value.into());
    }

    /// A numeric metric, if present.
    pub fn get(&self, key: &str) -> Option<f64> {
        self.metrics.get(key).and_then(Value::as_f64)
    }
}

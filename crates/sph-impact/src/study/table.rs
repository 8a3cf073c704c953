//! The study's table: one row per point with its values, how it ended, its metrics and
//! their relative errors against the references; written as `study.csv` (exact numbers,
//! nothing that changes from run to run, so two runs of a study compare byte for byte),
//! `study.json` (the same with the wall times and errors) and `study.md`.

use crate::study::error::StudyError;
use crate::study::metric;
use crate::study::runner::{point_dir, read_record};
use crate::study::study::{Reference, Study};
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::Path;

/// How a point stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum PointStatus {
    /// Its run reached the end time.
    Done,
    /// Its run failed (the error is recorded).
    Failed,
    /// Not run yet, or stopped before its end.
    Pending,
}

impl PointStatus {
    fn word(self) -> &'static str {
        match self {
            PointStatus::Done => "done",
            PointStatus::Failed => "failed",
            PointStatus::Pending => "pending",
        }
    }
}

/// One point's row.
#[derive(Clone, Debug, Serialize)]
pub struct PointRow {
    /// The point's number.
    pub index: usize,
    /// The value of each parameter path, as written in the study (JSON).
    pub values: Vec<serde_json::Value>,
    /// How the point stands.
    pub status: PointStatus,
    /// Each metric (NaN where not done, or where the run gives none), then each derived
    /// metric (computed from the point's scene, also for points not run).
    pub metrics: Vec<f64>,
    /// (value − reference)/reference for each reference, in the references' order.
    pub errors: Vec<f64>,
    /// The failure's message, or why a metric could not be read.
    pub error: Option<String>,
    /// The run's wall time (s), for finished points.
    pub wall_time_s: Option<f64>,
}

/// The table of a study.
#[derive(Clone, Debug, Serialize)]
pub struct StudyTable {
    /// The study's description.
    pub description: String,
    /// The parameter paths, one column each.
    pub parameters: Vec<String>,
    /// The metrics, then the derived metrics, one column each.
    pub metrics: Vec<String>,
    /// The references: (metric, value, source).
    pub references: Vec<(String, f64, String)>,
    /// One row per point.
    pub rows: Vec<PointRow>,
}

impl StudyTable {
    /// Reads every point's state and metrics from the study directory `dir`.
    pub fn collect(study: &Study, dir: &Path) -> Result<Self, StudyError> {
        let parameters: Vec<String> = study
            .axes
            .iter()
            .flat_map(|a| a.paths.iter().cloned())
            .collect();
        let columns = study.columns();
        let mut rows = Vec::new();
        for point in study.points() {
            let pdir = point_dir(dir, point.index);
            let record = read_record(&pdir)?;
            let status = record.as_ref().map_or(PointStatus::Pending, |r| r.status);
            let mut error = record.as_ref().and_then(|r| r.error.clone());
            let mut metrics = vec![f64::NAN; study.metrics.len()];
            if status == PointStatus::Done {
                let (values, e) = metric::read_point(&pdir, &study.metrics)?;
                metrics = values;
                if let Some(e) = e {
                    error.get_or_insert(e);
                }
            }
            metrics.extend(study.derived_values(&point));
            let errors = study
                .references
                .iter()
                .map(|r| relative_error(&columns, &metrics, r))
                .collect();
            rows.push(PointRow {
                index: point.index,
                values: point
                    .settings
                    .iter()
                    .map(|(_, v)| serde_json::to_value(v).unwrap_or(serde_json::Value::Null))
                    .collect(),
                status,
                metrics,
                errors,
                error,
                wall_time_s: record
                    .filter(|r| r.status == PointStatus::Done)
                    .map(|r| r.wall_time_s),
            });
        }
        Ok(Self {
            description: study.description.clone(),
            parameters,
            metrics: columns,
            references: study
                .references
                .iter()
                .map(|r| (r.metric.clone(), r.value, r.source.clone()))
                .collect(),
            rows,
        })
    }

    /// The rows as CSV: `point`, the parameters, `status`, the metrics, `error(METRIC)`
    /// for each reference. Numbers in their shortest exact form; NaN as empty.
    pub fn to_csv(&self) -> String {
        let mut s = String::new();
        let mut header = vec!["point".to_string()];
        header.extend(self.parameters.iter().cloned());
        header.push("status".into());
        header.extend(self.metrics.iter().cloned());
        header.extend(self.references.iter().map(|r| format!("error({})", r.0)));
        let _ = writeln!(
            s,
            "{}",
            header
                .iter()
                .map(|h| csv_field(h))
                .collect::<Vec<_>>()
                .join(",")
        );
        for row in &self.rows {
            let mut fields = vec![row.index.to_string()];
            fields.extend(row.values.iter().map(|v| csv_field(&json_cell(v))));
            fields.push(row.status.word().into());
            fields.extend(row.metrics.iter().chain(&row.errors).map(|x| exact(*x)));
            let _ = writeln!(s, "{}", fields.join(","));
        }
        s
    }

    /// The table in Markdown, four significant digits, errors in per cent.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        if !self.description.is_empty() {
            let _ = writeln!(s, "{}\n", self.description);
        }
        let mut header = vec!["point".to_string()];
        header.extend(self.parameters.iter().map(|p| format!("`{p}`")));
        header.push("status".into());
        header.extend(self.metrics.iter().map(|m| format!("`{m}`")));
        header.extend(
            self.references
                .iter()
                .map(|r| format!("error of `{}`", r.0)),
        );
        header.push("wall".into());
        let _ = writeln!(s, "| {} |", header.join(" | "));
        let _ = writeln!(s, "|{}", "---|".repeat(header.len()));
        for row in &self.rows {
            let mut f = vec![row.index.to_string()];
            f.extend(row.values.iter().map(json_cell));
            f.push(row.status.word().into());
            f.extend(row.metrics.iter().map(|x| significant(*x)));
            f.extend(row.errors.iter().map(|e| {
                if e.is_nan() {
                    String::new()
                } else {
                    format!("{:+.1} %", 100.0 * e)
                }
            }));
            f.push(
                row.wall_time_s
                    .map_or_else(String::new, |t| format!("{t:.0} s")),
            );
            let _ = writeln!(s, "| {} |", f.join(" | "));
        }
        if !self.references.is_empty() {
            let _ = writeln!(s);
            for (m, v, src) in &self.references {
                let _ = writeln!(
                    s,
                    "Reference `{m}` = {}{}",
                    significant(*v),
                    if src.is_empty() {
                        String::new()
                    } else {
                        format!(" ({src})")
                    }
                );
                let _ = writeln!(s);
            }
        }
        let failed: Vec<&PointRow> = self.rows.iter().filter(|r| r.error.is_some()).collect();
        for r in failed {
            let _ = writeln!(
                s,
                "Point {}: {}\n",
                r.index,
                r.error.as_deref().unwrap_or_default()
            );
        }
        s
    }

    /// Writes `study.csv`, `study.json`, `study.md` and the plots
    /// (`plot_<parameter>.png`, study::plots) into `dir`.
    pub fn write(&self, dir: &Path) -> Result<(), StudyError> {
        crate::study::plots::write_plots(self, dir)?;
        let json =
            serde_json::to_string_pretty(self).map_err(|e| StudyError::failed(e.to_string()))?;
        for (name, text) in [
            ("study.csv", self.to_csv()),
            ("study.json", json + "\n"),
            ("study.md", self.to_markdown()),
        ] {
            let path = dir.join(name);
            crate::study::runner::write_whole(&path, text.as_bytes())?;
        }
        Ok(())
    }
}

fn relative_error(columns: &[String], metrics: &[f64], r: &Reference) -> f64 {
    columns
        .iter()
        .position(|m| *m == r.metric)
        .map_or(f64::NAN, |k| (metrics[k] - r.value) / r.value)
}

/// A value in a table cell: TOML values arrive as JSON.
pub(crate) fn json_cell(v: &serde_json::Value) -> String {
    match v {
        serde_json::Value::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() => format!("{x:?}"),
            _ => n.to_string(),
        },
        serde_json::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// Shortest exact form (`2.7e41`, `0.0552`); NaN as empty.
pub(crate) fn exact(x: f64) -> String {
    if x.is_nan() {
        String::new()
    } else {
        format!("{x:?}")
    }
}

/// Four significant digits, whole numbers below 10⁹ in full; NaN as empty.
fn significant(x: f64) -> String {
    if x.is_nan() {
        return String::new();
    }
    if x.fract() == 0.0 && x.abs() < 1e9 {
        // Counts (particles, steps) as they are.
        return format!("{x:.0}");
    }
    let e = x.abs().log10().floor() as i32;
    if (-3..4).contains(&e) {
        let decimals = (3 - e).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.3e}")
    }
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_written_exactly_in_csv_and_to_four_digits_in_markdown() {
        assert_eq!(exact(2.7e41), "2.7e41");
        assert_eq!(exact(0.0552), "0.0552");
        assert_eq!(exact(f64::NAN), "");
        assert_eq!(significant(0.0552), "0.05520");
        assert_eq!(significant(2.1379), "2.138");
        assert_eq!(significant(1234.5), "1234");
        assert_eq!(significant(75872.5), "7.587e4");
        assert_eq!(significant(11264.0), "11264");
        assert_eq!(significant(0.0), "0");
        assert_eq!(significant(2.7e41), "2.700e41");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
    }
}

//! # Parameter studies
//!
//! A study runs one base scene at every combination of the values of some of its keys
//! (the parameters: `solver.n_target`, the target material's Weibull k, …) and tabulates
//! chosen numbers of each run's `summary.json` (the metrics), with their relative errors
//! against reference values (e.g. the experiment's crater). `sph-impact study FILE`
//! runs a study file (docs/studies.md); [`Study`] and [`run_study`] do the same in Rust.
//!
//! The points run side by side (`jobs`), each a single-thread run by default. A study is
//! resumable: its directory keeps each point's scene, run and result, a finished point
//! is never run again, a stopped one continues from its checkpoint, and a failed one is
//! recorded with its error while the study goes on.
//!
//! ```no_run
//! use sph_impact::study::{Axis, Study, StudyOptions, run_study};
//! use std::path::Path;
//!
//! let scene = std::fs::read_to_string("examples/scenes/smoke_rz.toml")?;
//! let mut study = Study::new(scene, "smoke_rz.toml");
//! study.axes.push(Axis::list("solver.n_target", [2.0, 2.5, 3.0].map(toml::Value::Float)));
//! study.metrics = vec!["beta".into(), "crater_depth_m".into()];
//! study.check()?;
//! let table = run_study(&study, Path::new("out/n_target"), &StudyOptions::default())?;
//! for row in &table.rows {
//!     println!("point {}: β = {}", row.index, row.metrics[0]);
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod axis;
mod derived;
mod error;
mod fit;
pub mod fit_plots;
pub mod metric;
mod plots;
mod runner;
mod scene_path;
mod slurm;
#[allow(clippy::module_inception)]
mod study;
mod table;

pub use axis::{Axis, Point, Range, Spacing, cell, points};
pub use derived::{Derived, StaticStrength};
pub use error::StudyError;
pub use fit::{
    Case, Constraint, Evaluation, Fit, FitReport, Free, HoldOut, Objective, Target, run_fit,
    run_fit_with,
};
pub use fit_plots::redraw_fit_plots;
pub use runner::{StudyOptions, point_dir, run_study};
pub use slurm::emit_slurm;
pub use study::{Reference, Study};
pub use table::{PointRow, PointStatus, StudyTable};

/// `s` with every character other than ASCII letters, digits, `-`, `_` and `.` replaced by
/// `_`: a parameter path as part of a file name, a study's name as a job name.
pub(crate) fn plain_name(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect()
}

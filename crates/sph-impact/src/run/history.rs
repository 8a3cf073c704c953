//! `history.csv`: one row every `history_every` steps (and at t = 0 and the end) with
//! time, step, β, crater size, energies and momentum, and what set the last time step.

use crate::run::error::RunError;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The columns of `history.csv` (SI units).
pub const HISTORY_COLUMNS: [&str; 17] = [
    "t_s",
    "step",
    "dt_s",
    "beta",
    "beta_target",
    "ejecta_mass_kg",
    "crater_depth_m",
    "crater_diameter_m",
    "kinetic_J",
    "internal_J",
    "total_J",
    "momentum_z_kg_m_s",
    "crater_measured",
    "dt_reason",
    "dt_particle_id",
    "beta_pendulum",
    "crater_axis_depth_m",
];

/// One row.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HistoryRow {
    /// Simulated time (s).
    pub t: f64,
    /// Steps completed.
    pub step: u64,
    /// Last step (s); 0 at t = 0.
    pub dt: f64,
    /// β from the ejecta.
    pub beta: f64,
    /// β from the target's momentum.
    pub beta_target: f64,
    /// β as a ballistic pendulum sees it (escaping projectile debris left out).
    pub beta_pendulum: f64,
    /// Ejecta mass (kg).
    pub ejecta_mass: f64,
    /// Crater depth (m), from the last snapshot.
    pub crater_depth: f64,
    /// Crater diameter (m), from the last snapshot.
    pub crater_diameter: f64,
    /// Crater depth on the axis from the target's volume fraction (m), from the last
    /// snapshot (docs/diagnostics.md §4.4).
    pub crater_axis_depth: f64,
    /// Σ ½ m v² of the whole bodies (J; 2π × the solver's per-radian sum in RZ).
    pub kinetic: f64,
    /// Σ m e of the whole bodies (J).
    pub internal: f64,
    /// Σ m v_z of the whole bodies (kg·m/s).
    pub momentum_z: f64,
    /// True on rows where the crater was measured (snapshots), false where the row
    /// carries the last measured value.
    pub crater_measured: bool,
    /// Why the last step had its length: the reason of the smallest time-step vote
    /// (`crate::TimestepVote`); "none" at t = 0. Contains no comma.
    pub dt_reason: &'static str,
    /// Stable id of the particle whose vote set the last step (0 at t = 0); look it up
    /// in the snapshots' `id` array to see where a run's time step is spent.
    pub dt_particle_id: u64,
}

/// How much β still moved over the second half of a run: (β(t_end) − β(t_end/2))/β(t_end),
/// with β(t_end/2) read at the row nearest the middle of the history's time span (t_end/2
/// for a run from t = 0). It is the number to look at before trusting a run's β: the
/// study reads β at 400 µs, where it has settled (paper §5). NaN when the history spans
/// no time (no row, or one) or β is not finite.
pub fn beta_change_last_half(rows: &[HistoryRow]) -> f64 {
    let (Some(first), Some(last)) = (rows.first(), rows.last()) else {
        return f64::NAN;
    };
    if last.t <= first.t {
        return f64::NAN;
    }
    let half = 0.5 * (first.t + last.t);
    let mid = rows
        .iter()
        .min_by(|a, b| (a.t - half).abs().total_cmp(&(b.t - half).abs()))
        .map_or(f64::NAN, |r| r.beta);
    // NaN propagates: a run without ejecta diagnostics has β NaN throughout.
    (last.beta - mid) / last.beta
}

/// The open history file and the rows so far (kept for the plots).
pub(crate) struct History {
    path: PathBuf,
    out: BufWriter<File>,
    pub rows: Vec<HistoryRow>,
}

impl History {
    pub fn create(path: &Path) -> Result<Self, RunError> {
        let file = File::create(path).map_err(|e| RunError::io(path, e))?;
        let mut out = BufWriter::new(file);
        writeln!(out, "{}", HISTORY_COLUMNS.join(",")).map_err(|e| RunError::io(path, e))?;
        Ok(Self {
            path: path.to_owned(),
            out,
            rows: Vec::new(),
        })
    }

    pub fn push(&mut self, r: HistoryRow) -> Result<(), RunError> {
        writeln!(
            self.out,
            "{:e},{},{:e},{},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{},{},{},{},{:e}",
            r.t,
            r.step,
            r.dt,
            r.beta,
            r.beta_target,
            r.ejecta_mass,
            r.crater_depth,
            r.crater_diameter,
            r.kinetic,
            r.internal,
            r.kinetic + r.internal,
            r.momentum_z,
            u8::from(r.crater_measured),
            r.dt_reason,
            r.dt_particle_id,
            r.beta_pendulum,
            r.crater_axis_depth
        )
        .map_err(|e| RunError::io(&self.path, e))?;
        self.rows.push(r);
        Ok(())
    }

    pub fn flush(&mut self) -> Result<(), RunError> {
        self.out.flush().map_err(|e| RunError::io(&self.path, e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(points: &[(f64, f64)]) -> Vec<HistoryRow> {
        points
            .iter()
            .map(|&(t, beta)| HistoryRow {
                t,
                beta,
                ..HistoryRow::default()
            })
            .collect()
    }

    #[test]
    fn beta_change_reads_the_row_nearest_half_the_end_time() {
        // β 1.5 at 0, 1.8 at 195 µs, 1.9 at 210 µs, 2.0 at 400 µs: the row nearest
        // 200 µs is the one at 195 µs, so the change is (2.0 − 1.8)/2.0.
        let r = rows(&[(0.0, 1.5), (195e-6, 1.8), (210e-6, 1.9), (400e-6, 2.0)]);
        assert!((beta_change_last_half(&r) - 0.1).abs() < 1e-12);
        // A flat history reads zero; a falling one is negative.
        let flat = rows(&[(0.0, 1.0), (1e-4, 1.7), (2e-4, 1.7)]);
        assert_eq!(beta_change_last_half(&flat), 0.0);
        let falling = rows(&[(0.0, 1.0), (1e-4, 2.0), (2e-4, 1.6)]);
        assert!((beta_change_last_half(&falling) + 0.25).abs() < 1e-12);
    }

    #[test]
    fn beta_change_is_nan_without_a_history_to_read() {
        assert!(beta_change_last_half(&[]).is_nan());
        assert!(beta_change_last_half(&rows(&[(1e-6, 1.2)])).is_nan());
        assert!(beta_change_last_half(&rows(&[(0.0, f64::NAN), (1e-6, f64::NAN)])).is_nan());
    }
}

//! `history.csv`: one row every `history_every` steps (and at t = 0 and the end) with
//! time, step, β, crater size, energies and momentum, and what set the last time step.

use crate::run::error::RunError;
use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The columns of `history.csv` (SI units).
pub const HISTORY_COLUMNS: [&str; 18] = [
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
    "beta_detached",
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
    /// β from the ejecta no longer touching the target, from the last snapshot
    /// (docs/diagnostics.md §3.1).
    pub beta_detached: f64,
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

/// Bytes of whole rows gathered before they go to the file.
const BUFFER_BYTES: usize = 1 << 16;

/// The open history file and the rows so far (kept for the plots). Rows reach the
/// file whole: they are gathered in a buffer and written a batch of whole rows at a
/// time, so that a run killed at any moment leaves a file that ends with a complete row.
pub(crate) struct History {
    path: PathBuf,
    out: File,
    buffer: Vec<u8>,
    pub rows: Vec<HistoryRow>,
}

impl History {
    pub fn create(path: &Path) -> Result<Self, RunError> {
        let header = format!("{}\n", HISTORY_COLUMNS.join(","));
        crate::run::atomic::write_bytes(path, header.as_bytes())?;
        Self::append_to(path, Vec::new())
    }

    /// Opens `path` to append the rows after `rows`.
    fn append_to(path: &Path, rows: Vec<HistoryRow>) -> Result<Self, RunError> {
        let out = std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| RunError::io(path, e))?;
        Ok(Self {
            path: path.to_owned(),
            out,
            buffer: Vec::with_capacity(BUFFER_BYTES),
            rows,
        })
    }

    /// Re-opens `path` for a resumed run: keeps its header and its first `rows` rows
    /// (those written up to the checkpoint) and drops the rest, which the resumed run
    /// writes again. The kept rows are read back exactly (`{:e}` and `{}` print the
    /// shortest text that reads back to the same f64) for the plots and the summary.
    pub fn resume(path: &Path, rows: usize) -> Result<Self, RunError> {
        let refuse = |reason: String| RunError::Resume {
            path: path.display().to_string(),
            reason,
        };
        let text = std::fs::read_to_string(path).map_err(|e| refuse(e.to_string()))?;
        let mut lines = text.lines();
        let header = HISTORY_COLUMNS.join(",");
        if lines.next() != Some(header.as_str()) {
            return Err(refuse("its header is not this program's".to_owned()));
        }
        let kept: Vec<&str> = lines.take(rows).collect();
        if kept.len() < rows {
            return Err(refuse(format!(
                "it has {} rows, the checkpoint was written after row {rows}",
                kept.len()
            )));
        }
        let parsed = kept
            .iter()
            .enumerate()
            .map(|(k, line)| {
                parse_row(line).ok_or_else(|| refuse(format!("row {} cannot be read", k + 1)))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut text = String::new();
        for line in std::iter::once(header.as_str()).chain(kept) {
            text.push_str(line);
            text.push('\n');
        }
        crate::run::atomic::write_bytes(path, text.as_bytes())?;
        Self::append_to(path, parsed)
    }

    pub fn push(&mut self, r: HistoryRow) -> Result<(), RunError> {
        writeln!(
            self.buffer,
            "{:e},{},{:e},{},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{},{},{},{},{:e},{}",
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
            r.crater_axis_depth,
            r.beta_detached
        )
        .map_err(|e| RunError::io(&self.path, e))?;
        self.rows.push(r);
        if self.buffer.len() >= BUFFER_BYTES {
            self.flush()?;
        }
        Ok(())
    }

    /// Writes the gathered rows to the file.
    pub fn flush(&mut self) -> Result<(), RunError> {
        self.out
            .write_all(&self.buffer)
            .map_err(|e| RunError::io(&self.path, e))?;
        self.buffer.clear();
        Ok(())
    }
}

/// A row as [`History::push`] writes it; `None` if it does not read.
fn parse_row(line: &str) -> Option<HistoryRow> {
    let f: Vec<&str> = line.split(',').collect();
    if f.len() != HISTORY_COLUMNS.len() {
        return None;
    }
    let x = |k: usize| f[k].parse::<f64>().ok();
    Some(HistoryRow {
        t: x(0)?,
        step: f[1].parse().ok()?,
        dt: x(2)?,
        beta: x(3)?,
        beta_target: x(4)?,
        ejecta_mass: x(5)?,
        crater_depth: x(6)?,
        crater_diameter: x(7)?,
        kinetic: x(8)?,
        internal: x(9)?,
        // Column 10 is kinetic + internal.
        momentum_z: x(11)?,
        crater_measured: match f[12] {
            "0" => false,
            "1" => true,
            _ => return None,
        },
        dt_reason: crate::solver::timestep::reason_named(f[13])?,
        dt_particle_id: f[14].parse().ok()?,
        beta_pendulum: x(15)?,
        crater_axis_depth: x(16)?,
        beta_detached: x(17)?,
    })
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
    fn a_resumed_history_reads_its_rows_back_to_the_bit_and_drops_the_rest() {
        let dir = std::env::temp_dir().join(format!("history-resume-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("history.csv");
        let odd = [f64::NAN, f64::INFINITY, -0.0, 5e-324, 1.0 / 3.0, -2.5e300];
        let written: Vec<HistoryRow> = odd
            .iter()
            .enumerate()
            .map(|(k, &x)| HistoryRow {
                t: 1e-7 * k as f64,
                step: k as u64 * 7,
                dt: x,
                beta: 1.0 + x,
                beta_target: x / 3.0,
                beta_pendulum: -x,
                ejecta_mass: x * 1e-9,
                crater_depth: x,
                crater_diameter: 2.0 * x,
                crater_axis_depth: x + 1e-3,
                beta_detached: 2.0 - x,
                kinetic: x,
                internal: 0.1 + x,
                momentum_z: -x,
                crater_measured: k % 2 == 0,
                dt_reason: crate::solver::timestep::REASONS[k % 4],
                dt_particle_id: u64::MAX - k as u64,
            })
            .collect();
        let mut h = History::create(&path).unwrap();
        for r in &written {
            h.push(*r).unwrap();
        }
        h.flush().unwrap();
        drop(h);
        let mut back = History::resume(&path, 4).unwrap();
        let bits = |r: &HistoryRow| {
            [
                r.t,
                r.dt,
                r.beta,
                r.beta_target,
                r.beta_pendulum,
                r.ejecta_mass,
                r.crater_depth,
                r.crater_diameter,
                r.crater_axis_depth,
                r.beta_detached,
                r.kinetic,
                r.internal,
                r.momentum_z,
            ]
            // Every NaN reads back as the one NaN (its sign and payload are not printed).
            .map(|x| {
                if x.is_nan() {
                    f64::NAN.to_bits()
                } else {
                    x.to_bits()
                }
            })
        };
        assert_eq!(back.rows.len(), 4);
        for (a, b) in written.iter().zip(&back.rows) {
            assert_eq!(bits(a), bits(b));
            assert_eq!(
                (a.step, a.crater_measured, a.dt_reason, a.dt_particle_id),
                (b.step, b.crater_measured, b.dt_reason, b.dt_particle_id)
            );
        }
        // The rows after the fourth are gone from the file; new ones follow the kept.
        back.push(written[5]).unwrap();
        back.flush().unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text.lines().count(), 1 + 5);
        assert!(History::resume(&path, 6).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn beta_change_is_nan_without_a_history_to_read() {
        assert!(beta_change_last_half(&[]).is_nan());
        assert!(beta_change_last_half(&rows(&[(1e-6, 1.2)])).is_nan());
        assert!(beta_change_last_half(&rows(&[(0.0, f64::NAN), (1e-6, f64::NAN)])).is_nan());
    }
}

//! # Running a scene
//!
//! [`run`] builds a [`Scene`] — 3-D, or axisymmetric (RZ) — steps it to the end time and
//! writes into the run directory (docs/scenes.md, "Outputs"):
//!
//! - `snapshots/NNNNN.vtu` every snapshot interval (and at t = 0 and the end), listed
//!   with their times in `run.pvd` for ParaView;
//! - `history.csv`: time, step, β, crater size, energies and axial momentum
//!   ([`HISTORY_COLUMNS`]); β every row, the crater at every snapshot (rows in between
//!   carry the last value);
//! - `summary.json` ([`RunSummary`]): the final crater, β (from the ejecta and from the
//!   target), ejecta, damage, projectile melt fractions, cost, version, scene and scheme;
//! - PNG plots: `crater_section.png`, `history.png`, `ejecta.png`,
//!   `projectile_energy.png`.
//!
//! An RZ run is measured and written in the scene's 3-D convention (docs/diagnostics.md
//! §1): a ring is the point (r, 0, z) with velocity (v_r, 0, v_z) and its whole mass
//! 2π × (mass per radian), so every total in the outputs is the whole body's.

mod arrays;
mod checkpoint;
mod drive;
mod error;
mod finish;
mod history;
mod measure;
mod plots;
mod progress;
mod snapshot;
mod summary;

pub use checkpoint::CHECKPOINT_FILE;
pub use error::RunError;
pub use history::{HISTORY_COLUMNS, HistoryRow, beta_change_last_half};
pub use summary::{BodyDamageSummary, RunSummary, Totals};

use crate::scene::{Built, In3d, InLine, InPlane, InRz, Scene, SceneSimulation};
use std::path::Path;
use std::time::Instant;

/// How to run a scene.
#[derive(Clone, Debug, PartialEq)]
pub struct RunOptions {
    /// Worker threads; `None` uses rayon's default (all cores, or `RAYON_NUM_THREADS`).
    pub threads: Option<usize>,
    /// Simulated end time (s) instead of the scene's.
    pub end_time: Option<f64>,
    /// Every particle spacing is divided by this (> 1 refines; 1 runs the scene as
    /// written).
    pub resolution_scale: f64,
    /// No progress line.
    pub quiet: bool,
    /// Write a checkpoint ([`CHECKPOINT_FILE`] in the run directory) at every snapshot
    /// before the end, to resume from.
    pub checkpoint: bool,
    /// Continue from the run directory's checkpoint instead of starting at t = 0: the
    /// scene and resolution must be those it was written with; the end time may be
    /// later. `history.csv` keeps its rows up to the checkpoint, and the snapshots after
    /// it are written again.
    pub resume: bool,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            threads: None,
            end_time: None,
            resolution_scale: 1.0,
            quiet: false,
            checkpoint: false,
            resume: false,
        }
    }
}

/// Runs `scene` and writes its outputs into `out_dir` (created if needed).
pub fn run(scene: &Scene, out_dir: &Path, options: &RunOptions) -> Result<RunSummary, RunError> {
    let end_time = options.end_time.unwrap_or(scene.end_time);
    if !(end_time > 0.0 && end_time.is_finite()) {
        return Err(RunError::Option {
            option: "end-time",
            value: end_time,
            reason: "must be positive (s)",
        });
    }
    if !(options.resolution_scale > 0.0 && options.resolution_scale.is_finite()) {
        return Err(RunError::Option {
            option: "resolution-scale",
            value: options.resolution_scale,
            reason: "must be positive",
        });
    }
    let pool = match options.threads {
        Some(0) => {
            return Err(RunError::Option {
                option: "threads",
                value: 0.0,
                reason: "must be at least 1",
            });
        }
        Some(n) => rayon::ThreadPoolBuilder::new().num_threads(n).build(),
        None => rayon::ThreadPoolBuilder::new().build(),
    }
    .map_err(|e| RunError::Diagnostics(format!("cannot start the worker threads: {e}")))?;
    let threads = pool.current_num_threads();
    pool.install(|| run_in_pool(scene, out_dir, options, end_time, threads))
}

fn run_in_pool(
    scene: &Scene,
    dir: &Path,
    options: &RunOptions,
    end_time: f64,
    threads: usize,
) -> Result<RunSummary, RunError> {
    let wall = Instant::now();
    let snapshots = dir.join("snapshots");
    std::fs::create_dir_all(&snapshots).map_err(|e| RunError::io(&snapshots, e))?;
    let Built { simulation, bodies } = scene.build_scaled(options.resolution_scale)?;
    let job = drive::Job {
        scene,
        dir,
        options,
        end_time,
        threads,
        wall,
    };
    match simulation {
        SceneSimulation::ThreeD(sim) => job.run::<In3d>(sim, bodies),
        SceneSimulation::Rz(sim) => job.run::<InRz>(sim, bodies),
        SceneSimulation::Plane(sim) => job.run::<InPlane>(sim, bodies),
        SceneSimulation::Line(sim) => job.run::<InLine>(sim, bodies),
    }
}

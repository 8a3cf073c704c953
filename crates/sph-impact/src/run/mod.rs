//! # Running a scene
//!
//! [`run`] builds a [`Scene`] — 3-D, or axisymmetric (RZ) — steps it to the end time and
//! writes into the run directory (docs/scenes.md, "Outputs"):
//!
//! - `snapshots/NNNNN.vtu` every snapshot interval (and at t = 0 and the end), listed
//!   with their times in `run.pvd` for ParaView (over several MPI ranks a piece per rank,
//!   `NNNNN_K.vtu`, joined by `NNNNN.pvtu`: run/snapshot.rs);
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
pub(crate) mod atomic;
mod checkpoint;
mod directory;
mod drive;
mod error;
mod finish;
mod history;
mod lockstep;
mod measure;
mod plots;
pub(crate) mod progress;
mod snapshot;
mod stop;
mod summary;

pub use checkpoint::{CHECKPOINT_DIR, MAGIC as CHECKPOINT_MAGIC, checkpoints};
pub use directory::{RUN_FILES, RUN_SUBDIRS, clear_previous_run, previous_run_files};
pub use error::RunError;
pub use history::{HISTORY_COLUMNS, HistoryRow, beta_change_last_half};
pub use stop::StopFlag;
pub use summary::{BodyDamageSummary, RunSummary, Totals};

use crate::scene::{Built, In3d, InLine, InPlane, InRz, Scene, SceneSimulation};
use crate::solver::{OneRank, Ranks};
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
    /// Write a checkpoint (into [`CHECKPOINT_DIR`] in the run directory) at every
    /// snapshot before the end, to resume from. A stop request writes one in any case.
    pub checkpoint: bool,
    /// How many checkpoints to keep (the newest; at least 1): an earlier one can be
    /// resumed from (`resume_from`) when a later one holds a bad state.
    pub keep_checkpoints: usize,
    /// Continue from the run directory's newest checkpoint (or `resume_from`) instead of
    /// starting at t = 0: the scene and resolution must be those it was written with;
    /// the end time may be later. `history.csv` keeps its rows up to the checkpoint; the
    /// snapshots after it, the checkpoints after it, the summary and the plots are
    /// removed and written again.
    pub resume: bool,
    /// With `resume`: the checkpoint to continue from (a path, or a file name in
    /// [`CHECKPOINT_DIR`]) instead of the newest.
    pub resume_from: Option<std::path::PathBuf>,
    /// Clear the run directory of a previous run's files ([`previous_run_files`]) before
    /// starting; without it (or `resume`) a directory holding them is refused.
    pub overwrite: bool,
    /// Raised to stop the run after its current step ([`StopFlag`]).
    pub stop: StopFlag,
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            threads: None,
            end_time: None,
            resolution_scale: 1.0,
            quiet: false,
            checkpoint: false,
            keep_checkpoints: 3,
            resume: false,
            resume_from: None,
            overwrite: false,
            stop: StopFlag::new(),
        }
    }
}

/// Runs `scene` and writes its outputs into `out_dir` (created if needed).
pub fn run(scene: &Scene, out_dir: &Path, options: &RunOptions) -> Result<RunSummary, RunError> {
    run_over(scene, out_dir, options, &OneRank)
}

/// [`run`] as rank 0 of `ranks` (solver/ranks.rs; docs/mpi.md): the steps' pair passes
/// are shared with the other ranks, which call [`follow`] with the same scene and
/// options; rank 0 alone writes the run directory. On one rank, [`run`].
pub fn run_over(
    scene: &Scene,
    out_dir: &Path,
    options: &RunOptions,
    ranks: &dyn Ranks,
) -> Result<RunSummary, RunError> {
    // The end time and the resolution scale are checked with the scene
    // (`Scene::preflight`), as `check` checks them.
    let end_time = options.end_time.unwrap_or(scene.end_time);
    if options.resume && options.overwrite {
        return Err(RunError::Conflict(
            "--resume continues the run in the directory and --overwrite clears it: give one"
                .into(),
        ));
    }
    if options.resume_from.is_some() && !options.resume {
        return Err(RunError::Conflict(
            "--resume-from names the checkpoint of a --resume".into(),
        ));
    }
    if options.keep_checkpoints == 0 {
        return Err(RunError::Option {
            option: "keep-checkpoints",
            value: 0.0,
            reason: "must be at least 1",
        });
    }
    let pool = worker_pool(options.threads)?;
    let threads = pool.current_num_threads();
    pool.install(|| run_in_pool(scene, out_dir, options, end_time, threads, ranks))
}

/// A rank other than 0 of a run over `ranks` ([`run_over`]) into `out_dir`: builds
/// `scene` as rank 0 does and steps it in lockstep with rank 0 until the run ends;
/// writes only its pieces of the snapshots (`snapshots/NNNNN_K.vtu`, K its rank).
pub fn follow(
    scene: &Scene,
    out_dir: &Path,
    options: &RunOptions,
    ranks: &dyn Ranks,
) -> Result<(), RunError> {
    let end_time = options.end_time.unwrap_or(scene.end_time);
    let (dir, copies, resume) = (out_dir, scene.symmetry_copies(), options.resume);
    let pool = worker_pool(options.threads)?;
    pool.install(|| {
        let preflight = scene.preflight(options.resolution_scale, Some(end_time))?;
        let Built { simulation, .. } = scene.build_placed(&preflight.placed)?;
        match simulation {
            SceneSimulation::ThreeD(sim) => {
                lockstep::follow::<In3d>(ranks, sim, resume, dir, copies)
            }
            SceneSimulation::Rz(sim) => lockstep::follow::<InRz>(ranks, sim, resume, dir, copies),
            SceneSimulation::Plane(sim) => {
                lockstep::follow::<InPlane>(ranks, sim, resume, dir, copies)
            }
            SceneSimulation::Line(sim) => {
                lockstep::follow::<InLine>(ranks, sim, resume, dir, copies)
            }
        }
    })
}

/// The run's worker threads: `threads`, else rayon's default.
fn worker_pool(threads: Option<usize>) -> Result<rayon::ThreadPool, RunError> {
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        if !(1..=crate::cli::MAX_THREADS).contains(&n) {
            return Err(RunError::Option {
                option: "threads",
                value: n as f64,
                reason: "must be 1 to 1024 (sph_impact::cli::MAX_THREADS)",
            });
        }
        pool = pool.num_threads(n);
    }
    pool.build()
        .map_err(|e| RunError::Diagnostics(format!("cannot start the worker threads: {e}")))
}

fn run_in_pool(
    scene: &Scene,
    dir: &Path,
    options: &RunOptions,
    end_time: f64,
    threads: usize,
    ranks: &dyn Ranks,
) -> Result<RunSummary, RunError> {
    let wall = Instant::now();
    // Refused before the set-up's work; cleared (with --overwrite) only once the scene
    // has built, so that a bad scene does not cost the previous run.
    if !options.resume && !options.overwrite {
        directory::prepare_fresh(dir, false)?;
    }
    // The validation `sph-impact check` runs: nothing it passes fails before stepping.
    let preflight = scene.preflight(options.resolution_scale, Some(end_time))?;
    let Built { simulation, bodies } = scene.build_placed(&preflight.placed)?;
    // The placed bodies are in the simulation now: not held through the run.
    drop(preflight);
    if !options.resume {
        directory::prepare_fresh(dir, true)?;
    }
    // A resumed run makes it once its checkpoint has been accepted: a refused resume
    // leaves the directory as it was.
    if !options.resume {
        let snapshots = dir.join("snapshots");
        std::fs::create_dir_all(&snapshots).map_err(|e| RunError::io(&snapshots, e))?;
    }
    let job = drive::Job {
        scene,
        dir,
        options,
        end_time,
        threads,
        wall,
        ranks,
    };
    match simulation {
        SceneSimulation::ThreeD(sim) => job.run::<In3d>(sim, bodies),
        SceneSimulation::Rz(sim) => job.run::<InRz>(sim, bodies),
        SceneSimulation::Plane(sim) => job.run::<InPlane>(sim, bodies),
        SceneSimulation::Line(sim) => job.run::<InLine>(sim, bodies),
    }
}

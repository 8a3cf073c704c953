//! The stepping loop of a run, the same for 3-D and RZ: snapshots (VTU, PVD, crater) at
//! every interval, β and totals into `history.csv`, the progress line; then the final
//! diagnostics ([`super::finish`]).

use crate::run::arrays::Arrays;
use crate::run::checkpoint::RunCheckpoint;
use crate::run::error::RunError;
use crate::run::history::{History, HistoryRow};
use crate::run::lockstep::{self, Command};
use crate::run::measure::{BetaMeasure, Measurer};
use crate::run::progress::Progress;
use crate::run::summary::{RunSummary, Totals};
use crate::run::{RunOptions, finish, snapshot};
use crate::scene::{BodyInfo, Scene, SceneDimension, SimOf};
use crate::solver::{Ranks, StepInfo};
use sph_diagnostics::Pvd;
use std::path::Path;
use std::time::Instant;

/// One run: the scene, where it writes, and how.
pub(crate) struct Job<'a> {
    pub scene: &'a Scene,
    pub dir: &'a Path,
    pub options: &'a RunOptions,
    /// Simulated end time (s).
    pub end_time: f64,
    pub threads: usize,
    /// When the run started (set-up included).
    pub wall: Instant,
    /// The ranks that share the steps (this is rank 0; run/lockstep.rs).
    pub ranks: &'a dyn Ranks,
}

/// What the loop hands to the final diagnostics.
pub(crate) struct Stepped<D: SceneDimension> {
    pub sim: SimOf<D>,
    pub bodies: Vec<BodyInfo>,
    pub measurer: Measurer,
    pub history: History,
    pub initial: Totals,
    pub steps: u64,
    /// Σ over the steps of the particles stepped (fewer than particles × steps once
    /// some are in free flight).
    pub particle_steps: u64,
    /// Particles in free flight at the end (`SchemeConfig::free_flight_above`).
    pub free_flight: usize,
    /// Wall time of the stepping alone (s), the earlier parts of a resumed run included.
    pub stepping: f64,
    /// Wall time of the earlier parts of a resumed run (s; 0 for a run in one go).
    pub wall_before: f64,
    /// The checkpoint times a resumed run started from (s).
    pub resumed_from: Vec<f64>,
    /// False for a run stopped on request before its end time.
    pub complete: bool,
}

/// The work of a resumed run's earlier parts (all zero for a run in one go).
#[derive(Default)]
struct Before {
    steps: u64,
    particle_steps: u64,
    stepping: f64,
    wall: f64,
    resumed_from: Vec<f64>,
}

/// The snapshots written so far and the crater they last measured.
struct Outputs {
    pvd: Pvd,
    /// The next snapshot's number.
    index: usize,
    crater: CraterReading,
}

impl Outputs {
    /// Writes the next snapshot of `sim` (with the other ranks' pieces: they are told
    /// to write them, and whether it is the end's), measures the crater on it and adds a
    /// history row after the step `step` (`None` at t = 0).
    #[allow(clippy::too_many_arguments)]
    fn take<D: SceneDimension>(
        &mut self,
        sim: &SimOf<D>,
        copies: f64,
        dir: &Path,
        measurer: &Measurer,
        history: &mut History,
        step: Option<&StepInfo>,
        ranks: &dyn Ranks,
        end: bool,
    ) -> Result<(), RunError> {
        let a = Arrays::of::<D>(sim, copies);
        lockstep::tell(
            ranks,
            Command::Snapshot {
                index: self.index,
                end,
            },
        );
        snapshot::write_snapshot::<D>(sim, &a, dir, self.index, &mut self.pvd, ranks)?;
        self.index += 1;
        if let Some(c) = measurer.crater(&a)? {
            self.crater = CraterReading {
                depth: c.depth,
                diameter: c.diameter,
                axis_depth: measurer.axis_depth(&a)?,
                beta_detached: measurer.beta_detached(&a)?,
            };
        }
        history.push(row::<D>(
            sim,
            copies,
            &measurer.beta(&a)?,
            self.crater,
            step,
            true,
        ))
    }
}

impl Job<'_> {
    /// Steps `sim` (built from the scene, with its `bodies`) to the end time, writing the
    /// outputs, and returns the summary.
    pub fn run<D: SceneDimension>(
        &self,
        mut sim: SimOf<D>,
        bodies: Vec<BodyInfo>,
    ) -> Result<RunSummary, RunError> {
        let (scene, dir, end_time) = (self.scene, self.dir, self.end_time);
        let copies = scene.symmetry_copies();
        let setup = scene
            .diagnostic_setup(self.options.resolution_scale)
            .map_err(|e| scene.locate(e))?;
        let target_density = setup
            .targets
            .first()
            .map_or(f64::NAN, |&t| bodies[t].material.density);
        let mut measurer = Measurer {
            targets: setup.targets.iter().map(|&t| t as u16).collect(),
            projectile_mass: bodies[setup.projectile].mass,
            initial_target_momentum_z: bodies
                .iter()
                .enumerate()
                .filter(|(k, _)| *k != setup.projectile)
                .map(|(_, b)| b.mass * b.velocity[2])
                .sum(),
            setup,
            geometry: D::KIND,
            copies,
            reference: None,
            target_density,
            axis: None,
        };
        measurer.calibrate(&Arrays::of::<D>(&sim, copies))?;
        let n = sim.state.particles.len();
        let interval = scene.output.interval(end_time);
        let history_every = scene.output.history_every.unwrap_or(1);
        let initial = Totals::of::<D>(&sim, copies);
        let history_path = dir.join("history.csv");
        let mut progress = Progress::new(self.options.quiet, end_time, n);
        let mut outputs = Outputs {
            pvd: Pvd::new(),
            index: 0,
            crater: CraterReading::default(),
        };
        // The work of the run's earlier parts, when it resumes from a checkpoint.
        let mut before = Before::default();
        let (mut history, mut next_snapshot) = if self.options.resume {
            let from = RunCheckpoint::<D>::choose(dir, self.options)?;
            let RunCheckpoint {
                next_snapshot,
                snapshot_index,
                pvd,
                crater: [depth, diameter, axis_depth, beta_detached],
                steps,
                particle_steps,
                stepping_s,
                wall_s,
                history_rows,
                mut resumed_from_s,
                solver,
                ..
            } = RunCheckpoint::<D>::read(&from, scene, self.options, end_time)?;
            let t_checkpoint = solver.state.time;
            // The solver's state first: a checkpoint that does not fit leaves the
            // directory as it was (the history is cut only once it does).
            sim.restore(solver).map_err(|e| RunError::Resume {
                path: from.display().to_string(),
                reason: e.to_string(),
            })?;
            lockstep::send_state::<D>(self.ranks, &sim)?;
            let history = History::resume(&history_path, history_rows)?;
            // What the run wrote after the checkpoint is written again; none of it may
            // stay beside the resumed run's files.
            discard_after(dir, steps, snapshot_index)?;
            let snapshots = dir.join("snapshots");
            std::fs::create_dir_all(&snapshots).map_err(|e| RunError::io(&snapshots, e))?;
            for (t, file) in pvd {
                outputs.pvd.push(t, file);
            }
            snapshot::write_pvd(&outputs.pvd, dir)?;
            outputs.index = snapshot_index;
            outputs.crater = CraterReading {
                depth,
                diameter,
                axis_depth,
                beta_detached,
            };
            resumed_from_s.push(t_checkpoint);
            before = Before {
                steps,
                particle_steps,
                stepping: stepping_s,
                wall: wall_s,
                resumed_from: resumed_from_s,
            };
            progress = progress.starting_at(t_checkpoint, steps);
            if !self.options.quiet {
                eprintln!(
                    "resuming at t = {t_checkpoint:e} s (step {steps}) from {}",
                    from.display()
                );
            }
            (history, next_snapshot)
        } else {
            let mut history = History::create(&history_path)?;
            let ranks = self.ranks;
            outputs.take::<D>(
                &sim,
                copies,
                dir,
                &measurer,
                &mut history,
                None,
                ranks,
                false,
            )?;
            (history, interval.min(end_time))
        };
        let t_step = Instant::now();
        let mut steps: u64 = before.steps;
        let mut particle_steps: u64 = before.particle_steps;
        let mut free_flight = 0;
        // The checkpoint written on a stop request, once the loop has stopped for one.
        let mut interrupted: Option<std::path::PathBuf> = None;
        let tol = 1e-12 * end_time;
        let failed = |sim: &SimOf<D>, e: crate::SolverError| RunError::Solver {
            time: sim.state.time,
            step: sim.state.step,
            message: e.to_string(),
        };
        while sim.state.time < end_time - tol {
            let target = next_snapshot.min(end_time);
            particle_steps += sim.state.particles.len() as u64;
            let max_dt = target - sim.state.time;
            lockstep::tell(self.ranks, Command::Step(max_dt));
            let info = match sim.step_over(max_dt, self.ranks) {
                Ok(info) => info,
                Err(e) => return Err(failed(&sim, e)),
            };
            steps += 1;
            let at_snapshot = sim.state.time >= next_snapshot - tol;
            let at_end = sim.state.time >= end_time - tol;
            if at_end {
                // Summation density is recomputed from the final positions for output.
                if let Err(e) = sim.sync_density() {
                    return Err(failed(&sim, e));
                }
                // The final state and its diagnostics hold every particle.
                free_flight = sim.in_free_flight();
                sim.end_free_flight();
            }
            if at_snapshot || at_end {
                let ranks = self.ranks;
                sim.with_free_flight(|sim| {
                    let (m, h) = (&measurer, &mut history);
                    outputs.take::<D>(sim, copies, dir, m, h, Some(&info), ranks, at_end)
                })?;
                while next_snapshot <= sim.state.time + tol {
                    next_snapshot += interval;
                }
                if self.options.checkpoint && !at_end {
                    // The end's state is not a step's (density synchronised, flight
                    // ended): a run resumed to a later end time restarts from here.
                    let at = Work::now(steps, particle_steps, t_step, self.wall, &before);
                    self.checkpoint::<D>(&sim, &mut history, &outputs, next_snapshot, at)?;
                }
            } else if steps.is_multiple_of(history_every) {
                let r = sim.with_free_flight(|sim| -> Result<HistoryRow, RunError> {
                    let a = Arrays::of::<D>(sim, copies);
                    Ok(row::<D>(
                        sim,
                        copies,
                        &measurer.beta(&a)?,
                        outputs.crater,
                        Some(&info),
                        false,
                    ))
                })?;
                history.push(r)?;
            }
            progress.update(sim.state.time, steps, false);
            if self.options.stop.requested() && !at_end {
                // Checkpointed as the step left it; the partial summary below then
                // measures every particle, those in flight included.
                let at = Work::now(steps, particle_steps, t_step, self.wall, &before);
                interrupted =
                    Some(self.checkpoint::<D>(&sim, &mut history, &outputs, next_snapshot, at)?);
                free_flight = sim.in_free_flight();
                sim.end_free_flight();
                break;
            }
        }
        lockstep::tell(self.ranks, Command::Done);
        let stepping = before.stepping + t_step.elapsed().as_secs_f64();
        progress.finish(sim.state.time, steps);
        history.flush()?;
        let (time, step) = (sim.state.time, steps);
        let summary = finish::summarise(
            self,
            Stepped::<D> {
                sim,
                bodies,
                measurer,
                history,
                initial,
                steps,
                particle_steps,
                free_flight,
                stepping,
                wall_before: before.wall,
                resumed_from: before.resumed_from,
                complete: interrupted.is_none(),
            },
        )?;
        match interrupted {
            None => Ok(summary),
            Some(checkpoint) => Err(RunError::Interrupted {
                time,
                step,
                checkpoint: checkpoint.display().to_string(),
            }),
        }
    }

    /// Writes a checkpoint of `sim` after the work `at` (flushing the history first, so
    /// that the rows it counts are on disk) and returns its file.
    fn checkpoint<D: SceneDimension>(
        &self,
        sim: &SimOf<D>,
        history: &mut History,
        outputs: &Outputs,
        next_snapshot: f64,
        at: Work,
    ) -> Result<std::path::PathBuf, RunError> {
        history.flush()?;
        let (format, version, geometry) = RunCheckpoint::<D>::tags();
        RunCheckpoint::<D> {
            format,
            version,
            geometry,
            scene: RunCheckpoint::<D>::scene_text(self.scene)?,
            resolution_scale: self.options.resolution_scale,
            end_time: self.end_time,
            next_snapshot,
            snapshot_index: outputs.index,
            pvd: outputs.pvd.entries().to_vec(),
            crater: [
                outputs.crater.depth,
                outputs.crater.diameter,
                outputs.crater.axis_depth,
                outputs.crater.beta_detached,
            ],
            steps: at.steps,
            particle_steps: at.particle_steps,
            stepping_s: at.stepping,
            wall_s: at.wall,
            history_rows: history.rows.len(),
            resumed_from_s: at.resumed_from,
            solver: sim.checkpoint(),
        }
        .write(self.dir, self.options.keep_checkpoints)
    }
}

/// The work done up to a checkpoint, the earlier parts of a resumed run included.
#[derive(Clone)]
struct Work {
    steps: u64,
    particle_steps: u64,
    /// Wall time of the stepping (s).
    stepping: f64,
    /// Wall time of the whole run (s).
    wall: f64,
    resumed_from: Vec<f64>,
}

impl Work {
    /// The work done so far: `steps` and `particle_steps` in all, the stepping timed
    /// from `t_step` and the run from `wall` in this part, on top of `before`.
    fn now(
        steps: u64,
        particle_steps: u64,
        t_step: Instant,
        wall: Instant,
        before: &Before,
    ) -> Work {
        Work {
            steps,
            particle_steps,
            stepping: before.stepping + t_step.elapsed().as_secs_f64(),
            wall: before.wall + wall.elapsed().as_secs_f64(),
            resumed_from: before.resumed_from.clone(),
        }
    }
}

/// Removes what a run wrote after the checkpoint it resumes from (after `steps` steps,
/// with `snapshot_index` snapshots written): later checkpoints (of a continuation being
/// abandoned), later snapshots, the summary and the plots. They are written again.
fn discard_after(dir: &Path, steps: u64, snapshot_index: usize) -> Result<(), RunError> {
    let remove = |path: &Path| match std::fs::remove_file(path) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(RunError::io(path, e)),
        _ => Ok(()),
    };
    for (s, path) in crate::run::checkpoints(dir) {
        if s > steps {
            remove(&path)?;
        }
    }
    if let Ok(entries) = std::fs::read_dir(dir.join("snapshots")) {
        for e in entries.filter_map(|e| e.ok()) {
            let name = e.file_name().to_string_lossy().into_owned();
            if snapshot::snapshot_number(&name).is_some_and(|k| k >= snapshot_index) {
                remove(&e.path())?;
            }
        }
    }
    for name in crate::run::RUN_FILES {
        if !matches!(name, "history.csv" | "run.pvd") {
            remove(&dir.join(name))?;
        }
    }
    Ok(())
}

/// The crater as last measured (at a snapshot), carried by the rows in between (m).
#[derive(Clone, Copy, Debug)]
struct CraterReading {
    depth: f64,
    diameter: f64,
    /// From the volume fraction averaged over a disc about the axis
    /// (`Measurer::axis_depth`).
    axis_depth: f64,
    /// β from the ejecta no longer touching the target (`Measurer::beta_detached`).
    beta_detached: f64,
}

impl Default for CraterReading {
    fn default() -> Self {
        Self {
            depth: f64::NAN,
            diameter: f64::NAN,
            axis_depth: f64::NAN,
            beta_detached: f64::NAN,
        }
    }
}

/// A history row of the current state (totals of the whole bodies) after the step
/// `step` (`None` at t = 0).
fn row<D: SceneDimension>(
    sim: &SimOf<D>,
    copies: f64,
    beta: &BetaMeasure,
    crater: CraterReading,
    step: Option<&StepInfo>,
    crater_measured: bool,
) -> HistoryRow {
    let c = Totals::of::<D>(sim, copies);
    HistoryRow {
        t: sim.state.time,
        step: sim.state.step,
        dt: step.map_or(0.0, |s| s.dt),
        dt_reason: step.map_or("none", |s| s.vote.reason),
        dt_particle_id: step.map_or(0, |s| s.vote.particle_id),
        beta: beta.beta,
        beta_target: beta.beta_target,
        beta_pendulum: beta.beta_pendulum,
        ejecta_mass: beta.ejecta_mass,
        crater_depth: crater.depth,
        crater_diameter: crater.diameter,
        crater_axis_depth: crater.axis_depth,
        beta_detached: crater.beta_detached,
        kinetic: c.kinetic,
        internal: c.internal,
        momentum_z: c.momentum[2],
        crater_measured,
    }
}

//! The stepping loop of a run, the same for 3-D and RZ: snapshots (VTU, PVD, crater) at
//! every interval, β and totals into `history.csv`, the progress line; then the final
//! diagnostics ([`super::finish`]).

use crate::Simulation;
use crate::run::arrays::Arrays;
use crate::run::error::RunError;
use crate::run::history::{History, HistoryRow};
use crate::run::measure::{BetaMeasure, Measurer};
use crate::run::progress::Progress;
use crate::run::summary::{RunSummary, Totals};
use crate::run::{RunOptions, finish, snapshot};
use crate::scene::{BodyInfo, Scene, SceneDimension};
use crate::solver::StepInfo;
use sph_diagnostics::Pvd;
use sph_kernel::KernelChoice;
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
}

/// What the loop hands to the final diagnostics.
pub(crate) struct Stepped<D: SceneDimension> {
    pub sim: Simulation<D, KernelChoice>,
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
    /// Wall time of the stepping alone (s).
    pub stepping: f64,
}

impl Job<'_> {
    /// Steps `sim` (built from the scene, with its `bodies`) to the end time, writing the
    /// outputs, and returns the summary.
    pub fn run<D: SceneDimension>(
        &self,
        mut sim: Simulation<D, KernelChoice>,
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
            top_offset: 0.0,
            target_density,
            axis: None,
        };
        measurer.calibrate(&Arrays::of(&sim, copies))?;
        let n = sim.state.particles.len();
        let interval = scene.output.interval(end_time);
        let history_every = scene.output.history_every.unwrap_or(1);
        let initial = Totals::of(&sim, copies);
        let mut history = History::create(&dir.join("history.csv"))?;
        let mut pvd = Pvd::new();
        let mut progress = Progress::new(self.options.quiet, end_time, n);

        let mut snapshot_index = 0;
        let mut crater = CraterReading::default();
        let mut take_snapshot = |sim: &Simulation<D, KernelChoice>,
                                 history: &mut History,
                                 step: Option<&StepInfo>,
                                 crater: &mut CraterReading|
         -> Result<(), RunError> {
            let a = Arrays::of(sim, copies);
            let (pressure, _) = sim.pressure_and_sound_speed();
            snapshot::write_snapshot(sim, &a, &pressure, dir, snapshot_index, &mut pvd)?;
            snapshot_index += 1;
            if let Some(c) = measurer.crater(&a)? {
                *crater = CraterReading {
                    depth: c.depth,
                    diameter: c.diameter,
                    axis_depth: measurer.axis_depth(&a)?,
                };
            }
            history.push(row(sim, copies, &measurer.beta(&a)?, *crater, step, true))?;
            Ok(())
        };
        take_snapshot(&sim, &mut history, None, &mut crater)?;
        let mut next_snapshot = interval.min(end_time);
        let t_step = Instant::now();
        let mut steps: u64 = 0;
        let mut particle_steps: u64 = 0;
        let mut free_flight = 0;
        let tol = 1e-12 * end_time;
        let failed = |sim: &Simulation<D, KernelChoice>, e: crate::SolverError| RunError::Solver {
            time: sim.state.time,
            step: sim.state.step,
            message: e.to_string(),
        };
        while sim.state.time < end_time - tol {
            let target = next_snapshot.min(end_time);
            particle_steps += sim.state.particles.len() as u64;
            let info = match sim.step(target - sim.state.time) {
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
                sim.with_free_flight(|sim| {
                    take_snapshot(sim, &mut history, Some(&info), &mut crater)
                })?;
                while next_snapshot <= sim.state.time + tol {
                    next_snapshot += interval;
                }
            } else if steps.is_multiple_of(history_every) {
                let r = sim.with_free_flight(|sim| -> Result<HistoryRow, RunError> {
                    let a = Arrays::of(sim, copies);
                    Ok(row(
                        sim,
                        copies,
                        &measurer.beta(&a)?,
                        crater,
                        Some(&info),
                        false,
                    ))
                })?;
                history.push(r)?;
            }
            progress.update(sim.state.time, steps, false);
        }
        let stepping = t_step.elapsed().as_secs_f64();
        progress.finish(sim.state.time, steps);
        history.flush()?;
        finish::summarise(
            self,
            Stepped {
                sim,
                bodies,
                measurer,
                history,
                initial,
                steps,
                particle_steps,
                free_flight,
                stepping,
            },
        )
    }
}

/// The crater as last measured (at a snapshot), carried by the rows in between (m).
#[derive(Clone, Copy, Debug)]
struct CraterReading {
    depth: f64,
    diameter: f64,
    /// From the volume fraction on the axis (`Measurer::axis_depth`).
    axis_depth: f64,
}

impl Default for CraterReading {
    fn default() -> Self {
        Self {
            depth: f64::NAN,
            diameter: f64::NAN,
            axis_depth: f64::NAN,
        }
    }
}

/// A history row of the current state (totals of the whole bodies) after the step
/// `step` (`None` at t = 0).
fn row<D: SceneDimension>(
    sim: &Simulation<D, KernelChoice>,
    copies: f64,
    beta: &BetaMeasure,
    crater: CraterReading,
    step: Option<&StepInfo>,
    crater_measured: bool,
) -> HistoryRow {
    let c = Totals::of(sim, copies);
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
        kinetic: c.kinetic,
        internal: c.internal,
        momentum_z: c.momentum[2],
        crater_measured,
    }
}

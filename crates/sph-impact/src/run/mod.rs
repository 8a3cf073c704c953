//! # Running a scene
//!
//! [`run`] builds a [`Scene`], steps it to the end time and writes into the run
//! directory (docs/scenes.md, "Outputs"):
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

mod arrays;
mod error;
mod history;
mod measure;
mod plots;
mod progress;
mod snapshot;
mod summary;

pub use error::RunError;
pub use history::{HISTORY_COLUMNS, HistoryRow};
pub use summary::{BodyDamageSummary, RunSummary};

use crate::scene::{Built, Scene};
use arrays::Arrays;
use history::History;
use measure::{BetaMeasure, Measurer};
use progress::Progress;
use sph_diagnostics::{
    FULLY_DAMAGED, Pvd, damage_stats, ejecta_distribution, energy_histogram, phase_fractions,
    uniform_edges,
};
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
}

impl Default for RunOptions {
    fn default() -> Self {
        Self {
            threads: None,
            end_time: None,
            resolution_scale: 1.0,
            quiet: false,
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
    let scale = options.resolution_scale;
    let Built {
        simulation: mut sim,
        bodies,
    } = scene.build_scaled(scale)?;
    let setup = scene.diagnostic_setup(scale).map_err(|e| scene.locate(e))?;
    let mut measurer = Measurer {
        targets: setup.targets.iter().map(|&t| t as u16).collect(),
        projectile_mass: bodies[setup.projectile].mass,
        initial_target_momentum_z: bodies
            .iter()
            .enumerate()
            .filter(|(k, _)| *k != setup.projectile)
            .map(|(_, b)| b.mass * b.velocity[2])
            .sum(),
        setup: setup.clone(),
        top_offset: 0.0,
    };
    measurer.calibrate(&Arrays::of(&sim))?;
    let n = sim.state.particles.len();
    let interval = scene.output.interval(end_time);
    let history_every = scene.output.history_every.unwrap_or(1);
    let initial = sim.conserved();
    let mut history = History::create(&dir.join("history.csv"))?;
    let mut pvd = Pvd::new();
    let mut progress = Progress::new(options.quiet, end_time, n);

    let mut snapshot_index = 0;
    let mut crater = (f64::NAN, f64::NAN);
    let mut take_snapshot = |sim: &crate::Simulation<_, _>,
                             history: &mut History,
                             dt: f64,
                             crater: &mut (f64, f64)|
     -> Result<(), RunError> {
        let a = Arrays::of(sim);
        let (pressure, _) = sim.pressure_and_sound_speed();
        snapshot::write_snapshot(sim, &a, &pressure, dir, snapshot_index, &mut pvd)?;
        snapshot_index += 1;
        if let Some(c) = measurer.crater(&a)? {
            *crater = (c.depth, c.diameter);
        }
        history.push(row(sim, &measurer.beta(&a)?, *crater, dt, true))?;
        Ok(())
    };
    take_snapshot(&sim, &mut history, 0.0, &mut crater)?;
    let mut next_snapshot = interval.min(end_time);
    let t_step = Instant::now();
    let mut steps: u64 = 0;
    let tol = 1e-12 * end_time;
    while sim.state.time < end_time - tol {
        let target = next_snapshot.min(end_time);
        let info = sim
            .step(target - sim.state.time)
            .map_err(|e| RunError::Solver {
                time: sim.state.time,
                step: sim.state.step,
                message: e.to_string(),
            })?;
        steps += 1;
        let at_snapshot = sim.state.time >= next_snapshot - tol;
        let at_end = sim.state.time >= end_time - tol;
        if at_end {
            // Summation density is recomputed from the final positions for output.
            sim.sync_density().map_err(|e| RunError::Solver {
                time: sim.state.time,
                step: sim.state.step,
                message: e.to_string(),
            })?;
        }
        if at_snapshot || at_end {
            take_snapshot(&sim, &mut history, info.dt, &mut crater)?;
            while next_snapshot <= sim.state.time + tol {
                next_snapshot += interval;
            }
        } else if steps.is_multiple_of(history_every) {
            let a = Arrays::of(&sim);
            history.push(row(&sim, &measurer.beta(&a)?, crater, info.dt, false))?;
        }
        progress.update(sim.state.time, steps, false);
    }
    let stepping = t_step.elapsed().as_secs_f64();
    progress.finish(sim.state.time, steps);
    history.flush()?;

    // Final diagnostics.
    let a = Arrays::of(&sim);
    let view = a.view();
    let beta = measurer.beta(&a)?;
    let final_crater = measurer.crater(&a)?;
    let ejecta_bins = if measurer.active() {
        ejecta_distribution(
            &view,
            &measurer.criterion(),
            setup.impact_speed,
            setup.ejecta_bin,
        )?
    } else {
        Vec::new()
    };
    let damage = damage_stats(&view, FULLY_DAMAGED, 20)?
        .iter()
        .map(|d| BodyDamageSummary::of(d, &bodies))
        .collect();
    let projectile = setup.projectile as u16;
    let thermal = sim.materials[setup.projectile].thermal;
    let phase = match &thermal {
        Some(t) => Some(phase_fractions(
            &view,
            &[projectile],
            &a.specific_energy,
            &sph_diagnostics::PhaseThresholds {
                incipient_melting: t.incipient_melting_energy(),
                complete_melting: t.complete_melting_energy(),
                incipient_vaporisation: t.incipient_vaporisation_energy(),
                complete_vaporisation: t.complete_vaporisation_energy(),
            },
        )?),
        None => None,
    };
    let e_proj: Vec<f64> = (0..n)
        .filter(|&i| a.body[i] == projectile)
        .map(|i| a.specific_energy[i])
        .collect();
    let e_hi = e_proj
        .iter()
        .copied()
        .fold(0.0f64, f64::max)
        .max(thermal.map_or(0.0, |t| t.complete_vaporisation_energy() * 1.05))
        .max(1.0);
    let e_lo = e_proj.iter().copied().fold(0.0f64, f64::min);
    let e_hist = energy_histogram(
        &view,
        &[projectile],
        &a.specific_energy,
        uniform_edges(e_lo, e_hi, 60)?,
    )?;

    let plots = |name: &str| dir.join(name);
    plots::cross_section(
        &a,
        &sim.state.spacing0,
        setup.surface_z,
        projectile,
        &plots("crater_section.png"),
    )?;
    plots::histories(&history.rows, &plots("history.png"))?;
    plots::ejecta(&ejecta_bins, &plots("ejecta.png"))?;
    plots::projectile_energy(&e_hist, thermal.as_ref(), &plots("projectile_energy.png"))?;

    let last = sim.conserved();
    let c = final_crater.unwrap_or_default();
    let mut summary = RunSummary {
        crater_diameter_m: if measurer.active() {
            c.diameter
        } else {
            f64::NAN
        },
        bowl_diameter_m: if measurer.active() {
            c.bowl_diameter
        } else {
            f64::NAN
        },
        crater_depth_m: if measurer.active() { c.depth } else { f64::NAN },
        rim_height_m: if measurer.active() {
            c.rim_height
        } else {
            f64::NAN
        },
        beta: f64::NAN,
        beta_target: f64::NAN,
        ejecta_mass_kg: 0.0,
        ejecta_momentum_z_kg_m_s: 0.0,
        projectile_mass_kg: measurer.projectile_mass,
        impact_speed_m_s: setup.impact_speed,
        particles: n,
        steps,
        end_time_s: end_time,
        wall_time_s: 0.0,
        particle_steps_per_s: steps as f64 * n as f64 / stepping.max(1e-12),
        threads,
        resolution_scale: scale,
        version: env!("CARGO_PKG_VERSION").to_owned(),
        scene: serde_json::to_value(scene)
            .map_err(|e| RunError::Diagnostics(format!("scene as JSON: {e}")))?,
        scheme: sim.scheme.clone(),
        bodies,
        damage,
        projectile_phase_fractions: phase,
        ejecta_distribution: ejecta_bins,
        crater_profile: (c.profile.radius.clone(), c.profile.depth.clone()),
        initial,
        last,
        energy_error: last.energy() / initial.energy() - 1.0,
        timings: sim.timings,
        damage_events: sim.damage_events,
    };
    summary.set_beta(&beta);
    summary.wall_time_s = wall.elapsed().as_secs_f64();
    let path = dir.join("summary.json");
    let text = serde_json::to_string_pretty(&summary).map_err(|e| RunError::io(&path, e))?;
    std::fs::write(&path, text).map_err(|e| RunError::io(&path, e))?;
    Ok(summary)
}

/// A history row of the current state.
fn row<K: sph_kernel::Kernel>(
    sim: &crate::Simulation<sph_core::Dim3, K>,
    beta: &BetaMeasure,
    crater: (f64, f64),
    dt: f64,
    crater_measured: bool,
) -> HistoryRow {
    let c = sim.conserved();
    HistoryRow {
        t: sim.state.time,
        step: sim.state.step,
        dt,
        beta: beta.beta,
        beta_target: beta.beta_target,
        ejecta_mass: beta.ejecta_mass,
        crater_depth: crater.0,
        crater_diameter: crater.1,
        kinetic: c.kinetic,
        internal: c.internal,
        momentum_z: c.momentum.z,
        crater_measured,
    }
}

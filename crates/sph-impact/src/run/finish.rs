//! The end of a run: the final crater, β, ejecta distribution, damage and projectile
//! melt, the plots, and `summary.json`.

use crate::run::arrays::Arrays;
use crate::run::drive::{Job, Stepped};
use crate::run::error::RunError;
use crate::run::history::beta_change_last_half;
use crate::run::plots;
use crate::run::summary::{BodyDamageSummary, RunSummary, Totals};
use crate::scene::{GeometryKind, SceneDimension};
use sph_diagnostics::{
    FULLY_DAMAGED, damage_stats, ejecta_distribution, energy_histogram, phase_fractions,
    uniform_edges,
};

/// Measures the final state, draws the plots, writes `summary.json` and returns it.
pub(crate) fn summarise<D: SceneDimension>(
    job: &Job<'_>,
    run: Stepped<D>,
) -> Result<RunSummary, RunError> {
    let Stepped {
        sim,
        bodies,
        measurer,
        history,
        initial,
        steps,
        particle_steps,
        free_flight,
        stepping,
        wall_before,
        resumed_from,
        complete,
    } = run;
    let (dir, setup) = (job.dir, &measurer.setup);
    let n = sim.state.particles.len();
    let a = Arrays::of::<D>(&sim, job.scene.symmetry_copies());
    let view = a.view();
    let beta = measurer.beta(&a)?;
    let final_crater = measurer.crater(&a)?;
    let axis_depth = measurer.axis_depth(&a)?;
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

    let plot = |name: &str| dir.join(name);
    // A figure that cannot be drawn from the numbers (a NaN β, no crater) is a warning,
    // never a failed run once the work is done; a file that cannot be written is an error.
    let mut warnings = Vec::new();
    let mut drawn = |r: Result<(), RunError>| match r {
        Err(RunError::Plot { path, message }) => {
            warnings.push(format!("{path} not drawn: {message}"));
            Ok(())
        }
        other => other,
    };
    drawn(plots::cross_section(
        &a,
        &sim.state.spacing0,
        setup.surface_z,
        projectile,
        D::KIND,
        &plot("crater_section.png"),
    ))?;
    let mut skipped = Vec::new();
    drawn(plots::histories(&history.rows, &plot("history.png")).map(|s| skipped = s))?;
    drawn(plots::ejecta(&ejecta_bins, &plot("ejecta.png")))?;
    drawn(plots::projectile_energy(
        &e_hist,
        thermal.as_ref(),
        &plot("projectile_energy.png"),
    ))?;
    for s in skipped {
        warnings.push(format!(
            "history.png: {s} is undefined (NaN) throughout, not drawn"
        ));
    }
    if !job.options.quiet {
        for w in &warnings {
            eprintln!("warning: {w}");
        }
    }

    let last = Totals::of::<D>(&sim, job.scene.symmetry_copies());
    let c = final_crater.unwrap_or_default();
    let active = |x: f64| if measurer.active() { x } else { f64::NAN };
    // A 1-D target has no lateral extent: its crater is a depth alone.
    let lateral = |x: f64| {
        if job.scene.geometry == GeometryKind::Line {
            f64::NAN
        } else {
            active(x)
        }
    };
    let mut summary = RunSummary {
        complete,
        time_reached_s: sim.state.time,
        geometry: job.scene.geometry,
        totals_per: job.scene.geometry.per(),
        crater_diameter_m: lateral(c.diameter),
        crater_diameter_removed_m: lateral(c.diameter_removed),
        bowl_diameter_m: lateral(c.bowl_diameter),
        crater_depth_m: active(c.depth),
        crater_axis_depth_m: axis_depth,
        crater_axis_kernel_width_m: active(setup.axis_kernel_width),
        crater_axis_disc_radius_m: active(setup.axis_disc_radius),
        rim_height_m: active(c.rim_height),
        beta: f64::NAN,
        beta_target: f64::NAN,
        beta_pendulum: f64::NAN,
        beta_detached: measurer.beta_detached(&a)?,
        beta_change_last_half: f64::NAN,
        ejecta_mass_kg: 0.0,
        ejecta_momentum_z_kg_m_s: 0.0,
        projectile_mass_kg: measurer.projectile_mass,
        impact_speed_m_s: setup.impact_speed,
        particles: n,
        steps,
        end_time_s: job.end_time,
        wall_time_s: 0.0,
        particle_steps_per_s: particle_steps as f64 / stepping.max(1e-12),
        neighbours_per_particle: sim.timings.neighbour_entries as f64
            / sim.timings.derivative_evaluations as f64,
        threads: job.threads,
        resolution_scale: job.options.resolution_scale,
        version: env!("CARGO_PKG_VERSION").to_owned(),
        scene: serde_json::to_value(job.scene)
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
        density_floor_events: sim.density_floor_events,
        axis_crossings: sim.axis_crossings,
        axis_crossings_midpoint: sim.axis_crossings_midpoint,
        free_flight_particles: free_flight,
        resumed_from_s: resumed_from,
        warnings,
    };
    summary.set_beta(&beta);
    summary.beta_change_last_half = beta_change_last_half(&history.rows);
    summary.wall_time_s = wall_before + job.wall.elapsed().as_secs_f64();
    let path = dir.join("summary.json");
    let text = serde_json::to_string_pretty(&summary).map_err(|e| RunError::io(&path, e))?;
    crate::run::atomic::write_bytes(&path, text.as_bytes())?;
    Ok(summary)
}

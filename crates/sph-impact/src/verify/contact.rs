//! Multi-material contact, planar (docs/verification.md, "Multi-material contact, planar"):
//! an aluminium plate (Tillotson, the study's set, ρ0 = 2785) at 3.9 km/s into a basalt
//! plate at rest (Tillotson, the study's set, ρ0 = 2876), 1-D, hydrodynamic (the strength
//! adds ~2Y/3 ≈ 0.2 GPa to tens of GPa). The two materials meet at an unbonded interface
//! with b_ij = 0 (the Riemann interface velocity).
//!
//! Reference: the impedance match on the Tillotson Hugoniots (sph-eos `hugoniot`): the
//! contact velocity u with P_basalt(u) = P_Al(V − u). Measured before the shocks reach the
//! free ends: the median pressure between the two shock fronts (away from both by a fifth
//! of the gap), and the minimum density and finiteness over the run.

use super::column::{Planar, PlanarRun};
use super::outcome::{Outcome, Profile};
use super::setup::median;
use crate::{Material, SchemeConfig, SolverError};
use sph_core::{Dim1, ParticleInit, Particles};
use sph_eos::{EquationOfState, Tillotson, TillotsonParams, hugoniot};

const SPEED: f64 = 3900.0;
const LENGTH: f64 = 0.05;

/// The impedance-match state: (contact velocity, pressure).
fn impedance_match(al: &Tillotson, ba: &Tillotson) -> Result<(f64, f64), SolverError> {
    let bad = |e: sph_eos::EosError| SolverError::Material(e.to_string());
    let (rho_al, rho_ba) = (
        al.reference_density().unwrap_or(2785.0),
        ba.reference_density().unwrap_or(2876.0),
    );
    // f(u) = P_basalt(u) − P_Al(V − u) increases with u; bisection on (0, V).
    let f = |u: f64| -> Result<f64, SolverError> {
        Ok(hugoniot(ba, rho_ba, u).map_err(bad)?.pressure
            - hugoniot(al, rho_al, SPEED - u).map_err(bad)?.pressure)
    };
    let (mut lo, mut hi) = (1.0, SPEED - 1.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if f(mid)? < 0.0 { lo = mid } else { hi = mid }
    }
    let u = 0.5 * (lo + hi);
    Ok((u, hugoniot(ba, rho_ba, u).map_err(bad)?.pressure))
}

/// Runs with `n` particles per plate (plates 5 cm long), in 1-D (then also the 3-D
/// sphere) or as an RZ column (the profile on the axis).
pub(crate) fn run(
    n: usize,
    scheme: SchemeConfig,
    geometry: Planar,
) -> Result<Outcome, SolverError> {
    // The 3-D part keeps the solver's n_target (the 1-D default of 4 is for this planar
    // part only) unless the caller changed it from 4.
    let mut sphere_scheme = scheme.clone();
    if sphere_scheme.n_target == 4.0 {
        sphere_scheme.n_target = SchemeConfig::default().n_target;
    }
    let bad = |e: sph_eos::EosError| SolverError::Material(e.to_string());
    let al = Tillotson::new(TillotsonParams::aluminium_study()).map_err(bad)?;
    let ba = Tillotson::new(TillotsonParams::basalt_study()).map_err(bad)?;
    let (u_contact, p_match) = impedance_match(&al, &ba)?;
    let (rho_al, rho_ba) = (2785.0, 2876.0);
    let dx = LENGTH / n as f64;
    let mut p = Particles::<Dim1>::new();
    for k in 0..n {
        let s = (k as f64 + 0.5) * dx;
        p.push(ParticleInit {
            position: -s,
            velocity: SPEED,
            mass: rho_al * dx,
            density: rho_al,
            specific_energy: 0.0,
            smoothing_length: scheme.n_target * dx,
            material: 0,
        });
        // Equal spacing on both sides; the basalt particles carry its own density.
        p.push(ParticleInit {
            position: s,
            velocity: 0.0,
            mass: rho_ba * dx,
            density: rho_ba,
            specific_energy: 0.0,
            smoothing_length: scheme.n_target * dx,
            material: 1,
        });
    }
    let mats = vec![
        Material::fluid("aluminium (Tillotson, study)", al),
        Material::fluid("basalt (Tillotson, study)", ba),
    ];
    let mut sim = PlanarRun::new(p, mats, scheme, dx, geometry)?;
    let us_ba = hugoniot(&ba, rho_ba, u_contact).map_err(bad)?.shock_speed;
    let us_al = hugoniot(&al, rho_al, SPEED - u_contact)
        .map_err(bad)?
        .shock_speed;
    // Stop when the faster shock has run 60 % of a plate (relative to its material).
    let t_end = 0.6 * LENGTH / us_ba.max(us_al);
    let mut min_rho = f64::INFINITY;
    let wall = std::time::Instant::now();
    let steps = sim.run_until(t_end, |rho| {
        min_rho = rho.iter().cloned().fold(min_rho, f64::min);
    })?;
    let prof = sim.profile();
    let (x, press) = (&prof.x, &prof.p);
    // Fronts (lab frame): the contact moves at u; the basalt shock at U_s,ba; the Al shock
    // moves back into Al at V − U_s,al. The contact started at x = 0.
    let (x_ba, x_al) = (us_ba * t_end, (SPEED - us_al) * t_end);
    let gap = x_ba - x_al;
    let zone: Vec<f64> = (0..x.len())
        .filter(|&k| x[k] > x_al + 0.2 * gap && x[k] < x_ba - 0.2 * gap)
        .map(|k| press[k])
        .collect();
    let p_num = median(zone);
    let v_sorted = &prof.v;
    let u_num = median(
        (0..x.len())
            .filter(|&k| x[k] > x_al + 0.2 * gap && x[k] < x_ba - 0.2 * gap)
            .map(|k| v_sorted[k])
            .collect(),
    );
    let mut out = Outcome {
        problem: match geometry {
            Planar::OneD => "contact".into(),
            Planar::Rz { .. } => "contact (rz)".into(),
        },
        ..Default::default()
    };
    out.set("impact_speed", SPEED);
    out.set("contact_velocity_exact", u_contact);
    out.set("pressure_exact", p_match);
    out.set("pressure", p_num);
    out.set("pressure_error_relative", p_num / p_match - 1.0);
    out.set("contact_velocity", u_num);
    out.set("contact_velocity_error_relative", u_num / u_contact - 1.0);
    out.set("shock_speed_basalt_exact", us_ba);
    out.set("shock_speed_aluminium_exact", us_al);
    out.set("min_density_over_run", min_rho);
    out.set("t_end", t_end);
    out.set("steps", steps as f64);
    out.set("particles", sim.particles() as f64);
    out.set_axis_crossings(sim.axis_crossings());
    out.set("resolution", n as f64);
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    let profile = Profile {
        columns: ["x", "rho", "v", "p"].map(String::from).to_vec(),
        rows: (0..x.len())
            .map(|k| vec![x[k], prof.rho[k], prof.v[k], press[k]])
            .collect(),
    };
    out.profile = profile;
    if geometry != Planar::OneD {
        return Ok(out);
    }
    // The 3-D sphere into a block with the study's full material models, 12 spacings
    // across the sphere (the study's 0.5 mm).
    let sc = super::contact3d::run(12, sphere_scheme)?;
    out.set("sphere_particles", sc.particles as f64);
    out.set("sphere_steps", sc.steps as f64);
    out.set("sphere_t_end", sc.t_end);
    out.set("sphere_min_density_ratio", sc.min_density_ratio);
    out.set("sphere_dt_first", sc.dt_first);
    out.set("sphere_dt_min", sc.dt_min);
    out.set("sphere_dt_last", sc.dt_last);
    out.set("sphere_peak_pressure_contact", sc.peak_pressure);
    out.set(
        "sphere_peak_pressure_over_impedance_match",
        sc.peak_pressure / p_match,
    );
    out.set("sphere_target_fully_damaged_fraction", sc.damaged_fraction);
    out.set("sphere_wall_time_s", sc.wall_time_s);
    Ok(out)
}

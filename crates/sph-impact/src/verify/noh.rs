//! Noh implosions (docs/verification.md, "Noh"): γ = 5/3, ρ0 = 1, inflow speed 1, P0 = 1e-6,
//! t = 0.6; exact shock at r = 0.2.
//!
//! * planar: 1-D, particles on [0, 1], reflecting wall at x = 0, free far end;
//! * cylindrical / spherical: cubic lattice filling the disc / ball of radius 1 (no
//!   particle at the centre), free outer surface.
//!
//! Norms over r ∈ [0.05, 0.35] (the window excludes the wall-heating zone), weights
//! m/ρ; shock where the density crosses (ρ_pre + ρ2)/2; wall heating reported as the
//! innermost particles' ρ/ρ2 and e/0.5.

use super::outcome::{Outcome, Profile};
use super::radial::{RADIAL_COLUMNS, Radial, push_exact_curves};
use super::setup::{gas, last_crossing, particle, simulation};
use crate::{Boundary, SchemeConfig, Simulation, SolverError};
use sph_core::{Dim1, Dim2, Dim3, Dimension, Particles, Vector};
use sph_diagnostics::exact::Noh;
use sph_geometry::{Sphere, cubic_lattice};
use sph_kernel::KernelChoice;

const GAMMA: f64 = 5.0 / 3.0;
const T_END: f64 = 0.6;
const P0: f64 = 1e-6;

fn exact(dim: u32) -> Result<Noh, SolverError> {
    Noh::new(dim, GAMMA, 1.0, 1.0).map_err(|e| SolverError::Material(e.to_string()))
}

/// Planar Noh with `n` particles across [0, 1].
pub(crate) fn run_planar(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    finish("noh-planar", 1, n, 1.0 / n as f64, planar_1d(n, scheme)?)
}

/// The 1-D planar set-up with `n` particles across [0, 1], not yet run.
fn planar_1d(
    n: usize,
    scheme: SchemeConfig,
) -> Result<Simulation<Dim1, KernelChoice>, SolverError> {
    let dx = 1.0 / n as f64;
    let mut p = Particles::<Dim1>::new();
    for k in 0..n {
        p.push(particle(
            (k as f64 + 0.5) * dx,
            -1.0,
            dx,
            1.0,
            P0,
            GAMMA,
            scheme.n_target * dx,
        ));
    }
    simulation(
        p,
        gas(GAMMA)?,
        scheme,
        vec![Boundary::Wall {
            point: 0.0,
            normal: 1.0,
        }],
        None,
    )
}

/// Planar Noh along z in a 2-D column: `n` rows on z ∈ [0, 1] and n/4 columns out to
/// R = n/4 spacings, moving at −1 in z; the walls z = 0 and r = R reflect (the flow stays
/// one-dimensional, along z), the top is free. With `rz` the column is axisymmetric about
/// r = 0, each particle a ring of mass ρ0 Δx² r per radian; without, it is plane 2-D
/// (mass ρ0 Δx² per unit depth) with a third wall at r = 0. Profile and norms along z,
/// against the planar exact solution.
pub(crate) fn run_planar_column(
    n: usize,
    mut scheme: SchemeConfig,
    rz: bool,
) -> Result<Outcome, SolverError> {
    use sph_core::glam::DVec2;
    scheme.geometry = if rz {
        crate::Geometry::Axisymmetric
    } else {
        crate::Geometry::Cartesian
    };
    let dx = 1.0 / n as f64;
    let columns = (n / 4).max(4);
    let r_wall = columns as f64 * dx;
    let mut p = Particles::<Dim2>::new();
    for a in 0..columns {
        for b in 0..n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            p.push(particle(
                x,
                DVec2::new(0.0, -1.0),
                if rz { dx * dx * x.x } else { dx * dx },
                1.0,
                P0,
                GAMMA,
                scheme.n_target * dx,
            ));
        }
    }
    let mut walls = vec![
        Boundary::Wall {
            point: DVec2::ZERO,
            normal: DVec2::Y,
        },
        Boundary::Wall {
            point: DVec2::new(r_wall, 0.0),
            normal: -DVec2::X,
        },
    ];
    if !rz {
        walls.push(Boundary::Wall {
            point: DVec2::ZERO,
            normal: DVec2::X,
        });
    }
    let name = if rz {
        "noh-planar (rz)"
    } else {
        "noh-planar (plane column)"
    };
    let mut one_d = scheme.clone();
    one_d.geometry = crate::Geometry::Cartesian;
    let sim = simulation(p, gas(GAMMA)?, scheme, walls, None)?;
    let (mut out, column) = finish_with(name, 1, n, dx, sim, |s| Radial::along(s, 1))?;
    // The comparison (RZ reproduces the 1-D result): the same problem in 1-D
    // with the same scheme, and the relative L1 difference of the two density profiles
    // along z, each averaged over the cross-section in bins one initial spacing wide.
    let (line, reference) = finish_with("noh-planar", 1, n, dx, planar_1d(n, one_d)?, Radial::of)?;
    out.set("l1_rho_1d", line.get("l1_rho").unwrap_or(f64::NAN));
    out.set(
        "rho_profile_difference_from_1d",
        column.binned_difference(&reference, dx, 0.05, 0.35),
    );
    Ok(out)
}

/// Cylindrical Noh with `n` lattice spacings across the radius.
pub(crate) fn run_cylindrical(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    run_radial::<Dim2>("noh-cylindrical", n, scheme)
}

/// Spherical Noh with `n` lattice spacings across the radius.
pub(crate) fn run_spherical(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    run_radial::<Dim3>("noh-spherical", n, scheme)
}

/// Spherical Noh in axisymmetric RZ: a square lattice with `n` spacings across the
/// radius on the half-disc r > 0, r² + z² ≤ 1, each particle a ring of mass 2π ρ0 Δx² r
/// (stored per radian), all moving toward the centre at unit speed.
pub(crate) fn run_spherical_rz(n: usize, mut scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    scheme.geometry = crate::Geometry::Axisymmetric;
    let dx = 1.0 / n as f64;
    let mut p = Particles::<Dim2>::new();
    for a in 0..n {
        for b in 0..2 * n {
            let x = sph_core::glam::DVec2::new((a as f64 + 0.5) * dx, -1.0 + (b as f64 + 0.5) * dx);
            if x.length() <= 1.0 {
                let v = x * (-1.0 / x.length());
                p.push(particle(
                    x,
                    v,
                    dx * dx * x.x,
                    1.0,
                    P0,
                    GAMMA,
                    scheme.n_target * dx,
                ));
            }
        }
    }
    let sim = simulation(p, gas(GAMMA)?, scheme, Vec::new(), None)?;
    finish("noh-spherical (rz)", 3, n, dx, sim)
}

fn run_radial<D: Dimension>(
    name: &str,
    n: usize,
    scheme: SchemeConfig,
) -> Result<Outcome, SolverError> {
    let dx = 1.0 / n as f64;
    let ball =
        Sphere::new(D::Vector::ZERO, 1.0).map_err(|e| SolverError::Material(e.to_string()))?;
    let body = cubic_lattice(&ball, dx, 1.0).map_err(|e| SolverError::Material(e.to_string()))?;
    let mut p = Particles::<D>::new();
    for (x, m) in body.positions.iter().zip(&body.masses) {
        let v = *x * (-1.0 / x.norm());
        p.push(particle(*x, v, *m, 1.0, P0, GAMMA, scheme.n_target * dx));
    }
    let sim = simulation(p, gas(GAMMA)?, scheme, Vec::new(), None)?;
    finish(name, D::DIM as u32, n, dx, sim)
}

fn finish<D: Dimension>(
    name: &str,
    dim: u32,
    n: usize,
    dx: f64,
    sim: Simulation<D, KernelChoice>,
) -> Result<Outcome, SolverError> {
    Ok(finish_with(name, dim, n, dx, sim, Radial::of)?.0)
}

/// [`finish`] with the profile taken by `profile` (the exact solution's geometry is
/// `dim`, the run's may be larger); also returns that profile.
fn finish_with<D: Dimension>(
    name: &str,
    dim: u32,
    n: usize,
    dx: f64,
    mut sim: Simulation<D, KernelChoice>,
    profile: fn(&Simulation<D, KernelChoice>) -> Radial,
) -> Result<(Outcome, Radial), SolverError> {
    let c0 = sim.conserved();
    let wall = std::time::Instant::now();
    let steps = sim.run_until(T_END, |_, _| {})?;
    let wall = wall.elapsed().as_secs_f64();
    let c1 = sim.conserved();
    let noh = exact(dim)?;
    let rad = profile(&sim);
    let ex: Vec<_> = rad.r.iter().map(|&r| noh.state(r, T_END)).collect();
    let ex_cols: Vec<(f64, f64, f64, f64)> = ex
        .iter()
        .map(|s| (s.density, s.velocity, s.pressure, s.specific_energy))
        .collect();

    let mut out = Outcome::for_run(name, sim.state.particles.len(), n, Some(T_END), steps, wall);
    out.set_axis_crossings(sim.axis_crossing_counts());
    let window = |k: usize| rad.r[k] >= 0.05 && rad.r[k] <= 0.35;
    rad.set_norms(&mut out, &ex, window, true);
    // Shock: the outermost crossing of the mid density, on radially binned data in 2-D/3-D.
    let rho2 = noh.post_shock_density();
    let r_s = noh.shock_radius(T_END);
    let pre = noh.state(r_s * (1.0 + 1e-9), T_END).density;
    let level = 0.5 * (pre + rho2);
    let (rb, db) = if D::DIM == 1 {
        (rad.r.clone(), rad.rho.clone())
    } else {
        rad.binned_density(dx)
    };
    if let Some(xs) = last_crossing(&rb, &db, level) {
        out.set("shock_position", xs);
        out.set("shock_position_exact", r_s);
        // Local spacing at the crossing: the initial spacing compressed to the mid
        // density, Δx (ρ0/ρ)^(1/d) with ρ0 = 1.
        out.set(
            "shock_error_in_spacings",
            (xs - r_s) / (dx * level.powf(-1.0 / dim as f64)),
        );
    }
    // Wall heating: the innermost particles (r < 1.5 initial spacings... at least 1).
    let inner: Vec<usize> = (0..rad.r.len()).filter(|&k| rad.r[k] < 0.05).collect();
    let inner = if inner.is_empty() { vec![0] } else { inner };
    let mean = |v: &Vec<f64>| inner.iter().map(|&k| v[k]).sum::<f64>() / inner.len() as f64;
    out.set("centre_density_over_rho2", mean(&rad.rho) / rho2);
    out.set("centre_energy_over_half", mean(&rad.e) / 0.5);
    out.set(
        "energy_change_relative",
        (c1.energy() - c0.energy()) / c0.energy(),
    );
    // Momentum balance: change minus what the boundaries delivered, relative to Σ m|v|.
    let scale = c0.mass;
    out.set(
        "momentum_balance_relative",
        (c1.momentum - c0.momentum - sim.boundary_impulse).norm() / scale,
    );
    out.profile = Profile {
        columns: RADIAL_COLUMNS.map(String::from).to_vec(),
        rows: rad.rows(&ex_cols),
    };
    push_exact_curves(&mut out, 1.0, |r| noh.state(r, T_END));
    Ok((out, rad))
}

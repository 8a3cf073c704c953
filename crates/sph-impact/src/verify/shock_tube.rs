//! 1-D Riemann problems (docs/verification.md, "1-D Riemann problems"): Sod, Toro 123, Toro 3.
//!
//! Set-up: domain [0, 1], interface at 0.5, ideal gas γ = 1.4, equal-mass particles
//! (spacing ratio ρ_L/ρ_R), reflecting walls at both ends for Sod and Toro 3, free ends
//! for Toro 123 (the gas moves outward; the end rarefactions do not reach the centre by
//! t = 0.15). The initial jump is not smoothed.

use super::outcome::{Outcome, Profile};
use super::setup::{gas, last_crossing, median, particle, simulation};
use crate::solver::{Boundary, SolverError};
use sph_core::{Dim1, Particles};
use sph_diagnostics::error_norms;
use sph_diagnostics::exact::{GasState, RiemannSolution};

/// Which tube.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Tube {
    Sod,
    Toro123,
    Toro3,
}

struct Spec {
    name: &'static str,
    left: [f64; 3],
    right: [f64; 3],
    t_end: f64,
    walls: bool,
}

fn spec(t: Tube) -> Spec {
    match t {
        Tube::Sod => Spec {
            name: "sod",
            left: [1.0, 0.0, 1.0],
            right: [0.125, 0.0, 0.1],
            t_end: 0.2,
            walls: true,
        },
        Tube::Toro123 => Spec {
            name: "toro123",
            left: [1.0, -2.0, 0.4],
            right: [1.0, 2.0, 0.4],
            t_end: 0.15,
            walls: false,
        },
        Tube::Toro3 => Spec {
            name: "toro3",
            left: [1.0, 0.0, 1000.0],
            right: [1.0, 0.0, 0.01],
            t_end: 0.012,
            walls: true,
        },
    }
}

/// Runs a tube with `n` particles in the left state for Sod (n/8 in the right), `n`
/// particles across [0, 1] for the others.
pub(crate) fn run(tube: Tube, n: usize, sch: crate::SchemeConfig) -> Result<Outcome, SolverError> {
    let s = spec(tube);
    if tube == Tube::Sod && !n.is_multiple_of(8) {
        // The right state holds n/8 equal-mass particles in [0.5, 1]: any other n puts a
        // particle on the wall and compresses the right state.
        return Err(SolverError::BadConfig {
            field: "resolution",
            value: n as f64,
            reason: "Sod needs a multiple of 8 (n particles left of the jump, n/8 right of it)",
        });
    }
    let gamma = 1.4;
    let (rl, rr) = (s.left[0], s.right[0]);
    // Equal masses: dx_L/dx_R = ρ_R/ρ_L.
    let n_left = if tube == Tube::Sod { n } else { n / 2 };
    let dx_l = 0.5 / n_left as f64;
    let dx_r = dx_l * rl / rr;
    let mass = rl * dx_l;
    // The jump is sharp (smoothing it over a coarse spacing made every metric worse).
    let n_right = (0.5 / dx_r).round() as usize;
    let positions: Vec<f64> = (0..n_left)
        .map(|k| (k as f64 + 0.5) * dx_l)
        .chain((0..n_right).map(|k| 0.5 + (k as f64 + 0.5) * dx_r))
        .collect();
    let profile = |x: f64, a: f64, b: f64| if x < 0.5 { a } else { b };
    let mut p = Particles::<Dim1>::new();
    for &x in &positions {
        let rho = profile(x, rl, rr);
        let h = sch.n_target * mass / rho;
        p.push(particle(
            x,
            profile(x, s.left[1], s.right[1]),
            mass,
            rho,
            profile(x, s.left[2], s.right[2]),
            gamma,
            h,
        ));
    }
    let walls = if s.walls {
        Boundary::slab(0.0, 1.0)
    } else {
        Vec::new()
    };
    let mut sim = simulation(p, gas(gamma)?, sch, walls, None)?;
    let c0 = sim.conserved();
    let (mut min_p, mut min_rho) = (f64::INFINITY, f64::INFINITY);
    let track = |sim: &crate::Simulation<Dim1, _>, min_p: &mut f64, min_rho: &mut f64| {
        let (pr, _) = sim.pressure_and_sound_speed();
        *min_p = pr.iter().cloned().fold(*min_p, f64::min);
        *min_rho = sim
            .state
            .particles
            .density
            .iter()
            .cloned()
            .fold(*min_rho, f64::min);
    };
    track(&sim, &mut min_p, &mut min_rho);
    let wall = std::time::Instant::now();
    let steps = sim.run_until(s.t_end, |sim, _| track(sim, &mut min_p, &mut min_rho))?;
    let wall = wall.elapsed().as_secs_f64();
    let c1 = sim.conserved();

    let exact = RiemannSolution::solve(
        GasState {
            density: rl,
            velocity: s.left[1],
            pressure: s.left[2],
        },
        GasState {
            density: rr,
            velocity: s.right[1],
            pressure: s.right[2],
        },
        gamma,
    )
    .map_err(|e| SolverError::Material(e.to_string()))?;
    let sample = |x: f64| exact.sample((x - 0.5) / s.t_end);

    // Profile sorted by x.
    let (pr, _) = sim.pressure_and_sound_speed();
    let pa = &sim.state.particles;
    let mut idx: Vec<usize> = (0..pa.len()).collect();
    idx.sort_by(|&a, &b| pa.position[a].total_cmp(&pa.position[b]));
    let x: Vec<f64> = idx.iter().map(|&i| pa.position[i]).collect();
    let rho: Vec<f64> = idx.iter().map(|&i| pa.density[i]).collect();
    let v: Vec<f64> = idx.iter().map(|&i| pa.velocity[i]).collect();
    let pp: Vec<f64> = idx.iter().map(|&i| pr[i]).collect();
    let e: Vec<f64> = idx.iter().map(|&i| pa.specific_energy[i]).collect();
    let w: Vec<f64> = idx.iter().map(|&i| pa.mass[i] / pa.density[i]).collect();
    let ex: Vec<GasState> = x.iter().map(|&xx| sample(xx)).collect();
    let ex_rho: Vec<f64> = ex.iter().map(|g| g.density).collect();
    let ex_v: Vec<f64> = ex.iter().map(|g| g.velocity).collect();
    let ex_p: Vec<f64> = ex.iter().map(|g| g.pressure).collect();
    let ex_e: Vec<f64> = ex
        .iter()
        .map(|g| g.pressure / ((gamma - 1.0) * g.density))
        .collect();
    // Compare only where the exact solution is defined at t (the gas that started in
    // [0, 1] minus what free ends let expand).
    let inside = |k: usize| x[k] > 0.0 && x[k] < 1.0;

    let mut out = Outcome::for_run(s.name, pa.len(), n, Some(s.t_end), steps, wall);
    for (name, num, exv) in [
        ("rho", &rho, &ex_rho),
        ("v", &v, &ex_v),
        ("p", &pp, &ex_p),
        ("e", &e, &ex_e),
    ] {
        let nrm = error_norms(num, exv, &w, inside);
        out.set(&format!("l1_{name}"), nrm.l1);
        out.set(&format!("linf_{name}"), nrm.linf);
    }
    out.set("min_pressure_over_run", min_p);
    out.set("min_density_over_run", min_rho);
    // Momentum balance: change minus the wall impulse, relative to Σ m c_L (the momentum
    // scale of the flow).
    let scale = c0.mass * (gamma * s.left[2] / rl).sqrt();
    out.set(
        "momentum_balance_relative",
        (c1.momentum - c0.momentum - sim.boundary_impulse).abs() / scale,
    );
    out.set(
        "energy_change_relative",
        (c1.energy() - c0.energy()) / c0.energy(),
    );
    out.set("exact_p_star", exact.p_star);
    out.set("exact_u_star", exact.u_star);

    // Star plateau: between the rarefaction tail and the shock, away from the contact
    // (±3 post-shock spacings) and from both ends of the plateau (10 % of its width).
    if let Some(shock) = exact.right_shock_speed() {
        let cl = (gamma * s.left[2] / rl).sqrt();
        let c_star = cl * (exact.p_star / s.left[2]).powf((gamma - 1.0) / (2.0 * gamma));
        let tail = 0.5 + s.t_end * (exact.u_star - c_star);
        let front = 0.5 + s.t_end * shock;
        let contact = 0.5 + s.t_end * exact.u_star;
        let band = 3.0 * mass / exact.rho_star_right;
        let margin = 0.1 * (front - tail);
        let sel: Vec<usize> = (0..x.len())
            .filter(|&k| {
                x[k] > tail + margin && x[k] < front - margin && (x[k] - contact).abs() > band
            })
            .collect();
        let p_star = median(sel.iter().map(|&k| pp[k]).collect());
        let u_star = median(sel.iter().map(|&k| v[k]).collect());
        out.set("p_star", p_star);
        out.set("u_star", u_star);
        out.set(
            "p_star_error_relative",
            (p_star - exact.p_star) / exact.p_star,
        );
        out.set(
            "u_star_error_relative",
            (u_star - exact.u_star) / exact.u_star,
        );
        // Shock: last crossing of the mid density between the shocked and unshocked gas.
        let level = 0.5 * (exact.rho_star_right + rr);
        if let Some(xs) = last_crossing(&x, &rho, level) {
            out.set("shock_position", xs);
            out.set("shock_position_exact", front);
            // The local spacing at the measured point: m/ρ at the half-height density.
            let spacing = mass / level;
            out.set("shock_error_in_spacings", (xs - front) / spacing);
            out.set("shock_error_relative", (xs - front) / front);
        }
    }

    out.profile = Profile {
        columns: [
            "x",
            "rho",
            "v",
            "p",
            "e",
            "rho_exact",
            "v_exact",
            "p_exact",
            "e_exact",
        ]
        .map(String::from)
        .to_vec(),
        rows: (0..x.len())
            .map(|k| {
                vec![
                    x[k], rho[k], v[k], pp[k], e[k], ex_rho[k], ex_v[k], ex_p[k], ex_e[k],
                ]
            })
            .collect(),
    };
    let dense: Vec<f64> = (0..=2000).map(|k| k as f64 / 2000.0).collect();
    for (name, f) in [("rho", 0usize), ("v", 1), ("p", 2)] {
        let pts = dense
            .iter()
            .map(|&xx| {
                let g = sample(xx);
                (xx, [g.density, g.velocity, g.pressure][f])
            })
            .collect();
        out.exact.push((name.to_string(), pts));
    }
    Ok(out)
}

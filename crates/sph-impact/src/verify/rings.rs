//! Colliding rubber rings (docs/verification.md, "Colliding rubber rings"; Monaghan 2000; Gray,
//! Monaghan & Swift 2001), Spheral's set in SI: rings r_in = 3 cm, r_out = 4 cm centred at
//! x = ∓5 cm, ρ0 = 1010 kg/m³, c0 = 852 m/s, K = ρ0c0² = 733 MPa, G = 0.22 K (linear elastic EOS,
//! no yield), moving at ±0.059 c0 = 50.3 m/s toward each other; first contact at 198.9 µs.
//! 2-D plane strain, `n` particles across the ring wall on concentric circles. The rings
//! are two bodies (two materials with the same properties), so their contact is an
//! unbonded interface.
//!
//! Two runs to 1600 µs: with the tensor artificial stress (ε = 0.3, n = 4) and without.
//! Measured: the friends-of-friends fragment count (link 1.5 Δp) over time, the smallest
//! pair distance in spacings, the rebound speed of each ring, and the energy and momentum
//! histories.

use super::outcome::{Outcome, Panel, Picture, Profile};
use super::setup::elastic_solid;
use super::setup::{closest_pair, pieces, simulation};
use crate::{Material, SchemeConfig, Simulation, SolverError};
use sph_core::glam::DVec2;
use sph_core::{Dim2, ParticleInit, Particles};
use sph_kernel::KernelChoice;
use sph_riemann::{ArtificialStress, ArtificialStressForm};

const RHO: f64 = 1010.0;
const C0: f64 = 852.0;
const R_IN: f64 = 0.03;
const R_OUT: f64 = 0.04;
const CENTRE: f64 = 0.05;
const T_END: f64 = 1600.0e-6;

/// Two rings with `n` particles across the wall.
fn rings(n: usize, scheme: SchemeConfig) -> Result<Simulation<Dim2, KernelChoice>, SolverError> {
    let bulk = RHO * C0 * C0;
    let (eos, strength) = elastic_solid(RHO, bulk, 0.22 * bulk, 1.0e15, None)?;
    let dx = (R_OUT - R_IN) / n as f64;
    let speed = 0.059 * C0;
    let mut p = Particles::<Dim2>::new();
    for (side, material) in [(-1.0, 0u16), (1.0, 1u16)] {
        let centre = DVec2::new(side * CENTRE, 0.0);
        for k in 0..n {
            let r = R_IN + (k as f64 + 0.5) * dx;
            let count = (2.0 * std::f64::consts::PI * r / dx).round() as usize;
            // Each particle holds its share of the layer's annulus area.
            let mass = RHO * std::f64::consts::PI * 2.0 * r * dx / count as f64;
            for j in 0..count {
                let phi =
                    2.0 * std::f64::consts::PI * (j as f64 + 0.5 * (k % 2) as f64) / count as f64;
                p.push(ParticleInit {
                    position: centre + DVec2::new(r * phi.cos(), r * phi.sin()),
                    velocity: DVec2::new(-side * speed, 0.0),
                    mass,
                    density: RHO,
                    specific_energy: 0.0,
                    smoothing_length: scheme.n_target * dx,
                    material,
                });
            }
        }
    }
    let count = p.len();
    simulation(
        p,
        vec![
            Material::solid("rubber ring A", eos, strength),
            Material::solid("rubber ring B", eos, strength),
        ],
        scheme,
        Vec::new(),
        Some(vec![dx; count]),
    )
}

/// Histories of one run.
#[derive(Default)]
struct RingRun {
    t: Vec<f64>,
    kinetic: Vec<f64>,
    internal: Vec<f64>,
    momentum_x: Vec<f64>,
    fragments: Vec<f64>,
    max_fragments: usize,
    min_distance: f64,
    rebound_speed: f64,
    energy_change: f64,
    snapshots: Vec<(f64, Vec<f64>, Vec<f64>)>,
    steps: u64,
    particles: usize,
}

fn run_case(n: usize, scheme: SchemeConfig) -> Result<RingRun, SolverError> {
    let mut sim = rings(n, scheme)?;
    let dx = (R_OUT - R_IN) / n as f64;
    let c0 = sim.conserved();
    let mut out = RingRun {
        min_distance: f64::INFINITY,
        particles: sim.state.particles.len(),
        ..Default::default()
    };
    // Snapshot times lie on the 10 µs sample grid.
    let shots = [200.0e-6, 400.0e-6, 800.0e-6, T_END];
    let samples = 160;
    for k in 1..=samples {
        let t = T_END * k as f64 / samples as f64;
        out.steps += sim.run_until(t, |_, _| {})?;
        let p = &sim.state.particles;
        let count = pieces(p, 1.5 * dx);
        out.max_fragments = out.max_fragments.max(count);
        out.fragments.push(count as f64);
        out.min_distance = out.min_distance.min(closest_pair(p) / dx);
        let c = sim.conserved();
        out.t.push(t);
        out.kinetic.push(c.kinetic);
        out.internal.push(c.internal);
        out.momentum_x.push(c.momentum.x);
        if shots.iter().any(|&s| (s - t).abs() < 1e-9) {
            out.snapshots.push((
                t,
                p.position.iter().map(|x| x.x).collect(),
                p.position.iter().map(|x| x.y).collect(),
            ));
        }
    }
    let c1 = sim.conserved();
    out.energy_change = (c1.energy() - c0.energy()) / c0.energy();
    // Rebound: the centre-of-mass speed of the right ring (material 1), outward positive.
    let p = &sim.state.particles;
    let (mut m, mut mv) = (0.0, 0.0);
    for i in 0..p.len() {
        if p.material[i] == 1 {
            m += p.mass[i];
            mv += p.mass[i] * p.velocity[i].x;
        }
    }
    out.rebound_speed = mv / m;
    Ok(out)
}

/// Runs with and without artificial stress, `n` particles across each ring wall.
pub(crate) fn run(n: usize, scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    let wall = std::time::Instant::now();
    let with = ArtificialStress {
        epsilon: 0.3,
        exponent: 4,
        form: ArtificialStressForm::Principal,
        cap: None,
    };
    let mut s_with = scheme.clone();
    s_with.artificial_stress = with;
    let mut s_without = scheme;
    s_without.artificial_stress = ArtificialStress {
        epsilon: 0.0,
        ..with
    };
    let a = run_case(n, s_with)?;
    let b = run_case(n, s_without)?;
    let mut out = Outcome::for_run("rings", a.particles, n, Some(T_END), a.steps + b.steps, 0.0);
    let ke0 = a.kinetic.first().copied().unwrap_or(f64::NAN);
    let speed = 0.059 * C0;
    for (tag, r) in [("with_stress", &a), ("without_stress", &b)] {
        out.set(&format!("max_fragments_{tag}"), r.max_fragments as f64);
        out.set(
            &format!("final_fragments_{tag}"),
            *r.fragments.last().unwrap_or(&f64::NAN),
        );
        out.set(&format!("min_pair_distance_{tag}"), r.min_distance);
        out.set(
            &format!("rebound_speed_over_initial_{tag}"),
            r.rebound_speed / speed,
        );
        out.set(&format!("energy_change_relative_{tag}"), r.energy_change);
        let p_max = r.momentum_x.iter().fold(0.0f64, |m, p| m.max(p.abs()));
        out.set(
            &format!("momentum_x_max_over_ring_momentum_{tag}"),
            p_max / (0.5 * (2.0 * ke0 / speed)),
        );
    }
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    out.profile = Profile {
        columns: [
            "t",
            "ke_with",
            "internal_with",
            "fragments_with",
            "ke_without",
            "internal_without",
            "fragments_without",
        ]
        .map(String::from)
        .to_vec(),
        rows: (0..a.t.len())
            .map(|k| {
                vec![
                    a.t[k],
                    a.kinetic[k],
                    a.internal[k],
                    a.fragments[k],
                    b.kinetic[k],
                    b.internal[k],
                    b.fragments[k],
                ]
            })
            .collect(),
    };
    let us = |t: &[f64]| t.iter().map(|x| x * 1e6).collect::<Vec<_>>();
    let mut panels = vec![
        Panel {
            title: "energies (J/m)".into(),
            labels: ("t (µs)".into(), "energy per unit depth (J/m)".into()),
            lines: vec![
                ("kinetic, ε = 0.3".into(), us(&a.t), a.kinetic.clone()),
                ("internal, ε = 0.3".into(), us(&a.t), a.internal.clone()),
                ("kinetic, ε = 0".into(), us(&b.t), b.kinetic.clone()),
                ("internal, ε = 0".into(), us(&b.t), b.internal.clone()),
            ],
            ..Default::default()
        },
        Panel {
            title: "momentum x (kg m/s per m) and fragments".into(),
            labels: ("t (µs)".into(), "value".into()),
            lines: vec![
                ("p_x, ε = 0.3".into(), us(&a.t), a.momentum_x.clone()),
                ("p_x, ε = 0".into(), us(&b.t), b.momentum_x.clone()),
                ("fragments, ε = 0.3".into(), us(&a.t), a.fragments.clone()),
                ("fragments, ε = 0".into(), us(&b.t), b.fragments.clone()),
            ],
            ..Default::default()
        },
    ];
    for (label, r) in [("ε = 0.3", &a), ("ε = 0", &b)] {
        for (t, x, y) in &r.snapshots {
            panels.push(Panel {
                title: format!("{label}, t = {:.0} µs", t * 1e6),
                labels: ("x (m)".into(), "y (m)".into()),
                points: vec![("particles".into(), x.clone(), y.clone())],
                equal_aspect: true,
                ..Default::default()
            });
        }
    }
    out.pictures.push(Picture {
        name: "rings".into(),
        title: "Colliding rubber rings with (ε = 0.3) and without artificial stress".into(),
        panels,
        columns: 4,
    });
    Ok(out)
}

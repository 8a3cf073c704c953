//! A user-defined material next to the built-in ones.
//!
//! Outside the library crates, this file writes
//!
//! - an equation of state, the stiffened gas P = (γ − 1)ρe − γP∞ (Harlow & Amsden 1971;
//!   Saurel & Abgrall 1999, J. Comput. Phys. 150:425, with their water parameters
//!   γ = 4.4, P∞ = 6e8 Pa), implementing `sph_eos::EquationOfState`;
//! - a strength model, an exponential pressure-hardening cap, implementing
//!   `sph_strength::StrengthModel`;
//! - a damage model, cracks that grow at 0.4 c_L once the local tensile strain passes a
//!   critical strain, implementing `sph_damage::DamageModel`, with the recipe that builds
//!   it for each body, `sph_damage::BodyDamage`;
//!
//! puts them into `MaterialSpec`s next to the library's `basalt-study`, prints the
//! descriptions and a few evaluated values, runs a 1-D water shock tube with the
//! stiffened gas in the existing fluid solver, checking the star pressure against the
//! exact Riemann solution and printing the energy and momentum balance, and runs a small
//! 3-D impact into basalt with the user's damage model, printing the damaged target.
//!
//! Run: `cargo run -p sph-examples --example custom_material`.

use sph_core::{Dim1, ParticleInit, Particles};
use sph_damage::{
    BodyDamage, BodyParticles, DamageBounds, DamageError, DamageEval, DamageInput, DamageModel,
    DamageVariable,
};
use sph_eos::{EosPoint, EquationOfState};
use sph_impact::materials::DamageSpec;
use sph_impact::materials::{EosChoice, MaterialSpec, StrengthChoice, builtin, table};
use sph_impact::scene::{PlacementSpec, SceneBuilder, SceneSimulation, ShapeSpec};
use sph_impact::{Boundary, Material, SchemeConfig, Simulation};
use sph_strength::{StrengthModel, StrengthState, frictional_weakening};
use std::error::Error;
use std::sync::Arc;

// ---------------------------------------------------------------------------------------
// The user's equation of state.

/// Stiffened gas: P = (γ − 1)ρe − γP∞.
///
/// ∂P/∂ρ|_e = (γ − 1)e and ∂P/∂e|_ρ = (γ − 1)ρ, so
/// c² = ∂P/∂ρ + (P/ρ²)∂P/∂e = γ(P + P∞)/ρ.
#[derive(Clone, Copy, Debug)]
struct StiffenedGas {
    /// γ (> 1).
    gamma: f64,
    /// P∞, Pa (≥ 0).
    p_inf: f64,
    /// Reference density, kg/m³.
    rho0: f64,
}

impl StiffenedGas {
    /// Saurel & Abgrall (1999) water: γ = 4.4, P∞ = 6e8 Pa; ρ0 = 1000 kg/m³.
    fn water() -> Self {
        Self {
            gamma: 4.4,
            p_inf: 6.0e8,
            rho0: 1000.0,
        }
    }

    /// The specific energy giving pressure `p` at density `rho`.
    fn energy(&self, rho: f64, p: f64) -> f64 {
        (p + self.gamma * self.p_inf) / ((self.gamma - 1.0) * rho)
    }
}

impl EquationOfState for StiffenedGas {
    fn name(&self) -> &str {
        "stiffened-gas"
    }

    fn reference_density(&self) -> Option<f64> {
        Some(self.rho0)
    }

    /// c0 at ρ0 and P = 0: c0² = γP∞/ρ0 (1625 m/s for the water set; the trait's usual
    /// e = 0 reference is P = −γP∞ here, not a physical state).
    fn reference_sound_speed(&self) -> Option<f64> {
        Some((self.gamma * self.p_inf / self.rho0).sqrt())
    }

    fn pressure(&self, rho: f64, e: f64) -> f64 {
        (self.gamma - 1.0) * rho * e - self.gamma * self.p_inf
    }

    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        let gm1 = self.gamma - 1.0;
        // Floor 0: where c² < 0 (P < −P∞) the sound speed is 0 and flagged.
        EosPoint::from_derivatives(rho, self.pressure(rho, e), gm1 * e, gm1 * rho, 0.0)
    }
}

// ---------------------------------------------------------------------------------------
// The user's strength model.

/// Exponential pressure-hardening cap (an illustrative model, not a published one):
///
/// Y_i = Y_M − (Y_M − Y0) exp(−μP/(Y_M − Y0)) for P ≥ 0,
/// Y_i = max(0, Y0 + μP) in tension,
///
/// with the same cohesion Y0, slope μ at P = 0 and limit Y_M as the Lundborg curve
/// (Collins et al. 2004, eq. 4), approached exponentially instead of hyperbolically.
/// Damage weakens it frictionally, paper eq. (13), with the library's
/// `frictional_weakening`.
#[derive(Debug)]
struct ExponentialCap {
    cohesion: f64,
    friction: f64,
    limit_strength: f64,
    damaged_friction: f64,
    shear_modulus: f64,
}

impl StrengthModel for ExponentialCap {
    fn name(&self) -> &str {
        "exponential-cap"
    }

    fn shear_modulus(&self, _s: &StrengthState) -> f64 {
        self.shear_modulus
    }

    fn intact_yield(&self, s: &StrengthState) -> f64 {
        let span = self.limit_strength - self.cohesion;
        if s.pressure >= 0.0 {
            self.limit_strength - span * (-self.friction * s.pressure / span).exp()
        } else {
            (self.cohesion + self.friction * s.pressure).max(0.0)
        }
    }

    fn yield_strength(&self, s: &StrengthState) -> f64 {
        frictional_weakening(
            self.intact_yield(s),
            self.damaged_friction,
            s.pressure,
            s.damage,
        )
    }
}

// ---------------------------------------------------------------------------------------
// The user's damage model.

/// Cracks grow at c_g = 0.4 c_L over the particle (ds/dt = c_g/R_s for s = D^(1/3), as
/// Benz & Asphaug's single active flaw) once the local tensile strain
/// ε = σ_1/((1 − D)E) passes a critical strain ε_c; no flaws, no state per particle.
#[derive(Clone, Copy, Debug)]
struct CriticalStrain {
    /// ε_c (> 0).
    strain: f64,
    /// The variable the solver integrates (the body's: D^(1/3) in 3-D).
    variable: DamageVariable,
}

impl DamageModel for CriticalStrain {
    fn name(&self) -> &str {
        "critical-strain"
    }

    fn variable(&self) -> DamageVariable {
        self.variable
    }

    fn evaluate(&self, _particle: usize, input: &DamageInput) -> DamageEval {
        let intact = (1.0 - input.damage).max(1e-12);
        let strain = input.max_principal_stress / (intact * input.youngs_modulus);
        let cracking = strain > self.strain;
        DamageEval {
            rate: if cracking {
                0.4 * input.longitudinal_wave_speed / input.particle_size
            } else {
                0.0
            },
            bounds: DamageBounds { min: 0.0, max: 1.0 },
            active_flaws: u32::from(cracking),
        }
    }
}

/// The recipe a material holds: the same model for every body (it has no flaws to deal).
#[derive(Debug)]
struct CriticalStrainRecipe {
    strain: f64,
}

impl BodyDamage for CriticalStrainRecipe {
    fn name(&self) -> &str {
        "critical-strain"
    }

    fn build(&self, body: &BodyParticles<'_>) -> Result<Arc<dyn DamageModel>, DamageError> {
        if !(self.strain > 0.0 && self.strain.is_finite()) {
            return Err(DamageError::Custom {
                model: self.name().into(),
                message: format!("critical strain {} must be positive", self.strain),
            });
        }
        Ok(Arc::new(CriticalStrain {
            strain: self.strain,
            variable: body.variable,
        }))
    }

    /// σ_b = E ε_c at any volume.
    fn static_strength(&self, youngs_modulus: f64, _volume: f64) -> Option<f64> {
        Some(youngs_modulus * self.strain)
    }
}

// ---------------------------------------------------------------------------------------
// Exact Riemann solution of the stiffened gas (Toro, *Riemann Solvers*, ch. 4).
//
// With P̃ = P + P∞ and ê = e − P∞/ρ the stiffened gas is an ideal gas, P̃ = (γ − 1)ρê, and
// the jump and isentrope relations carry over (only pressure differences and P̃ dv
// appear), so Toro's ideal-gas solver applies in P̃.

/// Toro's f_K(P̃) and its derivative for one side (ρ_K, P̃_K).
fn side_function(p: f64, rho_k: f64, p_k: f64, gamma: f64) -> (f64, f64) {
    if p > p_k {
        // Shock.
        let a = 2.0 / ((gamma + 1.0) * rho_k);
        let b = (gamma - 1.0) / (gamma + 1.0) * p_k;
        let q = (a / (p + b)).sqrt();
        ((p - p_k) * q, q * (1.0 - 0.5 * (p - p_k) / (b + p)))
    } else {
        // Rarefaction.
        let c = (gamma * p_k / rho_k).sqrt();
        let r = p / p_k;
        let f = 2.0 * c / (gamma - 1.0) * (r.powf((gamma - 1.0) / (2.0 * gamma)) - 1.0);
        (f, r.powf(-(gamma + 1.0) / (2.0 * gamma)) / (rho_k * c))
    }
}

/// Star pressure P̃* and velocity u* for left/right states at rest (u_L = u_R = 0), by
/// Newton's method on f_L + f_R = 0.
fn star_state(rho_l: f64, p_l: f64, rho_r: f64, p_r: f64, gamma: f64) -> (f64, f64) {
    let mut p = 0.5 * (p_l + p_r);
    for _ in 0..100 {
        let (fl, dl) = side_function(p, rho_l, p_l, gamma);
        let (fr, dr) = side_function(p, rho_r, p_r, gamma);
        let step = (fl + fr) / (dl + dr);
        p = (p - step).max(1e-6 * p);
        if step.abs() < 1e-14 * p {
            break;
        }
    }
    let (fl, _) = side_function(p, rho_l, p_l, gamma);
    let (fr, _) = side_function(p, rho_r, p_r, gamma);
    (p, 0.5 * (fr - fl))
}

// ---------------------------------------------------------------------------------------

fn main() -> Result<(), Box<dyn Error>> {
    // Materials: a built-in, a fluid with the user's EOS, and basalt with the user's
    // strength model in place of Lundborg.
    let basalt = builtin("basalt-study")?;
    let gas = StiffenedGas::water();
    let water = MaterialSpec::new("water-stiffened-gas", gas.rho0, EosChoice::custom(gas))
        .with_source(
            "eos: stiffened gas, Saurel & Abgrall 1999 water (gamma = 4.4, P_inf = 6e8 Pa)",
        )
        .validated()?;
    let lundborg = basalt.strength.clone();
    let cap = ExponentialCap {
        cohesion: 26.5e6,
        friction: 0.6,
        limit_strength: 300.0e6,
        damaged_friction: 0.6,
        shear_modulus: basalt.shear_modulus,
    };
    let mut capped = basalt.clone();
    capped.name = "basalt-exponential-cap".into();
    capped.strength = StrengthChoice::custom(cap);
    capped.sources.push(
        "strength: exponential cap (this example) with the Lundborg parameters of paper Table 1"
            .into(),
    );
    capped.validate()?;

    for m in [&basalt, &water, &capped] {
        println!("{}", m.describe());
    }
    println!(
        "{}",
        table(&[basalt.clone(), water.clone(), capped.clone()])
    );

    // A few evaluated values.
    let e_atm = gas.energy(gas.rho0, 1.0e5);
    println!("Water (stiffened gas), e = {e_atm:.1} J/kg (1 atm at 1000 kg/m^3):");
    for rho in [1000.0, 1050.0, 1100.0] {
        let p = water.eos.evaluate(rho, e_atm);
        println!(
            "  rho = {rho:6.1} kg/m^3: P = {:10.4e} Pa, c = {:7.1} m/s",
            p.pressure, p.sound_speed
        );
    }
    let p = basalt.eos.evaluate(1.1 * basalt.density, 0.0);
    println!(
        "Basalt (Tillotson), rho = 1.1 rho0, e = 0: P = {:.4e} Pa, c = {:.1} m/s",
        p.pressure, p.sound_speed
    );
    println!("Yield strength (MPa): Lundborg (built-in) vs exponential cap (user), intact / D = 1");
    for pressure in [0.0, 50.0e6, 100.0e6, 500.0e6, 2.0e9] {
        let mut s = StrengthState::new(pressure, basalt.density, 300.0);
        let (l0, c0) = (
            lundborg.yield_strength(&s),
            capped.strength.yield_strength(&s),
        );
        s.damage = 1.0;
        let (l1, c1) = (
            lundborg.yield_strength(&s),
            capped.strength.yield_strength(&s),
        );
        println!(
            "  P = {:7.1} MPa: {:7.2} vs {:7.2} | {:7.2} vs {:7.2}",
            pressure / 1e6,
            l0 / 1e6,
            c0 / 1e6,
            l1 / 1e6,
            c1 / 1e6
        );
    }
    for m in [&basalt, &water] {
        println!(
            "{}: c_L = {:.1} m/s, E = {:.3} GPa",
            m.name,
            m.longitudinal_wave_speed().unwrap_or(f64::NAN),
            m.youngs_modulus().unwrap_or(f64::NAN) / 1e9
        );
    }
    // Damage is seeded per body: 1000 particles of the study's target cylinder.
    let volume = std::f64::consts::PI * 0.06165_f64.powi(2) * 0.1233;
    let damage = basalt.damage.build(&vec![volume / 1000.0; 1000], 2024)?;
    if let sph_damage::BuiltinDamage::BenzAsphaug(ba) = &damage {
        println!(
            "Basalt target: sigma_b = E (kV)^(-1/m) = {:.3} MPa (paper: 7.34), {} flaws on 1000 particles",
            basalt
                .damage
                .static_strength(basalt.youngs_modulus().unwrap_or(0.0), volume)
                .unwrap_or(f64::NAN)
                / 1e6,
            ba.flaws().total_flaws()
        );
    }

    // Basalt with the user's damage model: ε_c = 7.34 MPa / E, the study's static
    // strength of its target cylinder, at every volume.
    let mut cracking = basalt.clone();
    cracking.name = "basalt-critical-strain".into();
    let youngs = basalt
        .youngs_modulus()
        .ok_or("basalt has a Young's modulus")?;
    cracking.damage = DamageSpec::custom(CriticalStrainRecipe {
        strain: 7.34e6 / youngs,
    });
    cracking.validate()?;
    println!("{}", cracking.describe());
    println!("{}", table(std::slice::from_ref(&cracking)));
    // The same impact with the built-in Benz–Asphaug flaws and with the user's model.
    damaged_target(&basalt)?;
    damaged_target(&cracking)?;

    // A 1-D water shock tube with the user's EOS in the fluid solver: water at rest,
    // 1 GPa on the left of x = 0.5, 1 atm on the right, reflecting walls at 0 and 1.
    let (p_left, p_right, rho) = (1.0e9, 1.0e5, gas.rho0);
    let n = 600;
    let dx = 1.0 / n as f64;
    let scheme = SchemeConfig::default();
    let mut particles = Particles::<Dim1>::new();
    for k in 0..n {
        let x = (k as f64 + 0.5) * dx;
        let p = if x < 0.5 { p_left } else { p_right };
        particles.push(ParticleInit {
            position: x,
            velocity: 0.0,
            mass: rho * dx,
            density: rho,
            specific_energy: gas.energy(rho, p),
            smoothing_length: scheme.n_target * dx,
            material: 0,
        });
    }
    let materials = vec![Material::fluid("stiffened gas", gas)];
    let walls = Boundary::slab(0.0, 1.0);
    let kernel = scheme.kernel;
    let mut sim = Simulation::new(particles, materials, scheme, kernel, walls, None)?;
    let before = sim.conserved();
    let t_end = 1.0e-4;
    let clock = std::time::Instant::now();
    let steps = sim.run_until(t_end, |_, _| {})?;
    let wall = clock.elapsed().as_secs_f64();
    let after = sim.conserved();

    // Exact star state in P̃ = P + P∞.
    let (g, pi) = (gas.gamma, gas.p_inf);
    let (pt_star, u_star) = star_state(rho, p_left + pi, rho, p_right + pi, g);
    let p_star = pt_star - pi;
    let c_left = (g * (p_left + pi) / rho).sqrt();
    let c_star_left = c_left * (pt_star / (p_left + pi)).powf((g - 1.0) / (2.0 * g));
    let c_right = (g * (p_right + pi) / rho).sqrt();
    let shock =
        c_right * ((g + 1.0) / (2.0 * g) * pt_star / (p_right + pi) + (g - 1.0) / (2.0 * g)).sqrt();
    let (x_tail, x_shock) = (0.5 + (u_star - c_star_left) * t_end, 0.5 + shock * t_end);
    // The middle half of the star region (rarefaction tail to shock).
    let (lo, hi) = (
        x_tail + 0.25 * (x_shock - x_tail),
        x_shock - 0.25 * (x_shock - x_tail),
    );
    let (pressure, _) = sim.pressure_and_sound_speed();
    let pa = &sim.state.particles;
    let mut star: Vec<(f64, f64)> = (0..pa.len())
        .filter(|&i| pa.position[i] > lo && pa.position[i] < hi)
        .map(|i| (pressure[i], pa.velocity[i]))
        .collect();
    star.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (p_sph, _) = star[star.len() / 2];
    star.sort_by(|a, b| a.1.total_cmp(&b.1));
    let (_, u_sph) = star[star.len() / 2];

    println!(
        "\nWater shock tube (stiffened gas, {n} particles, t = {:.0} us): {steps} steps, {wall:.2} s wall",
        t_end * 1e6
    );
    println!(
        "  star pressure: SPH median {:.4e} Pa, exact {:.4e} Pa ({:+.2} %)",
        p_sph,
        p_star,
        100.0 * (p_sph / p_star - 1.0)
    );
    println!(
        "  star velocity: SPH median {:.3} m/s, exact {:.3} m/s ({:+.2} %); shock speed {:.1} m/s",
        u_sph,
        u_star,
        100.0 * (u_sph / u_star - 1.0),
        shock
    );
    let energy_change = (after.energy() - before.energy()) / before.energy();
    let momentum_scale = before.mass * c_left;
    let momentum_balance =
        (after.momentum - before.momentum - sim.boundary_impulse) / momentum_scale;
    // The compatible energy equation conserves energy exactly in the semi-discrete
    // equations; what remains is the RK2 time-integration error. The total is dominated
    // by the γP∞/((γ − 1)ρ) part of e, so the change is also given relative to the
    // kinetic energy the flow has gained.
    println!(
        "  energy (kinetic + internal): {:.9e} -> {:.9e} J/m^2, relative change {energy_change:.2e} \
         ({:.2e} of the final kinetic energy {:.4e} J/m^2)",
        before.energy(),
        after.energy(),
        (after.energy() - before.energy()) / after.kinetic,
        after.kinetic
    );
    println!(
        "  momentum: change {:.6e}, wall impulse {:.6e} kg/(m s); balance {momentum_balance:.2e} of sum(m) c_L",
        after.momentum - before.momentum,
        sim.boundary_impulse
    );
    println!("  mass: {:.12e} -> {:.12e} kg/m^2", before.mass, after.mass);
    Ok(())
}

/// A 1 mm aluminium ball at 3.9 km/s into a basalt block of material `target` (lattices
/// of 0.5 mm) for 2 µs: how much of the target the damage model has cracked.
fn damaged_target(target: &MaterialSpec) -> Result<(), Box<dyn Error>> {
    let scene = SceneBuilder::new(2.0e-6)
        .body(
            "projectile",
            ShapeSpec::Sphere {
                centre: [0.0, 0.0, 1.5e-3],
                radius: 1.0e-3,
            },
            "aluminium-2024-jc",
            PlacementSpec::Lattice { spacing: 0.5e-3 },
        )
        .velocity([0.0, 0.0, -3900.0])
        .body(
            "target",
            ShapeSpec::Cuboid {
                min: [-4e-3, -4e-3, -4e-3],
                max: [4e-3, 4e-3, 0.0],
            },
            target.clone(),
            PlacementSpec::Lattice { spacing: 0.5e-3 },
        )
        .build()?;
    let built = scene.build()?;
    let SceneSimulation::ThreeD(mut sim) = built.simulation else {
        return Err("a 3-D scene".into());
    };
    let clock = std::time::Instant::now();
    let steps = sim.run_until(scene.end_time, |_, _| {})?;
    let range = built.bodies[1].range.clone();
    let damage = sim.damage();
    let target_d = &damage[range.clone()];
    let cracked = target_d.iter().filter(|&&d| d > 0.0).count();
    let broken = target_d.iter().filter(|&&d| d >= 0.99).count();
    println!(
        "Impact into {} ({} particles), 2 us, {steps} steps, {:.1} s: {cracked} target \
         particles cracked (D > 0), {broken} fully damaged (D >= 0.99)",
        target.name,
        range.len(),
        clock.elapsed().as_secs_f64()
    );
    Ok(())
}

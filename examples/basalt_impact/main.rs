//! The bundled basalt-impact example (paper §6, Table 1): a 6 mm aluminium 2024 sphere
//! into a Ø123.3 × 123.3 mm basalt cylinder.
//!
//! Today it builds the two bodies with the study's variable-resolution Fibonacci
//! placement and reports what a run would start from — particle counts, masses against
//! the exact ρ·V, spacings and smoothing lengths. It becomes the full impact run once the
//! solid-dynamics and RZ solvers land.
//!
//! ```text
//! cargo run --release -p sph-examples --example basalt_impact -- [--speed 3.9] [--a-res 0.5] [--q 1.01]
//! ```

use clap::Parser;
use sph_core::glam::DVec3;
use sph_geometry::{BodyParticles, Cylinder, FibonacciPlacement, Shape, Sphere};
use std::process::ExitCode;
use std::time::Instant;

/// Build the study's impact bodies and report them.
#[derive(Parser, Debug)]
#[command(about)]
struct Args {
    /// Impact speed in km/s (the study: 2.3, 3.47 or 3.9).
    #[arg(long, default_value_t = 3.9)]
    speed: f64,
    /// Finest particle spacing A_res in mm (the study: 0.5).
    #[arg(long, default_value_t = 0.5)]
    a_res: f64,
    /// Spacing ratio q between the target's layers (the study: 1.01).
    #[arg(long, default_value_t = 1.01)]
    q: f64,
    /// Support radius in spacings (the study: 2.5).
    #[arg(long, default_value_t = 2.5)]
    n_target: f64,
}

/// Table 1 of the study.
const PROJECTILE_DIAMETER: f64 = 6.0e-3;
const PROJECTILE_DENSITY: f64 = 2785.0;
const TARGET_DIAMETER: f64 = 123.3e-3;
const TARGET_HEIGHT: f64 = 123.3e-3;
const TARGET_DENSITY: f64 = 2876.0;

fn report(name: &str, body: &BodyParticles<DVec3>, exact_mass: f64, n_target: f64, seconds: f64) {
    let h = body.smoothing_lengths(n_target).unwrap_or_default();
    let (h_min, h_max) = h
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    println!("{name}");
    println!("  particles                {:>12}", body.len());
    println!(
        "  share of uniform lattice {:>11.2} %  (lattice at the finest spacing: {:.0})",
        100.0 * body.lattice_share(),
        body.lattice_equivalent_count
    );
    println!(
        "  mass                     {:>12.6e} kg (exact ρ·V {:.6e} kg)",
        body.total_mass(),
        exact_mass
    );
    if let Some(e) = body.raw_mass_error {
        println!(
            "  raw mass error           {:>+11.2e}   (before the final rescale to ρ·V)",
            e
        );
    }
    println!(
        "  spacing                  {:.3} … {:.3} mm",
        1e3 * body.min_spacing(),
        1e3 * body.max_spacing()
    );
    println!(
        "  support radius h         {:.3} … {:.3} mm",
        1e3 * h_min,
        1e3 * h_max
    );
    println!("  placement time           {seconds:.2} s");
}

fn main() -> ExitCode {
    let args = Args::parse();
    let a_res = args.a_res * 1e-3;
    let pr = 0.5 * PROJECTILE_DIAMETER;
    // Target: top face at z = 0, body below; the impact point is the top centre.
    let target_shape = match Cylinder::new(
        DVec3::new(0.0, 0.0, -TARGET_HEIGHT),
        DVec3::Z,
        0.5 * TARGET_DIAMETER,
        TARGET_HEIGHT,
    ) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: target: {e}");
            return ExitCode::FAILURE;
        }
    };
    // Projectile: touching the target one spacing above its surface, moving down.
    let centre = DVec3::new(0.0, 0.0, pr + a_res);
    let projectile_shape = match Sphere::new(centre, pr) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: projectile: {e}");
            return ExitCode::FAILURE;
        }
    };
    println!(
        "Basalt impact (paper §6): Al 2024 sphere Ø6 mm at {} km/s into basalt Ø123.3 × 123.3 mm",
        args.speed
    );
    println!(
        "A_res = {} mm, target q = {}, projectile q = 1.00, n_target = {}\n",
        args.a_res, args.q, args.n_target
    );

    let t0 = Instant::now();
    let projectile = FibonacciPlacement::new(centre, a_res, 1.0, PROJECTILE_DENSITY)
        .and_then(|p| p.place(&projectile_shape));
    let t1 = Instant::now();
    let target = FibonacciPlacement::new(DVec3::ZERO, a_res, args.q, TARGET_DENSITY)
        .and_then(|p| p.place(&target_shape));
    let t2 = Instant::now();
    let (projectile, target) = match (projectile, target) {
        (Ok(p), Ok(t)) => (p, t),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let vol = |s: &dyn Shape<DVec3>| s.volume().unwrap_or(f64::NAN);
    let m_p = PROJECTILE_DENSITY * vol(&projectile_shape);
    report(
        "projectile (aluminium 2024, ρ 2785 kg/m³)",
        &projectile,
        m_p,
        args.n_target,
        (t1 - t0).as_secs_f64(),
    );
    report(
        "target (basalt, ρ 2876 kg/m³)",
        &target,
        TARGET_DENSITY * vol(&target_shape),
        args.n_target,
        (t2 - t1).as_secs_f64(),
    );
    let v = args.speed * 1e3;
    println!(
        "\nimpactor momentum m·v = {:.4} kg·m/s, kinetic energy ½m·v² = {:.1} J",
        m_p * v,
        0.5 * m_p * v * v
    );
    println!("total particles {}", projectile.len() + target.len());
    ExitCode::SUCCESS
}

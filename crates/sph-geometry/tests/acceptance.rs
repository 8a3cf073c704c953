//! Acceptance numbers of the variable-resolution placement (docs/placement.md).
//!
//! Every test prints its numbers; run with `--nocapture` to see them:
//!
//! ```text
//! cargo test -p sph-geometry --release --test acceptance -- --include-ignored --nocapture --test-threads 1
//! ```

use sph_core::glam::DVec3;
use sph_core::{CellList, NeighborSearch, ScalarSupport};
use sph_geometry::{
    BodyParticles, Cuboid, Cylinder, FibonacciPlacement, Shape, Sphere, closest_approach,
    cubic_lattice, hcp_lattice,
};
use std::f64::consts::PI;
use std::time::Instant;

/// The study's neighbour number: support radius h = 2.5 Δx (paper §2.4).
const N_TARGET: f64 = 2.5;

/// Wendland C2 in 3-D with support radius h (paper §2.4).
fn wendland_c2(r: f64, h: f64) -> f64 {
    let q = r / h;
    if q >= 1.0 {
        0.0
    } else {
        21.0 / (2.0 * PI * h.powi(3)) * (1.0 - q).powi(4) * (4.0 * q + 1.0)
    }
}

/// Statistics of the kernel-sum density deviation ρ_i/ρ − 1.
#[derive(Clone, Copy, Debug)]
struct KernelStats {
    max_abs: f64,
    mean: f64,
    rms: f64,
    count: usize,
}

/// Kernel-sum density deviation ρ_i/ρ − 1, with ρ_i = Σ_j m_j W(|x_i − x_j|, h_i)
/// (gather, self included), for the particles at least h_i deep inside the body
/// (`depth` = distance to the surface); `None` for the others. This is the local density
/// an SPH run starts from; near the surface the kernel is cut and the sum is low for
/// every placement, so those particles are left out.
fn kernel_deviations(p: &BodyParticles<DVec3>, depth: impl Fn(DVec3) -> f64) -> Vec<Option<f64>> {
    let h = p.smoothing_lengths(N_TARGET).unwrap();
    let list = CellList::new()
        .neighbors(&p.positions, &ScalarSupport::new(&h).unwrap())
        .unwrap();
    (0..p.len())
        .map(|i| {
            if depth(p.positions[i]) < h[i] {
                return None;
            }
            let mut rho = p.masses[i] * wendland_c2(0.0, h[i]);
            for j in list.neighbors(i) {
                let j = j as usize;
                rho += p.masses[j] * wendland_c2((p.positions[i] - p.positions[j]).length(), h[i]);
            }
            Some(rho / p.density - 1.0)
        })
        .collect()
}

/// Max |·|, mean and rms of the kernel-density deviations of the interior particles.
fn kernel_density_deviation(p: &BodyParticles<DVec3>, depth: impl Fn(DVec3) -> f64) -> KernelStats {
    let devs: Vec<f64> = kernel_deviations(p, depth).into_iter().flatten().collect();
    let n = devs.len() as f64;
    KernelStats {
        max_abs: devs.iter().fold(0.0, |a, d| a.max(d.abs())),
        mean: devs.iter().sum::<f64>() / n,
        rms: (devs.iter().map(|d| d * d).sum::<f64>() / n).sqrt(),
        count: devs.len(),
    }
}

/// Masses of the 10 × 10 columns (each 10 × 10 wide, full height) of the XY projection
/// of the cube [0, 100]³, row-major in (x, y).
fn column_masses(p: &BodyParticles<DVec3>) -> Vec<f64> {
    let mut col = vec![0.0; 100];
    for (x, m) in p.positions.iter().zip(&p.masses) {
        let i = ((x.x / 10.0).floor() as usize).min(9);
        let j = ((x.y / 10.0).floor() as usize).min(9);
        col[j * 10 + i] += m;
    }
    col
}

/// The numbers docs/placement.md tabulates.
struct Metrics {
    count: usize,
    share: f64,
    raw_error: f64,
    /// Total-mass error had each kept point simply taken its layer's full-shell share
    /// ρ V_shell / N_k (no shell-volume quadrature).
    naive_error: f64,
    /// Total-mass error had each kept point taken its lattice-cell mass ρ r_k³.
    cell_error: f64,
    closest: f64,
    kernel: KernelStats,
    seconds: f64,
}

fn place_and_measure<S: Shape<DVec3>>(
    shape: &S,
    placement: &FibonacciPlacement,
    depth: impl Fn(DVec3) -> f64,
) -> (BodyParticles<DVec3>, Metrics) {
    let t0 = Instant::now();
    let (p, layers) = placement.place_with_report(shape).expect("placement");
    let seconds = t0.elapsed().as_secs_f64();
    let outside = p.positions.iter().filter(|&&x| !shape.contains(x)).count();
    assert_eq!(outside, 0, "{outside} particles outside the body");
    let closest = closest_approach(&p.positions, &p.spacing)
        .expect("neighbour search")
        .map_or(f64::INFINITY, |c| c.ratio);
    let mass_ratio = p.total_mass() / (p.density * p.volume);
    assert!(
        (mass_ratio - 1.0).abs() < 1e-10,
        "normalised total mass {mass_ratio}"
    );
    let naive_volume: f64 = layers
        .iter()
        .map(|l| l.shell.volume() * l.kept as f64 / l.shell.count as f64)
        .sum();
    let cell_volume: f64 = layers
        .iter()
        .map(|l| l.kept as f64 * l.shell.spacing.powi(3))
        .sum();
    let kernel = kernel_density_deviation(&p, depth);
    let m = Metrics {
        count: p.len(),
        share: p.lattice_share(),
        raw_error: p.raw_mass_error.expect("exact volume known"),
        naive_error: naive_volume / p.volume - 1.0,
        cell_error: cell_volume / p.volume - 1.0,
        closest,
        kernel,
        seconds,
    };
    (p, m)
}

fn report(label: &str, m: &Metrics) {
    println!(
        "{label}:\n  particles {} ({:.2} % of the uniform lattice)\n  raw total-mass error \
         {:+.2e} (baselines: full-shell shares {:+.3} %, cell masses rho r^3 {:+.3} %)\n  closest pair |x_i - x_j| / (0.5 min dx) \
         {:.3}\n  kernel density (n_target {N_TARGET}, {} interior particles): max |dev| {:.2} %, \
         mean {:+.2} %, rms {:.2} %\n  placement time {:.2} s",
        m.count,
        100.0 * m.share,
        m.raw_error,
        100.0 * m.naive_error,
        100.0 * m.cell_error,
        m.closest,
        m.kernel.count,
        100.0 * m.kernel.max_abs,
        100.0 * m.kernel.mean,
        100.0 * m.kernel.rms,
        m.seconds
    );
}

/// Places the acceptance cube and returns (metrics, max column deviation).
fn cube_metrics(q: f64) -> (Metrics, f64) {
    let cube = Cuboid::new(DVec3::ZERO, DVec3::splat(100.0)).unwrap();
    let placement = FibonacciPlacement::new(DVec3::ZERO, 1.0, q, 1.0).unwrap();
    let depth = |x: DVec3| x.min_element().min((DVec3::splat(100.0) - x).min_element());
    let (p, m) = place_and_measure(&cube, &placement, depth);
    assert!((p.lattice_equivalent_count - 1.0e6).abs() < 1e-6);
    let cols = column_masses(&p);
    let column_dev = cols
        .iter()
        .map(|c| (c / 1.0e4 - 1.0).abs())
        .fold(0.0, f64::max);
    report(&format!("cube 100^3, corner origin, A_res 1, q {q}"), &m);
    println!(
        "  columns 10x10 (uniform 1e4): max |dev| {:.2} %, min {:.1}, max {:.1}; map (%, y up):",
        100.0 * column_dev,
        cols.iter().cloned().fold(f64::INFINITY, f64::min),
        cols.iter().cloned().fold(0.0, f64::max)
    );
    for j in (0..10).rev() {
        let row: Vec<String> = (0..10)
            .map(|i| format!("{:+5.1}", 100.0 * (cols[j * 10 + i] / 1.0e4 - 1.0)))
            .collect();
        println!("    {}", row.join(" "));
    }
    let mut slabs = [0.0; 10];
    for (x, mass) in p.positions.iter().zip(&p.masses) {
        slabs[((x.z / 10.0).floor() as usize).min(9)] += mass;
    }
    let slab_dev = slabs
        .iter()
        .map(|s| (s / 1.0e5 - 1.0).abs())
        .fold(0.0, f64::max);
    println!(
        "  z-slabs 10 thick (uniform 1e5): max |dev| {:.2} %",
        100.0 * slab_dev
    );
    (m, column_dev)
}

/// Cube of side 100, density 1, origin at the corner, A_res = 1, q = 1.01.
#[test]
fn cube_metrics_q1_01() {
    let (m, column_dev) = cube_metrics(1.01);
    assert!(m.raw_error.abs() <= 0.005, "raw mass error {}", m.raw_error);
    assert!(column_dev <= 0.05, "column deviation {column_dev}");
    assert!(m.closest >= 1.0, "closest pair ratio {}", m.closest);
}

/// Cube of side 100, density 1, origin at the corner, A_res = 1, q = 1.03.
#[test]
fn cube_metrics_q1_03() {
    let (m, column_dev) = cube_metrics(1.03);
    assert!(m.raw_error.abs() <= 0.005, "raw mass error {}", m.raw_error);
    assert!(column_dev <= 0.10, "column deviation {column_dev}");
    assert!(m.closest >= 1.0, "closest pair ratio {}", m.closest);
}

/// The study's projectile: sphere Ø6 mm, A_res 0.5 mm, q = 1.00, origin at its centre.
#[test]
fn projectile_sphere() {
    let ball = Sphere::new(DVec3::ZERO, 3.0e-3).unwrap();
    let placement = FibonacciPlacement::new(DVec3::ZERO, 0.5e-3, 1.0, 2785.0).unwrap();
    let (p, m) = place_and_measure(&ball, &placement, |x| 3.0e-3 - x.length());
    report("projectile sphere D 6 mm, A_res 0.5 mm, q 1.00", &m);
    println!(
        "  uniform 0.5 mm cubic lattice equivalent V/dx^3 = {:.1}",
        p.lattice_equivalent_count
    );
    // Kernel density by layer: the irregular cluster of the first layers.
    let devs = kernel_deviations(&p, |x| 3.0e-3 - x.length());
    for layer in 0..4 {
        let radius = 0.5e-3 * (layer as f64 + 0.5);
        let max = p
            .positions
            .iter()
            .zip(&devs)
            .filter(|(x, _)| (x.length() - radius).abs() < 1e-9)
            .filter_map(|(_, d)| d.map(f64::abs))
            .fold(0.0, f64::max);
        println!(
            "  layer {layer} (R {:.2} mm): kernel density max |dev| {:.2} %",
            1e3 * radius,
            100.0 * max
        );
    }
    assert_eq!(m.count, 896);
    assert!(m.raw_error.abs() < 1e-9, "raw mass error {}", m.raw_error);
    assert!(m.closest >= 1.0, "closest pair ratio {}", m.closest);
}

/// The study's target: cylinder Ø123.3 × 123.3 mm, axis z, top face at z = 0, origin at
/// the top centre, A_res 0.5 mm, q = 1.01; once with the paper's Fibonacci poles on the
/// impact axis (z) and once with the poles turned into the top face (x). Heavy: run in
/// release.
#[test]
#[ignore = "heavy: cargo test -p sph-geometry --release --test acceptance -- --ignored --nocapture impact_target"]
fn impact_target_cylinder() {
    let (r, h) = (0.06165, 0.1233);
    let target = Cylinder::new(DVec3::new(0.0, 0.0, -h), DVec3::Z, r, h).unwrap();
    let depth = |x: DVec3| (r - x.truncate().length()).min(-x.z).min(x.z + h);
    for (pole, name) in [(DVec3::Z, "z (paper)"), (DVec3::X, "x")] {
        let placement = FibonacciPlacement::new(DVec3::ZERO, 0.5e-3, 1.01, 2876.0)
            .unwrap()
            .with_pole_axis(pole)
            .unwrap();
        let (p, m) = place_and_measure(&target, &placement, depth);
        report(
            &format!(
                "impact target cylinder D 123.3 x 123.3 mm, A_res 0.5 mm, q 1.01, poles {name}"
            ),
            &m,
        );
        println!(
            "  uniform 0.5 mm cubic lattice equivalent V/dx^3 = {:.4e}; spacing {:.3} to {:.3} mm",
            p.lattice_equivalent_count,
            1e3 * p.min_spacing(),
            1e3 * p.max_spacing()
        );
        assert!(m.raw_error.abs() <= 0.005, "raw mass error {}", m.raw_error);
        // The layer rule fixes the count: ∫ dV / (A_res + (q − 1)R)³ over the cylinder
        // is 1.02e6 (8.7 %); see docs/placement.md on the study's ~4 %.
        assert!(m.share < 0.09, "share {}", m.share);
        assert!(m.closest >= 1.0, "closest pair ratio {}", m.closest);
        assert!(
            m.kernel.mean.abs() < 0.02,
            "kernel density mean {}",
            m.kernel.mean
        );
        if pole == DVec3::X {
            assert!(
                m.kernel.max_abs < 0.03,
                "kernel density {}",
                m.kernel.max_abs
            );
        }
    }
}

/// A ball about its centre: every layer is concentric with the surface, and a radius
/// that is not a shell boundary leaves the outer part of the last shell without
/// particles of its own. The orphan rule hands it to the layer inside, so the total
/// mass stays right without inflating the interior density.
#[test]
fn concentric_ball_keeps_its_skin() {
    let radius = 9.9;
    let ball = Sphere::new(DVec3::ZERO, radius).unwrap();
    let placement = FibonacciPlacement::new(DVec3::ZERO, 0.5, 1.01, 1.0).unwrap();
    // Leave out the innermost layers (|x| < 2), whose 3, 28, ... points are too few
    // for a regular arrangement (reported separately in docs/placement.md).
    let (_, m) = place_and_measure(&ball, &placement, |x| {
        (radius - x.length()).min(x.length() - 2.0)
    });
    report("ball R 9.9 about its centre, A_res 0.5, q 1.01", &m);
    assert!(m.raw_error.abs() < 1e-3, "raw mass error {}", m.raw_error);
    // Spreading the last shell's missing volume over the body (the scheme without the
    // orphan rule) gave a mean of +7 %; the lattice floor of the kernel sum is +1.3 %.
    assert!(
        m.kernel.mean.abs() < 0.02,
        "kernel density mean {}",
        m.kernel.mean
    );
    // The largest deviations sit at the Fibonacci poles (±z), measured 4.7 %.
    assert!(
        m.kernel.max_abs < 0.05,
        "kernel density {}",
        m.kernel.max_abs
    );
    assert!(m.closest >= 1.0, "closest pair ratio {}", m.closest);
}

/// The kernel-sum density of uniform lattices at the same n_target: the floor that the
/// kernel sum itself sets (a Wendland C2 sum over a lattice is not exactly ρ).
#[test]
fn kernel_density_baseline_lattices() {
    let cube = Cuboid::new(DVec3::ZERO, DVec3::splat(30.0)).unwrap();
    let depth = |x: DVec3| x.min_element().min((DVec3::splat(30.0) - x).min_element());
    let cubic = cubic_lattice(&cube, 1.0, 1.0).unwrap();
    let c = kernel_density_deviation(&cubic, depth);
    let hcp = hcp_lattice(&cube, 1.0, 1.0).unwrap();
    let h = kernel_density_deviation(&hcp, depth);
    println!(
        "kernel density baseline (n_target {N_TARGET}): cubic lattice {:+.3} % ({} particles); \
         HCP lattice {:+.3} % ({} particles)",
        100.0 * c.mean,
        c.count,
        100.0 * h.mean,
        h.count
    );
    // A lattice is uniform, so every interior particle sees the same sum.
    assert!(c.max_abs - c.mean.abs() < 1e-9 && h.max_abs - h.mean.abs() < 1e-9);
    assert!(c.max_abs < 0.05 && h.max_abs < 0.05);
}

/// How the raw total-mass error and the placement time depend on the shell-volume
/// quadrature (directions per layer point × sample intervals per ray).
#[test]
#[ignore = "timing: cargo test -p sph-geometry --release --test acceptance -- --ignored --nocapture quadrature_sensitivity"]
fn quadrature_sensitivity() {
    let cube = Cuboid::new(DVec3::ZERO, DVec3::splat(100.0)).unwrap();
    let (r, h) = (0.06165, 0.1233);
    let target = Cylinder::new(DVec3::new(0.0, 0.0, -h), DVec3::Z, r, h).unwrap();
    let cases: [(&str, &dyn Shape<DVec3>, FibonacciPlacement); 3] = [
        (
            "cube q 1.01",
            &cube,
            FibonacciPlacement::new(DVec3::ZERO, 1.0, 1.01, 1.0).unwrap(),
        ),
        (
            "cube q 1.03",
            &cube,
            FibonacciPlacement::new(DVec3::ZERO, 1.0, 1.03, 1.0).unwrap(),
        ),
        (
            "target cylinder",
            &target,
            FibonacciPlacement::new(DVec3::ZERO, 0.5e-3, 1.01, 1.0).unwrap(),
        ),
    ];
    for (label, shape, placement) in cases {
        for (angular, radial) in [(1, 1), (4, 4), (16, 4), (64, 4)] {
            let t0 = Instant::now();
            let (p, layers) = placement
                .with_quadrature(angular, radial)
                .unwrap()
                .place_with_report(shape)
                .unwrap();
            let lost: f64 = layers.iter().map(|l| l.volume_lost).sum();
            println!(
                "{label}: directions x{angular}, ray samples {radial}: raw error {:+.2e}, \
                 lost orphans {:.1e} V, {:.2} s",
                p.raw_mass_error.unwrap(),
                lost / p.volume,
                t0.elapsed().as_secs_f64()
            );
        }
    }
}

//! Placement for axisymmetric (RZ) runs (docs/placement.md §6): the ring masses per
//! radian add up to the body's mass, every particle is off the axis, the spacings are the
//! layers', q = 1 is uniform, and the kernel-sum density of the interior is uniform.
//!
//! `cargo test -p sph-geometry --test rz -- --nocapture --test-threads 1` prints the numbers.

use sph_core::glam::{DVec2, DVec3};
use sph_core::{CellList, NeighborSearch, ScalarSupport};
use sph_geometry::{
    BodyParticles, Cylinder, GeometryError, HalfSpace, RzLayeredPlacement, Shape, Sphere,
    cubic_lattice, rz_lattice, shells,
};
use std::f64::consts::{PI, TAU};

/// Wendland C2 in 2-D with support radius h.
fn wendland_c2_2d(r: f64, h: f64) -> f64 {
    let q = r / h;
    if q >= 1.0 {
        0.0
    } else {
        7.0 / (PI * h * h) * (1.0 - q).powi(4) * (4.0 * q + 1.0)
    }
}

/// 2π Σ m / (ρ V) − 1 (the layers rescale their masses so that this is zero; their raw
/// error, before the rescaling, is `raw_mass_error`).
fn mass_error(p: &BodyParticles<DVec2>) -> f64 {
    TAU * p.total_mass() / (p.density * p.exact_volume.unwrap()) - 1.0
}

/// RZ kernel-sum density deviation Σ_j m_j W_ij / (ρ r_i) − 1 (h = 2.5 Δ_i, self
/// included) of the particles at least h from the axis and `depth` ≥ h inside: max |·|
/// and mean. Away from the axis the kernel average of r is r itself, so a uniform ring
/// density gives ρ r.
fn kernel_density(p: &BodyParticles<DVec2>, depth: impl Fn(DVec2) -> f64) -> (f64, f64, usize) {
    let h = p.smoothing_lengths(2.5).unwrap();
    let list = CellList::new()
        .neighbors(&p.positions, &ScalarSupport::new(&h).unwrap())
        .unwrap();
    let devs: Vec<f64> = (0..p.len())
        .filter(|&i| p.positions[i].x >= h[i] && depth(p.positions[i]) >= h[i])
        .map(|i| {
            let mut s = p.masses[i] * wendland_c2_2d(0.0, h[i]);
            for j in list.neighbors(i) {
                let j = j as usize;
                s += p.masses[j] * wendland_c2_2d((p.positions[i] - p.positions[j]).length(), h[i]);
            }
            s / (p.density * p.positions[i].x) - 1.0
        })
        .collect();
    let max = devs.iter().fold(0.0f64, |a, d| a.max(d.abs()));
    let mean = devs.iter().sum::<f64>() / devs.len() as f64;
    (max, mean, devs.len())
}

fn report(label: &str, p: &BodyParticles<DVec2>) {
    println!(
        "{label}: {} particles, 2πΣm/(ρV) − 1 = {:+.3e} (raw {:+.3e}), spacing {:.4} … {:.4}, share {:.3}",
        p.len(),
        mass_error(p),
        p.raw_mass_error.unwrap(),
        p.min_spacing(),
        p.max_spacing(),
        p.lattice_share()
    );
}

/// The study's target: cylinder Ø123.3 × 123.3 mm, top face at z = 0.
fn study_target() -> Cylinder {
    Cylinder::new(DVec3::new(0.0, 0.0, -0.1233), DVec3::Z, 0.06165, 0.1233).unwrap()
}

/// The RZ layers about (0, `origin_z`) in `shape`.
fn layers(
    shape: &impl Shape<DVec3>,
    origin_z: f64,
    a: f64,
    q: f64,
    rho: f64,
) -> BodyParticles<DVec2> {
    RzLayeredPlacement::new(origin_z, a, q, rho)
        .unwrap()
        .place(shape)
        .unwrap()
}

#[test]
fn masses_add_up_to_the_body() {
    let rho = 2876.0;
    // A sphere about its centre whose radius is a layer boundary: exact.
    let projectile = Sphere::new(DVec3::new(0.0, 0.0, 3.5e-3), 3.0e-3).unwrap();
    let p = layers(&projectile, 3.5e-3, 0.5e-3, 1.0, 2785.0);
    report("projectile sphere, origin at its centre, q = 1", &p);
    assert!(mass_error(&p).abs() < 1e-12);
    assert!(p.raw_mass_error.unwrap().abs() < 1e-12);
    // A sphere whose surface cuts the layers obliquely.
    let ball = Sphere::new(DVec3::new(0.0, 0.0, -10.0), 7.3).unwrap();
    let p = RzLayeredPlacement::new(-4.0, 0.25, 1.02, rho)
        .unwrap()
        .place(&ball)
        .unwrap();
    report("sphere R 7.3, origin 6 off its centre, q = 1.02", &p);
    assert!(mass_error(&p).abs() < 1e-12);
    assert!(p.raw_mass_error.unwrap().abs() < 1e-3);
    // Layers that overshoot the surface: 2 mm layers about the centre of a 3 mm sphere
    // (the study's projectile at a quarter of its resolution). Each particle carries the
    // inside part of its sector (whole sectors gave the sphere 2.37 times its mass).
    let p = layers(&projectile, 3.5e-3, 2.0e-3, 1.0, 2785.0);
    report("projectile sphere, 2 mm layers", &p);
    assert!(mass_error(&p).abs() < 1e-12);
    assert!(p.raw_mass_error.unwrap().abs() < 0.02);
    // The study's target about its top centre, and off the top face.
    let cyl = study_target();
    let t = std::time::Instant::now();
    let p = RzLayeredPlacement::new(0.0, 0.5e-3, 1.01, rho)
        .unwrap()
        .place(&cyl)
        .unwrap();
    report("study target, origin top centre, q = 1.01", &p);
    println!("  placement {:.3} s", t.elapsed().as_secs_f64());
    assert!(mass_error(&p).abs() < 1e-12);
    assert!(p.raw_mass_error.unwrap().abs() < 1e-4);
    let p = RzLayeredPlacement::new(-0.03, 0.5e-3, 1.03, rho)
        .unwrap()
        .place(&cyl)
        .unwrap();
    report("study target, origin 30 mm deep, q = 1.03", &p);
    assert!(mass_error(&p).abs() < 1e-12);
    assert!(p.raw_mass_error.unwrap().abs() < 1e-3);
    // Lattices.
    let p = rz_lattice(&cyl, 0.5e-3, rho).unwrap();
    report("study target, RZ lattice 0.5 mm", &p);
    assert!(mass_error(&p).abs() < 0.01);
    let p = rz_lattice(&ball, 0.25, rho).unwrap();
    report("sphere R 7.3, RZ lattice 0.25", &p);
    assert!(mass_error(&p).abs() < 0.03);
}

#[test]
fn every_particle_is_off_the_axis_and_inside() {
    let cyl = study_target();
    for p in [
        RzLayeredPlacement::new(0.0, 1e-3, 1.01, 1.0)
            .unwrap()
            .place(&cyl)
            .unwrap(),
        rz_lattice(&cyl, 1e-3, 1.0).unwrap(),
    ] {
        for (x, m) in p.positions.iter().zip(&p.masses) {
            assert!(x.x > 0.0 && *m > 0.0, "{x:?} {m}");
            assert!(cyl.contains(DVec3::new(x.x, 0.0, x.y)));
        }
    }
}

#[test]
fn spacing_is_the_layers_and_no_particle_sits_on_the_origin_plane() {
    let (a, q) = (0.5e-3, 1.01);
    let cyl = study_target();
    let p = RzLayeredPlacement::new(0.0, a, q, 1.0)
        .unwrap()
        .place(&cyl)
        .unwrap();
    let layers = shells(a, q, 0.2).unwrap();
    for (x, &dx) in p.positions.iter().zip(&p.spacing) {
        let r = x.length();
        let s = layers
            .iter()
            .find(|s| s.inner <= r && r <= s.outer)
            .unwrap();
        assert_eq!(dx, s.spacing);
        assert!((r - s.radius).abs() < 1e-12 * s.radius.max(1e-3));
        // θ = π/2 is a sector boundary: the top layer lies about Δ/2 below the face.
        assert!(x.y < -0.2 * dx, "{x:?}");
    }
    assert_eq!(p.min_spacing(), a);
    println!(
        "study target: spacing {:.4} … {:.4} mm, top layer at {:.4} mm",
        p.min_spacing() * 1e3,
        p.max_spacing() * 1e3,
        p.positions.iter().map(|x| x.y).fold(f64::MIN, f64::max) * 1e3
    );
}

#[test]
fn q_one_is_uniform() {
    let a = 0.1;
    let ball = Sphere::new(DVec3::ZERO, 4.0).unwrap();
    let p = RzLayeredPlacement::new(0.0, a, 1.0, 1.0)
        .unwrap()
        .place(&ball)
        .unwrap();
    assert!(p.spacing.iter().all(|&d| d == a));
    // Arc spacing πR_k/n_k within rounding of Δ; radial spacing exactly Δ.
    for s in shells(a, 1.0, 4.0).unwrap().iter().skip(3) {
        let n = sph_geometry::rz_layer_point_count(s.radius, s.spacing);
        let arc = PI * s.radius / n as f64;
        assert!((arc / a - 1.0).abs() < 0.12, "layer {}: arc {arc}", s.index);
        assert_eq!(n % 2, 0);
    }
    let (max, mean, count) = kernel_density(&p, |x| 4.0 - x.length());
    println!(
        "ball R 40Δ, q = 1: {} particles; interior kernel density max {:.2} %, mean {:+.2} % ({count})",
        p.len(),
        100.0 * max,
        100.0 * mean
    );
    assert!(max < 0.05 && mean.abs() < 0.02);
}

#[test]
fn interior_kernel_density_of_the_study_target() {
    let cyl = study_target();
    let depth = |x: DVec2| (-x.y).min(0.1233 + x.y).min(0.06165 - x.x);
    let p = RzLayeredPlacement::new(0.0, 0.5e-3, 1.01, 2876.0)
        .unwrap()
        .place(&cyl)
        .unwrap();
    let (max, mean, count) = kernel_density(&p, depth);
    println!(
        "study target, layers q = 1.01: interior kernel density max {:.2} %, mean {:+.2} % ({count} particles)",
        100.0 * max,
        100.0 * mean
    );
    assert!(max < 0.08 && mean.abs() < 0.02);
    let p = rz_lattice(&cyl, 1e-3, 2876.0).unwrap();
    let (max, mean, count) = kernel_density(&p, depth);
    println!(
        "study target, RZ lattice 1 mm: interior kernel density max {:.2} %, mean {:+.2} % ({count} particles)",
        100.0 * max,
        100.0 * mean
    );
    assert!(max < 0.02);
}

#[test]
fn rz_lattice_shares_the_cubic_lattices_z_layers_and_cell_masses() {
    let cyl = Cylinder::new(DVec3::new(0.0, 0.0, -2.0), DVec3::Z, 1.5, 2.0).unwrap();
    let a = 0.25;
    let p = rz_lattice(&cyl, a, 3.0).unwrap();
    // Radius and length are whole spacings: the cells tile the section exactly.
    assert!(mass_error(&p).abs() < 1e-12, "{}", mass_error(&p));
    assert_eq!(p.len(), 6 * 8);
    for (x, m) in p.positions.iter().zip(&p.masses) {
        assert!((m - 3.0 * a * a * x.x).abs() < 1e-15);
    }
    let cubic = cubic_lattice(&cyl, a, 3.0).unwrap();
    let mut zs: Vec<f64> = cubic.positions.iter().map(|x| x.z).collect();
    zs.sort_by(f64::total_cmp);
    zs.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    let mut zr: Vec<f64> = p.positions.iter().map(|x| x.y).collect();
    zr.sort_by(f64::total_cmp);
    zr.dedup_by(|a, b| (*a - *b).abs() < 1e-12);
    assert_eq!(zs.len(), zr.len());
    assert!(zs.iter().zip(&zr).all(|(a, b)| (a - b).abs() < 1e-12));
}

#[test]
fn bad_input_is_named() {
    let e = RzLayeredPlacement::new(0.0, -1.0, 1.0, 1.0).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("RzLayeredPlacement.first_spacing (A_res) = -1")
    );
    let e = RzLayeredPlacement::new(0.0, 1.0, 0.99, 1.0).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("RzLayeredPlacement.ratio (q) = 0.99")
    );
    assert!(RzLayeredPlacement::new(0.0, 1.0, f64::INFINITY, 1.0).is_err());
    assert!(RzLayeredPlacement::new(f64::NAN, 1.0, 1.0, 1.0).is_err());
    assert!(RzLayeredPlacement::new(0.0, 1.0, 1.0, 0.0).is_err());
    assert!(rz_lattice(&study_target(), 0.0, 1.0).is_err());
    assert!(rz_lattice(&study_target(), 1e-3, f64::NAN).is_err());
    let half = HalfSpace::new(DVec3::ZERO, DVec3::Z).unwrap();
    assert!(matches!(
        rz_lattice(&half, 1.0, 1.0),
        Err(GeometryError::Unbounded { .. })
    ));
    // A body far from the layers' reach has none of their points.
    let tiny = Sphere::new(DVec3::new(0.0, 0.0, 5.0), 0.01).unwrap();
    assert!(matches!(
        RzLayeredPlacement::new(0.0, 1.0, 1.0, 1.0)
            .unwrap()
            .place(&tiny),
        Err(GeometryError::EmptyPlacement { .. })
    ));
}

//! Uniform lattices filling a shape: cubic (1-D, 2-D, 3-D), hexagonal (2-D) and
//! hexagonal close-packed (HCP, 3-D). The spacing Δx is the nearest-neighbour distance
//! in each; every particle carries the mass ρ × (volume per lattice site), so a uniform
//! lattice gives a uniform mass density by construction (paper §4 uses q = 1.00, a
//! uniform arrangement, for the projectile; these are the classical alternatives).
//!
//! Anchoring: the cubic lattice is centred on the shape's bounds with cell-centred
//! sites (a box whose edges are multiples of Δx holds exactly edge/Δx sites per edge);
//! the hexagonal and HCP lattices put a site at the centre of the bounds.

use crate::error::{GeometryError, bounds_of, check_candidates, positive_finite};
use crate::placement::BodyParticles;
use crate::shape::{Aabb, Shape, format_point};
use rayon::prelude::*;
use sph_core::Vector;
use sph_core::glam::{DVec2, DVec3};

/// Volume per site of a cubic lattice in `dim` dimensions: Δx^dim.
pub fn cubic_site_volume(dim: usize, spacing: f64) -> f64 {
    spacing.powi(dim as i32)
}

/// Area per site of the 2-D hexagonal (triangular) lattice: (√3/2) Δx² (each site owns
/// a rhombus of sides Δx and angle 60°).
pub fn hexagonal_site_volume(spacing: f64) -> f64 {
    3f64.sqrt() / 2.0 * spacing * spacing
}

/// Volume per site of the hexagonal close-packed lattice: Δx³/√2 (hexagonal layers of
/// area (√3/2)Δx² per site, stacked sqrt(2/3)·Δx apart).
pub fn hcp_site_volume(spacing: f64) -> f64 {
    spacing.powi(3) / 2f64.sqrt()
}

/// Fills `shape` with a cubic lattice of spacing `spacing` (m) and mass density
/// `density`; each particle has mass ρΔx^DIM.
pub fn cubic_lattice<V: Vector, S: Shape<V> + ?Sized>(
    shape: &S,
    spacing: f64,
    density: f64,
) -> Result<BodyParticles<V>, GeometryError> {
    let (a, bounds) = check("cubic lattice", shape, spacing, density)?;
    // Sites per axis: enough that n·Δx covers the edge; the tolerance keeps an edge of
    // exactly n spacings (up to round-off) at n sites.
    let counts: Vec<usize> = (0..V::DIM)
        .map(|k| ((bounds.extent().component(k) / a - 1e-9).ceil().max(1.0)) as usize)
        .collect();
    let total: f64 = counts.iter().map(|&n| n as f64).product();
    check_candidates(shape, "cubic lattice", total)?;
    let centre = bounds.centre();
    let site = |mut lin: usize| {
        V::from_fn(|k| {
            let j = lin % counts[k];
            lin /= counts[k];
            centre.component(k) + (j as f64 - 0.5 * (counts[k] - 1) as f64) * a
        })
    };
    let positions: Vec<V> = (0..total as usize)
        .into_par_iter()
        .map(site)
        .filter(|&p| shape.contains(p))
        .collect();
    finish(
        shape,
        "cubic",
        positions,
        a,
        density,
        cubic_site_volume(V::DIM, a),
        &bounds,
    )
}

/// Fills a 2-D `shape` with a hexagonal lattice (rows Δx apart along x, (√3/2)Δx apart
/// along y, odd rows shifted by Δx/2); each particle has mass ρ(√3/2)Δx².
pub fn hexagonal_lattice<S: Shape<DVec2> + ?Sized>(
    shape: &S,
    spacing: f64,
    density: f64,
) -> Result<BodyParticles<DVec2>, GeometryError> {
    let (a, bounds) = check("hexagonal lattice", shape, spacing, density)?;
    let dy = 3f64.sqrt() / 2.0 * a;
    let half = bounds.extent() * 0.5;
    let ni = (half.x / a).ceil() as i64 + 1;
    let nj = (half.y / dy).ceil() as i64 + 1;
    let (wi, wj) = (2 * ni + 1, 2 * nj + 1);
    check_candidates(shape, "hexagonal lattice", (wi * wj) as f64)?;
    let centre = bounds.centre();
    let positions: Vec<DVec2> = (0..wi * wj)
        .into_par_iter()
        .map(|lin| {
            let (i, j) = (lin % wi - ni, lin / wi - nj);
            centre + hex_site(i, j, a)
        })
        .filter(|&p| shape.contains(p))
        .collect();
    finish(
        shape,
        "hexagonal",
        positions,
        a,
        density,
        hexagonal_site_volume(a),
        &bounds,
    )
}

/// Fills a 3-D `shape` with a hexagonal close-packed lattice (ABAB stacking of
/// hexagonal layers sqrt(2/3)Δx apart, B layers shifted over the centroids of the A
/// triangles); each particle has mass ρΔx³/√2.
pub fn hcp_lattice<S: Shape<DVec3> + ?Sized>(
    shape: &S,
    spacing: f64,
    density: f64,
) -> Result<BodyParticles<DVec3>, GeometryError> {
    let (a, bounds) = check("HCP lattice", shape, spacing, density)?;
    let dy = 3f64.sqrt() / 2.0 * a;
    let dz = (2.0f64 / 3.0).sqrt() * a;
    let half = bounds.extent() * 0.5;
    // One extra column for the B-layer shift.
    let ni = (half.x / a).ceil() as i64 + 2;
    let nj = (half.y / dy).ceil() as i64 + 2;
    let nl = (half.z / dz).ceil() as i64 + 1;
    let (wi, wj, wl) = (2 * ni + 1, 2 * nj + 1, 2 * nl + 1);
    check_candidates(shape, "HCP lattice", (wi * wj * wl) as f64)?;
    let centre = bounds.centre();
    let b_shift = DVec2::new(0.5 * a, a / (2.0 * 3f64.sqrt()));
    let positions: Vec<DVec3> = (0..wi * wj * wl)
        .into_par_iter()
        .map(|lin| {
            let (i, j, l) = (lin % wi - ni, (lin / wi) % wj - nj, lin / (wi * wj) - nl);
            let mut xy = hex_site(i, j, a);
            if l.rem_euclid(2) == 1 {
                xy += b_shift;
            }
            centre + xy.extend(l as f64 * dz)
        })
        .filter(|&p| shape.contains(p))
        .collect();
    finish(
        shape,
        "HCP",
        positions,
        a,
        density,
        hcp_site_volume(a),
        &bounds,
    )
}

/// Site (i, j) of the triangular lattice of spacing a, odd rows shifted by a/2.
#[inline]
fn hex_site(i: i64, j: i64, a: f64) -> DVec2 {
    let shift = 0.5 * j.rem_euclid(2) as f64;
    DVec2::new((i as f64 + shift) * a, j as f64 * 3f64.sqrt() / 2.0 * a)
}

/// Validates spacing and density and fetches the bounds (a lattice must know where to
/// stop, so unbounded shapes are refused).
fn check<V: Vector, S: Shape<V> + ?Sized>(
    operation: &'static str,
    shape: &S,
    spacing: f64,
    density: f64,
) -> Result<(f64, Aabb<V>), GeometryError> {
    let a = positive_finite("lattice spacing", spacing)?;
    positive_finite("lattice density", density)?;
    Ok((a, bounds_of(shape, operation)?))
}

/// Assigns the uniform site mass and the totals. When the exact volume is unknown the
/// volume is taken as (sites × site volume), so `raw_mass_error` is `None`.
fn finish<V: Vector, S: Shape<V> + ?Sized>(
    shape: &S,
    lattice: &str,
    positions: Vec<V>,
    spacing: f64,
    density: f64,
    site_volume: f64,
    bounds: &Aabb<V>,
) -> Result<BodyParticles<V>, GeometryError> {
    if positions.is_empty() {
        return Err(GeometryError::EmptyPlacement {
            body: shape.describe(),
            reason: format!(
                "no site of the {lattice} lattice with spacing {spacing} m lies inside it \
                 (bounds {} to {}); use a smaller spacing",
                format_point(bounds.min),
                format_point(bounds.max)
            ),
        });
    }
    let n = positions.len();
    let exact_volume = shape.volume();
    let volume = exact_volume.unwrap_or(n as f64 * site_volume);
    Ok(BodyParticles {
        body: shape.describe(),
        masses: vec![density * site_volume; n],
        spacing: vec![spacing; n],
        density,
        exact_volume,
        volume,
        raw_mass_error: exact_volume.map(|v| n as f64 * site_volume / v - 1.0),
        lattice_equivalent_count: volume / cubic_site_volume(V::DIM, spacing),
        positions,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cuboid, HalfSpace, Sphere};
    use sph_core::{ScalarSupport, brute_force_neighbors};

    /// Smallest pair distance and the neighbour count of the particle nearest `centre`
    /// within 1.001 spacings.
    fn nn_stats<V: Vector>(p: &[V], a: f64, centre: V) -> (f64, usize) {
        let mut dmin = f64::INFINITY;
        for i in 0..p.len() {
            for j in 0..i {
                dmin = dmin.min((p[i] - p[j]).norm());
            }
        }
        let h = vec![1.001 * a; p.len()];
        let list = brute_force_neighbors(p, &ScalarSupport::new(&h).unwrap()).unwrap();
        let c = (0..p.len())
            .min_by(|&i, &j| {
                (p[i] - centre)
                    .norm()
                    .partial_cmp(&(p[j] - centre).norm())
                    .unwrap()
            })
            .unwrap();
        (dmin, list.count(c))
    }

    #[test]
    fn cubic_box_is_exact_and_cell_centred() {
        let b = Cuboid::new(DVec3::ZERO, DVec3::new(4.0, 3.0, 2.0)).unwrap();
        let p = cubic_lattice(&b, 0.5, 2.0).unwrap();
        assert_eq!(p.len(), 8 * 6 * 4);
        assert_eq!(p.raw_mass_error, Some(0.0));
        assert!((p.total_mass() - 2.0 * 24.0).abs() < 1e-12);
        assert!(p.positions.iter().all(|x| x.min_element() >= 0.25 - 1e-12));
        assert_eq!(p.masses[0], 2.0 * 0.125);
        assert_eq!(p.lattice_equivalent_count, 192.0);
    }

    #[test]
    fn cubic_in_each_dimension_has_nn_distance_spacing() {
        let a = 0.1;
        let seg = cubic_lattice(&Cuboid::new(0.0f64, 1.0).unwrap(), a, 1.0).unwrap();
        assert_eq!(seg.len(), 10);
        let (d, n) = nn_stats(&seg.positions, a, 0.5);
        assert!((d - a).abs() < 1e-12 && n == 2);
        let disc = cubic_lattice(&Sphere::new(DVec2::ZERO, 0.5).unwrap(), a, 1.0).unwrap();
        let (d, n) = nn_stats(&disc.positions, a, DVec2::ZERO);
        assert!((d - a).abs() < 1e-12 && n == 4);
        let ball = cubic_lattice(&Sphere::new(DVec3::ZERO, 0.5).unwrap(), a, 1.0).unwrap();
        let (d, n) = nn_stats(&ball.positions, a, DVec3::ZERO);
        assert!((d - a).abs() < 1e-12 && n == 6);
        // Ball of radius 5Δx: the lattice count misses the volume by a boundary effect
        // (552 sites, +5.4 %).
        assert_eq!(ball.len(), 552);
        assert!((ball.raw_mass_error.unwrap() - 0.0542).abs() < 1e-3);
    }

    #[test]
    fn hexagonal_nn_distance_and_site_area() {
        let a = 0.1;
        let disc = Sphere::new(DVec2::new(0.3, 0.1), 1.0).unwrap();
        let p = hexagonal_lattice(&disc, a, 3.0).unwrap();
        let (d, n) = nn_stats(&p.positions, a, DVec2::new(0.3, 0.1));
        assert!((d - a).abs() < 1e-12, "{d}");
        assert_eq!(n, 6);
        assert!((p.masses[0] - 3.0 * 3f64.sqrt() / 2.0 * 0.01).abs() < 1e-15);
        // Disc of radius 10Δx: boundary effect, measured +1.2 %.
        assert!(
            p.raw_mass_error.unwrap().abs() < 0.015,
            "{:?}",
            p.raw_mass_error
        );
    }

    #[test]
    fn hcp_nn_distance_and_mass_per_site() {
        let a = 0.2;
        let ball = Sphere::new(DVec3::new(0.1, -0.2, 0.3), 1.0).unwrap();
        let p = hcp_lattice(&ball, a, 2.0).unwrap();
        let (d, n) = nn_stats(&p.positions, a, ball.centre());
        assert!((d - a).abs() < 1e-12, "{d}");
        assert_eq!(n, 12);
        assert!((p.masses[0] - 2.0 * a.powi(3) / 2f64.sqrt()).abs() < 1e-15);
        // Sites × Δx³/√2 recovers the ball's volume up to the boundary effect.
        assert!(
            p.raw_mass_error.unwrap().abs() < 0.03,
            "{:?}",
            p.raw_mass_error
        );
        assert!(p.positions.iter().all(|&x| ball.contains(x)));
    }

    #[test]
    fn errors_name_the_body() {
        let tiny = Sphere::new(DVec3::ZERO, 0.1).unwrap();
        // Spacing 1: the centred cubic lattice has its single site at the centre, so it
        // fits; the HCP one too. A spacing larger than the ball's diameter with the box
        // corner-centred: a 2-site lattice along each axis misses the ball.
        let e = cubic_lattice(&tiny, 0.15, 1.0).unwrap_err();
        assert!(matches!(e, GeometryError::EmptyPlacement { .. }));
        assert!(
            e.to_string()
                .contains("sphere (centre (0, 0, 0), radius 0.1 m)")
        );
        let h = HalfSpace::new(DVec3::ZERO, DVec3::Z).unwrap();
        assert!(matches!(
            hcp_lattice(&h, 0.1, 1.0),
            Err(GeometryError::Unbounded { .. })
        ));
        assert!(cubic_lattice(&tiny, -0.1, 1.0).is_err());
        assert!(cubic_lattice(&tiny, 0.01, 0.0).is_err());
        assert!(matches!(
            cubic_lattice(&Sphere::new(DVec3::ZERO, 1.0).unwrap(), 1e-5, 1.0),
            Err(GeometryError::TooManyPoints { .. })
        ));
    }
}

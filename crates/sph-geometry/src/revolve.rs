//! 3-D particles from an axisymmetric (RZ) placement: each ring is replaced by points
//! spread evenly around the z axis.
//!
//! Why: a cubic lattice has preferred in-plane axes, and a flow that spreads radially
//! (the foot of a Taylor rod, a crater rim) spreads differently along them and between
//! them (docs/verification.md, Taylor bar). Points on rings have no preferred azimuth
//! beyond the ring's own point spacing, and a body placed this way is the 3-D twin of the
//! RZ run made from the same rings: the same radii, heights and masses, so an RZ-against-
//! 3-D comparison measures the geometry and not the placement.
//!
//! A ring at radius r with spacing Δ and mass μ per radian gets
//! n = s · max(1, round(2πr/(sΔ))) points at the azimuths φ_k = (k + ½) 2π/n, each of mass
//! 2πμ/n, so the points of a ring are Δ apart along it up to rounding and carry exactly
//! the ring's mass. `s` (the azimuthal multiple) makes n divisible by s: with s = 4 no
//! point lies on the planes x = 0 or y = 0 and each quadrant holds exactly n/4 points of
//! every ring, so a quarter model (x > 0, y > 0 between reflecting walls) is exact.

use crate::error::GeometryError;
use crate::placement::BodyParticles;
use sph_core::glam::{DVec2, DVec3};
use std::f64::consts::TAU;

/// The number of points a ring of radius `radius` and spacing `spacing` gets:
/// `multiple` · max(1, round(2π r/(multiple · Δ))).
pub fn ring_point_count(radius: f64, spacing: f64, multiple: usize) -> usize {
    let s = multiple.max(1);
    s * ((TAU * radius / (s as f64 * spacing)).round() as usize).max(1)
}

/// Revolves the rings of an RZ placement (positions (r, z) with r > 0, masses per radian,
/// as [`rz_lattice`](crate::rz_lattice) and [`RzLayeredPlacement`](crate::RzLayeredPlacement)
/// return them) about the z axis into 3-D particles; see the module docs. Each ring's
/// spacing carries over to its points. The totals keep their meaning: the same body,
/// volume and raw mass error (the ring masses are split, not changed), and
/// `lattice_equivalent_count` = volume/Δ_min³.
///
/// Errors: `multiple` = 0, or a ring with r ≤ 0, a non-finite coordinate, or a
/// non-positive spacing or mass (which an RZ placement never returns).
pub fn revolve(
    rings: &BodyParticles<DVec2>,
    multiple: usize,
) -> Result<BodyParticles<DVec3>, GeometryError> {
    if multiple == 0 {
        return Err(GeometryError::InvalidCount {
            field: "revolve(multiple)",
            value: multiple,
            requirement: "must be at least 1",
        });
    }
    let mut positions = Vec::new();
    let mut masses = Vec::new();
    let mut spacing = Vec::new();
    for ((p, &mu), &dx) in rings
        .positions
        .iter()
        .zip(&rings.masses)
        .zip(&rings.spacing)
    {
        check_ring(*p, mu, dx)?;
        let n = ring_point_count(p.x, dx, multiple);
        let m = TAU * mu / n as f64;
        for k in 0..n {
            let phi = (k as f64 + 0.5) * TAU / n as f64;
            positions.push(DVec3::new(p.x * phi.cos(), p.x * phi.sin(), p.y));
            masses.push(m);
            spacing.push(dx);
        }
    }
    let dmin = rings.min_spacing();
    Ok(BodyParticles {
        body: rings.body.clone(),
        positions,
        masses,
        spacing,
        density: rings.density,
        exact_volume: rings.exact_volume,
        volume: rings.volume,
        raw_mass_error: rings.raw_mass_error,
        lattice_equivalent_count: rings.volume / (dmin * dmin * dmin),
    })
}

/// A ring must sit off the axis with finite coordinates and a positive spacing and mass.
fn check_ring(p: DVec2, mass: f64, spacing: f64) -> Result<(), GeometryError> {
    if !(p.x > 0.0 && p.x.is_finite() && p.y.is_finite()) {
        return Err(GeometryError::InvalidVector {
            field: "revolve(ring position)",
            value: [p.x, p.y, 0.0],
            requirement: "a ring needs a finite radius r > 0 and a finite height z",
        });
    }
    for (field, v) in [
        ("revolve(ring mass)", mass),
        ("revolve(ring spacing)", spacing),
    ] {
        if !(v > 0.0 && v.is_finite()) {
            return Err(GeometryError::InvalidParameter {
                field,
                value: v,
                requirement: "must be positive and finite",
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cylinder, Sphere, rz_lattice};
    use crate::{RzLayeredPlacement, Shape};

    fn close(a: f64, b: f64, tol: f64) {
        assert!((a / b - 1.0).abs() < tol, "{a} against {b}");
    }

    #[test]
    fn a_rod_keeps_its_mass_and_each_ring_its_radius() {
        let rod = Cylinder::new(DVec3::ZERO, DVec3::Z, 3.2e-3, 32.4e-3).unwrap();
        let dx = 0.4e-3;
        let rings = rz_lattice(&rod, dx, 8930.0).unwrap();
        let body = revolve(&rings, 4).unwrap();
        // The rings tile the disc exactly (annuli a Δ … (a+1) Δ), so the mass is exact
        // up to the lattice's z layers, which fit the rod's length exactly here too.
        let exact = 8930.0 * rod.volume().unwrap();
        close(body.total_mass(), exact, 1e-12);
        close(body.total_mass(), TAU * rings.total_mass(), 1e-12);
        // Every point lies at its ring's radius, off the symmetry planes, and each
        // quadrant holds a quarter of the points.
        let mut quadrant = [0usize; 4];
        for p in &body.positions {
            let r = p.truncate().length();
            assert!(rings.positions.iter().any(|q| (q.x - r).abs() < 1e-12));
            assert!(p.x.abs() > 1e-9 && p.y.abs() > 1e-9);
            quadrant[(p.x < 0.0) as usize * 2 + (p.y < 0.0) as usize] += 1;
        }
        assert!(
            quadrant.iter().all(|&q| q * 4 == body.len()),
            "{quadrant:?}"
        );
    }

    #[test]
    fn points_along_a_ring_are_about_one_spacing_apart() {
        for (r, dx) in [(0.5, 1.0), (1.5, 1.0), (7.5, 1.0), (40.3, 0.7)] {
            let n = ring_point_count(r, dx, 1);
            let chord = 2.0 * r * (TAU / (2.0 * n as f64)).sin();
            // round() keeps the arc within half a point of Δ; the innermost rings have
            // the fewest points and the largest relative rounding.
            assert!(n >= 1);
            assert!((TAU * r / n as f64 / dx - 1.0).abs() <= 0.5 / n as f64 + 1e-12 || n == 1);
            assert!(chord <= TAU * r / n as f64 + 1e-12);
        }
        assert_eq!(ring_point_count(0.5, 1.0, 4), 4);
        assert_eq!(ring_point_count(10.0, 1.0, 4), 64);
        assert_eq!(ring_point_count(10.0, 1.0, 1), 63);
    }

    #[test]
    fn a_variable_resolution_sphere_revolves_with_its_spacings() {
        let ball = Sphere::new(DVec3::ZERO, 3.0e-3).unwrap();
        let rings = RzLayeredPlacement::new(0.0, 0.5e-3, 1.0, 2785.0)
            .unwrap()
            .place(&ball)
            .unwrap();
        let body = revolve(&rings, 1).unwrap();
        close(body.total_mass(), TAU * rings.total_mass(), 1e-12);
        assert_eq!(body.raw_mass_error, rings.raw_mass_error);
        assert!(body.positions.iter().all(|p| ball.contains(*p)));
        assert_eq!(body.min_spacing(), rings.min_spacing());
        // About as many points as a cubic lattice at the same spacing.
        let share = body.lattice_share();
        assert!((0.8..1.25).contains(&share), "lattice share {share}");
    }

    #[test]
    fn bad_input_is_named() {
        let rod = Cylinder::new(DVec3::ZERO, DVec3::Z, 1.0, 1.0).unwrap();
        let mut rings = rz_lattice(&rod, 0.25, 1.0).unwrap();
        assert!(matches!(
            revolve(&rings, 0),
            Err(GeometryError::InvalidCount { .. })
        ));
        rings.positions[0].x = 0.0;
        let e = revolve(&rings, 1).unwrap_err().to_string();
        assert!(e.contains("ring position"), "{e}");
        rings.positions[0].x = 0.1;
        rings.masses[1] = f64::NAN;
        let e = revolve(&rings, 1).unwrap_err().to_string();
        assert!(e.contains("ring mass"), "{e}");
    }
}

//! The Fibonacci sphere (paper §4): N nearly evenly spaced points on a sphere, each
//! owning the same area 4πR²/N.
//!
//! Point n = 1..N sits at height z_n = R(1 − (2n − 1)/N), at distance
//! ρ_n = sqrt(R² − z_n²) from the polar axis and azimuth 2πnφ with φ = (√5 − 1)/2.
//! The heights are the midpoints of N bands of equal height 2R/N, and by Archimedes'
//! hat-box theorem bands of equal height have equal area, so the points are
//! equal-area; the golden-ratio azimuth keeps consecutive points from lining up.

use crate::error::{GeometryError, unit_vector};
use sph_core::glam::DVec3;
use std::f64::consts::TAU;

/// φ = (√5 − 1)/2, the fractional golden ratio that sets the azimuth step 2πφ.
pub const GOLDEN_FRACTION: f64 = 0.618_033_988_749_894_8;

/// Unit vector of point `n` (1-based, `1 ≤ n ≤ count`) of a `count`-point Fibonacci
/// sphere.
#[inline]
pub fn fibonacci_direction(n: usize, count: usize) -> DVec3 {
    debug_assert!(n >= 1 && n <= count);
    let t = 1.0 - (2 * n - 1) as f64 / count as f64;
    // (1 − t)(1 + t) rather than 1 − t² keeps the polar points accurate.
    let rho = ((1.0 - t) * (1.0 + t)).max(0.0).sqrt();
    // Reduce nφ to its fractional part before scaling by 2π, so the angle keeps its
    // precision for large n.
    let (sin, cos) = (TAU * (n as f64 * GOLDEN_FRACTION).fract()).sin_cos();
    DVec3::new(rho * cos, rho * sin, t)
}

/// The orientation of a Fibonacci sphere: an orthonormal frame (e1, e2, pole) mapping
/// the formula's (x, y, z) to space. The paper's formula has its poles on ±z
/// ([`PoleFrame::Z`]). The spiral is least regular near the poles, so a placement may
/// turn them away from where resolution matters (off the impact axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoleFrame {
    e1: DVec3,
    e2: DVec3,
    pole: DVec3,
}

impl PoleFrame {
    /// Poles on ±z: the paper's formula unchanged.
    pub const Z: Self = Self {
        e1: DVec3::X,
        e2: DVec3::Y,
        pole: DVec3::Z,
    };

    /// Poles along `axis` (normalised here; finite and non-zero).
    pub fn new(axis: DVec3) -> Result<Self, GeometryError> {
        let pole = unit_vector("FibonacciPlacement.pole_axis", axis)?;
        if pole == DVec3::Z {
            return Ok(Self::Z);
        }
        let (e1, e2) = pole.any_orthonormal_pair();
        Ok(Self { e1, e2, pole })
    }

    /// The polar axis.
    pub fn pole(&self) -> DVec3 {
        self.pole
    }

    /// Maps a direction from the formula's frame to space.
    #[inline]
    pub fn apply(&self, local: DVec3) -> DVec3 {
        self.e1 * local.x + self.e2 * local.y + self.pole * local.z
    }
}

/// The `count` points of the Fibonacci sphere of `radius` about `centre`, in order
/// n = 1..count (north to south).
pub fn fibonacci_sphere(centre: DVec3, radius: f64, count: usize) -> Vec<DVec3> {
    (1..=count)
        .map(|n| centre + fibonacci_direction(n, count) * radius)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn golden_fraction() {
        assert!((GOLDEN_FRACTION - (5f64.sqrt() - 1.0) / 2.0).abs() <= f64::EPSILON);
    }

    #[test]
    fn formula_of_the_paper() {
        // n = 2 of N = 10, R = 3 about (1, 2, 3).
        let (r, n, big_n) = (3.0f64, 2.0f64, 10.0f64);
        let z = r * (1.0 - (2.0 * n - 1.0) / big_n);
        let rho = (r * r - z * z).sqrt();
        let a = 2.0 * std::f64::consts::PI * n * GOLDEN_FRACTION;
        let expect = DVec3::new(1.0 + rho * a.cos(), 2.0 + rho * a.sin(), 3.0 + z);
        let got = fibonacci_sphere(DVec3::new(1.0, 2.0, 3.0), 3.0, 10)[1];
        assert!((got - expect).length() < 1e-14, "{got} {expect}");
    }

    #[test]
    fn points_lie_on_the_sphere_and_balance() {
        let c = DVec3::new(-1.0, 0.5, 2.0);
        let r = 7.5;
        let pts = fibonacci_sphere(c, r, 5000);
        assert_eq!(pts.len(), 5000);
        for p in &pts {
            assert!(((*p - c).length() - r).abs() <= 4.0 * f64::EPSILON * r);
        }
        // Equal-area points: the centroid sits at the centre up to O(1/N).
        let mean = pts.iter().fold(DVec3::ZERO, |s, p| s + *p) / pts.len() as f64;
        assert!((mean - c).length() < 2e-3 * r, "{mean}");
        // Mirror symmetry of the heights: z_n + z_(N+1−n) = 0.
        assert!((pts[0].z - c.z + (pts[4999].z - c.z)).abs() < 1e-12);
    }

    #[test]
    fn pole_frame_is_orthonormal() {
        assert_eq!(PoleFrame::new(DVec3::Z * 3.0).unwrap(), PoleFrame::Z);
        let u = DVec3::new(0.3, -0.2, 0.9);
        assert_eq!(PoleFrame::Z.apply(u), u);
        let f = PoleFrame::new(DVec3::new(1.0, 1.0, 0.0)).unwrap();
        assert!((f.apply(DVec3::Z) - DVec3::new(1.0, 1.0, 0.0).normalize()).length() < 1e-15);
        assert!((f.apply(u).length() - u.length()).abs() < 1e-15);
        assert!(f.e1.dot(f.e2).abs() < 1e-15 && f.e1.dot(f.pole).abs() < 1e-15);
        assert!(PoleFrame::new(DVec3::ZERO).is_err());
    }

    #[test]
    fn octant_share_tends_to_one_eighth() {
        let n = 100_000;
        let inside = (1..=n)
            .map(|k| fibonacci_direction(k, n))
            .filter(|u| u.x >= 0.0 && u.y >= 0.0 && u.z >= 0.0)
            .count();
        assert!((inside as f64 / n as f64 - 0.125).abs() < 1e-3);
    }
}

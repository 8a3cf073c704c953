//! [`Cylinder`]: the 3-D right circular cylinder of any axis direction. The study's
//! target is a basalt cylinder Ø123.3 mm × 123.3 mm (paper §6).

use crate::error::{GeometryError, finite_vector, positive_finite, unit_vector};
use crate::shape::{Aabb, Shape, format_point};
use sph_core::glam::DVec3;
use std::f64::consts::PI;

/// The closed cylinder of points whose projection on the axis lies within
/// `[0, length]` from `base` and whose distance from the axis is at most `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    base: DVec3,
    axis: DVec3,
    radius: f64,
    length: f64,
}

impl Cylinder {
    /// A cylinder from the centre of its base face, the axis direction (normalised here;
    /// finite and non-zero), the radius and the length along the axis (both positive).
    pub fn new(base: DVec3, axis: DVec3, radius: f64, length: f64) -> Result<Self, GeometryError> {
        Ok(Self {
            base: finite_vector("Cylinder.base", base)?,
            axis: unit_vector("Cylinder.axis", axis)?,
            radius: positive_finite("Cylinder.radius", radius)?,
            length: positive_finite("Cylinder.length", length)?,
        })
    }

    /// The cylinder between the centres of its two end faces.
    pub fn between(start: DVec3, end: DVec3, radius: f64) -> Result<Self, GeometryError> {
        finite_vector("Cylinder.start", start)?;
        finite_vector("Cylinder.end", end)?;
        let length = (end - start).length();
        if !(length > 0.0) {
            return Err(GeometryError::InvalidVector {
                field: "Cylinder.end",
                value: end.to_array(),
                requirement: "must differ from Cylinder.start",
            });
        }
        Self::new(start, end - start, radius, length)
    }

    /// Centre of the base face.
    pub fn base(&self) -> DVec3 {
        self.base
    }
    /// Unit axis, from the base face towards the other end.
    pub fn axis(&self) -> DVec3 {
        self.axis
    }
    /// Radius (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }
    /// Length along the axis (m).
    pub fn length(&self) -> f64 {
        self.length
    }
}

impl Shape<DVec3> for Cylinder {
    #[inline]
    fn contains(&self, p: DVec3) -> bool {
        let d = p - self.base;
        let t = d.dot(self.axis);
        if !(0.0..=self.length).contains(&t) {
            return false;
        }
        (d - self.axis * t).length_squared() <= self.radius * self.radius
    }

    /// The exact box of the two end discs: a disc of radius R with unit normal a reaches
    /// R·sqrt(1 − a_k²) along axis k.
    fn bounds(&self) -> Option<Aabb<DVec3>> {
        let top = self.base + self.axis * self.length;
        let reach = DVec3::new(
            (1.0 - self.axis.x * self.axis.x).max(0.0).sqrt(),
            (1.0 - self.axis.y * self.axis.y).max(0.0).sqrt(),
            (1.0 - self.axis.z * self.axis.z).max(0.0).sqrt(),
        ) * self.radius;
        Some(Aabb {
            min: self.base.min(top) - reach,
            max: self.base.max(top) + reach,
        })
    }

    fn volume(&self) -> Option<f64> {
        Some(PI * self.radius * self.radius * self.length)
    }

    fn describe(&self) -> String {
        format!(
            "cylinder (base {}, axis {}, radius {} m, length {} m)",
            format_point(self.base),
            format_point(self.axis),
            self.radius,
            self.length
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::estimate_volume;

    #[test]
    fn validates_fields() {
        let e = Cylinder::new(DVec3::ZERO, DVec3::Z, -1.0, 1.0).unwrap_err();
        assert!(e.to_string().contains("Cylinder.radius = -1"));
        assert!(Cylinder::new(DVec3::ZERO, DVec3::ZERO, 1.0, 1.0).is_err());
        assert!(Cylinder::new(DVec3::ZERO, DVec3::Z, 1.0, 0.0).is_err());
        assert!(Cylinder::between(DVec3::ONE, DVec3::ONE, 1.0).is_err());
    }

    #[test]
    fn containment_along_z() {
        // The study's target: axis z, top face at z = 0, body below.
        let c = Cylinder::new(DVec3::new(0.0, 0.0, -0.1233), DVec3::Z, 0.06165, 0.1233).unwrap();
        assert!(c.contains(DVec3::new(0.0, 0.0, 0.0)));
        assert!(c.contains(DVec3::new(0.06, 0.0, -0.1)));
        assert!(!c.contains(DVec3::new(0.0, 0.0, 1e-9)));
        assert!(!c.contains(DVec3::new(0.05, 0.05, -0.05)));
        let b = c.bounds().unwrap();
        assert!(
            (b.min - DVec3::new(-0.06165, -0.06165, -0.1233))
                .abs()
                .max_element()
                < 1e-15
        );
        assert!(
            (b.max - DVec3::new(0.06165, 0.06165, 0.0))
                .abs()
                .max_element()
                < 1e-15
        );
    }

    #[test]
    fn oblique_axis() {
        let a = DVec3::new(1.0, 1.0, 1.0).normalize();
        let c = Cylinder::between(DVec3::ZERO, a * 4.0, 0.5).unwrap();
        assert!((c.axis() - a).length() < 1e-15);
        assert!((c.length() - 4.0).abs() < 1e-15);
        // On the axis, and 0.49 off it perpendicular to the axis.
        let perp = DVec3::new(1.0, -1.0, 0.0).normalize();
        assert!(c.contains(a * 2.0));
        assert!(c.contains(a * 2.0 + perp * 0.49));
        assert!(!c.contains(a * 2.0 + perp * 0.51));
        assert!(!c.contains(a * 4.01));
        assert!(!c.contains(-a * 0.01));
        // Bounds are exact: a disc of radius 0.5 with normal (1,1,1)/√3 reaches
        // 0.5·sqrt(2/3) along each axis.
        let b = c.bounds().unwrap();
        let reach = 0.5 * (2.0f64 / 3.0).sqrt();
        assert!((b.min - DVec3::splat(-reach)).abs().max_element() < 1e-14);
        assert!(
            (b.max - DVec3::splat(4.0 / 3f64.sqrt() + reach))
                .abs()
                .max_element()
                < 1e-14
        );
        // Every bound face is touched by the cylinder (tight), and volume agrees.
        let rel = estimate_volume(&c, 160).unwrap() / c.volume().unwrap() - 1.0;
        assert!(rel.abs() < 5e-3, "{rel}");
    }

    #[test]
    fn estimate_agrees_with_exact_volume_axis_z() {
        let c = Cylinder::new(DVec3::ZERO, DVec3::Z, 1.0, 2.0).unwrap();
        let rel = estimate_volume(&c, 200).unwrap() / c.volume().unwrap() - 1.0;
        assert!(rel.abs() < 1e-3, "{rel}");
    }
}

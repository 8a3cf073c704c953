//! [`HalfSpace`]: all points on the inner side of a plane (a line in 2-D, a point in
//! 1-D). Unbounded, so it is only useful cut against a bounded shape in a
//! [`Intersection`](crate::Intersection) or [`Difference`](crate::Difference).

use crate::error::{GeometryError, finite_vector, unit_vector};
use crate::shape::{Aabb, Shape, format_point};
use sph_core::Vector;

/// The closed half-space `(p − point)·normal ≤ 0`: `normal` points out of the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfSpace<V: Vector> {
    point: V,
    normal: V,
}

impl<V: Vector> HalfSpace<V> {
    /// A half-space through `point` with outward `normal` (normalised here; it must be
    /// finite and non-zero).
    pub fn new(point: V, normal: V) -> Result<Self, GeometryError> {
        Ok(Self {
            point: finite_vector("HalfSpace.point", point)?,
            normal: unit_vector("HalfSpace.normal", normal)?,
        })
    }
    /// A point on the bounding plane.
    pub fn point(&self) -> V {
        self.point
    }
    /// The outward unit normal.
    pub fn normal(&self) -> V {
        self.normal
    }
    /// Signed distance from the plane, positive outside.
    #[inline]
    pub fn signed_distance(&self, p: V) -> f64 {
        (p - self.point).dot(self.normal)
    }
}

impl<V: Vector> Shape<V> for HalfSpace<V> {
    #[inline]
    fn contains(&self, p: V) -> bool {
        self.signed_distance(p) <= 0.0
    }
    fn bounds(&self) -> Option<Aabb<V>> {
        None
    }
    fn volume(&self) -> Option<f64> {
        None
    }
    fn describe(&self) -> String {
        format!(
            "half-space (point {}, outward normal {})",
            format_point(self.point),
            format_point(self.normal)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::estimate_volume;
    use sph_core::glam::DVec3;

    #[test]
    fn inner_side_is_inside() {
        let h = HalfSpace::new(DVec3::new(0.0, 0.0, 1.0), DVec3::new(0.0, 0.0, 3.0)).unwrap();
        assert_eq!(h.normal(), DVec3::Z);
        assert!(h.contains(DVec3::new(5.0, -7.0, 0.0)));
        assert!(h.contains(DVec3::new(5.0, -7.0, 1.0)));
        assert!(!h.contains(DVec3::new(0.0, 0.0, 1.0 + 1e-9)));
        assert!(h.bounds().is_none() && h.volume().is_none());
        assert!(matches!(
            estimate_volume(&h, 4),
            Err(GeometryError::Unbounded { .. })
        ));
        assert!(HalfSpace::new(DVec3::ZERO, DVec3::ZERO).is_err());
        let line = HalfSpace::new(2.0f64, -1.0).unwrap();
        assert!(line.contains(3.0) && !line.contains(1.0));
    }
}

//! [`Cuboid`]: the axis-aligned box in any dimension (a rectangle in 2-D, an interval in
//! 1-D), e.g. the cube of the placement acceptance test (docs/placement.md).

use crate::error::{GeometryError, finite_vector};
use crate::shape::{Aabb, Shape, format_point};
use sph_core::Vector;

/// The closed box `min ≤ p ≤ max` (component-wise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid<V: Vector> {
    aabb: Aabb<V>,
}

impl<V: Vector> Cuboid<V> {
    /// A box with finite corners and `min < max` in every component (a box of zero
    /// thickness holds no volume to fill).
    pub fn new(min: V, max: V) -> Result<Self, GeometryError> {
        finite_vector("Cuboid.min", min)?;
        finite_vector("Cuboid.max", max)?;
        if (0..V::DIM).any(|k| !(min.component(k) < max.component(k))) {
            return Err(GeometryError::InvalidVector {
                field: "Cuboid.max",
                value: max.to_array3(),
                requirement: "must exceed Cuboid.min in every component",
            });
        }
        Ok(Self {
            aabb: Aabb { min, max },
        })
    }

    /// A box of the given centre and half edge lengths (each positive).
    pub fn from_centre(centre: V, half_extents: V) -> Result<Self, GeometryError> {
        finite_vector("Cuboid.centre", centre)?;
        finite_vector("Cuboid.half_extents", half_extents)?;
        if (0..V::DIM).any(|k| !(half_extents.component(k) > 0.0)) {
            return Err(GeometryError::InvalidVector {
                field: "Cuboid.half_extents",
                value: half_extents.to_array3(),
                requirement: "every component must be positive",
            });
        }
        Self::new(centre - half_extents, centre + half_extents)
    }

    /// The box as an [`Aabb`].
    pub fn aabb(&self) -> Aabb<V> {
        self.aabb
    }
}

impl<V: Vector> Shape<V> for Cuboid<V> {
    #[inline]
    fn contains(&self, p: V) -> bool {
        self.aabb.contains(p)
    }
    fn bounds(&self) -> Option<Aabb<V>> {
        Some(self.aabb)
    }
    fn volume(&self) -> Option<f64> {
        Some(self.aabb.volume())
    }
    fn describe(&self) -> String {
        format!(
            "box (min {}, max {})",
            format_point(self.aabb.min),
            format_point(self.aabb.max)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::estimate_volume;
    use sph_core::glam::{DVec2, DVec3};

    #[test]
    fn validates_corners() {
        assert!(Cuboid::new(DVec3::ZERO, DVec3::new(1.0, 0.0, 1.0)).is_err());
        assert!(Cuboid::new(DVec3::ONE, DVec3::ZERO).is_err());
        assert!(Cuboid::new(DVec3::ZERO, DVec3::new(1.0, f64::INFINITY, 1.0)).is_err());
        assert!(Cuboid::from_centre(DVec2::ZERO, DVec2::new(1.0, -1.0)).is_err());
    }

    #[test]
    fn containment_bounds_volume() {
        let c = Cuboid::from_centre(DVec3::ONE, DVec3::new(1.0, 2.0, 0.5)).unwrap();
        assert_eq!(c.volume(), Some(8.0));
        assert!(c.contains(DVec3::new(0.0, -1.0, 0.5)));
        assert!(!c.contains(DVec3::new(0.0, -1.0, 0.49)));
        assert_eq!(c.bounds().unwrap().max, DVec3::new(2.0, 3.0, 1.5));
        let seg = Cuboid::new(-1.0f64, 2.0).unwrap();
        assert_eq!(seg.volume(), Some(3.0));
        // A box aligned with the quadrature cells is integrated exactly.
        let rect = Cuboid::new(DVec2::ZERO, DVec2::new(2.0, 1.0)).unwrap();
        assert!((estimate_volume(&rect, 64).unwrap() - 2.0).abs() < 1e-12);
    }
}

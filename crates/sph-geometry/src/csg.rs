//! Boolean combinations of shapes (constructive solid geometry): [`Union`],
//! [`Intersection`] and [`Difference`] of two shapes, generic or boxed `dyn Shape`.
//!
//! Their exact volume is not known in general, so [`Shape::volume`] is `None`; use
//! [`estimate_volume`](crate::estimate_volume). Bounds come from the operands where
//! that is possible.

use crate::shape::{Aabb, Shape};
use sph_core::Vector;

/// Points in `a` or in `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Union<A, B> {
    /// First operand.
    pub a: A,
    /// Second operand.
    pub b: B,
}

/// Points in both `a` and `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Intersection<A, B> {
    /// First operand.
    pub a: A,
    /// Second operand.
    pub b: B,
}

/// Points in `a` but not in `b`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Difference<A, B> {
    /// The shape cut from.
    pub a: A,
    /// The shape removed.
    pub b: B,
}

impl<V: Vector, A: Shape<V>, B: Shape<V>> Shape<V> for Union<A, B> {
    #[inline]
    fn contains(&self, p: V) -> bool {
        self.a.contains(p) || self.b.contains(p)
    }
    /// The box holding both operands' boxes; unbounded if either is.
    fn bounds(&self) -> Option<Aabb<V>> {
        Some(self.a.bounds()?.union(&self.b.bounds()?))
    }
    fn volume(&self) -> Option<f64> {
        None
    }
    fn describe(&self) -> String {
        format!(
            "union of [{}] and [{}]",
            self.a.describe(),
            self.b.describe()
        )
    }
}

impl<V: Vector, A: Shape<V>, B: Shape<V>> Shape<V> for Intersection<A, B> {
    #[inline]
    fn contains(&self, p: V) -> bool {
        self.a.contains(p) && self.b.contains(p)
    }
    /// The overlap of the operands' boxes (either box alone if the other operand is
    /// unbounded). Disjoint boxes give a box of zero volume at the corner where they
    /// come closest: the intersection is empty, and a placement reports it so.
    fn bounds(&self) -> Option<Aabb<V>> {
        match (self.a.bounds(), self.b.bounds()) {
            (Some(x), Some(y)) => Some(x.intersection(&y).unwrap_or_else(|| {
                let p = x.min.component_max(y.min).component_min(x.max);
                Aabb { min: p, max: p }
            })),
            (Some(x), None) | (None, Some(x)) => Some(x),
            (None, None) => None,
        }
    }
    fn volume(&self) -> Option<f64> {
        None
    }
    fn describe(&self) -> String {
        format!(
            "intersection of [{}] and [{}]",
            self.a.describe(),
            self.b.describe()
        )
    }
}

impl<V: Vector, A: Shape<V>, B: Shape<V>> Shape<V> for Difference<A, B> {
    #[inline]
    fn contains(&self, p: V) -> bool {
        self.a.contains(p) && !self.b.contains(p)
    }
    /// The box of `a`: removing material never enlarges a body.
    fn bounds(&self) -> Option<Aabb<V>> {
        self.a.bounds()
    }
    fn volume(&self) -> Option<f64> {
        None
    }
    fn describe(&self) -> String {
        format!("[{}] minus [{}]", self.a.describe(), self.b.describe())
    }
}

/// Builder methods for boolean combinations: `a.union(b)`, `a.intersect(b)`,
/// `a.subtract(b)`.
pub trait ShapeExt<V: Vector>: Shape<V> + Sized {
    /// Points in `self` or in `other`.
    fn union<B: Shape<V>>(self, other: B) -> Union<Self, B> {
        Union { a: self, b: other }
    }
    /// Points in both `self` and `other`.
    fn intersect<B: Shape<V>>(self, other: B) -> Intersection<Self, B> {
        Intersection { a: self, b: other }
    }
    /// Points in `self` but not in `other`.
    fn subtract<B: Shape<V>>(self, other: B) -> Difference<Self, B> {
        Difference { a: self, b: other }
    }
}

impl<V: Vector, S: Shape<V>> ShapeExt<V> for S {}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cuboid, HalfSpace, Sphere, estimate_volume};
    use sph_core::glam::{DVec2, DVec3};
    use std::f64::consts::PI;

    fn unit_disc_and_square() -> (Sphere<DVec2>, Cuboid<DVec2>) {
        (
            Sphere::new(DVec2::ZERO, 1.0).unwrap(),
            Cuboid::new(DVec2::new(0.0, -0.5), DVec2::new(2.0, 0.5)).unwrap(),
        )
    }

    /// The truth table of each operator at points in: both, a only, b only, neither.
    #[test]
    fn truth_tables() {
        let (a, b) = unit_disc_and_square();
        let both = DVec2::new(0.5, 0.0);
        let a_only = DVec2::new(-0.5, 0.0);
        let b_only = DVec2::new(1.5, 0.0);
        let neither = DVec2::new(0.0, 3.0);
        for (p, ia, ib) in [
            (both, true, true),
            (a_only, true, false),
            (b_only, false, true),
            (neither, false, false),
        ] {
            assert_eq!(a.contains(p), ia);
            assert_eq!(b.contains(p), ib);
            assert_eq!(a.union(b).contains(p), ia || ib);
            assert_eq!(a.intersect(b).contains(p), ia && ib);
            assert_eq!(a.subtract(b).contains(p), ia && !ib);
            assert_eq!(b.subtract(a).contains(p), ib && !ia);
        }
    }

    #[test]
    fn bounds_from_operands() {
        let (a, b) = unit_disc_and_square();
        let u = a.union(b).bounds().unwrap();
        assert_eq!(
            (u.min, u.max),
            (DVec2::new(-1.0, -1.0), DVec2::new(2.0, 1.0))
        );
        let i = a.intersect(b).bounds().unwrap();
        assert_eq!(
            (i.min, i.max),
            (DVec2::new(0.0, -0.5), DVec2::new(1.0, 0.5))
        );
        let d = a.subtract(b).bounds().unwrap();
        assert_eq!(
            (d.min, d.max),
            (DVec2::new(-1.0, -1.0), DVec2::new(1.0, 1.0))
        );
        let h = HalfSpace::new(DVec2::ZERO, DVec2::X).unwrap();
        assert!(a.union(h).bounds().is_none());
        assert_eq!(a.intersect(h).bounds(), a.bounds());
        assert!(h.subtract(a).bounds().is_none());
        let far = Sphere::new(DVec2::splat(10.0), 1.0).unwrap();
        assert_eq!(a.intersect(far).bounds().unwrap().volume(), 0.0);
        assert!(a.union(b).volume().is_none());
    }

    #[test]
    fn boxed_dyn_operands_and_volume_estimate() {
        // A ball with its upper half cut off by a half-space: half the ball's volume.
        let ball: Box<dyn Shape<DVec3>> = Box::new(Sphere::new(DVec3::ZERO, 1.0).unwrap());
        let cut: Box<dyn Shape<DVec3>> = Box::new(HalfSpace::new(DVec3::ZERO, DVec3::Z).unwrap());
        let half = Intersection { a: ball, b: cut };
        let v = estimate_volume(&half, 100).unwrap();
        assert!((v / (2.0 / 3.0 * PI) - 1.0).abs() < 5e-3, "{v}");
        assert!(half.describe().starts_with("intersection of [sphere"));
        // A disc with a square hole.
        let (a, _) = unit_disc_and_square();
        let hole = Cuboid::from_centre(DVec2::ZERO, DVec2::splat(0.25)).unwrap();
        let v = estimate_volume(&a.subtract(hole), 800).unwrap();
        assert!((v - (PI - 0.25)).abs() < 1e-3, "{v}");
    }
}

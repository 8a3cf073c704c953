//! The [`Shape`] trait (a body as a point-membership test with optional bounds and
//! exact volume), the axis-aligned bounding box [`Aabb`], and [`estimate_volume`] for
//! shapes whose volume has no closed form.

use crate::error::{GeometryError, bounds_of, check_candidates, finite_vector};
use sph_core::Vector;
use std::f64::consts::PI;
use std::sync::Arc;

/// An axis-aligned box `[min, max]` (closed). Used as the bounds of a shape.
///
/// The fields are public for convenience; [`Aabb::new`] checks `min ≤ max`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb<V: Vector> {
    /// Lower corner.
    pub min: V,
    /// Upper corner.
    pub max: V,
}

impl<V: Vector> Aabb<V> {
    /// A box with finite corners and `min ≤ max` in every component.
    pub fn new(min: V, max: V) -> Result<Self, GeometryError> {
        finite_vector("Aabb.min", min)?;
        finite_vector("Aabb.max", max)?;
        if (0..V::DIM).any(|k| min.component(k) > max.component(k)) {
            return Err(GeometryError::InvalidVector {
                field: "Aabb.max",
                value: max.to_array3(),
                requirement: "must be at least Aabb.min in every component",
            });
        }
        Ok(Self { min, max })
    }

    /// Whether `p` lies in the closed box.
    #[inline]
    pub fn contains(&self, p: V) -> bool {
        (0..V::DIM).all(|k| {
            let x = p.component(k);
            x >= self.min.component(k) && x <= self.max.component(k)
        })
    }

    /// Edge lengths `max − min`.
    #[inline]
    pub fn extent(&self) -> V {
        self.max - self.min
    }

    /// Centre `(min + max)/2`.
    #[inline]
    pub fn centre(&self) -> V {
        (self.min + self.max) * 0.5
    }

    /// Volume (length in 1-D, area in 2-D); zero for an inverted box.
    pub fn volume(&self) -> f64 {
        (0..V::DIM)
            .map(|k| (self.max.component(k) - self.min.component(k)).max(0.0))
            .product()
    }

    /// The smallest box holding both.
    pub fn union(&self, other: &Self) -> Self {
        Self {
            min: self.min.component_min(other.min),
            max: self.max.component_max(other.max),
        }
    }

    /// The overlap of both boxes, or `None` when they are disjoint.
    pub fn intersection(&self, other: &Self) -> Option<Self> {
        let min = self.min.component_max(other.min);
        let max = self.max.component_min(other.max);
        (0..V::DIM)
            .all(|k| min.component(k) <= max.component(k))
            .then_some(Self { min, max })
    }

    /// Distance from `p` to the farthest corner: every point of the box lies within it.
    /// The variable-resolution placement stops adding layers beyond this radius.
    pub fn farthest_distance(&self, p: V) -> f64 {
        (0..V::DIM)
            .map(|k| {
                let x = p.component(k);
                let d = (x - self.min.component(k))
                    .abs()
                    .max((x - self.max.component(k)).abs());
                d * d
            })
            .sum::<f64>()
            .sqrt()
    }

    /// Distance from `p` to the nearest point of the box (zero inside). Layers closer to
    /// the placement origin than this cannot touch the body.
    pub fn nearest_distance(&self, p: V) -> f64 {
        (0..V::DIM)
            .map(|k| {
                let x = p.component(k);
                let d = (self.min.component(k) - x)
                    .max(x - self.max.component(k))
                    .max(0.0);
                d * d
            })
            .sum::<f64>()
            .sqrt()
    }
}

/// A body's geometry: which points it holds, its bounds, its volume.
///
/// Implementations must be cheap to query (`contains` sits in the inner loop of every
/// placement) and thread-safe (placements test points in parallel).
pub trait Shape<V: Vector>: Send + Sync {
    /// Whether `p` is in the body. Built-in shapes are closed sets (the boundary
    /// belongs to the body).
    fn contains(&self, p: V) -> bool;

    /// A box holding every point of the body, or `None` for an unbounded body.
    fn bounds(&self) -> Option<Aabb<V>>;

    /// The exact volume (length in 1-D, area in 2-D) where a closed form is known;
    /// `None` otherwise (use [`estimate_volume`]).
    fn volume(&self) -> Option<f64>;

    /// A short human-readable description used in error messages
    /// ("sphere (centre (0, 0, 0), radius 0.003 m)"). Defaults to the type name.
    fn describe(&self) -> String {
        std::any::type_name::<Self>().to_string()
    }
}

/// Shapes behind references and smart pointers are shapes (so `Box<dyn Shape<V>>` works).
macro_rules! forward_shape {
    ($($pointer:ty),*) => {$(
        impl<V: Vector, S: Shape<V> + ?Sized> Shape<V> for $pointer {
            #[inline]
            fn contains(&self, p: V) -> bool {
                (**self).contains(p)
            }
            fn bounds(&self) -> Option<Aabb<V>> {
                (**self).bounds()
            }
            fn volume(&self) -> Option<f64> {
                (**self).volume()
            }
            fn describe(&self) -> String {
                (**self).describe()
            }
        }
    )*};
}

forward_shape!(&S, Box<S>, Arc<S>);

/// Volume of the unit ball in `dim` dimensions: 2 (1-D), π (2-D), 4π/3 (3-D); the
/// general π^(d/2)/Γ(d/2 + 1) through the recurrence V_d = 2π/d · V_(d−2).
pub fn unit_ball_volume(dim: usize) -> f64 {
    match dim {
        0 => 1.0,
        1 => 2.0,
        d => 2.0 * PI / d as f64 * unit_ball_volume(d - 2),
    }
}

/// Estimates the volume of a bounded shape by midpoint-lattice quadrature: the bounds
/// are cut into `samples_per_axis^DIM` equal cells and each cell whose centre lies in
/// the shape counts in full. The error is a boundary effect, of order
/// (surface area × cell size)/volume, so it falls like `1/samples_per_axis`, usually
/// faster since errors of opposite sign cancel along a smooth boundary.
pub fn estimate_volume<V: Vector, S: Shape<V> + ?Sized>(
    shape: &S,
    samples_per_axis: usize,
) -> Result<f64, GeometryError> {
    if samples_per_axis == 0 {
        return Err(GeometryError::InvalidCount {
            field: "estimate_volume(samples_per_axis)",
            value: 0,
            requirement: "must be at least 1",
        });
    }
    let bounds = bounds_of(shape, "estimate_volume")?;
    let total = (samples_per_axis as f64).powi(V::DIM as i32);
    check_candidates(shape, "estimate_volume", total)?;
    let n = samples_per_axis;
    let cell = bounds.extent() / n as f64;
    let mut inside = 0usize;
    let mut index = vec![0usize; V::DIM];
    for _ in 0..total as usize {
        let p =
            V::from_fn(|k| bounds.min.component(k) + (index[k] as f64 + 0.5) * cell.component(k));
        if shape.contains(p) {
            inside += 1;
        }
        // Odometer increment over the DIM indices.
        for i in index.iter_mut() {
            *i += 1;
            if *i < n {
                break;
            }
            *i = 0;
        }
    }
    Ok(inside as f64 / total * bounds.volume())
}

/// Formats a point as `(x, y, z)` with its `DIM` components, for messages.
pub(crate) fn format_point<V: Vector>(p: V) -> String {
    let parts: Vec<String> = (0..V::DIM).map(|k| format!("{}", p.component(k))).collect();
    format!("({})", parts.join(", "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::{DVec2, DVec3};

    #[test]
    fn unit_ball_volumes() {
        assert_eq!(unit_ball_volume(1), 2.0);
        assert!((unit_ball_volume(2) - PI).abs() < 1e-15);
        assert!((unit_ball_volume(3) - 4.0 / 3.0 * PI).abs() < 1e-15);
        assert!((unit_ball_volume(4) - PI * PI / 2.0).abs() < 1e-14);
    }

    #[test]
    fn aabb_checks_and_measures() {
        assert!(Aabb::new(DVec2::new(1.0, 0.0), DVec2::new(0.0, 1.0)).is_err());
        assert!(Aabb::new(DVec2::new(f64::NAN, 0.0), DVec2::ONE).is_err());
        let a = Aabb::new(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0)).unwrap();
        assert_eq!(a.volume(), 6.0);
        assert_eq!(a.centre(), DVec3::new(0.5, 1.0, 1.5));
        assert!(a.contains(DVec3::new(1.0, 2.0, 3.0)));
        assert!(!a.contains(DVec3::new(1.0, 2.0, 3.0 + 1e-12)));
        assert_eq!(a.farthest_distance(DVec3::ZERO), 14f64.sqrt());
        assert_eq!(a.nearest_distance(DVec3::new(0.5, 1.0, 1.0)), 0.0);
        assert_eq!(a.nearest_distance(DVec3::new(-3.0, 6.0, 1.0)), 5.0);
        let b = Aabb::new(DVec3::splat(0.5), DVec3::splat(4.0)).unwrap();
        let i = a.intersection(&b).unwrap();
        assert_eq!(i.min, DVec3::splat(0.5));
        assert_eq!(i.max, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(a.union(&b).max, DVec3::splat(4.0));
        let far = Aabb::new(DVec3::splat(10.0), DVec3::splat(11.0)).unwrap();
        assert!(a.intersection(&far).is_none());
    }

    #[test]
    fn format_point_uses_dim_components() {
        assert_eq!(format_point(1.5f64), "(1.5)");
        assert_eq!(format_point(DVec3::new(0.0, 1.0, -2.5)), "(0, 1, -2.5)");
    }
}

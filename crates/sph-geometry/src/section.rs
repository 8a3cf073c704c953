//! Lower-dimensional sections of a 3-D shape, for runs in plane strain (2-D) and in
//! uniaxial strain (1-D):
//!
//! * [`PlaneSection`]: the section y = 0, a 2-D shape in (x, z) — the point (x, z) is
//!   inside when (x, 0, z) is. A plane-strain run treats the body as this section
//!   extruded without end along y.
//! * [`LineSection`]: the section x = y = 0 (the z axis), a 1-D shape in z — the point z
//!   is inside when (0, 0, z) is. A uniaxial-strain run treats the body as this segment
//!   extruded without end in x and y (a plate).
//!
//! The 2-D and 1-D vectors are (x, z) as [`DVec2`] and z as `f64`, so the section's "up"
//! is the 3-D z axis in every geometry. A section's measure (area in 2-D, length in 1-D)
//! has no general closed form from the 3-D shape's volume; a caller that knows it (a
//! sphere's section is a disc, a box's a rectangle) gives it with `with_measure`, else
//! [`Shape::volume`] is `None` and the placements estimate it.

use crate::shape::{Aabb, Shape};
use sph_core::glam::{DVec2, DVec3};

/// The section y = 0 of a 3-D shape, as a 2-D shape in (x, z) (module docs).
#[derive(Clone, Debug)]
pub struct PlaneSection<S> {
    shape: S,
    area: Option<f64>,
}

impl<S: Shape<DVec3>> PlaneSection<S> {
    /// The section of `shape`, its area unknown.
    pub fn new(shape: S) -> Self {
        Self { shape, area: None }
    }

    /// The section with its exact area `area` (m²), as [`Shape::volume`] will report.
    pub fn with_measure(self, area: f64) -> Self {
        Self {
            area: Some(area),
            ..self
        }
    }
}

impl<S: Shape<DVec3>> Shape<DVec2> for PlaneSection<S> {
    fn contains(&self, p: DVec2) -> bool {
        self.shape.contains(DVec3::new(p.x, 0.0, p.y))
    }

    /// The (x, z) extent of the 3-D bounds; `None` when the 3-D shape is unbounded or its
    /// bounds do not reach the plane y = 0 (the section is empty).
    fn bounds(&self) -> Option<Aabb<DVec2>> {
        let b = self.shape.bounds()?;
        (b.min.y <= 0.0 && b.max.y >= 0.0).then(|| Aabb {
            min: DVec2::new(b.min.x, b.min.z),
            max: DVec2::new(b.max.x, b.max.z),
        })
    }

    fn volume(&self) -> Option<f64> {
        self.area
    }

    fn describe(&self) -> String {
        format!("the section y = 0 of {}", self.shape.describe())
    }
}

/// The section x = y = 0 of a 3-D shape, as a 1-D shape in z (module docs).
#[derive(Clone, Debug)]
pub struct LineSection<S> {
    shape: S,
    length: Option<f64>,
}

impl<S: Shape<DVec3>> LineSection<S> {
    /// The section of `shape`, its length unknown.
    pub fn new(shape: S) -> Self {
        Self {
            shape,
            length: None,
        }
    }

    /// The section with its exact length `length` (m), as [`Shape::volume`] will report.
    pub fn with_measure(self, length: f64) -> Self {
        Self {
            length: Some(length),
            ..self
        }
    }
}

impl<S: Shape<DVec3>> Shape<f64> for LineSection<S> {
    fn contains(&self, z: f64) -> bool {
        self.shape.contains(DVec3::new(0.0, 0.0, z))
    }

    /// The z extent of the 3-D bounds; `None` when the 3-D shape is unbounded or its
    /// bounds do not reach the z axis (the section is empty).
    fn bounds(&self) -> Option<Aabb<f64>> {
        let b = self.shape.bounds()?;
        let spans = |lo: f64, hi: f64| lo <= 0.0 && hi >= 0.0;
        (spans(b.min.x, b.max.x) && spans(b.min.y, b.max.y)).then_some(Aabb {
            min: b.min.z,
            max: b.max.z,
        })
    }

    fn volume(&self) -> Option<f64> {
        self.length
    }

    fn describe(&self) -> String {
        format!("the section x = y = 0 of {}", self.shape.describe())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Cuboid, Sphere, cubic_lattice};

    /// A sphere's plane section is its great disc: a square lattice of it holds the sites
    /// within R of the centre, and its mass ρΔ² per site sums to ρπR² within the lattice's
    /// boundary error.
    #[test]
    fn plane_section_of_a_sphere_is_its_disc() {
        let r = 1.0e-2;
        let ball = Sphere::new(DVec3::new(0.0, 0.0, -r), r).unwrap();
        let disc = PlaneSection::new(ball).with_measure(std::f64::consts::PI * r * r);
        assert!(disc.contains(DVec2::new(0.9 * r, -r)));
        assert!(!disc.contains(DVec2::new(0.5 * r, 0.1 * r)));
        let b = disc.bounds().unwrap();
        assert_eq!(
            (b.min, b.max),
            (DVec2::new(-r, -2.0 * r), DVec2::new(r, 0.0))
        );
        let p = cubic_lattice(&disc, r / 20.0, 1000.0).unwrap();
        for x in &p.positions {
            assert!((*x - DVec2::new(0.0, -r)).length() <= r);
        }
        let err = p.raw_mass_error.unwrap();
        assert!(err.abs() < 0.02, "mass error {err}");
        assert_eq!(p.masses[0], 1000.0 * (r / 20.0) * (r / 20.0));
    }

    /// A box's line section is its z extent when it straddles the axis, and empty (no
    /// bounds) when it does not.
    #[test]
    fn line_section_of_a_box() {
        let slab = Cuboid::new(DVec3::new(-1.0, -1.0, -0.3), DVec3::new(1.0, 1.0, 0.0)).unwrap();
        let line = LineSection::new(slab).with_measure(0.3);
        let b = line.bounds().unwrap();
        assert_eq!((b.min, b.max), (-0.3, 0.0));
        assert!(line.contains(-0.1) && !line.contains(0.1));
        let p = cubic_lattice(&line, 0.01, 2.0).unwrap();
        assert_eq!(p.len(), 30);
        assert!(p.raw_mass_error.unwrap().abs() < 1e-12);
        let aside = Cuboid::new(DVec3::new(0.5, -1.0, -0.3), DVec3::new(1.0, 1.0, 0.0)).unwrap();
        assert!(LineSection::new(aside).bounds().is_none());
        let above = Cuboid::new(DVec3::new(-1.0, 0.5, 0.0), DVec3::new(1.0, 1.0, 1.0)).unwrap();
        assert!(PlaneSection::new(above).bounds().is_none());
    }
}

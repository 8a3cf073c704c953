//! Filling each body with particles — in 3-D, in the (r, z) half-plane for an
//! axisymmetric (RZ) scene, in the section y = 0 for a plane-strain scene or on the z axis
//! for a 1-D one — and the overlap check: no particle of one body may lie
//! inside another body's shape (two bodies in one place would double the mass there,
//! and their pair forces start from an unphysical compression).

use crate::materials::MaterialSpec;
use crate::scene::Scene;
use crate::scene::body::PlacementSpec;
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::settings::GeometryKind;
use rayon::prelude::*;
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};
use sph_core::glam::{DVec2, DVec3};
use sph_geometry::{
    Aabb, BodyParticles, FibonacciPlacement, GeometryError, LineSection, PlaneSection,
    RzLayeredPlacement, Shape, cubic_lattice, revolve, rz_lattice,
};
use std::f64::consts::TAU;

/// A body's particles in the scene's geometry.
#[derive(Clone, Debug)]
pub enum PlacedParticles {
    /// 3-D: positions (m), masses (kg), spacings (m).
    ThreeD(BodyParticles<DVec3>),
    /// RZ: positions (r, z) in the half-plane r > 0 (m), ring masses per radian (kg/rad),
    /// spacings (m).
    Rz(BodyParticles<DVec2>),
    /// 3-D quarter model: the particles with x > 0, y > 0 of a body placed as rings
    /// (masses in kg; the body is 4 times them).
    Quarter(BodyParticles<DVec3>),
    /// Plane strain: positions (x, z) in the section y = 0 (m), masses per metre of depth
    /// (kg/m), spacings (m).
    Plane(BodyParticles<DVec2>),
    /// 1-D: positions z on the axis (m), masses per square metre (kg/m²), spacings (m).
    Line(BodyParticles<f64>),
}

/// `$body` with `$p` bound to the particles, whatever their dimension.
macro_rules! each {
    ($particles:expr, $p:ident => $body:expr) => {
        match $particles {
            PlacedParticles::ThreeD($p) | PlacedParticles::Quarter($p) => $body,
            PlacedParticles::Rz($p) | PlacedParticles::Plane($p) => $body,
            PlacedParticles::Line($p) => $body,
        }
    };
}

impl PlacedParticles {
    /// Number of particles.
    pub fn len(&self) -> usize {
        each!(self, p => p.len())
    }

    /// The number of 3-D particles the body's particles stand for, over which its
    /// Benz–Asphaug flaws are dealt (`SceneDimension::stands_for`): its own count in 3-D
    /// and for a quarter, in plane strain and 1-D, Σ round(2πr/Δ) over the rings in RZ.
    pub fn stands_for(&self) -> usize {
        use crate::scene::dimension::{In3d, InLine, InPlane, InRz, SceneDimension};
        match self {
            Self::ThreeD(p) | Self::Quarter(p) => In3d::stands_for(p),
            Self::Rz(p) => InRz::stands_for(p),
            Self::Plane(p) => InPlane::stands_for(p),
            Self::Line(p) => InLine::stands_for(p),
        }
    }

    /// True without particles (placements never return this).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The body's mass: Σ m in 3-D (kg), 2π Σ m in RZ (kg), 4 Σ m for a quarter (kg);
    /// Σ m per metre of depth in plane strain (kg/m), per square metre in 1-D (kg/m²).
    pub fn body_mass(&self) -> f64 {
        match self {
            Self::Quarter(p) => 4.0 * p.total_mass(),
            Self::Rz(p) => TAU * p.total_mass(),
            other => each!(other, p => p.total_mass()),
        }
    }

    /// Each particle's spacing (m).
    pub fn spacing(&self) -> &[f64] {
        each!(self, p => &p.spacing)
    }

    /// Finest and coarsest spacing (m).
    pub fn spacing_range(&self) -> (f64, f64) {
        each!(self, p => (p.min_spacing(), p.max_spacing()))
    }

    /// The 3-D volume each particle stands for (m³), over which its Benz–Asphaug flaws
    /// are counted: m/ρ in 3-D, the ring's 2π m/ρ in RZ; in plane strain and 1-D, where
    /// a particle is a prism or plate without end, the cube of its spacing (the volume
    /// of one 3-D particle of the same spacing, docs/scenes.md).
    pub fn volumes(&self, density: f64) -> Vec<f64> {
        match self {
            Self::ThreeD(p) | Self::Quarter(p) => p.masses.iter().map(|m| m / density).collect(),
            Self::Rz(p) => p.masses.iter().map(|m| TAU * m / density).collect(),
            Self::Plane(_) | Self::Line(_) => self.spacing().iter().map(|d| d.powi(3)).collect(),
        }
    }

    /// Particle `i` as a 3-D point: itself, (r, 0, z) in RZ, (x, 0, z) in plane strain,
    /// (0, 0, z) in 1-D.
    pub fn point(&self, i: usize) -> DVec3 {
        match self {
            Self::ThreeD(p) | Self::Quarter(p) => p.positions[i],
            Self::Rz(p) | Self::Plane(p) => DVec3::new(p.positions[i].x, 0.0, p.positions[i].y),
            Self::Line(p) => DVec3::new(0.0, 0.0, p.positions[i]),
        }
    }
}

/// One body filled with particles.
#[derive(Clone, Debug)]
pub struct PlacedBody {
    /// The body's name.
    pub name: String,
    /// Its material.
    pub material: MaterialSpec,
    /// Its particles.
    pub particles: PlacedParticles,
    /// ρ·V of its shape (kg), when the shape's volume is known exactly; in plane strain
    /// and 1-D ρ × its section's area (kg/m) or length (kg/m²).
    pub exact_mass: Option<f64>,
    /// Initial velocity (m/s).
    pub velocity: DVec3,
}

/// Fills `shape` as `placement` says, in `geometry`; `section` is the measure of a plane
/// or 1-D section when known (its area or length).
fn fill(
    shape: &dyn Shape<DVec3>,
    placement: PlacementSpec,
    rho: f64,
    geometry: GeometryKind,
    section: Option<f64>,
) -> Result<PlacedParticles, GeometryError> {
    Ok(match (geometry, placement) {
        (GeometryKind::Plane, PlacementSpec::Lattice { spacing }) => {
            let mut plane = PlaneSection::new(shape);
            if let Some(area) = section {
                plane = plane.with_measure(area);
            }
            PlacedParticles::Plane(cubic_lattice(&plane, spacing, rho)?)
        }
        (GeometryKind::Line, PlacementSpec::Lattice { spacing }) => {
            let mut line = LineSection::new(shape);
            if let Some(length) = section {
                line = line.with_measure(length);
            }
            PlacedParticles::Line(cubic_lattice(&line, spacing, rho)?)
        }
        // `Scene::check` allows only lattices in plane and 1-D scenes.
        (
            GeometryKind::Plane | GeometryKind::Line,
            PlacementSpec::Variable { .. } | PlacementSpec::Rings { .. },
        ) => {
            return Err(GeometryError::EmptyPlacement {
                body: shape.describe(),
                reason: format!(
                    "geometry = \"{}\" needs placement kind \"lattice\"",
                    geometry.name()
                ),
            });
        }
        (GeometryKind::ThreeD, PlacementSpec::Lattice { spacing }) => {
            PlacedParticles::ThreeD(cubic_lattice(shape, spacing, rho)?)
        }
        (GeometryKind::ThreeD, PlacementSpec::Variable { origin, a_res, q }) => {
            PlacedParticles::ThreeD(
                FibonacciPlacement::new(DVec3::from_array(origin), a_res, q, rho)?.place(shape)?,
            )
        }
        (GeometryKind::Rz, PlacementSpec::Lattice { spacing }) => {
            PlacedParticles::Rz(rz_lattice(shape, spacing, rho)?)
        }
        // The origin is on the axis (`check_revolvable`): only its z counts.
        (
            GeometryKind::Rz,
            PlacementSpec::Variable { origin, a_res, q }
            | PlacementSpec::Rings { origin, a_res, q },
        ) => PlacedParticles::Rz(RzLayeredPlacement::new(origin[2], a_res, q, rho)?.place(shape)?),
        // A multiple of four points per ring: a quarter of every ring lies in x > 0,
        // y > 0 and none on the planes, so "3d" and "3d-quarter" hold the same particles.
        (
            GeometryKind::ThreeD | GeometryKind::ThreeDQuarter,
            PlacementSpec::Rings { origin, a_res, q },
        ) => {
            let rings = RzLayeredPlacement::new(origin[2], a_res, q, rho)?.place(shape)?;
            let body = revolve(&rings, 4)?;
            if geometry == GeometryKind::ThreeDQuarter {
                PlacedParticles::Quarter(quarter(body))
            } else {
                PlacedParticles::ThreeD(body)
            }
        }
        // `Scene::check` allows only rings in a quarter model.
        (
            GeometryKind::ThreeDQuarter,
            PlacementSpec::Lattice { .. } | PlacementSpec::Variable { .. },
        ) => {
            return Err(GeometryError::EmptyPlacement {
                body: shape.describe(),
                reason: "geometry = \"3d-quarter\" needs placement kind \"rings\"".into(),
            });
        }
    })
}

/// The particles of `body` with x > 0 and y > 0; the totals (volume, mass errors) stay
/// the whole body's.
fn quarter(body: BodyParticles<DVec3>) -> BodyParticles<DVec3> {
    let (mut positions, mut masses, mut spacing) = (Vec::new(), Vec::new(), Vec::new());
    for ((x, m), dx) in body.positions.iter().zip(&body.masses).zip(&body.spacing) {
        if x.x > 0.0 && x.y > 0.0 {
            positions.push(*x);
            masses.push(*m);
            spacing.push(*dx);
        }
    }
    BodyParticles {
        positions,
        masses,
        spacing,
        ..body
    }
}

impl Scene {
    /// Places every body's particles in the scene's geometry, with all spacings divided
    /// by `resolution_scale` (> 0; 1 is the scene as written, 2 halves the spacings), and
    /// checks that no body overlaps another.
    pub fn place(&self, resolution_scale: f64) -> Result<Vec<PlacedBody>, SceneError> {
        if !(resolution_scale > 0.0 && resolution_scale.is_finite()) {
            return Err(SceneError::general(SceneErrorKind::Invalid {
                value: resolution_scale,
                reason: "the resolution scale must be positive".into(),
            }));
        }
        self.check().map_err(|e| self.locate(e))?;
        let materials = self.materials().map_err(|e| self.locate(e))?;
        let mut placed = Vec::with_capacity(self.bodies.len());
        let mut shapes = Vec::with_capacity(self.bodies.len());
        for (i, (b, material)) in self.bodies.iter().zip(materials).enumerate() {
            let err = |key: &str, kind| self.locate(SceneError::in_body(i, &b.name, key, kind));
            let shape = b.shape.shape().map_err(|k| err("shape", k))?;
            let rho = material.density;
            let geometry = |e: sph_geometry::GeometryError| {
                err("placement", SceneErrorKind::Geometry(e.to_string()))
            };
            let section = b.shape.section_measure(self.geometry);
            let particles = fill(
                shape.as_ref(),
                b.placement.refined(resolution_scale),
                rho,
                self.geometry,
                section,
            )
            .map_err(geometry)?;
            let measure = if self.geometry.is_section() {
                section
            } else {
                shape.volume()
            };
            placed.push(PlacedBody {
                name: b.name.clone(),
                exact_mass: measure.map(|v| rho * v),
                material,
                particles,
                velocity: DVec3::from_array(b.velocity),
            });
            shapes.push(shape);
        }
        if let Some(o) = first_overlap(&placed, &shapes) {
            return Err(self.locate(SceneError::in_body(
                o.body,
                &placed[o.body].name,
                "shape",
                SceneErrorKind::Overlap {
                    other: placed[o.other].name.clone(),
                    count: o.count,
                    first: o.first.to_array(),
                },
            )));
        }
        Ok(placed)
    }
}

/// Particles of body `body` inside the shape of body `other`.
#[derive(Debug, PartialEq)]
struct Overlap {
    body: usize,
    other: usize,
    /// How many of `body`'s particles lie in `other`'s shape.
    count: usize,
    /// The first of them (the lowest index).
    first: DVec3,
}

/// A body tested against more candidate shapes than this has its particles indexed in an
/// R-tree first; with fewer, each test scans them all. A large target under thousands of
/// boulders would otherwise be scanned once per boulder.
const SCAN_CANDIDATES: usize = 8;

/// The envelope of a box, for the R-trees.
fn envelope(b: &Aabb<DVec3>) -> AABB<[f64; 3]> {
    AABB::from_corners(b.min.to_array(), b.max.to_array())
}

/// The first overlap in body order: the first body with particles inside another body's
/// shape, and the first such other body (the order the check has always reported in),
/// or `None`.
fn first_overlap(placed: &[PlacedBody], shapes: &[Box<dyn Shape<DVec3>>]) -> Option<Overlap> {
    let index = ShapeIndex::new(shapes);
    (0..placed.len())
        .into_par_iter()
        .find_map_first(|i| index.first_overlap_of(i, &placed[i].particles))
}

/// The bodies' shapes with an R-tree of their boxes.
///
/// Only pairs whose boxes meet are tested — the box of one body's particles against the
/// box of the other's shape — so the work grows with the number of bodies times their
/// neighbours, not with its square: with every pair tested, a rubble pile of 1 000
/// boulders took 18 s and 2 000 took 98 s. A particle outside a shape's box is outside
/// the shape, so skipping the other pairs changes no result.
struct ShapeIndex<'a> {
    shapes: &'a [Box<dyn Shape<DVec3>>],
    bounds: Vec<Option<Aabb<DVec3>>>,
    tree: RTree<GeomWithData<Rectangle<[f64; 3]>, usize>>,
    /// The shapes without a box: they may hold any particle.
    unbounded: Vec<usize>,
}

impl<'a> ShapeIndex<'a> {
    fn new(shapes: &'a [Box<dyn Shape<DVec3>>]) -> Self {
        let bounds: Vec<Option<Aabb<DVec3>>> = shapes.iter().map(|s| s.bounds()).collect();
        let tree = RTree::bulk_load(
            bounds
                .iter()
                .enumerate()
                .filter_map(|(j, b)| {
                    b.as_ref()
                        .map(|b| GeomWithData::new(Rectangle::from_aabb(envelope(b)), j))
                })
                .collect(),
        );
        let unbounded = (0..bounds.len()).filter(|&j| bounds[j].is_none()).collect();
        Self {
            shapes,
            bounds,
            tree,
            unbounded,
        }
    }

    /// The first shape other than body `body`'s own that holds some of `particles` (the
    /// body's), or `None`.
    fn first_overlap_of(&self, body: usize, particles: &PlacedParticles) -> Option<Overlap> {
        let own = particle_box(particles)?;
        let mut candidates: Vec<usize> = self
            .tree
            .locate_in_envelope_intersecting(envelope(&own))
            .map(|g| g.data)
            .chain(self.unbounded.iter().copied())
            .filter(|&j| j != body)
            .collect();
        candidates.sort_unstable();
        let points = (candidates.len() > SCAN_CANDIDATES).then(|| {
            RTree::bulk_load(
                (0..particles.len())
                    .map(|k| GeomWithData::new(particles.point(k).to_array(), k))
                    .collect(),
            )
        });
        candidates.into_iter().find_map(|j| {
            let shape = self.shapes[j].as_ref();
            let (count, first) = match (&points, &self.bounds[j]) {
                (Some(points), Some(b)) => inside_indexed(points, particles, shape, b),
                _ => inside(particles, shape),
            }?;
            Some(Overlap {
                body,
                other: j,
                count,
                first,
            })
        })
    }
}

/// The box of the particles (as 3-D points); `None` without particles.
fn particle_box(particles: &PlacedParticles) -> Option<Aabb<DVec3>> {
    let first = (!particles.is_empty()).then(|| particles.point(0))?;
    let (min, max) = (1..particles.len())
        .map(|k| particles.point(k))
        .fold((first, first), |(lo, hi), p| (lo.min(p), hi.max(p)));
    Some(Aabb { min, max })
}

/// How many of the particles lie in `shape` (as 3-D points), and the first of them;
/// `None` for none.
fn inside(particles: &PlacedParticles, shape: &dyn Shape<DVec3>) -> Option<(usize, DVec3)> {
    // Cheap rejection first: a body far from the shape's box has nothing inside.
    let bounds = shape.bounds();
    let hits: Vec<usize> = (0..particles.len())
        .into_par_iter()
        .filter(|&k| {
            let p = particles.point(k);
            bounds.is_none_or(|b| b.contains(p)) && shape.contains(p)
        })
        .collect();
    hits.first().map(|&k| (hits.len(), particles.point(k)))
}

/// [`inside`] for a shape with box `bounds`, testing only the particles the R-tree `index`
/// of their points finds in the box (the same set: both boxes include their faces).
fn inside_indexed(
    index: &RTree<GeomWithData<[f64; 3], usize>>,
    particles: &PlacedParticles,
    shape: &dyn Shape<DVec3>,
    bounds: &Aabb<DVec3>,
) -> Option<(usize, DVec3)> {
    let mut count = 0;
    let mut first = usize::MAX;
    for k in index.locate_in_envelope(envelope(bounds)).map(|g| g.data) {
        let p = particles.point(k);
        if bounds.contains(p) && shape.contains(p) {
            count += 1;
            first = first.min(k);
        }
    }
    (count > 0).then(|| (count, particles.point(first)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_geometry::{Cuboid, HalfSpace, Sphere};

    /// Every body's first overlap through the index is the one that testing every pair
    /// finds: balls scattered so that many overlap, a slab under them (tested against
    /// more than `SCAN_CANDIDATES` shapes, so its particles are indexed) and a body whose
    /// shape is a half-space (no box: a candidate of every body).
    #[test]
    fn indexed_overlaps_are_those_of_all_pairs() {
        let mut state = 12_345_u64;
        let mut uniform = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut shapes: Vec<Box<dyn Shape<DVec3>>> = Vec::new();
        let mut particles = Vec::new();
        let lattice = |shape: &dyn Shape<DVec3>| {
            PlacedParticles::ThreeD(cubic_lattice(shape, 0.5e-3, 1000.0).unwrap())
        };
        for _ in 0..150 {
            let centre = DVec3::new(0.02 * uniform(), 0.02 * uniform(), 4e-3 * uniform() - 1e-3);
            let ball = Sphere::new(centre, 1e-3).unwrap();
            particles.push(lattice(&ball));
            shapes.push(Box::new(ball));
        }
        let slab = Cuboid::new(DVec3::new(0.0, 0.0, -4e-3), DVec3::new(0.02, 0.02, 0.0)).unwrap();
        particles.push(lattice(&slab));
        shapes.push(Box::new(slab));
        // Placed as a small ball high above the rest; its shape holds everything below
        // z = 2.5 mm.
        let high = Sphere::new(DVec3::new(0.01, 0.01, 0.01), 1e-3).unwrap();
        particles.push(lattice(&high));
        shapes.push(Box::new(
            HalfSpace::new(DVec3::new(0.0, 0.0, 2.5e-3), DVec3::Z).unwrap(),
        ));
        let index = ShapeIndex::new(&shapes);
        let all_pairs = |i: usize| {
            (0..shapes.len()).filter(|&j| j != i).find_map(|j| {
                inside(&particles[i], shapes[j].as_ref()).map(|(count, first)| Overlap {
                    body: i,
                    other: j,
                    count,
                    first,
                })
            })
        };
        let mut overlapping = 0;
        for (i, p) in particles.iter().enumerate() {
            let expected = all_pairs(i);
            overlapping += usize::from(expected.is_some());
            assert_eq!(index.first_overlap_of(i, p), expected, "body {i}");
        }
        // Both outcomes occur, and the slab overlaps balls (not only the half-space).
        assert!(
            overlapping > 10 && overlapping < particles.len(),
            "{overlapping}"
        );
        let slab_overlap = index.first_overlap_of(150, &particles[150]).unwrap();
        assert!(slab_overlap.other < 150, "{slab_overlap:?}");
    }
}

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
use sph_core::glam::{DVec2, DVec3};
use sph_geometry::{
    BodyParticles, FibonacciPlacement, GeometryError, LineSection, PlaneSection,
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
        for (i, body) in placed.iter().enumerate() {
            for (j, shape) in shapes.iter().enumerate() {
                if i == j {
                    continue;
                }
                if let Some((count, first)) = inside(&body.particles, shape.as_ref()) {
                    return Err(self.locate(SceneError::in_body(
                        i,
                        &body.name,
                        "shape",
                        SceneErrorKind::Overlap {
                            other: placed[j].name.clone(),
                            count,
                            first: first.to_array(),
                        },
                    )));
                }
            }
        }
        Ok(placed)
    }
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

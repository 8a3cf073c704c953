//! Filling each body with particles, and the overlap check: no particle of one body may
//! lie inside another body's shape (two bodies in one place would double the mass
//! there, and their pair forces start from an unphysical compression).

use crate::materials::MaterialSpec;
use crate::scene::Scene;
use crate::scene::body::PlacementSpec;
use crate::scene::error::{SceneError, SceneErrorKind};
use rayon::prelude::*;
use sph_core::glam::DVec3;
use sph_geometry::{BodyParticles, FibonacciPlacement, Shape, cubic_lattice};

/// One body filled with particles.
#[derive(Clone, Debug)]
pub struct PlacedBody {
    /// The body's name.
    pub name: String,
    /// Its material.
    pub material: MaterialSpec,
    /// Its particles (positions m, masses kg, spacings m).
    pub particles: BodyParticles<DVec3>,
    /// ρ·V of its shape (kg), when the shape's volume is known exactly.
    pub exact_mass: Option<f64>,
    /// Initial velocity (m/s).
    pub velocity: DVec3,
}

impl Scene {
    /// Places every body's particles, with all spacings divided by `resolution_scale`
    /// (> 0; 1 is the scene as written, 2 halves the spacings), and checks that no body
    /// overlaps another.
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
            let particles = match b.placement.refined(resolution_scale) {
                PlacementSpec::Lattice { spacing } => {
                    cubic_lattice(&shape, spacing, rho).map_err(geometry)?
                }
                PlacementSpec::Variable { origin, a_res, q } => {
                    FibonacciPlacement::new(DVec3::from_array(origin), a_res, q, rho)
                        .and_then(|p| p.place(&shape))
                        .map_err(geometry)?
                }
            };
            placed.push(PlacedBody {
                name: b.name.clone(),
                exact_mass: shape.volume().map(|v| rho * v),
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
                if let Some((count, first)) = inside(&body.particles.positions, shape.as_ref()) {
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

/// How many of `points` lie in `shape`, and the first of them; `None` for none.
fn inside(points: &[DVec3], shape: &dyn Shape<DVec3>) -> Option<(usize, DVec3)> {
    // Cheap rejection first: a body far from the shape's box has nothing inside.
    let bounds = shape.bounds();
    let hits: Vec<usize> = points
        .par_iter()
        .enumerate()
        .filter(|(_, p)| bounds.is_none_or(|b| b.contains(**p)) && shape.contains(**p))
        .map(|(k, _)| k)
        .collect();
    hits.first().map(|&k| (hits.len(), points[k]))
}

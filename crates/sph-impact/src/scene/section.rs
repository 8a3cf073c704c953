//! What a plane-strain (`geometry = "plane"`) or 1-D (`"1d"`) scene asks of its bodies,
//! and the measure of their sections. The bodies are written in 3-D as in any scene; the
//! run holds their section y = 0 (plane) or their section on the z axis (1-D), each
//! extruded without end: a plane-strain body is a prism along y, a 1-D body a plate.
//! So every body must cross that section, move within it (v_y = 0; in 1-D also
//! v_x = 0) and be placed on a lattice (the layered placements are built about a point,
//! not a plane or a line).

use crate::scene::body::{BodySpec, PlacementSpec, ShapeSpec};
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::settings::GeometryKind;
use std::f64::consts::PI;

/// √(a² − b²) when |b| < a, else `None` (the chord's half-length).
fn half_chord(a: f64, b: f64) -> Option<f64> {
    (b.abs() < a).then(|| (a * a - b * b).sqrt())
}

impl ShapeSpec {
    /// The exact measure of the shape's section in `geometry` where it has a closed form:
    /// its area (m²) in plane strain, its length (m) in 1-D; `None` for the 3-D
    /// geometries, for an empty section and for a cylinder whose axis is not z (the
    /// lattice's own estimate is used then).
    pub(crate) fn section_measure(&self, geometry: GeometryKind) -> Option<f64> {
        let plane = match geometry {
            GeometryKind::Plane => true,
            GeometryKind::Line => false,
            _ => return None,
        };
        match *self {
            ShapeSpec::Sphere { centre, radius } => {
                let [x, y, _] = centre;
                if plane {
                    half_chord(radius, y).map(|r| PI * r * r)
                } else {
                    half_chord(radius, x.hypot(y)).map(|h| 2.0 * h)
                }
            }
            ShapeSpec::Cuboid { min, max } => {
                let spans = |k: usize| min[k] <= 0.0 && max[k] >= 0.0;
                let height = max[2] - min[2];
                if plane {
                    spans(1).then(|| (max[0] - min[0]) * height)
                } else {
                    (spans(0) && spans(1)).then_some(height)
                }
            }
            ShapeSpec::Cylinder {
                base,
                axis,
                radius,
                length,
            } if axis[0] == 0.0 && axis[1] == 0.0 && axis[2] != 0.0 => {
                let [x, y, _] = base;
                if plane {
                    half_chord(radius, y).map(|w| 2.0 * w * length)
                } else {
                    half_chord(radius, x.hypot(y)).map(|_| length)
                }
            }
            ShapeSpec::Cylinder { .. } => None,
        }
    }
}

impl BodySpec {
    /// Checks that the body suits a plane-strain or 1-D scene (module docs); `index` is
    /// its place in the scene, for the error's key.
    pub(crate) fn check_section(
        &self,
        index: usize,
        geometry: GeometryKind,
    ) -> Result<(), SceneError> {
        let name = geometry.name();
        let err = |key: &str, reason: String| {
            SceneError::in_body(index, &self.name, key, SceneErrorKind::Geometry(reason))
        };
        if !matches!(self.placement, PlacementSpec::Lattice { .. }) {
            return Err(err(
                "placement.kind",
                format!(
                    "geometry = \"{name}\" needs every body placed as kind \"lattice\" (the \
                     layered placements are built about a point, not a plane or a line)"
                ),
            ));
        }
        let [vx, vy, _] = self.velocity;
        let (moving_out, what) = if geometry == GeometryKind::Plane {
            (vy != 0.0, format!("v_y = 0, not {vy} m/s"))
        } else {
            (
                vx != 0.0 || vy != 0.0,
                format!("v_x = v_y = 0, not ({vx}, {vy}) m/s"),
            )
        };
        if moving_out {
            return Err(err(
                "velocity",
                format!("in geometry = \"{name}\" a body moves within its section: {what}"),
            ));
        }
        let shape = self
            .shape
            .shape()
            .map_err(|k| SceneError::in_body(index, &self.name, "shape", k))?;
        let crosses = shape.bounds().is_some_and(|b| {
            let spans = |lo: f64, hi: f64| lo <= 0.0 && hi >= 0.0;
            spans(b.min.y, b.max.y) && (geometry == GeometryKind::Plane || spans(b.min.x, b.max.x))
        });
        if !crosses {
            let section = if geometry == GeometryKind::Plane {
                "the plane y = 0"
            } else {
                "the z axis (x = y = 0)"
            };
            return Err(err(
                "shape",
                format!(
                    "geometry = \"{name}\" runs the bodies' section on {section}, which this \
                     body does not reach"
                ),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn section_measures() {
        let ball = ShapeSpec::Sphere {
            centre: [0.3, 0.6, -1.0],
            radius: 1.0,
        };
        // Plane: the disc of radius √(1 − 0.36) = 0.8; line: the chord at distance
        // √(0.09 + 0.36) from the centre.
        let area = ball.section_measure(GeometryKind::Plane).unwrap();
        assert!((area - PI * 0.64).abs() < 1e-12);
        let length = ball.section_measure(GeometryKind::Line).unwrap();
        assert!((length - 2.0 * (1.0f64 - 0.45).sqrt()).abs() < 1e-12);
        assert_eq!(ball.section_measure(GeometryKind::Rz), None);
        let slab = ShapeSpec::Cuboid {
            min: [-2.0, -1.0, -0.5],
            max: [3.0, 1.0, 0.0],
        };
        assert_eq!(slab.section_measure(GeometryKind::Plane), Some(2.5));
        assert_eq!(slab.section_measure(GeometryKind::Line), Some(0.5));
        let rod = ShapeSpec::Cylinder {
            base: [0.0, 0.0, 0.0],
            axis: [0.0, 0.0, -1.0],
            radius: 0.5,
            length: 2.0,
        };
        assert_eq!(rod.section_measure(GeometryKind::Plane), Some(2.0));
        assert_eq!(rod.section_measure(GeometryKind::Line), Some(2.0));
        let aside = ShapeSpec::Sphere {
            centre: [0.0, 2.0, 0.0],
            radius: 1.0,
        };
        assert_eq!(aside.section_measure(GeometryKind::Plane), None);
    }
}

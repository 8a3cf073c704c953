//! What an axisymmetric (RZ) scene asks of its bodies: each one a solid of revolution
//! about the z axis (a sphere centred on it, a cylinder standing on it), moving along it,
//! with its variable-resolution layers centred on it. The run then holds the (r, z)
//! half-plane of every body, and each particle stands for a ring.

use crate::scene::body::{BodySpec, PlacementSpec, ShapeSpec};
use crate::scene::error::{SceneError, SceneErrorKind};

/// "(x, y) = (…, …)" for a message.
fn xy(p: [f64; 3]) -> String {
    format!("(x, y) = ({}, {})", p[0], p[1])
}

/// True when x = y = 0 exactly.
fn on_axis(p: [f64; 3]) -> bool {
    p[0] == 0.0 && p[1] == 0.0
}

impl ShapeSpec {
    /// Why the shape is not a solid of revolution about the z axis: the key within the
    /// shape and the reason; `None` when it is.
    pub(crate) fn axisymmetry_problem(&self) -> Option<(&'static str, String)> {
        match *self {
            ShapeSpec::Sphere { centre, .. } if !on_axis(centre) => Some((
                "centre",
                format!(
                    "the centre must be on the z axis, x = y = 0, not {}",
                    xy(centre)
                ),
            )),
            ShapeSpec::Cylinder { base, .. } if !on_axis(base) => Some((
                "base",
                format!(
                    "the base centre must be on the z axis, x = y = 0, not {}",
                    xy(base)
                ),
            )),
            ShapeSpec::Cylinder { axis, .. } if !(on_axis(axis) && axis[2] != 0.0) => Some((
                "axis",
                format!(
                    "the cylinder's axis must be the z axis, [0, 0, ±1], not [{}, {}, {}]",
                    axis[0], axis[1], axis[2]
                ),
            )),
            ShapeSpec::Cuboid { .. } => Some((
                "kind",
                "a cuboid has no axis of revolution; RZ scenes take spheres and cylinders on \
                 the z axis"
                    .into(),
            )),
            _ => None,
        }
    }
}

impl BodySpec {
    /// Checks that the body suits an RZ scene (module docs); `index` is its place in the
    /// scene, for the error's key.
    pub(crate) fn check_axisymmetric(&self, index: usize) -> Result<(), SceneError> {
        self.check_revolvable(index)?;
        if !on_axis(self.velocity) {
            return Err(self.not_axisymmetric(
                index,
                "velocity",
                format!(
                    "the velocity must be along z, v_x = v_y = 0, not (v_x, v_y) = ({}, {}) m/s",
                    self.velocity[0], self.velocity[1]
                ),
            ));
        }
        Ok(())
    }

    /// Checks that the body's shape and its layers' origin are symmetric about the z
    /// axis, as an RZ scene and a 3-D placement of kind `rings` need (its velocity may
    /// point anywhere in 3-D).
    pub(crate) fn check_revolvable(&self, index: usize) -> Result<(), SceneError> {
        if let Some((key, reason)) = self.shape.axisymmetry_problem() {
            return Err(self.not_axisymmetric(index, &format!("shape.{key}"), reason));
        }
        if let PlacementSpec::Variable { origin, .. } | PlacementSpec::Rings { origin, .. } =
            self.placement
            && !on_axis(origin)
        {
            return Err(self.not_axisymmetric(
                index,
                "placement.origin",
                format!(
                    "the layers' origin must be on the z axis, x = y = 0, not {}",
                    xy(origin)
                ),
            ));
        }
        Ok(())
    }

    fn not_axisymmetric(&self, index: usize, key: &str, reason: String) -> SceneError {
        SceneError::in_body(
            index,
            &self.name,
            key,
            SceneErrorKind::NotAxisymmetric(reason),
        )
    }
}

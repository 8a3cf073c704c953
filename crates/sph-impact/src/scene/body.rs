//! A body of a scene: name, shape, material, placement and initial velocity.

use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::material_ref::MaterialRef;
use serde::{Deserialize, Serialize};
use sph_core::glam::DVec3;
use sph_geometry::{Cuboid, Cylinder, Shape, Sphere};

/// A body's shape (lengths in m). TOML: `shape = { kind = "sphere", centre = […],
/// radius = … }`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum ShapeSpec {
    /// A ball.
    Sphere {
        /// Centre (m).
        centre: [f64; 3],
        /// Radius (m), > 0.
        radius: f64,
    },
    /// A right circular cylinder.
    Cylinder {
        /// Centre of the base face (m).
        base: [f64; 3],
        /// Axis direction from the base face (normalised; non-zero).
        axis: [f64; 3],
        /// Radius (m), > 0.
        radius: f64,
        /// Length along the axis (m), > 0.
        length: f64,
    },
    /// An axis-aligned box.
    Cuboid {
        /// Lower corner (m).
        min: [f64; 3],
        /// Upper corner (m), above `min` in every component.
        max: [f64; 3],
    },
}

impl ShapeSpec {
    /// The geometry crate's shape; the error names what is wrong.
    pub fn shape(&self) -> Result<Box<dyn Shape<DVec3>>, SceneErrorKind> {
        let v = DVec3::from_array;
        let geometry = |e: sph_geometry::GeometryError| SceneErrorKind::Geometry(e.to_string());
        Ok(match *self {
            ShapeSpec::Sphere { centre, radius } => {
                Box::new(Sphere::new(v(centre), radius).map_err(geometry)?)
            }
            ShapeSpec::Cylinder {
                base,
                axis,
                radius,
                length,
            } => Box::new(Cylinder::new(v(base), v(axis), radius, length).map_err(geometry)?),
            ShapeSpec::Cuboid { min, max } => {
                Box::new(Cuboid::new(v(min), v(max)).map_err(geometry)?)
            }
        })
    }

    /// This shape scaled by `factor` about the origin (for scaled-down test scenes).
    pub fn scaled(&self, factor: f64) -> Self {
        let s = |a: [f64; 3]| a.map(|x| x * factor);
        match *self {
            ShapeSpec::Sphere { centre, radius } => ShapeSpec::Sphere {
                centre: s(centre),
                radius: radius * factor,
            },
            ShapeSpec::Cylinder {
                base,
                axis,
                radius,
                length,
            } => ShapeSpec::Cylinder {
                base: s(base),
                axis,
                radius: radius * factor,
                length: length * factor,
            },
            ShapeSpec::Cuboid { min, max } => ShapeSpec::Cuboid {
                min: s(min),
                max: s(max),
            },
        }
    }
}

/// How a body is filled with particles. TOML: `placement = { kind = "lattice",
/// spacing = … }`, `{ kind = "variable", origin = […], a_res = …, q = … }` or
/// `{ kind = "rings", origin = […], a_res = …, q = … }`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum PlacementSpec {
    /// A uniform cubic lattice of spacing `spacing` (m).
    Lattice {
        /// Particle spacing Δx (m), > 0.
        spacing: f64,
    },
    /// The study's variable-resolution Fibonacci layers (paper §4) about `origin`: first
    /// layer spacing `a_res` (m), each further layer `q` times the one before.
    Variable {
        /// Point of highest resolution (m), usually the impact point.
        origin: [f64; 3],
        /// First-layer spacing A_res (m), > 0.
        a_res: f64,
        /// Spacing ratio q ≥ 1 between layers (1 is uniform).
        q: f64,
    },
    /// The RZ variable-resolution layers about `origin` (on the z axis), each ring
    /// revolved into points one spacing apart around the axis
    /// ([`sph_geometry::revolve()`]): in 3-D a placement with no preferred azimuth and the
    /// same rings as the RZ run of the scene; in RZ the same as `Variable`. The body
    /// must be symmetric about the z axis.
    Rings {
        /// Point of highest resolution (m), on the z axis.
        origin: [f64; 3],
        /// First-layer spacing A_res (m), > 0.
        a_res: f64,
        /// Spacing ratio q ≥ 1 between layers (1 is uniform).
        q: f64,
    },
}

impl PlacementSpec {
    /// The finest spacing (m).
    pub fn finest_spacing(&self) -> f64 {
        match *self {
            PlacementSpec::Lattice { spacing } => spacing,
            PlacementSpec::Variable { a_res, .. } | PlacementSpec::Rings { a_res, .. } => a_res,
        }
    }

    /// The same placement with every spacing divided by `resolution_scale` (> 1 refines).
    pub fn refined(&self, resolution_scale: f64) -> Self {
        match *self {
            PlacementSpec::Lattice { spacing } => PlacementSpec::Lattice {
                spacing: spacing / resolution_scale,
            },
            PlacementSpec::Variable { origin, a_res, q } => PlacementSpec::Variable {
                origin,
                a_res: a_res / resolution_scale,
                q,
            },
            PlacementSpec::Rings { origin, a_res, q } => PlacementSpec::Rings {
                origin,
                a_res: a_res / resolution_scale,
                q,
            },
        }
    }

    /// Range checks; `Err` is (key within the placement, what is wrong).
    pub fn check(&self) -> Result<(), (&'static str, SceneErrorKind)> {
        let invalid = |key, value: f64, reason: &str| {
            Err((
                key,
                SceneErrorKind::Invalid {
                    value,
                    reason: reason.to_owned(),
                },
            ))
        };
        match *self {
            PlacementSpec::Lattice { spacing } => {
                if !(spacing > 0.0 && spacing.is_finite()) {
                    return invalid("spacing", spacing, "the spacing must be positive (m)");
                }
            }
            PlacementSpec::Variable { origin, a_res, q }
            | PlacementSpec::Rings { origin, a_res, q } => {
                if let Some(&x) = origin.iter().find(|x| !x.is_finite()) {
                    return invalid("origin", x, "the origin must be finite (m)");
                }
                if !(a_res > 0.0 && a_res.is_finite()) {
                    return invalid("a_res", a_res, "A_res must be positive (m)");
                }
                if !(q >= 1.0 && q.is_finite()) {
                    return invalid("q", q, "the spacing ratio q must be ≥ 1");
                }
            }
        }
        Ok(())
    }
}

/// One body of a scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Unique name (used by `[diagnostics]` and in messages).
    pub name: String,
    /// Its shape.
    pub shape: ShapeSpec,
    /// A built-in material by name, or an inline material table.
    pub material: MaterialRef,
    /// How it is filled with particles.
    pub placement: PlacementSpec,
    /// Initial velocity (m/s); default at rest.
    #[serde(default, deserialize_with = "exactly_three")]
    pub velocity: [f64; 3],
    /// Seed of the body's Benz–Asphaug flaws; default the scene's `seed` plus the body's
    /// index.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damage_seed: Option<u64>,
    /// The largest accepted relative difference between the placed particles' mass and
    /// ρV, |Σm/(ρV) − 1| (default [`DEFAULT_MASS_TOLERANCE`]): a body placed with more
    /// is refused before the run, since its momentum, energy and β would be off by as
    /// much. Raise it for a body whose placement is knowingly coarse.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_tolerance: Option<f64>,
}

/// Three numbers, no more and no fewer (a fourth velocity component would otherwise be
/// dropped without a word).
fn exactly_three<'de, D: serde::Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
    let v = Vec::<f64>::deserialize(d)?;
    <[f64; 3]>::try_from(v.as_slice())
        .map_err(|_| serde::de::Error::invalid_length(v.len(), &"three components (x, y, z)"))
}

/// The default [`BodySpec::mass_tolerance`]: 5 %.
pub const DEFAULT_MASS_TOLERANCE: f64 = 0.05;

impl BodySpec {
    /// A body at rest.
    pub fn new(
        name: impl Into<String>,
        shape: ShapeSpec,
        material: impl Into<MaterialRef>,
        placement: PlacementSpec,
    ) -> Self {
        Self {
            name: name.into(),
            shape,
            material: material.into(),
            placement,
            velocity: [0.0; 3],
            damage_seed: None,
            mass_tolerance: None,
        }
    }

    /// Checks the shape, placement and velocity (not the material); `index` is the body's
    /// position in the scene, for the error's key.
    pub fn check(&self, index: usize) -> Result<(), SceneError> {
        let err = |key: &str, kind| SceneError::in_body(index, &self.name, key, kind);
        if self.name.trim().is_empty() {
            return Err(err(
                "name",
                SceneErrorKind::Syntax("a body name must not be empty".into()),
            ));
        }
        // Names are printed in messages and in `check`'s report: an escape sequence in
        // one would drive the terminal.
        if let Some(c) = self.name.chars().find(|c| c.is_control()) {
            return Err(err(
                "name",
                SceneErrorKind::Syntax(format!(
                    "a body name must not contain control characters (found U+{:04X})",
                    u32::from(c)
                )),
            ));
        }
        self.shape.shape().map_err(|k| err("shape", k))?;
        self.placement
            .check()
            .map_err(|(key, k)| err(&format!("placement.{key}"), k))?;
        if let Some(&v) = self.velocity.iter().find(|v| !v.is_finite()) {
            return Err(err(
                "velocity",
                SceneErrorKind::Invalid {
                    value: v,
                    reason: "the velocity must be finite (m/s)".into(),
                },
            ));
        }
        Ok(())
    }
}

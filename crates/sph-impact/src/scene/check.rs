//! The checks a scene passes before anything is placed: end time, bodies (names, shapes,
//! placements, velocities, materials; in an RZ scene also their symmetry about the z
//! axis, in a plane or 1-D scene their section), solver settings, output and diagnostics settings. Overlapping bodies need the
//! particles and are found when the bodies are placed ([`Scene::place`]).

use crate::materials::MaterialSpec;
use crate::scene::Scene;
use crate::scene::body::PlacementSpec;
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::settings::GeometryKind;

/// `value` must be positive and finite.
fn positive(key: &str, value: f64, what: &str) -> Result<(), SceneError> {
    if value > 0.0 && value.is_finite() {
        Ok(())
    } else {
        Err(SceneError::at_key(
            key,
            SceneErrorKind::Invalid {
                value,
                reason: format!("{what} must be positive and finite"),
            },
        ))
    }
}

impl Scene {
    /// Checks the scene as a whole; the error names the key (and the body).
    pub fn check(&self) -> Result<(), SceneError> {
        positive("end_time", self.end_time, "the end time (s)")?;
        if self.bodies.is_empty() {
            return Err(SceneError::at_key("body", SceneErrorKind::NoBodies));
        }
        // The names seen so far: a set, not a scan of the bodies before each one, so that
        // a scene of thousands of bodies is checked in linear time.
        let mut names = std::collections::HashSet::with_capacity(self.bodies.len());
        for (i, b) in self.bodies.iter().enumerate() {
            b.check(i)?;
            if self.geometry == GeometryKind::ThreeDQuarter
                && !matches!(b.placement, PlacementSpec::Rings { .. })
            {
                return Err(SceneError::in_body(
                    i,
                    &b.name,
                    "placement.kind",
                    SceneErrorKind::Geometry(
                        "geometry = \"3d-quarter\" needs every body placed as kind \"rings\" \
                         (the placement that is exactly four-fold symmetric)"
                            .into(),
                    ),
                ));
            }
            if self.geometry.is_section() {
                b.check_section(i, self.geometry)?;
            } else if matches!(
                self.geometry,
                GeometryKind::Rz | GeometryKind::ThreeDQuarter
            ) {
                b.check_axisymmetric(i)?;
            } else if matches!(b.placement, PlacementSpec::Rings { .. }) {
                b.check_revolvable(i)?;
            }
            if !names.insert(b.name.as_str()) {
                return Err(SceneError::in_body(
                    i,
                    &b.name,
                    "name",
                    SceneErrorKind::DuplicateBody(b.name.clone()),
                ));
            }
        }
        self.materials()?;
        self.solver.scheme().validate().map_err(|e| match e {
            crate::SolverError::BadConfig { field, .. } => SceneError::at_key(
                format!("solver.{field}"),
                SceneErrorKind::Solver(e.to_string()),
            ),
            other => SceneError::at_key("solver", SceneErrorKind::Solver(other.to_string())),
        })?;
        if let Some(dt) = self.output.snapshot_interval {
            positive("output.snapshot_interval", dt, "the snapshot interval (s)")?;
        }
        if self.output.history_every == Some(0) {
            return Err(SceneError::at_key(
                "output.history_every",
                SceneErrorKind::Invalid {
                    value: 0.0,
                    reason: "must be at least 1 step".into(),
                },
            ));
        }
        self.diagnostic_setup(1.0)?;
        Ok(())
    }

    /// The material of every body, validated, in body order.
    pub fn materials(&self) -> Result<Vec<MaterialSpec>, SceneError> {
        self.bodies
            .iter()
            .enumerate()
            .map(|(i, b)| {
                b.material.resolve(&b.name).map_err(|(sub, kind)| {
                    let key = if sub.is_empty() {
                        "material".to_owned()
                    } else {
                        format!("material.{sub}")
                    };
                    SceneError::in_body(i, &b.name, &key, kind)
                })
            })
            .collect()
    }
}

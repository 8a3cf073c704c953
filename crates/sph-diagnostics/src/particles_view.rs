//! A borrowed, read-only view of the particles at one instant, and the geometry convention
//! every impact diagnostic uses (docs/diagnostics.md §1).
//!
//! **Convention.** The impact axis is z. The projectile moves in −z; the target's original
//! top surface is the plane z = `surface_z`; the impact point is on the axis x = y = 0.
//!
//! **Axisymmetric (RZ) runs** store position (r, 0, z), velocity (v_r, 0, v_z) and, in
//! `mass`, the *full ring mass* 2π × (mass per radian). With that, every mass and momentum
//! sum below is the same code in 3-D and RZ: a ring of mass m moving with v_z carries
//! axial momentum m v_z whichever way it is stored. Only the radius from the axis
//! differs ([`Geometry::radius`]).

use crate::error::ImpactError;
use serde::{Deserialize, Serialize};

/// Per-particle arrays of one snapshot, borrowed from the solver's storage (SI units).
///
/// All arrays have one entry per particle (the length of `position`); [`validate`] checks
/// this and the values. Diagnostics validate the view they are given.
///
/// [`validate`]: ParticleView::validate
#[derive(Clone, Copy, Debug)]
pub struct ParticleView<'a> {
    /// Positions (m): (x, y, z) in 3-D, (r, 0, z) in RZ.
    pub position: &'a [[f64; 3]],
    /// Velocities (m/s): (v_x, v_y, v_z) in 3-D, (v_r, 0, v_z) in RZ.
    pub velocity: &'a [[f64; 3]],
    /// Masses (kg); in RZ the full ring mass 2π × mass per radian. Non-negative.
    pub mass: &'a [f64],
    /// Body (material region) id of each particle, e.g. 0 projectile, 1 target.
    pub body: &'a [u16],
    /// Scalar damage D ∈ [0, 1] (dimensionless), if the run has damage.
    pub damage: Option<&'a [f64]>,
    /// Mass density ρ (kg/m³), positive, if available.
    pub density: Option<&'a [f64]>,
}

impl<'a> ParticleView<'a> {
    /// A view without damage and density.
    pub fn new(
        position: &'a [[f64; 3]],
        velocity: &'a [[f64; 3]],
        mass: &'a [f64],
        body: &'a [u16],
    ) -> Self {
        Self {
            position,
            velocity,
            mass,
            body,
            damage: None,
            density: None,
        }
    }

    /// The same view with a damage array (dimensionless, in [0, 1]).
    pub fn with_damage(self, damage: &'a [f64]) -> Self {
        Self {
            damage: Some(damage),
            ..self
        }
    }

    /// The same view with a density array (kg/m³).
    pub fn with_density(self, density: &'a [f64]) -> Self {
        Self {
            density: Some(density),
            ..self
        }
    }

    /// Number of particles (the length of `position`).
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// True for a view of no particles.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Checks lengths (one entry per particle), finiteness of every value, mass ≥ 0,
    /// damage ∈ [0, 1] and density > 0. The first problem found is returned, naming the
    /// particle and the field.
    pub fn validate(&self) -> Result<(), ImpactError> {
        let n = self.len();
        check_len("velocity", self.velocity.len(), n)?;
        check_len("mass", self.mass.len(), n)?;
        check_len("body", self.body.len(), n)?;
        if let Some(d) = self.damage {
            check_len("damage", d.len(), n)?;
        }
        if let Some(r) = self.density {
            check_len("density", r.len(), n)?;
        }
        check_vectors("position", self.position)?;
        check_vectors("velocity", self.velocity)?;
        for (index, &mass) in self.mass.iter().enumerate() {
            finite_at("mass", index, mass)?;
            if mass < 0.0 {
                return Err(ImpactError::NegativeMass { index, mass });
            }
        }
        for (index, &value) in self.damage.unwrap_or(&[]).iter().enumerate() {
            finite_at("damage", index, value)?;
            if !(0.0..=1.0).contains(&value) {
                return Err(ImpactError::DamageOutOfRange { index, value });
            }
        }
        for (index, &value) in self.density.unwrap_or(&[]).iter().enumerate() {
            finite_at("density", index, value)?;
            if !(value > 0.0) {
                return Err(ImpactError::NonPositiveDensity { index, value });
            }
        }
        Ok(())
    }

    /// A per-particle array supplied next to the view (e.g. specific energy), checked for
    /// length and finiteness.
    pub fn check_extra(&self, field: &'static str, values: &[f64]) -> Result<(), ImpactError> {
        check_len(field, values.len(), self.len())?;
        for (index, &v) in values.iter().enumerate() {
            finite_at(field, index, v)?;
        }
        Ok(())
    }
}

/// How positions map to the distance from the impact axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Geometry {
    /// Full 3-D: the radius is sqrt(x² + y²).
    #[default]
    ThreeD,
    /// Axisymmetric (RZ): position is (r, 0, z); the radius is |x|. The absolute value
    /// makes a mirrored half-plane (r < 0) read the same.
    Axisymmetric,
    /// Plane strain: position is (x, 0, z) in the section y = 0, masses per unit depth
    /// (kg/m); the "radius" is the distance |x| from the impact plane x = 0, so a crater
    /// is a trench and its diameter the trench's width.
    Plane,
    /// Uniaxial strain (1-D): position is (0, 0, z), masses per unit area (kg/m²); every
    /// particle is on the axis (radius 0).
    Line,
}

impl Geometry {
    /// Distance of a position from the impact axis (m).
    pub fn radius(self, position: [f64; 3]) -> f64 {
        match self {
            Geometry::ThreeD => position[0].hypot(position[1]),
            Geometry::Axisymmetric | Geometry::Plane => position[0].abs(),
            Geometry::Line => 0.0,
        }
    }

    /// The number of space dimensions the particles fill: 3 (3-D and RZ, whose rings
    /// fill 3-D space), 2 (plane) or 1 (line).
    pub fn dimension(self) -> usize {
        match self {
            Geometry::ThreeD | Geometry::Axisymmetric => 3,
            Geometry::Plane => 2,
            Geometry::Line => 1,
        }
    }
}

fn check_len(field: &'static str, len: usize, expected: usize) -> Result<(), ImpactError> {
    if len == expected {
        Ok(())
    } else {
        Err(ImpactError::LengthMismatch {
            field,
            len,
            expected,
        })
    }
}

fn finite_at(field: &'static str, index: usize, value: f64) -> Result<(), ImpactError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(ImpactError::NonFinite {
            field,
            index,
            value,
        })
    }
}

fn check_vectors(field: &'static str, v: &[[f64; 3]]) -> Result<(), ImpactError> {
    for (index, p) in v.iter().enumerate() {
        for &c in p {
            finite_at(field, index, c)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const P: [[f64; 3]; 2] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]];
    const V: [[f64; 3]; 2] = [[0.0; 3]; 2];

    #[test]
    fn a_consistent_view_validates() {
        let v = ParticleView::new(&P, &V, &[1.0, 0.0], &[0, 1])
            .with_damage(&[0.0, 1.0])
            .with_density(&[2.0, 3.0]);
        assert_eq!(v.validate(), Ok(()));
        assert_eq!((v.len(), v.is_empty()), (2, false));
    }

    #[test]
    fn length_mismatch_names_the_field() {
        let v = ParticleView::new(&P, &V, &[1.0], &[0, 1]);
        assert_eq!(
            v.validate(),
            Err(ImpactError::LengthMismatch {
                field: "mass",
                len: 1,
                expected: 2
            })
        );
        let d = ParticleView::new(&P, &V, &[1.0, 1.0], &[0, 1]).with_damage(&[0.0]);
        assert!(matches!(
            d.validate(),
            Err(ImpactError::LengthMismatch {
                field: "damage",
                ..
            })
        ));
    }

    #[test]
    fn bad_values_name_the_particle() {
        let p = [[0.0; 3], [0.0, f64::NAN, 0.0]];
        let v = ParticleView::new(&p, &V, &[1.0, 1.0], &[0, 1]);
        assert!(matches!(
            v.validate(),
            Err(ImpactError::NonFinite {
                field: "position",
                index: 1,
                ..
            })
        ));
        let v = ParticleView::new(&P, &V, &[1.0, -2.0], &[0, 1]);
        assert_eq!(
            v.validate(),
            Err(ImpactError::NegativeMass {
                index: 1,
                mass: -2.0
            })
        );
        let v = ParticleView::new(&P, &V, &[1.0, 1.0], &[0, 1]).with_damage(&[1.5, 0.0]);
        assert_eq!(
            v.validate(),
            Err(ImpactError::DamageOutOfRange {
                index: 0,
                value: 1.5
            })
        );
        let v = ParticleView::new(&P, &V, &[1.0, 1.0], &[0, 1]).with_density(&[1.0, 0.0]);
        assert_eq!(
            v.validate(),
            Err(ImpactError::NonPositiveDensity {
                index: 1,
                value: 0.0
            })
        );
        let ok = ParticleView::new(&P, &V, &[1.0, 1.0], &[0, 1]);
        assert!(
            ok.check_extra("specific_energy", &[1.0, f64::INFINITY])
                .is_err()
        );
        assert!(ok.check_extra("specific_energy", &[1.0]).is_err());
    }

    #[test]
    fn radius_from_the_axis() {
        assert_eq!(Geometry::ThreeD.radius([3.0, -4.0, 7.0]), 5.0);
        assert_eq!(Geometry::Axisymmetric.radius([-3.0, 0.0, 7.0]), 3.0);
        assert_eq!(Geometry::Plane.radius([-3.0, 0.0, 7.0]), 3.0);
        assert_eq!(Geometry::Line.radius([0.0, 0.0, 7.0]), 0.0);
    }
}

//! The particle store: structure of arrays, one `Vec` per field.
//!
//! Only the fields every SPH scheme has live here; physics packages (strength, damage)
//! keep their own per-particle arrays and reorder them with the same
//! [`Permutation`].

use crate::dimension::Dimension;
use crate::error::CoreError;
use crate::permutation::Permutation;
use crate::vector::Vector;
use serde::{Deserialize, Serialize};

/// Particle fields as structure of arrays. All vectors have the same length.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Particles<D: Dimension> {
    /// Position x (m).
    pub position: Vec<D::Vector>,
    /// Velocity v (m/s).
    pub velocity: Vec<D::Vector>,
    /// Mass m (kg; kg/m in 2-D, kg/m² in 1-D).
    pub mass: Vec<f64>,
    /// Mass density ρ (kg/m^DIM).
    pub density: Vec<f64>,
    /// Specific internal energy e (J/kg).
    pub specific_energy: Vec<f64>,
    /// Kernel support radius h (m): the kernel vanishes beyond h (paper §2.4 convention).
    pub smoothing_length: Vec<f64>,
    /// Material index into the scene's material table.
    pub material: Vec<u16>,
    /// Stable particle identifier (survives reordering).
    pub id: Vec<u64>,
}

/// One particle's initial values, for [`Particles::push`].
#[derive(Clone, Copy, Debug)]
pub struct ParticleInit<V> {
    /// Position (m).
    pub position: V,
    /// Velocity (m/s).
    pub velocity: V,
    /// Mass (kg).
    pub mass: f64,
    /// Density (kg/m^DIM).
    pub density: f64,
    /// Specific internal energy (J/kg).
    pub specific_energy: f64,
    /// Support radius (m).
    pub smoothing_length: f64,
    /// Material index.
    pub material: u16,
}

impl<D: Dimension> Particles<D> {
    /// An empty store.
    pub fn new() -> Self {
        Self {
            position: Vec::new(),
            velocity: Vec::new(),
            mass: Vec::new(),
            density: Vec::new(),
            specific_energy: Vec::new(),
            smoothing_length: Vec::new(),
            material: Vec::new(),
            id: Vec::new(),
        }
    }

    /// Number of particles.
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// True when there are no particles.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Appends a particle; its id is its index at the time of insertion.
    pub fn push(&mut self, p: ParticleInit<D::Vector>) {
        let id = self.len() as u64;
        self.position.push(p.position);
        self.velocity.push(p.velocity);
        self.mass.push(p.mass);
        self.density.push(p.density);
        self.specific_energy.push(p.specific_energy);
        self.smoothing_length.push(p.smoothing_length);
        self.material.push(p.material);
        self.id.push(id);
    }

    /// Checks lengths and physical ranges: finite positions and velocities, positive
    /// finite mass, density and support radius, finite specific energy.
    pub fn validate(&self) -> Result<(), CoreError> {
        let n = self.len();
        for (what, got) in [
            ("velocity", self.velocity.len()),
            ("mass", self.mass.len()),
            ("density", self.density.len()),
            ("specific_energy", self.specific_energy.len()),
            ("smoothing_length", self.smoothing_length.len()),
            ("material", self.material.len()),
            ("id", self.id.len()),
        ] {
            if got != n {
                return Err(CoreError::LengthMismatch {
                    what,
                    expected: n,
                    got,
                });
            }
        }
        for i in 0..n {
            if !self.position[i].all_finite() {
                return Err(CoreError::NonFinitePosition {
                    index: i,
                    position: self.position[i].to_array3(),
                });
            }
            let v = self.velocity[i];
            if !v.all_finite() {
                return Err(CoreError::BadField {
                    index: i,
                    field: "velocity",
                    value: v.norm(),
                    reason: "not finite",
                });
            }
            for (field, value) in [
                ("mass", self.mass[i]),
                ("density", self.density[i]),
                ("smoothing_length", self.smoothing_length[i]),
            ] {
                if !(value > 0.0 && value.is_finite()) {
                    return Err(CoreError::BadField {
                        index: i,
                        field,
                        value,
                        reason: "must be positive and finite",
                    });
                }
            }
            if !self.specific_energy[i].is_finite() {
                return Err(CoreError::BadField {
                    index: i,
                    field: "specific_energy",
                    value: self.specific_energy[i],
                    reason: "not finite",
                });
            }
        }
        Ok(())
    }

    /// Reorders every field with `perm` (`perm[new] = old`).
    pub fn reorder(&mut self, perm: &Permutation) -> Result<(), CoreError> {
        perm.apply("position", &mut self.position)?;
        perm.apply("velocity", &mut self.velocity)?;
        perm.apply("mass", &mut self.mass)?;
        perm.apply("density", &mut self.density)?;
        perm.apply("specific_energy", &mut self.specific_energy)?;
        perm.apply("smoothing_length", &mut self.smoothing_length)?;
        perm.apply("material", &mut self.material)?;
        perm.apply("id", &mut self.id)?;
        Ok(())
    }

    /// Total mass Σ m_i.
    pub fn total_mass(&self) -> f64 {
        self.mass.iter().sum()
    }

    /// Total linear momentum Σ m_i v_i.
    pub fn total_momentum(&self) -> D::Vector {
        self.mass
            .iter()
            .zip(&self.velocity)
            .fold(D::Vector::ZERO, |acc, (&m, &v)| acc + v * m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dimension::Dim2;
    use glam::DVec2;

    fn sample() -> Particles<Dim2> {
        let mut p = Particles::<Dim2>::new();
        for k in 0..3 {
            p.push(ParticleInit {
                position: DVec2::new(k as f64, 0.0),
                velocity: DVec2::new(0.0, k as f64),
                mass: 1.0 + k as f64,
                density: 1.0,
                specific_energy: 0.0,
                smoothing_length: 0.1,
                material: k as u16,
            });
        }
        p
    }

    #[test]
    fn reorder_moves_every_field_together() {
        let mut p = sample();
        p.reorder(&Permutation::new(vec![2, 0, 1]).unwrap())
            .unwrap();
        assert_eq!(p.id, vec![2, 0, 1]);
        assert_eq!(p.mass, vec![3.0, 1.0, 2.0]);
        assert_eq!(p.material, vec![2, 0, 1]);
        assert_eq!(p.position[0], DVec2::new(2.0, 0.0));
        assert_eq!(p.total_momentum(), DVec2::new(0.0, 2.0 + 6.0));
    }

    #[test]
    fn validate_names_the_bad_particle() {
        let mut p = sample();
        assert!(p.validate().is_ok());
        p.density[1] = -1.0;
        let e = p.validate().unwrap_err();
        assert!(
            matches!(
                e,
                CoreError::BadField {
                    index: 1,
                    field: "density",
                    ..
                }
            ),
            "{e}"
        );
        p.density[1] = 1.0;
        p.mass.pop();
        assert!(matches!(
            p.validate(),
            Err(CoreError::LengthMismatch { what: "mass", .. })
        ));
    }
}

//! [`BodyDamage`]: a damage model as a material carries it before its body exists.
//!
//! A damage model may hold state per particle (Benz–Asphaug's flaws, dealt over the
//! body's volume with a seed; paper §3.3, Benz & Asphaug 1995, CPC 87:253), so a
//! material cannot hold the model itself: it holds a *recipe* that the scene builder
//! calls once per body, with that body's particles ([`BodyParticles`]). The built-in
//! models are recipes of this kind inside the material layer; a user's own model
//! implements this trait in their crate and plugs into a material the way a user's
//! equation of state or strength model does (`examples/custom_material`).

use crate::{DamageError, DamageModel, DamageVariable};
use std::sync::Arc;

/// The particles of one body, as the damage model of its material is built for them.
#[derive(Clone, Copy, Debug)]
pub struct BodyParticles<'a> {
    /// Each particle's volume (m³), in the order the solver gets them (in RZ, the volume
    /// of the ring). Index k of this slice is the `particle` index the solver passes to
    /// [`DamageModel::evaluate`].
    pub volumes: &'a [f64],
    /// The body's seed (the scene's `seed` plus the body's index, or its own
    /// `damage_seed`): the same seed and volumes must give the same model, bit for bit.
    pub seed: u64,
    /// The variable s = D^(1/p) the solver should integrate: D^(1/3) for 3-D cracks,
    /// D^(1/2) in plane strain.
    pub variable: DamageVariable,
    /// The number of 3-D particles the body's particles stand for (the particle count
    /// in 3-D; more in RZ, where each ring stands for a ring of 3-D particles): what
    /// flaws are dealt over ([`crate::FlawSet::seed_dealt`]).
    pub stands_for: usize,
}

/// A damage model's recipe: builds the model for one body.
///
/// Implementations must be deterministic (the same [`BodyParticles`] give the same
/// model) and the model they build must follow the [`DamageModel`] contract.
pub trait BodyDamage: Send + Sync + std::fmt::Debug {
    /// Short name for logs, material descriptions and errors.
    fn name(&self) -> &str;

    /// The model for the body's particles.
    fn build(&self, body: &BodyParticles<'_>) -> Result<Arc<dyn DamageModel>, DamageError>;

    /// The static tensile strength (Pa) of a volume V (m³) of the material, Young's
    /// modulus E (Pa), where the model defines one (used to report σ_b of a specimen);
    /// `None` by default.
    fn static_strength(&self, youngs_modulus: f64, volume: f64) -> Option<f64> {
        let _ = (youngs_modulus, volume);
        None
    }

    /// Whether the models it builds add to their D the shear failure of
    /// [`crate::PlasticFailure`], which needs a scalar D; `None` by default.
    fn shear_failure(&self) -> Option<crate::PlasticFailure> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{DamageEval, DamageInput, MaxTensileStress};

    /// A recipe that builds one maximum-tensile-stress model whatever the body, and
    /// refuses an empty body.
    #[derive(Debug)]
    struct Threshold(f64);

    impl BodyDamage for Threshold {
        fn name(&self) -> &str {
            "threshold"
        }
        fn build(&self, body: &BodyParticles<'_>) -> Result<Arc<dyn DamageModel>, DamageError> {
            if body.volumes.is_empty() {
                return Err(DamageError::Custom {
                    model: self.name().into(),
                    message: "no particles".into(),
                });
            }
            Ok(Arc::new(MaxTensileStress::new(self.0)?))
        }
    }

    #[test]
    fn a_recipe_builds_a_model_per_body_and_reports_its_errors() {
        let volumes = [1e-9; 4];
        let body = BodyParticles {
            volumes: &volumes,
            seed: 1,
            variable: DamageVariable::CubeRoot,
            stands_for: 4,
        };
        let model = Threshold(1e7).build(&body).unwrap();
        let input = DamageInput {
            max_principal_stress: 2e7,
            youngs_modulus: 5e10,
            longitudinal_wave_speed: 5e3,
            particle_size: 1e-3,
            damage: 0.0,
            principal_strain: None,
        };
        let eval: DamageEval = model.evaluate(0, &input);
        assert!(eval.rate > 0.0);
        let empty = BodyParticles {
            volumes: &[],
            ..body
        };
        let err = Threshold(1e7).build(&empty).unwrap_err();
        assert_eq!(err.to_string(), "damage model threshold: no particles");
        assert!(Threshold(-1.0).build(&body).is_err());
        assert_eq!(Threshold(1e7).static_strength(5e10, 1e-6), None);
    }
}

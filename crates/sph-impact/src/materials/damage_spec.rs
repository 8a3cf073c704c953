//! [`DamageSpec`]: the damage model of a material as a *specification*. Benz–Asphaug
//! flaws belong to one body (they depend on its particle volumes and a seed, paper §3.3;
//! Benz & Asphaug 1995, CPC 87:253), so a material holds the parameters and the scene
//! builder turns them into a model per body with [`DamageSpec::build`].

use sph_damage::{
    ActivationStrain, BenzAsphaug, BenzAsphaugParams, BodyDamage, BodyParticles, BuiltinDamage,
    CRACK_SPEED_FRACTION_BA94, DamageError, DamageForm, DamageModel, DamageVariable, FlawTail,
    GrowthLaw, MaxTensileStress, NoDamage, PlasticFailure, TensileFailure, WeibullParams,
};
use std::sync::Arc;

/// The damage model of a material (paper §3.3).
///
/// The built-in variants can be written to and read from TOML; [`DamageSpec::Custom`]
/// holds a user's model (a [`BodyDamage`] recipe from their own crate) and exists in
/// code only, like a custom equation of state or strength model.
#[derive(Clone, Debug, Default, PartialEq)]
pub enum DamageSpec {
    /// No damage.
    #[default]
    None,
    /// Maximum tensile stress: every particle fails at one threshold σ_b (paper §3.3).
    MaxTensileStress {
        /// σ_b, Pa (> 0).
        sigma_b: f64,
        /// Crack growth at c_g or instant failure.
        failure: TensileFailure,
        /// c_g / c_L in (0, 1] (0.4, Benz & Asphaug 1994, for crack growth).
        crack_speed_fraction: f64,
        /// Shear failure from plastic strain added to the same D
        /// (sph_damage::shear_failure), or none.
        shear: Option<PlasticFailure>,
    },
    /// Benz–Asphaug Weibull flaws n(ε) = k ε^m per unit volume with crack growth (Benz &
    /// Asphaug 1994, Icarus 107:98).
    BenzAsphaug {
        /// Weibull k, m⁻³ (> 0).
        k: f64,
        /// Weibull modulus m (> 0).
        m: f64,
        /// c_g / c_L in (0, 1] (0.4, Benz & Asphaug 1994).
        crack_speed_fraction: f64,
        /// How the growth rate depends on the number of active flaws.
        growth: GrowthLaw,
        /// Flaws beyond the strongest seeded one (sph_damage::flaw_tail).
        tail: FlawTail,
        /// The strain the flaws activate on (sph_damage::activation).
        strain: ActivationStrain,
        /// Scalar or tensor damage (sph_damage::tensor).
        form: DamageForm,
        /// Shear failure from plastic strain added to the same D
        /// (sph_damage::shear_failure; scalar form only), or none.
        shear: Option<PlasticFailure>,
    },
    /// A user's damage model, built per body by its recipe.
    Custom(CustomDamage),
}

/// A user's damage recipe in a [`DamageSpec`]: compared by identity (two specs are equal
/// when they hold the same `Arc`), so the built-in variants keep their derived,
/// value-wise equality.
#[derive(Clone, Debug)]
pub struct CustomDamage(pub Arc<dyn BodyDamage>);

impl PartialEq for CustomDamage {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl std::ops::Deref for CustomDamage {
    type Target = dyn BodyDamage;
    fn deref(&self) -> &Self::Target {
        &*self.0
    }
}

impl DamageSpec {
    /// A user's damage model (see [`BodyDamage`]).
    pub fn custom(recipe: impl BodyDamage + 'static) -> Self {
        Self::Custom(CustomDamage(Arc::new(recipe)))
    }

    /// False for [`DamageSpec::Custom`], which material files cannot describe.
    pub fn is_builtin(&self) -> bool {
        !matches!(self, Self::Custom(_))
    }

    /// Maximum tensile stress at σ_b (Pa) with crack growth at 0.4 c_L.
    pub fn max_tensile_stress(sigma_b: f64) -> Self {
        Self::MaxTensileStress {
            sigma_b,
            failure: TensileFailure::default(),
            crack_speed_fraction: CRACK_SPEED_FRACTION_BA94,
            shear: None,
        }
    }

    /// Benz–Asphaug with Weibull k (m⁻³) and m, crack speed 0.4 c_L, the default growth
    /// law ([`GrowthLaw::PerActivatedFlaw`]), only the seeded flaws
    /// ([`FlawTail::Seeded`]), activation on the stress ([`ActivationStrain::Stress`]) and
    /// scalar damage ([`DamageForm::Scalar`]).
    pub fn benz_asphaug(k: f64, m: f64) -> Self {
        Self::BenzAsphaug {
            k,
            m,
            crack_speed_fraction: CRACK_SPEED_FRACTION_BA94,
            growth: GrowthLaw::default(),
            tail: FlawTail::default(),
            strain: ActivationStrain::default(),
            form: DamageForm::default(),
            shear: None,
        }
    }

    /// Benz–Asphaug from a named Weibull set (e.g. [`WeibullParams::BASALT_STUDY`]).
    pub fn benz_asphaug_weibull(weibull: WeibullParams) -> Self {
        Self::benz_asphaug(weibull.k(), weibull.m())
    }

    /// The same model with shear failure added (Collins et al. 2004;
    /// sph_damage::shear_failure); `None` for [`DamageSpec::None`], which has no damage
    /// for it to raise, and for a custom model, which adds its own
    /// ([`BodyDamage::shear_failure`]).
    pub fn with_shear_failure(&self, law: PlasticFailure) -> Option<Self> {
        let mut out = self.clone();
        match &mut out {
            Self::None | Self::Custom(_) => return None,
            Self::MaxTensileStress { shear, .. } | Self::BenzAsphaug { shear, .. } => {
                *shear = Some(law)
            }
        }
        Some(out)
    }

    /// The shear-failure law, if the model has one.
    pub fn shear_failure(&self) -> Option<PlasticFailure> {
        match self {
            Self::None => None,
            Self::MaxTensileStress { shear, .. } | Self::BenzAsphaug { shear, .. } => *shear,
            Self::Custom(recipe) => recipe.shear_failure(),
        }
    }

    /// Model name as in material files: `none`, `max-tensile-stress`, `benz-asphaug`;
    /// a custom model's own name.
    pub fn name(&self) -> &str {
        match self {
            Self::None => "none",
            Self::MaxTensileStress { .. } => "max-tensile-stress",
            Self::BenzAsphaug { .. } => "benz-asphaug",
            Self::Custom(recipe) => recipe.name(),
        }
    }

    /// Checks the parameters with the constructors of sph-damage; the error names the
    /// field (`sigma_b`, `k`, `m`, `crack_speed_fraction`).
    pub fn validate(&self) -> Result<(), DamageError> {
        match *self {
            // A custom recipe checks its parameters when it is built.
            Self::None | Self::Custom(_) => Ok(()),
            Self::MaxTensileStress {
                sigma_b,
                failure,
                crack_speed_fraction,
                ..
            } => MaxTensileStress::new(sigma_b)?
                .with_failure(failure)
                .with_crack_speed_fraction(crack_speed_fraction)
                .map(|_| ()),
            Self::BenzAsphaug {
                k,
                m,
                crack_speed_fraction,
                form,
                shear,
                ..
            } => {
                if let (DamageForm::Tensor, Some(law)) = (form, shear) {
                    return Err(DamageError::Parameter {
                        field: "shear_min_strain",
                        value: law.min_strain(),
                        reason: "shear failure raises a scalar damage: it needs form = \"scalar\"",
                    });
                }
                let w = WeibullParams::new(k, m)?;
                BenzAsphaugParams::new(w, 0)
                    .with_crack_speed_fraction(crack_speed_fraction)
                    .map(|_| ())
            }
        }
    }

    /// Static tensile strength of a volume V (m³) for a material of Young's modulus E (Pa):
    /// σ_b itself for the maximum-tensile-stress model, E (kV)^(−1/m) for Benz–Asphaug
    /// (paper §3.3), `None` without damage.
    pub fn static_strength(&self, youngs_modulus: f64, volume: f64) -> Option<f64> {
        match *self {
            Self::None => None,
            Self::MaxTensileStress { sigma_b, .. } => Some(sigma_b),
            Self::BenzAsphaug { k, m, .. } => {
                Some(sph_damage::static_strength(youngs_modulus, k, m, volume))
            }
            Self::Custom(ref recipe) => recipe.static_strength(youngs_modulus, volume),
        }
    }

    /// Builds the model for one body whose particles have volumes `particle_volumes` (m³;
    /// V = Σ V_i, used by Benz–Asphaug only), seeding its flaws with `seed` (same volumes
    /// and seed → the same flaws, bit for bit). The solver integrates D^(1/3) (3-D
    /// cracks); see [`Self::build_with_variable`] for 2-D.
    pub fn build(&self, particle_volumes: &[f64], seed: u64) -> Result<BuiltinDamage, DamageError> {
        self.build_with_variable(
            particle_volumes,
            seed,
            DamageVariable::CubeRoot,
            particle_volumes.len(),
        )
    }

    /// As [`Self::build`], choosing the integrated variable of Benz–Asphaug damage
    /// (D^(1/2) for 2-D cracks, as miluphcuda integrates D^(1/DIM)) and the number of
    /// particles the flaws are dealt over, `dealt_over` ≥ the particle count: the
    /// particle count itself in 3-D, the 3-D particles the rings stand for in RZ
    /// ([`sph_damage::FlawSet::seed_dealt`]).
    pub fn build_with_variable(
        &self,
        particle_volumes: &[f64],
        seed: u64,
        variable: DamageVariable,
        dealt_over: usize,
    ) -> Result<BuiltinDamage, DamageError> {
        match *self {
            Self::Custom(ref recipe) => Err(DamageError::Custom {
                model: recipe.name().to_owned(),
                message: "a custom model is built by DamageSpec::build_model, not as a \
                          built-in"
                    .to_owned(),
            }),
            Self::None => Ok(BuiltinDamage::None(NoDamage)),
            Self::MaxTensileStress {
                sigma_b,
                failure,
                crack_speed_fraction,
                ..
            } => Ok(BuiltinDamage::MaxTensileStress(
                MaxTensileStress::new(sigma_b)?
                    .with_failure(failure)
                    .with_crack_speed_fraction(crack_speed_fraction)?,
            )),
            Self::BenzAsphaug {
                k,
                m,
                crack_speed_fraction,
                growth,
                tail,
                strain,
                form,
                ..
            } => {
                let params = BenzAsphaugParams::new(WeibullParams::new(k, m)?, seed)
                    .with_crack_speed_fraction(crack_speed_fraction)?
                    .with_growth(growth)
                    .with_variable(variable)
                    .with_tail(tail)
                    .with_activation(strain)
                    .with_form(form);
                Ok(BuiltinDamage::BenzAsphaug(
                    BenzAsphaug::seed_with_volumes_dealt(params, particle_volumes, dealt_over)?,
                ))
            }
        }
    }

    /// The model for one body, built-in or custom: what the scene builder hands the
    /// solver ([`Self::build_with_variable`] for the built-in ones, the recipe's
    /// [`BodyDamage::build`] for a custom one).
    pub fn build_model(
        &self,
        body: &BodyParticles<'_>,
    ) -> Result<Arc<dyn DamageModel>, DamageError> {
        match self {
            Self::Custom(recipe) => recipe.build(body),
            _ => Ok(Arc::new(self.build_with_variable(
                body.volumes,
                body.seed,
                body.variable,
                body.stands_for,
            )?)),
        }
    }
}

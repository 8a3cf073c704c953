//! [`MaterialSpec`]: a material as the composition of an equation of state, a strength
//! model, a damage model and thermal data, with its reference density, shear modulus and
//! the sources of its parameters (paper §3; design.md "a material is a combination of an
//! EOS, a strength model and a damage model").
//!
//! Elastic constants at the reference state (ρ0, e = 0, P = 0, T = 300 K):
//!
//! - bulk modulus K = ρ0 c0², c0 the EOS's reference sound speed (Tillotson: K = A);
//! - Young's modulus E = 9KG/(3K + G) and Poisson's ratio ν = (3K − 2G)/(2(3K + G))
//!   (isotropic elasticity, Landau & Lifshitz, *Theory of Elasticity* §4–5);
//! - longitudinal wave speed c_L = √((K + 4G/3)/ρ) (paper §2.5: the speed the CFL
//!   condition must use for a solid), shear wave speed c_s = √(G/ρ).

use crate::materials::damage_spec::DamageSpec;
use crate::materials::eos_choice::EosChoice;
use crate::materials::error::MaterialError;
use crate::materials::strength_choice::StrengthChoice;
use sph_damage::DamageError;
use sph_eos::{EquationOfState, ThermalModel};
use sph_strength::{BuiltinStrength, StrengthModel, StrengthState};

/// The largest accepted material density (kg/m³): over four times osmium's, the densest
/// element; beyond it a run's first steps collapse.
pub const MAX_DENSITY: f64 = 1.0e5;
/// Temperature of the reference state at which a material's shear modulus is compared
/// with its strength model's G: 300 K, the reference temperature of the Steinberg–Guinan
/// bracket (Steinberg, Cochran & Guinan 1980).
pub const REFERENCE_TEMPERATURE: f64 = 300.0;

/// Relative tolerance of the consistency checks (density vs EOS ρ0, shear modulus vs the
/// strength model's G): round-off only.
const CONSISTENCY_TOLERANCE: f64 = 1e-9;

/// A complete material description.
///
/// Fields are public so a material can be written as a struct literal; call
/// [`MaterialSpec::validate`] (or build with [`MaterialSpec::validated`]) before use.
/// The built-in materials are in [`crate::materials::library()`]; TOML input and output in
/// [`MaterialSpec::from_toml_str`] and [`MaterialSpec::to_toml`].
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialSpec {
    /// Name, e.g. `"basalt-study"`.
    pub name: String,
    /// Reference density ρ0, kg/m³: the EOS's reference density where the EOS has one
    /// (checked).
    pub density: f64,
    /// Shear modulus G at the reference state, Pa: > 0 with strength, 0 for a fluid
    /// (checked against the strength model).
    pub shear_modulus: f64,
    /// Equation of state.
    pub eos: EosChoice,
    /// Strength model ([`StrengthChoice::NONE`] for a fluid).
    pub strength: StrengthChoice,
    /// Damage model, as parameters; flaws are seeded per body ([`DamageSpec::build`]).
    pub damage: DamageSpec,
    /// Caloric model T(e) with melting and vaporisation (paper §3.1); `None` if the
    /// material has no thermal data.
    pub thermal: Option<ThermalModel>,
    /// Where the parameters come from, one entry per parameter group
    /// (`"eos: Tillotson, Table A1 of the study ..."`).
    pub sources: Vec<String>,
}

impl MaterialSpec {
    /// A fluid: `eos` only, no strength, damage or thermal data. Add the rest with the
    /// `with_*` methods.
    pub fn new(name: impl Into<String>, density: f64, eos: impl Into<EosChoice>) -> Self {
        Self {
            name: name.into(),
            density,
            shear_modulus: 0.0,
            eos: eos.into(),
            strength: StrengthChoice::NONE,
            damage: DamageSpec::None,
            thermal: None,
            sources: Vec::new(),
        }
    }

    /// Sets the strength model and the shear modulus G (Pa) it uses.
    pub fn with_strength(
        mut self,
        strength: impl Into<StrengthChoice>,
        shear_modulus: f64,
    ) -> Self {
        self.strength = strength.into();
        self.shear_modulus = shear_modulus;
        self
    }

    /// Sets the damage model.
    pub fn with_damage(mut self, damage: DamageSpec) -> Self {
        self.damage = damage;
        self
    }

    /// Sets the thermal data.
    pub fn with_thermal(mut self, thermal: ThermalModel) -> Self {
        self.thermal = Some(thermal);
        self
    }

    /// Adds a source (citation) line.
    pub fn with_source(mut self, source: impl Into<String>) -> Self {
        self.sources.push(source.into());
        self
    }

    /// [`Self::validate`]s and returns the material.
    pub fn validated(self) -> Result<Self, MaterialError> {
        self.validate()?;
        Ok(self)
    }

    /// True without strength (the solver then skips the deviatoric stress).
    pub fn is_fluid(&self) -> bool {
        !self.strength.has_strength()
    }

    /// The state at which G is compared: P = 0, ρ = ρ0, T = [`REFERENCE_TEMPERATURE`],
    /// intact and unstrained.
    pub fn reference_strength_state(&self) -> StrengthState {
        StrengthState::new(0.0, self.density, REFERENCE_TEMPERATURE)
    }

    /// Bulk modulus K = ρ0 c0² (Pa) from the EOS's reference sound speed; `None` if the
    /// EOS has none (ideal gas).
    pub fn bulk_modulus(&self) -> Option<f64> {
        let c0 = self.eos.reference_sound_speed()?;
        let rho0 = self.eos.reference_density().unwrap_or(self.density);
        Some(rho0 * c0 * c0)
    }

    /// Young's modulus E = 9KG/(3K + G), Pa (0 for a fluid).
    pub fn youngs_modulus(&self) -> Option<f64> {
        self.bulk_modulus()
            .map(|k| sph_damage::youngs_modulus(k, self.shear_modulus))
    }

    /// Poisson's ratio ν = (3K − 2G)/(2(3K + G)) (½ for a fluid).
    pub fn poisson_ratio(&self) -> Option<f64> {
        self.bulk_modulus()
            .map(|k| sph_damage::poisson_ratio(k, self.shear_modulus))
    }

    /// Longitudinal wave speed c_L = √((K + 4G/3)/ρ0), m/s, at the reference density
    /// (the bulk sound speed for a fluid).
    pub fn longitudinal_wave_speed(&self) -> Option<f64> {
        self.longitudinal_wave_speed_at(self.density)
    }

    /// c_L = √((K + 4G/3)/ρ) with the reference K and G at another density ρ (kg/m³):
    /// e.g. basalt at 2700 kg/m³ (docs/reference/weibull_flaws.md, "Parameter sets").
    pub fn longitudinal_wave_speed_at(&self, density: f64) -> Option<f64> {
        self.bulk_modulus()
            .map(|k| sph_damage::longitudinal_wave_speed(k, self.shear_modulus, density))
    }

    /// Shear wave speed c_s = √(G/ρ0), m/s (0 for a fluid).
    pub fn shear_wave_speed(&self) -> f64 {
        (self.shear_modulus / self.density).sqrt()
    }

    /// The material as a fluid: its EOS alone under this name (strength, damage and
    /// thermal data dropped), for hydrodynamic runs.
    pub fn hydrodynamic_material(&self) -> crate::Material {
        crate::Material {
            name: self.name.clone(),
            eos: self.eos.shared(),
            strength: None,
            thermal: None,
            damage: None,
            shear_failure: None,
        }
    }

    /// The material of one body for the solver: [`Self::solver_material`] with the damage
    /// model built for the body's particles (volumes m³, in the order the solver gets
    /// them), seeding its flaws with `seed` dealt over `dealt_over` particles (the
    /// particle count in 3-D; see [`crate::materials::DamageSpec::build_with_variable`]),
    /// integrating `variable` (D^(1/3) for 3-D cracks, D^(1/2) in 2-D).
    pub fn body_material(
        &self,
        particle_volumes: &[f64],
        (seed, dealt_over): (u64, usize),
        variable: sph_damage::DamageVariable,
    ) -> Result<crate::Material, sph_damage::DamageError> {
        let mut m = self.solver_material();
        if self.damage != crate::materials::DamageSpec::None {
            m.damage = Some(self.damage.build_model(&sph_damage::BodyParticles {
                volumes: particle_volumes,
                seed,
                variable,
                stands_for: dealt_over,
            })?);
            m.shear_failure = self.damage.shear_failure();
        }
        Ok(m)
    }

    /// The material for the solver with its strength model and thermal data; damage is
    /// per body ([`Self::body_material`]).
    pub fn solver_material(&self) -> crate::Material {
        let strength: Option<std::sync::Arc<dyn sph_strength::StrengthModel>> = (!self.is_fluid())
            .then(|| {
                std::sync::Arc::new(self.strength.clone())
                    as std::sync::Arc<dyn sph_strength::StrengthModel>
            });
        crate::Material {
            name: self.name.clone(),
            eos: self.eos.shared(),
            strength,
            thermal: self.thermal,
            // Damage belongs to a body (its flaws): see `DamageSpec::build`.
            damage: None,
            shear_failure: None,
        }
    }

    /// Checks the material as a whole; the error names the field:
    ///
    /// - `name` not empty; `density` positive and finite and equal to the EOS's reference
    ///   density (relative 1e-9);
    /// - the EOS evaluates to finite values at (ρ0, e = 0) and its reference sound speed,
    ///   if any, is positive;
    /// - `shear_modulus` > 0 and equal to the strength model's G at the reference state
    ///   ([`Self::reference_strength_state`]) for a solid, 0 for a fluid;
    /// - temperature-dependent strength (Johnson–Cook, Steinberg–Guinan) has thermal data;
    ///   a Steinberg–Guinan ρ0 equals the density;
    /// - damage parameters in range; Benz–Asphaug needs Young's modulus (G > 0 and an EOS
    ///   bulk modulus).
    pub fn validate(&self) -> Result<(), MaterialError> {
        let invalid = |field: &str, value: f64, reason: String| {
            Err(MaterialError::Invalid {
                material: self.name.clone(),
                field: field.to_owned(),
                value,
                reason,
                location: None,
            })
        };
        let inconsistent = |field: &str, reason: String| {
            Err(MaterialError::Inconsistent {
                material: self.name.clone(),
                field: field.to_owned(),
                reason,
                location: None,
            })
        };
        if self.name.trim().is_empty() {
            return inconsistent("name", "must not be empty".into());
        }
        // Names are printed in messages and reports: an escape sequence in one would
        // drive the terminal (the message quotes the name escaped).
        if let Some(c) = self.name.chars().find(|c| c.is_control()) {
            return Err(MaterialError::Inconsistent {
                material: crate::input::printable(&self.name).into_owned(),
                field: "name".into(),
                reason: format!(
                    "must not contain control characters (found U+{:04X})",
                    u32::from(c)
                ),
                location: None,
            });
        }
        let rho = self.density;
        if !(rho > 0.0 && rho <= MAX_DENSITY) {
            return invalid(
                "density",
                rho,
                format!("must be positive and at most {MAX_DENSITY:e} kg/m^3"),
            );
        }
        let g = self.shear_modulus;
        if !(g.is_finite() && g >= 0.0) {
            return invalid("shear_modulus", g, "must be non-negative and finite".into());
        }

        // Equation of state.
        if let Some(rho0) = self.eos.reference_density()
            && !((rho0 - rho).abs() <= CONSISTENCY_TOLERANCE * rho)
        {
            return invalid(
                "density",
                rho,
                format!(
                    "differs from the reference density of the {} EOS, rho0 = {rho0} kg/m^3 \
                     (a material's density must be its EOS's reference density)",
                    self.eos.name()
                ),
            );
        }
        if let Err(e) = self.eos.checked_evaluate(rho, 0.0) {
            return inconsistent("eos", format!("fails at the reference state: {e}"));
        }
        if let Some(c0) = self.eos.reference_sound_speed()
            && !(c0.is_finite() && c0 > 0.0)
        {
            return inconsistent(
                "eos",
                format!("reference sound speed c0 = {c0} m/s must be positive"),
            );
        }

        // Strength.
        if self.strength.has_strength() {
            if !(g > 0.0) {
                return invalid(
                    "shear_modulus",
                    g,
                    format!(
                        "must be positive for a material with strength (model `{}`)",
                        self.strength.name()
                    ),
                );
            }
            let g_model = self
                .strength
                .shear_modulus(&self.reference_strength_state());
            if !((g_model - g).abs() <= CONSISTENCY_TOLERANCE * g) {
                return invalid(
                    "shear_modulus",
                    g,
                    format!(
                        "differs from the `{}` model's G = {g_model} Pa at the reference \
                         state (P = 0, rho = {rho} kg/m^3, T = {REFERENCE_TEMPERATURE} K)",
                        self.strength.name()
                    ),
                );
            }
            if self.strength.needs_temperature() && self.thermal.is_none() {
                return inconsistent(
                    "strength.model",
                    format!(
                        "`{}` depends on temperature: the material needs thermal data \
                         ([thermal]) to get T from the specific energy",
                        self.strength.name()
                    ),
                );
            }
            if let Some(BuiltinStrength::SteinbergGuinan(sg)) = self.strength.builtin() {
                let rho_sg = sg.params().reference_density;
                if !((rho_sg - rho).abs() <= CONSISTENCY_TOLERANCE * rho) {
                    return invalid(
                        "strength.reference_density",
                        rho_sg,
                        format!("differs from the material density {rho} kg/m^3"),
                    );
                }
            }
        } else if g != 0.0 {
            return invalid(
                "shear_modulus",
                g,
                "must be 0 for a material without strength (a fluid has no shear modulus)".into(),
            );
        }

        // Damage.
        self.damage.validate().map_err(|e| self.damage_error(e))?;
        if matches!(self.damage, DamageSpec::BenzAsphaug { .. })
            && !(self.youngs_modulus().is_some_and(|e| e > 0.0))
        {
            return inconsistent(
                "damage.model",
                "benz-asphaug activates flaws on the strain sigma/E: it needs Young's \
                 modulus, i.e. a shear modulus > 0 and an EOS with a reference sound speed"
                    .into(),
            );
        }
        Ok(())
    }

    /// A damage parameter error as a material error naming `damage.<field>`.
    pub(crate) fn damage_error(&self, e: DamageError) -> MaterialError {
        match e {
            DamageError::Parameter {
                field,
                value,
                reason,
            } => MaterialError::Invalid {
                material: self.name.clone(),
                field: format!("damage.{field}"),
                value,
                reason: reason.to_owned(),
                location: None,
            },
            other => MaterialError::Inconsistent {
                material: self.name.clone(),
                field: "damage".into(),
                reason: other.to_string(),
                location: None,
            },
        }
    }
}

//! The parameters of each model as a list of `key = value` pairs, spelled as in a
//! material file: the common form behind TOML output, presets, `base = ...` overrides and
//! the descriptions. Built from a model here; turned back into a model in `build.rs`.

use crate::materials::damage_spec::DamageSpec;
use crate::materials::eos_choice::EosChoice;
use crate::materials::strength_choice::StrengthChoice;
use sph_damage::{ActivationStrain, DamageForm, FlawTail, GrowthLaw, TensileFailure};
use sph_eos::{DEFAULT_SOUND_SPEED_FLOOR_FRACTION, ThermalModel};
use sph_strength::{BuiltinStrength, LundborgTension};
use std::ops::Range;

/// A parameter value: a number or a name.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    Num(f64),
    Str(String),
}

/// One `key = value` with the byte span of the value in the file it came from.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Param {
    pub(crate) key: &'static str,
    pub(crate) value: Value,
    pub(crate) span: Option<Range<usize>>,
}

/// A model and its parameters.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Section {
    /// Model name (`None` for thermal data, which has one model).
    pub(crate) model: Option<String>,
    /// Span of the `model = ...` value, if it came from a file.
    pub(crate) model_span: Option<Range<usize>>,
    pub(crate) params: Vec<Param>,
}

impl Section {
    pub(crate) fn new(model: Option<&str>) -> Self {
        Self {
            model: model.map(str::to_owned),
            ..Self::default()
        }
    }

    fn num(mut self, key: &'static str, value: f64) -> Self {
        self.set(Param {
            key,
            value: Value::Num(value),
            span: None,
        });
        self
    }

    fn name(mut self, key: &'static str, value: &str) -> Self {
        self.set(Param {
            key,
            value: Value::Str(value.to_owned()),
            span: None,
        });
        self
    }

    pub(crate) fn get(&self, key: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.key == key)
    }

    /// Replaces the parameter of the same key, or appends it.
    pub(crate) fn set(&mut self, p: Param) {
        match self.params.iter_mut().find(|q| q.key == p.key) {
            Some(q) => *q = p,
            None => self.params.push(p),
        }
    }
}

/// Names of [`TensileFailure`] in material files.
pub(crate) const TENSILE_FAILURES: [(&str, TensileFailure); 2] = [
    ("crack-growth", TensileFailure::CrackGrowth),
    ("instant", TensileFailure::Instant),
];

/// Names of [`GrowthLaw`] in material files.
pub(crate) const GROWTH_LAWS: [(&str, GrowthLaw); 4] = [
    ("per-activated-flaw", GrowthLaw::PerActivatedFlaw),
    ("activated-fraction", GrowthLaw::ActivatedFraction),
    ("single-crack", GrowthLaw::SingleCrack),
    ("crack-volume", GrowthLaw::CrackVolume),
];

/// Names of [`FlawTail`] in material files.
pub(crate) const FLAW_TAILS: [(&str, FlawTail); 2] = [
    ("seeded", FlawTail::Seeded),
    ("continuum", FlawTail::Continuum),
];

/// Names of [`ActivationStrain`] in material files (`[damage] strain`).
pub(crate) const ACTIVATION_STRAINS: [(&str, ActivationStrain); 2] = [
    ("stress", ActivationStrain::Stress),
    ("pseudo-plastic", ActivationStrain::PseudoPlastic),
];

/// Names of [`DamageForm`] in material files (`[damage] form`).
pub(crate) const DAMAGE_FORMS: [(&str, DamageForm); 2] = [
    ("scalar", DamageForm::Scalar),
    ("tensor", DamageForm::Tensor),
];

/// Names of [`LundborgTension`] in material files.
pub(crate) const LUNDBORG_TENSIONS: [(&str, LundborgTension); 2] = [
    ("linear-to-zero", LundborgTension::LinearToZero),
    ("constant-cohesion", LundborgTension::ConstantCohesion),
];

/// The file name of an option value.
pub(crate) fn name_of<T: PartialEq + Copy>(table: &[(&'static str, T)], value: T) -> &'static str {
    table
        .iter()
        .find(|(_, v)| *v == value)
        .map(|(n, _)| *n)
        .unwrap_or("?")
}

/// The EOS's parameters; `None` for a user-defined EOS.
pub(crate) fn eos_section(eos: &EosChoice) -> Option<Section> {
    Some(match eos {
        EosChoice::Tillotson(t) => {
            let p = t.params();
            let mut s = Section::new(Some("tillotson"))
                .num("rho0", p.rho0)
                .num("A", p.A)
                .num("B", p.B)
                .num("a", p.a)
                .num("b", p.b)
                .num("alpha", p.alpha)
                .num("beta", p.beta)
                .num("E0", p.E0)
                .num("E_iv", p.E_iv)
                .num("E_cv", p.E_cv);
            if t.sound_speed_floor_fraction() != DEFAULT_SOUND_SPEED_FLOOR_FRACTION {
                s = s.num("sound_speed_floor_fraction", t.sound_speed_floor_fraction());
            }
            if let Some(p_min) = t.min_pressure() {
                s = s.num("min_pressure", p_min);
            }
            s
        }
        EosChoice::MieGruneisen(m) => {
            let p = m.params();
            let s = Section::new(Some("mie-gruneisen"))
                .num("rho0", p.rho0)
                .num("c0", p.c0)
                .num("s", p.s)
                .num("gamma0", p.gamma0);
            with_floor(s, m.sound_speed_floor(), p.c0)
        }
        EosChoice::Murnaghan(m) => {
            let p = m.params();
            let s = Section::new(Some("murnaghan"))
                .num("rho0", p.rho0)
                .num("K0", p.K0)
                .num("n", p.n);
            with_floor(s, m.sound_speed_floor(), (p.K0 / p.rho0).sqrt())
        }
        EosChoice::LinearElastic(m) => {
            let p = m.params();
            Section::new(Some("linear-elastic"))
                .num("rho0", p.rho0)
                .num("K0", p.K0)
        }
        EosChoice::IdealGas(g) => {
            let s = Section::new(Some("ideal-gas")).num("gamma", g.gamma());
            if g.sound_speed_floor() != 0.0 {
                s.num("min_sound_speed", g.sound_speed_floor())
            } else {
                s
            }
        }
        EosChoice::Custom(_) => return None,
    })
}

/// Adds `sound_speed_floor_fraction` when the floor is not the default fraction of c0
/// (the fraction is recovered as floor/c0, exact up to round-off).
fn with_floor(s: Section, floor: f64, c0: f64) -> Section {
    if floor != DEFAULT_SOUND_SPEED_FLOOR_FRACTION * c0 {
        s.num("sound_speed_floor_fraction", floor / c0)
    } else {
        s
    }
}

/// The strength model's parameters without the shear modulus (a material-level value);
/// `None` for a user-defined model.
pub(crate) fn strength_section(strength: &StrengthChoice) -> Option<Section> {
    let b = strength.builtin()?;
    Some(match b {
        BuiltinStrength::None => Section::new(Some("none")),
        BuiltinStrength::VonMises(m) => {
            let p = m.params();
            let s = Section::new(Some("von-mises")).num("yield_strength", p.yield_strength);
            match p.hardening {
                Some(h) => s.num("hardening_modulus", h.modulus),
                None => s,
            }
        }
        BuiltinStrength::DruckerPrager(m) => {
            let p = m.params();
            Section::new(Some("drucker-prager"))
                .num("cohesion", p.cohesion)
                .num("friction", p.friction)
                .num("limit_strength", p.limit_strength)
                .num("damaged_friction", p.damaged_friction)
        }
        BuiltinStrength::Lundborg(m) => {
            let p = m.params();
            Section::new(Some("lundborg"))
                .num("cohesion", p.cohesion)
                .num("friction", p.friction)
                .num("limit_strength", p.limit_strength)
                .num("damaged_friction", p.damaged_friction)
                .name("tension", name_of(&LUNDBORG_TENSIONS, p.tension))
        }
        BuiltinStrength::JohnsonCook(m) => {
            let p = m.params();
            Section::new(Some("johnson-cook"))
                .num("a", p.a)
                .num("b", p.b)
                .num("n", p.n)
                .num("c", p.c)
                .num("m", p.m)
                .num("melt_temperature", p.melt_temperature)
                .num("reference_temperature", p.reference_temperature)
                .num("reference_strain_rate", p.reference_strain_rate)
        }
        BuiltinStrength::SteinbergGuinan(m) => {
            let p = m.params();
            let s = Section::new(Some("steinberg-guinan"))
                .num("pressure_coefficient", p.pressure_coefficient)
                .num("temperature_coefficient", p.temperature_coefficient)
                .num("yield_strength", p.yield_strength)
                .num("max_yield_strength", p.max_yield_strength)
                .num("hardening_coefficient", p.hardening_coefficient)
                .num("hardening_exponent", p.hardening_exponent)
                .num("initial_plastic_strain", p.initial_plastic_strain)
                .num("reference_density", p.reference_density)
                .num("melt_temperature", p.melt_temperature);
            match p.melt_law {
                Some(law) => s.num("melt_gamma0", law.gamma0).num("melt_a", law.a),
                None => s,
            }
        }
    })
}

/// The damage model's parameters; `None` for a user-defined model.
pub(crate) fn damage_section(damage: &DamageSpec) -> Option<Section> {
    let sec = damage_model_section(damage)?;
    Some(match damage.shear_failure() {
        Some(law) => sec
            .num("shear_min_strain", law.min_strain())
            .num("shear_pressure_slope", law.pressure_slope())
            .num("shear_pressure_offset", law.pressure_offset()),
        None => sec,
    })
}

/// The damage model's own parameters (without shear failure).
fn damage_model_section(damage: &DamageSpec) -> Option<Section> {
    Some(match *damage {
        DamageSpec::Custom(_) => return None,
        DamageSpec::None => Section::new(Some("none")),
        DamageSpec::MaxTensileStress {
            sigma_b,
            failure,
            crack_speed_fraction,
            ..
        } => Section::new(Some("max-tensile-stress"))
            .num("sigma_b", sigma_b)
            .name("failure", name_of(&TENSILE_FAILURES, failure))
            .num("crack_speed_fraction", crack_speed_fraction),
        DamageSpec::BenzAsphaug {
            k,
            m,
            crack_speed_fraction,
            growth,
            tail,
            strain,
            form,
            ..
        } => Section::new(Some("benz-asphaug"))
            .num("k", k)
            .num("m", m)
            .num("crack_speed_fraction", crack_speed_fraction)
            .name("growth", name_of(&GROWTH_LAWS, growth))
            .name("tail", name_of(&FLAW_TAILS, tail))
            .name("strain", name_of(&ACTIVATION_STRAINS, strain))
            .name("form", name_of(&DAMAGE_FORMS, form)),
    })
}

/// The thermal model's parameters.
pub(crate) fn thermal_section(thermal: &ThermalModel) -> Section {
    let p = thermal.params();
    Section::new(None)
        .num("c_v", p.c_v)
        .num("T_ref", p.T_ref)
        .num("T_melt", p.T_melt)
        .num("L_melt", p.L_melt)
        .num("T_vap", p.T_vap)
        .num("L_vap", p.L_vap)
}

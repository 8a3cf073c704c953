//! Turns a [`Section`] (a model name and `key = value` pairs) back into a model, checking
//! that every key belongs to the model, that required keys are present and that the
//! values pass the model's own validation. Errors name `section.key` and, for values
//! from a file, the line.

use crate::materials::damage_spec::DamageSpec;
use crate::materials::eos_choice::EosChoice;
use crate::materials::error::{Location, MaterialError};
use crate::materials::sections::{
    ACTIVATION_STRAINS, DAMAGE_FORMS, FLAW_TAILS, GROWTH_LAWS, LUNDBORG_TENSIONS, Section,
    TENSILE_FAILURES, Value,
};
use crate::materials::strength_choice::StrengthChoice;
use sph_damage::{
    ActivationStrain, CRACK_SPEED_FRACTION_BA94, DamageError, DamageForm, FlawTail, GrowthLaw,
    PlasticFailure, TensileFailure,
};
use sph_eos::{
    EosError, IdealGas, IdealGasParams, LinearElastic, LinearElasticParams, MieGruneisen,
    MieGruneisenParams, Murnaghan, MurnaghanParams, ThermalModel, ThermalParams, Tillotson,
    TillotsonParams,
};
use sph_strength::{
    BuiltinStrength, DruckerPrager, DruckerPragerParams, JohnsonCook, JohnsonCookParams,
    LinearHardening, Lundborg, LundborgParams, LundborgTension, SgMeltLaw, SteinbergGuinan,
    SteinbergGuinanParams, StrengthError, VonMises, VonMisesParams,
};
use std::ops::Range;

/// Keys of each model (besides `model` and `preset`), required ones first.
pub(crate) const EOS_MODELS: [(&str, &[&str]); 5] = [
    (
        "tillotson",
        &[
            "rho0",
            "A",
            "B",
            "a",
            "b",
            "alpha",
            "beta",
            "E0",
            "E_iv",
            "E_cv",
            "sound_speed_floor_fraction",
            "min_pressure",
        ],
    ),
    (
        "mie-gruneisen",
        &["rho0", "c0", "s", "gamma0", "sound_speed_floor_fraction"],
    ),
    (
        "murnaghan",
        &["rho0", "K0", "n", "sound_speed_floor_fraction"],
    ),
    ("linear-elastic", &["rho0", "K0"]),
    ("ideal-gas", &["gamma", "min_sound_speed"]),
];

/// Keys of each strength model (the shear modulus is the material's `shear_modulus`).
pub(crate) const STRENGTH_MODELS: [(&str, &[&str]); 6] = [
    ("none", &[]),
    ("von-mises", &["yield_strength", "hardening_modulus"]),
    (
        "drucker-prager",
        &["cohesion", "friction", "limit_strength", "damaged_friction"],
    ),
    (
        "lundborg",
        &[
            "cohesion",
            "friction",
            "limit_strength",
            "damaged_friction",
            "tension",
        ],
    ),
    (
        "johnson-cook",
        &[
            "a",
            "b",
            "n",
            "c",
            "m",
            "melt_temperature",
            "reference_temperature",
            "reference_strain_rate",
        ],
    ),
    (
        "steinberg-guinan",
        &[
            "pressure_coefficient",
            "temperature_coefficient",
            "yield_strength",
            "max_yield_strength",
            "hardening_coefficient",
            "hardening_exponent",
            "melt_temperature",
            "initial_plastic_strain",
            "reference_density",
            "melt_gamma0",
            "melt_a",
        ],
    ),
];

/// Keys of each damage model.
pub(crate) const DAMAGE_MODELS: [(&str, &[&str]); 3] = [
    ("none", &[]),
    (
        "max-tensile-stress",
        &[
            "sigma_b",
            "failure",
            "crack_speed_fraction",
            "shear_min_strain",
            "shear_pressure_slope",
            "shear_pressure_offset",
        ],
    ),
    (
        "benz-asphaug",
        &[
            "k",
            "m",
            "crack_speed_fraction",
            "growth",
            "tail",
            "strain",
            "form",
            "shear_min_strain",
            "shear_pressure_slope",
            "shear_pressure_offset",
        ],
    ),
];

/// The keys of shear failure (sph_damage::shear_failure), all three or none.
const SHEAR_KEYS: &[&str] = &[
    "shear_min_strain",
    "shear_pressure_slope",
    "shear_pressure_offset",
];

/// Keys of the thermal data.
pub(crate) const THERMAL_KEYS: &[&str] = &["c_v", "T_ref", "T_melt", "L_melt", "T_vap", "L_vap"];

/// The Steinberg–Guinan melt law takes both keys or neither.
const MELT_LAW: &[&str] = &["melt_gamma0 and melt_a together (or neither)"];

/// The text a section came from, for locations.
#[derive(Clone, Copy)]
pub(crate) struct Source<'a> {
    pub(crate) origin: &'a str,
    pub(crate) text: &'a str,
}

/// Context of one section being built: names and places for errors.
pub(crate) struct Cx<'a> {
    pub(crate) material: &'a str,
    pub(crate) section: &'static str,
    pub(crate) source: Option<Source<'a>>,
    /// The `[section]` header.
    pub(crate) header: Option<Range<usize>>,
    /// Where defaults came from (a `preset = ...` or `base = ...` value).
    pub(crate) fallback: Option<Range<usize>>,
}

impl Cx<'_> {
    fn loc(&self, span: Option<&Range<usize>>) -> Option<Box<Location>> {
        let src = self.source?;
        Some(Box::new(
            match span.or(self.fallback.as_ref()).or(self.header.as_ref()) {
                Some(s) => Location::at_offset(src.origin, src.text, s.start),
                None => Location::whole_file(src.origin),
            },
        ))
    }

    fn field(&self, key: &str) -> String {
        format!("{}.{key}", self.section)
    }

    fn model_name<'s>(&self, sec: &'s Section) -> &'s str {
        sec.model.as_deref().unwrap_or("")
    }

    /// "eos model `tillotson`", or "[thermal]" for the one-model section.
    fn context(&self, sec: &Section) -> String {
        match sec.model.as_deref() {
            Some(m) => format!("{} model `{m}`", self.section),
            None => format!("[{}]", self.section),
        }
    }

    fn missing(&self, sec: &Section, key: &str, needs: &[&str]) -> MaterialError {
        MaterialError::Missing {
            material: self.material.to_owned(),
            field: self.field(key),
            needed_by: format!("{} needs {}", self.context(sec), needs.join(", ")),
            location: self.loc(None),
        }
    }

    pub(crate) fn invalid(
        &self,
        sec: &Section,
        key: &str,
        value: f64,
        reason: &str,
    ) -> MaterialError {
        MaterialError::Invalid {
            material: self.material.to_owned(),
            field: self.field(key),
            value,
            reason: reason.to_owned(),
            location: self.loc(sec.get(key).and_then(|p| p.span.as_ref())),
        }
    }

    fn inconsistent(&self, key: &str, reason: String) -> MaterialError {
        MaterialError::Inconsistent {
            material: self.material.to_owned(),
            field: self.field(key),
            reason,
            location: self.loc(None),
        }
    }

    /// The keys of `allowed` the section has, in order; any other key is an error.
    fn check_keys(&self, sec: &Section, allowed: &[&str]) -> Result<(), MaterialError> {
        for p in &sec.params {
            if !allowed.contains(&p.key) {
                return Err(MaterialError::UnexpectedKey {
                    material: self.material.to_owned(),
                    field: self.field(p.key),
                    context: self.context(sec),
                    allowed: allowed.iter().map(|s| s.to_string()).collect(),
                    location: self.loc(p.span.as_ref()),
                });
            }
        }
        Ok(())
    }

    fn num(&self, sec: &Section, key: &str) -> Result<Option<f64>, MaterialError> {
        match sec.get(key) {
            None => Ok(None),
            Some(p) => match &p.value {
                Value::Num(v) => Ok(Some(*v)),
                Value::Str(s) => Err(MaterialError::WrongType {
                    material: self.material.to_owned(),
                    field: self.field(key),
                    expected: "a number",
                    found: format!("the string \"{s}\""),
                    location: self.loc(p.span.as_ref()),
                }),
            },
        }
    }

    fn req(&self, sec: &Section, key: &str, needs: &[&str]) -> Result<f64, MaterialError> {
        self.num(sec, key)?
            .ok_or_else(|| self.missing(sec, key, needs))
    }

    /// An option given by name, looked up in `table`.
    fn option<T: Copy>(
        &self,
        sec: &Section,
        key: &str,
        table: &[(&'static str, T)],
    ) -> Result<Option<T>, MaterialError> {
        let Some(p) = sec.get(key) else {
            return Ok(None);
        };
        let known = || table.iter().map(|(n, _)| n.to_string()).collect::<Vec<_>>();
        match &p.value {
            Value::Str(s) => match table.iter().find(|(n, _)| n == s) {
                Some((_, v)) => Ok(Some(*v)),
                None => Err(MaterialError::UnknownName {
                    material: self.material.to_owned(),
                    field: self.field(key),
                    name: s.clone(),
                    known: known(),
                    location: self.loc(p.span.as_ref()),
                }),
            },
            Value::Num(v) => Err(MaterialError::WrongType {
                material: self.material.to_owned(),
                field: self.field(key),
                expected: "a name",
                found: format!("the number {v}"),
                location: self.loc(p.span.as_ref()),
            }),
        }
    }

    fn unknown_model(&self, sec: &Section, known: &[&str]) -> MaterialError {
        MaterialError::UnknownName {
            material: self.material.to_owned(),
            field: self.field("model"),
            name: self.model_name(sec).to_owned(),
            known: known.iter().map(|s| s.to_string()).collect(),
            location: self.loc(sec.model_span.as_ref()),
        }
    }

    fn eos_error(&self, sec: &Section, e: EosError) -> MaterialError {
        match e {
            EosError::Parameter {
                field,
                value,
                reason,
            } => {
                let key = if field == "P_min" {
                    "min_pressure"
                } else {
                    field
                };
                self.invalid(sec, key, value, reason)
            }
            other => self.inconsistent("model", other.to_string()),
        }
    }

    fn strength_error(&self, sec: &Section, e: StrengthError) -> MaterialError {
        match e {
            StrengthError::Parameter {
                field,
                value,
                reason,
                ..
            } => {
                if field == "shear_modulus" {
                    // The material-level value (located by the reader).
                    return MaterialError::Invalid {
                        material: self.material.to_owned(),
                        field: "shear_modulus".into(),
                        value,
                        reason: reason.to_owned(),
                        location: None,
                    };
                }
                let key = match field {
                    "hardening.modulus" => "hardening_modulus",
                    "melt_law.gamma0" => "melt_gamma0",
                    "melt_law.a" => "melt_a",
                    f => f,
                };
                self.invalid(sec, key, value, reason)
            }
            other => self.inconsistent("model", other.to_string()),
        }
    }

    fn damage_error(&self, sec: &Section, e: DamageError) -> MaterialError {
        match e {
            DamageError::Parameter {
                field,
                value,
                reason,
            } => self.invalid(sec, field, value, reason),
            other => self.inconsistent("model", other.to_string()),
        }
    }
}

fn keys_of<'t>(table: &'t [(&str, &'t [&'t str])], model: &str) -> Option<&'t [&'t str]> {
    table.iter().find(|(m, _)| *m == model).map(|(_, k)| *k)
}

fn names(table: &[(&'static str, &[&str])]) -> Vec<&'static str> {
    table.iter().map(|(m, _)| *m).collect()
}

/// The EOS of a section; `rho0` defaults to the material density.
pub(crate) fn build_eos(sec: &Section, cx: &Cx, density: f64) -> Result<EosChoice, MaterialError> {
    let model = cx.model_name(sec);
    let Some(keys) = keys_of(&EOS_MODELS, model) else {
        return Err(cx.unknown_model(sec, &names(&EOS_MODELS)));
    };
    cx.check_keys(sec, keys)?;
    let e = |err| cx.eos_error(sec, err);
    let rho0 = cx.num(sec, "rho0")?.unwrap_or(density);
    let floor = cx.num(sec, "sound_speed_floor_fraction")?;
    Ok(match model {
        "tillotson" => {
            let need = &keys[1..10];
            let r = |k| cx.req(sec, k, need);
            let mut t = Tillotson::new(TillotsonParams {
                rho0,
                A: r("A")?,
                B: r("B")?,
                a: r("a")?,
                b: r("b")?,
                alpha: r("alpha")?,
                beta: r("beta")?,
                E0: r("E0")?,
                E_iv: r("E_iv")?,
                E_cv: r("E_cv")?,
            })
            .map_err(e)?;
            if let Some(f) = floor {
                t = t.with_sound_speed_floor_fraction(f).map_err(e)?;
            }
            if let Some(p_min) = cx.num(sec, "min_pressure")? {
                t = t.with_min_pressure(p_min).map_err(e)?;
            }
            EosChoice::Tillotson(t)
        }
        "mie-gruneisen" => {
            let need = &keys[1..4];
            let r = |k| cx.req(sec, k, need);
            let mut m = MieGruneisen::new(MieGruneisenParams {
                rho0,
                c0: r("c0")?,
                s: r("s")?,
                gamma0: r("gamma0")?,
            })
            .map_err(e)?;
            if let Some(f) = floor {
                m = m.with_sound_speed_floor_fraction(f).map_err(e)?;
            }
            EosChoice::MieGruneisen(m)
        }
        "murnaghan" => {
            let need = &keys[1..3];
            let r = |k| cx.req(sec, k, need);
            let mut m = Murnaghan::new(MurnaghanParams {
                rho0,
                K0: r("K0")?,
                n: r("n")?,
            })
            .map_err(e)?;
            if let Some(f) = floor {
                m = m.with_sound_speed_floor_fraction(f).map_err(e)?;
            }
            EosChoice::Murnaghan(m)
        }
        "linear-elastic" => EosChoice::LinearElastic(
            LinearElastic::new(LinearElasticParams {
                rho0,
                K0: cx.req(sec, "K0", &keys[1..2])?,
            })
            .map_err(e)?,
        ),
        _ => {
            // "ideal-gas"
            let mut g = IdealGas::new(IdealGasParams {
                gamma: cx.req(sec, "gamma", &keys[..1])?,
            })
            .map_err(e)?;
            if let Some(c) = cx.num(sec, "min_sound_speed")? {
                g = g.with_min_sound_speed(c).map_err(e)?;
            }
            EosChoice::IdealGas(g)
        }
    })
}

/// The strength model of a section, using the material's shear modulus G and density.
pub(crate) fn build_strength(
    sec: &Section,
    cx: &Cx,
    shear_modulus: f64,
    density: f64,
) -> Result<StrengthChoice, MaterialError> {
    let model = cx.model_name(sec);
    let Some(keys) = keys_of(&STRENGTH_MODELS, model) else {
        return Err(cx.unknown_model(sec, &names(&STRENGTH_MODELS)));
    };
    cx.check_keys(sec, keys)?;
    let s = |err| cx.strength_error(sec, err);
    let b = match model {
        "none" => BuiltinStrength::None,
        "von-mises" => BuiltinStrength::VonMises(
            VonMises::new(VonMisesParams {
                yield_strength: cx.req(sec, "yield_strength", &keys[..1])?,
                shear_modulus,
                hardening: cx
                    .num(sec, "hardening_modulus")?
                    .map(|modulus| LinearHardening { modulus }),
            })
            .map_err(s)?,
        ),
        "drucker-prager" | "lundborg" => {
            let need = &keys[..4];
            let r = |k| cx.req(sec, k, need);
            let (cohesion, friction, limit_strength, damaged_friction) = (
                r("cohesion")?,
                r("friction")?,
                r("limit_strength")?,
                r("damaged_friction")?,
            );
            if model == "lundborg" {
                BuiltinStrength::Lundborg(
                    Lundborg::new(LundborgParams {
                        cohesion,
                        friction,
                        limit_strength,
                        damaged_friction,
                        shear_modulus,
                        tension: cx
                            .option(sec, "tension", &LUNDBORG_TENSIONS)?
                            .unwrap_or(LundborgTension::default()),
                    })
                    .map_err(s)?,
                )
            } else {
                BuiltinStrength::DruckerPrager(
                    DruckerPrager::new(DruckerPragerParams {
                        cohesion,
                        friction,
                        limit_strength,
                        damaged_friction,
                        shear_modulus,
                    })
                    .map_err(s)?,
                )
            }
        }
        "johnson-cook" => {
            let need = &keys[..7];
            let r = |k| cx.req(sec, k, need);
            BuiltinStrength::JohnsonCook(
                JohnsonCook::new(JohnsonCookParams {
                    a: r("a")?,
                    b: r("b")?,
                    n: r("n")?,
                    c: r("c")?,
                    m: r("m")?,
                    melt_temperature: r("melt_temperature")?,
                    reference_temperature: r("reference_temperature")?,
                    reference_strain_rate: cx.num(sec, "reference_strain_rate")?.unwrap_or(1.0),
                    shear_modulus,
                })
                .map_err(s)?,
            )
        }
        _ => {
            // "steinberg-guinan"
            let need = &keys[..7];
            let r = |k| cx.req(sec, k, need);
            let melt_law = match (cx.num(sec, "melt_gamma0")?, cx.num(sec, "melt_a")?) {
                (Some(gamma0), Some(a)) => Some(SgMeltLaw { gamma0, a }),
                (None, None) => None,
                (Some(_), None) => return Err(cx.missing(sec, "melt_a", MELT_LAW)),
                (None, Some(_)) => return Err(cx.missing(sec, "melt_gamma0", MELT_LAW)),
            };
            BuiltinStrength::SteinbergGuinan(
                SteinbergGuinan::new(SteinbergGuinanParams {
                    shear_modulus,
                    pressure_coefficient: r("pressure_coefficient")?,
                    temperature_coefficient: r("temperature_coefficient")?,
                    yield_strength: r("yield_strength")?,
                    max_yield_strength: r("max_yield_strength")?,
                    hardening_coefficient: r("hardening_coefficient")?,
                    hardening_exponent: r("hardening_exponent")?,
                    initial_plastic_strain: cx.num(sec, "initial_plastic_strain")?.unwrap_or(0.0),
                    reference_density: cx.num(sec, "reference_density")?.unwrap_or(density),
                    melt_temperature: r("melt_temperature")?,
                    melt_law,
                })
                .map_err(s)?,
            )
        }
    };
    Ok(StrengthChoice::Builtin(b))
}

/// The damage specification of a section.
pub(crate) fn build_damage(sec: &Section, cx: &Cx) -> Result<DamageSpec, MaterialError> {
    let model = cx.model_name(sec);
    let Some(keys) = keys_of(&DAMAGE_MODELS, model) else {
        return Err(cx.unknown_model(sec, &names(&DAMAGE_MODELS)));
    };
    cx.check_keys(sec, keys)?;
    let fraction = cx
        .num(sec, "crack_speed_fraction")?
        .unwrap_or(CRACK_SPEED_FRACTION_BA94);
    let shear = build_shear_failure(sec, cx)?;
    let spec = match model {
        "none" => DamageSpec::None,
        "max-tensile-stress" => DamageSpec::MaxTensileStress {
            sigma_b: cx.req(sec, "sigma_b", &keys[..1])?,
            failure: cx
                .option(sec, "failure", &TENSILE_FAILURES)?
                .unwrap_or(TensileFailure::default()),
            crack_speed_fraction: fraction,
            shear,
        },
        _ => DamageSpec::BenzAsphaug {
            k: cx.req(sec, "k", &keys[..2])?,
            m: cx.req(sec, "m", &keys[..2])?,
            crack_speed_fraction: fraction,
            growth: cx
                .option(sec, "growth", &GROWTH_LAWS)?
                .unwrap_or(GrowthLaw::default()),
            tail: cx
                .option(sec, "tail", &FLAW_TAILS)?
                .unwrap_or(FlawTail::default()),
            strain: cx
                .option(sec, "strain", &ACTIVATION_STRAINS)?
                .unwrap_or(ActivationStrain::default()),
            form: cx
                .option(sec, "form", &DAMAGE_FORMS)?
                .unwrap_or(DamageForm::default()),
            shear,
        },
    };
    spec.validate().map_err(|e| cx.damage_error(sec, e))?;
    Ok(spec)
}

/// Shear failure from the section's `shear_*` keys: none without them, all three
/// needed once one is given; each value checked by sph-damage, the error naming its key.
fn build_shear_failure(sec: &Section, cx: &Cx) -> Result<Option<PlasticFailure>, MaterialError> {
    if SHEAR_KEYS.iter().all(|k| sec.get(k).is_none()) {
        return Ok(None);
    }
    let r = |k| cx.req(sec, k, SHEAR_KEYS);
    let (eps, slope, offset) = (
        r("shear_min_strain")?,
        r("shear_pressure_slope")?,
        r("shear_pressure_offset")?,
    );
    PlasticFailure::new(eps, slope, offset)
        .map(Some)
        .map_err(|e| match e {
            DamageError::Parameter {
                field,
                value,
                reason,
            } => {
                let key = match field {
                    "min_strain" => "shear_min_strain",
                    "pressure_slope" => "shear_pressure_slope",
                    _ => "shear_pressure_offset",
                };
                cx.invalid(sec, key, value, reason)
            }
            other => cx.damage_error(sec, other),
        })
}

/// The thermal model of a section.
pub(crate) fn build_thermal(sec: &Section, cx: &Cx) -> Result<ThermalModel, MaterialError> {
    cx.check_keys(sec, THERMAL_KEYS)?;
    let r = |k| cx.req(sec, k, THERMAL_KEYS);
    ThermalModel::new(ThermalParams {
        c_v: r("c_v")?,
        T_ref: r("T_ref")?,
        T_melt: r("T_melt")?,
        L_melt: r("L_melt")?,
        T_vap: r("T_vap")?,
        L_vap: r("L_vap")?,
    })
    .map_err(|e| cx.eos_error(sec, e))
}

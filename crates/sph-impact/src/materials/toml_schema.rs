//! The shape of a material file for serde: every table rejects unknown keys
//! (`deny_unknown_fields`, so a misspelt key is an error naming it and the line), and every
//! value keeps its byte span so later checks can name the line too. A section table holds
//! the union of its models' keys; which keys a model takes is checked in `build.rs`.

use serde::Deserialize;
use serde::de::{self, Deserializer, Visitor};
use std::fmt;
use toml::Spanned;

/// A value as written: a number (a TOML integer is taken as a float), a name, or a
/// boolean (which no parameter takes; kept to report it precisely).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Scalar {
    Num(f64),
    Str(String),
    Bool(bool),
}

impl<'de> Deserialize<'de> for Scalar {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct ScalarVisitor;
        impl Visitor<'_> for ScalarVisitor {
            type Value = Scalar;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or a name")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Scalar, E> {
                Ok(Scalar::Num(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Scalar, E> {
                Ok(Scalar::Num(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Scalar, E> {
                Ok(Scalar::Num(v as f64))
            }
            fn visit_bool<E: de::Error>(self, v: bool) -> Result<Scalar, E> {
                Ok(Scalar::Bool(v))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Scalar, E> {
                Ok(Scalar::Str(v.to_owned()))
            }
        }
        d.deserialize_any(ScalarVisitor)
    }
}

/// A section table: its keys as optional spanned scalars, and the present ones as a list.
macro_rules! section_table {
    ($(#[$meta:meta])* $name:ident { $($field:ident => $key:literal),* $(,)? }) => {
        $(#[$meta])*
        #[derive(Debug, Default, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub(crate) struct $name {
            $(
                #[serde(rename = $key)]
                $field: Option<Spanned<Scalar>>,
            )*
        }

        impl $name {
            /// The keys present, in file order.
            pub(crate) fn into_entries(self) -> Vec<(&'static str, Spanned<Scalar>)> {
                let mut v = Vec::new();
                $( if let Some(s) = self.$field { v.push(($key, s)); } )*
                v.sort_by_key(|(_, s)| s.span().start);
                v
            }
        }
    };
}

section_table!(
    /// `[eos]`: `model` or `preset`, and the parameters of every EOS model.
    EosTable {
        model => "model",
        preset => "preset",
        rho0 => "rho0",
        cap_a => "A",
        cap_b => "B",
        a => "a",
        b => "b",
        alpha => "alpha",
        beta => "beta",
        e0 => "E0",
        e_iv => "E_iv",
        e_cv => "E_cv",
        floor => "sound_speed_floor_fraction",
        min_pressure => "min_pressure",
        c0 => "c0",
        s => "s",
        gamma0 => "gamma0",
        k0 => "K0",
        n => "n",
        gamma => "gamma",
        min_sound_speed => "min_sound_speed",
    }
);

section_table!(
    /// `[strength]`: `model` or `preset`, and the parameters of every strength model.
    StrengthTable {
        model => "model",
        preset => "preset",
        yield_strength => "yield_strength",
        hardening_modulus => "hardening_modulus",
        cohesion => "cohesion",
        friction => "friction",
        limit_strength => "limit_strength",
        damaged_friction => "damaged_friction",
        tension => "tension",
        a => "a",
        b => "b",
        n => "n",
        c => "c",
        m => "m",
        melt_temperature => "melt_temperature",
        reference_temperature => "reference_temperature",
        reference_strain_rate => "reference_strain_rate",
        pressure_coefficient => "pressure_coefficient",
        temperature_coefficient => "temperature_coefficient",
        max_yield_strength => "max_yield_strength",
        hardening_coefficient => "hardening_coefficient",
        hardening_exponent => "hardening_exponent",
        initial_plastic_strain => "initial_plastic_strain",
        reference_density => "reference_density",
        melt_gamma0 => "melt_gamma0",
        melt_a => "melt_a",
    }
);

section_table!(
    /// `[damage]`: `model` or `preset`, and the parameters of every damage model.
    DamageTable {
        model => "model",
        preset => "preset",
        sigma_b => "sigma_b",
        failure => "failure",
        crack_speed_fraction => "crack_speed_fraction",
        k => "k",
        m => "m",
        growth => "growth",
        tail => "tail",
        strain => "strain",
        form => "form",
        shear_min_strain => "shear_min_strain",
        shear_pressure_slope => "shear_pressure_slope",
        shear_pressure_offset => "shear_pressure_offset",
    }
);

section_table!(
    /// `[thermal]`: `preset` and/or the six caloric parameters.
    ThermalTable {
        preset => "preset",
        c_v => "c_v",
        t_ref => "T_ref",
        t_melt => "T_melt",
        l_melt => "L_melt",
        t_vap => "T_vap",
        l_vap => "L_vap",
    }
);

/// A whole material file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct MaterialFile {
    pub(crate) name: Option<Spanned<String>>,
    pub(crate) base: Option<Spanned<String>>,
    pub(crate) density: Option<Spanned<Scalar>>,
    pub(crate) shear_modulus: Option<Spanned<Scalar>>,
    pub(crate) sources: Option<Vec<String>>,
    pub(crate) eos: Option<Spanned<EosTable>>,
    pub(crate) strength: Option<Spanned<StrengthTable>>,
    pub(crate) damage: Option<Spanned<DamageTable>>,
    pub(crate) thermal: Option<Spanned<ThermalTable>>,
}

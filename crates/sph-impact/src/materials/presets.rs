//! Named parameter sets a material file can start a section from (`preset = "..."`),
//! taken from the model crates' named sets and [`crate::materials::parameter_sets`].

use crate::materials::damage_spec::DamageSpec;
use crate::materials::eos_choice::EosChoice;
use crate::materials::parameter_sets::{
    ARMCO_IRON_JC, GRANITE_WEIBULL_K, GRANITE_WEIBULL_M, ICE_BA99_VON_MISES, THERMAL_COPPER,
    THERMAL_IRON, tillotson_copper,
};
use crate::materials::sections::{
    Section, damage_section, eos_section, strength_section, thermal_section,
};
use crate::materials::strength_choice::StrengthChoice;
use sph_damage::WeibullParams;
use sph_eos::{MieGruneisen, MieGruneisenParams, ThermalModel, Tillotson, TillotsonParams};
use sph_strength::{JohnsonCook, Lundborg, SteinbergGuinan, VonMises, materials as strength_sets};

/// Every named set is valid (tested through the presets test).
const VALID: &str = "named parameter set is valid (tested)";

/// The sections a preset can fill.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PresetKind {
    /// `[eos]`.
    Eos,
    /// `[strength]`.
    Strength,
    /// `[damage]`.
    Damage,
    /// `[thermal]`.
    Thermal,
}

impl PresetKind {
    /// The section name in a material file.
    pub fn section(self) -> &'static str {
        match self {
            Self::Eos => "eos",
            Self::Strength => "strength",
            Self::Damage => "damage",
            Self::Thermal => "thermal",
        }
    }
}

/// The presets of one section, by name.
pub(crate) fn presets(kind: PresetKind) -> Vec<(String, Section)> {
    match kind {
        PresetKind::Eos => {
            let mut v: Vec<(String, Section)> = TillotsonParams::named()
                .into_iter()
                .map(|(name, p)| (name.replace('_', "-"), eos(Tillotson::new(p).expect(VALID))))
                .collect();
            v.push((
                "copper".into(),
                eos(Tillotson::new(tillotson_copper()).expect(VALID)),
            ));
            v.push((
                "aluminium-6061".into(),
                eos(MieGruneisen::new(MieGruneisenParams::aluminium_6061()).expect(VALID)),
            ));
            v
        }
        PresetKind::Strength => vec![
            (
                "basalt-study".into(),
                strength(Lundborg::new(strength_sets::BASALT_LUNDBORG)),
            ),
            (
                "granite-collins2004".into(),
                strength(Lundborg::new(strength_sets::GRANITE_LUNDBORG_COLLINS2004)),
            ),
            (
                "aluminium-2024-jc".into(),
                strength(JohnsonCook::new(strength_sets::ALUMINIUM_2024_JC_MEASURED)),
            ),
            (
                "aluminium-2024-jc-earlier".into(),
                strength(JohnsonCook::new(strength_sets::ALUMINIUM_2024_JC_EARLIER)),
            ),
            (
                "aluminium-2024-sg".into(),
                strength(SteinbergGuinan::new(strength_sets::ALUMINIUM_2024_SG)),
            ),
            (
                "ofhc-copper-jc".into(),
                strength(JohnsonCook::new(strength_sets::OFHC_COPPER_JC)),
            ),
            (
                "al-6061-t6-jc".into(),
                strength(JohnsonCook::new(strength_sets::AL_6061_T6_JC)),
            ),
            (
                "copper-sg".into(),
                strength(SteinbergGuinan::new(strength_sets::COPPER_SG)),
            ),
            (
                "copper-sg-taylor-fit".into(),
                strength(SteinbergGuinan::new(strength_sets::COPPER_SG_TAYLOR_FIT)),
            ),
            (
                "taylor-bar-copper".into(),
                strength(VonMises::new(strength_sets::TAYLOR_BAR_COPPER)),
            ),
            (
                "armco-iron-jc".into(),
                strength(JohnsonCook::new(ARMCO_IRON_JC)),
            ),
            (
                "ice-ba99".into(),
                strength(VonMises::new(ICE_BA99_VON_MISES)),
            ),
        ],
        PresetKind::Damage => {
            let mut v: Vec<(String, Section)> = WeibullParams::NAMED
                .iter()
                .map(|n| {
                    (
                        n.name.to_owned(),
                        damage_section(&DamageSpec::benz_asphaug_weibull(n.params))
                            .expect("a built-in model"),
                    )
                })
                .collect();
            v.push((
                "granite-spheral".into(),
                damage_section(&DamageSpec::benz_asphaug(
                    GRANITE_WEIBULL_K,
                    GRANITE_WEIBULL_M,
                ))
                .expect("a built-in model"),
            ));
            v.push((
                "aluminium-2024-study".into(),
                damage_section(&DamageSpec::max_tensile_stress(2500.0e6))
                    .expect("a built-in model"),
            ));
            v
        }
        PresetKind::Thermal => vec![
            (
                "aluminium".into(),
                thermal_section(&ThermalModel::aluminium()),
            ),
            ("basalt".into(), thermal_section(&ThermalModel::basalt())),
            (
                "iron".into(),
                thermal_section(&ThermalModel::new(THERMAL_IRON).expect(VALID)),
            ),
            (
                "copper".into(),
                thermal_section(&ThermalModel::new(THERMAL_COPPER).expect(VALID)),
            ),
        ],
    }
}

/// Names of the presets of one section.
pub fn preset_names(kind: PresetKind) -> Vec<String> {
    presets(kind).into_iter().map(|(n, _)| n).collect()
}

fn eos(e: impl Into<EosChoice>) -> Section {
    eos_section(&e.into()).expect("built-in EOS has parameters")
}

fn strength<M: Into<StrengthChoice>, E: std::fmt::Debug>(m: Result<M, E>) -> Section {
    strength_section(&m.expect(VALID).into()).expect("built-in strength has parameters")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::build::{Cx, build_damage, build_eos, build_strength, build_thermal};
    use crate::materials::sections::Value;

    fn cx(section: &'static str) -> Cx<'static> {
        Cx {
            material: "preset",
            section,
            source: None,
            header: None,
            fallback: None,
        }
    }

    /// Every preset builds into a model whose parameters read back to the preset.
    #[test]
    fn every_preset_builds() {
        for (name, sec) in presets(PresetKind::Eos) {
            let rho0 = match sec.get("rho0").map(|p| &p.value) {
                Some(Value::Num(r)) => *r,
                _ => panic!("{name}: no rho0"),
            };
            let eos = build_eos(&sec, &cx("eos"), rho0).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(eos_section(&eos).unwrap(), sec, "{name}");
        }
        for (name, sec) in presets(PresetKind::Strength) {
            let s = build_strength(&sec, &cx("strength"), 1.0e10, 1000.0)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(strength_section(&s).unwrap(), sec, "{name}");
        }
        for (name, sec) in presets(PresetKind::Damage) {
            let d = build_damage(&sec, &cx("damage")).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(damage_section(&d).unwrap(), sec, "{name}");
        }
        for (name, sec) in presets(PresetKind::Thermal) {
            let t = build_thermal(&sec, &cx("thermal")).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(thermal_section(&t), sec, "{name}");
        }
    }
}

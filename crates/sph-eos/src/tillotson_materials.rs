//! Named Tillotson parameter sets, each with its source.
//!
//! The literature sets are those of docs/reference/tillotson.md, "Parameters (SI)" (taken from
//! miluphcuda's `material_data/*.till.cfg`, which cite Benz & Asphaug 1999, Melosh 1989 and
//! Tillotson 1962, and cross-checked with Spheral's MaterialPropertiesLib in CGS). The
//! "study" sets are Table A1 of the reference study with its Table 1 densities (paper §3.1).
//! Variants in circulation (docs/reference/tillotson.md, "Parameters (SI)") are *not* these:
//! e.g. Spheral's "aluminum" has E_iv = 2.7, E_cv = 14.1 MJ/kg, its "basalt" ρ0 = 2900 kg/m³.

use crate::tillotson::TillotsonParams;

impl TillotsonParams {
    /// Basalt of the reference study: Table A1 (A = B = 26.7 GPa, a = 0.5, b = 1.5,
    /// α = β = 5, E0 = 487 MJ/kg, E_iv = 4.72 MJ/kg, E_cv = 18.2 MJ/kg) with the target
    /// density of its Table 1, ρ0 = 2876 kg/m³ (paper §3.1, §6).
    pub fn basalt_study() -> Self {
        Self {
            rho0: 2876.0,
            ..Self::basalt_ba99()
        }
    }

    /// Aluminium of the reference study: Table A1 (A = 75.2 GPa, B = 65 GPa, a = 0.5,
    /// b = 1.63, α = β = 5, E0 = 5 MJ/kg, E_iv = 3 MJ/kg, **E_cv = 15 MJ/kg**) with the
    /// projectile density of its Table 1 (Al 2024), ρ0 = 2785 kg/m³ (paper §3.1, §6).
    pub fn aluminium_study() -> Self {
        Self {
            rho0: 2785.0,
            E_cv: 1.5e7,
            ..Self::aluminium_melosh89()
        }
    }

    /// Basalt, Benz & Asphaug (1999), "Catastrophic disruptions revisited", Icarus 142:5
    /// (their Tillotson table; also miluphcuda `basalt.till.cfg`): ρ0 = 2700 kg/m³,
    /// A = B = 26.7 GPa, E0 = 487 MJ/kg, E_iv = 4.72 MJ/kg, E_cv = 18.2 MJ/kg, a = 0.5,
    /// b = 1.5, α = β = 5. The set of the check points of docs/reference/tillotson.md.
    pub fn basalt_ba99() -> Self {
        Self {
            rho0: 2700.0,
            A: 26.7e9,
            B: 26.7e9,
            a: 0.5,
            b: 1.5,
            alpha: 5.0,
            beta: 5.0,
            E0: 487e6,
            E_iv: 4.72e6,
            E_cv: 18.2e6,
        }
    }

    /// Aluminium, Tillotson (1962) as tabulated by Melosh (1989), *Impact Cratering*,
    /// Table AII.3 (miluphcuda / Spheral "aluminum melosh89"): ρ0 = 2700 kg/m³,
    /// A = 75.2 GPa, B = 65.0 GPa, E0 = 5.0 MJ/kg, E_iv = 3.0 MJ/kg, E_cv = 13.9 MJ/kg,
    /// a = 0.5, b = 1.63, α = β = 5. The set of the check points of
    /// docs/reference/tillotson.md.
    pub fn aluminium_melosh89() -> Self {
        Self {
            rho0: 2700.0,
            A: 75.2e9,
            B: 65.0e9,
            a: 0.5,
            b: 1.63,
            alpha: 5.0,
            beta: 5.0,
            E0: 5.0e6,
            E_iv: 3.0e6,
            E_cv: 13.9e6,
        }
    }

    /// Granite, Allen (1967), as tabulated in docs/reference/tillotson.md: ρ0 = 2680 kg/m³,
    /// A = B = 18 GPa, E0 = 16 MJ/kg, E_iv = 3.5 MJ/kg, E_cv = 18 MJ/kg, a = 0.5, b = 1.3,
    /// α = β = 5.
    pub fn granite() -> Self {
        Self {
            rho0: 2680.0,
            A: 18e9,
            B: 18e9,
            a: 0.5,
            b: 1.3,
            alpha: 5.0,
            beta: 5.0,
            E0: 16e6,
            E_iv: 3.5e6,
            E_cv: 18e6,
        }
    }

    /// Iron, Melosh (1989), *Impact Cratering*, Table AII.3: ρ0 = 7800 kg/m³,
    /// A = 128 GPa, B = 105 GPa, E0 = 9.5 MJ/kg, E_iv = 2.4 MJ/kg, E_cv = 8.67 MJ/kg,
    /// a = 0.5, b = 1.5, α = β = 5.
    pub fn iron() -> Self {
        Self {
            rho0: 7800.0,
            A: 128e9,
            B: 105e9,
            a: 0.5,
            b: 1.5,
            alpha: 5.0,
            beta: 5.0,
            E0: 9.5e6,
            E_iv: 2.4e6,
            E_cv: 8.67e6,
        }
    }

    /// Water ice, Benz & Asphaug (1999), Icarus 142:5: ρ0 = 917 kg/m³, A = B = 9.47 GPa,
    /// E0 = 10 MJ/kg, E_iv = 0.773 MJ/kg, E_cv = 3.04 MJ/kg, a = 0.3, b = 0.1, α = 10,
    /// β = 5.
    pub fn ice() -> Self {
        Self {
            rho0: 917.0,
            A: 9.47e9,
            B: 9.47e9,
            a: 0.3,
            b: 0.1,
            alpha: 10.0,
            beta: 5.0,
            E0: 10e6,
            E_iv: 0.773e6,
            E_cv: 3.04e6,
        }
    }

    /// Every named set with its constructor's name, for tests and tables.
    pub fn named() -> [(&'static str, Self); 7] {
        [
            ("basalt_study", Self::basalt_study()),
            ("aluminium_study", Self::aluminium_study()),
            ("basalt_ba99", Self::basalt_ba99()),
            ("aluminium_melosh89", Self::aluminium_melosh89()),
            ("granite", Self::granite()),
            ("iron", Self::iron()),
            ("ice", Self::ice()),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_named_set_is_valid() {
        for (name, p) in TillotsonParams::named() {
            assert!(p.validate().is_ok(), "{name}");
        }
    }

    /// docs/reference/tillotson.md, "Check points": c0 = √(A/ρ0) = 3144.7 (basalt), 5277.5
    /// (Al), 2591.6 (granite), 4051.0 (iron), 3213.6 m/s (ice), to the printed 0.1 m/s.
    #[test]
    fn reference_sound_speeds() {
        for (p, c0) in [
            (TillotsonParams::basalt_ba99(), 3144.7),
            (TillotsonParams::aluminium_melosh89(), 5277.5),
            (TillotsonParams::granite(), 2591.6),
            (TillotsonParams::iron(), 4051.0),
            (TillotsonParams::ice(), 3213.6),
        ] {
            assert!((p.reference_sound_speed() - c0).abs() <= 0.05, "{c0}");
        }
    }
}

//! Handbook thermal data for the study's materials (paper §3.1: "take them from standard
//! handbooks and cite the source"). Each value says where it comes from and how sure it is.

use crate::thermal::{ThermalModel, ThermalParams};

impl ThermalParams {
    /// Aluminium (pure Al data; the study's projectile is Al 2024).
    ///
    /// - c_v = 897 J/kg/K: c_p of Al at 298 K, 24.20 J/mol/K ÷ 26.98 g/mol (CRC Handbook
    ///   of Chemistry and Physics; solids: c_v ≈ c_p). The true c_p rises to ~1.2 kJ/kg/K
    ///   near the melt, so this constant *underestimates* the energy to reach T_melt.
    /// - T_ref = 300 K: the study's reference temperature T_r (Table A2).
    /// - T_melt = 933.47 K: freezing point of Al, an ITS-90 fixed point (660.323 °C). The
    ///   study's Johnson–Cook T_m = 935 K (Table A2) agrees. Al 2024 melts over a range
    ///   instead, solidus ≈ 775 K (502 °C) to liquidus ≈ 911 K (638 °C) (ASM / MatWeb
    ///   2024-T3 data); pure Al is chosen to stay consistent with the study's T_m.
    /// - L_melt = 3.97e5 J/kg: ΔH_fus = 10.71 kJ/mol (CRC) ÷ 26.98 g/mol.
    /// - T_vap = 2792 K: normal boiling point, 2519 °C (CRC; JANAF/NIST gives 2790.8 K).
    /// - L_vap = 1.09e7 J/kg: ΔH_vap = 294.0 kJ/mol at the boiling point (CRC) ÷
    ///   26.98 g/mol. Other tabulations give 290.8–293.4 kJ/mol (1.08e7) and Engineering
    ///   ToolBox 2500 kcal/kg (1.05e7): uncertain by ~4 %.
    ///
    /// Thresholds: melting 0.568–0.965 MJ/kg, vaporisation 2.63–13.5 MJ/kg.
    pub fn aluminium() -> Self {
        Self {
            c_v: 897.0,
            T_ref: 300.0,
            T_melt: 933.47,
            L_melt: 3.97e5,
            T_vap: 2792.0,
            L_vap: 1.09e7,
        }
    }

    /// Basalt. Rock has no single melting or boiling point; these are representative
    /// values, **less certain than the aluminium ones**:
    ///
    /// - c_v = 840 J/kg/K: the usual room-temperature handbook value for basalt
    ///   (Robertson 1988, USGS Open-File Report 88-441, lists ~0.8–0.9 kJ/kg/K); ±10 %,
    ///   and it rises with temperature.
    /// - T_ref = 300 K (as for the projectile).
    /// - T_melt = 1473 K (1200 °C): the upper end of basalt's 1-atm melting interval
    ///   (≈ 1000–1200 °C); uncertain by ~±100 K.
    /// - L_melt = 4.0e5 J/kg: Bouhifd et al. (2007), Contrib. Mineral. Petrol. 153:689,
    ///   measured the enthalpy of fusion of a basalt rising from 15.4 kJ/mol at 1000 K to
    ///   33.6 kJ/mol at 1800 K (per mole of oxide components); ≈ 25 kJ/mol near 1450 K with
    ///   a mean oxide molar mass ≈ 62 g/mol gives ≈ 4.0e5 J/kg (this conversion is ours,
    ///   ±25 %).
    /// - T_vap = 2900 K, L_vap = 1.1e7 J/kg: **no handbook value found** (silicates
    ///   vaporise incongruently, with no single boiling point). Order-of-magnitude
    ///   estimates only, of the size of Tillotson basalt's E_cv − E_iv = 13.5 MJ/kg
    ///   (Benz & Asphaug 1999); replace them when a sourced value is available.
    ///
    /// Thresholds: melting 0.985–1.385 MJ/kg, vaporisation 2.58–13.6 MJ/kg.
    pub fn basalt() -> Self {
        Self {
            c_v: 840.0,
            T_ref: 300.0,
            T_melt: 1473.0,
            L_melt: 4.0e5,
            T_vap: 2900.0,
            L_vap: 1.1e7,
        }
    }
}

impl ThermalModel {
    /// Aluminium, [`ThermalParams::aluminium`].
    pub fn aluminium() -> Self {
        Self::from_valid(ThermalParams::aluminium())
    }

    /// Basalt, [`ThermalParams::basalt`].
    pub fn basalt() -> Self {
        Self::from_valid(ThermalParams::basalt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn named_sets_are_valid_and_match() {
        for (p, m) in [
            (ThermalParams::aluminium(), ThermalModel::aluminium()),
            (ThermalParams::basalt(), ThermalModel::basalt()),
        ] {
            assert_eq!(ThermalModel::new(p).unwrap(), m);
        }
    }
}

//! Parameter sets the library's materials need that the model crates do not carry (yet),
//! each with its source. Candidates for sph-eos / sph-strength.

use sph_eos::{ThermalParams, TillotsonParams};
use sph_strength::{JohnsonCookParams, VonMisesParams};

/// Copper, Tillotson (1962) as listed in LLNL Spheral's `MaterialPropertiesLib.py`
/// ("copper", CGS: ρ0 = 8.9 g/cm³, A = 1.39 Mbar, B = 1.10 Mbar, a = 0.5, b = 1.5,
/// α = β = 5, E0 = 3.25e11 erg/g, E_iv = 1.35e10 erg/g, E_cv = 3.00e10 erg/g). In SI:
/// ρ0 = 8900 kg/m³, A = 139 GPa, B = 110 GPa, E0 = 32.5 MJ/kg, E_iv = 1.35 MJ/kg,
/// E_cv = 3.0 MJ/kg. Not in docs/reference/tillotson.md; A, B and E0 agree with a second
/// public impact code's table, E_iv and E_cv were not cross-checked against Tillotson 1962.
pub fn tillotson_copper() -> TillotsonParams {
    TillotsonParams {
        rho0: 8900.0,
        A: 139.0e9,
        B: 110.0e9,
        a: 0.5,
        b: 1.5,
        alpha: 5.0,
        beta: 5.0,
        E0: 32.5e6,
        E_iv: 1.35e6,
        E_cv: 3.0e6,
    }
}

/// Armco iron, Johnson–Cook (Johnson & Cook 1983, Proc. 7th Int. Symp. Ballistics, 541,
/// the iron of their table): A = 175 MPa, B = 380 MPa, n = 0.32, C = 0.06, m = 0.55,
/// T_m = 1811 K. T_r = 298 K and ε̇0 = 1 /s as in the OFHC-copper set of
/// docs/reference/strength_point_values.md, "Johnson–Cook copper and aluminium". G = 82 GPa,
/// the handbook shear modulus of polycrystalline iron (CRC Handbook of Chemistry and Physics,
/// elastic constants of metals: E = 211 GPa, ν = 0.29).
pub const ARMCO_IRON_JC: JohnsonCookParams = JohnsonCookParams {
    a: 175.0e6,
    b: 380.0e6,
    n: 0.32,
    c: 0.06,
    m: 0.55,
    melt_temperature: 1811.0,
    reference_temperature: 298.0,
    reference_strain_rate: 1.0,
    shear_modulus: 82.0e9,
};

/// Water ice of Benz & Asphaug (1999, Icarus 142:5) as in miluphcuda's ice material
/// file: von Mises Y = 1 GPa, G = 2.8 GPa. That file notes the yield stress "may be (much)
/// too large" (cf. Petrovic 2003, J. Mater. Sci. 38:1, for measured ice strengths).
pub const ICE_BA99_VON_MISES: VonMisesParams = VonMisesParams {
    yield_strength: 1.0e9,
    shear_modulus: 2.8e9,
    hardening: None,
};

/// Weibull k of granite in Spheral's material library, 1e27 cm⁻³ = 1e33 m⁻³
/// (docs/reference/weibull_flaws.md, "Parameter sets").
pub const GRANITE_WEIBULL_K: f64 = 1.0e33;
/// Weibull m of granite in Spheral's material library (docs/reference/weibull_flaws.md,
/// "Parameter sets").
pub const GRANITE_WEIBULL_M: f64 = 6.2;

/// Iron, handbook thermal data (pure Fe, CRC Handbook of Chemistry and Physics):
///
/// - c_v = 449 J/kg/K: c_p at 298 K, 25.10 J/mol/K ÷ 55.845 g/mol (solids: c_v ≈ c_p);
///   it rises steeply towards the Curie point (1043 K), so this underestimates the
///   energy to reach the melt.
/// - T_ref = 298 K, the Johnson–Cook T_r of [`ARMCO_IRON_JC`].
/// - T_melt = 1811 K (1538 °C); the α→γ (1185 K) and γ→δ transitions and their small
///   latent heats are not modelled.
/// - L_melt = 2.47e5 J/kg: ΔH_fus = 13.81 kJ/mol ÷ 55.845 g/mol. Engineering ToolBox
///   lists 69.1 kcal/kg = 2.89e5 J/kg: uncertain by ~15 %.
/// - T_vap = 3134 K (2861 °C), normal boiling point.
/// - L_vap = 6.09e6 J/kg: ΔH_vap = 340 kJ/mol ÷ 55.845 g/mol (Engineering ToolBox:
///   1520 kcal/kg = 6.36e6 J/kg).
pub const THERMAL_IRON: ThermalParams = ThermalParams {
    c_v: 449.0,
    T_ref: 298.0,
    T_melt: 1811.0,
    L_melt: 2.47e5,
    T_vap: 3134.0,
    L_vap: 6.09e6,
};

/// Copper, handbook thermal data (pure Cu, CRC Handbook of Chemistry and Physics):
///
/// - c_v = 385 J/kg/K: c_p at 298 K, 24.44 J/mol/K ÷ 63.546 g/mol.
/// - T_ref = 298 K, the Johnson–Cook T_r of the OFHC set (docs/reference/strength_point_values.md,
///   "Johnson–Cook copper and aluminium").
/// - T_melt = 1357.77 K, the ITS-90 freezing point of copper (JC uses T_m = 1356 K).
/// - L_melt = 2.09e5 J/kg: ΔH_fus = 13.26 kJ/mol ÷ 63.546 g/mol.
/// - T_vap = 2835 K (2562 °C), normal boiling point.
/// - L_vap = 4.73e6 J/kg: ΔH_vap = 300.4 kJ/mol ÷ 63.546 g/mol (Engineering ToolBox:
///   1210 kcal/kg = 5.07e6 J/kg: uncertain by ~7 %).
pub const THERMAL_COPPER: ThermalParams = ThermalParams {
    c_v: 385.0,
    T_ref: 298.0,
    T_melt: 1357.77,
    L_melt: 2.09e5,
    T_vap: 2835.0,
    L_vap: 4.73e6,
};

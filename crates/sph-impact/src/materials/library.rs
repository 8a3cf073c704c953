//! The built-in materials, each with its sources: the study's basalt target and
//! aluminium 2024 projectile (paper §3, §6, Tables 1, A1–A3) and granite, iron, copper and
//! ice (docs/reference/tillotson.md, strength_point_values.md and weibull_flaws.md). Where
//! those pages give no value for a parameter group, the constructor's documentation says
//! what was chosen and why.
//!
//! ```
//! use sph_impact::materials::{builtin, library};
//! let basalt = builtin("basalt-study")?;
//! assert_eq!(basalt.density, 2876.0);
//! assert_eq!(library().len(), 7);
//! assert!(builtin("basalt").unwrap_err().to_string().contains("basalt-study"));
//! # Ok::<(), sph_impact::materials::MaterialError>(())
//! ```

use crate::materials::damage_spec::DamageSpec;
use crate::materials::error::MaterialError;
use crate::materials::parameter_sets::{
    ARMCO_IRON_JC, GRANITE_WEIBULL_K, GRANITE_WEIBULL_M, ICE_BA99_VON_MISES, THERMAL_COPPER,
    THERMAL_IRON, tillotson_copper,
};
use crate::materials::spec::MaterialSpec;
use sph_damage::WeibullParams;
use sph_eos::{ThermalModel, Tillotson, TillotsonParams};
use sph_strength::{JohnsonCook, Lundborg, SteinbergGuinan, VonMises, materials as strength_sets};

/// Names of the built-in materials, in [`library`] order.
pub const BUILTIN_NAMES: [&str; 7] = [
    "basalt-study",
    "aluminium-2024-jc",
    "aluminium-2024-sg",
    "granite",
    "iron",
    "copper",
    "ice",
];

/// Every built-in parameter set is valid (the library tests check each material).
const VALID: &str = "built-in parameter set is valid (tested)";

/// All built-in materials.
pub fn library() -> Vec<MaterialSpec> {
    vec![
        MaterialSpec::basalt_study(),
        MaterialSpec::aluminium_2024_jc(),
        MaterialSpec::aluminium_2024_sg(),
        MaterialSpec::granite(),
        MaterialSpec::iron(),
        MaterialSpec::copper(),
        MaterialSpec::ice(),
    ]
}

/// The built-in material called `name`; the error lists the known names.
pub fn builtin(name: &str) -> Result<MaterialSpec, MaterialError> {
    library()
        .into_iter()
        .find(|m| m.name == name)
        .ok_or_else(|| MaterialError::UnknownMaterial {
            name: name.to_owned(),
            known: BUILTIN_NAMES.iter().map(|s| s.to_string()).collect(),
        })
}

/// Source lines as owned strings.
fn sources(lines: &[&str]) -> Vec<String> {
    lines.iter().map(|s| s.to_string()).collect()
}

/// Appends source lines.
trait WithSources {
    fn with_sources(self, lines: &[&str]) -> Self;
}

impl WithSources for MaterialSpec {
    fn with_sources(mut self, lines: &[&str]) -> Self {
        self.sources.extend(sources(lines));
        self
    }
}

fn tillotson(p: TillotsonParams) -> Tillotson {
    Tillotson::new(p).expect(VALID)
}

impl MaterialSpec {
    /// `basalt-study`: the basalt target of the reference study (paper §3, §6).
    ///
    /// - ρ0 = 2876 kg/m³, G = 22.7 GPa (Table 1).
    /// - EOS: Tillotson, Table A1 (A = B = 26.7 GPa, a = 0.5, b = 1.5, α = β = 5,
    ///   E0 = 487 MJ/kg, E_iv = 4.72 MJ/kg, E_cv = 18.2 MJ/kg) at ρ0 = 2876 kg/m³.
    /// - Strength: Lundborg, Y0 = 26.5 MPa, μ = μ_d = 0.6, Y_M = 300 MPa (Table 1); in
    ///   tension Y_i = max(0, Y0 + μP) (sph-strength's default).
    /// - Damage: Benz–Asphaug, m = 10, k = 2.7e41 m⁻³ (Table 1), crack speed 0.4 c_L
    ///   (Benz & Asphaug 1994; paper §3.3 "classically 0.4 c_s"), growth per activated
    ///   flaw (miluphcuda's form, sph-damage's default).
    /// - Thermal: [`ThermalModel::basalt`] (handbook estimates; T_vap, L_vap are
    ///   order-of-magnitude only, see sph-eos).
    ///
    /// Derived: K = 26.7 GPa, E = 53.06 GPa, ν = 0.169, c_L = 4450.6 m/s at 2876 kg/m³
    /// (4593.3 m/s at the 2700 kg/m³ of docs/reference/weibull_flaws.md, "Parameter sets").
    pub fn basalt_study() -> Self {
        MaterialSpec::new(
            "basalt-study",
            2876.0,
            tillotson(TillotsonParams::basalt_study()),
        )
        .with_strength(
            Lundborg::new(strength_sets::BASALT_LUNDBORG).expect(VALID),
            22.7e9,
        )
        .with_damage(DamageSpec::benz_asphaug_weibull(
            WeibullParams::BASALT_STUDY,
        ))
        .with_thermal(ThermalModel::basalt())
        .with_sources(&[
            "density, shear modulus: paper Table 1 (§6): rho0 = 2876 kg/m^3, G = 22.7 GPa",
            "eos: Tillotson basalt, paper Table A1 (= Benz & Asphaug 1999) at the Table 1 \
                 density (§3.1)",
            "strength: Lundborg, paper Table 1: Y0 = 26.5 MPa, mu = mu_d = 0.6, Y_M = 300 \
                 MPa; tension branch linear to zero (sph-strength default)",
            "damage: Benz-Asphaug, paper Table 1: m = 10, k = 2.7e41 m^-3; crack speed 0.4 \
                 c_L (Benz & Asphaug 1994); growth per activated flaw (miluphcuda, Schaefer et \
                 al. 2016)",
            "thermal: basalt handbook estimates of sph-eos (c_v: Robertson 1988; L_melt: \
                 Bouhifd et al. 2007; T_vap, L_vap order of magnitude only)",
        ])
    }

    /// `aluminium-2024-jc`: the study's aluminium 2024 projectile with Johnson–Cook
    /// strength (paper §3, §6).
    ///
    /// - ρ0 = 2785 kg/m³, G = 26.5 GPa (Table 1).
    /// - EOS: Tillotson, Table A1 (A = 75.2 GPa, B = 65 GPa, a = 0.5, b = 1.63,
    ///   α = β = 5, E0 = 5 MJ/kg, E_iv = 3 MJ/kg, E_cv = 15 MJ/kg) at 2785 kg/m³.
    /// - Strength: Johnson–Cook, the "measured" row of Table A2 (A = 265 MPa,
    ///   B = 426 MPa, n = 0.34, C = 0.015, m = 1.0, T_m = 935 K, T_r = 300 K); the study
    ///   does not state ε̇0, 1 /s is assumed.
    /// - Damage: maximum tensile stress σ_b = 2500 MPa (Table 1), crack growth at 0.4 c_L.
    /// - Thermal: [`ThermalModel::aluminium`] (pure-Al handbook data, CRC).
    pub fn aluminium_2024_jc() -> Self {
        MaterialSpec::new(
            "aluminium-2024-jc",
            2785.0,
            tillotson(TillotsonParams::aluminium_study()),
        )
        .with_strength(
            JohnsonCook::new(strength_sets::ALUMINIUM_2024_JC_MEASURED).expect(VALID),
            26.5e9,
        )
        .with_damage(DamageSpec::max_tensile_stress(2500.0e6))
        .with_thermal(ThermalModel::aluminium())
        .with_sources(&[
            "density, shear modulus: paper Table 1 (§6): rho0 = 2785 kg/m^3, G = 26.5 GPa",
            "eos: Tillotson aluminium, paper Table A1 (E_cv = 15 MJ/kg) at the Table 1 density \
             (§3.1)",
            "strength: Johnson-Cook, paper Table A2 'measured' row: A = 265 MPa, B = 426 MPa, n \
             = 0.34, C = 0.015, m = 1.0, T_m = 935 K, T_r = 300 K; reference strain rate 1/s \
             assumed (not stated)",
            "damage: maximum tensile stress sigma_b = 2500 MPa, paper Table 1; crack growth at \
             0.4 c_L",
            "thermal: pure-Al handbook data of sph-eos (CRC Handbook; T_melt agrees with the JC \
             T_m = 935 K)",
        ])
    }

    /// `aluminium-2024-sg`: as [`Self::aluminium_2024_jc`] with Steinberg–Guinan strength
    /// (paper Table A3: G0 = 28.6 GPa, Y0 = 260 MPa, Y_max = 760 MPa, β = 310,
    /// n = 0.185, G'_p = 1.8647, G'_T = −17.62 MPa/K, T_m0 = 1220 K).
    ///
    /// The shear modulus is the set's own G0 = 28.6 GPa, not Table 1's 26.5 GPa (which
    /// goes with Johnson–Cook): Steinberg–Guinan computes G itself from G0, so the two
    /// cannot differ. The study found both strength models give nearly the same crater
    /// and β (paper §7).
    pub fn aluminium_2024_sg() -> Self {
        let mut m = Self::aluminium_2024_jc().with_strength(
            SteinbergGuinan::new(strength_sets::ALUMINIUM_2024_SG).expect(VALID),
            strength_sets::ALUMINIUM_2024_SG.shear_modulus,
        );
        m.name = "aluminium-2024-sg".into();
        m.sources = sources(&[
            "density: paper Table 1 (§6): rho0 = 2785 kg/m^3",
            "shear modulus: G0 = 28.6 GPa of the Steinberg-Guinan set, paper Table A3 (Table \
             1's 26.5 GPa goes with Johnson-Cook)",
            "eos: Tillotson aluminium, paper Table A1 (E_cv = 15 MJ/kg) at the Table 1 density \
             (§3.1)",
            "strength: Steinberg-Guinan, paper Table A3: Y0 = 260 MPa, Y_max = 760 MPa, beta = \
             310, n = 0.185, G'_p = 1.8647, G'_T = -1.762e7 Pa/K, T_m0 = 1220 K (Y'_p = 0.01695 \
             implied)",
            "damage: maximum tensile stress sigma_b = 2500 MPa, paper Table 1; crack growth at \
             0.4 c_L",
            "thermal: pure-Al handbook data of sph-eos (CRC Handbook)",
        ]);
        m
    }

    /// `granite`.
    ///
    /// - EOS: Tillotson granite (Allen 1967; docs/reference/tillotson.md), ρ0 = 2680 kg/m³.
    /// - Strength: Lundborg of Collins, Melosh & Ivanov 2004: Y0 = 90 MPa, μ_i = 2,
    ///   Y_M = 1.5 GPa, μ_d = 0.8 (docs/reference/strength_point_values.md, "Lundborg granite
    ///   and radial return"); G = 27 GPa (miluphcuda's granite; neither source gives G).
    /// - Damage: Benz–Asphaug with Spheral's granite Weibull set, k = 1e33 m⁻³, m = 6.2
    ///   (docs/reference/weibull_flaws.md, "Parameter sets"), crack speed 0.4 c_L.
    /// - Thermal: none. Granite melts over several hundred kelvin and no sourced latent
    ///   heats were found; give `[thermal]` data in a material file if melting matters.
    pub fn granite() -> Self {
        MaterialSpec::new("granite", 2680.0, tillotson(TillotsonParams::granite()))
            .with_strength(
                Lundborg::new(strength_sets::GRANITE_LUNDBORG_COLLINS2004).expect(VALID),
                strength_sets::GRANITE_LUNDBORG_COLLINS2004.shear_modulus,
            )
            .with_damage(DamageSpec::benz_asphaug(
                GRANITE_WEIBULL_K,
                GRANITE_WEIBULL_M,
            ))
            .with_sources(&[
                "density: Tillotson rho0 = 2680 kg/m^3 (Allen 1967; docs/reference/tillotson.md)",
                "eos: Tillotson granite, Allen 1967 as tabulated in docs/reference/tillotson.md",
                "strength: Lundborg, Collins, Melosh & Ivanov 2004 (MAPS 39:217) via miluphcuda \
                 granite.plasticity.cfg: Y0 = 90 MPa, mu_i = 2, Y_M = 1.5 GPa, mu_d = 0.8 \
                 (docs/reference/strength_point_values.md, \"Lundborg granite and radial \
                 return\")",
                "shear modulus: G = 27 GPa, miluphcuda's granite (chosen: Collins 2004 gives \
                 none)",
                "damage: Benz-Asphaug, Spheral MaterialPropertiesLib granite: k = 1e27 cm^-3 = \
                 1e33 m^-3, m = 6.2 (docs/reference/weibull_flaws.md, \"Parameter sets\")",
                "thermal: none (no single melting point; no sourced latent heats)",
            ])
    }

    /// `iron`.
    ///
    /// - EOS: Tillotson iron (Melosh 1989, Table AII.3; docs/reference/tillotson.md),
    ///   ρ0 = 7800 kg/m³.
    /// - Strength: Johnson–Cook for Armco iron (Johnson & Cook 1983): A = 175 MPa,
    ///   B = 380 MPa, n = 0.32, C = 0.06, m = 0.55, T_m = 1811 K, T_r = 298 K. Chosen
    ///   because the specification gives no iron strength and this is the iron of the
    ///   Johnson–Cook paper. G = 82 GPa (CRC handbook, polycrystalline iron).
    /// - Damage: none. The specification gives no iron failure data, and iron's spall
    ///   strength depends strongly on the strain rate, so no single σ_b is offered; add
    ///   a `[damage]` section for a scene.
    /// - Thermal: CRC handbook data for Fe ([`crate::materials::parameter_sets::THERMAL_IRON`]).
    pub fn iron() -> Self {
        MaterialSpec::new("iron", 7800.0, tillotson(TillotsonParams::iron()))
            .with_strength(
                JohnsonCook::new(ARMCO_IRON_JC).expect(VALID),
                ARMCO_IRON_JC.shear_modulus,
            )
            .with_thermal(ThermalModel::new(THERMAL_IRON).expect(VALID))
            .with_sources(&[
                "density: Tillotson rho0 = 7800 kg/m^3 (Melosh 1989; \
                 docs/reference/tillotson.md)",
                "eos: Tillotson iron, Melosh 1989 Table AII.3 (docs/reference/tillotson.md)",
                "strength: Johnson-Cook, Armco iron of Johnson & Cook 1983: A = 175 MPa, B = \
                 380 MPa, n = 0.32, C = 0.06, m = 0.55, T_m = 1811 K; T_r = 298 K, rate 1/s \
                 (chosen: no iron strength in the spec)",
                "shear modulus: G = 82 GPa, CRC Handbook elastic constants of iron (E = 211 \
                 GPa, nu = 0.29)",
                "damage: none (chosen: no iron failure data in the spec; spall strength is rate \
                 dependent)",
                "thermal: CRC Handbook data for Fe (c_p 25.10 J/mol/K, T_melt 1811 K, dH_fus \
                 13.81 kJ/mol, T_boil 3134 K, dH_vap 340 kJ/mol)",
            ])
    }

    /// `copper`.
    ///
    /// - EOS: Tillotson copper (Tillotson 1962 via Spheral's material library;
    ///   [`crate::materials::parameter_sets::tillotson_copper`]), ρ0 = 8900 kg/m³.
    ///   docs/reference/tillotson.md has no copper set.
    /// - Strength: Johnson–Cook for OFHC copper (Johnson & Cook 1983;
    ///   docs/reference/strength_point_values.md, "Johnson–Cook copper and aluminium"):
    ///   A = 90 MPa, B = 292 MPa, n = 0.31, C = 0.025, m = 1.09, T_m = 1356 K, T_r = 298 K;
    ///   G = 47.7 GPa (Steinberg 1996's G0; "Steinberg–Guinan copper" on the same page).
    ///   Johnson–Cook rather than that Steinberg–Guinan set because its ρ0 = 8930 kg/m³
    ///   differs from the Tillotson ρ0.
    /// - Damage: none (as for iron: no sourced failure data in the specification).
    /// - Thermal: CRC handbook data for Cu ([`crate::materials::parameter_sets::THERMAL_COPPER`]).
    pub fn copper() -> Self {
        MaterialSpec::new("copper", 8900.0, tillotson(tillotson_copper()))
            .with_strength(
                JohnsonCook::new(strength_sets::OFHC_COPPER_JC).expect(VALID),
                strength_sets::OFHC_COPPER_JC.shear_modulus,
            )
            .with_thermal(ThermalModel::new(THERMAL_COPPER).expect(VALID))
            .with_sources(&[
                "density: Tillotson rho0 = 8900 kg/m^3 (Spheral MaterialPropertiesLib copper)",
                "eos: Tillotson copper, Tillotson 1962 via Spheral MaterialPropertiesLib (A = \
                 1.39 Mbar, B = 1.10 Mbar, E0 = 3.25e11 erg/g, E_iv = 1.35e10 erg/g, E_cv = \
                 3.0e10 erg/g); not in docs/reference/tillotson.md",
                "strength: Johnson-Cook OFHC copper, Johnson & Cook 1983 \
                 (docs/reference/strength_point_values.md, \"Johnson–Cook copper and aluminium\")",
                "shear modulus: G = 47.7 GPa, copper G0 of Steinberg 1996 \
                 (docs/reference/strength_point_values.md, \"Steinberg–Guinan copper\")",
                "damage: none (chosen: no copper failure data in the spec)",
                "thermal: CRC Handbook data for Cu (c_p 24.44 J/mol/K, T_melt 1357.77 K, dH_fus \
                 13.26 kJ/mol, T_boil 2835 K, dH_vap 300.4 kJ/mol)",
            ])
    }

    /// `ice`: water ice of Benz & Asphaug (1999).
    ///
    /// - EOS: Tillotson ice (Benz & Asphaug 1999; docs/reference/tillotson.md), ρ0 = 917 kg/m³.
    /// - Strength: von Mises, Y = 1 GPa, G = 2.8 GPa (Benz & Asphaug 1999 as in
    ///   miluphcuda's ice file, which warns that Y may be much too large; measured ice
    ///   strengths are MPa-scale, Petrovic 2003). Chosen to keep the EOS, strength and
    ///   damage from one consistent source; the specification gives no ice strength.
    /// - Damage: Benz–Asphaug, k = 1.4e38 m⁻³, m = 9.6 (Benz & Asphaug 1999;
    ///   docs/reference/weibull_flaws.md, "Parameter sets").
    /// - Thermal: none. The one-c_v caloric model cannot hold ice (c_p ≈ 2.1 kJ/kg/K) and
    ///   liquid water (4.2 kJ/kg/K) at once, and an icy body's reference temperature is
    ///   scene-specific; give `[thermal]` data in a material file.
    pub fn ice() -> Self {
        MaterialSpec::new("ice", 917.0, tillotson(TillotsonParams::ice()))
            .with_strength(
                VonMises::new(ICE_BA99_VON_MISES).expect(VALID),
                ICE_BA99_VON_MISES.shear_modulus,
            )
            .with_damage(DamageSpec::benz_asphaug_weibull(WeibullParams::ICE_BA99))
            .with_sources(&[
                "density: Tillotson rho0 = 917 kg/m^3 (Benz & Asphaug 1999; \
                 docs/reference/tillotson.md)",
                "eos: Tillotson ice, Benz & Asphaug 1999 (docs/reference/tillotson.md)",
                "strength: von Mises Y = 1 GPa, G = 2.8 GPa, Benz & Asphaug 1999 via \
                 miluphcuda's ice file (Y possibly much too large, cf. Petrovic 2003)",
                "damage: Benz-Asphaug, k = 1.4e38 m^-3, m = 9.6 (Benz & Asphaug 1999; \
                 docs/reference/weibull_flaws.md, \"Parameter sets\")",
                "thermal: none (one constant c_v cannot represent ice and water)",
            ])
    }
}

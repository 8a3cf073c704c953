//! Tillotson (1962) equation of state, all four regions, with analytic derivatives.
//!
//! Reference: J. H. Tillotson, "Metallic equations of state for hypervelocity impact",
//! General Atomic report GA-3216 (1962); the region logic as in Melosh (1989), *Impact
//! Cratering*, Appendix II, and Benz & Asphaug (1999), Icarus 142:5. Formulas exactly as
//! in docs/reference/tillotson.md, "Formula", with no cutoffs:
//!
//! η = ρ/ρ0, μ = η − 1, ω0 = e/(E0 η²) + 1, z = ρ0/ρ − 1.
//!
//! | region | condition | pressure |
//! |---|---|---|
//! | compressed | η ≥ 1 (any e) | P_c = (a + b/ω0) ρ e + A μ + B μ² |
//! | cold expanded | η < 1, e ≤ E_iv | P_c (the B μ² term is **kept**, as miluphcuda does; Spheral drops it) |
//! | intermediate | η < 1, E_iv < e < E_cv | P = [(e − E_iv) P_e + (E_cv − e) P_c] / (E_cv − E_iv) |
//! | hot expanded | η < 1, e ≥ E_cv | P_e = a ρ e + [b ρ e/ω0 + A μ e^(−βz)] e^(−αz²) |
//!
//! The intermediate region interpolates linearly in e, so P is continuous across E_iv and
//! E_cv; P_c = P_e at η = 1, so P is continuous (and, since the exponential factors have
//! zero slope there, C¹) across η = 1.
//!
//! **Derivatives** (derived here; checked against central differences in the tests). With
//! ∂ω0/∂ρ = −2(ω0 − 1)/ρ and ∂ω0/∂e = (ω0 − 1)/e:
//! - ∂P_c/∂ρ = a e + b e (3ω0 − 2)/ω0² + (A + 2Bμ)/ρ0,  ∂P_c/∂e = ρ (a + b/ω0²);
//! - with X = e^(−αz²), Y = e^(−βz), G = bρe/ω0 + AμY and ζ = ρ0/ρ² (= −dz/dρ):
//!   ∂P_e/∂ρ = a e + X [b e (3ω0 − 2)/ω0² + A Y (1/ρ0 + β μ ζ)] + 2 α z ζ X G,
//!   ∂P_e/∂e = ρ (a + b X/ω0²);
//! - intermediate: ∂P/∂ρ is the same e-weighted mean of ∂P_e/∂ρ and ∂P_c/∂ρ, and
//!   ∂P/∂e = (P_e − P_c)/(E_cv − E_iv) + the weighted mean of ∂P_e/∂e and ∂P_c/∂e.
//!
//! **Validity.** ρ > 0 and ω0 > 0 (e > −E0 η²). The formulas are evaluated as they stand
//! everywhere else, including deep tension, where the cold branch gives c² < 0 (basalt at
//! e = 0: c² = (A/ρ0)(1 + 4μ) < 0 for η < 0.75). There the sound speed is floored at
//! `sound_speed_floor_fraction · c0`, c0 = √(A/ρ0), and flagged
//! ([`crate::EosPoint::sound_speed_floored`]). No pressure cutoff is applied unless
//! [`Tillotson::with_min_pressure`] is called. Not implemented (documented alternatives in
//! docs/reference/tillotson.md, "Formula"): miluphcuda's P = 0 for η < ρ_limit and its
//! ideal-gas switch above 100 E_cv.

use crate::eos::{
    DEFAULT_SOUND_SPEED_FLOOR_FRACTION, EosPoint, EquationOfState, basic_state_check,
    floor_from_fraction,
};
use crate::error::{EosError, check, non_negative, positive};
use serde::{Deserialize, Serialize};

/// Tillotson parameters (SI). Field names follow the literature (Tillotson 1962; Melosh
/// 1989), so a TOML material file reads `A = 26.7e9`, `E_iv = 4.72e6`.
///
/// Plain data: [`Tillotson::new`] validates. Named sets with their sources are in
/// `tillotson_materials.rs` ([`TillotsonParams::basalt_ba99`], ...).
#[allow(non_snake_case)]
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TillotsonParams {
    /// Reference density ρ0, kg/m³ (> 0).
    pub rho0: f64,
    /// Bulk modulus term A, Pa (> 0); c0 = √(A/ρ0).
    pub A: f64,
    /// Non-linear compression term B, Pa (≥ 0).
    pub B: f64,
    /// Dimensionless a (> 0): the high-expansion, hot limit is P → aρe.
    pub a: f64,
    /// Dimensionless b (≥ 0).
    pub b: f64,
    /// Dimensionless α (> 0), decay of the hot-expanded correction with z².
    pub alpha: f64,
    /// Dimensionless β (> 0), decay of the A μ term with z.
    pub beta: f64,
    /// Energy E0, J/kg (> 0), in ω0 = e/(E0 η²) + 1.
    pub E0: f64,
    /// Specific energy of incipient vaporisation E_iv, J/kg (≥ 0).
    pub E_iv: f64,
    /// Specific energy of complete vaporisation E_cv, J/kg (> E_iv).
    pub E_cv: f64,
}

impl TillotsonParams {
    /// Checks every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), EosError> {
        positive("rho0", self.rho0)?;
        positive("A", self.A)?;
        non_negative("B", self.B)?;
        positive("a", self.a)?;
        non_negative("b", self.b)?;
        positive("alpha", self.alpha)?;
        positive("beta", self.beta)?;
        positive("E0", self.E0)?;
        non_negative("E_iv", self.E_iv)?;
        check(
            "E_cv",
            self.E_cv,
            self.E_cv > self.E_iv,
            "must exceed E_iv (the intermediate region needs E_iv < E_cv)",
        )
    }

    /// Reference bulk sound speed c0 = √(A/ρ0), m/s.
    pub fn reference_sound_speed(&self) -> f64 {
        (self.A / self.rho0).sqrt()
    }
}

/// Which of the four Tillotson regions a state falls in (see the module table).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TillotsonRegion {
    /// η ≥ 1: P_c.
    Compressed,
    /// η < 1 and e ≤ E_iv: P_c.
    ColdExpanded,
    /// η < 1 and E_iv < e < E_cv: interpolation between P_c and P_e.
    Intermediate,
    /// η < 1 and e ≥ E_cv: P_e.
    HotExpanded,
}

/// The Tillotson EOS. Construct with [`Tillotson::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tillotson {
    p: TillotsonParams,
    inv_rho0: f64,
    inv_de: f64,
    c0: f64,
    floor_fraction: f64,
    c_floor: f64,
    min_pressure: Option<f64>,
}

/// P and its two partial derivatives in one branch.
#[derive(Clone, Copy)]
struct Branch {
    p: f64,
    dr: f64,
    de: f64,
}

impl Tillotson {
    /// Validates the parameters. Sound-speed floor: [`DEFAULT_SOUND_SPEED_FLOOR_FRACTION`]
    /// of c0; no pressure floor.
    pub fn new(params: TillotsonParams) -> Result<Self, EosError> {
        params.validate()?;
        let c0 = params.reference_sound_speed();
        Ok(Self {
            p: params,
            inv_rho0: 1.0 / params.rho0,
            inv_de: 1.0 / (params.E_cv - params.E_iv),
            c0,
            floor_fraction: DEFAULT_SOUND_SPEED_FLOOR_FRACTION,
            c_floor: DEFAULT_SOUND_SPEED_FLOOR_FRACTION * c0,
            min_pressure: None,
        })
    }

    /// Sets the sound-speed floor to `fraction · c0` (fraction in [0, 1]; 0 returns c = 0
    /// wherever c² ≤ 0, still flagged when c² < 0).
    pub fn with_sound_speed_floor_fraction(mut self, fraction: f64) -> Result<Self, EosError> {
        self.c_floor = floor_from_fraction(fraction, self.c0)?;
        self.floor_fraction = fraction;
        Ok(self)
    }

    /// Optional pressure floor P ≥ `p_min` (Pa, finite, ≤ 0), off by default. Where it
    /// acts, P = p_min, both derivatives are 0 (those of the returned, constant pressure),
    /// so c² = 0 and the sound-speed floor applies; [`crate::EosPoint::pressure_floored`]
    /// is set. [`EquationOfState::pressure`] applies the same floor but cannot flag it.
    pub fn with_min_pressure(mut self, p_min: f64) -> Result<Self, EosError> {
        check(
            "P_min",
            p_min,
            p_min <= 0.0,
            "must be <= 0 (a tension limit)",
        )?;
        self.min_pressure = Some(p_min);
        Ok(self)
    }

    /// The parameters.
    pub fn params(&self) -> &TillotsonParams {
        &self.p
    }

    /// Sound-speed floor, m/s.
    pub fn sound_speed_floor(&self) -> f64 {
        self.c_floor
    }

    /// Sound-speed floor as a fraction of c0.
    pub fn sound_speed_floor_fraction(&self) -> f64 {
        self.floor_fraction
    }

    /// The optional pressure floor, Pa.
    pub fn min_pressure(&self) -> Option<f64> {
        self.min_pressure
    }

    /// The region of (ρ, e).
    pub fn region(&self, rho: f64, e: f64) -> TillotsonRegion {
        if rho >= self.p.rho0 {
            TillotsonRegion::Compressed
        } else if e <= self.p.E_iv {
            TillotsonRegion::ColdExpanded
        } else if e >= self.p.E_cv {
            TillotsonRegion::HotExpanded
        } else {
            TillotsonRegion::Intermediate
        }
    }

    /// P_c and derivatives (compressed / cold branch), any (ρ, e).
    #[inline(always)]
    fn cold(&self, rho: f64, e: f64, mu: f64, omega: f64) -> Branch {
        let p = &self.p;
        let inv_w = 1.0 / omega;
        Branch {
            p: (p.a + p.b * inv_w) * rho * e + p.A * mu + p.B * mu * mu,
            dr: p.a * e
                + p.b * e * (3.0 * omega - 2.0) * inv_w * inv_w
                + (p.A + 2.0 * p.B * mu) * self.inv_rho0,
            de: rho * (p.a + p.b * inv_w * inv_w),
        }
    }

    /// P_e and derivatives (hot expanded branch), any (ρ, e).
    #[inline(always)]
    fn hot(&self, rho: f64, e: f64, mu: f64, omega: f64) -> Branch {
        let p = &self.p;
        let inv_w = 1.0 / omega;
        let z = p.rho0 / rho - 1.0;
        let x = (-p.alpha * z * z).exp();
        let y = (-p.beta * z).exp();
        let zeta = p.rho0 / (rho * rho);
        let g = p.b * rho * e * inv_w + p.A * mu * y;
        let dg = p.b * e * (3.0 * omega - 2.0) * inv_w * inv_w
            + p.A * y * (self.inv_rho0 + p.beta * mu * zeta);
        Branch {
            p: p.a * rho * e + g * x,
            dr: p.a * e + x * dg + 2.0 * p.alpha * z * zeta * x * g,
            de: rho * (p.a + p.b * x * inv_w * inv_w),
        }
    }

    /// Unfloored P and derivatives in the region of (ρ, e).
    #[inline(always)]
    fn raw(&self, rho: f64, e: f64) -> Branch {
        let p = &self.p;
        // Division, not a stored 1/ρ0: η = 1 exactly at ρ = ρ0, so P(ρ0, 0) = 0 exactly.
        let eta = rho / p.rho0;
        let mu = eta - 1.0;
        let omega = e / (p.E0 * eta * eta) + 1.0;
        if rho >= p.rho0 || e <= p.E_iv {
            self.cold(rho, e, mu, omega)
        } else if e >= p.E_cv {
            self.hot(rho, e, mu, omega)
        } else {
            let c = self.cold(rho, e, mu, omega);
            let h = self.hot(rho, e, mu, omega);
            let (we, wc) = (e - p.E_iv, p.E_cv - e);
            Branch {
                p: (we * h.p + wc * c.p) * self.inv_de,
                dr: (we * h.dr + wc * c.dr) * self.inv_de,
                de: (h.p - c.p) * self.inv_de + (we * h.de + wc * c.de) * self.inv_de,
            }
        }
    }
}

impl EquationOfState for Tillotson {
    fn name(&self) -> &str {
        "tillotson"
    }

    fn reference_density(&self) -> Option<f64> {
        Some(self.p.rho0)
    }

    fn reference_sound_speed(&self) -> Option<f64> {
        Some(self.c0)
    }

    #[inline]
    fn pressure(&self, rho: f64, e: f64) -> f64 {
        let p = self.raw(rho, e).p;
        match self.min_pressure {
            Some(p_min) if p < p_min => p_min,
            _ => p,
        }
    }

    #[inline]
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        let b = self.raw(rho, e);
        match self.min_pressure {
            Some(p_min) if b.p < p_min => EosPoint {
                pressure_floored: true,
                ..EosPoint::from_derivatives(rho, p_min, 0.0, 0.0, self.c_floor)
            },
            _ => EosPoint::from_derivatives(rho, b.p, b.dr, b.de, self.c_floor),
        }
    }

    /// ρ > 0 finite, e finite and ω0 = e/(E0 η²) + 1 > 0.
    fn check_state(&self, rho: f64, e: f64) -> Result<(), EosError> {
        basic_state_check(self.name(), rho, e)?;
        let eta = rho / self.p.rho0;
        if e / (self.p.E0 * eta * eta) + 1.0 > 0.0 {
            Ok(())
        } else {
            Err(EosError::OutsideValidity {
                eos: self.name().to_owned(),
                rho,
                e,
                reason: "omega0 = e/(E0 eta^2) + 1 must be positive (e > -E0 eta^2)",
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn basalt() -> TillotsonParams {
        TillotsonParams::basalt_ba99()
    }

    #[test]
    fn validation_names_the_field() {
        type Breaker = (&'static str, fn(&mut TillotsonParams));
        let cases: [Breaker; 6] = [
            ("rho0", |p| p.rho0 = 0.0),
            ("A", |p| p.A = -1.0),
            ("E0", |p| p.E0 = f64::NAN),
            ("E_cv", |p| p.E_cv = p.E_iv),
            ("alpha", |p| p.alpha = 0.0),
            ("B", |p| p.B = -1.0),
        ];
        for (field, break_it) in cases {
            let mut p = basalt();
            break_it(&mut p);
            match Tillotson::new(p) {
                Err(EosError::Parameter { field: f, .. }) => assert_eq!(f, field),
                other => panic!("{field}: expected a parameter error, got {other:?}"),
            }
        }
        let t = Tillotson::new(basalt()).unwrap();
        assert!(t.with_min_pressure(1.0).is_err());
        assert!(t.with_sound_speed_floor_fraction(1.5).is_err());
    }

    #[test]
    fn regions() {
        let t = Tillotson::new(basalt()).unwrap();
        let r0 = 2700.0;
        assert_eq!(t.region(r0, 1e9), TillotsonRegion::Compressed);
        assert_eq!(t.region(0.9 * r0, 4.72e6), TillotsonRegion::ColdExpanded);
        assert_eq!(t.region(0.9 * r0, 5e6), TillotsonRegion::Intermediate);
        assert_eq!(t.region(0.9 * r0, 18.2e6), TillotsonRegion::HotExpanded);
    }

    #[test]
    fn omega_must_stay_positive() {
        let t = Tillotson::new(basalt()).unwrap();
        assert!(t.check_state(2700.0, -4.9e8).is_err());
        assert!(t.check_state(2700.0, -4.0e8).is_ok());
    }

    #[test]
    fn min_pressure_is_flagged() {
        let t = Tillotson::new(basalt())
            .unwrap()
            .with_min_pressure(-1e8)
            .unwrap();
        let p = t.evaluate(0.95 * 2700.0, 0.0); // raw P = −1.27 GPa
        assert!(p.pressure_floored && p.sound_speed_floored);
        assert_eq!(p.pressure, -1e8);
        assert_eq!(t.pressure(0.95 * 2700.0, 0.0), -1e8);
        let q = t.evaluate(1.1 * 2700.0, 0.0);
        assert!(!q.pressure_floored);
    }
}

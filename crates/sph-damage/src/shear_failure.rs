//! Shear failure of rock: damage from plastic flow (Ivanov et al. 1997; Collins, Melosh &
//! Ivanov 2004, MAPS 39:217, the damage model of iSALE).
//!
//! A brittle rock that flows plastically is being broken up along shear fractures. The
//! model measures that with the equivalent plastic strain ε_p: damage grows as
//!
//! ```text
//! dD = dε_p / ε_f(P),   ε_f(P) = max(ε_fb, B (P − P_c))
//! ```
//!
//! ε_fb is the failure strain of brittle rock at low pressure, and the slope B above the
//! brittle–ductile transition pressure P_c makes rock at high confining pressure need
//! more strain to fail (it flows ductilely). Collins et al. (2004) use ε_fb = 10⁻⁴,
//! B = 10⁻¹¹ Pa⁻¹ and P_c = 300 MPa for crustal rock ([`PlasticFailure::ROCK_COLLINS2004`]):
//! below 310 MPa a hundredth of a percent of plastic strain breaks the rock; at 1.3 GPa it
//! takes 1 %.
//!
//! The increment is added to the same scalar damage that tensile failure raises (one
//! damage variable, as in iSALE), so a particle's D is the sum of both up to 1. The
//! solver applies it after each plastic update; this module only holds the law.
//!
//! ```
//! use sph_damage::PlasticFailure;
//!
//! let rock = PlasticFailure::ROCK_COLLINS2004;
//! assert_eq!(rock.failure_strain(0.0), 1.0e-4); // brittle: ε_fb
//! assert!((rock.failure_strain(1.3e9) - 1.0e-2).abs() < 1e-15); // B (P − P_c)
//! // Half the failure strain at 50 MPa damages by 0.5.
//! assert!((rock.damage_increment(0.5e-4, 50.0e6) - 0.5).abs() < 1e-12);
//! ```

use crate::error::{DamageError, positive};
use serde::{Deserialize, Serialize};

/// The pressure-dependent failure strain ε_f(P) = max(ε_fb, B (P − P_c)) of shear failure
/// (validated; serde with the same checks).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "PlasticFailureUnchecked")]
pub struct PlasticFailure {
    min_strain: f64,
    pressure_slope: f64,
    pressure_offset: f64,
}

#[derive(Deserialize)]
struct PlasticFailureUnchecked {
    min_strain: f64,
    pressure_slope: f64,
    pressure_offset: f64,
}

impl TryFrom<PlasticFailureUnchecked> for PlasticFailure {
    type Error = DamageError;
    fn try_from(raw: PlasticFailureUnchecked) -> Result<Self, DamageError> {
        PlasticFailure::new(raw.min_strain, raw.pressure_slope, raw.pressure_offset)
    }
}

impl PlasticFailure {
    /// Crustal rock (granite) of Collins, Melosh & Ivanov (2004), after Ivanov et al.
    /// (1997): ε_fb = 10⁻⁴, B = 10⁻¹¹ Pa⁻¹, P_c = 300 MPa. Spheral's material library
    /// gives the same three values for basalt.
    pub const ROCK_COLLINS2004: PlasticFailure = PlasticFailure {
        min_strain: 1.0e-4,
        pressure_slope: 1.0e-11,
        pressure_offset: 3.0e8,
    };

    /// The law with ε_fb (`min_strain`, > 0), B (`pressure_slope`, Pa⁻¹, ≥ 0) and P_c
    /// (`pressure_offset`, Pa, finite); the error names the bad field.
    pub fn new(
        min_strain: f64,
        pressure_slope: f64,
        pressure_offset: f64,
    ) -> Result<Self, DamageError> {
        positive("min_strain", min_strain)?;
        if !(pressure_slope.is_finite() && pressure_slope >= 0.0) {
            return Err(DamageError::Parameter {
                field: "pressure_slope",
                value: pressure_slope,
                reason: "must be finite and not negative",
            });
        }
        if !pressure_offset.is_finite() {
            return Err(DamageError::Parameter {
                field: "pressure_offset",
                value: pressure_offset,
                reason: "must be finite",
            });
        }
        Ok(Self {
            min_strain,
            pressure_slope,
            pressure_offset,
        })
    }

    /// ε_fb, the failure strain of brittle rock.
    pub fn min_strain(&self) -> f64 {
        self.min_strain
    }

    /// B, Pa⁻¹.
    pub fn pressure_slope(&self) -> f64 {
        self.pressure_slope
    }

    /// P_c, Pa.
    pub fn pressure_offset(&self) -> f64 {
        self.pressure_offset
    }

    /// ε_f(P) = max(ε_fb, B (P − P_c)) (Collins et al. 2004), P in Pa; ≥ ε_fb > 0.
    #[inline]
    pub fn failure_strain(&self, pressure: f64) -> f64 {
        self.min_strain
            .max(self.pressure_slope * (pressure - self.pressure_offset))
    }

    /// The damage a plastic strain increment dε_p (≥ 0) at pressure P adds:
    /// dε_p / ε_f(P). Not capped: the solver adds it to D and keeps D ≤ 1.
    #[inline]
    pub fn damage_increment(&self, plastic_strain_increment: f64, pressure: f64) -> f64 {
        plastic_strain_increment / self.failure_strain(pressure)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failure_strain_is_brittle_below_the_transition_and_linear_above() {
        let r = PlasticFailure::ROCK_COLLINS2004;
        // Tension and low pressure: ε_fb.
        assert_eq!(r.failure_strain(-1.0e8), 1.0e-4);
        assert_eq!(r.failure_strain(3.1e8), 1.0e-4);
        // B (P − P_c) = 1e-11 × 1e9 = 0.01 at 1.3 GPa, 0.097 at 10 GPa.
        assert!((r.failure_strain(1.3e9) - 0.01).abs() < 1e-15);
        assert!((r.failure_strain(10.0e9) - 0.097).abs() < 1e-15);
        // The kink where B (P − P_c) = ε_fb: P = 310 MPa.
        assert!((r.failure_strain(3.1e8 + 1.0e6) - 1.1e-4).abs() < 1e-15);
    }

    #[test]
    fn increment_is_strain_over_failure_strain() {
        let r = PlasticFailure::ROCK_COLLINS2004;
        assert!((r.damage_increment(1.0e-4, 0.0) - 1.0).abs() < 1e-12);
        assert!((r.damage_increment(1.0e-3, 1.3e9) - 0.1).abs() < 1e-12);
        assert_eq!(r.damage_increment(0.0, 5.0e9), 0.0);
    }

    #[test]
    fn bad_parameters_are_named() {
        for (args, field) in [
            ((0.0, 1e-11, 3e8), "min_strain"),
            ((f64::NAN, 1e-11, 3e8), "min_strain"),
            ((1e-4, -1e-11, 3e8), "pressure_slope"),
            ((1e-4, f64::INFINITY, 3e8), "pressure_slope"),
            ((1e-4, 1e-11, f64::NAN), "pressure_offset"),
        ] {
            match PlasticFailure::new(args.0, args.1, args.2) {
                Err(DamageError::Parameter { field: f, .. }) => assert_eq!(f, field),
                other => panic!("{args:?}: expected an error on {field}, got {other:?}"),
            }
        }
        // A zero slope is allowed: ε_f = ε_fb at every pressure.
        let flat = PlasticFailure::new(1e-3, 0.0, 0.0).unwrap();
        assert_eq!(flat.failure_strain(1e10), 1e-3);
    }

    #[test]
    fn serde_checks_the_values() {
        let ok: PlasticFailure = serde_json::from_str(
            r#"{"min_strain":1e-4,"pressure_slope":1e-11,"pressure_offset":3e8}"#,
        )
        .unwrap();
        assert_eq!(ok, PlasticFailure::ROCK_COLLINS2004);
        let bad: Result<PlasticFailure, _> = serde_json::from_str(
            r#"{"min_strain":-1,"pressure_slope":1e-11,"pressure_offset":3e8}"#,
        );
        assert!(bad.unwrap_err().to_string().contains("min_strain"));
    }
}

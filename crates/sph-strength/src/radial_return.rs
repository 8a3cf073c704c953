//! Radial return to the von Mises yield surface (Wilkins 1964, "Calculation of
//! elastic-plastic flow", Methods Comput. Phys. 3:211; paper §3.2).
//!
//! After the elastic trial update, if the equivalent stress σ_eq = √(3 J2) of the
//! deviatoric trial stress exceeds Y, S is scaled by exactly Y/σ_eq
//! (docs/reference/strength_point_values.md, "Lundborg granite and radial return"), which
//! puts it on the yield surface without changing its direction. With
//! `J2 = ½ S:S` (S deviatoric), √(3 J2) = √(3/2 S:S).
//!
//! The equivalent plastic strain of the return is (Wilkins 1964; for a perfectly plastic
//! step with the shear modulus G that built the trial stress)
//!
//!   `Δε_p = (σ_eq,trial − Y) / (3G)`,
//!
//! from σ_eq,trial − σ_eq = 3G Δε_p (the radial correction removes a deviatoric strain
//! increment Δε_p·(3/2) S/σ_eq along the flow direction); the solver divides by the step
//! for the plastic strain rate.

use sph_core::glam::DMat3;

/// Second invariant `J2 = ½ S:S` of a deviatoric stress (Pa²). S must be deviatoric
/// (traceless); the Jaumann update keeps it so.
#[inline]
pub fn j2(stress: &DMat3) -> f64 {
    let (a, b, c) = (stress.x_axis, stress.y_axis, stress.z_axis);
    0.5 * (a.dot(a) + b.dot(b) + c.dot(c))
}

/// Von Mises equivalent stress `√(3 J2)` (Pa).
#[inline]
pub fn equivalent_stress(stress: &DMat3) -> f64 {
    (3.0 * j2(stress)).sqrt()
}

/// The outcome of [`radial_return`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReturnResult {
    /// The returned deviatoric stress: the trial stress times `scale`.
    pub stress: DMat3,
    /// The factor applied, min(1, Y/σ_eq,trial); 0 when Y ≤ 0.
    pub scale: f64,
    /// σ_eq,trial = √(3 J2) of the trial stress (Pa).
    pub trial_equivalent_stress: f64,
    /// The yield strength returned to (Pa), with Y < 0 taken as 0.
    pub yield_strength: f64,
}

impl ReturnResult {
    /// True when the trial stress lay outside the yield surface.
    #[inline]
    pub fn yielded(&self) -> bool {
        self.scale < 1.0
    }

    /// σ_eq,trial − Y, the excess removed by the return (Pa); 0 for an elastic step.
    #[inline]
    pub fn excess(&self) -> f64 {
        if self.yielded() {
            self.trial_equivalent_stress - self.yield_strength
        } else {
            0.0
        }
    }

    /// Equivalent plastic strain increment `Δε_p = (σ_eq,trial − Y)/(3G)` (Wilkins 1964)
    /// for the shear modulus G of the step. `Some(0.0)` for an elastic step; `None` when
    /// the step yielded but G is not positive and finite (a melted Steinberg–Guinan
    /// state: no increment can be defined, the caller decides).
    #[inline]
    pub fn plastic_strain_increment(&self, shear_modulus: f64) -> Option<f64> {
        if !self.yielded() {
            Some(0.0)
        } else if shear_modulus.is_finite() && shear_modulus > 0.0 {
            Some(self.excess() / (3.0 * shear_modulus))
        } else {
            None
        }
    }
}

/// Scales the deviatoric trial stress back to the yield surface √(3 J2) = Y when it lies
/// outside, and leaves it untouched (scale 1) inside or on it. `Y ≤ 0` gives S = 0 (no
/// strength; Y < 0 is read as 0). A NaN Y gives a NaN stress so that the solver's state
/// check catches it rather than a silent zero.
#[inline]
pub fn radial_return(trial_stress: DMat3, yield_strength: f64) -> ReturnResult {
    let sigma_eq = equivalent_stress(&trial_stress);
    if yield_strength.is_nan() {
        return ReturnResult {
            stress: trial_stress * f64::NAN,
            scale: f64::NAN,
            trial_equivalent_stress: sigma_eq,
            yield_strength,
        };
    }
    let y = yield_strength.max(0.0);
    if sigma_eq <= y {
        return ReturnResult {
            stress: trial_stress,
            scale: 1.0,
            trial_equivalent_stress: sigma_eq,
            yield_strength: y,
        };
    }
    // Here σ_eq > y ≥ 0, so the division is safe; y = 0 gives scale 0 and S = 0.
    let scale = y / sigma_eq;
    ReturnResult {
        stress: trial_stress * scale,
        scale,
        trial_equivalent_stress: sigma_eq,
        yield_strength: y,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::DVec3;

    #[test]
    fn uniaxial_deviator_point_value() {
        // S = diag(2, −1, −1)·s: J2 = ½(4 + 1 + 1)s² = 3s², σ_eq = 3s.
        let s = 100.0e6;
        let st = DMat3::from_diagonal(DVec3::new(2.0 * s, -s, -s));
        assert!((equivalent_stress(&st) - 3.0 * s).abs() < 1e-6);
        // Y = 150 MPa: scale 1/2, Δε_p = (300 − 150) MPa / (3·50 GPa) = 1e-3.
        let r = radial_return(st, 150.0e6);
        assert_eq!(r.scale, 0.5);
        assert!(r.yielded());
        assert!((r.plastic_strain_increment(50.0e9).unwrap() - 1.0e-3).abs() < 1e-15);
        assert_eq!(r.plastic_strain_increment(0.0), None);
    }

    #[test]
    fn zero_or_negative_yield_zeroes_stress() {
        let st = DMat3::from_diagonal(DVec3::new(2.0, -1.0, -1.0));
        for y in [0.0, -5.0] {
            let r = radial_return(st, y);
            assert_eq!(r.stress, DMat3::ZERO);
            assert_eq!(r.scale, 0.0);
            assert_eq!(r.yield_strength, 0.0);
        }
        // Zero stress with zero strength is elastic.
        let r = radial_return(DMat3::ZERO, 0.0);
        assert!(!r.yielded());
        assert_eq!(r.plastic_strain_increment(0.0), Some(0.0));
    }

    #[test]
    fn nan_yield_propagates() {
        let st = DMat3::from_diagonal(DVec3::new(2.0, -1.0, -1.0));
        let r = radial_return(st, f64::NAN);
        assert!(r.stress.x_axis.x.is_nan());
    }
}

//! The [`EquationOfState`] trait and the result of one evaluation, [`EosPoint`].
//!
//! Conventions (all SI): density ρ in kg/m³, specific internal energy e in J/kg, pressure P
//! in Pa with compression positive (tension negative), sound speed c in m/s.
//!
//! **Sound speed.** Every EOS here returns the isentropic (bulk) sound speed of a
//! P(ρ, e) equation of state, from de = (P/ρ²) dρ along an isentrope:
//!
//! c² = ∂P/∂ρ|_e + (P/ρ²) ∂P/∂e|_ρ
//!
//! (e.g. Benz & Asphaug 1999, Icarus 142:5, for the Tillotson case; it is the first law
//! de = −P d(1/ρ) at constant entropy). Where this c² falls below a floor c_floor² (for the
//! solids in deep tension, see [`crate::Tillotson`]), the returned sound speed is c_floor and
//! [`EosPoint::sound_speed_floored`] is set: never a silent clamp. The unfloored value is
//! kept in [`EosPoint::raw_sound_speed_squared`] so callers can count and locate floored
//! particles. A NaN c² is passed through as NaN (not floored), so bad states stay visible.

use crate::error::EosError;
use std::fmt::Debug;
use std::sync::Arc;

/// Default sound-speed floor of the solid EOSs, as a fraction of their reference bulk
/// sound speed c0: c ≥ 0.01 c0.
///
/// Why a floor at all: the Tillotson cold branch has c² < 0 in tension below
/// η ≈ 0.75 (basalt: c² = (A/ρ0)(1 + 4μ) at e = 0), and a Riemann solver needs a positive
/// impedance ρc on both sides of a pair. Why 1 %: it is far below any sound speed of
/// intact material, so it only acts where the raw c² is (nearly) negative, i.e. in
/// material that has failed in tension; the flag says where.
pub const DEFAULT_SOUND_SPEED_FLOOR_FRACTION: f64 = 0.01;

/// Result of one EOS evaluation at (ρ, e).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EosPoint {
    /// Pressure, Pa (compression positive).
    pub pressure: f64,
    /// Bulk sound speed, m/s: √(c²) with c² from the module formula, or the floor if
    /// [`Self::sound_speed_floored`] is set.
    pub sound_speed: f64,
    /// ∂P/∂ρ at constant e, m²/s² (= Pa·m³/kg), of the returned pressure.
    pub dp_drho: f64,
    /// ∂P/∂e at constant ρ, kg/m³ (= Pa·kg/J), of the returned pressure.
    pub dp_de: f64,
    /// c² = ∂P/∂ρ|_e + (P/ρ²) ∂P/∂e|_ρ before the floor, m²/s² (may be negative).
    pub raw_sound_speed_squared: f64,
    /// True when c² was below the floor and the floor was returned as the sound speed.
    pub sound_speed_floored: bool,
    /// True when an optional pressure floor (e.g. [`crate::Tillotson::with_min_pressure`])
    /// replaced the EOS pressure. Off by default everywhere.
    pub pressure_floored: bool,
}

impl EosPoint {
    /// Builds a point from P and its derivatives, computing c² and applying the sound-speed
    /// floor `c_floor` (m/s, ≥ 0). Used by every EOS in this crate; public so user EOSs
    /// can report the same way.
    #[inline]
    pub fn from_derivatives(
        rho: f64,
        pressure: f64,
        dp_drho: f64,
        dp_de: f64,
        c_floor: f64,
    ) -> Self {
        let c2 = dp_drho + pressure / (rho * rho) * dp_de;
        // `c2 < floor²` is false for NaN, so a NaN c² stays NaN and unflagged.
        let floored = c2 < c_floor * c_floor;
        Self {
            pressure,
            sound_speed: if floored { c_floor } else { c2.sqrt() },
            dp_drho,
            dp_de,
            raw_sound_speed_squared: c2,
            sound_speed_floored: floored,
            pressure_floored: false,
        }
    }
}

/// An equation of state P(ρ, e) with its sound speed and derivatives.
///
/// Object safe: `Box<dyn EquationOfState>` works (a user's own EOS plugs in that way);
/// the concrete types ([`crate::Tillotson`], ...) are the fast path for monomorphised loops.
///
/// The hot-path methods ([`Self::pressure`], [`Self::evaluate`]) do not validate their
/// inputs: outside an EOS's documented range they return what the formula gives (possibly
/// NaN or ±∞). [`Self::checked_evaluate`] validates the state and the outputs and returns a
/// typed error instead.
pub trait EquationOfState: Send + Sync + Debug {
    /// Short name, e.g. `"tillotson"`.
    fn name(&self) -> &str;

    /// Reference density ρ0 in kg/m³ if the EOS has one (`None` for the ideal gas).
    fn reference_density(&self) -> Option<f64>;

    /// Reference bulk sound speed c0 in m/s (the sound speed at ρ0, e = 0) if the EOS has
    /// one; the default sound-speed floor is a fraction of it.
    fn reference_sound_speed(&self) -> Option<f64> {
        None
    }

    /// Pressure in Pa (compression positive) at density `rho` (kg/m³) and specific internal
    /// energy `e` (J/kg).
    fn pressure(&self, rho: f64, e: f64) -> f64;

    /// Pressure, sound speed and the derivatives ∂P/∂ρ|_e, ∂P/∂e|_ρ.
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint;

    /// Bulk sound speed in m/s (floored, see [`EosPoint::sound_speed_floored`]).
    fn sound_speed(&self, rho: f64, e: f64) -> f64 {
        self.evaluate(rho, e).sound_speed
    }

    /// Checks that (ρ, e) lies in the EOS's range of definition. The default requires a
    /// finite ρ > 0 and a finite e; EOSs with further limits override it.
    fn check_state(&self, rho: f64, e: f64) -> Result<(), EosError> {
        basic_state_check(self.name(), rho, e)
    }

    /// [`Self::evaluate`] with the state checked first ([`Self::check_state`]) and every
    /// output checked for NaN/∞. For input validation and diagnostics, not the inner loop.
    fn checked_evaluate(&self, rho: f64, e: f64) -> Result<EosPoint, EosError> {
        self.check_state(rho, e)?;
        let p = self.evaluate(rho, e);
        for (quantity, value) in [
            ("pressure", p.pressure),
            ("sound_speed", p.sound_speed),
            ("dp_drho", p.dp_drho),
            ("dp_de", p.dp_de),
        ] {
            if !value.is_finite() {
                return Err(EosError::NonFinite {
                    eos: self.name().to_owned(),
                    quantity,
                    value,
                    rho,
                    e,
                });
            }
        }
        Ok(p)
    }
}

/// ρ finite and positive, e finite.
pub(crate) fn basic_state_check(name: &str, rho: f64, e: f64) -> Result<(), EosError> {
    let reason = if !(rho.is_finite() && rho > 0.0) {
        "density must be positive and finite"
    } else if !e.is_finite() {
        "specific internal energy must be finite"
    } else {
        return Ok(());
    };
    Err(EosError::OutsideValidity {
        eos: name.to_owned(),
        rho,
        e,
        reason,
    })
}

/// Forwards every method, so `&E`, `Box<E>` and `Arc<E>` (including `dyn
/// EquationOfState`) can be passed where an `E: EquationOfState` is expected.
macro_rules! forward_eos {
    ($($wrapper:ty),*) => {$(
        impl<T: EquationOfState + ?Sized> EquationOfState for $wrapper {
            fn name(&self) -> &str { (**self).name() }
            fn reference_density(&self) -> Option<f64> { (**self).reference_density() }
            fn reference_sound_speed(&self) -> Option<f64> { (**self).reference_sound_speed() }
            #[inline]
            fn pressure(&self, rho: f64, e: f64) -> f64 { (**self).pressure(rho, e) }
            #[inline]
            fn evaluate(&self, rho: f64, e: f64) -> EosPoint { (**self).evaluate(rho, e) }
            #[inline]
            fn sound_speed(&self, rho: f64, e: f64) -> f64 { (**self).sound_speed(rho, e) }
            fn check_state(&self, rho: f64, e: f64) -> Result<(), EosError> {
                (**self).check_state(rho, e)
            }
            fn checked_evaluate(&self, rho: f64, e: f64) -> Result<EosPoint, EosError> {
                (**self).checked_evaluate(rho, e)
            }
        }
    )*};
}
forward_eos!(&T, Box<T>, Arc<T>);

/// Converts a floor fraction of c0 into an absolute floor, validating the fraction.
pub(crate) fn floor_from_fraction(fraction: f64, c0: f64) -> Result<f64, EosError> {
    crate::error::check(
        "sound_speed_floor_fraction",
        fraction,
        (0.0..=1.0).contains(&fraction),
        "must lie in [0, 1]",
    )?;
    Ok(fraction * c0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_is_flagged_and_nan_is_not_hidden() {
        let p = EosPoint::from_derivatives(1.0, -1.0, 0.5, 1.0, 0.1);
        // c² = 0.5 − 1 = −0.5 < 0.01
        assert!(p.sound_speed_floored);
        assert_eq!(p.sound_speed, 0.1);
        assert_eq!(p.raw_sound_speed_squared, -0.5);
        let q = EosPoint::from_derivatives(1.0, 0.0, 4.0, 1.0, 0.1);
        assert!(!q.sound_speed_floored);
        assert_eq!(q.sound_speed, 2.0);
        let n = EosPoint::from_derivatives(1.0, f64::NAN, 4.0, 1.0, 0.1);
        assert!(n.sound_speed.is_nan() && !n.sound_speed_floored);
    }

    #[test]
    fn state_check_names_the_problem() {
        assert!(basic_state_check("x", 1.0, 0.0).is_ok());
        for (rho, e) in [
            (0.0, 0.0),
            (-1.0, 0.0),
            (f64::NAN, 0.0),
            (1.0, f64::INFINITY),
        ] {
            assert!(matches!(
                basic_state_check("x", rho, e),
                Err(EosError::OutsideValidity { .. })
            ));
        }
    }
}

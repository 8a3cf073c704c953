//! The [`StrengthModel`] trait and its input, the local [`StrengthState`].

use crate::error::StrengthError;

/// Local state a strength model may depend on. SI units; pressure compression-positive.
///
/// The models assume a state that passes [`StrengthState::validate`] (the solver checks
/// its fields there, once per particle, and reports the particle on failure); they do not
/// re-check or clamp the fields themselves.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StrengthState {
    /// Pressure P (Pa), positive in compression.
    pub pressure: f64,
    /// Mass density ρ (kg/m³).
    pub density: f64,
    /// Temperature T (K).
    pub temperature: f64,
    /// Equivalent (von Mises) plastic strain ε_p, dimensionless, ≥ 0.
    pub plastic_strain: f64,
    /// Equivalent plastic strain rate ε̇_p (1/s), ≥ 0.
    pub plastic_strain_rate: f64,
    /// Scalar damage D in [0, 1] (0 intact, 1 fully damaged).
    pub damage: f64,
    /// Mass fraction melted, in [0, 1] (from the EOS temperature model, paper §3.1). The
    /// built-in models take melting from the temperature instead (Johnson–Cook,
    /// Steinberg–Guinan); the field is there for user models and for the solver.
    pub melt_fraction: f64,
}

impl StrengthState {
    /// A state at pressure `pressure`, density `density` and temperature `temperature`,
    /// intact (D = 0), unstrained and unmelted.
    pub fn new(pressure: f64, density: f64, temperature: f64) -> Self {
        Self {
            pressure,
            density,
            temperature,
            ..Self::default()
        }
    }

    /// Checks every field against its physical range: pressure finite; density positive;
    /// temperature non-negative; plastic strain and its rate non-negative; damage and melt
    /// fraction in [0, 1]. All must be finite. Returns the first offending field.
    pub fn validate(&self) -> Result<(), StrengthError> {
        let bad = |field, value, reason| {
            Err(StrengthError::State {
                field,
                value,
                reason,
            })
        };
        if !self.pressure.is_finite() {
            return bad("pressure", self.pressure, "must be finite");
        }
        if !(self.density.is_finite() && self.density > 0.0) {
            return bad("density", self.density, "must be positive and finite");
        }
        if !(self.temperature.is_finite() && self.temperature >= 0.0) {
            return bad(
                "temperature",
                self.temperature,
                "must be non-negative and finite",
            );
        }
        if !(self.plastic_strain.is_finite() && self.plastic_strain >= 0.0) {
            return bad(
                "plastic_strain",
                self.plastic_strain,
                "must be non-negative and finite",
            );
        }
        if !(self.plastic_strain_rate.is_finite() && self.plastic_strain_rate >= 0.0) {
            return bad(
                "plastic_strain_rate",
                self.plastic_strain_rate,
                "must be non-negative and finite",
            );
        }
        if !(0.0..=1.0).contains(&self.damage) {
            return bad("damage", self.damage, "must lie in [0, 1]");
        }
        if !(0.0..=1.0).contains(&self.melt_fraction) {
            return bad("melt_fraction", self.melt_fraction, "must lie in [0, 1]");
        }
        Ok(())
    }
}

/// Shear modulus and yield strength evaluated together (see
/// [`StrengthModel::evaluate`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StrengthPoint {
    /// Shear modulus G (Pa).
    pub shear_modulus: f64,
    /// Yield strength Y including damage weakening (Pa).
    pub yield_strength: f64,
}

/// A strength model: shear modulus and yield strength as functions of the local state
/// (paper §3.2). Object safe, so user models plug in as `Box<dyn StrengthModel>`; the
/// built-in concrete types (and [`crate::BuiltinStrength`]) are the fast path.
///
/// Yield is in the von Mises sense: the material yields when the equivalent stress
/// √(3 J2) of the deviatoric stress reaches Y (see [`crate::radial_return()`]).
pub trait StrengthModel: Send + Sync + std::fmt::Debug {
    /// Name for output and messages.
    fn name(&self) -> &str;
    /// Shear modulus G (Pa) at this state.
    fn shear_modulus(&self, s: &StrengthState) -> f64;
    /// Undamaged yield strength Y_i (Pa), von Mises sense: yield when √(3 J2) = Y.
    fn intact_yield(&self, s: &StrengthState) -> f64;
    /// Yield strength including damage weakening (paper eqs 12/13), Pa.
    fn yield_strength(&self, s: &StrengthState) -> f64;
    /// False for fluids: the solver then skips deviatoric stress entirely.
    fn has_strength(&self) -> bool {
        true
    }
    /// The damaged shear modulus G(D) = (1 − D) G(state) with D = `s.damage`
    /// ([`crate::weakening::damaged_shear_modulus`]): one rule for every model, which the
    /// solver uses when damage weakens the moduli (paper §3.3; Spheral's
    /// ConstantStrength/CollinsStrength). Not meant to be overridden.
    #[inline]
    fn damaged_shear_modulus(&self, s: &StrengthState) -> f64 {
        crate::weakening::damaged_shear_modulus(self.shear_modulus(s), s.damage)
    }
    /// G and Y together. Models whose G and Y share work (Steinberg–Guinan) override it.
    #[inline]
    fn evaluate(&self, s: &StrengthState) -> StrengthPoint {
        StrengthPoint {
            shear_modulus: self.shear_modulus(s),
            yield_strength: self.yield_strength(s),
        }
    }
}

/// Forwarding so that `Box<dyn StrengthModel>` and `Arc<dyn StrengthModel>` (and boxed or
/// shared concrete models) can be used wherever a `M: StrengthModel` is expected.
macro_rules! forward_strength {
    ($($pointer:ty),*) => {$(
        impl<M: StrengthModel + ?Sized> StrengthModel for $pointer {
            fn name(&self) -> &str {
                (**self).name()
            }
            #[inline]
            fn shear_modulus(&self, s: &StrengthState) -> f64 {
                (**self).shear_modulus(s)
            }
            #[inline]
            fn intact_yield(&self, s: &StrengthState) -> f64 {
                (**self).intact_yield(s)
            }
            #[inline]
            fn yield_strength(&self, s: &StrengthState) -> f64 {
                (**self).yield_strength(s)
            }
            fn has_strength(&self) -> bool {
                (**self).has_strength()
            }
            #[inline]
            fn evaluate(&self, s: &StrengthState) -> StrengthPoint {
                (**self).evaluate(s)
            }
        }
    )*};
}

forward_strength!(Box<M>, std::sync::Arc<M>);

//! # sph-strength
//!
//! Shear strength of solids for SPH (paper §3.2): the [`StrengthModel`] trait giving the
//! shear modulus G and the yield strength Y from the local [`StrengthState`] (pressure,
//! density, temperature, plastic strain and its rate, damage); the built-in models
//! [`NoStrength`] (fluid), [`VonMises`] (constant, optionally linearly hardening),
//! [`DruckerPrager`], [`Lundborg`], [`JohnsonCook`] and [`SteinbergGuinan`]; damage
//! weakening exactly as paper eqs (12)/(13) ([`weakening`]); named parameter sets with
//! their sources ([`materials`]); and, as plain functions on 3×3 matrices, the Jaumann
//! stress rate ([`jaumann_rate`]) and the radial return to the yield surface
//! ([`radial_return()`]).
//!
//! All quantities are f64 in SI units; pressure is positive in compression; yield is in
//! the von Mises sense, √(3 J2) = Y.
//!
//! ```
//! use sph_strength::{materials, radial_return, jaumann_rate, Lundborg, StrengthModel, StrengthState};
//! use sph_core::glam::{DMat3, DVec3};
//!
//! // The study's basalt (paper Table 1) at 100 MPa, half damaged.
//! let basalt = Lundborg::new(materials::BASALT_LUNDBORG)?;
//! let mut state = StrengthState::new(100.0e6, 2876.0, 300.0);
//! state.damage = 0.5;
//! state.validate()?;
//! let y_i = basalt.intact_yield(&state); // 75.7 MPa
//! let y = basalt.yield_strength(&state); // eq. 13: ½·min(0.6 P, Y_i) + ½·Y_i
//! assert!((y - 0.5 * (60.0e6 + y_i)).abs() < 1.0);
//!
//! // One elastic-plastic stress update: Jaumann rate, then radial return.
//! let g = basalt.shear_modulus(&state);
//! let l = DMat3::from_cols(DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0e3, 0.0, 0.0), DVec3::ZERO);
//! let trial = DMat3::ZERO + jaumann_rate(&DMat3::ZERO, &l, g) * 1.0e-5;
//! let ret = radial_return(trial, y);
//! assert!(ret.yielded());
//! let dep = ret.plastic_strain_increment(g).unwrap();
//! assert!(dep > 0.0);
//! # Ok::<(), sph_strength::StrengthError>(())
//! ```
//!
//! User models implement [`StrengthModel`] and plug in as `Box<dyn StrengthModel>`; the
//! concrete types and the [`BuiltinStrength`] enum are the fast paths.
//!
//! ## Feature flags
//! None.

mod builtin;
pub mod drucker_prager;
mod error;
pub mod fluid;
pub mod jaumann;
pub mod johnson_cook;
pub mod lundborg;
pub mod materials;
mod model;
pub mod radial_return;
pub mod steinberg_guinan;
pub mod von_mises;
pub mod weakening;

pub use builtin::BuiltinStrength;
pub use drucker_prager::{DruckerPrager, DruckerPragerParams};
pub use error::StrengthError;
pub use fluid::NoStrength;
pub use jaumann::{deviator, jaumann_rate, rotation_terms, spin, strain_rate};
pub use johnson_cook::{JohnsonCook, JohnsonCookParams};
pub use lundborg::{Lundborg, LundborgParams, LundborgTension};
pub use model::{StrengthModel, StrengthPoint, StrengthState};
pub use radial_return::{ReturnResult, equivalent_stress, j2, radial_return};
pub use steinberg_guinan::{SgMeltLaw, SteinbergGuinan, SteinbergGuinanParams};
pub use von_mises::{LinearHardening, VonMises, VonMisesParams};
pub use weakening::{
    damaged_shear_modulus, damaged_strength, frictional_weakening, multiplicative_weakening,
};

/// Serde goes through the parameter struct: deserialising validates with `new`, and a
/// model serialises as its parameters. One line per model instead of two impl blocks.
#[macro_export]
#[doc(hidden)]
macro_rules! params_conversions {
    ($model:ty, $params:ty) => {
        impl TryFrom<$params> for $model {
            type Error = $crate::StrengthError;
            fn try_from(p: $params) -> Result<Self, $crate::StrengthError> {
                Self::new(p)
            }
        }
        impl From<$model> for $params {
            fn from(m: $model) -> Self {
                m.params
            }
        }
    };
}

//! [`BuiltinStrength`]: the built-in models as one enum, for scene files and for a
//! solver that wants one concrete type per material without a `Box<dyn>`.

use crate::NoStrength;
use crate::drucker_prager::DruckerPrager;
use crate::johnson_cook::JohnsonCook;
use crate::lundborg::Lundborg;
use crate::model::{StrengthModel, StrengthPoint, StrengthState};
use crate::steinberg_guinan::SteinbergGuinan;
use crate::von_mises::VonMises;
use serde::{Deserialize, Serialize};

/// One of the built-in strength models. Serialised with a `model` tag next to the
/// parameters (`{"model": "lundborg", "cohesion": 2.65e7, ...}`); deserialisation
/// validates the parameters and reports the bad field. Solvers `match` on it once to run
/// monomorphised code, or call it through [`StrengthModel`] (one branch per call).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "model", rename_all = "kebab-case")]
pub enum BuiltinStrength {
    /// [`NoStrength`] (fluid).
    None,
    /// [`VonMises`].
    VonMises(VonMises),
    /// [`DruckerPrager`].
    DruckerPrager(DruckerPrager),
    /// [`Lundborg`].
    Lundborg(Lundborg),
    /// [`JohnsonCook`].
    JohnsonCook(JohnsonCook),
    /// [`SteinbergGuinan`].
    SteinbergGuinan(SteinbergGuinan),
}

macro_rules! dispatch {
    ($self:ident, $m:ident => $e:expr) => {
        match $self {
            BuiltinStrength::None => {
                let $m = &NoStrength;
                $e
            }
            BuiltinStrength::VonMises($m) => $e,
            BuiltinStrength::DruckerPrager($m) => $e,
            BuiltinStrength::Lundborg($m) => $e,
            BuiltinStrength::JohnsonCook($m) => $e,
            BuiltinStrength::SteinbergGuinan($m) => $e,
        }
    };
}

impl StrengthModel for BuiltinStrength {
    fn name(&self) -> &str {
        match self {
            BuiltinStrength::None => "none",
            BuiltinStrength::VonMises(m) => m.name(),
            BuiltinStrength::DruckerPrager(m) => m.name(),
            BuiltinStrength::Lundborg(m) => m.name(),
            BuiltinStrength::JohnsonCook(m) => m.name(),
            BuiltinStrength::SteinbergGuinan(m) => m.name(),
        }
    }
    #[inline]
    fn shear_modulus(&self, s: &StrengthState) -> f64 {
        dispatch!(self, m => m.shear_modulus(s))
    }
    #[inline]
    fn intact_yield(&self, s: &StrengthState) -> f64 {
        dispatch!(self, m => m.intact_yield(s))
    }
    #[inline]
    fn yield_strength(&self, s: &StrengthState) -> f64 {
        dispatch!(self, m => m.yield_strength(s))
    }
    fn has_strength(&self) -> bool {
        !matches!(self, BuiltinStrength::None)
    }
    #[inline]
    fn evaluate(&self, s: &StrengthState) -> StrengthPoint {
        dispatch!(self, m => m.evaluate(s))
    }
}

impl From<NoStrength> for BuiltinStrength {
    fn from(_: NoStrength) -> Self {
        BuiltinStrength::None
    }
}

macro_rules! from_model {
    ($($t:ident),*) => {$(
        impl From<$t> for BuiltinStrength {
            fn from(m: $t) -> Self {
                BuiltinStrength::$t(m)
            }
        }
    )*};
}
from_model!(
    VonMises,
    DruckerPrager,
    Lundborg,
    JohnsonCook,
    SteinbergGuinan
);

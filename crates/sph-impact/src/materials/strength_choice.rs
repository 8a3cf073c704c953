//! [`StrengthChoice`]: the strength model of a material, one of the built-ins
//! ([`BuiltinStrength`], a `match` away from monomorphised code) or the user's own
//! (`Arc<dyn StrengthModel>`).

use sph_strength::{
    BuiltinStrength, DruckerPrager, JohnsonCook, Lundborg, NoStrength, SteinbergGuinan,
    StrengthModel, StrengthPoint, StrengthState, VonMises,
};
use std::sync::Arc;

/// The strength model of a material (paper §3.2).
#[derive(Clone, Debug)]
pub enum StrengthChoice {
    /// A built-in model (including [`BuiltinStrength::None`] for fluids).
    Builtin(BuiltinStrength),
    /// A user-defined model.
    Custom(Arc<dyn StrengthModel>),
}

impl StrengthChoice {
    /// No strength (a fluid).
    pub const NONE: StrengthChoice = StrengthChoice::Builtin(BuiltinStrength::None);

    /// Wraps a user-defined strength model.
    pub fn custom(model: impl StrengthModel + 'static) -> Self {
        Self::Custom(Arc::new(model))
    }

    /// False for [`StrengthChoice::Custom`].
    pub fn is_builtin(&self) -> bool {
        matches!(self, Self::Builtin(_))
    }

    /// The built-in model, if it is one.
    pub fn builtin(&self) -> Option<&BuiltinStrength> {
        match self {
            Self::Builtin(b) => Some(b),
            Self::Custom(_) => None,
        }
    }

    /// True for the built-ins whose yield strength depends on temperature (Johnson–Cook,
    /// Steinberg–Guinan): a material using them needs thermal data to get T from e.
    pub fn needs_temperature(&self) -> bool {
        matches!(
            self,
            Self::Builtin(BuiltinStrength::JohnsonCook(_) | BuiltinStrength::SteinbergGuinan(_))
        )
    }
}

impl Default for StrengthChoice {
    fn default() -> Self {
        Self::NONE
    }
}

/// Built-ins compare by parameters; user models by identity (the same `Arc`).
impl PartialEq for StrengthChoice {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Builtin(a), Self::Builtin(b)) => a == b,
            (Self::Custom(a), Self::Custom(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}

macro_rules! dispatch {
    ($self:ident, $m:ident => $e:expr) => {
        match $self {
            StrengthChoice::Builtin($m) => $e,
            StrengthChoice::Custom($m) => $e,
        }
    };
}

impl StrengthModel for StrengthChoice {
    fn name(&self) -> &str {
        dispatch!(self, m => m.name())
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
        dispatch!(self, m => m.has_strength())
    }
    #[inline]
    fn evaluate(&self, s: &StrengthState) -> StrengthPoint {
        dispatch!(self, m => m.evaluate(s))
    }
}

impl From<BuiltinStrength> for StrengthChoice {
    fn from(b: BuiltinStrength) -> Self {
        Self::Builtin(b)
    }
}

impl From<Arc<dyn StrengthModel>> for StrengthChoice {
    fn from(m: Arc<dyn StrengthModel>) -> Self {
        Self::Custom(m)
    }
}

macro_rules! from_model {
    ($($t:ident),*) => {$(
        impl From<$t> for StrengthChoice {
            fn from(m: $t) -> Self {
                Self::Builtin(BuiltinStrength::from(m))
            }
        }
    )*};
}
from_model!(
    NoStrength,
    VonMises,
    DruckerPrager,
    Lundborg,
    JohnsonCook,
    SteinbergGuinan
);

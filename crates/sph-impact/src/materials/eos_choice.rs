//! [`EosChoice`]: the equation of state of a material, a built-in (one concrete type per
//! variant, so a solver can `match` once and run monomorphised code) or the user's own
//! (`Arc<dyn EquationOfState>`).

use sph_eos::{
    EosError, EosPoint, EquationOfState, IdealGas, LinearElastic, MieGruneisen, Murnaghan,
    Tillotson,
};
use std::sync::Arc;

/// The equation of state of a material.
///
/// The built-in variants can be written to and read from TOML; [`EosChoice::Custom`]
/// holds any user type implementing [`EquationOfState`] (see
/// `examples/custom_material/main.rs`) and works everywhere else.
#[derive(Clone, Debug)]
pub enum EosChoice {
    /// [`Tillotson`] (Tillotson 1962; paper §3.1).
    Tillotson(Tillotson),
    /// [`MieGruneisen`] on a linear U_s–u_p Hugoniot.
    MieGruneisen(MieGruneisen),
    /// [`Murnaghan`] (Murnaghan 1944).
    Murnaghan(Murnaghan),
    /// [`LinearElastic`], P = K0 μ.
    LinearElastic(LinearElastic),
    /// [`IdealGas`], P = (γ − 1)ρe.
    IdealGas(IdealGas),
    /// A user-defined equation of state.
    Custom(Arc<dyn EquationOfState>),
}

impl EosChoice {
    /// Wraps a user-defined equation of state.
    pub fn custom(eos: impl EquationOfState + 'static) -> Self {
        Self::Custom(Arc::new(eos))
    }

    /// False for [`EosChoice::Custom`].
    pub fn is_builtin(&self) -> bool {
        !matches!(self, Self::Custom(_))
    }

    /// As a shared trait object (what the current fluid solver's
    /// [`Material`](crate::Material) holds).
    pub fn shared(&self) -> Arc<dyn EquationOfState> {
        match self {
            Self::Custom(eos) => Arc::clone(eos),
            other => Arc::new(other.clone()),
        }
    }
}

/// Built-ins compare by parameters; user models by identity (the same `Arc`).
impl PartialEq for EosChoice {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Self::Tillotson(a), Self::Tillotson(b)) => a == b,
            (Self::MieGruneisen(a), Self::MieGruneisen(b)) => a == b,
            (Self::Murnaghan(a), Self::Murnaghan(b)) => a == b,
            (Self::LinearElastic(a), Self::LinearElastic(b)) => a == b,
            (Self::IdealGas(a), Self::IdealGas(b)) => a == b,
            (Self::Custom(a), Self::Custom(b)) => Arc::ptr_eq(a, b),
            _ => false,
        }
    }
}

macro_rules! dispatch {
    ($self:ident, $m:ident => $e:expr) => {
        match $self {
            EosChoice::Tillotson($m) => $e,
            EosChoice::MieGruneisen($m) => $e,
            EosChoice::Murnaghan($m) => $e,
            EosChoice::LinearElastic($m) => $e,
            EosChoice::IdealGas($m) => $e,
            EosChoice::Custom($m) => $e,
        }
    };
}

impl EquationOfState for EosChoice {
    fn name(&self) -> &str {
        dispatch!(self, m => m.name())
    }
    fn reference_density(&self) -> Option<f64> {
        dispatch!(self, m => m.reference_density())
    }
    fn reference_sound_speed(&self) -> Option<f64> {
        dispatch!(self, m => m.reference_sound_speed())
    }
    #[inline]
    fn pressure(&self, rho: f64, e: f64) -> f64 {
        dispatch!(self, m => m.pressure(rho, e))
    }
    #[inline]
    fn evaluate(&self, rho: f64, e: f64) -> EosPoint {
        dispatch!(self, m => m.evaluate(rho, e))
    }
    #[inline]
    fn sound_speed(&self, rho: f64, e: f64) -> f64 {
        dispatch!(self, m => m.sound_speed(rho, e))
    }
    fn check_state(&self, rho: f64, e: f64) -> Result<(), EosError> {
        dispatch!(self, m => m.check_state(rho, e))
    }
    fn checked_evaluate(&self, rho: f64, e: f64) -> Result<EosPoint, EosError> {
        dispatch!(self, m => m.checked_evaluate(rho, e))
    }
}

macro_rules! from_eos {
    ($($t:ident),*) => {$(
        impl From<$t> for EosChoice {
            fn from(eos: $t) -> Self {
                EosChoice::$t(eos)
            }
        }
    )*};
}
from_eos!(Tillotson, MieGruneisen, Murnaghan, LinearElastic, IdealGas);

impl From<Arc<dyn EquationOfState>> for EosChoice {
    fn from(eos: Arc<dyn EquationOfState>) -> Self {
        EosChoice::Custom(eos)
    }
}

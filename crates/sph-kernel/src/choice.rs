//! Run-time kernel selection for scene files, dispatched once to a concrete type.

use crate::{CubicSpline, Kernel, WendlandC2, WendlandC4, WendlandC6};
use serde::{Deserialize, Serialize};

/// The built-in kernels by name (`"wendland-c2"`, …), for configuration files. Solvers
/// `match` on it once and run monomorphised code for the concrete kernel; it also
/// implements [`Kernel`] itself (with a branch per call) for convenience.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum KernelChoice {
    /// [`WendlandC2`], the study's default.
    #[default]
    WendlandC2,
    /// [`WendlandC4`].
    WendlandC4,
    /// [`WendlandC6`].
    WendlandC6,
    /// [`CubicSpline`].
    CubicSpline,
}

impl KernelChoice {
    /// All built-in kernels.
    pub const ALL: [KernelChoice; 4] = [
        KernelChoice::WendlandC2,
        KernelChoice::WendlandC4,
        KernelChoice::WendlandC6,
        KernelChoice::CubicSpline,
    ];
}

macro_rules! dispatch {
    ($self:ident, $k:ident => $e:expr) => {
        match $self {
            KernelChoice::WendlandC2 => {
                let $k = WendlandC2;
                $e
            }
            KernelChoice::WendlandC4 => {
                let $k = WendlandC4;
                $e
            }
            KernelChoice::WendlandC6 => {
                let $k = WendlandC6;
                $e
            }
            KernelChoice::CubicSpline => {
                let $k = CubicSpline;
                $e
            }
        }
    };
}

impl Kernel for KernelChoice {
    fn name(&self) -> &'static str {
        dispatch!(self, k => k.name())
    }
    #[inline]
    fn f(&self, q: f64) -> f64 {
        dispatch!(self, k => k.f(q))
    }
    #[inline]
    fn df(&self, q: f64) -> f64 {
        dispatch!(self, k => k.df(q))
    }
    #[inline]
    fn sigma(&self, dim: usize) -> f64 {
        dispatch!(self, k => k.sigma(dim))
    }
}

impl std::str::FromStr for KernelChoice {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        KernelChoice::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = KernelChoice::ALL.iter().map(|k| k.name()).collect();
                format!("unknown kernel '{s}' (known: {})", names.join(", "))
            })
    }
}

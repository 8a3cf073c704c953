//! Weibull flaw parameters n(ε) = k ε^m (flaws per unit volume with activation strain
//! below ε; Weibull 1939, as used by Grady & Kipp 1980 and Benz & Asphaug 1994), with
//! the named sets found in the literature.

use crate::error::{DamageError, positive};
use serde::{Deserialize, Serialize};

/// Weibull parameters: `k` in m⁻³, `m` dimensionless. Validated on construction and on
/// deserialisation: both positive and finite.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "WeibullParamsUnchecked")]
pub struct WeibullParams {
    k: f64,
    m: f64,
}

#[derive(Deserialize)]
struct WeibullParamsUnchecked {
    k: f64,
    m: f64,
}

impl TryFrom<WeibullParamsUnchecked> for WeibullParams {
    type Error = DamageError;
    fn try_from(raw: WeibullParamsUnchecked) -> Result<Self, DamageError> {
        WeibullParams::new(raw.k, raw.m)
    }
}

impl WeibullParams {
    /// The study's basalt (paper §6, Table 1): k = 2.7e41 m⁻³, m = 10.0.
    pub const BASALT_STUDY: WeibullParams = WeibullParams { k: 2.7e41, m: 10.0 };
    /// Basalt, Benz & Asphaug 1999 (Icarus 142:5, Table II): k = 4e29 cm⁻³ = 4e35 m⁻³,
    /// m = 9.
    pub const BASALT_BA99: WeibullParams = WeibullParams { k: 4.0e35, m: 9.0 };
    /// Basalt, Benz & Asphaug 1994 (Icarus 107:98) fit to Nakamura & Fujiwara 1991:
    /// k = 5e34 m⁻³, m = 8.5.
    pub const BASALT_BA94: WeibullParams = WeibullParams { k: 5.0e34, m: 8.5 };
    /// Basalt, Schäfer et al. 2016 (A&A 590:A19): k = 5e34 m⁻³, m = 8.
    pub const BASALT_SCHAEFER16: WeibullParams = WeibullParams { k: 5.0e34, m: 8.0 };
    /// Basalt, measured by Nakamura et al. 2007 (m = 15–17, k = 1e57–1e65 m⁻³); the
    /// central values k = 1e61 m⁻³, m = 16 of
    /// docs/reference/weibull_flaws.md, "Parameter sets".
    pub const BASALT_NAKAMURA07: WeibullParams = WeibullParams { k: 1.0e61, m: 16.0 };
    /// Ice, Benz & Asphaug 1999 (Icarus 142:5, Table II): k = 1.4e38 m⁻³, m = 9.6.
    pub const ICE_BA99: WeibullParams = WeibullParams { k: 1.4e38, m: 9.6 };

    /// All named sets with their citation, for scene files and documentation.
    pub const NAMED: [NamedWeibull; 6] = [
        NamedWeibull {
            name: "basalt-study",
            params: Self::BASALT_STUDY,
            citation: "the reference study, paper §6 Table 1",
        },
        NamedWeibull {
            name: "basalt-ba99",
            params: Self::BASALT_BA99,
            citation: "Benz & Asphaug 1999, Icarus 142:5, Table II",
        },
        NamedWeibull {
            name: "basalt-ba94",
            params: Self::BASALT_BA94,
            citation: "Benz & Asphaug 1994, Icarus 107:98",
        },
        NamedWeibull {
            name: "basalt-schaefer16",
            params: Self::BASALT_SCHAEFER16,
            citation: "Schäfer et al. 2016, A&A 590:A19",
        },
        NamedWeibull {
            name: "basalt-nakamura07",
            params: Self::BASALT_NAKAMURA07,
            citation: "Nakamura et al. 2007 (central values of m = 15–17, k = 1e57–1e65)",
        },
        NamedWeibull {
            name: "ice-ba99",
            params: Self::ICE_BA99,
            citation: "Benz & Asphaug 1999, Icarus 142:5, Table II",
        },
    ];

    /// Validated parameters: `k` (m⁻³) and `m` positive and finite.
    pub fn new(k: f64, m: f64) -> Result<Self, DamageError> {
        Ok(WeibullParams {
            k: positive("k", k)?,
            m: positive("m", m)?,
        })
    }

    /// A named set (`"basalt-study"`, `"basalt-ba99"`, …; see [`WeibullParams::NAMED`]).
    pub fn named(name: &str) -> Option<WeibullParams> {
        Self::NAMED
            .iter()
            .find(|n| n.name == name)
            .map(|n| n.params)
    }

    /// k, flaws per m³ at unit strain.
    pub fn k(&self) -> f64 {
        self.k
    }

    /// m, the Weibull modulus.
    pub fn m(&self) -> f64 {
        self.m
    }

    /// The smallest activation strain in a volume V, ε_min = (kV)^(−1/m): the strain at
    /// which one flaw is expected (n(ε) V = 1). See [`crate::min_activation_strain`].
    pub fn min_activation_strain(&self, volume: f64) -> f64 {
        crate::min_activation_strain(self.k, self.m, volume)
    }

    /// Static tensile strength of a volume V, σ_b = E (kV)^(−1/m). See
    /// [`crate::static_strength`].
    pub fn static_strength(&self, youngs_modulus: f64, volume: f64) -> f64 {
        crate::static_strength(youngs_modulus, self.k, self.m, volume)
    }
}

/// A named Weibull parameter set with its source.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NamedWeibull {
    /// Name used in scene files.
    pub name: &'static str,
    /// The parameters.
    pub params: WeibullParams,
    /// Where they come from.
    pub citation: &'static str,
}

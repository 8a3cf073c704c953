//! Derived metrics: numbers of a point that come from its scene rather than from its run,
//! such as the static tensile strength of a named volume of a body's material, so that a
//! study (or a fit) can show and constrain what its Weibull parameters mean.

use crate::scene::Scene;
use serde::{Deserialize, Serialize};

/// The static tensile strength (Pa) of `volume` (m³) of body `body`'s material:
/// E (kV)^(−1/m) for Benz–Asphaug flaws, σ_b for the maximum tensile stress (paper §3.3;
/// `DamageSpec::static_strength`). The study's Brazilian disc, Ø50 × 50 mm, is
/// 9.817e-5 m³ (9.62 MPa with the bundled basalt); its cylinder 1.472e-3 m³ (7.34 MPa).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StaticStrength {
    /// The body's name.
    pub body: String,
    /// The volume, m³.
    pub volume: f64,
}

/// A named derived metric: `[[derived]] name = "…"` with what it computes
/// (`static_strength = { body = "target", volume = 9.817e-5 }`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Derived {
    /// Its column name (not a key of summary.json).
    pub name: String,
    /// The static tensile strength of a volume of a body's material.
    pub static_strength: StaticStrength,
}

impl Derived {
    /// Its value for a point's scene; `Err` says why it has none.
    pub fn value(&self, scene: &Scene) -> Result<f64, String> {
        let StaticStrength { body, volume } = &self.static_strength;
        if !(volume.is_finite() && *volume > 0.0) {
            return Err(format!("the volume must be positive, in m³, not {volume}"));
        }
        let b = scene
            .bodies
            .iter()
            .find(|b| b.name == *body)
            .ok_or_else(|| {
                let names: Vec<&str> = scene.bodies.iter().map(|b| b.name.as_str()).collect();
                format!(
                    "the scene has no body named `{body}` (its bodies: {})",
                    names.join(", ")
                )
            })?;
        let spec = b
            .material
            .resolve(&b.name)
            .map_err(|(_, e)| format!("body `{body}`'s material: {e}"))?;
        let e = spec
            .youngs_modulus()
            .ok_or_else(|| format!("body `{body}`'s material has no Young's modulus (a fluid)"))?;
        spec.damage.static_strength(e, *volume).ok_or_else(|| {
            format!("body `{body}`'s material has no damage model, so no static strength")
        })
    }
}

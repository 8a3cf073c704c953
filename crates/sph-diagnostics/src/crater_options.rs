//! Parameters of the crater measurement (docs/diagnostics.md §4): radial bins, which
//! target particles count as wall, and the thresholds that define the crater and its
//! central bowl.

use crate::error::{ImpactError, finite, positive};
use crate::particles_view::Geometry;
use serde::{Deserialize, Serialize};

/// Material whose density fell below `min_fraction × reference_density` is not wall:
/// fully comminuted, dilated rubble would be swept out of a real crater before it is
/// measured.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct DensityCut {
    /// Reference density ρ_ref (kg/m³), e.g. the target's initial density.
    pub reference_density: f64,
    /// Fraction of ρ_ref below which a particle is excluded (dimensionless, in (0, 1]).
    pub min_fraction: f64,
}

/// How [`crater_profile`](crate::crater_profile::crater_profile) bins and filters and how
/// [`measure_crater`](crate::crater::measure_crater) reads the profile.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CraterOptions {
    /// 3-D (radius √(x²+y²)) or RZ (radius |x|).
    pub geometry: Geometry,
    /// Radial bin width (m); default the particle spacing near the impact point.
    pub bin: f64,
    /// A bin is crater when its depth exceeds this (m); default one particle spacing, so
    /// the particle-scale roughness of an undisturbed surface is not crater.
    pub depth_threshold: f64,
    /// The central bowl is where the depth is at least this fraction of the crater depth
    /// (dimensionless, in (0, 1]; default 0.5): the steep-walled pit inside the shallow
    /// spall zone, whose floor lies well below half the maximum depth.
    pub bowl_fraction: f64,
    /// Height of the original surface above the centres of the top particle layer (m,
    /// default 0): depth is measured from `surface_z − top_offset`, so that an untouched
    /// bed reads zero. Use Δp/2 for a lattice whose top layer sits half a spacing down.
    pub top_offset: f64,
    /// Each wall particle covers the bins within half its own spacing of its radius,
    /// not only the bin of its centre (needs densities in the view; default `false`).
    /// The spacing is the particle's size from its volume m/ρ: (m/ρ)^(1/3) in 3-D, and
    /// in RZ the side of the ring's cross-section m/(2πρr), the ring's radius being at
    /// least half its side. With variable-resolution placement the particles away from
    /// the impact point are spaced wider than the bins, and a bin that no top-layer
    /// particle's centre falls in would read the top of a deeper one as its floor
    /// (docs/diagnostics.md §4.1).
    #[serde(default)]
    pub footprint: bool,
    /// How many mirror copies each particle's mass in the view stands for (≥ 1; default
    /// 1): 4 for a 3-D quarter model, whose particles carry the mass of their four
    /// mirror images so that totals are the whole body's. The footprint's spacing is one
    /// copy's size, (m/(copies ρ))^(1/3); the whole mass would widen every footprint by
    /// 4^(1/3) and read a shallower floor (docs/diagnostics.md §4.1).
    #[serde(default = "one_copy")]
    pub copies: f64,
    /// Optional low-density cut (needs densities in the view).
    pub density_cut: Option<DensityCut>,
    /// Optional: particles with damage above this are not wall (needs damage in the view).
    /// Default `None`: a crater is where material was *removed*, and damaged rock still in
    /// place is still there (the study's damaged-but-intact walls, paper §7).
    pub max_damage: Option<f64>,
    /// Optional: the diameter of the whole crater counts target material with damage
    /// above this as *spall*, removed (needs damage in the view). The experiment's
    /// diameter includes the spall zone, measured after the loose, fully fractured plates
    /// around the bowl have come off; at the end of a run they are still in place or
    /// barely lifted. Only the diameter reads the spall profile: the depth and the bowl
    /// stay those of the material actually removed, since the crushed rock under the
    /// bowl, also fully damaged, stays in place (docs/diagnostics.md §4.3).
    pub spall_damage: Option<f64>,
}

/// The serde default of [`CraterOptions::copies`]: a particle stands for itself.
fn one_copy() -> f64 {
    1.0
}

impl CraterOptions {
    /// Default fraction of the crater depth that defines the bowl.
    pub const DEFAULT_BOWL_FRACTION: f64 = 0.5;

    /// Defaults for particle spacing `spacing` (m): bin and depth threshold = spacing,
    /// bowl fraction 0.5, no offset, no footprint, no density or damage cut.
    pub fn new(geometry: Geometry, spacing: f64) -> Self {
        Self {
            geometry,
            bin: spacing,
            depth_threshold: spacing,
            bowl_fraction: Self::DEFAULT_BOWL_FRACTION,
            top_offset: 0.0,
            footprint: false,
            copies: 1.0,
            density_cut: None,
            max_damage: None,
            spall_damage: None,
        }
    }

    /// Checks every parameter's range.
    pub fn check(&self) -> Result<(), ImpactError> {
        positive("bin", self.bin)?;
        finite("depth_threshold", self.depth_threshold)?;
        finite("top_offset", self.top_offset)?;
        if !(self.copies >= 1.0 && self.copies.is_finite()) {
            return Err(ImpactError::BadParameter {
                name: "copies",
                value: self.copies,
                reason: "must be finite and ≥ 1 (mirror copies per particle)",
            });
        }
        if !(self.bowl_fraction > 0.0 && self.bowl_fraction <= 1.0) {
            return Err(ImpactError::BadParameter {
                name: "bowl_fraction",
                value: self.bowl_fraction,
                reason: "must be in (0, 1]",
            });
        }
        if let Some(cut) = self.density_cut {
            positive("reference_density", cut.reference_density)?;
            if !(cut.min_fraction > 0.0 && cut.min_fraction <= 1.0) {
                return Err(ImpactError::BadParameter {
                    name: "min_fraction",
                    value: cut.min_fraction,
                    reason: "must be in (0, 1]",
                });
            }
        }
        if let Some(d) = self.max_damage
            && !(0.0..=1.0).contains(&d)
        {
            return Err(ImpactError::BadParameter {
                name: "max_damage",
                value: d,
                reason: "must be in [0, 1]",
            });
        }
        if let Some(d) = self.spall_damage
            && !(0.0..1.0).contains(&d)
        {
            return Err(ImpactError::BadParameter {
                name: "spall_damage",
                value: d,
                reason: "must be in [0, 1) (damage above it is spall)",
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_and_range_checks() {
        let o = CraterOptions::new(Geometry::ThreeD, 5e-4);
        assert_eq!(
            (o.bin, o.depth_threshold, o.bowl_fraction),
            (5e-4, 5e-4, 0.5)
        );
        assert_eq!(o.check(), Ok(()));
        let bad = [
            CraterOptions { bin: 0.0, ..o },
            CraterOptions { copies: 0.5, ..o },
            CraterOptions {
                copies: f64::INFINITY,
                ..o
            },
            CraterOptions {
                bowl_fraction: 0.0,
                ..o
            },
            CraterOptions {
                top_offset: f64::NAN,
                ..o
            },
            CraterOptions {
                max_damage: Some(1.5),
                ..o
            },
            CraterOptions {
                spall_damage: Some(1.0),
                ..o
            },
            CraterOptions {
                spall_damage: Some(-0.1),
                ..o
            },
            CraterOptions {
                density_cut: Some(DensityCut {
                    reference_density: 2876.0,
                    min_fraction: 0.0,
                }),
                ..o
            },
        ];
        for b in bad {
            assert!(b.check().is_err(), "{b:?}");
        }
    }
}

//! The crater profile: how deep the target's surface lies below its original height, as a
//! function of the distance from the impact axis (paper §5; docs/diagnostics.md §4).
//!
//! **Method.** Keep the target's *wall* particles: target bodies, not ejecta (same
//! criterion as module `ejecta`), and, if asked, not below a density cut nor above a
//! damage cut. Bin them by radius s from the axis (√(x²+y²) in 3-D, |x| in RZ) in bins
//! [k b, (k+1) b). In each bin the *floor* is the highest particle centre: material still
//! there. The depth is
//!
//! ```text
//! depth(s) = (surface_z − top_offset) − floor(s),
//! ```
//!
//! signed: a raised rim reads negative, nothing is clamped. A bin with no wall particle
//! has depth NaN — no evidence either way; `crater::measure_crater` says how it reads them.

use crate::crater_options::CraterOptions;
use crate::ejecta::EjectaCriterion;
use crate::error::ImpactError;
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// Most radial bins a profile may have (a stray particle far out would otherwise make a
/// huge, almost empty profile).
pub const MAX_PROFILE_BINS: usize = 1 << 22;

/// Crater depth against radius, one entry per radial bin from the axis outwards.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct CraterProfile {
    /// Bin centres (k + ½) b (m).
    pub radius: Vec<f64>,
    /// Signed depth below the original surface (m): positive in the crater, negative on
    /// a raised rim, NaN where the bin holds no wall particle.
    pub depth: Vec<f64>,
}

impl CraterProfile {
    /// Height of the highest raised rim above the original surface (m): the largest
    /// −depth over the non-empty bins, or 0 if nothing stands above the surface.
    pub fn rim_height(&self) -> f64 {
        self.depth
            .iter()
            .filter(|d| !d.is_nan())
            .fold(0.0f64, |h, &d| h.max(-d))
    }

    /// Number of bins.
    pub fn len(&self) -> usize {
        self.radius.len()
    }

    /// True for a profile of no bins.
    pub fn is_empty(&self) -> bool {
        self.radius.is_empty()
    }
}

/// True if particle `i` is crater wall: a target particle that is not ejecta and passes
/// the density and damage cuts of `options`.
pub fn is_wall(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
    i: usize,
) -> bool {
    if !criterion.is_target(view.body[i]) || criterion.is_ejecta(view, i) {
        return false;
    }
    if let (Some(cut), Some(rho)) = (options.density_cut, view.density)
        && rho[i] < cut.min_fraction * cut.reference_density
    {
        return false;
    }
    if let (Some(max), Some(d)) = (options.max_damage, view.damage)
        && d[i] > max
    {
        return false;
    }
    true
}

/// The crater profile of `view` (validated first). Errors: a bad criterion or option, a
/// cut whose array the view lacks, no wall particle at all, or more than
/// [`MAX_PROFILE_BINS`] bins.
pub fn crater_profile(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
) -> Result<CraterProfile, ImpactError> {
    view.validate()?;
    criterion.check()?;
    options.check()?;
    if options.density_cut.is_some() && view.density.is_none() {
        return Err(ImpactError::MissingField("density"));
    }
    if options.max_damage.is_some() && view.damage.is_none() {
        return Err(ImpactError::MissingField("damage"));
    }
    let wall: Vec<(f64, f64)> = (0..view.len())
        .filter(|&i| is_wall(view, criterion, options, i))
        .map(|i| {
            let p = view.position[i];
            (options.geometry.radius(p) / options.bin, p[2])
        })
        .collect();
    if wall.is_empty() {
        return Err(ImpactError::EmptySelection("no target wall particles"));
    }
    let needed = wall.iter().fold(0.0f64, |a, w| a.max(w.0)).floor() + 1.0;
    if needed > MAX_PROFILE_BINS as f64 {
        return Err(ImpactError::TooManyBins {
            what: "crater profile",
            count: needed,
            limit: MAX_PROFILE_BINS,
        });
    }
    let n = needed as usize;
    let mut floor = vec![f64::NEG_INFINITY; n];
    for (s, z) in wall {
        let k = (s.floor() as usize).min(n - 1);
        floor[k] = floor[k].max(z);
    }
    let top = criterion.surface_z - options.top_offset;
    Ok(CraterProfile {
        radius: (0..n).map(|k| (k as f64 + 0.5) * options.bin).collect(),
        depth: floor
            .iter()
            .map(|&f| if f.is_finite() { top - f } else { f64::NAN })
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crater_options::DensityCut;
    use crate::ejecta::tests::Arrays;
    use crate::particles_view::Geometry;

    /// RZ columns at r = 0.5, 1.5, 2.5, 4.5 (bin 3 empty), with chosen tops.
    fn columns() -> Arrays {
        let mut p = Vec::new();
        for (r, top) in [(0.5, -3.0), (1.5, -2.0), (2.5, 0.5), (4.5, 0.0)] {
            for k in 0..5 {
                p.push([r, 0.0, top - k as f64]);
            }
        }
        let n = p.len();
        (p, vec![[0.0; 3]; n], vec![1.0; n], vec![1; n])
    }

    #[test]
    fn hand_made_columns() {
        let (p, v, m, b) = columns();
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = EjectaCriterion::new(&[1], 0.0);
        let o = CraterOptions::new(Geometry::Axisymmetric, 1.0);
        let prof = crater_profile(&view, &c, &o).unwrap();
        assert_eq!(prof.radius, vec![0.5, 1.5, 2.5, 3.5, 4.5]);
        assert_eq!(&prof.depth[..3], &[3.0, 2.0, -0.5]);
        assert!(prof.depth[3].is_nan());
        assert_eq!(prof.depth[4], 0.0);
        assert_eq!(prof.rim_height(), 0.5);
        // A top offset of 0.25 m lowers the reference plane.
        let o2 = CraterOptions {
            top_offset: 0.25,
            ..o
        };
        assert_eq!(crater_profile(&view, &c, &o2).unwrap().depth[0], 2.75);
    }

    #[test]
    fn ejecta_projectile_and_cut_particles_are_not_wall() {
        let (mut p, mut v, mut m, mut b) = columns();
        // Rising target particle above the axis bin: ejecta, ignored.
        p.push([0.2, 0.0, 5.0]);
        v.push([0.0, 0.0, 1.0]);
        m.push(1.0);
        b.push(1);
        // Projectile remnant in the crater: not target, ignored.
        p.push([0.3, 0.0, -0.5]);
        v.push([0.0; 3]);
        m.push(1.0);
        b.push(0);
        let n = p.len();
        let mut rho = vec![1000.0; n];
        let mut dmg = vec![0.0; n];
        rho[5] = 100.0; // the top of column 2 (z = −2) is rubble
        dmg[0] = 1.0; // the top of column 1 (z = −3) is fully damaged
        let view = ParticleView::new(&p, &v, &m, &b)
            .with_density(&rho)
            .with_damage(&dmg);
        let c = EjectaCriterion::new(&[1], 0.0);
        let o = CraterOptions::new(Geometry::Axisymmetric, 1.0);
        let prof = crater_profile(&view, &c, &o).unwrap();
        assert_eq!(&prof.depth[..2], &[3.0, 2.0]);
        let cut = CraterOptions {
            density_cut: Some(DensityCut {
                reference_density: 1000.0,
                min_fraction: 0.5,
            }),
            max_damage: Some(0.99),
            ..o
        };
        let prof = crater_profile(&view, &c, &cut).unwrap();
        assert_eq!(&prof.depth[..2], &[4.0, 3.0]);
        let bare = ParticleView::new(&p, &v, &m, &b);
        assert_eq!(
            crater_profile(&bare, &c, &cut),
            Err(ImpactError::MissingField("density"))
        );
    }

    #[test]
    fn errors_instead_of_panics() {
        let (p, v, m, b) = columns();
        let view = ParticleView::new(&p, &v, &m, &b);
        let o = CraterOptions::new(Geometry::ThreeD, 1.0);
        let none = EjectaCriterion::new(&[9], 0.0);
        assert!(matches!(
            crater_profile(&view, &none, &o),
            Err(ImpactError::EmptySelection(_))
        ));
        let tiny = CraterOptions::new(Geometry::ThreeD, 1e-9);
        assert!(matches!(
            crater_profile(&view, &EjectaCriterion::new(&[1], 0.0), &tiny),
            Err(ImpactError::TooManyBins { .. })
        ));
    }
}

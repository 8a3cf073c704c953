//! Ejecta mass and momentum against normalised axial speed v_z/U (paper §5: the study
//! plots both, binned and cumulative; U is the impact speed).
//!
//! The speed is the axial component v_z, the one that carries the momentum β is made of;
//! every ejecta particle has v_z > 0 (module `ejecta`). The cumulative form M(≥ v) is the
//! one used for ejecta scaling (Housen & Holsapple 2011, Icarus 211, 856).

use crate::ejecta::EjectaCriterion;
use crate::error::{ImpactError, positive};
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// Most bins [`ejecta_distribution`] will allocate.
pub const MAX_EJECTA_BINS: usize = 1_000_000;

/// Ejecta in one bin lo ≤ v_z/U < hi.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EjectaBin {
    /// Lower edge of v_z/U (dimensionless).
    pub v_over_u_lo: f64,
    /// Upper edge of v_z/U (dimensionless).
    pub v_over_u_hi: f64,
    /// Ejecta mass in the bin (kg).
    pub mass: f64,
    /// Ejecta axial momentum Σ m v_z in the bin (kg·m/s).
    pub momentum_z: f64,
}

/// Ejecta binned by v_z/U in bins [k w, (k+1) w), k = 0, 1, … up to the bin of the
/// fastest particle; `impact_speed` U (m/s) and `bin_width` w (dimensionless) positive.
///
/// Bins start at 0 and have a fixed width, so runs and snapshots share edges and no
/// ejecta fall outside; no ejecta gives no bins. More than [`MAX_EJECTA_BINS`] bins
/// (a stray very fast particle) is an error.
pub fn ejecta_distribution(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    impact_speed: f64,
    bin_width: f64,
) -> Result<Vec<EjectaBin>, ImpactError> {
    let u = positive("impact_speed", impact_speed)?;
    let w = positive("bin_width", bin_width)?;
    let samples = ejecta_samples(view, criterion, u)?;
    if samples.is_empty() {
        return Ok(Vec::new());
    }
    let top = samples.iter().fold(0.0f64, |a, s| a.max(s.0));
    let needed = (top / w).floor() + 1.0;
    if needed > MAX_EJECTA_BINS as f64 {
        return Err(ImpactError::TooManyBins {
            what: "ejecta v_z/U",
            count: needed,
            limit: MAX_EJECTA_BINS,
        });
    }
    let mut bins: Vec<EjectaBin> = (0..needed as usize)
        .map(|k| EjectaBin {
            v_over_u_lo: k as f64 * w,
            v_over_u_hi: (k + 1) as f64 * w,
            ..EjectaBin::default()
        })
        .collect();
    for (x, m, p) in samples {
        let k = ((x / w).floor() as usize).min(bins.len() - 1);
        bins[k].mass += m;
        bins[k].momentum_z += p;
    }
    Ok(bins)
}

/// Ejecta mass and momentum with v_z/U ≥ v, at every distinct v of the ejecta.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct EjectaCumulative {
    /// Distinct values of v_z/U, increasing (dimensionless).
    pub v_over_u: Vec<f64>,
    /// Mass of ejecta with v_z/U ≥ `v_over_u[i]` (kg); non-increasing, first = total.
    pub mass: Vec<f64>,
    /// Axial momentum of ejecta with v_z/U ≥ `v_over_u[i]` (kg·m/s).
    pub momentum_z: Vec<f64>,
}

impl EjectaCumulative {
    /// Mass (kg) and axial momentum (kg·m/s) of the ejecta with v_z/U ≥ `v_over_u`.
    pub fn at(&self, v_over_u: f64) -> (f64, f64) {
        let i = self.v_over_u.partition_point(|&x| x < v_over_u);
        match (self.mass.get(i), self.momentum_z.get(i)) {
            (Some(&m), Some(&p)) => (m, p),
            _ => (0.0, 0.0),
        }
    }
}

/// Cumulative ejecta mass and momentum against v_z/U, exact (no binning).
pub fn ejecta_cumulative(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    impact_speed: f64,
) -> Result<EjectaCumulative, ImpactError> {
    let u = positive("impact_speed", impact_speed)?;
    let mut samples = ejecta_samples(view, criterion, u)?;
    // Fastest first, so the running sums are "speed ≥ v"; ties share one point.
    samples.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut c = EjectaCumulative::default();
    let (mut m, mut p) = (0.0, 0.0);
    for (k, &(x, dm, dp)) in samples.iter().enumerate() {
        m += dm;
        p += dp;
        if samples.get(k + 1).is_none_or(|next| next.0 != x) {
            c.v_over_u.push(x);
            c.mass.push(m);
            c.momentum_z.push(p);
        }
    }
    c.v_over_u.reverse();
    c.mass.reverse();
    c.momentum_z.reverse();
    Ok(c)
}

/// (v_z/U, m, m v_z) of each ejecta particle, in index order.
fn ejecta_samples(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    u: f64,
) -> Result<Vec<(f64, f64, f64)>, ImpactError> {
    view.validate()?;
    criterion.check()?;
    Ok((0..view.len())
        .filter(|&i| criterion.is_ejecta(view, i))
        .map(|i| {
            let (m, vz) = (view.mass[i], view.velocity[i][2]);
            (vz / u, m, m * vz)
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ejecta::{ejecta, tests::six};
    use proptest::prelude::*;

    #[test]
    fn hand_made_bins_and_cumulative() {
        // Ejecta of `six`: m = 2 at v_z = 3, m = 6 at v_z = 4; U = 10.
        let (p, v, m, b) = six();
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = EjectaCriterion::new(&[1, 2], 0.0);
        let bins = ejecta_distribution(&view, &c, 10.0, 0.25).unwrap();
        assert_eq!(bins.len(), 2);
        assert_eq!((bins[0].v_over_u_lo, bins[0].v_over_u_hi), (0.0, 0.25));
        assert_eq!((bins[1].mass, bins[1].momentum_z), (8.0, 30.0));
        // v_z/U = 0.3 and 0.4 fall in [0.24, 0.36) and [0.36, 0.48).
        let bins = ejecta_distribution(&view, &c, 10.0, 0.12).unwrap();
        assert_eq!(bins.len(), 4);
        let masses: Vec<f64> = bins.iter().map(|b| b.mass).collect();
        assert_eq!(masses, vec![0.0, 0.0, 2.0, 6.0]);
        let cum = ejecta_cumulative(&view, &c, 10.0).unwrap();
        assert_eq!(cum.v_over_u, vec![0.3, 0.4]);
        assert_eq!(cum.mass, vec![8.0, 6.0]);
        assert_eq!(cum.momentum_z, vec![30.0, 24.0]);
        assert_eq!(cum.at(0.0), (8.0, 30.0));
        assert_eq!(cum.at(0.35), (6.0, 24.0));
        assert_eq!(cum.at(0.5), (0.0, 0.0));
    }

    #[test]
    fn no_ejecta_and_bad_parameters() {
        let (p, v, m, b) = six();
        let view = ParticleView::new(&p, &v, &m, &b);
        let none = EjectaCriterion::new(&[7], 0.0);
        assert!(
            ejecta_distribution(&view, &none, 1.0, 0.1)
                .unwrap()
                .is_empty()
        );
        assert_eq!(
            ejecta_cumulative(&view, &none, 1.0).unwrap(),
            EjectaCumulative::default()
        );
        let c = EjectaCriterion::new(&[1, 2], 0.0);
        assert!(ejecta_distribution(&view, &c, 0.0, 0.1).is_err());
        assert!(ejecta_distribution(&view, &c, 1.0, -0.1).is_err());
        assert!(matches!(
            ejecta_distribution(&view, &c, 1.0, 1e-9),
            Err(ImpactError::TooManyBins { .. })
        ));
    }

    proptest! {
        #[test]
        fn bins_and_cumulative_add_up_to_the_totals(
            parts in prop::collection::vec(
                (-1.0f64..1.0, -1.0f64..3.0, 0.0f64..2.0, 0u16..3), 0..60),
            width in 0.05f64..1.0,
        ) {
            let p: Vec<[f64; 3]> = parts.iter().map(|t| [0.0, 0.0, t.0]).collect();
            let v: Vec<[f64; 3]> = parts.iter().map(|t| [0.0, 0.0, t.1]).collect();
            let m: Vec<f64> = parts.iter().map(|t| t.2).collect();
            let b: Vec<u16> = parts.iter().map(|t| t.3).collect();
            let view = ParticleView::new(&p, &v, &m, &b);
            let c = EjectaCriterion::new(&[1, 2], 0.0);
            let total = ejecta(&view, &c).unwrap();
            let bins = ejecta_distribution(&view, &c, 2.0, width).unwrap();
            let tol = 1e-12 * (1.0 + total.mass + total.momentum_z);
            prop_assert!((bins.iter().map(|b| b.mass).sum::<f64>() - total.mass).abs() < tol);
            prop_assert!(
                (bins.iter().map(|b| b.momentum_z).sum::<f64>() - total.momentum_z).abs() < tol
            );
            let cum = ejecta_cumulative(&view, &c, 2.0).unwrap();
            if total.count > 0 {
                prop_assert!((cum.mass[0] - total.mass).abs() < tol);
                prop_assert!((cum.momentum_z[0] - total.momentum_z).abs() < tol);
            }
            for k in 1..cum.mass.len() {
                prop_assert!(cum.v_over_u[k] > cum.v_over_u[k - 1]);
                prop_assert!(cum.mass[k] <= cum.mass[k - 1]);
            }
        }
    }
}

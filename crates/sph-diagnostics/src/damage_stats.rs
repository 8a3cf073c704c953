//! Mass-weighted damage statistics per body (paper §5 "damage maps"; the damage variable
//! D ∈ [0, 1] of Benz & Asphaug 1995, Comput. Phys. Commun. 87, 253).
//!
//! Mass weighting makes the numbers independent of the particle placement: with the
//! study's variable resolution a fine particle near the impact point must not count as
//! much as a coarse one far away. In RZ the mass is the ring mass, so the same sums hold.

use crate::error::ImpactError;
use crate::mass_histogram::{MassHistogram, uniform_edges};
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Damage from which a particle counts as fully damaged. Not 1: crack-growth laws
/// approach D = 1 only asymptotically (D^(1/3) grows linearly in time in Benz & Asphaug
/// 1995), so "= 1" would miss material that is failed for every practical purpose.
pub const FULLY_DAMAGED: f64 = 0.99;

/// Damage statistics of one body.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BodyDamage {
    /// Body id.
    pub body: u16,
    /// Body mass (kg).
    pub mass: f64,
    /// Mass-weighted mean damage Σ m D / Σ m (dimensionless; 0 for a body of zero mass).
    pub mean_damage: f64,
    /// Mass with D ≥ the full-damage threshold (kg).
    pub fully_damaged_mass: f64,
    /// Volume Σ m/ρ of the fully damaged particles (m³), if the view has densities.
    pub fully_damaged_volume: Option<f64>,
    /// Mass per damage bin over [0, 1] (kg); D = 1 is in the last bin.
    pub histogram: MassHistogram,
}

/// Per-body damage statistics of `view` (which must have damage), in increasing body id;
/// `fully_damaged` is the threshold (use [`FULLY_DAMAGED`]) and `bins` ≥ 1 the number of
/// equal histogram bins over [0, 1].
pub fn damage_stats(
    view: &ParticleView,
    fully_damaged: f64,
    bins: usize,
) -> Result<Vec<BodyDamage>, ImpactError> {
    view.validate()?;
    let damage = view.damage.ok_or(ImpactError::MissingField("damage"))?;
    if !(0.0..=1.0).contains(&fully_damaged) {
        return Err(ImpactError::BadParameter {
            name: "fully_damaged",
            value: fully_damaged,
            reason: "must be in [0, 1]",
        });
    }
    let empty = MassHistogram::new(uniform_edges(0.0, 1.0, bins)?)?;
    let mut per_body: BTreeMap<u16, (BodyDamage, f64)> = BTreeMap::new();
    for i in 0..view.len() {
        let (m, d) = (view.mass[i], damage[i]);
        let (s, md) = per_body.entry(view.body[i]).or_insert_with(|| {
            let s = BodyDamage {
                body: view.body[i],
                fully_damaged_volume: view.density.map(|_| 0.0),
                histogram: empty.clone(),
                ..BodyDamage::default()
            };
            (s, 0.0)
        });
        s.mass += m;
        *md += m * d;
        s.histogram.add(d, m);
        if d >= fully_damaged {
            s.fully_damaged_mass += m;
            if let (Some(v), Some(rho)) = (s.fully_damaged_volume.as_mut(), view.density) {
                *v += m / rho[i];
            }
        }
    }
    Ok(per_body
        .into_values()
        .map(|(mut s, md)| {
            s.mean_damage = if s.mass > 0.0 { md / s.mass } else { 0.0 };
            s
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn hand_made_bodies() {
        let p = [[0.0; 3]; 5];
        let v = [[0.0; 3]; 5];
        let m = [1.0, 3.0, 2.0, 2.0, 4.0];
        let b = [3, 3, 1, 1, 1];
        let d = [0.0, 1.0, 0.995, 0.5, 0.0];
        let rho = [1.0, 2.0, 4.0, 1.0, 1.0];
        let view = ParticleView::new(&p, &v, &m, &b)
            .with_damage(&d)
            .with_density(&rho);
        let s = damage_stats(&view, FULLY_DAMAGED, 2).unwrap();
        assert_eq!(s.len(), 2);
        let (b1, b3) = (&s[0], &s[1]);
        assert_eq!((b1.body, b1.mass, b1.fully_damaged_mass), (1, 8.0, 2.0));
        assert_eq!(b1.mean_damage, (2.0 * 0.995 + 1.0) / 8.0);
        assert_eq!(b1.fully_damaged_volume, Some(0.5));
        assert_eq!(b1.histogram.mass, vec![4.0, 4.0]); // D = 0.5 opens the upper bin
        assert_eq!(
            (b3.body, b3.mean_damage, b3.fully_damaged_mass),
            (3, 0.75, 3.0)
        );
        assert_eq!(b3.fully_damaged_volume, Some(1.5));
        assert_eq!(b3.histogram.mass, vec![1.0, 3.0]);
        let no_rho = ParticleView::new(&p, &v, &m, &b).with_damage(&d);
        assert_eq!(
            damage_stats(&no_rho, 0.99, 2).unwrap()[0].fully_damaged_volume,
            None
        );
    }

    #[test]
    fn errors() {
        let p = [[0.0; 3]];
        let view = ParticleView::new(&p, &p, &[1.0], &[0]);
        assert_eq!(
            damage_stats(&view, 0.99, 4),
            Err(ImpactError::MissingField("damage"))
        );
        let view = view.with_damage(&[0.5]);
        assert!(damage_stats(&view, 1.5, 4).is_err());
        assert!(damage_stats(&view, 0.99, 0).is_err());
        let zero = ParticleView::new(&p, &p, &[0.0], &[0]).with_damage(&[0.5]);
        assert_eq!(damage_stats(&zero, 0.99, 1).unwrap()[0].mean_damage, 0.0);
    }

    proptest! {
        #[test]
        fn sums_are_consistent(
            parts in prop::collection::vec((0.0f64..2.0, 0.0f64..=1.0, 0u16..4), 1..80),
            bins in 1usize..12,
        ) {
            let n = parts.len();
            let p = vec![[0.0; 3]; n];
            let m: Vec<f64> = parts.iter().map(|t| t.0).collect();
            let d: Vec<f64> = parts.iter().map(|t| t.1).collect();
            let b: Vec<u16> = parts.iter().map(|t| t.2).collect();
            let view = ParticleView::new(&p, &p, &m, &b).with_damage(&d);
            let stats = damage_stats(&view, FULLY_DAMAGED, bins).unwrap();
            let total: f64 = m.iter().sum();
            let tol = 1e-12 * (1.0 + total);
            prop_assert!((stats.iter().map(|s| s.mass).sum::<f64>() - total).abs() < tol);
            for s in &stats {
                prop_assert!((0.0..=1.0).contains(&s.mean_damage));
                prop_assert!(s.fully_damaged_mass <= s.mass + tol);
                let h = &s.histogram;
                prop_assert_eq!((h.below, h.above), (0.0, 0.0));
                prop_assert!((h.total() - s.mass).abs() < tol);
            }
        }
    }
}

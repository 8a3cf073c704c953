//! Projectile specific-energy distribution and the mass fractions past the melting and
//! vaporisation energies (paper §1 and §5: the aluminium projectile ≈ 50 % melts and
//! ≈ 5 % vaporises at 3.9 km/s).
//!
//! An energy criterion in the spirit of Pierazzo, Vickery & Melosh (1997, Icarus 127,
//! 408): a particle counts as (incipiently) melted when its specific internal energy
//! reaches the material's threshold. The thresholds come from the caller — from the EOS
//! or thermal model, or from tables — so this module needs no EOS. Which energy to pass
//! is the caller's choice too: the current e, or the peak e a solver tracks (the study
//! plots the distribution at the end of the run).

use crate::error::ImpactError;
use crate::mass_histogram::MassHistogram;
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// Specific energies (J/kg) of the phase changes of the projectile's material.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PhaseThresholds {
    /// Energy at which melting starts (J/kg).
    pub incipient_melting: f64,
    /// Energy at which melting is complete (J/kg).
    pub complete_melting: f64,
    /// Energy at which vaporisation starts (J/kg), e.g. Tillotson E_iv.
    pub incipient_vaporisation: f64,
    /// Energy at which vaporisation is complete (J/kg), e.g. Tillotson E_cv.
    pub complete_vaporisation: f64,
}

/// Mass fractions (dimensionless, of the selected bodies' mass) at or past each threshold.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PhaseFractions {
    /// Fraction with e ≥ incipient melting.
    pub incipient_melting: f64,
    /// Fraction with e ≥ complete melting.
    pub complete_melting: f64,
    /// Fraction with e ≥ incipient vaporisation.
    pub incipient_vaporisation: f64,
    /// Fraction with e ≥ complete vaporisation.
    pub complete_vaporisation: f64,
}

/// For each threshold (J/kg), the fraction of the mass of `bodies` whose specific energy
/// `specific_energy` (J/kg, one per particle) is ≥ it. The bodies must have mass.
pub fn mass_fractions_above(
    view: &ParticleView,
    bodies: &[u16],
    specific_energy: &[f64],
    thresholds: &[f64],
) -> Result<Vec<f64>, ImpactError> {
    let sel = selected(view, bodies, specific_energy)?;
    let total: f64 = sel.iter().map(|s| s.1).sum();
    if !(total > 0.0) {
        return Err(ImpactError::EmptySelection(
            "the selected bodies have no mass",
        ));
    }
    Ok(thresholds
        .iter()
        // From +0: `Sum` of an empty iterator is −0, which a table prints as "-0".
        .map(|&t| {
            sel.iter()
                .filter(|s| s.0 >= t)
                .fold(0.0, |sum, s| sum + s.1)
                / total
        })
        .collect())
}

/// The four phase fractions of `bodies` (see [`mass_fractions_above`]).
pub fn phase_fractions(
    view: &ParticleView,
    bodies: &[u16],
    specific_energy: &[f64],
    thresholds: &PhaseThresholds,
) -> Result<PhaseFractions, ImpactError> {
    let t = thresholds;
    let f = mass_fractions_above(
        view,
        bodies,
        specific_energy,
        &[
            t.incipient_melting,
            t.complete_melting,
            t.incipient_vaporisation,
            t.complete_vaporisation,
        ],
    )?;
    Ok(PhaseFractions {
        incipient_melting: f[0],
        complete_melting: f[1],
        incipient_vaporisation: f[2],
        complete_vaporisation: f[3],
    })
}

/// Mass of `bodies` per specific-energy bin (edges in J/kg, at least two, increasing);
/// energies outside the edges are kept in `below` / `above`.
pub fn energy_histogram(
    view: &ParticleView,
    bodies: &[u16],
    specific_energy: &[f64],
    edges: Vec<f64>,
) -> Result<MassHistogram, ImpactError> {
    let mut h = MassHistogram::new(edges)?;
    for (e, m) in selected(view, bodies, specific_energy)? {
        h.add(e, m);
    }
    Ok(h)
}

/// (e, m) of the particles of `bodies`, after checking the view and the energies.
fn selected(
    view: &ParticleView,
    bodies: &[u16],
    specific_energy: &[f64],
) -> Result<Vec<(f64, f64)>, ImpactError> {
    view.validate()?;
    view.check_extra("specific_energy", specific_energy)?;
    if bodies.is_empty() {
        return Err(ImpactError::EmptySelection("no bodies given"));
    }
    Ok((0..view.len())
        .filter(|&i| bodies.contains(&view.body[i]))
        .map(|i| (specific_energy[i], view.mass[i]))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mass_histogram::uniform_edges;
    use proptest::prelude::*;

    fn view_of<'a>(p: &'a [[f64; 3]], m: &'a [f64], b: &'a [u16]) -> ParticleView<'a> {
        ParticleView::new(p, p, m, b)
    }

    #[test]
    fn hand_made_fractions_and_histogram() {
        let p = [[0.0; 3]; 5];
        let m = [1.0, 1.0, 2.0, 4.0, 100.0];
        let b = [0, 0, 0, 0, 1]; // body 1 (the target) is not selected
        let e = [0.5e6, 1.0e6, 2.0e6, 6.0e6, 9.0e9];
        let view = view_of(&p, &m, &b);
        let t = PhaseThresholds {
            incipient_melting: 1.0e6,
            complete_melting: 1.5e6,
            incipient_vaporisation: 5.0e6,
            complete_vaporisation: 1.0e7,
        };
        let f = phase_fractions(&view, &[0], &e, &t).unwrap();
        assert_eq!(
            (f.incipient_melting, f.complete_melting),
            (7.0 / 8.0, 6.0 / 8.0)
        );
        assert_eq!(
            (f.incipient_vaporisation, f.complete_vaporisation),
            (0.5, 0.0)
        );
        // A fraction of nothing is +0, not −0 (which tables print as "-0").
        assert!(f.complete_vaporisation.is_sign_positive());
        let h = energy_histogram(&view, &[0], &e, uniform_edges(0.0, 4.0e6, 2).unwrap()).unwrap();
        assert_eq!(
            (h.mass.clone(), h.below, h.above),
            (vec![2.0, 2.0], 0.0, 4.0)
        );
    }

    #[test]
    fn errors() {
        let p = [[0.0; 3]; 2];
        let view = view_of(&p, &[1.0, 0.0], &[0, 1]);
        assert!(mass_fractions_above(&view, &[0], &[1.0], &[0.0]).is_err());
        assert!(mass_fractions_above(&view, &[0], &[1.0, f64::NAN], &[0.0]).is_err());
        assert!(mass_fractions_above(&view, &[], &[1.0, 1.0], &[0.0]).is_err());
        assert!(matches!(
            mass_fractions_above(&view, &[1], &[1.0, 1.0], &[0.0]),
            Err(ImpactError::EmptySelection(_))
        ));
        assert!(energy_histogram(&view, &[0], &[1.0, 1.0], vec![1.0]).is_err());
    }

    proptest! {
        #[test]
        fn fractions_fall_with_the_threshold(
            parts in prop::collection::vec((0.01f64..2.0, 0.0f64..1e7), 1..50),
            mut thresholds in prop::collection::vec(-1e6f64..2e7, 1..8),
        ) {
            let n = parts.len();
            let p = vec![[0.0; 3]; n];
            let m: Vec<f64> = parts.iter().map(|t| t.0).collect();
            let e: Vec<f64> = parts.iter().map(|t| t.1).collect();
            let b = vec![0u16; n];
            thresholds.sort_by(f64::total_cmp);
            let f = mass_fractions_above(&view_of(&p, &m, &b), &[0], &e, &thresholds).unwrap();
            for k in 0..f.len() {
                prop_assert!((0.0..=1.0 + 1e-12).contains(&f[k]));
                if k > 0 { prop_assert!(f[k] <= f[k - 1] + 1e-12); }
            }
        }
    }
}

//! The momentum-transfer factor β (paper §5; Holsapple & Housen 2012, Icarus 221, 875).
//!
//! An impactor of mass m_p at speed U brings P_imp = m_p U along −z. The target gets that
//! plus the recoil of the material thrown back out, so its momentum change is
//! −(P_imp + P_ej) = −β P_imp, i.e. **β = 1 + P_ej / P_imp** with P_ej the ejecta's axial
//! momentum (positive, away from the target). The study computes β that way
//! ([`beta_from_ejecta`]).
//!
//! [`beta_from_target`] measures the same number from the other side of the momentum
//! balance, from everything that did *not* escape (docs/diagnostics.md §3). With
//! momentum conserved exactly, the two agree to round-off; a difference measures momentum
//! lost or gained through walls, boundaries or a non-conservative scheme.

use crate::ejecta::EjectaCriterion;
use crate::error::{ImpactError, finite, positive};
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// β = 1 + P_ej / (m_p U), from the ejecta axial momentum P_ej (kg·m/s), the projectile
/// mass m_p (kg) and the impact speed U (m/s); m_p and U must be positive, P_ej finite.
pub fn beta_from_ejecta(
    ejecta_momentum_z: f64,
    projectile_mass: f64,
    impact_speed: f64,
) -> Result<f64, ImpactError> {
    let p_imp = impactor_momentum(projectile_mass, impact_speed)?;
    Ok(1.0 + finite("ejecta_momentum_z", ejecta_momentum_z)? / p_imp)
}

/// What to do with projectile material in [`beta_from_target`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum ProjectileDebris {
    /// All projectile particles count with the remnant, wherever they go. Then
    /// β_target = 1 + P_ej/P_imp exactly when momentum is conserved: the cross-check of
    /// [`beta_from_ejecta`].
    #[default]
    WithRemnant,
    /// Projectile particles that escape (above the surface plus tolerance and moving up,
    /// the ejecta test applied to the projectile) are left out of the remnant, as a
    /// ballistic pendulum would: then β_target = 1 + (P_ej + P_esc)/P_imp.
    ExcludeEscaping,
}

/// β from the remnant, and the sums it was made from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TargetBeta {
    /// β_target (dimensionless).
    pub beta: f64,
    /// Σ m v_z over the remnant (kg·m/s): every particle not counted as escaping.
    pub remnant_momentum_z: f64,
    /// Σ m v_z of the escaping projectile particles left out (kg·m/s); 0 with
    /// [`ProjectileDebris::WithRemnant`].
    pub escaping_projectile_momentum_z: f64,
}

/// β from the momentum the remnant received:
///
/// β_target = −(P_rem − P_0) / (m_p U),  P_rem = Σ_{remnant} m v_z,
///
/// where the remnant is every particle of the view except the target's ejecta (and,
/// with [`ProjectileDebris::ExcludeEscaping`], except escaping projectile particles);
/// "projectile" means every body not in `criterion.targets()`. P_0 =
/// `initial_target_momentum_z` (kg·m/s) is the initial axial momentum of everything but
/// the projectile (0 for a target at rest).
///
/// Why: initially the total is −m_p U + P_0; it is conserved, and at the end it is
/// P_ej (+ P_esc) + P_rem, so P_rem − P_0 = −(m_p U + P_ej (+ P_esc)) = −β P_imp.
pub fn beta_from_target(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    projectile_mass: f64,
    impact_speed: f64,
    initial_target_momentum_z: f64,
    debris: ProjectileDebris,
) -> Result<TargetBeta, ImpactError> {
    let p_imp = impactor_momentum(projectile_mass, impact_speed)?;
    let p0 = finite("initial_target_momentum_z", initial_target_momentum_z)?;
    view.validate()?;
    criterion.check()?;
    let mut out = TargetBeta::default();
    for i in 0..view.len() {
        let (p, v) = (view.position[i], view.velocity[i]);
        let pz = view.mass[i] * v[2];
        if criterion.is_target(view.body[i]) {
            if !criterion.is_escaping(p, v) {
                out.remnant_momentum_z += pz;
            }
        } else if debris == ProjectileDebris::ExcludeEscaping && criterion.is_escaping(p, v) {
            out.escaping_projectile_momentum_z += pz;
        } else {
            out.remnant_momentum_z += pz;
        }
    }
    out.beta = -(out.remnant_momentum_z - p0) / p_imp;
    Ok(out)
}

/// P_imp = m_p U (kg·m/s), both positive.
pub fn impactor_momentum(projectile_mass: f64, impact_speed: f64) -> Result<f64, ImpactError> {
    Ok(positive("projectile_mass", projectile_mass)? * positive("impact_speed", impact_speed)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ejecta::{ejecta, tests::six};
    use proptest::prelude::*;

    #[test]
    fn beta_from_ejecta_by_hand() {
        assert_eq!(beta_from_ejecta(3.0, 2.0, 1.5).unwrap(), 2.0);
        assert_eq!(beta_from_ejecta(0.0, 2.0, 1.5).unwrap(), 1.0);
        assert!(beta_from_ejecta(1.0, 0.0, 1.0).is_err());
        assert!(beta_from_ejecta(1.0, 1.0, -1.0).is_err());
        assert!(beta_from_ejecta(f64::NAN, 1.0, 1.0).is_err());
    }

    #[test]
    fn beta_from_target_by_hand() {
        // `six`: momenta m v_z = 10 (projectile, escaping), 6 (ejecta), −3, 20, 25 (target
        // remnant), 24 (ejecta). P_imp = 1 × 100.
        let (p, v, m, b) = six();
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = EjectaCriterion::new(&[1, 2], 0.0);
        let with =
            beta_from_target(&view, &c, 1.0, 100.0, 0.0, ProjectileDebris::WithRemnant).unwrap();
        assert_eq!(with.remnant_momentum_z, 10.0 - 3.0 + 20.0 + 25.0);
        assert_eq!(with.escaping_projectile_momentum_z, 0.0);
        assert_eq!(with.beta, -0.52);
        let without = beta_from_target(
            &view,
            &c,
            1.0,
            100.0,
            2.0,
            ProjectileDebris::ExcludeEscaping,
        )
        .unwrap();
        assert_eq!(without.remnant_momentum_z, 42.0);
        assert_eq!(without.escaping_projectile_momentum_z, 10.0);
        assert_eq!(without.beta, -0.4);
        assert!(beta_from_target(&view, &c, -1.0, 1.0, 0.0, Default::default()).is_err());
        assert!(beta_from_target(&view, &c, 1.0, 1.0, f64::NAN, Default::default()).is_err());
    }

    #[test]
    fn embedded_projectile_gives_beta_one() {
        // A projectile of 1 kg at 10 m/s sticks in a 9 kg target: all move at −1 m/s,
        // no ejecta, β = 1 both ways.
        let p = [[0.0, 0.0, -0.1], [0.0, 0.0, -0.2]];
        let v = [[0.0, 0.0, -1.0]; 2];
        let view = ParticleView::new(&p, &v, &[1.0, 9.0], &[0, 1]);
        let c = EjectaCriterion::new(&[1], 0.0);
        let t = beta_from_target(&view, &c, 1.0, 10.0, 0.0, Default::default()).unwrap();
        assert!((t.beta - 1.0).abs() < 1e-15);
        let e = ejecta(&view, &c).unwrap();
        assert_eq!(beta_from_ejecta(e.momentum_z, 1.0, 10.0).unwrap(), 1.0);
    }

    proptest! {
        /// With the initial momentum chosen so that momentum is conserved, the remnant and
        /// the ejecta give the same β; excluding escaping debris adds P_esc/P_imp.
        #[test]
        fn both_betas_agree_when_momentum_is_conserved(
            parts in prop::collection::vec(
                (-1.0f64..1.0, -5.0f64..5.0, 0.0f64..2.0, 0u16..3), 1..60),
            mp in 0.1f64..3.0,
            u in 1.0f64..5000.0,
        ) {
            let p: Vec<[f64; 3]> = parts.iter().map(|t| [0.0, 0.0, t.0]).collect();
            let v: Vec<[f64; 3]> = parts.iter().map(|t| [0.0, 0.0, t.1]).collect();
            let m: Vec<f64> = parts.iter().map(|t| t.2).collect();
            let b: Vec<u16> = parts.iter().map(|t| t.3).collect();
            let view = ParticleView::new(&p, &v, &m, &b);
            let c = EjectaCriterion::new(&[1, 2], 0.0);
            let total: f64 = m.iter().zip(&v).map(|(m, v)| m * v[2]).sum();
            let p0 = total + mp * u; // −m_p U + P_0 = total
            let e = ejecta(&view, &c).unwrap();
            let be = beta_from_ejecta(e.momentum_z, mp, u).unwrap();
            let t = beta_from_target(&view, &c, mp, u, p0, ProjectileDebris::WithRemnant)
                .unwrap();
            let scale = 1.0 + m.iter().zip(&v).map(|(m, v)| (m * v[2]).abs()).sum::<f64>()
                / (mp * u);
            prop_assert!((t.beta - be).abs() < 1e-12 * scale);
            let x = beta_from_target(&view, &c, mp, u, p0, ProjectileDebris::ExcludeEscaping)
                .unwrap();
            let expect = be + x.escaping_projectile_momentum_z / (mp * u);
            prop_assert!((x.beta - expect).abs() < 1e-12 * scale);
            prop_assert!(x.escaping_projectile_momentum_z >= 0.0);
        }
    }
}

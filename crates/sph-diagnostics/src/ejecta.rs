//! Ejecta: target material that has left the target (paper §5).
//!
//! **Definition** (docs/diagnostics.md §2). A particle is ejecta when
//! 1. its body is one of the target bodies,
//! 2. it is above the original surface: z > `surface_z` + `tolerance`, and
//! 3. it moves away from the target: v_z > 0.
//!
//! Both position and velocity are needed: material still inside the crater moves upward
//! during excavation but has not left yet, and material above the surface that falls
//! back (v_z ≤ 0) is not carrying momentum away. The tolerance (default 0, m) lifts the
//! plane, e.g. by a particle spacing so that a rim bulging a fraction of a spacing is not
//! counted. Ejecta momentum along the axis is what β is made of (module `beta`).

use crate::error::{ImpactError, finite};
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// Which particles are ejecta: target bodies, the original surface and a tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EjectaCriterion<'a> {
    /// Body ids of the target (at least one).
    targets: &'a [u16],
    /// Height of the target's original top surface (m).
    pub surface_z: f64,
    /// Extra height above the surface a particle must pass (m, ≥ 0; default 0).
    pub tolerance: f64,
    /// `targets` is in ascending order, so [`Self::is_target`] bisects it: every
    /// particle is looked up, and a rubble pile's targets are thousands of bodies.
    sorted: bool,
}

impl<'a> EjectaCriterion<'a> {
    /// The criterion with zero tolerance.
    pub fn new(targets: &'a [u16], surface_z: f64) -> Self {
        Self {
            targets,
            surface_z,
            tolerance: 0.0,
            sorted: targets.is_sorted(),
        }
    }

    /// Body ids of the target.
    pub fn targets(&self) -> &'a [u16] {
        self.targets
    }

    /// The same criterion with another tolerance (m).
    pub fn with_tolerance(self, tolerance: f64) -> Self {
        Self { tolerance, ..self }
    }

    /// Checks: at least one target body, finite surface, finite non-negative tolerance.
    pub fn check(&self) -> Result<(), ImpactError> {
        if self.targets.is_empty() {
            return Err(ImpactError::EmptySelection("no target bodies given"));
        }
        finite("surface_z", self.surface_z)?;
        if !(self.tolerance >= 0.0 && self.tolerance.is_finite()) {
            return Err(ImpactError::BadParameter {
                name: "tolerance",
                value: self.tolerance,
                reason: "must be finite and ≥ 0",
            });
        }
        Ok(())
    }

    /// True if `body` is a target body (in time logarithmic in the number of targets when
    /// they are given in ascending order, as a scene's are).
    pub fn is_target(&self, body: u16) -> bool {
        if self.sorted {
            self.targets.binary_search(&body).is_ok()
        } else {
            self.targets.contains(&body)
        }
    }

    /// True if a particle at `position` (m) with `velocity` (m/s) is above the surface
    /// plus tolerance and moving up — the ejecta test without the body condition.
    pub fn is_escaping(&self, position: [f64; 3], velocity: [f64; 3]) -> bool {
        position[2] > self.surface_z + self.tolerance && velocity[2] > 0.0
    }

    /// True if particle `i` of `view` is ejecta.
    pub fn is_ejecta(&self, view: &ParticleView, i: usize) -> bool {
        self.is_target(view.body[i]) && self.is_escaping(view.position[i], view.velocity[i])
    }
}

/// Totals over the ejecta.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Ejecta {
    /// Ejecta mass (kg).
    pub mass: f64,
    /// Axial momentum Σ m v_z (kg·m/s), positive (away from the target).
    pub momentum_z: f64,
    /// Σ m v (kg·m/s). Across the axis it cancels by symmetry in 3-D; in RZ the first
    /// component is Σ m v_r, the radial outflow, and the second is 0.
    pub momentum: [f64; 3],
    /// Number of ejecta particles.
    pub count: usize,
}

impl Ejecta {
    /// The totals over the particles `members` of `view`.
    pub(crate) fn of(view: &ParticleView, members: impl Iterator<Item = usize>) -> Self {
        let mut e = Self::default();
        for i in members {
            let (m, v) = (view.mass[i], view.velocity[i]);
            e.mass += m;
            for a in 0..3 {
                e.momentum[a] += m * v[a];
            }
            e.count += 1;
        }
        e.momentum_z = e.momentum[2];
        e
    }
}

/// Mass, momentum and count of the ejecta of `view` (validated first).
pub fn ejecta(view: &ParticleView, criterion: &EjectaCriterion) -> Result<Ejecta, ImpactError> {
    view.validate()?;
    criterion.check()?;
    Ok(Ejecta::of(
        view,
        (0..view.len()).filter(|&i| criterion.is_ejecta(view, i)),
    ))
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// Owned arrays for a test view: position, velocity, mass, body.
    pub(crate) type Arrays = (Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<f64>, Vec<u16>);

    /// Six hand-made particles: body 0 projectile, 1 and 2 target, surface at z = 0.
    pub(crate) fn six() -> Arrays {
        let p = vec![
            [0.0, 0.0, 0.5],  // projectile above, rising: not ejecta (not target)
            [1.0, 0.0, 0.5],  // target above, rising: ejecta
            [0.0, 2.0, 0.5],  // target above, falling: not ejecta
            [0.0, 0.0, -0.5], // target below, rising: not ejecta
            [0.0, 0.0, 0.0],  // target on the plane, rising: not ejecta (strict >)
            [3.0, 4.0, 2.0],  // second target body above, rising: ejecta
        ];
        let v = vec![
            [0.0, 0.0, 10.0],
            [2.0, 0.0, 3.0],
            [0.0, 0.0, -1.0],
            [0.0, 0.0, 5.0],
            [0.0, 0.0, 5.0],
            [0.0, -1.0, 4.0],
        ];
        (
            p,
            v,
            vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0],
            vec![0, 1, 1, 1, 1, 2],
        )
    }

    #[test]
    fn hand_made_ejecta() {
        let (p, v, m, b) = six();
        let view = ParticleView::new(&p, &v, &m, &b);
        let e = ejecta(&view, &EjectaCriterion::new(&[1, 2], 0.0)).unwrap();
        assert_eq!(e.count, 2);
        assert_eq!(e.mass, 8.0);
        assert_eq!(e.momentum_z, 2.0 * 3.0 + 6.0 * 4.0);
        assert_eq!(e.momentum, [4.0, -6.0, 30.0]);
        // Tolerance 1 m leaves only the particle at z = 2.
        let c = EjectaCriterion::new(&[1, 2], 0.0).with_tolerance(1.0);
        assert_eq!(ejecta(&view, &c).unwrap().mass, 6.0);
        // Only body 1 as target.
        assert_eq!(
            ejecta(&view, &EjectaCriterion::new(&[1], 0.0))
                .unwrap()
                .count,
            1
        );
    }

    /// Target lists in ascending order (bisected) and in any order (scanned) select the
    /// same bodies.
    #[test]
    fn target_lookup_in_any_order() {
        let ascending: Vec<u16> = (0..5000).filter(|b| b % 3 != 1).collect();
        let mut shuffled = ascending.clone();
        shuffled.swap(0, 3000);
        for targets in [&ascending, &shuffled] {
            let c = EjectaCriterion::new(targets, 0.0);
            for body in 0..5100 {
                assert_eq!(c.is_target(body), targets.contains(&body), "{body}");
            }
        }
        assert_eq!(
            EjectaCriterion::new(&shuffled, 0.0).targets(),
            &shuffled[..]
        );
    }

    #[test]
    fn bad_criteria_are_errors() {
        let (p, v, m, b) = six();
        let view = ParticleView::new(&p, &v, &m, &b);
        assert!(matches!(
            ejecta(&view, &EjectaCriterion::new(&[], 0.0)),
            Err(ImpactError::EmptySelection(_))
        ));
        let c = EjectaCriterion::new(&[1], 0.0).with_tolerance(-1.0);
        assert!(ejecta(&view, &c).is_err());
        assert!(ejecta(&view, &EjectaCriterion::new(&[1], f64::NAN)).is_err());
    }
}

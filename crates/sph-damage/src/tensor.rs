//! Directional (tensor) damage: [`DamageForm`] and the operations on a damage tensor.
//!
//! In the scalar form (the paper's §2–§3.3) one number D weakens a particle in every
//! direction. A crack, though, opens across one plane: a particle split by a crack normal
//! to n can no longer carry tension or shear across that plane, but still carries them
//! along it. LLNL Spheral's probabilistic (Benz–Asphaug) damage, the code the reference
//! study modified, keeps this as a symmetric tensor **D** (its `tensorDamage`):
//!
//! * **Growth per principal direction.** The activation strain tensor ε is decomposed into
//!   principal strains λ_1 ≥ λ_2 ≥ λ_3 with directions n_j. For each positive λ_j, in that
//!   order, the damage already across n_j is D_0 = |**D** n_j|, the local strain is
//!   λ_j/(1 − D_0), its active flaws set the growth rate and the cap exactly as in the
//!   scalar model, and the increment D_1 − D_0 is added as (D_1 − D_0) n_j ⊗ n_j.
//!   A tension along one axis thus cracks the particle across that axis only: **D** =
//!   n ⊗ n, with eigenvalues (1, 0, 0).
//! * **Rotation with the material.** **D** turns with the particle's spin like the
//!   deviatoric stress: d**D**/dt = Ω **D** − **D** Ω (the solver applies it).
//! * **Bounds.** Every eigenvalue stays in [0, 1] ([`bound_eigenvalues`]).
//! * **Use.** A pair's deviatoric coupling sees each particle's damage projected on the
//!   pair's direction r̂, |**D** r̂| ([`projected_damage`]): a crack normal to r̂ passes no
//!   stress across it, one along r̂ passes it all. The damaged pressure (tension weakened
//!   by 1 − D) uses the largest eigenvalue ([`largest_damage`]), as Spheral's damaged
//!   pressure does; so do the damaged yield strength (paper §3.2) and the output's scalar
//!   D. (Spheral reports tr **D**/3 as its scalar damage; the largest eigenvalue says
//!   "cracked through in some direction", which is what the crater's spall measure asks.)
//!
//! A scalar damage D is the isotropic tensor D I, whose projection on any direction is D:
//! the projected coupling reduces to the scalar one for particles of scalar materials.

use crate::model::DamageVariable;
use serde::{Deserialize, Serialize};
use sph_core::Tensor;
use sph_core::glam::{DMat3, DVec3};

/// Whether a damage model's D is one number per particle or a tensor (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum DamageForm {
    /// One D per particle, weakening every direction alike (paper §2).
    #[default]
    Scalar,
    /// A symmetric tensor grown along the principal strain directions (Spheral's
    /// probabilistic damage).
    Tensor,
}

/// The principal values of a symmetric strain tensor, largest first, with their unit
/// directions: `[(λ_1, n_1), (λ_2, n_2), (λ_3, n_3)]`, λ_1 ≥ λ_2 ≥ λ_3.
pub fn principal_strains(strain: &DMat3) -> [(f64, DVec3); 3] {
    let e = strain.sym_eigen();
    // sph-core returns ascending eigenvalues with the vectors as columns.
    [2, 1, 0].map(|k| (e.values[k], e.vectors.col(k)))
}

/// |**D** n|, the damage across the plane normal to the unit vector `n`, in [0, 1].
#[inline]
pub fn projected_damage(damage: &DMat3, n: DVec3) -> f64 {
    (*damage * n).length().clamp(0.0, 1.0)
}

/// The largest eigenvalue of **D**, in [0, 1]: the particle's scalar damage for the
/// damaged pressure, the damaged yield strength and the output (module docs).
#[inline]
pub fn largest_damage(damage: &DMat3) -> f64 {
    damage.sym_eigenvalues()[2].clamp(0.0, 1.0)
}

/// The growth of one principal direction, from one evaluation of the damage model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalGrowth {
    /// The unit direction n_j.
    pub direction: DVec3,
    /// d(D^(1/p))/dt across n_j (≥ 0; 0 where the strain is not tensile).
    pub rate: f64,
    /// The cap on the damage across n_j (the active-flaw fraction, never below the
    /// damage it had when evaluated).
    pub cap: f64,
}

impl DirectionalGrowth {
    /// No growth along `direction`.
    pub const fn none(direction: DVec3) -> Self {
        DirectionalGrowth {
            direction,
            rate: 0.0,
            cap: 0.0,
        }
    }
}

/// What [`grow`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GrowthOutcome {
    /// Directions whose growth was stopped at their cap.
    pub capped: u32,
    /// True when the eigenvalues had to be brought back into [0, 1].
    pub rebounded: bool,
}

/// Grows **D** over `dt` along each direction in turn (module docs): with
/// D_0 = |**D** n| and s = D^(1/p) of `variable`, s ← min(s_0 + dt · rate,
/// s(max(cap, D_0))), and **D** += (D_1 − D_0) n ⊗ n; then the eigenvalues are bounded to
/// [0, 1]. A direction already fully damaged (D_0 = 1) does not grow.
pub fn grow(
    damage: DMat3,
    growth: &[DirectionalGrowth],
    variable: DamageVariable,
    dt: f64,
) -> (DMat3, GrowthOutcome) {
    let mut d = damage;
    let mut outcome = GrowthOutcome::default();
    for g in growth {
        if !(g.rate > 0.0) {
            continue;
        }
        let n = g.direction;
        let d0 = projected_damage(&d, n);
        if d0 >= 1.0 {
            continue;
        }
        let s0 = variable.from_damage(d0);
        let s_max = variable.from_damage(g.cap.clamp(d0, 1.0));
        let mut s = s0 + dt * g.rate;
        if s > s_max {
            s = s_max;
            outcome.capped += 1;
        }
        let d1 = variable.to_damage(s);
        d += outer(n) * (d1 - d0);
    }
    let (bounded, rebounded) = bound_eigenvalues(&d);
    outcome.rebounded = rebounded;
    (bounded, outcome)
}

/// n ⊗ n.
#[inline]
fn outer(n: DVec3) -> DMat3 {
    DMat3::from_cols(n * n.x, n * n.y, n * n.z)
}

/// **D** with its eigenvalues clamped to [0, 1], and whether any was outside (within a
/// relative 1e-12, which round-off of the eigen-decomposition itself reaches, the tensor
/// is returned unchanged).
pub fn bound_eigenvalues(damage: &DMat3) -> (DMat3, bool) {
    let e = damage.sym_eigen();
    const SLACK: f64 = 1e-12;
    if e.values[0] >= -SLACK && e.values[2] <= 1.0 + SLACK {
        return (*damage, false);
    }
    let v = e.vectors;
    let mut out = DMat3::ZERO;
    for k in 0..3 {
        out += outer(v.col(k)) * e.values[k].clamp(0.0, 1.0);
    }
    (out, true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use proptest::prelude::*;

    fn diag(a: f64, b: f64, c: f64) -> DMat3 {
        DMat3::from_diagonal(DVec3::new(a, b, c))
    }

    #[test]
    fn principal_strains_are_sorted_largest_first() {
        let p = principal_strains(&diag(-1.0, 3.0, 2.0));
        assert_eq!(p.map(|(l, _)| l), [3.0, 2.0, -1.0]);
        assert_relative_eq!(p[0].1.y.abs(), 1.0, epsilon = 1e-12);
        assert_relative_eq!(p[2].1.x.abs(), 1.0, epsilon = 1e-12);
    }

    #[test]
    fn a_crack_across_x_passes_stress_along_y_and_z() {
        let d = outer(DVec3::X);
        assert_eq!(projected_damage(&d, DVec3::X), 1.0);
        assert_eq!(projected_damage(&d, DVec3::Y), 0.0);
        let diagonal = DVec3::new(1.0, 1.0, 0.0).normalize();
        assert_relative_eq!(
            projected_damage(&d, diagonal),
            0.5f64.sqrt(),
            epsilon = 1e-15
        );
        assert_relative_eq!(largest_damage(&d), 1.0, epsilon = 1e-12);
    }

    #[test]
    fn isotropic_damage_projects_to_itself() {
        let d = DMat3::IDENTITY * 0.3;
        for n in [
            DVec3::X,
            DVec3::new(0.6, 0.0, 0.8),
            DVec3::new(1.0, 2.0, 2.0) / 3.0,
        ] {
            assert_relative_eq!(projected_damage(&d, n), 0.3, epsilon = 1e-15);
        }
    }

    #[test]
    fn growth_along_one_axis_adds_only_there_and_stops_at_the_cap() {
        // s = D^(1/3) grows by dt·rate = 0.5: D_1 = 0.125 along x, nothing elsewhere.
        let g = [DirectionalGrowth {
            direction: DVec3::X,
            rate: 0.5e6,
            cap: 1.0,
        }];
        let (d, out) = grow(DMat3::ZERO, &g, DamageVariable::CubeRoot, 1e-6);
        assert_relative_eq!(d.x_axis.x, 0.125, epsilon = 1e-15);
        assert_eq!((d.y_axis.y, d.z_axis.z, d.x_axis.y), (0.0, 0.0, 0.0));
        assert_eq!(out, GrowthOutcome::default());
        // A cap of 0.1 stops it there, and says so.
        let capped = [DirectionalGrowth { cap: 0.1, ..g[0] }];
        let (d, out) = grow(DMat3::ZERO, &capped, DamageVariable::CubeRoot, 1e-6);
        assert_relative_eq!(d.x_axis.x, 0.1, epsilon = 1e-15);
        assert_eq!(out.capped, 1);
    }

    #[test]
    fn growth_continues_from_the_projected_damage() {
        // D = 0.125 I: along x the cube root starts at 0.5 and reaches 1.0.
        let g = [DirectionalGrowth {
            direction: DVec3::X,
            rate: 0.5e6,
            cap: 1.0,
        }];
        let (d, _) = grow(DMat3::IDENTITY * 0.125, &g, DamageVariable::CubeRoot, 1e-6);
        assert_relative_eq!(d.x_axis.x, 1.0, epsilon = 1e-14);
        assert_relative_eq!(d.y_axis.y, 0.125, epsilon = 1e-15);
        // Fully damaged along x: no further growth there.
        let (again, out) = grow(d, &g, DamageVariable::CubeRoot, 1e-6);
        assert_eq!(again, d);
        assert_eq!(out, GrowthOutcome::default());
    }

    #[test]
    fn three_directions_of_full_damage_make_the_identity() {
        let g = [DVec3::X, DVec3::Y, DVec3::Z].map(|n| DirectionalGrowth {
            direction: n,
            rate: 1e9,
            cap: 1.0,
        });
        let (d, out) = grow(DMat3::ZERO, &g, DamageVariable::CubeRoot, 1.0);
        assert!(d.abs_diff_eq(DMat3::IDENTITY, 1e-15));
        assert_eq!(out.capped, 3);
    }

    #[test]
    fn eigenvalues_outside_the_unit_interval_are_clamped() {
        let (d, moved) = bound_eigenvalues(&diag(1.5, -0.2, 0.4));
        assert!(moved);
        assert!(d.abs_diff_eq(diag(1.0, 0.0, 0.4), 1e-12));
        let inside = diag(1.0, 0.0, 0.4);
        assert_eq!(bound_eigenvalues(&inside), (inside, false));
    }

    fn unit() -> impl Strategy<Value = DVec3> {
        (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
            .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 0.01)
            .prop_map(|(x, y, z)| DVec3::new(x, y, z).normalize())
    }

    proptest! {
        /// Growth keeps D symmetric with eigenvalues in [0, 1]; unless the eigenvalues had
        /// to be bounded, it never heals (the quadratic form n·D n does not fall along
        /// any direction, since each increment is positive semi-definite).
        #[test]
        fn growth_is_bounded_symmetric_and_does_not_heal(
            n1 in unit(), n2 in unit(), r1 in 0.0f64..2e6, r2 in 0.0f64..2e6,
            c1 in 0.0f64..1.0, c2 in 0.0f64..1.0, dt in 1e-9f64..1e-6,
        ) {
            let g = [
                DirectionalGrowth { direction: n1, rate: r1, cap: c1 },
                DirectionalGrowth { direction: n2, rate: r2, cap: c2 },
            ];
            let (d, _) = grow(DMat3::ZERO, &g, DamageVariable::CubeRoot, dt);
            prop_assert!(d.abs_diff_eq(d.transpose(), 1e-14));
            let e = d.sym_eigen();
            prop_assert!(e.values[0] >= -1e-12 && e.values[2] <= 1.0 + 1e-12);
            let (d2, out) = grow(d, &g, DamageVariable::CubeRoot, dt);
            if !out.rebounded {
                for n in [n1, n2, DVec3::X, DVec3::Y, DVec3::Z] {
                    prop_assert!(n.dot(d2 * n) >= n.dot(d * n) - 1e-12);
                }
            }
        }

        /// One direction grows to at most its cap, whatever the rate and step.
        #[test]
        fn one_direction_stops_at_its_cap(
            n in unit(), rate in 0.0f64..1e9, cap in 0.0f64..1.0, dt in 1e-9f64..1e-3,
        ) {
            let g = [DirectionalGrowth { direction: n, rate, cap }];
            let (d, _) = grow(DMat3::ZERO, &g, DamageVariable::CubeRoot, dt);
            prop_assert!(projected_damage(&d, n) <= cap + 1e-12);
            prop_assert!(largest_damage(&d) <= cap + 1e-12);
        }
    }
}

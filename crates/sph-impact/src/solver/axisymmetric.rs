//! Axisymmetric (RZ) geometry: 2-D particles in the (r, z) half-plane (x = r ≥ 0,
//! y = z) standing for rings about the z axis (paper §6: a sphere hitting a cylinder
//! head-on is axisymmetric).
//!
//! Formulation (the ring-mass form: conservative in axial momentum and total energy).
//! Each particle's `mass` is its ring mass per radian, m_i = ρ_i A_i r_i (kg/rad),
//! constant; `density` stays the physical ρ. With η = ρ r (mass per radian per unit area)
//! the (r, z) parts of the equations are plane 2-D SPH sums over the ring masses:
//!
//! ```text
//! dη/dt = 2-D continuity sum (mass or volume form),   ρ = η / r
//! dv/dt = Σ_j m_j (r_i σ_i + r_j σ_j)/(η_i η_j) ∇_i W_ij − σ_θθ ŝ_i/η_i e_r
//! dS/dt = Jaumann rate with L_θθ = v_r / r   (S_θθ is the third diagonal entry)
//! de/dt = compatible: the pair work and −v̄·(hoop force); or the study's sum
//!         plus σ_θθ v_r/(ρ r)
//! ```
//!
//! since ρ r dv/dt = ∇₂·(r σ) − σ_θθ e_r exactly (the cylindrical equations of Petschek &
//! Libersky 1993, JCP 109:76, multiplied by r; the r-weighted pair form keeps the pair
//! forces equal and opposite between ring masses). So Σ m v_z (per radian) is conserved to
//! round-off, and with the compatible energy equation so is Σ m (v²/2 + e).
//!
//! Next to the axis the pair sums see mirror images (the axis is a reflecting wall: P, ρ, r
//! and S_rr even, v_r and S_rz odd), which makes their estimate of ∂(r P)/∂r miss part of
//! P. Within two support radii of the axis the hoop force therefore uses ŝ_i, the pair
//! sums' own estimate of ∂r/∂r (`PairRates::hoop_gauge`), so a uniform stress is in
//! equilibrium exactly there. Beyond three support radii it uses the exact ∂r/∂r = 1
//! (blended smoothly in between): out there ŝ no longer measures the axis but free
//! surfaces and density jumps, where it grows like r/h and would turn any σ_rr ≠ σ_θθ
//! into a spurious radial force (it made the rim of a Taylor bar's foot jet outward at
//! km/s, and skewed the RZ Sedov front). Far from the axis a uniform stress is then in
//! equilibrium to the lattice's first-moment error (3e-7 m/s after a step in the test,
//! against 2e-4 m/s of free-surface release). Inside the axis zone ŝ is kept within
//! [0.35, 1.6], the range a lattice there gives it (0.43–1.21) widened: in a body only a
//! few support radii across the zone holds its free surface too, and there the unbounded
//! ŝ took either sign (−2.7 on a Taylor rod 4 spacings across, which then jetted at its
//! rim and stopped; down to −2.8 on the projectile's surface in the first 3 µs of the
//! Al → basalt impact at A_res 1 mm), turning the hoop force around. Summation density
//! divides Σ m W by the same smoothing of r. The smoothing length follows the area per
//! particle, h = n_target (m/(ρ r))^(1/2), with r at least the half-width of the ring's
//! own section (`ring_area`: with the bare r a ring carried onto the axis had an
//! unbounded h).
//! Totals (`Simulation::conserved`) are per radian: multiply by 2π for the bodies'. A
//! mirror ghost of a wall normal to r (a cylinder wall) carries the ring mass of its own radius,
//! m r'/r, so it stands for the same area of material as its source. The Monaghan
//! viscosity and the artificial stress are weighted like the pressure (× r̄/(r_i r_j),
//! R/r) and have no hoop part. (With R̂ in place of r in those two weights the spherical
//! Noh run lost 4.7e-4 of its energy instead of 5e-7: docs/verification.md.) The
//! artificial stress' reference spacing Δp in f = W(r_ij)/W(Δp) is the ring's (r, z)
//! spacing at its present radius, Δp₀ √(r₀/r) (`reference_spacing`): with the fixed
//! Δp₀, two rings that had moved outward over a crater floor had f⁴ = 3 300 and the
//! Al → basalt impact with ε = 0.2 collapsed at ~4 µs.

use crate::solver::config::EnergyForm;
use crate::solver::derivatives::Rates;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use sph_core::{Dimension, Particles, Vector};

/// The geometry a 2-D run stands for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Geometry {
    /// Plane (plane strain in 2-D), or 1-D/3-D Cartesian.
    #[default]
    Cartesian,
    /// Axisymmetric about the y (z) axis, x = r ≥ 0; 2-D only.
    Axisymmetric,
}

/// The radius r = |x| of a position (x = r; mirror ghosts have x < 0).
#[inline]
pub(crate) fn radius<V: Vector>(x: V) -> f64 {
    x.component(0).abs()
}

/// The (r, z) area of a ring of mass per radian `m` and density `rho` at radius `r`: its
/// volume per radian over its centroid radius, m/(ρ r), except that the centroid of a
/// section of width w cannot lie closer to the axis than w/2, so r is taken as at least
/// (m/(4ρ))^(1/3), where m/(ρ r) = (2r)²; closer in, the area is (2m/ρ)^(2/3), the
/// same value at the switch. A lattice's first column (r = Δx/2, area Δx²) sits exactly
/// at the switch, so nothing changes for it. With the bare m/(ρ r) a ring carried onto
/// the axis had an area, and an h, without bound: in the RZ Sedov blast at 240 across
/// a first-column ring pressed to r = 1e-4 had h at its cap, 8 times its neighbours',
/// kicked them, and the run stopped in a runaway (docs/verification.md, RZ Sedov).
#[inline]
pub(crate) fn ring_area(m: f64, r: f64, rho: f64) -> f64 {
    m / (rho * r.max((m / (4.0 * rho)).cbrt()))
}

/// The density at which a ring at radius `r` has the area side² ([`ring_area`] solved
/// for ρ): m/(r side²) while r ≥ side/2, m/((side/2) side²) closer to the axis.
#[inline]
pub(crate) fn ring_density_for_area(m: f64, r: f64, side: f64) -> f64 {
    m / (r.max(0.5 * side) * side * side)
}

/// The artificial stress' reference spacing Δp of a ring now at radius `r` that was placed
/// at `r0` with (r, z) spacing `spacing0`: Δp₀ √(r₀/r), at most `cap` Δp₀.
///
/// f_ij = W(r_ij)/W(Δp) (paper §2.3) measures a pair's distance against the spacing of
/// the undisturbed lattice under the same kernel; in 3-D, h = n_target (m/ρ)^(1/3) makes
/// that a function of the density alone, h/Δp₀ = n_target (ρ₀/ρ)^(1/3). A ring's (r, z)
/// area is m/(ρ r), so in RZ h = n_target (m/(ρ r))^(1/2) = n_target Δp₀ √(ρ₀ r₀/(ρ r)):
/// a ring that moves outward at unchanged density stretches around the hoop and closes up
/// in the meridional plane, and its neighbours and h shrink as √(r₀/r) while Δp₀ stays.
/// With Δp₀ in W(Δp) every ordinary neighbour then has f > 1, and W(Δp₀) = 0 (f = ∞) once
/// r/r₀ ≥ n_target² ρ₀/ρ. In the Al → basalt impact at 3.9 km/s (A_res 1 mm) an aluminium
/// ring that had moved from r₀ = 0.49 to 1.20 mm and a basalt ring from 0.35 to 1.42 mm
/// met at the crater floor 0.46 mm apart: f = 7.6, f⁴ = 3 300 (f ≈ 1.3 with the Δp below).
/// The artificial stress of 30 MPa of tension gave that pair 4e9 m/s², of 300 MPa a step
/// later 4e10 m/s²; its work drove e negative (−2.4e7 J/kg) and the Tillotson tension with
/// it, and the time step collapsed at 4.17 µs. The ring's own lattice spacing at reference
/// density and its present radius, √(m/(ρ₀ r)) = Δp₀ √(r₀/r), restores the 3-D relation,
/// h/Δp = n_target (ρ₀/ρ)^(1/2). The cap is h's (`SchemeConfig::h_max_factor`), so Δp
/// stays finite and inside the support for a ring that moved toward the axis.
#[inline]
pub(crate) fn reference_spacing(spacing0: f64, r0: f64, r: f64, cap: f64) -> f64 {
    (spacing0 * (r0 / r).sqrt()).min(cap * spacing0)
}

/// What the hoop terms need of one stage.
pub(crate) struct HoopInput<'a, D: Dimension> {
    pub particles: &'a Particles<D>,
    /// Intact deviatoric stress S (3×3; empty without strength).
    pub stress: &'a [sph_core::glam::DMat3],
    /// Damage D (empty without damage).
    pub damage: &'a [f64],
    /// Damaged pressure P_D.
    pub pressure: &'a [f64],
    /// How damage weakens the hoop stress (`StressCoupling::own_factor`).
    pub coupling: sph_damage::StressCoupling,
    pub energy: EnergyForm,
    /// The kernel-smoothed radius R̂ (the denominators use ρ R̂, finite on the axis).
    pub smoothed_radius: &'a SmoothedRadius,
}

/// Adds the hoop terms to the stage's rates (module docs) and turns the pair sums' dη/dt
/// into dρ/dt = (dη/dt − ρ v_r)/r.
pub(crate) fn add_hoop_terms<D: Dimension>(
    input: &HoopInput<'_, D>,
    rates: &mut [Rates<D>],
    hoop_gauge: &[f64],
) {
    let p = input.particles;
    // Each ring's terms are its own: the rings are done in parallel (the same numbers on
    // any number of threads).
    rates
        .par_iter_mut()
        .enumerate()
        .zip(hoop_gauge)
        .for_each(|((i, out), &gauge)| {
            let (r, h) = (radius(p.position[i]), p.smoothing_length[i]);
            // R̂ stands for r in every denominator: equal to r beyond one support radius from
            // the axis, and finite on it.
            let r_hat = input.smoothed_radius.at(r, h);
            let rho = p.density[i];
            let v_r = p.velocity[i].component(0);
            // η = ρ R̂: dρ/dt = (dη/dt − ρ R̂' v_r)/R̂.
            out.drho = (out.drho - rho * input.smoothed_radius.slope(r, h) * v_r) / r_hat;
            let d = input.damage.get(i).copied().unwrap_or(0.0);
            let s_tt = input.stress.get(i).map_or(0.0, |s| s.z_axis.z);
            let sigma_tt = input.coupling.own_factor(d) * s_tt - input.pressure[i];
            // −σ_θθ ŝ/η along r.
            let mut a = D::Vector::ZERO;
            a.set_component(0, -sigma_tt * gauge / (rho * r_hat));
            out.dv += a;
            if input.energy == EnergyForm::Study {
                out.de += sigma_tt * v_r / (rho * r_hat);
            }
        });
}

/// The hoop strain rate L_θθ = v_r/R̂ of particle i (R̂ for r, finite on the axis), which
/// the deviatoric stress rate adds to the in-plane velocity gradient in RZ.
pub(crate) fn hoop_strain_rate<D: Dimension>(
    p: &Particles<D>,
    i: usize,
    smoothed_radius: &SmoothedRadius,
) -> f64 {
    let (r, h) = (radius(p.position[i]), p.smoothing_length[i]);
    p.velocity[i].component(0) / smoothed_radius.at(r, h)
}

/// The kernel-smoothed radius R̂(r, h) = ∫ |x'| W(x − x', h) dA' of the (r, z) plane, which
/// the summation Σ_j m_j W_ij = Σ ρ A r W of a uniform density returns as ρ R̂ instead of
/// ρ r: R̂ = r where the support does not reach the axis (r ≥ h), larger next to it.
/// Tabulated once per kernel as R̂ = h f(r/h), f by midpoint quadrature.
#[derive(Clone, Debug)]
pub(crate) struct SmoothedRadius {
    /// f(q) at q = k/(len − 1), k = 0 … len − 1.
    table: Vec<f64>,
}

impl SmoothedRadius {
    /// Tabulates f for the 2-D kernel `w(x, z)` of unit support radius.
    pub(crate) fn new(w: impl Fn(f64, f64) -> f64 + Sync) -> Self {
        let (nq, nu) = (201, 400);
        let du = 2.0 / nu as f64;
        // 32 M kernel values, at the start of every RZ run: the rows of the table in
        // parallel, each summed in its own fixed order.
        let table = (0..nq)
            .into_par_iter()
            .map(|k| {
                let q = k as f64 / (nq - 1) as f64;
                let (mut num, mut den) = (0.0, 0.0);
                for a in 0..nu {
                    let u = -1.0 + (a as f64 + 0.5) * du;
                    for b in 0..nu {
                        let v = -1.0 + (b as f64 + 0.5) * du;
                        let wk = w(u, v);
                        num += (q - u).abs() * wk;
                        den += wk;
                    }
                }
                // Normalised by the discrete ∫W, so f(q) = q exactly for q ≥ 1 up to the
                // quadrature of a linear function (exact by symmetry).
                num / den
            })
            .collect();
        Self { table }
    }

    /// dR̂/dr at (r, h) (1 for r ≥ h).
    pub(crate) fn slope(&self, r: f64, h: f64) -> f64 {
        let q = r / h;
        if q >= 1.0 {
            return 1.0;
        }
        let n = self.table.len() - 1;
        let k = ((q * n as f64).floor() as usize).min(n - 1);
        (self.table[k + 1] - self.table[k]) * n as f64
    }

    /// R̂(r, h).
    pub(crate) fn at(&self, r: f64, h: f64) -> f64 {
        let q = r / h;
        if q >= 1.0 {
            return r;
        }
        let n = self.table.len() - 1;
        let x = q * n as f64;
        let k = (x.floor() as usize).min(n - 1);
        let t = x - k as f64;
        h * (self.table[k] * (1.0 - t) + self.table[k + 1] * t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_kernel::{Kernel, WendlandC2};

    #[test]
    fn ring_area_is_the_lattice_cell_and_bounded_on_the_axis() {
        let (dx, rho) = (1e-3, 2876.0);
        for col in 0..5 {
            // A lattice ring: mass per radian ρ Δx² r, area Δx² (the first column at
            // the switch).
            let r = (col as f64 + 0.5) * dx;
            let a = ring_area(rho * dx * dx * r, r, rho);
            assert!((a / (dx * dx) - 1.0).abs() < 1e-12, "{col}: {a}");
        }
        // First-column mass: continuous through the switch, bounded on the axis.
        let m = rho * dx * dx * 0.5 * dx;
        let at = |r: f64| ring_area(m, r, rho) / (dx * dx);
        assert!((at(0.5 * dx * (1.0 - 1e-9)) - at(0.5 * dx * (1.0 + 1e-9))).abs() < 1e-8);
        assert!((at(0.0) - 1.0).abs() < 1e-12 && at(1e-6 * dx) == at(0.0));
        assert!((at(2.0 * dx) - 0.25).abs() < 1e-12);
        // The density for an area inverts ring_area on both sides of the switch.
        for r in [0.0, 0.2 * dx, 0.5 * dx, 3.0 * dx] {
            for side in [0.5 * dx, dx, 4.0 * dx] {
                let rho_s = ring_density_for_area(m, r, side);
                let back = ring_area(m, r, rho_s);
                assert!((back / (side * side) - 1.0).abs() < 1e-12, "{r} {side}");
            }
        }
    }

    #[test]
    fn smoothed_radius_is_r_away_from_the_axis_and_positive_on_it() {
        let k = WendlandC2;
        let s = SmoothedRadius::new(|u, v| k.w(sph_core::glam::DVec2::new(u, v), 1.0));
        // At q = 1 the support just touches the axis: R̂ = r.
        assert!(
            (s.at(0.999_999, 1.0) - 1.0).abs() < 1e-3,
            "{}",
            s.at(0.999_999, 1.0)
        );
        assert_eq!(s.at(2.0, 1.0), 2.0);
        // On the axis R̂ is the kernel's mean |x|, positive.
        let r0 = s.at(0.0, 1.0);
        assert!(r0 > 0.1 && r0 < 0.5, "{r0}");
        // Monotone.
        assert!((0..100).all(|k| s.at(k as f64 / 100.0, 1.0) < s.at((k + 1) as f64 / 100.0, 1.0)));
    }
}

//! The limited Monaghan–Gingold viscosity of LLNL Spheral
//! (src/ArtificialViscosity/LimitedMonaghanGingoldViscosity.cc), the viscosity of its solid
//! FSISPH, which the reference study ran.
//!
//! Before Monaghan's Π_ij is formed (paper §2.2, [`crate::MonaghanViscosity::pi`]), each
//! side's velocity is reconstructed to the pair midpoint with its own velocity gradient L
//! (∂v_a/∂x_b), scaled by a van Leer limiter φ of the two gradients' ratio along the pair:
//!
//! ```text
//! x̄ = (x_i − x_j)/2,   g_k = (L_k x̄)·x̄,   r_i = g_i/g_j,   r_j = g_j/g_i
//! φ = VL(min(r_i, r_j)),   VL(x) = 4x/(1 + x)² for x > 0, else 0
//! v_i' = v_i − φ L_i x̄,    v_j' = v_j + φ L_j x̄
//! ```
//!
//! and Π is formed from v_i' − v_j'. In a smooth compression (both sides see the same
//! linear field) φ = 1 and the reconstructed velocities meet at the midpoint: no
//! viscosity. At a shock or a discontinuity the gradients disagree, φ → 0, and Π is
//! Monaghan's. Pairs closer than one particle spacing fade φ out as
//! exp(−((q − 1)/0.2)²) with q = |x_i − x_j|/Δx (Spheral's etaCrit = 1/nPerh and
//! etaFold = 0.2/nPerh), so that interpenetrating particles keep their full viscosity.
//! The reconstruction is symmetric in (i, j): v_i' − v_j' changes sign with the pair, so
//! Π_ij = Π_ji and momentum stays exact.

use sph_core::{Tensor, Vector};

/// The van Leer limiter Spheral's viscosity uses: 4x/(1 + x)² for x > 0, else 0.
#[inline]
pub fn van_leer_ratio(x: f64) -> f64 {
    if x > 0.0 {
        4.0 * x / ((1.0 + x) * (1.0 + x))
    } else {
        0.0
    }
}

/// Spheral's sign convention: −1 below zero, +1 otherwise.
#[inline]
fn sgn(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}

/// The limiter φ of a pair (module docs): `l_i`, `l_j` the velocity gradients,
/// `half` = (x_i − x_j)/2, `q` = |x_i − x_j|/Δx (the pair's distance in particle
/// spacings).
#[inline]
pub fn limiter_phi<T: Tensor>(l_i: &T, l_j: &T, half: T::Vector, q: f64) -> f64 {
    let g_i = l_i.mul_vec(half).dot(half);
    let g_j = l_j.mul_vec(half).dot(half);
    let r_i = g_i / (sgn(g_j) * g_j.abs().max(1.0e-30));
    let r_j = g_j / (sgn(g_i) * g_i.abs().max(1.0e-30));
    let mut phi = van_leer_ratio(r_i.min(r_j));
    if q < 1.0 {
        let t = (q - 1.0) / 0.2;
        phi *= (-t * t).exp();
    }
    phi
}

/// The reconstructed relative velocity v_i' − v_j' of a pair (module docs): `r` =
/// x_i − x_j, `q` = |r|/Δx.
#[inline]
pub fn limited_relative_velocity<T: Tensor>(
    v_i: T::Vector,
    v_j: T::Vector,
    l_i: &T,
    l_j: &T,
    r: T::Vector,
    q: f64,
) -> T::Vector {
    let half = r * 0.5;
    let phi = limiter_phi(l_i, l_j, half, q);
    let vi = v_i - l_i.mul_vec(half) * phi;
    let vj = v_j + l_j.mul_vec(half) * phi;
    vi - vj
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::{DMat3, DVec3};

    #[test]
    fn van_leer_point_values() {
        assert_eq!(van_leer_ratio(1.0), 1.0);
        assert_eq!(van_leer_ratio(0.0), 0.0);
        assert_eq!(van_leer_ratio(-1.0), 0.0);
        assert!((van_leer_ratio(0.5) - 2.0 / 2.25).abs() < 1e-15);
    }

    #[test]
    fn a_linear_compression_has_no_relative_velocity_at_the_midpoint() {
        // v = −a x (uniform compression), the same L on both sides: φ = 1 and the
        // reconstructed velocities meet.
        let a = 1.0e3;
        let l = DMat3::from_diagonal(DVec3::splat(-a));
        let (xi, xj) = (DVec3::new(1.0e-3, 0.0, 0.0), DVec3::new(0.0, 0.5e-3, 0.0));
        let (vi, vj) = (xi * -a, xj * -a);
        let v = limited_relative_velocity(vi, vj, &l, &l, xi - xj, 1.5);
        assert!(v.length() < 1e-12 * (vi - vj).length(), "{v}");
    }

    #[test]
    fn opposite_gradients_keep_the_raw_velocity() {
        // A kink: compression on one side, expansion on the other: φ = 0.
        let li = DMat3::from_diagonal(DVec3::splat(-1.0e3));
        let lj = DMat3::from_diagonal(DVec3::splat(1.0e3));
        let (vi, vj) = (DVec3::new(-5.0, 0.0, 0.0), DVec3::new(5.0, 0.0, 0.0));
        let r = DVec3::new(1.0e-3, 0.0, 0.0);
        assert_eq!(limited_relative_velocity(vi, vj, &li, &lj, r, 1.5), vi - vj);
    }

    #[test]
    fn close_pairs_fade_the_limiter_out() {
        let l = DMat3::from_diagonal(DVec3::splat(-1.0e3));
        let half = DVec3::new(0.5e-3, 0.0, 0.0);
        assert_eq!(limiter_phi(&l, &l, half, 1.0), 1.0);
        let phi = limiter_phi(&l, &l, half, 0.8);
        assert!((phi - (-1.0f64).exp()).abs() < 1e-15);
        assert!(limiter_phi(&l, &l, half, 0.2) < 1e-6);
    }

    #[test]
    fn symmetric_in_the_pair() {
        let li = DMat3::from_cols(
            DVec3::new(-2.0, 0.3, 0.1),
            DVec3::new(0.2, -1.0, 0.0),
            DVec3::new(0.0, 0.4, -0.5),
        ) * 1.0e3;
        let lj = li * 0.7;
        let (vi, vj) = (DVec3::new(1.0, 2.0, 3.0), DVec3::new(-1.0, 0.5, 2.0));
        let r = DVec3::new(1.0e-3, 2.0e-4, -3.0e-4);
        let a = limited_relative_velocity(vi, vj, &li, &lj, r, 1.3);
        let b = limited_relative_velocity(vj, vi, &lj, &li, -r, 1.3);
        assert!((a + b).length() < 1e-13 * a.length());
    }
}

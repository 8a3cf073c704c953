//! Hooke's law for the deviatoric stress with the Jaumann (co-rotational) rate, paper
//! §3.2 (Libersky & Petschek 1991; Libersky et al. 1993, JCP 109:67, eq. 8):
//!
//!   `dS/dt = 2G ε̇' + Ω S − S Ω`,
//!
//! on 3×3 matrices ([`DMat3`]). Conventions, which every caller must share:
//!
//! - **Velocity gradient** `L_ij = ∂v_i/∂x_j`: row i, column j (glam stores columns, so
//!   `L.col(j)[i]`). Then `dx/dt = v` gives `d(dx)/dt = L dx` for a material line
//!   element dx.
//! - **Strain rate** `ε̇ = ½ (L + Lᵀ)`, and its **deviator** `ε̇' = ε̇ − (tr ε̇ / 3) I`,
//!   always the 3-D trace/3, also for states embedded from 1-D, 2-D or RZ.
//! - **Spin** `Ω = ½ (L − Lᵀ)`, so `Ω_ij = ½ (∂v_i/∂x_j − ∂v_j/∂x_i)`.
//!
//! With this sign a rigid rotation `v = W x` (W antisymmetric) has `L = Ω = W`, the body
//! turns as `R(t) = exp(W t)` and a stress carried by it, `S(t) = R S0 Rᵀ`, satisfies
//! `dS/dt = W S − S W` — exactly the rotation terms above. (Writing the terms as
//! `S Ωᵀ + Ω S` is the same thing; flipping the sign of Ω makes S counter-rotate, which
//! the rigid-rotation test catches.)
//!
//! **Embedding lower dimensions:** plane strain and RZ states put the out-of-plane
//! normal component in the third diagonal entry (S_zz, respectively the hoop S_θθ, with
//! `L_θθ = v_r / r` in RZ); 1-D uses only the first diagonal entry of L and a diagonal S.
//! The deviator then keeps the out-of-plane stress that plane strain needs.

use sph_core::glam::DMat3;

/// Symmetric part `ε̇ = ½ (L + Lᵀ)` of the velocity gradient (strain rate, 1/s).
#[inline]
pub fn strain_rate(velocity_gradient: &DMat3) -> DMat3 {
    (*velocity_gradient + velocity_gradient.transpose()) * 0.5
}

/// Antisymmetric part `Ω = ½ (L − Lᵀ)` of the velocity gradient (spin, 1/s).
#[inline]
pub fn spin(velocity_gradient: &DMat3) -> DMat3 {
    (*velocity_gradient - velocity_gradient.transpose()) * 0.5
}

/// 3-D deviator `A − (tr A / 3) I`.
#[inline]
pub fn deviator(a: &DMat3) -> DMat3 {
    let t = (a.x_axis.x + a.y_axis.y + a.z_axis.z) / 3.0;
    *a - DMat3::from_diagonal(sph_core::glam::DVec3::splat(t))
}

/// The co-rotational terms `Ω S − S Ω` for a symmetric S. Because S is symmetric and Ω
/// antisymmetric, `−S Ω = (Ω S)ᵀ`, so one product suffices.
#[inline]
pub fn rotation_terms(stress: &DMat3, spin: &DMat3) -> DMat3 {
    let ws = *spin * *stress;
    ws + ws.transpose()
}

/// Jaumann rate of the deviatoric stress, `dS/dt = 2G ε̇' + Ω S − S Ω` (Pa/s), for the
/// symmetric deviatoric stress `stress`, the velocity gradient `L_ij = ∂v_i/∂x_j` and the
/// shear modulus `shear_modulus` (see the module docs for every convention).
#[inline]
pub fn jaumann_rate(stress: &DMat3, velocity_gradient: &DMat3, shear_modulus: f64) -> DMat3 {
    let eps_dev = deviator(&strain_rate(velocity_gradient));
    eps_dev * (2.0 * shear_modulus) + rotation_terms(stress, &spin(velocity_gradient))
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::glam::DVec3;

    #[test]
    fn pure_shear_from_rest_is_hooke() {
        // Pure shear L = L^T with ε̇_xy = e: dS_xy/dt = 2 G e, no rotation.
        let e = 1.0e3;
        let g = 26.0e9;
        let l = DMat3::from_cols(
            DVec3::new(0.0, e, 0.0),
            DVec3::new(e, 0.0, 0.0),
            DVec3::ZERO,
        );
        let r = jaumann_rate(&DMat3::ZERO, &l, g);
        assert_eq!(r.col(1)[0], 2.0 * g * e);
        assert_eq!(r.col(0)[1], 2.0 * g * e);
        assert_eq!(r.x_axis.x, 0.0);
        assert_eq!(r.z_axis.z, 0.0);
    }

    #[test]
    fn uniaxial_compression_deviator() {
        // 1-D compression ε̇_xx = −d: ε̇' = diag(−2d/3, d/3, d/3); trace of the rate 0.
        let d = 300.0;
        let l = DMat3::from_diagonal(DVec3::new(-d, 0.0, 0.0));
        let r = jaumann_rate(&DMat3::ZERO, &l, 1.0);
        assert!((r.x_axis.x + 4.0 * d / 3.0).abs() < 1e-12);
        assert!((r.y_axis.y - 2.0 * d / 3.0).abs() < 1e-12);
        assert!((r.z_axis.z - 2.0 * d / 3.0).abs() < 1e-12);
    }
}

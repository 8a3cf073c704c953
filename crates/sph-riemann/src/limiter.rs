//! Slope limiters and the limited linear reconstruction of each particle's state at the
//! pair midpoint (MUSCL along the pair axis; Inutsuka 2002 and the GSPH literature
//! reconstruct along the pair axis in the same way).

use serde::{Deserialize, Serialize};

/// A TVD slope limiter φ(r) applied as a symmetric "limited average" of two slopes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Limiter {
    /// No reconstruction: first order (each side uses its particle value).
    #[default]
    None,
    /// minmod: the smaller slope when both have the same sign, else zero.
    Minmod,
    /// van Leer: the harmonic mean 2ab/(a+b) when a·b > 0, else zero.
    VanLeer,
}

impl Limiter {
    /// The limited slope from two slope estimates `a` and `b` (same units).
    #[inline]
    pub fn limit(&self, a: f64, b: f64) -> f64 {
        match self {
            Limiter::None => 0.0,
            Limiter::Minmod => {
                if a * b <= 0.0 {
                    0.0
                } else if a.abs() < b.abs() {
                    a
                } else {
                    b
                }
            }
            Limiter::VanLeer => {
                if a * b <= 0.0 {
                    0.0
                } else {
                    2.0 * a * b / (a + b)
                }
            }
        }
    }
}

/// Reconstructs a scalar at the pair midpoint from both particles.
///
/// `q_i`, `q_j` are the particle values; `dq_i`, `dq_j` the changes their own gradients
/// predict over the half-separation towards the midpoint (∇q_i·(x_j − x_i)/2 and
/// ∇q_j·(x_i − x_j)/2). Each side's increment is limited against the centred increment
/// (q_j − q_i)/2, so no new extrema appear. Returns (q_i at the face, q_j at the face).
#[inline]
pub fn reconstruct(q_i: f64, q_j: f64, dq_i: f64, dq_j: f64, limiter: Limiter) -> (f64, f64) {
    let centred = 0.5 * (q_j - q_i);
    let face_i = q_i + limiter.limit(dq_i, centred);
    let face_j = q_j + limiter.limit(dq_j, -centred);
    (face_i, face_j)
}

/// LLNL Spheral's limited linear reconstruction of a scalar to the pair midpoint
/// (SolidFSISPH::linearReconstruction, src/FSISPH/SolidFSISPH.cc), used by its energy
/// diffusion: with Δ = q_i − q_j and each side's predicted change over the half
/// separation δ_i = ∇q_i·(x_i − x_j)/2, δ_j = ∇q_j·(x_i − x_j)/2 (`dq_i`, `dq_j`), the
/// ratios x_k = 2δ_k/Δ set φ = ½(φ(x_i) + φ(x_j)) with the van Leer φ(x) = min(1,
/// 4x/(1 + x)²) for x > 0, else 0; the faces are q_i − φ δ_i and q_j + φ δ_j. A linear
/// field (x = 1) meets at the midpoint. Where the gradients are much steeper than the
/// pair's own difference Δ (a jump elsewhere in the kernel), φ ≈ 4/x → 0 but each face
/// still moves by φδ ≈ 2Δ, so the faces cross: their difference tends to −3Δ. A
/// diffusion driven by the faces then runs backwards between such a pair (measured on a
/// heat-conducting chain: the particle next to the jump on the hot side overshoots by
/// 0.5 %, tests/solid.rs); this is the formula as Spheral writes it.
#[inline]
pub fn spheral_reconstruct(q_i: f64, q_j: f64, dq_i: f64, dq_j: f64) -> (f64, f64) {
    let d0 = q_i - q_j;
    let denom = 2.0 / (if d0 < 0.0 { -1.0 } else { 1.0 } * d0.abs().max(f64::EPSILON));
    let vl = |x: f64| {
        if x > 0.0 {
            (4.0 * x / ((1.0 + x) * (1.0 + x))).min(1.0)
        } else {
            0.0
        }
    };
    let phi = 0.5 * (vl(dq_i * denom) + vl(dq_j * denom));
    (q_i - phi * dq_i, q_j + phi * dq_j)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spheral_reconstruction_point_values() {
        // A linear field q = x at x_i = 1, x_j = 0: δ = ½ on both sides, x = 1, φ = 1:
        // both faces at the midpoint.
        assert_eq!(spheral_reconstruct(1.0, 0.0, 0.5, 0.5), (0.5, 0.5));
        // Gradients twice as steep as the pair's difference: x = 2, φ = 8/9.
        let (a, b) = spheral_reconstruct(1.0, 0.0, 1.0, 1.0);
        assert!((a - 1.0 / 9.0).abs() < 1e-15 && (b - 8.0 / 9.0).abs() < 1e-15);
        // A jump elsewhere in the kernel: gradients 10⁴ times the pair's difference Δ,
        // x = 2e4, φ ≈ 4/x: each face moves by φδ ≈ 2Δ, so the faces cross and their
        // difference tends to −3Δ (Spheral's formula does this next to a jump).
        let (a, b) = spheral_reconstruct(1.0, 1.0 - 1e-4, 1.0, 1.0);
        assert!(((a - b) / 1e-4 + 3.0).abs() < 1e-3, "{a} {b}");
        // Both gradients against the pair's difference: no reconstruction; one of
        // them: φ is the mean of 0 and 1, applied to both sides.
        assert_eq!(spheral_reconstruct(1.0, 0.0, -0.5, -0.5), (1.0, 0.0));
        assert_eq!(spheral_reconstruct(1.0, 0.0, -0.5, 0.5), (1.25, 0.25));
        // Symmetric in the pair: swapping i and j flips x_i − x_j and so the δs' signs.
        let (a, b) = spheral_reconstruct(2.0, 1.0, 0.3, 0.6);
        let (c, d) = spheral_reconstruct(1.0, 2.0, -0.6, -0.3);
        assert_eq!((a, b), (d, c));
    }
}

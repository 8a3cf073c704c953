//! Wendland kernels C2, C4 and C6 (Wendland 1995; Dehnen & Aly 2012, Table 1), the
//! 3-D functions used in every dimension (positive definite in d ≤ 3), support radius 1.
//! σ_d = 1 / (S_d ∫₀¹ q^(d−1) f(q) dq) with S_d = 2, 2π, 4π, integrated exactly.

use crate::kernel::{Kernel, pick};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Wendland C2: f(q) = (1 − q)⁴ (1 + 4q). The study's kernel (paper §2.4):
/// σ = 3/2, 7/π, 21/(2π) in 1-, 2-, 3-D.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct WendlandC2;

impl Kernel for WendlandC2 {
    fn name(&self) -> &'static str {
        "wendland-c2"
    }
    #[inline]
    fn f(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        let u = 1.0 - q;
        let u2 = u * u;
        u2 * u2 * (1.0 + 4.0 * q)
    }
    #[inline]
    fn df(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        // d/dq[(1−q)⁴(1+4q)] = −20 q (1−q)³
        let u = 1.0 - q;
        -20.0 * q * u * u * u
    }
    #[inline]
    fn sigma(&self, dim: usize) -> f64 {
        pick(dim, [1.5, 7.0 / PI, 21.0 / (2.0 * PI)])
    }
}

/// Wendland C4: f(q) = (1 − q)⁶ (1 + 6q + 35q²/3); σ = 27/16, 9/π, 495/(32π).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct WendlandC4;

impl Kernel for WendlandC4 {
    fn name(&self) -> &'static str {
        "wendland-c4"
    }
    #[inline]
    fn f(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        let u = 1.0 - q;
        let u3 = u * u * u;
        u3 * u3 * (1.0 + 6.0 * q + 35.0 / 3.0 * q * q)
    }
    #[inline]
    fn df(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        // d/dq = −(56/3) q (1 + 5q) (1−q)⁵
        let u = 1.0 - q;
        let u2 = u * u;
        -56.0 / 3.0 * q * (1.0 + 5.0 * q) * u2 * u2 * u
    }
    #[inline]
    fn sigma(&self, dim: usize) -> f64 {
        pick(dim, [27.0 / 16.0, 9.0 / PI, 495.0 / (32.0 * PI)])
    }
}

/// Wendland C6: f(q) = (1 − q)⁸ (1 + 8q + 25q² + 32q³); σ = 15/8, 78/(7π), 1365/(64π).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct WendlandC6;

impl Kernel for WendlandC6 {
    fn name(&self) -> &'static str {
        "wendland-c6"
    }
    #[inline]
    fn f(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        let u = 1.0 - q;
        let u4 = (u * u) * (u * u);
        u4 * u4 * (1.0 + 8.0 * q + 25.0 * q * q + 32.0 * q * q * q)
    }
    #[inline]
    fn df(&self, q: f64) -> f64 {
        if q >= 1.0 {
            return 0.0;
        }
        // d/dq = −22 q (1 + 7q + 16q²) (1−q)⁷
        let u = 1.0 - q;
        let u3 = u * u * u;
        -22.0 * q * (1.0 + 7.0 * q + 16.0 * q * q) * u3 * u3 * u
    }
    #[inline]
    fn sigma(&self, dim: usize) -> f64 {
        pick(dim, [15.0 / 8.0, 78.0 / (7.0 * PI), 1365.0 / (64.0 * PI)])
    }
}

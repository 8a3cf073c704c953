//! The cubic B-spline (M4; Monaghan & Lattanzio 1985), rescaled to support radius 1:
//! with s = 2q, f = 1 − 3s²/2 + 3s³/4 for s < 1 and (2 − s)³/4 for 1 ≤ s < 2, i.e.
//! f(q) = 1 − 6q² + 6q³ (q < ½), 2(1 − q)³ (½ ≤ q < 1); σ = 4/3, 40/(7π), 8/π.

use crate::kernel::{Kernel, pick};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Cubic B-spline with compact support radius h (not 2h).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct CubicSpline;

impl Kernel for CubicSpline {
    fn name(&self) -> &'static str {
        "cubic-spline"
    }
    #[inline]
    fn f(&self, q: f64) -> f64 {
        if q >= 1.0 {
            0.0
        } else if q < 0.5 {
            1.0 - 6.0 * q * q + 6.0 * q * q * q
        } else {
            let u = 1.0 - q;
            2.0 * u * u * u
        }
    }
    #[inline]
    fn df(&self, q: f64) -> f64 {
        if q >= 1.0 {
            0.0
        } else if q < 0.5 {
            -12.0 * q + 18.0 * q * q
        } else {
            let u = 1.0 - q;
            -6.0 * u * u
        }
    }
    #[inline]
    fn sigma(&self, dim: usize) -> f64 {
        pick(dim, [4.0 / 3.0, 40.0 / (7.0 * PI), 8.0 / PI])
    }
}

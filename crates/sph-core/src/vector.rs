//! The [`Vector`] trait: what the SPH code needs from a position or velocity,
//! implemented for `f64` (1-D), [`glam::DVec2`] (2-D) and [`glam::DVec3`] (3-D).

use glam::{DVec2, DVec3};
use std::fmt::Debug;
use std::ops::{Add, AddAssign, Div, Mul, MulAssign, Neg, Sub, SubAssign};

/// A fixed-size f64 vector in `DIM` dimensions.
///
/// Only what the physics needs is here; everything is `#[inline]` so generic code
/// monomorphises to the same instructions as hand-written per-dimension code.
pub trait Vector:
    Copy
    + Clone
    + Send
    + Sync
    + Debug
    + Default
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Neg<Output = Self>
    + Mul<f64, Output = Self>
    + Div<f64, Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign<f64>
    + 'static
{
    /// Number of components.
    const DIM: usize;
    /// The zero vector.
    const ZERO: Self;

    /// Euclidean inner product.
    fn dot(self, other: Self) -> f64;
    /// Component `i` (0-based); panics if `i >= DIM`.
    fn component(self, i: usize) -> f64;
    /// Sets component `i` (0-based); panics if `i >= DIM`.
    fn set_component(&mut self, i: usize, value: f64);
    /// Builds a vector from its components.
    fn from_fn(f: impl FnMut(usize) -> f64) -> Self;

    /// Squared length.
    #[inline]
    fn norm_squared(self) -> f64 {
        self.dot(self)
    }
    /// Length.
    #[inline]
    fn norm(self) -> f64 {
        self.dot(self).sqrt()
    }
    /// All components set to `value`.
    #[inline]
    fn splat(value: f64) -> Self {
        Self::from_fn(|_| value)
    }
    /// Unit vector along axis `i`.
    #[inline]
    fn unit(i: usize) -> Self {
        Self::from_fn(|k| if k == i { 1.0 } else { 0.0 })
    }
    /// Component-wise minimum.
    #[inline]
    fn component_min(self, other: Self) -> Self {
        Self::from_fn(|k| self.component(k).min(other.component(k)))
    }
    /// Component-wise maximum.
    #[inline]
    fn component_max(self, other: Self) -> Self {
        Self::from_fn(|k| self.component(k).max(other.component(k)))
    }
    /// Component-wise product.
    #[inline]
    fn component_mul(self, other: Self) -> Self {
        Self::from_fn(|k| self.component(k) * other.component(k))
    }
    /// True when every component is finite (not NaN, not infinite).
    #[inline]
    fn all_finite(self) -> bool {
        (0..Self::DIM).all(|k| self.component(k).is_finite())
    }
    /// Components as a fixed 3-array (missing ones zero), for output writers.
    #[inline]
    fn to_array3(self) -> [f64; 3] {
        let mut a = [0.0; 3];
        for (k, v) in a.iter_mut().enumerate().take(Self::DIM) {
            *v = self.component(k);
        }
        a
    }
}

impl Vector for f64 {
    const DIM: usize = 1;
    const ZERO: Self = 0.0;
    #[inline]
    fn dot(self, other: Self) -> f64 {
        self * other
    }
    #[inline]
    fn component(self, i: usize) -> f64 {
        assert!(i == 0, "component {i} of a 1-D vector");
        self
    }
    #[inline]
    fn set_component(&mut self, i: usize, value: f64) {
        assert!(i == 0, "component {i} of a 1-D vector");
        *self = value;
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        f(0)
    }
}

impl Vector for DVec2 {
    const DIM: usize = 2;
    const ZERO: Self = DVec2::ZERO;
    #[inline]
    fn dot(self, other: Self) -> f64 {
        DVec2::dot(self, other)
    }
    #[inline]
    fn component(self, i: usize) -> f64 {
        self[i]
    }
    #[inline]
    fn set_component(&mut self, i: usize, value: f64) {
        self[i] = value;
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        DVec2::new(f(0), f(1))
    }
}

impl Vector for DVec3 {
    const DIM: usize = 3;
    const ZERO: Self = DVec3::ZERO;
    #[inline]
    fn dot(self, other: Self) -> f64 {
        DVec3::dot(self, other)
    }
    #[inline]
    fn component(self, i: usize) -> f64 {
        self[i]
    }
    #[inline]
    fn set_component(&mut self, i: usize, value: f64) {
        self[i] = value;
    }
    #[inline]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        DVec3::new(f(0), f(1), f(2))
    }
}

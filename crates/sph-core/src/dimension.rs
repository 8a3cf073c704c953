//! The [`Dimension`] abstraction: one generic source for 1-D, 2-D and 3-D.
//!
//! The geometry is chosen once at the top of a program (a `match` on the scene's
//! geometry) and everything below is monomorphised for it. The axisymmetric (RZ)
//! geometry will be a fourth implementor with `Vector = DVec2` and hoop-term hooks;
//! see `docs/architecture.md`.

use crate::tensor::Tensor;
use crate::vector::Vector;
use glam::{DMat2, DMat3, DVec2, DVec3};
use std::f64::consts::PI;
use std::fmt::Debug;

/// A spatial dimension: the vector and tensor types plus a few constants.
pub trait Dimension: Copy + Clone + Send + Sync + Debug + Default + PartialEq + 'static {
    /// Number of spatial coordinates.
    const DIM: usize;
    /// A short name for messages and output ("1d", "2d", "3d").
    const NAME: &'static str;
    /// Positions, velocities, gradients.
    type Vector: Vector + serde::Serialize + serde::de::DeserializeOwned;
    /// Second-rank tensors (velocity gradient, ASPH H).
    type Tensor: Tensor<Vector = Self::Vector> + serde::Serialize + serde::de::DeserializeOwned;

    /// Volume of the unit ball: 2 (1-D), π (2-D), 4π/3 (3-D).
    fn unit_ball_volume() -> f64;
    /// Surface measure of the unit sphere: 2 (1-D), 2π (2-D), 4π (3-D).
    fn unit_sphere_area() -> f64 {
        Self::DIM as f64 * Self::unit_ball_volume()
    }
}

/// One dimension: `Vector = f64`, `Tensor = f64`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dim1;
/// Two dimensions (planar): `Vector = DVec2`, `Tensor = DMat2`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dim2;
/// Three dimensions: `Vector = DVec3`, `Tensor = DMat3`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Dim3;

impl Dimension for Dim1 {
    const DIM: usize = 1;
    const NAME: &'static str = "1d";
    type Vector = f64;
    type Tensor = f64;
    fn unit_ball_volume() -> f64 {
        2.0
    }
}

impl Dimension for Dim2 {
    const DIM: usize = 2;
    const NAME: &'static str = "2d";
    type Vector = DVec2;
    type Tensor = DMat2;
    fn unit_ball_volume() -> f64 {
        PI
    }
}

impl Dimension for Dim3 {
    const DIM: usize = 3;
    const NAME: &'static str = "3d";
    type Vector = DVec3;
    type Tensor = DMat3;
    fn unit_ball_volume() -> f64 {
        4.0 / 3.0 * PI
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_area_is_dim_times_ball_volume() {
        assert_eq!(Dim1::unit_sphere_area(), 2.0);
        assert!((Dim2::unit_sphere_area() - 2.0 * PI).abs() < 1e-15);
        assert!((Dim3::unit_sphere_area() - 4.0 * PI).abs() < 1e-14);
    }
}

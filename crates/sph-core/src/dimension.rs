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
    /// The tensor as the top-left block of a 3×3 (zeros elsewhere): stress and strain
    /// rate live in 3-D even in 1-D (uniaxial strain) and 2-D (plane strain).
    fn embed(t: &Self::Tensor) -> glam::DMat3 {
        glam::DMat3::from_cols_array_2d(&std::array::from_fn(|col| {
            std::array::from_fn(|row| {
                if row < Self::DIM && col < Self::DIM {
                    t.component(row, col)
                } else {
                    0.0
                }
            })
        }))
    }
    /// The top-left DIM×DIM block of a 3×3.
    fn project(m: &glam::DMat3) -> Self::Tensor {
        Self::Tensor::from_fn(|row, col| m.col(col)[row])
    }
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

#[cfg(test)]
mod embed_tests {
    use super::*;
    use crate::tensor::Tensor;

    #[test]
    fn embed_then_project_is_the_identity_and_pads_with_zeros() {
        let t = DMat2::from_cols(DVec2::new(1.0, 2.0), DVec2::new(3.0, 4.0));
        let m = Dim2::embed(&t);
        assert_eq!(m.col(1)[0], 3.0);
        assert_eq!(m.col(2), glam::DVec3::ZERO);
        assert_eq!(Dim2::project(&m), t);
        assert_eq!(Dim1::project(&Dim1::embed(&5.0)), 5.0);
        assert_eq!(Dim1::embed(&5.0).col(1), glam::DVec3::ZERO);
        let full = DMat3::from_cols_array(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        assert_eq!(Dim3::embed(&Dim3::project(&full)), full);
        assert_eq!(full.component(0, 1), 4.0);
    }
}

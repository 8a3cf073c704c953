//! # sph-core
//!
//! The ground floor of the SPH workspace: the [`Dimension`] abstraction over glam's f64
//! types (1-D, 2-D, 3-D; axisymmetric RZ to come), [`Vector`] and [`Tensor`] helpers
//! (trace, deviator, J2, double contraction, outer product, symmetric eigen-decomposition),
//! the [`Particles`] store (structure of arrays), neighbour search ([`CellList`] giving a
//! CSR [`NeighborList`]) and the Morton reordering that keeps neighbours close in memory.
//!
//! All quantities are f64 in SI units.
//!
//! ```
//! use sph_core::{CellList, NeighborSearch, ScalarSupport, morton_order};
//! use glam::DVec3;
//!
//! // A 10×10×10 cubic lattice of spacing 1 with support radius h = 2.5.
//! let mut x: Vec<DVec3> = (0..1000)
//!     .map(|k| DVec3::new((k % 10) as f64, ((k / 10) % 10) as f64, (k / 100) as f64))
//!     .collect();
//! // Put the particles in space-filling-curve order first.
//! let perm = morton_order(&x).unwrap();
//! perm.apply("position", &mut x).unwrap();
//! let h = vec![2.5; x.len()];
//! let list = CellList::new()
//!     .neighbors(&x, &ScalarSupport::new(&h).unwrap())
//!     .unwrap();
//! // An interior particle sees every lattice point within 2.5 of it (the ball holds
//! // 81 lattice points including itself).
//! let centre = x.iter().position(|p| *p == DVec3::new(5.0, 5.0, 5.0)).unwrap();
//! assert_eq!(list.count(centre), 80);
//! ```
//!
//! ## Feature flags
//! None yet.

pub mod dimension;
pub mod eigen;
pub mod error;
pub mod neighbors;
pub mod particles;
pub mod permutation;
pub mod tensor;
pub mod vector;

pub use dimension::{Dim1, Dim2, Dim3, Dimension};
pub use eigen::SymEigen;
pub use error::CoreError;
pub use neighbors::{
    CellList, NeighborList, NeighborSearch, Neighbors, PairCriterion, PairSelection, Pairs,
    PickedRows, Region, RowPicker, ScalarSupport, TensorSupport, brute_force_neighbors, halo,
    regions_of_rows,
};
pub use particles::{ParticleInit, Particles};
pub use permutation::{Permutation, morton_order};
pub use tensor::Tensor;
pub use vector::Vector;

/// Re-export of glam, so downstream crates use the same version.
pub use glam;

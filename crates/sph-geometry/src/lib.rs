//! # sph-geometry
//!
//! Bodies and their particles: shapes, uniform lattices and the study's
//! variable-resolution Fibonacci placement (paper §4), all returning the same
//! [`BodyParticles`] (positions, masses, local spacings and the numbers that say how
//! well the particles fill the body). f64 throughout, SI units.
//!
//! ```
//! use sph_geometry::{FibonacciPlacement, Shape, Sphere};
//! use sph_core::glam::DVec3;
//!
//! // The study's projectile: an aluminium sphere of 6 mm diameter, 0.5 mm spacing,
//! // uniform layers (q = 1) about its centre.
//! let ball = Sphere::new(DVec3::ZERO, 3.0e-3)?;
//! let placement = FibonacciPlacement::new(ball.centre(), 0.5e-3, 1.0, 2785.0)?;
//! let particles = placement.place(&ball)?;
//! println!(
//!     "{} particles, mass {:.4e} kg (raw error {:+.2e})",
//!     particles.len(),
//!     particles.total_mass(),
//!     particles.raw_mass_error.unwrap()
//! );
//! assert_eq!(particles.len(), 896);
//! assert!((particles.total_mass() - 2785.0 * ball.volume().unwrap()).abs() < 1e-15);
//! // Support radii for n_target = 2.5 spacings (paper §2.4).
//! let h = particles.smoothing_lengths(2.5)?;
//! assert!((h[0] - 1.25e-3).abs() < 1e-15);
//! # Ok::<(), sph_geometry::GeometryError>(())
//! ```
//!
//! ## Modules
//!
//! * [`shape`] — the [`Shape`] trait, [`Aabb`], [`estimate_volume`].
//! * [`sphere`], [`cuboid`], [`cylinder`], [`half_space`] — primitive shapes.
//! * [`csg`] — [`Union`], [`Intersection`], [`Difference`] and the [`ShapeExt`]
//!   builders.
//! * [`lattice`] — cubic (1-, 2-, 3-D), hexagonal (2-D) and HCP (3-D) lattices.
//! * [`fibonacci`] — the variable-resolution placement ([`FibonacciPlacement`]).
//! * [`rz`] — placement in the meridional half-plane for axisymmetric (RZ) runs
//!   ([`rz_lattice`], [`RzLayeredPlacement`]; masses per radian).
//! * [`section`] — the plane (y = 0) and line (x = y = 0) sections of a 3-D shape, for
//!   plane-strain and uniaxial-strain runs ([`PlaneSection`], [`LineSection`]).
//! * [`mod@revolve`] — 3-D particles from an RZ placement, each ring as points evenly
//!   spaced around the axis ([`revolve()`]).
//! * [`placement`] — the common result [`BodyParticles`].
//! * [`quality`] — [`closest_approach`], the closest pair relative to the local spacing.
//! * [`error`] — [`GeometryError`].
//!
//! The layering and mass-assignment method and its measured accuracy are written up in
//! `docs/placement.md` of the workspace.
//!
//! ## Feature flags
//! None.

pub mod csg;
pub mod cuboid;
pub mod cylinder;
pub mod error;
pub mod fibonacci;
pub mod half_space;
pub mod lattice;
pub mod placement;
pub mod quality;
pub mod revolve;
pub mod rz;
pub mod section;
pub mod shape;
pub mod sphere;

pub use csg::{Difference, Intersection, ShapeExt, Union};
pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use error::{GeometryError, MAX_CANDIDATE_POINTS};
pub use fibonacci::{FibonacciPlacement, Shell, ShellReport, fibonacci_sphere, shells};
pub use half_space::HalfSpace;
pub use lattice::{cubic_lattice, hcp_lattice, hexagonal_lattice};
pub use placement::BodyParticles;
pub use quality::{CloseApproach, closest_approach};
pub use revolve::{revolve, ring_point_count};
pub use rz::{RzLayeredPlacement, rz_lattice, rz_layer_point_count};
pub use section::{LineSection, PlaneSection};
pub use shape::{Aabb, Shape, estimate_volume, unit_ball_volume};
pub use sphere::Sphere;

//! # sph-kernel
//!
//! Smoothing kernels for SPH behind the [`Kernel`] trait: Wendland C2 (the study's
//! choice), C4, C6 and the cubic B-spline, each with **compact support radius h** (the
//! kernel vanishes for r ≥ h; paper §2.4), normalised in 1-, 2- and 3-D, with gradients,
//! and evaluated either with a scalar h or with a symmetric smoothing tensor H (ASPH).
//!
//! ```
//! use sph_kernel::{Kernel, WendlandC2};
//! use sph_core::glam::{DMat3, DVec3};
//!
//! let k = WendlandC2;
//! let h = 2.5e-3; // support radius: 2.5 particle spacings of 1 mm
//! let r = DVec3::new(1.0e-3, 0.0, 0.0);
//! let w = k.w(r, h);
//! // The ASPH form with H = I/h is the same kernel.
//! let w_tensor = k.w_tensor(r, &(DMat3::IDENTITY * (1.0 / h)));
//! assert!((w - w_tensor).abs() <= 1e-12 * w);
//! // The gradient points along r and is negative (W falls with distance).
//! assert!(k.grad_w(r, h).x < 0.0);
//! ```
//!
//! Choosing a kernel at run time from a configuration string:
//!
//! ```
//! use sph_kernel::{Kernel, KernelChoice};
//! let k: KernelChoice = "wendland-c4".parse().unwrap();
//! assert_eq!(k.name(), "wendland-c4");
//! assert!("gaussian".parse::<KernelChoice>().is_err());
//! ```
//!
//! ## Feature flags
//! None.

mod choice;
mod cubic_spline;
mod kernel;
mod wendland;

pub use choice::KernelChoice;
pub use cubic_spline::CubicSpline;
pub use kernel::Kernel;
pub use wendland::{WendlandC2, WendlandC4, WendlandC6};

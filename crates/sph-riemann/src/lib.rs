//! # sph-riemann
//!
//! The pair terms of Riemann-SPH (paper §2): each pair (i, j) solves a 1-D Riemann
//! problem along its axis r̂ = (x_i − x_j)/|x_i − x_j| (j left, i right), and the
//! interface velocity v* replaces v_j in the continuity and energy equations.
//!
//! * [`wave_speeds`]: Davis, Einfeldt and pressure-based estimates.
//! * [`acoustic_star`], [`hllc_star`], [`RiemannSolver`]: star states (u*, P*).
//! * [`Limiter`], [`reconstruct`]: limited linear reconstruction along the pair axis.
//! * [`interface_velocity`]: v* with the damage/material coupling b_ij.
//! * [`MonaghanViscosity`], [`ArtificialStress`]: the dissipation and tensile-instability
//!   terms; [`balsara_factor`]: the switch that limits the viscosity to compressions.
//!
//! ```
//! use sph_riemann::{SideState, acoustic_star};
//! // Two identical solids colliding at ±100 m/s: the interface is at rest and the
//! // pressure is the impedance times the impact speed, P* = Z·100 m/s.
//! let z_side = |u| SideState { density: 2700.0, velocity: u, pressure: 0.0, sound_speed: 5000.0 };
//! let star = acoustic_star(&z_side(100.0), &z_side(-100.0));
//! assert_eq!(star.velocity, 0.0);
//! assert!((star.pressure - 2700.0 * 5000.0 * 100.0).abs() < 1e-3);
//! ```
//!
//! ## Feature flags
//! None.

mod artificial_stress;
mod balsara;
mod hllc;
mod interface;
mod limited_viscosity;
mod limiter;
mod state;
mod viscosity;
mod wave_speed;

pub use artificial_stress::{ArtificialStress, ArtificialStressForm};
pub use balsara::{BALSARA_EPSILON, ViscositySwitch, balsara_factor};
pub use hllc::{RiemannSolver, acoustic_star, hllc_star, hllc_star_with_speeds};
pub use interface::{InterfaceCoupling, PairInterface, coupling_weight, interface_velocity};
pub use limited_viscosity::{limited_relative_velocity, limiter_phi, van_leer_ratio};
pub use limiter::{Limiter, reconstruct, spheral_reconstruct};
pub use state::{SideState, StarState};
pub use viscosity::{MonaghanViscosity, ViscositySoundSpeed};
pub use wave_speed::{WaveSpeedEstimate, wave_speeds};

//! # sph-diagnostics
//!
//! What a run is judged by: exact solutions for verification problems, error norms,
//! conservation sums, impact diagnostics (ejecta, β, crater, damage, melt, fragments) and
//! particle output for ParaView (VTU, the parallel PVTU that joins pieces of it, and PVD).
//! Definitions: docs/diagnostics.md.
//!
//! ```
//! use sph_diagnostics::exact::{GasState, RiemannSolution};
//! // Sod's shock tube (Toro ch. 4, test 1).
//! let sod = RiemannSolution::solve(
//!     GasState { density: 1.0, velocity: 0.0, pressure: 1.0 },
//!     GasState { density: 0.125, velocity: 0.0, pressure: 0.1 },
//!     1.4,
//! ).unwrap();
//! assert!((sod.p_star - 0.30313).abs() < 1e-5);
//! assert!((sod.u_star - 0.92745).abs() < 1e-5);
//! ```
//!
//! Impact diagnostics work on a borrowed [`ParticleView`] (3-D or RZ, same code):
//!
//! ```
//! use sph_diagnostics::{EjectaCriterion, ParticleView, beta_from_ejecta, ejecta};
//! // A 1 kg projectile hit at 10 m/s; one 0.5 kg target particle (body 1) flies off at
//! // 4 m/s above the surface z = 0, one is pushed down.
//! let x = [[0.0, 0.0, 0.01], [0.0, 0.0, -0.01]];
//! let v = [[0.0, 0.0, 4.0], [0.0, 0.0, -12.0]];
//! let view = ParticleView::new(&x, &v, &[0.5, 1.0], &[1, 1]);
//! let e = ejecta(&view, &EjectaCriterion::new(&[1], 0.0))?;
//! assert_eq!(beta_from_ejecta(e.momentum_z, 1.0, 10.0)?, 1.2);
//! # Ok::<(), sph_diagnostics::ImpactError>(())
//! ```
//!
//! ## Feature flags
//! None.

pub mod axis_depth;
pub mod beta;
pub mod crater;
pub mod crater_options;
pub mod crater_profile;
pub mod damage_stats;
pub mod detached;
pub mod disc_kernel;
pub mod ejecta;
pub mod ejecta_distribution;
pub mod error;
pub mod exact;
pub mod fof;
pub mod mass_histogram;
pub mod melt;
pub mod norms;
pub mod particles_view;
pub mod plot;
pub mod pvd;
pub mod pvtu;
pub mod vtu;
pub mod xml;

pub use axis_depth::{AxisDepth, AxisField};
pub use beta::{
    ProjectileDebris, TargetBeta, beta_from_ejecta, beta_from_target, impactor_momentum,
};
pub use crater::{Crater, crater, crater_against, measure_crater};
pub use crater_options::{CraterOptions, DensityCut};
pub use crater_profile::{CraterProfile, crater_profile};
pub use damage_stats::{BodyDamage, FULLY_DAMAGED, damage_stats};
pub use detached::detached_ejecta;
pub use disc_kernel::DiscKernel;
pub use ejecta::{Ejecta, EjectaCriterion, ejecta};
pub use ejecta_distribution::{
    EjectaBin, EjectaCumulative, ejecta_cumulative, ejecta_distribution,
};
pub use error::{ExactError, ImpactError};
pub use fof::{Clusters, friends_of_friends};
pub use mass_histogram::{MassHistogram, uniform_edges};
pub use melt::{
    PhaseFractions, PhaseThresholds, energy_histogram, mass_fractions_above, phase_fractions,
};
pub use norms::{ErrorNorms, convergence_order, error_norms, log_log_slope};
pub use particles_view::{Geometry, ParticleView};
pub use plot::{Figure, PlotError};
pub use pvd::Pvd;
pub use vtu::VtuWriter;

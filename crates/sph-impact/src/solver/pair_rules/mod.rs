//! The pair rules of pass 2 (`derivatives::rates`), one file each: what a pair (i, j)
//! adds to the Riemann-SPH pair force beyond the pressure and the interface velocity
//! (paper §2). Each is a function of the pair's two sides, called from the one pair
//! loop when its scheme key is on; each is symmetric in (i, j) where it touches the
//! pair force, so momentum stays exact, and its reference is in its file.
//!
//! | rule | scheme key | file |
//! |---|---|---|
//! | decoupling of fractured material | `decouple_damaged` | `decoupling.rs` |
//! | FSISPH's density stabilisation of v* | `density_stabilization` | `density_stabilization.rs` |
//! | Monaghan–Gingold viscosity Π_ij (limited, switched) | `viscosity` | `viscosity.rs` |
//! | artificial stress | `artificial_stress` | `artificial_stress.rs` |
//! | damage coupling of the deviatoric stresses | `stress_coupling` | `stress_coupling.rs` |
//! | FSISPH's energy diffusion | `energy_diffusion` | `energy_diffusion.rs` |
//! | the user's own pair force | `Simulation::with_pair_rule` | `user.rs` |

mod artificial_stress;
mod decoupling;
mod density_stabilization;
mod energy_diffusion;
mod stress_coupling;
mod user;
mod viscosity;

pub(crate) use artificial_stress::artificial_stress;
pub(crate) use decoupling::decoupled;
pub(crate) use density_stabilization::{Side, density_stabilization};
pub(crate) use energy_diffusion::{DiffusionPair, energy_diffusion};
pub(crate) use stress_coupling::coupled_stresses;
pub use user::{NoPairRule, PairRule, PairView};
pub(crate) use viscosity::{ViscosityPair, viscous_pressure};

use crate::solver::state::Extended;
use sph_core::Dimension;

/// The pair's mean sound speed for the viscosity and FSISPH's smoothing terms: the
/// bulk sound speeds where the extended state carries them
/// (`ViscositySoundSpeed::Bulk`), else the signal speeds `ci`, `cj` (c_L for solids).
#[inline(always)]
pub(crate) fn pair_bulk_speed<D: Dimension>(
    ext: &Extended<'_, D>,
    i: usize,
    j: usize,
    ci: f64,
    cj: f64,
) -> f64 {
    if ext.bulk_sound_speed.is_empty() {
        0.5 * (ci + cj)
    } else {
        0.5 * (ext.bulk_sound_speed[i] + ext.bulk_sound_speed[j])
    }
}

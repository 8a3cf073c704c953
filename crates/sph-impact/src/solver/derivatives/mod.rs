//! The gather loops: per real particle, sums over its CSR neighbours (paper §2).
//!
//! Pass 1 (`gradients`): velocity gradient L_i = Σ_j V_j (v_j − v_i) ⊗ ∇_i W̄_ij and
//! pressure gradient, for reconstruction and the ASPH update.
//!
//! Pass 2 (`rates`), for each pair with r = x_i − x_j, r̂ = r/|r|, j left and i right:
//!
//! * v* from the pair's Riemann problem (paper §2.1) on limited reconstructed states,
//! * dρ_i/dt = 2 ρ_i Σ_j (m_j/ρ_j)(v_i − v*)·∇_i W̄_ij,
//! * dv_i/dt = Σ_j m_j F_ij ∇_i W̄_ij with the pair coefficient
//!   F_ij = −(P_i + P_j)/(ρ_iρ_j) − Π_ij − A_ij (pressure, Monaghan viscosity, artificial
//!   stress), symmetric in i, j, so the pair forces cancel exactly,
//! * de_i/dt by the chosen [`EnergyForm`].
//!
//! Both passes evaluate a pair of two particles of one block of rows once, for both
//! (pair_blocks.rs); the blocks are fixed by the particle count and each particle's sums
//! are added in an order fixed by the sorted rows, so results are identical for any
//! number of threads.
//!
//! Files: `summation.rs` (summation density), `gradients.rs` (pass 1), `switch.rs` (the
//! viscosity switch's factors from pass 1), `rates.rs` (pass 2, which calls the pair rules
//! of `solver/pair_rules/`), `pair_scheme.rs` (the scheme's choices pass 2 makes per pair,
//! constants of its loop for the study's scheme).

use crate::solver::config::{DensityForm, EnergyForm, MomentumForm, SchemeConfig};
use crate::solver::pair_blocks;
use crate::solver::pair_kernel::PairKernel;
use crate::solver::pair_rules::{self, DiffusionPair, Side, ViscosityPair, decoupled};
use crate::solver::ranks::{Flat, get_tensor, get_vector, put_tensor, put_vector};
use crate::solver::state::Extended;
use rayon::prelude::*;
use sph_core::{Dimension, Pairs, Tensor, Vector};
use sph_riemann::{PairInterface, SideState, interface_velocity, reconstruct};
use std::ops::Range;

/// Whether the extended state is an RZ one (it carries each particle's radius). The gather
/// loops are dispatched on it once per call, so that each geometry runs its own
/// monomorphised loop: in a Cartesian instantiation the RZ weights are the constant 1 and
/// the hoop terms are compiled out, in an RZ one nothing is tested per pair.
fn is_rz<D: Dimension>(ext: &Extended<'_, D>) -> bool {
    !ext.radius.is_empty()
}

/// Calls `f::<D, P, RZ>(ext, args…)` with `RZ` the geometry of `ext` ([`is_rz`]).
macro_rules! per_geometry {
    ($f:ident($ext:expr $(, $arg:expr)*)) => {
        if is_rz($ext) {
            $f::<D, P, true>($ext $(, $arg)*)
        } else {
            $f::<D, P, false>($ext $(, $arg)*)
        }
    };
}

/// Calls `f::<D, P, RZ, STUDY>(ext, args…)` with `RZ` the geometry of `ext` ([`is_rz`])
/// and `STUDY` the flag `$study`: the pair passes' loop for the study's choices as
/// constants (pair_scheme.rs) or the one that reads them.
macro_rules! per_case {
    ($f:ident($ext:expr $(, $arg:expr)*), $study:expr) => {
        match (is_rz($ext), $study) {
            (true, true) => $f::<D, P, true, true>($ext $(, $arg)*),
            (true, false) => $f::<D, P, true, false>($ext $(, $arg)*),
            (false, true) => $f::<D, P, false, true>($ext $(, $arg)*),
            (false, false) => $f::<D, P, false, false>($ext $(, $arg)*),
        }
    };
}

/// Each particle's volume m/η, real and ghost (η = ρ R̂ in RZ, ρ otherwise): the weight of
/// its terms in its partners' sums, computed once per particle rather than by a division
/// per pair side (the same division, so the same bits as a pair's own).
fn volumes<D: Dimension, const RZ: bool>(ext: &Extended<'_, D>) -> Vec<f64> {
    (0..ext.position.len())
        .into_par_iter()
        .with_min_len(1024)
        .map(|k| {
            let eta = if RZ {
                ext.density[k] * ext.smoothed_radius[k]
            } else {
                ext.density[k]
            };
            ext.mass[k] / eta
        })
        .collect()
}

/// The columns a pair pass reads of a pair's partner j, each cut to the extended state's
/// length m, so that one bounds test of j serves them all where the compiler would
/// otherwise test j against each array's own length ([`Partner::cut`], once per block
/// of rows, inlined into the pass). The columns not asked for are empty and never read.
pub(super) struct Partner<'e, D: Dimension> {
    /// x, v, ρ, P and c.
    pub position: &'e [D::Vector],
    pub velocity: &'e [D::Vector],
    pub density: &'e [f64],
    pub pressure: &'e [f64],
    pub sound_speed: &'e [f64],
    /// m, the material's index and, for a ghost, its source.
    pub mass: &'e [f64],
    pub material: &'e [u16],
    pub source: &'e [u32],
    /// D, where [`Columns::damage`].
    pub damage: &'e [f64],
    /// r and R̂, where [`Columns::rz`].
    pub radius: &'e [f64],
    pub smoothed_radius: &'e [f64],
    /// R_θθ of the artificial stress, where [`Columns::astress_hoop`].
    pub astress_hoop: &'e [f64],
    /// e, where [`Columns::energy`].
    pub specific_energy: &'e [f64],
    /// Each particle's volume m/η ([`volumes`]), where given.
    pub volume: &'e [f64],
}

/// Which of the optional columns [`Partner::cut`] keeps.
pub(super) struct Columns {
    pub damage: bool,
    pub rz: bool,
    pub astress_hoop: bool,
    pub energy: bool,
}

impl<'e, D: Dimension> Partner<'e, D> {
    /// The columns of `ext`, and `volume` unless it is empty, cut to the length of `ext`.
    #[inline(always)]
    pub fn cut(ext: &'e Extended<'_, D>, volume: &'e [f64], keep: Columns) -> Self {
        let m = ext.position.len();
        let opt = |on: bool, v: &'e [f64]| if on { &v[..m] } else { &v[..0] };
        Partner {
            position: &ext.position[..m],
            velocity: &ext.velocity[..m],
            density: &ext.density[..m],
            pressure: &ext.pressure[..m],
            sound_speed: &ext.sound_speed[..m],
            mass: &ext.mass[..m],
            material: &ext.material[..m],
            source: &ext.source[..m],
            damage: opt(keep.damage, &ext.damage),
            radius: opt(keep.rz, &ext.radius),
            smoothed_radius: opt(keep.rz, &ext.smoothed_radius),
            astress_hoop: opt(keep.astress_hoop, &ext.astress_hoop),
            specific_energy: opt(keep.energy, &ext.specific_energy),
            volume: opt(!volume.is_empty(), volume),
        }
    }
}

mod gradients;
mod pair_scheme;
mod rates;
mod summation;
mod switch;

pub(crate) use gradients::{GradientOptions, GradientSet, gradients};
pub(crate) use pair_scheme::PairScheme;
pub(crate) use rates::{PairRates, Rates, rates};
pub(crate) use summation::summation_density;

//! The Riemann-SPH solver (paper §2): state, derivatives, time integration.

pub mod axisymmetric;
pub mod boundary;
mod chunks;
pub mod config;
mod damage;
mod derivatives;
pub mod error;
mod free_flight;
pub mod material;
mod pair_blocks;
mod pair_kernel;
mod pair_rules;
pub mod ranks;
pub mod simulation;
pub mod state;
pub mod timestep;
mod warm_threads;

pub use axisymmetric::Geometry;
pub use boundary::Boundary;
pub use config::{
    CrackLength, DensityForm, EnergyForm, MomentumForm, NeighbourSearch, SchemeConfig,
    SmoothingMode, YieldPressure,
};
pub use damage::DamageEvents;
pub use error::SolverError;
pub use material::Material;
pub use pair_blocks::{PairEvaluations, pair_evaluations};
pub use pair_rules::{NoPairRule, PairRule, PairView};
pub use ranks::{Gathered, LocalState, OneRank, Ranks, exchange_halo, shares};
pub use simulation::{Conserved, PhaseTimes, Simulation, SolverCheckpoint, StepInfo};
pub use state::State;
pub use timestep::TimestepVote;

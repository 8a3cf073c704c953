//! Solver errors: each names what is wrong and where.

use thiserror::Error;

/// Errors of the solver.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SolverError {
    /// A checkpoint does not fit the simulation it is restored into
    /// ([`crate::Simulation::restore`]).
    #[error("the checkpoint does not fit this set-up: {0}")]
    BadCheckpoint(String),
    /// The ranks' exchange of particles failed (solver/ranks/local.rs): what went wrong.
    #[error("rank exchange: {0}")]
    Exchange(String),
    /// A scheme setting out of range.
    #[error("scheme setting {field} = {}: {reason}", crate::scene::shown_value(*value))]
    BadConfig {
        /// Field name.
        field: &'static str,
        /// Value.
        value: f64,
        /// Why.
        reason: &'static str,
    },
    /// The initial state is invalid.
    #[error("initial state: {0}")]
    BadState(#[from] sph_core::CoreError),
    /// A particle refers to a material that does not exist.
    #[error("particle {index}: material id {material} but only {count} materials are defined")]
    UnknownMaterial {
        /// Particle index.
        index: usize,
        /// Its material id.
        material: u16,
        /// Number of materials.
        count: usize,
    },
    /// The state became unphysical during the run.
    #[error("step {step}, t = {time:e} s: particle id {id} at {position:?}: {what} = {value:e}")]
    Unphysical {
        /// Step number.
        step: u64,
        /// Simulated time.
        time: f64,
        /// Stable particle id.
        id: u64,
        /// Position.
        position: [f64; 3],
        /// Which quantity.
        what: &'static str,
        /// Its value.
        value: f64,
    },
    /// The time step collapsed.
    #[error(
        "step {step}: time step {dt:e} s below the minimum {min:e} s (bound by particle id {id}: {reason}; at {position:?} m, density {density:e} kg/m^3, specific energy {specific_energy:e} J/kg, speed {speed:e} m/s, h {smoothing_length:e} m)"
    )]
    TimestepCollapse {
        /// Step number.
        step: u64,
        /// The step.
        dt: f64,
        /// The minimum allowed.
        min: f64,
        /// Particle that bound it.
        id: u64,
        /// Why.
        reason: &'static str,
        /// That particle's position (m; the unused components 0).
        position: [f64; 3],
        /// Its density (kg/m³).
        density: f64,
        /// Its specific internal energy (J/kg).
        specific_energy: f64,
        /// Its speed (m/s).
        speed: f64,
        /// Its smoothing length (m).
        smoothing_length: f64,
    },
    /// A boundary condition is invalid.
    #[error("boundary {index}: {reason}")]
    BadBoundary {
        /// Position in the boundary list.
        index: usize,
        /// What is wrong.
        reason: String,
    },
    /// A material model could not be built.
    #[error("material: {0}")]
    Material(String),
    /// A verification problem was asked for in a form (geometry or placement) it does
    /// not have.
    #[error("verify {problem}: {reason}")]
    NoSuchForm {
        /// The problem's name.
        problem: &'static str,
        /// Which forms exist.
        reason: &'static str,
    },
    /// A verification problem's resolution would need more memory than a run may take
    /// ([`crate::verify::VERIFY_MEMORY_LIMIT`]); refused before anything is allocated.
    #[error(
        "verify {problem}: resolution {resolution} needs about {particles:.2e} particles, \
         {bytes:.2e} bytes at {bytes_per_particle} bytes each, above the limit of {limit:.2e} \
         bytes; the largest resolution accepted is {largest}"
    )]
    TooLarge {
        /// The problem's name.
        problem: &'static str,
        /// The resolution asked for.
        resolution: usize,
        /// The particles it would place (an estimate from above).
        particles: f64,
        /// The memory they would need (bytes).
        bytes: f64,
        /// Bytes assumed per particle ([`crate::scene::ASSUMED_BYTES_PER_PARTICLE`]).
        bytes_per_particle: f64,
        /// The limit (bytes).
        limit: f64,
        /// The largest resolution within the limit.
        largest: usize,
    },
}

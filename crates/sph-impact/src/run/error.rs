//! Run errors: bad input (the scene, the options) against a failed run (the solver
//! stopped, an output could not be written). The command line maps the first to exit
//! code 2 and the second to 1.

use crate::scene::SceneError;
use thiserror::Error;

/// Why a run did not finish.
#[derive(Debug, Error)]
pub enum RunError {
    /// The scene is invalid (bad input). Boxed to keep `Result`s small.
    #[error("{0}")]
    Scene(Box<SceneError>),
    /// A run option is out of range (bad input).
    #[error("option `{option}` = {value}: {reason}")]
    Option {
        /// The option's name.
        option: &'static str,
        /// The value given.
        value: f64,
        /// What is allowed.
        reason: &'static str,
    },
    /// Options that exclude each other (bad input).
    #[error("{0}")]
    Conflict(String),
    /// A run cannot resume from its directory's checkpoint (bad input: a missing or
    /// foreign checkpoint, another scene or resolution, a history that does not match).
    #[error("cannot resume from {path}: {reason}")]
    Resume {
        /// The file.
        path: String,
        /// What is wrong.
        reason: String,
    },
    /// The run directory holds a previous run's files, and the run neither resumes it nor
    /// was told to overwrite it (bad input).
    #[error(
        "the run directory {path} holds a previous run ({files}): pass --resume to continue \
         it, --overwrite to clear it first, or choose another --out"
    )]
    DirectoryInUse {
        /// The directory.
        path: String,
        /// Some of the files found.
        files: String,
    },
    /// The run was asked to stop (SIGINT, SIGTERM, or `RunOptions::stop`): it finished
    /// the step under way and wrote a checkpoint and a partial `summary.json`.
    #[error(
        "interrupted at t = {time:e} s (step {step}); checkpoint {checkpoint}: continue with \
         --resume"
    )]
    Interrupted {
        /// Simulated time reached (s).
        time: f64,
        /// Steps completed.
        step: u64,
        /// The checkpoint written.
        checkpoint: String,
    },
    /// The solver stopped (the state became unphysical, the step collapsed).
    #[error("run failed at t = {time:e} s (step {step}): {message}")]
    Solver {
        /// Simulated time reached (s).
        time: f64,
        /// Steps completed.
        step: u64,
        /// The solver's message.
        message: String,
    },
    /// A diagnostic could not be computed.
    #[error("diagnostics: {0}")]
    Diagnostics(String),
    /// A figure could not be drawn from the run's numbers (the run reports it as a
    /// warning and goes on).
    #[error("cannot draw {path}: {message}")]
    Plot {
        /// The figure's file.
        path: String,
        /// What the plotting found.
        message: String,
    },
    /// An output file could not be written.
    #[error("cannot write {path}: {message}")]
    Io {
        /// The file.
        path: String,
        /// The operating system's or encoder's message.
        message: String,
    },
}

impl RunError {
    /// True for errors in the input (scene, options) rather than in the run.
    pub fn is_bad_input(&self) -> bool {
        matches!(
            self,
            RunError::Scene(_)
                | RunError::Option { .. }
                | RunError::Resume { .. }
                | RunError::DirectoryInUse { .. }
                | RunError::Conflict(_)
        )
    }

    /// True for a run stopped on request ([`RunError::Interrupted`]).
    pub fn is_interrupted(&self) -> bool {
        matches!(self, RunError::Interrupted { .. })
    }

    /// An I/O error on `path`.
    pub(crate) fn io(path: &std::path::Path, e: impl std::fmt::Display) -> Self {
        RunError::Io {
            path: path.display().to_string(),
            message: e.to_string(),
        }
    }
}

impl From<SceneError> for RunError {
    fn from(e: SceneError) -> Self {
        RunError::Scene(Box::new(e))
    }
}

impl From<sph_diagnostics::ImpactError> for RunError {
    fn from(e: sph_diagnostics::ImpactError) -> Self {
        RunError::Diagnostics(e.to_string())
    }
}

//! Stopping a run cleanly: a [`StopFlag`] that the run checks after every step. Once it
//! is raised the run finishes the step under way, writes a checkpoint, flushes
//! `history.csv`, writes a partial `summary.json` (`"complete": false`) and returns
//! [`RunError::Interrupted`](crate::run::RunError::Interrupted), which the command line
//! turns into exit code 130. The command line raises it on SIGINT and SIGTERM; a
//! program embedding the library raises it itself.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A request to stop a run after its current step; clones share the request.
#[derive(Clone, Debug, Default)]
pub struct StopFlag(Arc<AtomicBool>);

impl StopFlag {
    /// A flag not yet raised.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks the run to stop after its current step.
    pub fn request(&self) {
        self.0.store(true, Ordering::SeqCst);
    }

    /// True once a stop was requested.
    pub fn requested(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }

    /// Raises this flag on SIGINT and SIGTERM (Unix). A second signal while the flag is
    /// up ends the process at once with exit code 130, for a user who cannot wait for
    /// the step to finish.
    pub fn on_signals(&self) -> std::io::Result<()> {
        for signal in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
            // Registered first, so it sees the flag as it was before this signal.
            signal_hook::flag::register_conditional_shutdown(signal, 130, Arc::clone(&self.0))?;
            signal_hook::flag::register(signal, Arc::clone(&self.0))?;
        }
        Ok(())
    }
}

/// Two flags are equal when they are the same request.
impl PartialEq for StopFlag {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

#[cfg(test)]
mod tests {
    use super::StopFlag;

    #[test]
    fn clones_share_the_request() {
        let a = StopFlag::new();
        let b = a.clone();
        assert!(!b.requested());
        a.request();
        assert!(b.requested());
        assert_eq!(a, b);
        assert_ne!(a, StopFlag::new());
    }
}

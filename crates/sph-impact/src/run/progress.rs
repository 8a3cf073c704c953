//! The progress line of a run on standard error: simulated time, steps,
//! particle-steps per second and the estimated time left. On a terminal it is redrawn
//! in place at most twice a second; otherwise (a log file) a line is written every 30 s.

use crate::scene::estimate_human_seconds;
use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

/// The bar of a share `done` in [0, 1]: `[######------------------]`, 24 wide.
pub(crate) fn bar(done: f64) -> String {
    let width = 24;
    let filled = ((done.clamp(0.0, 1.0) * width as f64).round() as usize).min(width);
    format!("[{}{}]", "#".repeat(filled), "-".repeat(width - filled))
}

/// Prints progress unless quiet.
pub(crate) struct Progress {
    quiet: bool,
    terminal: bool,
    start: Instant,
    last: Option<Instant>,
    end_time: f64,
    particles: usize,
    /// Simulated time and steps when this process started (not 0 for a resumed run):
    /// the rate and the time left count only this process' work.
    t0: f64,
    steps0: u64,
}

impl Progress {
    pub fn new(quiet: bool, end_time: f64, particles: usize) -> Self {
        Self {
            quiet,
            terminal: std::io::stderr().is_terminal(),
            start: Instant::now(),
            last: None,
            end_time,
            particles,
            t0: 0.0,
            steps0: 0,
        }
    }

    /// The same, for a run resumed at simulated time `t0` after `steps0` steps.
    pub fn starting_at(self, t0: f64, steps0: u64) -> Self {
        Self { t0, steps0, ..self }
    }

    /// Reports the state after `steps` steps at simulated time `t` (s).
    pub fn update(&mut self, t: f64, steps: u64, force: bool) {
        if self.quiet {
            return;
        }
        let every = if self.terminal {
            Duration::from_millis(500)
        } else {
            Duration::from_secs(30)
        };
        let now = Instant::now();
        if !force && self.last.is_some_and(|l| now - l < every) {
            return;
        }
        self.last = Some(now);
        let wall = (now - self.start).as_secs_f64().max(1e-9);
        let rate = steps.saturating_sub(self.steps0) as f64 * self.particles as f64 / wall;
        let done = (t / self.end_time).clamp(0.0, 1.0);
        // The fraction of this process' stretch, [t0, end], done so far.
        let here = ((t - self.t0) / (self.end_time - self.t0)).clamp(0.0, 1.0);
        let eta = if here > 0.0 {
            estimate_human_seconds(wall * (1.0 - here) / here)
        } else {
            "?".into()
        };
        let line = format!(
            "{} t = {:.3e}/{:.3e} s ({:5.1} %) | step {} | {:.2e} particle-steps/s | ETA {}",
            bar(done),
            t,
            self.end_time,
            100.0 * done,
            steps,
            rate,
            eta
        );
        let mut err = std::io::stderr().lock();
        if self.terminal {
            let _ = write!(err, "\r{line}\x1b[K");
        } else {
            let _ = writeln!(err, "{line}");
        }
        let _ = err.flush();
    }

    /// Ends the line.
    pub fn finish(&mut self, t: f64, steps: u64) {
        self.update(t, steps, true);
        if !self.quiet && self.terminal {
            eprintln!();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::bar;

    #[test]
    fn the_bar_fills_with_the_share_done_and_stays_24_wide() {
        assert_eq!(bar(0.0), format!("[{}]", "-".repeat(24)));
        assert_eq!(bar(0.5), format!("[{}{}]", "#".repeat(12), "-".repeat(12)));
        assert_eq!(bar(1.0), format!("[{}]", "#".repeat(24)));
        // Outside [0, 1] (a resumed run's rounding): clamped to the ends, never wider.
        assert_eq!(bar(1.2), bar(1.0));
        assert_eq!(bar(-0.1), bar(0.0));
    }
}

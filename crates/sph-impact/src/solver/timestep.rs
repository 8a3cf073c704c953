//! Time-step votes: each limit names the particle that set it and why (Spheral's
//! physics packages each return a vote with a reason; so does each limit here).

use serde::Serialize;

/// Why the CFL vote set a step.
pub const REASON_CFL: &str = "CFL: sound + approach speed";
/// Why the density vote set a step.
pub const REASON_DENSITY: &str = "density change";
/// Why the acceleration vote set a step.
pub const REASON_ACCELERATION: &str = "acceleration";
/// The reason of a vote no particle cast (no particles).
pub const REASON_NONE: &str = "none";

/// Every reason a vote can give, so a reason read back as text (a `history.csv` row of
/// a resumed run) finds its `&'static str` again ([`reason_named`]).
pub const REASONS: [&str; 4] = [REASON_CFL, REASON_DENSITY, REASON_ACCELERATION, REASON_NONE];

/// The reason spelled `text`, if it is one of [`REASONS`].
pub fn reason_named(text: &str) -> Option<&'static str> {
    REASONS.iter().copied().find(|r| *r == text)
}

/// One candidate time step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TimestepVote {
    /// The step (s).
    pub dt: f64,
    /// Stable id of the particle that set it.
    pub particle_id: u64,
    /// Why.
    pub reason: &'static str,
}

impl TimestepVote {
    /// The smaller of two votes (ties keep `self`, so the choice is deterministic).
    pub fn min(self, other: TimestepVote) -> TimestepVote {
        if other.dt < self.dt { other } else { self }
    }
}

/// The CFL vote of a particle: λ Δx / (c + w), Δx = h/n_target its spacing, w its
/// largest approach speed (paper §2.5).
pub fn cfl_vote(
    cfl: f64,
    spacing: f64,
    sound_speed: f64,
    approach: f64,
    particle_id: u64,
) -> TimestepVote {
    TimestepVote {
        dt: cfl * spacing / (sound_speed + approach).max(f64::MIN_POSITIVE),
        particle_id,
        reason: REASON_CFL,
    }
}

/// The density vote: λ ρ/|dρ/dt|, so no step changes a density by more than the
/// fraction λ (a strong expansion would otherwise drive ρ negative).
pub fn density_vote(cfl: f64, density: f64, rate: f64, particle_id: u64) -> TimestepVote {
    let dt = if rate != 0.0 {
        cfl * density / rate.abs()
    } else {
        f64::INFINITY
    };
    TimestepVote {
        dt,
        particle_id,
        reason: REASON_DENSITY,
    }
}

/// The acceleration vote: λ sqrt(Δx/|a|).
pub fn acceleration_vote(
    cfl: f64,
    spacing: f64,
    acceleration: f64,
    particle_id: u64,
) -> TimestepVote {
    let dt = if acceleration > 0.0 {
        cfl * (spacing / acceleration).sqrt()
    } else {
        f64::INFINITY
    };
    TimestepVote {
        dt,
        particle_id,
        reason: REASON_ACCELERATION,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use rayon::prelude::*;

    proptest! {
        /// The stage's vote is reduced in parallel (`Simulation::vote`): with `min`
        /// keeping the earlier vote on a tie, any grouping of the particles gives the
        /// serial loop's vote, its particle and reason included. The steps are drawn from
        /// a few values so that ties are common; some are infinite (no vote cast).
        #[test]
        fn the_parallel_vote_is_the_serial_one(
            steps in proptest::collection::vec((0_usize..6, 0_usize..3), 0..400),
            threads in 1_usize..5,
        ) {
            let values = [1e-9, 2e-9, 2e-9, 5e-8, f64::INFINITY, 1e-9];
            let reasons = [REASON_CFL, REASON_DENSITY, REASON_ACCELERATION];
            let votes: Vec<TimestepVote> = steps
                .iter()
                .enumerate()
                .map(|(id, &(v, r))| TimestepVote {
                    dt: values[v],
                    particle_id: id as u64,
                    reason: reasons[r],
                })
                .collect();
            let none = TimestepVote { dt: f64::INFINITY, particle_id: 0, reason: REASON_NONE };
            let serial = votes.iter().fold(none, |best, &v| best.min(v));
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            let parallel = pool.install(|| {
                votes
                    .par_iter()
                    .with_max_len(7)
                    .map(|&v| none.min(v))
                    .reduce(|| none, TimestepVote::min)
            });
            prop_assert_eq!(parallel, serial);
        }
    }
}

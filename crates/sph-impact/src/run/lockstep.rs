//! A run over several ranks (solver/ranks.rs; docs/mpi.md): rank 0 runs the scene as a
//! single process does, writing the run directory; every other rank builds the same
//! simulation and steps it in lockstep, told by rank 0 how far each step may go. A
//! resumed run's state is rank 0's, read from its checkpoint and sent to the others.

use crate::run::error::RunError;
use crate::scene::{SceneDimension, SimOf};
use crate::solver::{Ranks, SolverCheckpoint};

/// What rank 0 tells the others before each step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Command {
    /// Take a step of at most this long (s).
    Step(f64),
    /// The run has ended (at its end time, or stopped at a checkpoint).
    Done,
}

impl Command {
    fn bytes(self) -> Vec<u8> {
        match self {
            Command::Step(dt) => dt.to_le_bytes().to_vec(),
            Command::Done => Vec::new(),
        }
    }

    fn from_bytes(b: &[u8]) -> Result<Self, RunError> {
        match b.len() {
            0 => Ok(Command::Done),
            8 => Ok(Command::Step(f64::from_le_bytes(
                b.try_into().expect("8 bytes"),
            ))),
            n => Err(RunError::Diagnostics(format!(
                "rank 0 sent a command of {n} bytes"
            ))),
        }
    }
}

/// Rank 0: tells the other ranks `command` (nothing on one rank).
pub(crate) fn tell(ranks: &dyn Ranks, command: Command) {
    if ranks.size() > 1 {
        ranks.broadcast(command.bytes());
    }
}

/// Rank 0: sends the simulation's state (resumed from a checkpoint) to the other ranks
/// (nothing on one rank).
pub(crate) fn send_state<D: SceneDimension>(
    ranks: &dyn Ranks,
    sim: &SimOf<D>,
) -> Result<(), RunError> {
    if ranks.size() > 1 {
        let mut bytes = Vec::new();
        ciborium::into_writer(&sim.checkpoint(), &mut bytes)
            .map_err(|e| RunError::Diagnostics(format!("cannot encode the state: {e}")))?;
        ranks.broadcast(bytes);
    }
    Ok(())
}

/// Another rank: steps `sim` as rank 0 tells it until the run ends, taking rank 0's
/// state first when the run resumes.
pub(crate) fn follow<D: SceneDimension>(
    ranks: &dyn Ranks,
    mut sim: SimOf<D>,
    resume: bool,
) -> Result<(), RunError> {
    if resume {
        let bytes = ranks.broadcast(Vec::new());
        let state: SolverCheckpoint<D::Dim> = ciborium::from_reader(bytes.as_slice())
            .map_err(|e| RunError::Diagnostics(format!("cannot decode rank 0's state: {e}")))?;
        sim.restore(state).map_err(|e| RunError::Resume {
            path: "rank 0's state".into(),
            reason: e.to_string(),
        })?;
    }
    loop {
        match Command::from_bytes(&ranks.broadcast(Vec::new()))? {
            Command::Step(dt) => {
                sim.step_over(dt, ranks).map_err(|e| RunError::Solver {
                    time: sim.state.time,
                    step: sim.state.step,
                    message: e.to_string(),
                })?;
            }
            Command::Done => return Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn commands_round_trip_through_their_bytes() {
        for c in [
            Command::Step(1.25e-9),
            Command::Step(f64::INFINITY),
            Command::Done,
        ] {
            assert_eq!(Command::from_bytes(&c.bytes()).unwrap(), c);
        }
        assert!(Command::from_bytes(&[1, 2, 3]).is_err());
    }
}

//! A run over several ranks (solver/ranks.rs; docs/mpi.md): rank 0 runs the scene as a
//! single process does, writing the run directory; every other rank builds the same
//! simulation and steps it in lockstep, told by rank 0 how far each step may go and when
//! to write its piece of a snapshot (run/snapshot.rs). A resumed run's state is rank 0's,
//! read from its checkpoint and sent to the others.

use crate::run::error::RunError;
use crate::run::snapshot;
use crate::scene::{SceneDimension, SimOf};
use crate::solver::{Ranks, SolverCheckpoint};
use std::path::Path;

/// What rank 0 tells the others before each step and each snapshot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Command {
    /// Take a step of at most this long (s).
    Step(f64),
    /// Write your piece of snapshot `index` (run/snapshot.rs); `end`: the run's last,
    /// taken once the density is synchronised and free flight has ended.
    Snapshot { index: usize, end: bool },
    /// The run has ended (at its end time, or stopped at a checkpoint).
    Done,
}

impl Command {
    fn bytes(self) -> Vec<u8> {
        match self {
            Command::Step(dt) => [&[0][..], &dt.to_le_bytes()].concat(),
            Command::Snapshot { index, end } => {
                [&[1, u8::from(end)][..], &(index as u64).to_le_bytes()].concat()
            }
            Command::Done => vec![2],
        }
    }

    fn from_bytes(b: &[u8]) -> Result<Self, RunError> {
        match b {
            [0, dt @ ..] if dt.len() == 8 => Ok(Command::Step(f64::from_le_bytes(
                dt.try_into().expect("8 bytes"),
            ))),
            [1, end @ (0 | 1), index @ ..] if index.len() == 8 => Ok(Command::Snapshot {
                index: u64::from_le_bytes(index.try_into().expect("8 bytes")) as usize,
                end: *end == 1,
            }),
            [2] => Ok(Command::Done),
            _ => Err(RunError::Diagnostics(format!(
                "rank 0 sent a command of {} bytes that is none of step, snapshot, done",
                b.len()
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
/// state first when the run resumes, and writes its pieces of the snapshots into `dir`
/// (each particle's mass is that of the `copies` it stands for, as rank 0 writes it).
pub(crate) fn follow<D: SceneDimension>(
    ranks: &dyn Ranks,
    mut sim: SimOf<D>,
    resume: bool,
    dir: &Path,
    copies: f64,
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
    let failed = |sim: &SimOf<D>, e: crate::SolverError| RunError::Solver {
        time: sim.state.time,
        step: sim.state.step,
        message: e.to_string(),
    };
    loop {
        match Command::from_bytes(&ranks.broadcast(Vec::new()))? {
            Command::Step(dt) => {
                sim.step_over(dt, ranks).map_err(|e| failed(&sim, e))?;
            }
            Command::Snapshot { index, end } => {
                // As rank 0 does before its last snapshot (run/drive.rs).
                if end {
                    sim.sync_density().map_err(|e| failed(&sim, e))?;
                    sim.end_free_flight();
                }
                sim.with_free_flight(|sim| {
                    snapshot::write_piece::<D>(sim, copies, dir, index, ranks)
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
            Command::Snapshot {
                index: 12,
                end: false,
            },
            Command::Snapshot {
                index: 0,
                end: true,
            },
            Command::Done,
        ] {
            assert_eq!(Command::from_bytes(&c.bytes()).unwrap(), c);
        }
        for bad in [
            &[][..],
            &[1, 2, 3],
            &[0; 8],
            &[1, 2, 0, 0, 0, 0, 0, 0, 0, 0],
            &[2, 0],
        ] {
            assert!(Command::from_bytes(bad).is_err(), "{bad:?}");
        }
    }
}

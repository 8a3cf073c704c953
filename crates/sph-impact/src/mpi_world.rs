//! The ranks of MPI's world communicator (the `mpi` feature; docs/mpi.md), through the
//! system's MPI by rsmpi.
//!
//! MPI is called from the process' main thread only (MPI_THREAD_FUNNELED): the command
//! runs on a thread of its own, and its collectives ([`Ranks::all_gather`],
//! [`Ranks::broadcast`], [`Ranks::exchange`]) are handed to the main thread over a channel, which performs
//! them and hands back the result. An error on any rank stops every rank (MPI_Abort)
//! with that rank's message, so that no rank waits for one that has gone.

use crate::cli::CommandError;
use crate::solver::{Gathered, Ranks};
use mpi::datatype::{Partition, PartitionMut};
use mpi::topology::SimpleCommunicator;
use mpi::traits::*;
use std::sync::Mutex;
use std::sync::mpsc::{Receiver, Sender, channel};

/// A collective asked of the main thread.
enum Request {
    AllGather(Vec<f64>),
    Broadcast(Vec<u8>),
    Exchange(Vec<Vec<f64>>),
}

/// What the main thread hands back.
enum Response {
    Gathered(Gathered),
    Broadcast(Vec<u8>),
    Exchanged(Vec<Vec<f64>>),
}

/// This process' rank of the world, as the solver sees it: its collectives go to the
/// main thread.
pub struct WorldRank {
    rank: usize,
    size: usize,
    channel: Mutex<(Sender<Request>, Receiver<Response>)>,
}

impl WorldRank {
    fn ask(&self, request: Request) -> Response {
        let c = self.channel.lock().expect("one collective at a time");
        c.0.send(request)
            .expect("the main thread serves until the command ends");
        c.1.recv().expect("the main thread answers every request")
    }
}

impl Ranks for WorldRank {
    fn rank(&self) -> usize {
        self.rank
    }
    fn size(&self) -> usize {
        self.size
    }
    fn all_gather(&self, own: Vec<f64>) -> Gathered {
        match self.ask(Request::AllGather(own)) {
            Response::Gathered(all) => all,
            _ => unreachable!("an all-gather answers an all-gather"),
        }
    }
    fn broadcast(&self, data: Vec<u8>) -> Vec<u8> {
        match self.ask(Request::Broadcast(data)) {
            Response::Broadcast(data) => data,
            _ => unreachable!("a broadcast answers a broadcast"),
        }
    }
    fn exchange(&self, to: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
        assert_eq!(to.len(), self.size, "one message per rank");
        match self.ask(Request::Exchange(to)) {
            Response::Exchanged(got) => got,
            _ => unreachable!("an exchange answers an exchange"),
        }
    }
}

/// Counts and displacements as MPI takes them (i32), refused past its range.
fn counts_of(lengths: &[usize]) -> (Vec<mpi::Count>, Vec<mpi::Count>) {
    let count = |n: usize| {
        mpi::Count::try_from(n).unwrap_or_else(|_| panic!("{n} values exceed one MPI message"))
    };
    let counts: Vec<_> = lengths.iter().map(|&n| count(n)).collect();
    let mut displs = Vec::with_capacity(lengths.len());
    let mut at = 0;
    for &n in lengths {
        displs.push(count(at));
        at += n;
    }
    (counts, displs)
}

/// Performs `request` over `world`.
fn serve(world: &SimpleCommunicator, request: Request) -> Response {
    match request {
        Request::AllGather(own) => {
            let size = world.size() as usize;
            let mut lengths = vec![0_u64; size];
            world.all_gather_into(&(own.len() as u64), &mut lengths[..]);
            let lengths: Vec<usize> = lengths.iter().map(|&n| n as usize).collect();
            let (counts, displs) = counts_of(&lengths);
            let mut all = vec![0.0_f64; lengths.iter().sum()];
            {
                let mut partition = PartitionMut::new(&mut all[..], counts, &displs[..]);
                world.all_gather_varcount_into(&own[..], &mut partition);
            }
            Response::Gathered(Gathered {
                values: all,
                lengths,
            })
        }
        Request::Exchange(to) => {
            // The lengths first (MPI_Alltoall), then the values (MPI_Alltoallv).
            let size = world.size() as usize;
            let sent: Vec<u64> = to.iter().map(|m| m.len() as u64).collect();
            let mut got = vec![0_u64; size];
            world.all_to_all_into(&sent[..], &mut got[..]);
            let sent: Vec<usize> = sent.iter().map(|&n| n as usize).collect();
            let got: Vec<usize> = got.iter().map(|&n| n as usize).collect();
            let (send_counts, send_displs) = counts_of(&sent);
            let (recv_counts, recv_displs) = counts_of(&got);
            // Never an empty buffer: MPI refuses its (dangling) address.
            let mut send = to.concat();
            send.resize(send.len().max(1), 0.0);
            let total: usize = got.iter().sum();
            let mut all = vec![0.0_f64; total.max(1)];
            {
                let out = Partition::new(&send[..], send_counts, &send_displs[..]);
                let mut back = PartitionMut::new(&mut all[..], recv_counts, &recv_displs[..]);
                world.all_to_all_varcount_into(&out, &mut back);
            }
            let mut at = 0;
            Response::Exchanged(
                got.iter()
                    .map(|&n| {
                        at += n;
                        all[at - n..at].to_vec()
                    })
                    .collect(),
            )
        }
        Request::Broadcast(mut data) => {
            let root = world.process_at_rank(0);
            let mut len = data.len() as u64;
            root.broadcast_into(&mut len);
            data.resize(len as usize, 0);
            // An empty buffer is not sent: MPI refuses its (dangling) address.
            if len > 0 {
                root.broadcast_into(&mut data[..]);
            }
            Response::Broadcast(data)
        }
    }
}

/// Runs `command` on every rank of MPI's world (initialised here, finalised on return),
/// with this process' rank; returns its result. On more than one rank, an error that
/// is not a stop request (exit code 130, after which every rank has ended its run) is
/// printed with the rank and stops every rank with its exit code (MPI_Abort).
pub fn over_world(
    command: impl FnOnce(&WorldRank) -> Result<(), CommandError> + Send,
) -> Result<(), CommandError> {
    let Some((universe, _)) = mpi::initialize_with_threading(mpi::Threading::Funneled) else {
        return Err(CommandError::failed(
            "MPI was initialised before: cannot run",
        ));
    };
    let world = universe.world();
    let (size, rank) = (world.size() as usize, world.rank() as usize);
    let (to_main, requests) = channel();
    let (answers, from_main) = channel();
    let me = WorldRank {
        rank,
        size,
        channel: Mutex::new((to_main, from_main)),
    };
    let result = std::thread::scope(|s| {
        let worker = s.spawn(move || {
            let me = me;
            command(&me)
        });
        // Serve until the command drops its end of the channel.
        for request in requests {
            if answers.send(serve(&world, request)).is_err() {
                break;
            }
        }
        worker
            .join()
            .unwrap_or_else(|_| Err(CommandError::failed("the command panicked")))
    });
    if let Err(e) = &result
        && size > 1
        && e.code != CommandError::INTERRUPTED
    {
        eprintln!(
            "error (rank {rank} of {size}): {}",
            crate::input::printable(&e.to_string())
        );
        world.abort(i32::from(e.code));
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_displacements_follow_the_lengths() {
        assert_eq!(counts_of(&[3, 0, 2]), (vec![3, 0, 2], vec![0, 3, 3]));
        assert_eq!(counts_of(&[]), (vec![], vec![]));
    }
}

//! Ranks as the threads of a unit test (the integration tests have their own, over the
//! public API: tests/ranks.rs).

use super::{Gathered, Ranks};
use std::sync::{Barrier, Mutex};

/// Rank `rank` of `size` threads sharing `posted` (a slot per rank) and `all_here`.
/// Every call is a collective, so each round posts its part, waits for all, reads, and
/// waits again before the next round posts.
pub(crate) struct Threads<'a> {
    rank: usize,
    size: usize,
    posted: &'a Mutex<Vec<Vec<f64>>>,
    all_here: &'a Barrier,
}

impl<'a> Threads<'a> {
    /// Rank `rank` of `size`; `posted` holds `size` slots and `all_here` waits for `size`.
    pub(crate) fn new(
        rank: usize,
        size: usize,
        posted: &'a Mutex<Vec<Vec<f64>>>,
        all_here: &'a Barrier,
    ) -> Self {
        Threads {
            rank,
            size,
            posted,
            all_here,
        }
    }
}

impl Ranks for Threads<'_> {
    fn rank(&self) -> usize {
        self.rank
    }
    fn size(&self) -> usize {
        self.size
    }
    fn all_gather(&self, own: Vec<f64>) -> Gathered {
        self.posted.lock().unwrap()[self.rank] = own;
        self.all_here.wait();
        let parts = self.posted.lock().unwrap().clone();
        self.all_here.wait();
        Gathered {
            lengths: parts.iter().map(Vec::len).collect(),
            values: parts.concat(),
        }
    }
    fn broadcast(&self, _: Vec<u8>) -> Vec<u8> {
        unreachable!("the tests of the halo exchange do not broadcast")
    }
}

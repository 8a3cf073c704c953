//! The pool's other threads kept awake through a step.
//!
//! A rayon worker that finds no work for a few dozen rounds (tens of microseconds) goes
//! to sleep, and the next job wakes it through the kernel. A stage of a scene of a few
//! thousand particles is a few milliseconds of short parallel passes with serial work
//! between them, so left alone the workers fall asleep and are woken again 29 times a
//! step, and each pass waits for them. Kept awake, the study's RZ case at 0.5 mm ran 1.08× faster
//! on two threads (docs/performance.md, "The pool's threads kept awake through a
//! step"). For the length of a step each other worker of the pool runs
//! [`keep_busy`]: it takes the pool's jobs as they come (`rayon::yield_now`, which runs
//! one pending job, local or stolen) and, between them, yields the processor without
//! going to sleep. It ends when the step ends, or after [`IDLE_LIMIT`] without a job,
//! so that a thread is never kept spinning through a long serial stretch; steps of
//! [`STEP_LIMIT`] or longer, whose passes are long, are left to rayon's own idling.
//! The pair passes run their blocks through [`for_each_awake`], whose calling thread
//! takes jobs rather than sleeping while the last blocks run.
//!
//! Which thread runs which job never changes a result: the passes' sums are fixed by
//! their blocks (solver/pair_blocks.rs), not by the threads that add them.

use rayon::iter::IndexedParallelIterator;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// How long a kept-awake worker waits without a job before it returns to rayon's own
/// idling (and, soon after, to sleep). A stage's serial stretches on the scenes
/// measured are far shorter; a longer one (a snapshot, a rank's collective) ends the
/// spinning.
const IDLE_LIMIT: Duration = Duration::from_millis(2);

/// Steps at least this long are left to rayon's own idling: the study's RZ case on two
/// threads saved about 1 ms per step by keeping the threads awake (about 29 wakes per
/// step), so a step of 50 ms loses at most about 2 % to waking, and a longer one (the 3-D
/// scene's steps take seconds) has nothing measurable to gain from a spinning thread.
const STEP_LIMIT: Duration = Duration::from_millis(50);

/// Whether a step keeps the pool's threads awake: yes while the steps are short, judged
/// by the last one (the first step of a run is kept awake).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct KeepAwake {
    last_step: Option<Duration>,
}

impl KeepAwake {
    /// The guard for the coming step: [`WarmThreads::start`] unless the last step took
    /// [`STEP_LIMIT`] or longer.
    pub(crate) fn for_step(&self) -> WarmThreads {
        if self.last_step.is_some_and(|d| d >= STEP_LIMIT) {
            WarmThreads { done: None }
        } else {
            WarmThreads::start()
        }
    }

    /// Records how long the step took.
    pub(crate) fn step_took(&mut self, wall: Duration) {
        self.last_step = Some(wall);
    }
}

/// Keeps the current pool's other workers awake until dropped. Does nothing outside a
/// rayon pool or in a pool of one thread.
pub(crate) struct WarmThreads {
    done: Option<Arc<AtomicBool>>,
}

impl WarmThreads {
    /// Starts one [`keep_busy`] on every other worker of the pool this thread runs in.
    pub(crate) fn start() -> Self {
        let Some(me) = rayon::current_thread_index() else {
            return WarmThreads { done: None };
        };
        if rayon::current_num_threads() < 2 {
            return WarmThreads { done: None };
        }
        let done = Arc::new(AtomicBool::new(false));
        let flag = Arc::clone(&done);
        // One task per worker, each run by its own worker (rayon's broadcast queues are
        // not stolen from); this thread's returns at once, so it never waits on itself.
        rayon::spawn_broadcast(move |ctx| {
            if ctx.index() != me {
                keep_busy(&flag, IDLE_LIMIT);
            }
        });
        WarmThreads { done: Some(done) }
    }
}

impl Drop for WarmThreads {
    fn drop(&mut self) {
        if let Some(done) = &self.done {
            done.store(true, Ordering::Release);
        }
    }
}

/// Runs `f` on every item of `items`, one task per item spread over the pool, and
/// returns when all have run. A parallel iterator's `for_each` leaves the thread that
/// finishes first waiting for the others' last tasks in rayon's own wait, where it goes
/// to sleep and must be woken at the end; here that thread keeps taking the pool's jobs
/// (`rayon::yield_now`) until every task is done, so the pass ends as soon as its last
/// task does. On a pool of one thread the items run in order.
pub(crate) fn for_each_awake<I: IndexedParallelIterator>(items: I, f: impl Fn(I::Item) + Sync) {
    let items: Vec<I::Item> = items.collect();
    if rayon::current_num_threads() < 2 {
        items.into_iter().for_each(f);
        return;
    }
    let left = AtomicUsize::new(items.len());
    // Counts a task done however it ends (a panic is passed on by the scope).
    struct Done<'a>(&'a AtomicUsize);
    impl Drop for Done<'_> {
        fn drop(&mut self) {
            self.0.fetch_sub(1, Ordering::Release);
        }
    }
    rayon::scope(|s| {
        for item in items {
            let (f, left) = (&f, &left);
            s.spawn(move |_| {
                let _done = Done(left);
                f(item);
            });
        }
        while left.load(Ordering::Acquire) > 0 {
            if rayon::yield_now() != Some(rayon::Yield::Executed) {
                std::thread::yield_now();
            }
        }
    });
}

/// Runs the pool's pending jobs on this worker until `done` is set, or until no job has
/// come for `idle_limit`.
fn keep_busy(done: &AtomicBool, idle_limit: Duration) {
    let mut idle_since: Option<Instant> = None;
    while !done.load(Ordering::Acquire) {
        match rayon::yield_now() {
            Some(rayon::Yield::Executed) => idle_since = None,
            Some(rayon::Yield::Idle) => {
                if idle_since.get_or_insert_with(Instant::now).elapsed() > idle_limit {
                    return;
                }
                std::thread::yield_now();
            }
            // Not on a pool's thread: nothing to keep awake.
            None => return,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rayon::prelude::*;

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
    }

    /// Outside a pool, and in a pool of one thread, nothing is started.
    #[test]
    fn nothing_to_keep_awake() {
        assert!(WarmThreads::start().done.is_none());
        assert!(pool(1).install(WarmThreads::start).done.is_none());
        assert!(pool(2).install(WarmThreads::start).done.is_some());
    }

    /// Short steps keep the threads awake, long ones do not.
    #[test]
    fn only_short_steps_keep_threads_awake() {
        let p = pool(2);
        let mut k = KeepAwake::default();
        assert!(p.install(|| k.for_step()).done.is_some());
        k.step_took(STEP_LIMIT);
        assert!(p.install(|| k.for_step()).done.is_none());
        k.step_took(STEP_LIMIT / 2);
        assert!(p.install(|| k.for_step()).done.is_some());
    }

    /// Parallel work under the guard gives what it gives without it.
    #[test]
    fn work_runs_under_the_guard() {
        let serial: u64 = (0..100_000u64).map(|k| k * k % 7).sum();
        for threads in [2, 3] {
            let sums: Vec<u64> = pool(threads).install(|| {
                let _warm = WarmThreads::start();
                (0..20)
                    .map(|_| (0..100_000u64).into_par_iter().map(|k| k * k % 7).sum())
                    .collect()
            });
            assert!(sums.iter().all(|&s| s == serial));
        }
    }

    /// Every item runs once, on any pool size, and a panicking task is passed on
    /// rather than waited for.
    #[test]
    fn each_item_runs_once() {
        for threads in [1, 2, 3] {
            let mut out = vec![0u64; 50];
            let items: Vec<(usize, &mut u64)> = out.iter_mut().enumerate().collect();
            pool(threads).install(|| {
                for_each_awake(items.into_par_iter(), |(k, slot)| *slot += (k * k) as u64);
            });
            assert!(out.iter().enumerate().all(|(k, &v)| v == (k * k) as u64));
        }
        let caught = std::panic::catch_unwind(|| {
            pool(2).install(|| {
                for_each_awake(vec![1, 2, 3].into_par_iter(), |k| assert!(k != 2, "task 2"))
            });
        });
        assert!(caught.is_err());
    }

    /// A kept-awake worker returns once the flag is set, and gives up after the idle
    /// limit if it never is; outside a pool it returns at once.
    #[test]
    fn kept_awake_workers_return() {
        let p = pool(2);
        let done = Arc::new(AtomicBool::new(false));
        let (tx, rx) = std::sync::mpsc::channel();
        let flag = Arc::clone(&done);
        p.spawn(move || {
            keep_busy(&flag, Duration::from_secs(3600));
            tx.send(()).unwrap();
        });
        std::thread::sleep(Duration::from_millis(20));
        assert!(rx.try_recv().is_err(), "returned before the flag was set");
        done.store(true, Ordering::Release);
        rx.recv_timeout(Duration::from_secs(10))
            .expect("returned after the flag was set");

        let t = Instant::now();
        p.install(|| keep_busy(&AtomicBool::new(false), Duration::from_millis(5)));
        assert!(t.elapsed() >= Duration::from_millis(5));

        keep_busy(&AtomicBool::new(false), Duration::from_secs(3600));
    }
}

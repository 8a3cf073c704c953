//! Shared set-up for the workspace benchmarks: reproducible particle clouds, and the
//! counting allocator and resident-memory reading the solver benches report memory with.

use sph_core::glam::DVec3;
use sph_core::morton_order;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A deterministic pseudo-random number in [0, 1) (splitmix64 finaliser).
pub fn unit(seed: u64) -> f64 {
    let mut z = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    (z ^ (z >> 31)) as f64 / 2f64.powi(64)
}

/// A cubic lattice of `side³` points with unit spacing, each point displaced uniformly
/// within ±`jitter` per axis, returned in Morton order (as a solver holds them after
/// its periodic reorder).
pub fn jittered_lattice(side: usize, jitter: f64) -> Vec<DVec3> {
    let mut x: Vec<DVec3> = (0..side * side * side)
        .map(|i| {
            let j = |s: u64| jitter * (2.0 * unit(3 * i as u64 + s) - 1.0);
            DVec3::new(
                (i % side) as f64 + j(0),
                ((i / side) % side) as f64 + j(1),
                (i / (side * side)) as f64 + j(2),
            )
        })
        .collect();
    let perm = morton_order(&x).expect("finite positions");
    perm.apply("position", &mut x).expect("same length");
    x
}

/// The system allocator, counting the live heap and its peak (bench-only
/// instrumentation: the solver itself never sees it). A bench binary installs it with
/// `#[global_allocator] static A: sph_benches::Counting = sph_benches::Counting;`.
pub struct Counting;

/// Bytes live on the heap now (with [`Counting`] installed).
pub static LIVE: AtomicUsize = AtomicUsize::new(0);
/// The largest [`LIVE`] since it was last reset.
pub static PEAK: AtomicUsize = AtomicUsize::new(0);

#[allow(unsafe_code)]
// SAFETY: every call forwards to `System` with the caller's layout unchanged; the
// counters are only bookkeeping.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                let grow = new_size - layout.size();
                let now = LIVE.fetch_add(grow, Ordering::Relaxed) + grow;
                PEAK.fetch_max(now, Ordering::Relaxed);
            } else {
                LIVE.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        p
    }
}

/// Keeps the memory a stage frees for the next one, as the `sph-impact` program does at
/// its start (its `keep_freed_memory`, src/bin/sph-impact.rs, says why): glibc's mmap
/// threshold at its largest, 32 MiB, and the heap's top never trimmed. Call it first in
/// a bench's main, before any thread starts.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
#[allow(unsafe_code)]
pub fn keep_freed_memory() {
    // SAFETY: mallopt only sets two allocator parameters, before other threads exist;
    // glibc refuses (returning 0) values out of its ranges, leaving its defaults.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
        libc::mallopt(libc::M_TRIM_THRESHOLD, i32::MAX);
    }
}

/// Other systems keep their allocator's defaults.
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
pub fn keep_freed_memory() {}

/// Peak resident set size (bytes) of this process so far, from /proc (Linux); 0 elsewhere.
pub fn peak_rss() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(0.0, |kb| kb * 1024.0)
}

//! Shared set-up for the workspace benchmarks: reproducible particle clouds.

use sph_core::glam::DVec3;
use sph_core::morton_order;

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

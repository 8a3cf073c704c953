//! Neighbour build + query in 3-D at ~1e5 and 1e6 particles, ≈65 neighbours each
//! (support radius 2.5 Δx on a lattice jittered by ±0.5 Δx): the sorted-grid cell list
//! beside an R*-tree (rstar). Both produce the same sorted CSR lists.
//!
//! `cargo bench -p sph-benches --bench neighbors`; criterion's "thrpt" is particles/s.

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use rayon::prelude::*;
use rstar::RTree;
use rstar::primitives::GeomWithData;
use sph_benches::jittered_lattice;
use sph_core::glam::DVec3;
use sph_core::{CellList, NeighborSearch, ScalarSupport};
use std::hint::black_box;

const SUPPORT: f64 = 2.5;

fn cell_list(x: &[DVec3], h: &[f64]) -> usize {
    let crit = ScalarSupport::new(h).unwrap();
    CellList::new().neighbors(x, &crit).unwrap().total_pairs()
}

fn rstar_tree(x: &[DVec3]) -> usize {
    let tree = RTree::bulk_load(
        x.iter()
            .enumerate()
            .map(|(i, p)| GeomWithData::new([p.x, p.y, p.z], i as u32))
            .collect(),
    );
    let rows: Vec<Vec<u32>> = x
        .par_iter()
        .enumerate()
        .map(|(i, p)| {
            let mut row: Vec<u32> = tree
                .locate_within_distance([p.x, p.y, p.z], SUPPORT * SUPPORT)
                .map(|g| g.data)
                .filter(|&j| {
                    j as usize != i && (x[j as usize] - *p).length_squared() < SUPPORT * SUPPORT
                })
                .collect();
            row.sort_unstable();
            row
        })
        .collect();
    rows.iter().map(Vec::len).sum()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("neighbors_3d");
    group.sample_size(10);
    for side in [46usize, 100] {
        let x = jittered_lattice(side, 0.5);
        let h = vec![SUPPORT; x.len()];
        let n = x.len();
        let pairs = cell_list(&x, &h);
        assert_eq!(pairs, rstar_tree(&x), "the two searches disagree");
        println!(
            "N = {n}: mean neighbour count {:.1}",
            pairs as f64 / n as f64
        );
        group.throughput(Throughput::Elements(n as u64));
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        group.bench_with_input(BenchmarkId::new("cell_list_2threads", n), &x, |b, x| {
            b.iter(|| black_box(cell_list(x, &h)))
        });
        group.bench_with_input(BenchmarkId::new("cell_list_1thread", n), &x, |b, x| {
            b.iter(|| one.install(|| black_box(cell_list(x, &h))))
        });
        group.bench_with_input(BenchmarkId::new("rstar_2threads", n), &x, |b, x| {
            b.iter(|| black_box(rstar_tree(x)))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);

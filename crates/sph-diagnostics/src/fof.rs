//! Friends-of-friends clustering (Davis, Efstathiou, Frenk & White 1985, ApJ 292, 371):
//! two particles closer than the linking length are friends, and a cluster is a maximal
//! set connected by friendship. Used to count fragments and to check that bodies that
//! should stay apart do (the colliding rubber rings stay two clusters at link 1.5 Δp).
//!
//! **Method.** Particles are binned into a uniform grid of cells one linking length wide
//! (a hash map from cell to particles, so memory is O(N) however sparse the cloud), so
//! friends are always in the same or an adjacent cell; each candidate pair is tested
//! exactly and friends are merged with union–find (path halving, Tarjan 1975, J. ACM 22,
//! 215). That is O(N) on average for a cloud of bounded density.
//!
//! **Labels are deterministic**: clusters are numbered 0, 1, … in the order of their
//! smallest particle index. The partition does not depend on the order in which pairs are
//! merged, so the labels depend only on the input, never on the grid or a thread count.

use crate::error::ImpactError;
use std::collections::HashMap;

/// The clusters found: a label per particle and a size per cluster.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Clusters {
    /// Cluster of each particle, in 0..sizes.len(); cluster k's smallest particle index is
    /// smaller than cluster (k+1)'s.
    pub label: Vec<u32>,
    /// Number of particles in each cluster.
    pub sizes: Vec<usize>,
}

impl Clusters {
    /// Number of clusters.
    pub fn count(&self) -> usize {
        self.sizes.len()
    }

    /// Mass of each cluster (kg), from per-particle masses (kg).
    pub fn masses(&self, mass: &[f64]) -> Result<Vec<f64>, ImpactError> {
        if mass.len() != self.label.len() {
            return Err(ImpactError::LengthMismatch {
                field: "mass",
                len: mass.len(),
                expected: self.label.len(),
            });
        }
        let mut m = vec![0.0; self.count()];
        for (&l, &mi) in self.label.iter().zip(mass) {
            // Only a hand-edited `Clusters` can have a label without a size.
            let slot = m.get_mut(l as usize).ok_or(ImpactError::BadParameter {
                name: "label",
                value: l as f64,
                reason: "no such cluster",
            })?;
            *slot += mi;
        }
        Ok(m)
    }
}

/// Friends-of-friends clusters of `points` (m) with linking length `link` (m): i and j are
/// friends when |x_i − x_j| < `link`.
///
/// Never panics: a point with a non-finite coordinate is its own cluster; `link` ≤ 0 or
/// NaN links nothing; `link` = ∞ links every finite point (in O(N²)). Labels are `u32`,
/// so at most 2³² particles.
pub fn friends_of_friends(points: &[[f64; 3]], link: f64) -> Clusters {
    let mut sets = UnionFind::new(points.len());
    if link > 0.0 {
        link_pairs(points, link, &mut sets);
    }
    sets.into_clusters()
}

/// Merges every pair of friends, testing only pairs in the same or adjacent cells.
fn link_pairs(points: &[[f64; 3]], link: f64, sets: &mut UnionFind) {
    let finite = |p: &[f64; 3]| p.iter().all(|c| c.is_finite());
    let mut lo = [f64::INFINITY; 3];
    for p in points.iter().filter(|p| finite(p)) {
        for a in 0..3 {
            lo[a] = lo[a].min(p[a]);
        }
    }
    // Slightly wider cells than `link` so that rounding in the cell coordinate can never
    // put two friends two cells apart (safe while the extent is < ~10⁶ links).
    let cell = link * (1.0 + 1e-9);
    let key = |p: &[f64; 3]| -> [i64; 3] {
        // `as` saturates; huge or infinite ratios (link = ∞ gives 0) stay well defined.
        std::array::from_fn(|a| ((p[a] - lo[a]) / cell).floor() as i64)
    };
    let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
    for (i, p) in points.iter().enumerate() {
        if finite(p) {
            grid.entry(key(p)).or_default().push(i as u32);
        }
    }
    let link2 = link * link;
    for (i, p) in points.iter().enumerate() {
        if !finite(p) {
            continue;
        }
        let k = key(p);
        for d in NEIGHBOUR_OFFSETS {
            let nk = [
                k[0].saturating_add(d[0]),
                k[1].saturating_add(d[1]),
                k[2].saturating_add(d[2]),
            ];
            let Some(cell_points) = grid.get(&nk) else {
                continue;
            };
            for &j in cell_points {
                let j = j as usize;
                if j > i && distance2(p, &points[j]) < link2 {
                    sets.union(i, j);
                }
            }
        }
    }
}

/// Squared distance (m²).
pub(crate) fn distance2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)
}

/// The 27 cells around and including a cell.
const NEIGHBOUR_OFFSETS: [[i64; 3]; 27] = {
    let mut o = [[0i64; 3]; 27];
    let mut n = 0;
    while n < 27 {
        o[n] = [
            (n % 3) as i64 - 1,
            ((n / 3) % 3) as i64 - 1,
            (n / 9) as i64 - 1,
        ];
        n += 1;
    }
    o
};

/// Disjoint sets over 0..n with path halving; `union` keeps the smaller index as root,
/// which bounds the tree depth well enough in practice and is deterministic.
pub(crate) struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n).collect(),
        }
    }

    pub(crate) fn find(&mut self, mut i: usize) -> usize {
        while self.parent[i] != i {
            self.parent[i] = self.parent[self.parent[i]];
            i = self.parent[i];
        }
        i
    }

    pub(crate) fn union(&mut self, a: usize, b: usize) {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra != rb {
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            self.parent[hi] = lo;
        }
    }

    /// Labels in order of each cluster's smallest member: scanning i upwards, the first
    /// member met of a cluster is its smallest.
    pub(crate) fn into_clusters(mut self) -> Clusters {
        let n = self.parent.len();
        let mut root_label = vec![u32::MAX; n];
        let mut label = Vec::with_capacity(n);
        let mut sizes = Vec::new();
        for i in 0..n {
            let r = self.find(i);
            if root_label[r] == u32::MAX {
                root_label[r] = sizes.len() as u32;
                sizes.push(0);
            }
            label.push(root_label[r]);
            sizes[root_label[r] as usize] += 1;
        }
        Clusters { label, sizes }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The O(N²) definition, for comparison.
    fn brute_force(points: &[[f64; 3]], link: f64) -> Clusters {
        let mut sets = UnionFind::new(points.len());
        for i in 0..points.len() {
            for j in i + 1..points.len() {
                if distance2(&points[i], &points[j]) < link * link {
                    sets.union(i, j);
                }
            }
        }
        sets.into_clusters()
    }

    #[test]
    fn hand_made_chain_and_singleton() {
        // 0–2–1 chained at 0.9 apart (friends of friends), 3 isolated, 4 a friend of 3.
        let p = [
            [0.0, 0.0, 0.0],
            [1.8, 0.0, 0.0],
            [0.9, 0.0, 0.0],
            [10.0, 0.0, 0.0],
            [10.0, 0.0, 0.5],
        ];
        let c = friends_of_friends(&p, 1.0);
        assert_eq!(c.label, vec![0, 0, 0, 1, 1]);
        assert_eq!(c.sizes, vec![3, 2]);
        assert_eq!(
            c.masses(&[1.0, 2.0, 3.0, 4.0, 5.0]).unwrap(),
            vec![6.0, 9.0]
        );
        assert!(c.masses(&[1.0]).is_err());
        let bad = Clusters {
            label: vec![3],
            sizes: vec![1],
        };
        assert!(bad.masses(&[1.0]).is_err());
        // Exactly `link` apart is not friends (strict inequality).
        let c = friends_of_friends(&[[0.0; 3], [1.0, 0.0, 0.0]], 1.0);
        assert_eq!(c.count(), 2);
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        assert_eq!(friends_of_friends(&[], 1.0), Clusters::default());
        let p = [[0.0; 3], [f64::NAN, 0.0, 0.0], [0.1, 0.0, 0.0]];
        assert_eq!(friends_of_friends(&p, 1.0).label, vec![0, 1, 0]);
        assert_eq!(friends_of_friends(&p, 0.0).count(), 3);
        assert_eq!(friends_of_friends(&p, f64::NAN).count(), 3);
        assert_eq!(friends_of_friends(&p, f64::INFINITY).label, vec![0, 1, 0]);
        let far = [[0.0; 3], [1e300, -1e300, 0.0], [1e-300, 0.0, 0.0]];
        assert_eq!(friends_of_friends(&far, 1e-3).label, vec![0, 1, 0]);
    }

    #[test]
    fn two_rings_a_lattice_step_apart_stay_two_bodies() {
        // Two rings of particles at spacing dp whose closest points are 2 dp apart: with
        // link 1.5 dp each ring is one cluster and they are not linked.
        let dp = 1e-3;
        let ring = |cx: f64| -> Vec<[f64; 3]> {
            let r = 20.0 * dp;
            let n = (2.0 * std::f64::consts::PI * r / dp) as usize;
            (0..n)
                .map(|k| {
                    let a = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                    [cx + r * a.cos(), r * a.sin(), 0.0]
                })
                .collect()
        };
        let mut p = ring(0.0);
        p.extend(ring(42.0 * dp));
        let c = friends_of_friends(&p, 1.5 * dp);
        assert_eq!(c.count(), 2);
        assert_eq!(c.sizes[0], c.sizes[1]);
    }

    #[test]
    fn a_large_lattice_is_one_cluster_or_all_singletons() {
        // 40³ points at unit spacing: link 1.5 joins them all, link 0.9 none (O(N) grid:
        // this runs in well under a second).
        let p: Vec<[f64; 3]> = (0..40 * 40 * 40)
            .map(|i| [(i % 40) as f64, ((i / 40) % 40) as f64, (i / 1600) as f64])
            .collect();
        assert_eq!(friends_of_friends(&p, 1.5).sizes, vec![p.len()]);
        let single = friends_of_friends(&p, 0.9);
        assert_eq!(single.count(), p.len());
        assert!(
            single
                .label
                .iter()
                .enumerate()
                .all(|(i, &l)| l as usize == i)
        );
    }

    proptest! {
        #[test]
        fn grid_search_equals_brute_force(
            pts in prop::collection::vec(prop::array::uniform3(-5.0f64..5.0), 0..150),
            link in 0.05f64..3.0,
        ) {
            prop_assert_eq!(friends_of_friends(&pts, link), brute_force(&pts, link));
        }

        #[test]
        fn labels_are_ordered_by_smallest_member(
            pts in prop::collection::vec(prop::array::uniform3(-3.0f64..3.0), 1..100),
            link in 0.1f64..2.0,
        ) {
            let c = friends_of_friends(&pts, link);
            prop_assert_eq!(c.sizes.iter().sum::<usize>(), pts.len());
            let mut next = 0u32;
            for &l in &c.label {
                prop_assert!(l <= next);
                if l == next { next += 1; }
            }
            prop_assert_eq!(next as usize, c.count());
        }
    }
}

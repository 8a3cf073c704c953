//! The multi-level sorted-grid cell list.
//!
//! Particles are binned by search radius into levels of one octave each (level ℓ holds
//! radii in (r_max/2^(ℓ+1), r_max/2^ℓ]; the last level takes everything smaller). Each
//! level is a uniform grid with cells of a fixed fraction of its largest radius
//! ([`DEFAULT_CELL_FRACTION`]), particles sorted by cell so that a row of cells along x
//! is one contiguous slice.
//!
//! **Gather, then transpose.** A particle of radius r_i visits, in every level, only the
//! cells within its own r_i, and keeps the accepted j with |r_ij| < r_i. A pair with
//! r_j > |r_ij| ≥ r_i is missed by i but found by j's own gather, which then hands i to
//! j's row ("one-sided"); rows are merged with these afterwards. Every accepted pair has
//! |r_ij| < max(r_i, r_j), so it is found from at least one side. Searching each
//! particle's own radius, not the largest radius of the level its neighbours sit in, is
//! what keeps the candidates per neighbour near a uniform lattice's on variable-resolution
//! bodies (docs/performance.md, "The scenes users run").
//!
//! **Some rows only.** [`CellList::neighbors_of_rows`] gives the rows of a range as the
//! whole search does (the others empty): it grids the range's rows and their halo only
//! (halo.rs: the particles outside that may pair with a row, from the boxes of the rows'
//! blocks), gathers the rows and, for the pairs only the other side finds, the halo
//! particles whose own radius reaches one of those boxes. A rank of a run over MPI
//! searches its own rows so, in about its share of the time of the whole search.
//!
//! A level whose bounding box would need more than a few cells per particle (points far
//! outside the bulk) switches from a dense `cell_start` table to a sorted list of cell
//! keys searched by bisection, so memory stays O(N) for any point cloud.

use super::criterion::check_inputs;
use super::halo::{Region, regions_of};
use super::list::{CHUNK, Chunk};
use super::{NeighborList, NeighborSearch, PairCriterion};
use crate::error::CoreError;
use crate::vector::Vector;
use rayon::prelude::*;
use std::ops::Range;

/// Default number of grid levels (radius ratios up to 2^(levels−1) are separated).
pub const DEFAULT_MAX_LEVELS: usize = 5;
/// Default cell size of a level as a fraction of the level's largest radius.
pub const DEFAULT_CELL_FRACTION: f64 = 0.5;
/// Cell coordinates beyond this (in cells) are refused: the domain is absurdly large
/// for the smallest support radius.
const MAX_CELL_COORD: f64 = 1.0e15;

/// The largest side of a box of a partial search's rows, in reaches of its particles
/// (`halo::regions_of_rows`): smaller boxes find a tighter halo, and each particle near the
/// rows is tested against more of them.
const HALO_REGION_SIZE: f64 = 4.0;

/// Statistics of one grid level of the last build.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LevelStats {
    /// Cell size (a fraction of the largest search radius in the level), m.
    pub cell_size: f64,
    /// Particles in the level.
    pub particles: usize,
    /// Cells in the level's bounding box.
    pub cells: f64,
    /// Whether the level uses the dense cell table (else sorted keys).
    pub dense: bool,
    /// Candidates of this level the last build tested by distance, over all the rows.
    pub candidates: u64,
}

/// The sorted-grid cell-list neighbour search (see the module docs).
#[derive(Clone, Debug)]
pub struct CellList {
    max_levels: usize,
    cell_fraction: f64,
    stats: Vec<LevelStats>,
    /// Candidates whose distance the last build tested (particles of the visited cells).
    candidates: u64,
}

impl Default for CellList {
    fn default() -> Self {
        Self::new()
    }
}

impl CellList {
    /// A cell list with [`DEFAULT_MAX_LEVELS`] levels.
    pub fn new() -> Self {
        Self::with_max_levels(DEFAULT_MAX_LEVELS)
    }
    /// A cell list with at most `levels` grid levels (at least 1; 1 gives the classic
    /// single grid with cells of the largest radius).
    pub fn with_max_levels(levels: usize) -> Self {
        Self {
            max_levels: levels.max(1),
            cell_fraction: DEFAULT_CELL_FRACTION,
            stats: Vec::new(),
            candidates: 0,
        }
    }
    /// The same list with cells of `fraction` times each level's largest radius.
    ///
    /// # Panics
    /// If `fraction` is not in [1/8, 4] (finer cells cost more rows than they save
    /// candidates; coarser ones test most of a level).
    pub fn with_cell_fraction(mut self, fraction: f64) -> Self {
        assert!(
            (0.125..=4.0).contains(&fraction),
            "cell fraction {fraction} outside [0.125, 4]"
        );
        self.cell_fraction = fraction;
        self
    }
    /// Statistics of the levels of the last build.
    pub fn level_stats(&self) -> &[LevelStats] {
        &self.stats
    }
    /// The candidates the last build tested by distance (every particle of every cell
    /// it visited, the searching one excepted): over the pairs found, the search's cost
    /// per neighbour: on a uniform 3-D lattice about 2.5³/(4π/3) ≈ 3.7 with the default
    /// cells of half the radius (3.0 measured, the lattice's faces cutting the spheres),
    /// 3³/(4π/3) ≈ 6.4 with cells of the radius.
    pub fn candidates(&self) -> u64 {
        self.candidates
    }
}

impl<V: Vector> NeighborSearch<V> for CellList {
    fn neighbors<C: PairCriterion<V>>(
        &mut self,
        positions: &[V],
        criterion: &C,
    ) -> Result<NeighborList, CoreError> {
        self.neighbors_of_rows(positions, criterion, 0..positions.len())
    }
}

impl CellList {
    /// The neighbours of the particles `rows` only, the same rows as [`NeighborSearch::neighbors`]
    /// gives them; every other row is empty. Only the rows and their halo are gridded;
    /// besides the rows' own gathers, the halo particles whose radius reaches a box of
    /// the rows' blocks are gathered for the pairs only they find (|r_ij| ≥ r_i): a
    /// process that evaluates some rows (a rank of a run over MPI) searches those and a
    /// layer around them, not every particle.
    pub fn neighbors_of_rows<V: Vector, C: PairCriterion<V>>(
        &mut self,
        positions: &[V],
        criterion: &C,
        rows: Range<usize>,
    ) -> Result<NeighborList, CoreError> {
        check_inputs(positions, criterion)?;
        if rows.end > positions.len() || rows.start > rows.end {
            return Err(CoreError::LengthMismatch {
                what: "rows of a partial neighbour search",
                expected: positions.len(),
                got: rows.end,
            });
        }
        let n = positions.len();
        if n == 0 {
            self.stats.clear();
            return Ok(NeighborList::from_rows(Vec::new()));
        }
        let radius: Vec<f64> = (0..n).map(|i| criterion.radius(i)).collect();
        for (index, &r) in radius.iter().enumerate() {
            if !(r > 0.0 && r.is_finite()) {
                return Err(CoreError::BadSupportRadius { index, radius: r });
            }
        }
        let r_max = radius.iter().cloned().fold(0.0, f64::max);
        let whole = rows.start == 0 && rows.end == n;
        // A partial search grids the rows and their halo only (halo.rs): the particles
        // outside that can pair with a row, found from the boxes of the rows' blocks.
        // Every pair of a row has its other side among them, so the rows are the whole
        // search's, and a rank of a run over MPI grids about its share of the particles.
        // Of the halo, only a particle whose own radius reaches a block's box gathers
        // (for the pairs that only it finds, |r_ij| ≥ r_i).
        let outside: Vec<Outside> = if whole {
            Vec::new()
        } else {
            // Two levels of boxes: a particle far from a group of eight regions tests
            // none of them.
            let regions = regions_of(positions, criterion, rows.clone(), HALO_REGION_SIZE);
            let groups: Vec<Region<V>> = regions
                .chunks(8)
                .map(|c| c.iter().skip(1).fold(c[0], |u, b| u.union(b)))
                .collect();
            (0..n)
                .into_par_iter()
                .map(|i| {
                    let (x, r) = (positions[i], radius[i]);
                    let mut found = Outside::Away;
                    if rows.contains(&i) {
                        return found;
                    }
                    for (g, group) in groups.iter().enumerate() {
                        if !group.may_pair(x, r) {
                            continue;
                        }
                        for b in &regions[8 * g..(8 * g + 8).min(regions.len())] {
                            let d2 = b.distance_squared(x);
                            if d2 < r * r {
                                return Outside::Reaches;
                            }
                            if d2 < b.reach * b.reach {
                                found = Outside::Halo;
                            }
                        }
                    }
                    found
                })
                .collect()
        };
        let gridded = |i: usize| whole || rows.contains(&i) || outside[i] != Outside::Away;

        // Bin particles into levels by octave of radius.
        let mut members: Vec<Vec<u32>> = vec![Vec::new(); self.max_levels];
        for (i, &r) in radius.iter().enumerate().filter(|&(i, _)| gridded(i)) {
            let l = ((r_max / r).log2().floor().max(0.0) as usize).min(self.max_levels - 1);
            members[l].push(i as u32);
        }
        let fraction = self.cell_fraction;
        let levels: Vec<Level<V>> = members
            .into_iter()
            .filter(|m| !m.is_empty())
            .map(|m| Level::build(m, positions, &radius, fraction))
            .collect::<Result<_, _>>()?;
        self.stats = levels.iter().map(Level::stats).collect();

        // Gather: each chunk of rows is searched by one task and kept as it is (no
        // concatenation into one array, which would hold the indices twice at the peak),
        // with the pairs it found for the other side only.
        let gathered: Vec<Gathered> = (0..n.div_ceil(CHUNK))
            .into_par_iter()
            .map(|c| {
                let range = c * CHUNK..((c + 1) * CHUNK).min(n);
                let mut chunk = Chunk::with_rows(range.start, range.len());
                // The row being gathered: its first `found` entries (the rest is room the
                // queries write into without growing it).
                let mut row: Vec<u32> = Vec::new();
                let mut one_sided: Vec<(u32, u32)> = Vec::new();
                let mut sided = 0;
                let mut candidates = vec![0u64; levels.len()];
                for i in range {
                    let mut found = 0;
                    let own = rows.contains(&i);
                    if own || (!whole && outside[i] == Outside::Reaches) {
                        let before = sided;
                        for (level, tested) in levels.iter().zip(&mut candidates) {
                            let start = found;
                            *tested += level.query(
                                i,
                                positions[i],
                                radius[i],
                                criterion,
                                (&mut row, &mut found),
                                (&mut one_sided, &mut sided),
                            );
                            if C::RADIUS_IS_EXACT
                                && let Some(k) =
                                    row[start..found].iter().position(|&j| j as usize == i)
                            {
                                // i found itself in its own level: not a candidate.
                                row.copy_within(start + k + 1..found, start + k);
                                found -= 1;
                                *tested -= 1;
                            }
                        }
                        if !whole {
                            // Only the rows searched for are kept.
                            let mut k = before;
                            for m in before..sided {
                                if rows.contains(&(one_sided[m].0 as usize)) {
                                    one_sided[k] = one_sided[m];
                                    k += 1;
                                }
                            }
                            sided = k;
                        }
                    }
                    let row = &mut row[..if own { found } else { 0 }];
                    row.sort_unstable();
                    chunk.push_row(row);
                }
                one_sided.truncate(sided);
                Gathered {
                    chunk: chunk.finish(),
                    one_sided,
                    candidates,
                }
            })
            .collect();
        for g in &gathered {
            for (stats, tested) in self.stats.iter_mut().zip(&g.candidates) {
                stats.candidates += tested;
            }
        }
        self.candidates = self.stats.iter().map(|s| s.candidates).sum();
        Ok(NeighborList::from_chunks(transpose_one_sided(gathered, n)))
    }
}

/// Where a particle outside the rows of a partial search stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Outside {
    /// It pairs with no row.
    Away,
    /// A row may reach it: it is gridded.
    Halo,
    /// Its own radius may reach a row: it is gridded and gathers.
    Reaches,
}

/// What one chunk's gather produced.
struct Gathered {
    chunk: Chunk,
    /// (j, i): j is i's neighbour at |r_ij| ≥ r_j, so j's own gather missed i.
    one_sided: Vec<(u32, u32)>,
    /// Candidates tested, per level.
    candidates: Vec<u64>,
}

/// Merges the one-sided pairs into the rows of the side that missed them. The pairs are
/// bucketed by row with a stable counting sort over the chunks in order, so each bucket
/// ascends and the result does not depend on the thread count.
fn transpose_one_sided(gathered: Vec<Gathered>, n: usize) -> Vec<Chunk> {
    let mut start = vec![0usize; n + 1];
    for g in &gathered {
        for &(j, _) in &g.one_sided {
            start[j as usize + 1] += 1;
        }
    }
    if start.iter().all(|&c| c == 0) {
        return gathered.into_iter().map(|g| g.chunk).collect();
    }
    for k in 0..n {
        start[k + 1] += start[k];
    }
    let mut fill = start.clone();
    let mut extra = vec![0u32; start[n]];
    let mut chunks = Vec::with_capacity(gathered.len());
    for g in gathered {
        for &(j, i) in &g.one_sided {
            extra[fill[j as usize]] = i;
            fill[j as usize] += 1;
        }
        chunks.push(g.chunk);
    }
    drop(fill);
    chunks
        .into_par_iter()
        .map(|chunk| {
            let first = chunk.first_row();
            let rows = chunk.rows();
            if start[first] == start[first + rows] {
                return chunk;
            }
            let mut merged = Chunk::with_rows(first, rows);
            let mut row = Vec::new();
            for k in 0..rows {
                let i = first + k;
                let more = &extra[start[i]..start[i + 1]];
                if more.is_empty() {
                    // Most rows have nothing to add: their bytes are copied as they are.
                    merged.push_row_of(&chunk, k);
                    continue;
                }
                // Both ascend and are disjoint (a one-sided pair is not in the row that
                // missed it): merge them.
                row.clear();
                let mut rest = more.iter().copied().peekable();
                for j in chunk.row(k) {
                    while let Some(m) = rest.next_if(|&m| m < j) {
                        row.push(m);
                    }
                    row.push(j);
                }
                row.extend(rest);
                merged.push_row(&row);
            }
            merged.finish()
        })
        .collect()
}

/// How a level finds the particles of a row of cells.
enum Lookup {
    /// `cell_start[c]..cell_start[c + 1]` are the slots of linear cell c.
    Dense(Vec<u32>),
    /// Per slot, the cell key (z, y, x), sorted; rows found by bisection.
    Sparse(Vec<[i64; 3]>),
}

/// One grid level: its particles sorted by cell, with copies of their positions.
struct Level<V> {
    cell: f64,
    inv_cell: f64,
    origin: V,
    dims: [i64; 3],
    index: Vec<u32>,
    pos: Vec<V>,
    /// Search radius per slot.
    rad: Vec<f64>,
    lookup: Lookup,
}

impl<V: Vector> Level<V> {
    fn build(
        members: Vec<u32>,
        positions: &[V],
        radius: &[f64],
        fraction: f64,
    ) -> Result<Self, CoreError> {
        let cell = fraction
            * members
                .iter()
                .map(|&i| radius[i as usize])
                .fold(0.0, f64::max);
        let inv_cell = 1.0 / cell;
        let mut lo = V::splat(f64::INFINITY);
        let mut hi = V::splat(f64::NEG_INFINITY);
        for &i in &members {
            lo = lo.component_min(positions[i as usize]);
            hi = hi.component_max(positions[i as usize]);
        }
        let mut dims = [1i64; 3];
        let mut ncells = 1.0f64;
        for k in 0..V::DIM {
            let extent = (hi.component(k) - lo.component(k)) * inv_cell;
            if !(extent <= MAX_CELL_COORD) {
                return Err(CoreError::DomainTooLarge {
                    extent: hi.component(k) - lo.component(k),
                    cell,
                });
            }
            dims[k] = extent.floor() as i64 + 1;
            ncells *= dims[k] as f64;
        }
        let coords = |p: V| -> [i64; 3] {
            let mut c = [0i64; 3];
            for k in 0..V::DIM {
                c[k] = (((p.component(k) - lo.component(k)) * inv_cell).floor() as i64)
                    .clamp(0, dims[k] - 1);
            }
            c
        };
        let dense = ncells <= (4 * members.len() + 64) as f64;
        let (index, lookup) = if dense {
            let nc = ncells as usize;
            let lin: Vec<usize> = members
                .iter()
                .map(|&i| {
                    let c = coords(positions[i as usize]);
                    ((c[2] * dims[1] + c[1]) * dims[0] + c[0]) as usize
                })
                .collect();
            // Counting sort by cell; stable, so slots within a cell ascend by index.
            let mut start = vec![0u32; nc + 1];
            for &l in &lin {
                start[l + 1] += 1;
            }
            for c in 0..nc {
                start[c + 1] += start[c];
            }
            let mut fill = start.clone();
            let mut index = vec![0u32; members.len()];
            for (&i, &l) in members.iter().zip(&lin) {
                index[fill[l] as usize] = i;
                fill[l] += 1;
            }
            (index, Lookup::Dense(start))
        } else {
            let mut keyed: Vec<([i64; 3], u32)> = members
                .iter()
                .map(|&i| {
                    let c = coords(positions[i as usize]);
                    ([c[2], c[1], c[0]], i)
                })
                .collect();
            keyed.sort_unstable();
            let index = keyed.iter().map(|k| k.1).collect();
            (
                index,
                Lookup::Sparse(keyed.into_iter().map(|k| k.0).collect()),
            )
        };
        let pos = index.iter().map(|&i| positions[i as usize]).collect();
        let rad = index.iter().map(|&i| radius[i as usize]).collect();
        Ok(Self {
            cell,
            inv_cell,
            origin: lo,
            dims,
            index,
            pos,
            rad,
            lookup,
        })
    }

    fn stats(&self) -> LevelStats {
        LevelStats {
            cell_size: self.cell,
            particles: self.index.len(),
            cells: self.dims.iter().map(|&d| d as f64).product(),
            dense: matches!(self.lookup, Lookup::Dense(_)),
            candidates: 0,
        }
    }

    /// Slots of the cells (x0..=x1, y, z).
    #[inline]
    fn row(&self, z: i64, y: i64, x0: i64, x1: i64) -> Range<usize> {
        match &self.lookup {
            Lookup::Dense(start) => {
                let base = (z * self.dims[1] + y) * self.dims[0];
                start[(base + x0) as usize] as usize..start[(base + x1 + 1) as usize] as usize
            }
            Lookup::Sparse(keys) => {
                let a = keys.partition_point(|k| *k < [z, y, x0]);
                let b = a + keys[a..].partition_point(|k| *k <= [z, y, x1]);
                a..b
            }
        }
    }

    /// Writes the neighbours j of particle i in this level with |r_ij| < r_i into `out`
    /// = (buffer, count), after the `count` entries there (growing the buffer when it
    /// lacks room), and appends to `one_sided` those with |r_ij| ≥ r_j as (j, i); returns
    /// the candidates tested (`one_sided` too is a buffer and a count). With an
    /// exact-radius criterion i itself is among them (at
    /// distance 0) when it is in this level: the caller takes it out.
    #[inline]
    fn query<C: PairCriterion<V>>(
        &self,
        i: usize,
        xi: V,
        ri: f64,
        crit: &C,
        out: (&mut Vec<u32>, &mut usize),
        one_sided: (&mut Vec<(u32, u32)>, &mut usize),
    ) -> u64 {
        let (buffer, count) = out;
        let mut lo = [0i64; 3];
        let mut hi = [0i64; 3];
        for k in 0..V::DIM {
            let x = xi.component(k) - self.origin.component(k);
            // A margin of 1e-6 cell guards the floor against round-off at cell faces.
            let a = (((x - ri) * self.inv_cell - 1e-6).floor()).max(0.0);
            let b = (((x + ri) * self.inv_cell + 1e-6).floor()).min((self.dims[k] - 1) as f64);
            if a > b {
                return 0;
            }
            lo[k] = a as i64;
            hi[k] = b as i64;
        }
        let r2 = ri * ri;
        // Counted a row of cells at a time, off the inner loop.
        let mut tested = 0u64;
        for z in lo[2]..=hi[2] {
            for y in lo[1]..=hi[1] {
                let slots = self.row(z, y, lo[0], hi[0]);
                tested += slots.len() as u64;
                if buffer.len() < *count + slots.len() {
                    buffer.resize(*count + slots.len() + 256, 0);
                }
                let index = &self.index[slots.clone()];
                let pos = &self.pos[slots.clone()];
                let rad = &self.rad[slots];
                if !C::RADIUS_IS_EXACT {
                    for ((&j, &xj), &rj) in index.iter().zip(pos).zip(rad) {
                        if j as usize == i {
                            tested -= 1;
                            continue;
                        }
                        let d = xi - xj;
                        let d2 = d.norm_squared();
                        if d2 < r2 && crit.accepts(i, j as usize, d) {
                            buffer[*count] = j;
                            *count += 1;
                            // j's gather tests the same d² (negation is exact) against r_j².
                            if d2 >= rj * rj {
                                let (pairs, sided) = (&mut *one_sided.0, &mut *one_sided.1);
                                pairs.truncate(*sided);
                                pairs.push((j, i as u32));
                                *sided += 1;
                            }
                        }
                    }
                    continue;
                }
                // An exact-radius criterion: |r| < r_i ≤ max(r_i, r_j) decides. Each
                // candidate is written at the row's next free place, which moves on only
                // if it is accepted: about four in five fail, in no order a branch
                // predictor learns, and a branch per candidate cost more than the test.
                let (pairs, sided) = (&mut *one_sided.0, &mut *one_sided.1);
                if pairs.len() < *sided + index.len() {
                    pairs.resize(*sided + index.len() + 256, (0, 0));
                }
                let room = &mut buffer[*count..*count + index.len()];
                let other_room = &mut pairs[*sided..*sided + index.len()];
                let (mut next, mut other) = (0, 0);
                for ((&j, &xj), &rj) in index.iter().zip(pos).zip(rad) {
                    let d2 = (xi - xj).norm_squared();
                    let accept = usize::from(d2 < r2);
                    room[next] = j;
                    next += accept;
                    // j's gather tests the same d² (negation is exact) against r_j²
                    // (never i itself: 0 < r_i²); the same write without a branch.
                    other_room[other] = (j, i as u32);
                    other += accept & usize::from(d2 >= rj * rj);
                }
                *count += next;
                *sided += other;
            }
        }
        tested
    }
}

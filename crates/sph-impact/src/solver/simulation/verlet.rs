//! A Verlet list (`NeighbourSearch::Verlet`): the neighbour list of a search with every
//! support enlarged by the skin, kept from stage to stage while it still holds every pair
//! a search of the present state would find.
//!
//! The search lists the pairs with |r_ij| < max(R_i, R_j), R = (1 + s) h at the build,
//! and the ghosts of the particles within R of a boundary. A stage needs the pairs with
//! |r_ij| < max(h_i, h_j) at its own positions and supports, between the ghosts a
//! placement with those would make. Since the build particle i has moved by the vector
//! Δ_i (a ghost by its map of its source's), so |r_ij(build)| ≤ |r_ij| + |Δ_i − Δ_j|;
//! with h_i ≥ h_j, a pair needed now was listed if h_i + |Δ_i − Δ_j| ≤ R_i. What matters
//! is how far two neighbours moved *relative to each other*: a body in flight, moving
//! as one, keeps its list. The list therefore holds while every particle has
//!
//! ```text
//! h_i + max_{j : |r_ij| < h_i} |Δ_i − Δ_j| ≤ R_i
//! ```
//!
//! and every ghost a placement would make now was placed at the build. The maximum is
//! bounded two ways, and the smaller bound taken: by |Δ_i| + max_j |Δ_j| over every
//! particle (cheap, and the whole test while no particle has moved far), and by the
//! farthest corner, from Δ_i, of the box of the displacements in the cells of side
//! max h around i's (its neighbours now lie in those cells). A ghost is placed where its
//! particle lies within its support of the boundary; that distance changes by at most
//! the displacement's part normal to the boundary, so a ghost made now was placed at the
//! build if h_i + |Δ_i · n| ≤ R_i for each particle a placement makes a ghost of now.
//!
//! Each test is applied with a margin of 10⁻⁹ of the reach, far beyond the rounding of
//! the distances it bounds. Each stage then picks from the list the pairs a search of its
//! present supports would list, between live particles (`Extended::pair_probe`; one bit
//! per listed pair, set by pass 1 as it reads each row in one process, else by
//! `NeighborList::select_pairs`; simulation/stage.rs), each row in its order, so the
//! passes sum the same terms in the same order as after a search of the stage's own:
//! when the list is rebuilt does not change the results, only how many searches they
//! take.

use super::*;

/// What a Verlet list was built from: enough to tell whether it still holds.
pub(super) struct SkinBuild<D: Dimension> {
    /// The skin s the reach was made with.
    skin: f64,
    /// The particles listed, by id, in their order then.
    ids: Vec<u64>,
    /// Their positions at the build.
    position: Vec<D::Vector>,
    /// Their reach R_i = (1 + s) h_i at the build.
    reach: Vec<f64>,
    /// The boundaries whose ghosts were placed.
    boundaries: Vec<Boundary<D>>,
}

/// Relative margin of the holding test: the distances it bounds are rounded to a few
/// units in 10⁻¹⁶ of the positions.
const MARGIN: f64 = 1e-9;

impl<D: Dimension> SkinBuild<D> {
    /// The build of a list searched with skin `skin` over the particles `ids`, at
    /// `position` with the supports `h` (their smoothing lengths).
    pub(super) fn new(
        skin: f64,
        ids: &[u64],
        (position, h): (&[D::Vector], &[f64]),
        boundaries: &[Boundary<D>],
    ) -> Self {
        SkinBuild {
            skin,
            ids: ids.to_vec(),
            position: position.to_vec(),
            reach: reach(h, skin),
            boundaries: boundaries.to_vec(),
        }
    }

    /// Whether the list still holds every pair of `state` (with skin `skin` now asked
    /// for, these boundaries and `plan`, the ghosts placed at the build): the same
    /// particles in the same order, and the tests of the module docs.
    pub(super) fn holds(
        &self,
        skin: f64,
        state: &State<D>,
        boundaries: &[Boundary<D>],
        plan: &[PlacedGhost<D>],
    ) -> bool {
        let p = &state.particles;
        if skin != self.skin || boundaries != self.boundaries.as_slice() || p.id != self.ids {
            return false;
        }
        // The displacements' lengths at every stage; the vectors only for the sharper
        // test, when the first bound fails.
        let displacement = || {
            p.position
                .par_iter()
                .zip(&self.position)
                .map(|(&x, &x0)| x - x0)
        };
        let distance: Vec<f64> = displacement().map(|d| d.norm()).collect();
        // The largest displacement; a NaN one stops the list (the next search reports it).
        // The same in any order (the largest, or a NaN if any), so reduced in parallel.
        let keep = |m: f64, d: f64| if d > m || d.is_nan() { d } else { m };
        let largest = distance
            .par_iter()
            .with_min_len(1024)
            .copied()
            .reduce(|| 0.0, keep);
        if !largest.is_finite() {
            return false;
        }
        let h = &p.smoothing_length;
        let fits = |k: usize, spread: f64| (h[k] + spread) * (1.0 + MARGIN) <= self.reach[k];
        if (0..distance.len())
            .into_par_iter()
            .all(|i| fits(i, distance[i] + largest))
        {
            return true;
        }
        drop(distance);
        Moved::new(state, &self.reach, displacement().collect(), plan).holds(largest, boundaries)
    }
}

/// Every particle a kept list's indices count (the real ones, then the build's ghosts
/// placed from their sources' present positions), with its displacement since the build:
/// the sharper test of the module docs.
struct Moved<'a, D: Dimension> {
    n_real: usize,
    position: &'a [D::Vector],
    /// Present supports and reaches at the build, of the real particles.
    h: &'a [f64],
    reach: &'a [f64],
    /// Displacements of the real particles, then of the ghosts.
    moved: Vec<D::Vector>,
    /// The ghosts' present positions, and the real particle each copies.
    ghost_position: Vec<D::Vector>,
    ghost_root: Vec<usize>,
    /// For each ghost, the boundary that made it.
    ghost_boundary: Vec<usize>,
}

impl<'a, D: Dimension> Moved<'a, D> {
    fn new(
        state: &'a State<D>,
        reach: &'a [f64],
        mut moved: Vec<D::Vector>,
        plan: &[PlacedGhost<D>],
    ) -> Self {
        let p = &state.particles;
        let n_real = p.position.len();
        let mut ghost_position: Vec<D::Vector> = Vec::with_capacity(plan.len());
        let mut ghost_root = Vec::with_capacity(plan.len());
        for g in plan {
            // A ghost's source is a real particle or an earlier ghost (a corner's ghost of a
            // ghost): both are placed by now.
            let s = g.ghost.source;
            let (x, root) = match s.checked_sub(n_real) {
                None => (p.position[s], s),
                Some(k) => (ghost_position[k], ghost_root[k]),
            };
            ghost_position.push(g.ghost.moved_to(x).position);
            ghost_root.push(root);
            moved.push(g.ghost.map.mul_vec(moved[s]));
        }
        Moved {
            n_real,
            position: &p.position,
            h: &p.smoothing_length,
            reach,
            moved,
            ghost_position,
            ghost_root,
            ghost_boundary: plan.iter().map(|g| g.boundary).collect(),
        }
    }

    /// Particle k's present position.
    fn position(&self, k: usize) -> D::Vector {
        match k.checked_sub(self.n_real) {
            None => self.position[k],
            Some(g) => self.ghost_position[g],
        }
    }

    /// The real particle whose support and reach particle k has.
    fn root(&self, k: usize) -> usize {
        match k.checked_sub(self.n_real) {
            None => k,
            Some(g) => self.ghost_root[g],
        }
    }

    /// Whether h_k + `spread` fits in particle k's reach.
    fn fits(&self, k: usize, spread: f64) -> bool {
        let r = self.root(k);
        (self.h[r] + spread) * (1.0 + MARGIN) <= self.reach[r]
    }

    /// The tests of the module docs, with `largest` the largest displacement.
    fn holds(&self, largest: f64, boundaries: &[Boundary<D>]) -> bool {
        self.ghosts_were_placed(boundaries) && self.pairs_were_listed(largest)
    }

    /// Every ghost a placement from the present positions and supports makes was placed
    /// at the build: each boundary's placement reads the real particles and the earlier
    /// boundaries' ghosts.
    fn ghosts_were_placed(&self, boundaries: &[Boundary<D>]) -> bool {
        boundaries.iter().enumerate().all(|(b, boundary)| {
            let read = self.n_real + self.ghost_boundary.iter().take_while(|&&g| g < b).count();
            (0..read).into_par_iter().all(|k| {
                let x = self.position(k);
                boundary.ghost_of(k, x, self.h[self.root(k)]).is_none()
                    || self.fits(k, boundary.normal_part(self.moved[k]))
            })
        })
    }

    /// Every pair with |r_ij| < max(h_i, h_j) now was within max(R_i, R_j) at the build.
    fn pairs_were_listed(&self, largest: f64) -> bool {
        let n = self.moved.len();
        // Cells a little larger than every support: i's neighbours lie in i's cell and
        // the cells around it, whatever the rounding of the positions.
        let side = self
            .h
            .par_iter()
            .with_min_len(1024)
            .copied()
            .reduce(|| 0.0, f64::max)
            * (1.0 + 1e-6);
        if !(side > 0.0 && side.is_finite()) {
            return false;
        }
        let (lo, hi) = (0..n)
            .into_par_iter()
            .map(|k| (self.position(k), self.position(k)))
            .reduce(
                || {
                    (
                        D::Vector::splat(f64::INFINITY),
                        D::Vector::splat(f64::NEG_INFINITY),
                    )
                },
                |a, b| (a.0.component_min(b.0), a.1.component_max(b.1)),
            );
        let mut dims = [1usize; 3];
        for (a, dim) in dims.iter_mut().enumerate().take(D::DIM) {
            let extent = ((hi.component(a) - lo.component(a)) / side).floor();
            if !(extent < 1e9) {
                return false;
            }
            *dim = extent as usize + 1;
        }
        let mut cells = Cells::new(dims, n);
        let key = |x: D::Vector| -> [usize; 3] {
            let mut c = [0; 3];
            for (a, c) in c.iter_mut().enumerate().take(D::DIM) {
                let f = ((x.component(a) - lo.component(a)) / side).floor();
                *c = (f.max(0.0) as usize).min(dims[a] - 1);
            }
            c
        };
        let keys: Vec<[usize; 3]> = (0..n)
            .into_par_iter()
            .map(|k| key(self.position(k)))
            .collect();
        // Each occupied cell's box of displacements (lowest and highest of each
        // component), in the order the cells were first met.
        let mut boxes: Vec<(D::Vector, D::Vector)> = Vec::new();
        let mut occupied: Vec<[usize; 3]> = Vec::new();
        let cell: Vec<u32> = keys
            .iter()
            .zip(&self.moved)
            .map(|(key, &d)| match cells.get(key) {
                Some(c) => {
                    let b = &mut boxes[c as usize];
                    *b = (b.0.component_min(d), b.1.component_max(d));
                    c
                }
                None => {
                    let c = boxes.len() as u32;
                    boxes.push((d, d));
                    occupied.push(*key);
                    cells.set(key, c);
                    c
                }
            })
            .collect();
        drop(keys);
        // The box of the displacements in each cell and the cells around it.
        let around: Vec<(D::Vector, D::Vector)> = occupied
            .par_iter()
            .zip(&boxes)
            .map(|(key, &own)| {
                let mut b = own;
                for offset in neighbour_offsets(D::DIM) {
                    let k = [0, 1, 2].map(|a| key[a] as i64 + offset[a]);
                    if k.iter().zip(&dims).any(|(&k, &d)| k < 0 || k >= d as i64) {
                        continue;
                    }
                    if let Some(o) = cells.get(&k.map(|k| k as usize)) {
                        let other = boxes[o as usize];
                        b = (b.0.component_min(other.0), b.1.component_max(other.1));
                    }
                }
                b
            })
            .collect();
        (0..n).into_par_iter().all(|k| {
            let d = self.moved[k];
            let (lo, hi) = around[cell[k] as usize];
            let corner = (0..D::DIM)
                .map(|a| {
                    let c = d.component(a);
                    (c - lo.component(a)).max(hi.component(a) - c).powi(2)
                })
                .sum::<f64>()
                .sqrt();
            self.fits(k, corner.min(d.norm() + largest))
        })
    }
}

/// The occupied cells of a grid, each with its number: a table over the grid's box where
/// that is no more than a few entries per particle, a map of the occupied ones otherwise
/// (particles far outside the bulk).
enum Cells {
    Dense { dims: [usize; 3], number: Vec<u32> },
    Sparse(std::collections::HashMap<[usize; 3], u32>),
}

impl Cells {
    /// No cell numbered yet; `dims` cells along each axis, for `n` particles.
    fn new(dims: [usize; 3], n: usize) -> Self {
        let total = dims.iter().try_fold(1usize, |t, &d| t.checked_mul(d));
        match total {
            Some(t) if t <= 4 * n + 64 => Cells::Dense {
                dims,
                number: vec![u32::MAX; t],
            },
            _ => Cells::Sparse(std::collections::HashMap::new()),
        }
    }

    fn get(&self, key: &[usize; 3]) -> Option<u32> {
        match self {
            Cells::Dense { dims, number } => {
                let c = number[(key[2] * dims[1] + key[1]) * dims[0] + key[0]];
                (c != u32::MAX).then_some(c)
            }
            Cells::Sparse(map) => map.get(key).copied(),
        }
    }

    fn set(&mut self, key: &[usize; 3], c: u32) {
        match self {
            Cells::Dense { dims, number } => {
                number[(key[2] * dims[1] + key[1]) * dims[0] + key[0]] = c
            }
            Cells::Sparse(map) => {
                map.insert(*key, c);
            }
        }
    }
}

/// The offsets of a cell's neighbours and itself, in `dim` dimensions (the others 0).
fn neighbour_offsets(dim: usize) -> impl Iterator<Item = [i64; 3]> {
    let span = move |a: usize| if a < dim { -1..=1 } else { 0..=0 };
    span(0).flat_map(move |x| span(1).flat_map(move |y| span(2).map(move |z| [x, y, z])))
}

/// The reach (1 + s) h of each support h: the search radius of a Verlet list.
pub(super) fn reach(support: &[f64], skin: f64) -> Vec<f64> {
    support.par_iter().map(|&h| h * (1.0 + skin)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use sph_core::Dim2;
    use sph_core::glam::DVec2;

    /// The build of a list searched with skin `skin` over `s`'s particles.
    fn build_of(skin: f64, s: &State<Dim2>, walls: &[Boundary<Dim2>]) -> SkinBuild<Dim2> {
        let p = &s.particles;
        SkinBuild::new(skin, &p.id, (&p.position, &p.smoothing_length), walls)
    }

    fn state(x: &[[f64; 2]], h: f64) -> State<Dim2> {
        let mut s = State::<Dim2>::default();
        let p = &mut s.particles;
        for (k, &[a, b]) in x.iter().enumerate() {
            p.id.push(k as u64);
            p.position.push(DVec2::new(a, b));
            p.smoothing_length.push(h);
        }
        s
    }

    /// The ghosts a Verlet search of `s` with skin `skin` places (what the kept list's
    /// indices count after the real particles).
    fn plan(s: &State<Dim2>, skin: f64, walls: &[Boundary<Dim2>]) -> Vec<PlacedGhost<Dim2>> {
        let reach = reach(&s.particles.smoothing_length, skin);
        crate::solver::state::skin_plan(&s.particles.position, &reach, walls)
    }

    /// Moves every particle of `s` by `d`.
    fn shifted(s: &State<Dim2>, d: DVec2) -> State<Dim2> {
        let mut s = s.clone();
        s.particles.position.iter_mut().for_each(|x| *x += d);
        s
    }

    /// The list holds while the neighbours' displacements relative to each other fit in
    /// the skin, and not for other particles, another skin or other boundaries.
    #[test]
    fn a_list_holds_while_the_relative_displacements_fit_in_the_skin() {
        let s0 = state(&[[0.0, 0.0], [1.0, 0.0]], 1.0);
        let walls = [Boundary::<Dim2>::axis()];
        let build = build_of(0.2, &s0, &walls);
        let ghosts = plan(&s0, 0.2, &walls);
        let holds = |s: &State<Dim2>| build.holds(0.2, s, &walls, &ghosts);
        assert!(holds(&s0));
        // Each moves 0.09: 1 + 0.09 + 0.09 ≤ 1.2 (the first bound).
        let mut s = s0.clone();
        s.particles.position[0].x += 0.09;
        s.particles.position[1].y -= 0.09;
        assert!(holds(&s));
        // Away from the wall (no ghosts), one moves 0.11 from the other: 1 + 0.11 ≤ 1.2
        // by the displacements' boxes; 0.21: 1 + 0.21 > 1.2.
        let far = state(&[[3.0, 0.0], [4.0, 0.0]], 1.0);
        let far_build = build_of(0.2, &far, &walls);
        let far_ghosts = plan(&far, 0.2, &walls);
        assert!(far_ghosts.is_empty());
        let mut s = far.clone();
        s.particles.position[1].x += 0.11;
        assert!(far_build.holds(0.2, &s, &walls, &far_ghosts));
        s.particles.position[1].x += 0.1;
        assert!(!far_build.holds(0.2, &s, &walls, &far_ghosts));
        // Both along the wall by 0.5 together: nothing moved relative to anything.
        assert!(holds(&shifted(&s0, DVec2::new(0.0, 0.5))));
        // Both away from the wall by 0.5: the first particle's ghost, made now (it is
        // within its support of the wall), was not placed at the build.
        assert!(!holds(&shifted(&s0, DVec2::new(0.5, 0.0))));
        // A support grown by 0.2 uses the whole skin.
        let mut s = s0.clone();
        s.particles.smoothing_length[0] = 1.2;
        assert!(!holds(&s));
        s.particles.smoothing_length[0] = 1.1;
        assert!(holds(&s));
        assert!(!build.holds(0.3, &s0, &walls, &ghosts));
        assert!(!build.holds(0.2, &s0, &[], &ghosts));
        let mut s = s0.clone();
        s.particles.id.swap(0, 1);
        assert!(!holds(&s));
        let mut s = s0.clone();
        s.particles.position[0].x = f64::NAN;
        assert!(!holds(&s));
    }

    /// Far-apart bodies moving apart or together: the test looks at each particle's
    /// neighbourhood, and a body in flight keeps its list.
    #[test]
    fn a_body_in_flight_keeps_its_list() {
        // Two rows of 64 particles 10 supports apart, one after the other in the
        // particles' order; the second flies at the first.
        let x: Vec<[f64; 2]> = [0.0, 10.0]
            .iter()
            .flat_map(|&y| (0..64).map(move |k| [0.5 * k as f64, y]))
            .collect();
        let s0 = state(&x, 1.0);
        let build = build_of(0.1, &s0, &[]);
        let mut s = s0.clone();
        s.particles.position[64..]
            .iter_mut()
            .for_each(|x| x.y -= 3.0);
        assert!(build.holds(0.1, &s, &[], &[]));
        // Within reach of the first row now: the pairs between the rows were not listed.
        s.particles.position[64..]
            .iter_mut()
            .for_each(|x| x.y -= 6.5);
        assert!(!build.holds(0.1, &s, &[], &[]));
    }

    proptest! {
        #![proptest_config(ProptestConfig { max_global_rejects: 8192, ..ProptestConfig::default() })]
        /// Whenever the test says the list holds, every pair of a real particle with a
        /// particle or a ghost that a search of the present state lists was within the
        /// reach at the build, and every ghost a placement makes now was placed then:
        /// checked against all pairs by brute force, with a wall and a periodic pair of
        /// faces (whose corner makes ghosts of ghosts).
        #[test]
        fn a_list_that_holds_has_every_present_pair(
            x in proptest::collection::vec((0.0..4.0f64, -0.5..4.5f64, 0.6..1.0f64), 2..24),
            drift in (-1.0..1.0f64, -1.0..1.0f64),
            moves in proptest::collection::vec((-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64), 24),
            skin in 0.05..0.5f64,
        ) {
            let mut s0 = State::<Dim2>::default();
            for (k, &(a, b, h)) in x.iter().enumerate() {
                s0.particles.id.push(k as u64);
                s0.particles.position.push(DVec2::new(a, b));
                s0.particles.smoothing_length.push(h);
            }
            let walls = [
                Boundary::<Dim2>::axis(),
                Boundary::<Dim2>::Periodic { axis: 1, lo: -1.0, hi: 5.0 },
            ];
            let build = build_of(skin, &s0, &walls);
            let ghosts = plan(&s0, skin, &walls);
            // Moves of the order of the skin: some lists hold, some do not.
            let mut s = s0.clone();
            let p = &mut s.particles;
            for (k, (x, h)) in p.position.iter_mut().zip(&mut p.smoothing_length).enumerate() {
                let (dx, dy, dh) = moves[k];
                *x += DVec2::new(drift.0 + dx * 0.4, drift.1 + dy * 0.4) * skin;
                *h *= 1.0 + 0.4 * skin * dh;
            }
            prop_assume!(build.holds(skin, &s, &walls, &ghosts));
            // Every particle of the present state, the ghosts a placement with the
            // present supports makes included: where it is now and was at the build, and
            // the real particle it copies.
            let n = x.len();
            let now = plan(&s, 0.0, &walls);
            let (mut x_now, mut x_then) = (s.particles.position.clone(), s0.particles.position.clone());
            let mut root: Vec<usize> = (0..n).collect();
            for g in &now {
                let k = g.ghost.source;
                x_now.push(g.ghost.position);
                x_then.push(g.ghost.moved_to(x_then[k]).position);
                root.push(root[k]);
            }
            let h = |k: usize| s.particles.smoothing_length[root[k]];
            let r = |k: usize| build.reach[root[k]];
            for g in &now {
                let k = g.ghost.source;
                let mut made = Vec::new();
                walls[g.boundary].ghosts_within(k, x_then[k], r(k), &mut made);
                prop_assert!(made.iter().any(|m| m.offset == g.ghost.offset), "a ghost of {k} not placed");
            }
            for a in 0..n {
                for b in (0..x_now.len()).filter(|&b| b != a) {
                    if (x_now[a] - x_now[b]).length() < h(a).max(h(b)) {
                        prop_assert!(
                            (x_then[a] - x_then[b]).length() < r(a).max(r(b)),
                            "pair ({a}, {b}) not listed"
                        );
                    }
                }
            }
        }
    }
}

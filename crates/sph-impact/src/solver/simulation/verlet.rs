//! A Verlet list (`NeighbourSearch::Verlet`): the neighbour list of a search with every
//! support enlarged by the skin, kept from stage to stage while it still holds every pair
//! a search of the present state would find.
//!
//! The search lists the pairs with |r_ij| < max(R_i, R_j), R = (1 + s) h at the build,
//! and the ghosts of the particles within R of a boundary. A stage needs the pairs with
//! |r_ij| < max(h_i, h_j) at its own positions and supports. Since the build each
//! particle has moved by d_i, so |r_ij(build)| ≤ |r_ij| + d_i + d_j; with h_i ≥ h_j,
//! a pair needed now was listed if h_i + d_i + d_j ≤ R_i. The list therefore holds while
//! every particle has
//!
//! ```text
//! h_i + d_i + max_j d_j ≤ R_i
//! ```
//!
//! A ghost moves with its source (an orthogonal map and a fixed offset keep distances),
//! and a particle's distance to a boundary changes by at most its displacement, so the
//! same test covers the pairs with ghosts and the ghosts a placement would make now. The
//! test is applied with a margin of 10⁻⁹ of the reach, far beyond the rounding of the
//! distances it bounds. Each stage then picks from the list the pairs a search of its
//! present supports would list, between live particles (`Extended::pair_probe`,
//! `NeighborList::retain_pairs`), each row in its order, so the passes sum the same terms
//! in the same order as after a search of the stage's own.

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
    /// The build of a list searched with skin `skin` over `state`'s particles, whose
    /// present supports are their smoothing lengths.
    pub(super) fn new(skin: f64, state: &State<D>, boundaries: &[Boundary<D>]) -> Self {
        let p = &state.particles;
        SkinBuild {
            skin,
            ids: p.id.clone(),
            position: p.position.clone(),
            reach: reach(&p.smoothing_length, skin),
            boundaries: boundaries.to_vec(),
        }
    }

    /// Whether the list still holds every pair of `state` (with skin `skin` now asked
    /// for and these boundaries): the same particles in the same order, and the test of
    /// the module docs for each.
    pub(super) fn holds(&self, skin: f64, state: &State<D>, boundaries: &[Boundary<D>]) -> bool {
        let p = &state.particles;
        if skin != self.skin || boundaries != self.boundaries.as_slice() || p.id != self.ids {
            return false;
        }
        let moved: Vec<f64> = p
            .position
            .par_iter()
            .zip(&self.position)
            .map(|(&x, &x0)| (x - x0).norm())
            .collect();
        // The largest displacement; a NaN one stops the list (the next search reports it).
        let largest = moved
            .iter()
            .fold(0.0_f64, |m, &d| if d > m || d.is_nan() { d } else { m });
        if !largest.is_finite() {
            return false;
        }
        (0..moved.len())
            .into_par_iter()
            .all(|i| (p.smoothing_length[i] + moved[i] + largest) * (1.0 + MARGIN) <= self.reach[i])
    }
}

/// The reach (1 + s) h of each support h: the search radius of a Verlet list.
pub(super) fn reach(support: &[f64], skin: f64) -> Vec<f64> {
    support.par_iter().map(|&h| h * (1.0 + skin)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::Dim2;
    use sph_core::glam::DVec2;

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

    /// The list holds until h + d_i + max d reaches (1 + s) h, and not for other
    /// particles, another skin or other boundaries.
    #[test]
    fn a_list_holds_while_the_displacements_fit_in_the_skin() {
        let s0 = state(&[[0.0, 0.0], [1.0, 0.0]], 1.0);
        let walls = [Boundary::<Dim2>::axis()];
        let build = SkinBuild::new(0.2, &s0, &walls);
        assert!(build.holds(0.2, &s0, &walls));
        // Each moves 0.09: 1 + 0.09 + 0.09 ≤ 1.2.
        let mut s = s0.clone();
        s.particles.position[0].x += 0.09;
        s.particles.position[1].y -= 0.09;
        assert!(build.holds(0.2, &s, &walls));
        // One moves 0.11 alone: 1 + 0.11 + 0.11 > 1.2.
        let mut s = s0.clone();
        s.particles.position[1].x += 0.11;
        assert!(!build.holds(0.2, &s, &walls));
        // A support grown by 0.2 uses the whole skin.
        let mut s = s0.clone();
        s.particles.smoothing_length[0] = 1.2;
        assert!(!build.holds(0.2, &s, &walls));
        s.particles.smoothing_length[0] = 1.1;
        assert!(build.holds(0.2, &s, &walls));
        assert!(!build.holds(0.3, &s0, &walls));
        assert!(!build.holds(0.2, &s0, &[]));
        let mut s = s0.clone();
        s.particles.id.swap(0, 1);
        assert!(!build.holds(0.2, &s, &walls));
        let mut s = s0.clone();
        s.particles.position[0].x = f64::NAN;
        assert!(!build.holds(0.2, &s, &walls));
    }
}

//! Boundaries as ghost particles: before each derivative evaluation, every particle
//! within its support radius of a boundary gets a ghost copy (mirrored across a
//! reflecting wall, shifted by the period for a periodic pair of faces). Ghosts take
//! part in the pair sums of real particles only. A free surface needs nothing.
//!
//! A [`Boundary::Wall`] is a mirror: its ghosts pull as well as push, which is right for
//! a symmetry plane. A [`Boundary::Contact`] (an anvil) has the same ghosts but can only
//! push: where the total force of a particle's contact ghosts would pull it toward the
//! wall, they are all left out of its pair sums (no force, density or energy change), so
//! material in tension against the wall behaves as at a free surface and can lift off;
//! where it pushes they all act, as a mirror's. (Deciding pair by pair instead drops the
//! share of the push carried by pairs that a tension along the wall makes attractive.)
//! With mirror walls the Taylor bar's anvil held the rod's
//! foot at up to 0.86 GPa of mean axial tension 2–4 µs after impact and pulled the rod
//! toward it between 1 and 2 µs (docs/verification.md, Taylor bar).

use serde::{Deserialize, Serialize};
use sph_core::{Dimension, Tensor, Vector};

/// A boundary condition.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    bound = "",
    rename_all = "kebab-case",
    tag = "kind",
    deny_unknown_fields
)]
pub enum Boundary<D: Dimension> {
    /// A rigid, frictionless wall: the plane through `point` with unit `normal`
    /// pointing into the material. Ghosts mirror position and the normal velocity.
    Wall {
        /// A point on the wall.
        point: D::Vector,
        /// Unit normal into the material.
        normal: D::Vector,
    },
    /// A rigid, frictionless wall that pushes but cannot pull (unilateral contact: an
    /// anvil). Ghosts as for [`Boundary::Wall`]; they act on a particle while their total
    /// force on it pushes it away from the wall, and not at all otherwise (module docs).
    Contact {
        /// A point on the wall.
        point: D::Vector,
        /// Unit normal into the material.
        normal: D::Vector,
    },
    /// Periodic in `axis` between `lo` and `hi` (period hi − lo).
    Periodic {
        /// Axis index (0 = x).
        axis: usize,
        /// Lower face.
        lo: f64,
        /// Upper face.
        hi: f64,
    },
}

/// A ghost: which particle it copies and how (an affine map of position and a linear
/// map of vectors such as the velocity).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ghost<D: Dimension> {
    /// Index (in the extended arrays) of the particle copied.
    pub source: usize,
    pub position: D::Vector,
    /// Linear map applied to vectors (reflection or identity).
    pub map: D::Tensor,
    /// The position's affine part: `position = map · x_source + offset`, so that the
    /// same ghost can be placed again from its source's later position (a neighbour
    /// list kept for the step's second stage, `SchemeConfig::neighbour_search`).
    pub offset: D::Vector,
}

impl<D: Dimension> Ghost<D> {
    /// The same ghost of a source now at `x`.
    #[inline]
    pub fn moved_to(&self, x: D::Vector) -> Self {
        Ghost {
            position: self.map.mul_vec(x) + self.offset,
            ..*self
        }
    }
}

impl<D: Dimension> Boundary<D> {
    /// The RZ axis r = 0 as a mirror (ghosts with v_r and S_rz reversed); the solver adds
    /// it to every axisymmetric run.
    pub(crate) fn axis() -> Self {
        Boundary::Wall {
            point: D::Vector::ZERO,
            normal: D::Vector::unit(0),
        }
    }

    /// How far a displacement `d` moves a point towards or away from the boundary: |d · n|
    /// for a wall's normal n, |d_axis| for a periodic pair of faces. A particle's distance
    /// to the boundary, which decides its ghosts, changes by no more (a Verlet list's
    /// holding test, solver/simulation/verlet.rs).
    #[inline]
    pub(crate) fn normal_part(&self, d: D::Vector) -> f64 {
        match *self {
            Boundary::Wall { normal, .. } | Boundary::Contact { normal, .. } => d.dot(normal).abs(),
            Boundary::Periodic { axis, .. } => d.component(axis).abs(),
        }
    }

    /// True for a boundary that pushes but cannot pull ([`Boundary::Contact`]).
    #[inline]
    pub fn is_unilateral(&self) -> bool {
        matches!(self, Boundary::Contact { .. })
    }

    /// Checks the parameters; `Err` names the problem.
    pub fn validate(&self) -> Result<(), String> {
        match self {
            Boundary::Wall { point, normal } | Boundary::Contact { point, normal } => {
                if !point.all_finite() || !normal.all_finite() || (normal.norm() - 1.0).abs() > 1e-9
                {
                    return Err(format!(
                        "wall normal {:?} must be a finite unit vector",
                        normal.to_array3()
                    ));
                }
            }
            Boundary::Periodic { axis, lo, hi } => {
                if *axis >= D::DIM {
                    return Err(format!(
                        "periodic axis {axis} does not exist in {} dimensions",
                        D::DIM
                    ));
                }
                if !(hi > lo) || !lo.is_finite() || !hi.is_finite() {
                    return Err(format!(
                        "periodic interval [{lo}, {hi}] is empty or not finite"
                    ));
                }
            }
        }
        Ok(())
    }

    /// Ghosts of the particles `positions[k]` with support radius `radius[k]`.
    pub(crate) fn ghosts(&self, positions: &[D::Vector], radius: &[f64], out: &mut Vec<Ghost<D>>) {
        out.extend(
            positions
                .iter()
                .zip(radius)
                .enumerate()
                .filter_map(|(k, (&x, &r))| self.ghost_of(k, x, r)),
        );
    }

    /// Every ghost of particle `source` at `x` that some support radius up to `reach` can
    /// make, in the order [`Self::ghosts`] would: the one ghost of a wall, and for a
    /// periodic pair of faces the shifted copies by each face within `reach` (a radius
    /// up to `reach` makes one of them). A Verlet list places these (Ghosts::Skin in
    /// solver/state.rs).
    pub(crate) fn ghosts_within(
        &self,
        source: usize,
        x: D::Vector,
        reach: f64,
        out: &mut Vec<Ghost<D>>,
    ) {
        match *self {
            Boundary::Wall { .. } | Boundary::Contact { .. } => {
                out.extend(self.ghost_of(source, x, reach));
            }
            Boundary::Periodic { axis, lo, hi } => {
                let period = hi - lo;
                let c = x.component(axis);
                for (near, shift) in [(c - lo < reach, period), (hi - c < reach, -period)] {
                    if near {
                        let offset = D::Vector::unit(axis) * shift;
                        out.push(Ghost {
                            source,
                            position: x + offset,
                            map: D::Tensor::IDENTITY,
                            offset,
                        });
                    }
                }
            }
        }
    }

    /// The ghost of particle `source` at `x` with support radius `radius`, if it is
    /// within that radius of the boundary ([`Self::ghosts`] for one particle: a Verlet
    /// list asks it of each kept ghost's source, solver/simulation/stage.rs).
    #[inline]
    pub(crate) fn ghost_of(&self, source: usize, x: D::Vector, radius: f64) -> Option<Ghost<D>> {
        match *self {
            Boundary::Wall { point, normal } | Boundary::Contact { point, normal } => {
                // x − 2 n ((x − p)·n) = R x + 2 n (p·n).
                let d = (x - point).dot(normal);
                (d < radius).then(|| Ghost {
                    source,
                    position: x - normal * (2.0 * d),
                    map: D::Tensor::IDENTITY - D::Tensor::outer(normal, normal) * 2.0,
                    offset: normal * (2.0 * point.dot(normal)),
                })
            }
            Boundary::Periodic { axis, lo, hi } => {
                let period = hi - lo;
                let c = x.component(axis);
                let shift = if c - lo < radius {
                    period
                } else if hi - c < radius {
                    -period
                } else {
                    return None;
                };
                let offset = D::Vector::unit(axis) * shift;
                Some(Ghost {
                    source,
                    position: x + offset,
                    map: D::Tensor::IDENTITY,
                    offset,
                })
            }
        }
    }

    /// Brings a particle that left the domain back: wraps across periodic faces, mirrors
    /// back through a wall. Returns true when it changed something.
    pub(crate) fn enforce(&self, x: &mut D::Vector, v: &mut D::Vector) -> bool {
        match *self {
            Boundary::Wall { point, normal } | Boundary::Contact { point, normal } => {
                let d = (*x - point).dot(normal);
                if d < 0.0 {
                    *x -= normal * (2.0 * d);
                    let vn = v.dot(normal);
                    if vn < 0.0 {
                        *v -= normal * (2.0 * vn);
                    }
                    true
                } else {
                    false
                }
            }
            Boundary::Periodic { axis, lo, hi } => {
                let c = x.component(axis);
                if c < lo || c >= hi {
                    let period = hi - lo;
                    x.set_component(axis, lo + (c - lo).rem_euclid(period));
                    true
                } else {
                    false
                }
            }
        }
    }
}

impl Boundary<sph_core::Dim1> {
    /// Reflecting walls at both ends of the 1-D interval [lo, hi], normals pointing in.
    pub fn slab(lo: f64, hi: f64) -> Vec<Boundary<sph_core::Dim1>> {
        vec![
            Boundary::Wall {
                point: lo,
                normal: 1.0,
            },
            Boundary::Wall {
                point: hi,
                normal: -1.0,
            },
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sph_core::Dim3;
    use sph_core::glam::DVec3;

    /// A ghost placed again from its source's later position (`Ghost::moved_to`, the
    /// midpoint stage of `NeighbourSearch::EachStep`) lands where a new ghost of that
    /// position would, with the same map: an oblique wall, a contact wall, a periodic
    /// face.
    #[test]
    fn a_ghost_moved_with_its_source_lands_where_a_new_one_would() {
        let n = DVec3::new(0.0, 0.6, 0.8);
        let boundaries = [
            Boundary::<Dim3>::Wall {
                point: DVec3::new(0.3e-3, -0.2e-3, -1.0e-3),
                normal: n,
            },
            Boundary::Contact {
                point: DVec3::new(0.0, 0.0, -1.0e-3),
                normal: DVec3::Z,
            },
            Boundary::Periodic {
                axis: 0,
                lo: -1.0e-3,
                hi: 2.0e-3,
            },
        ];
        let x0 = DVec3::new(-0.7e-3, 0.1e-3, -0.6e-3);
        let x1 = x0 + DVec3::new(0.05e-3, -0.02e-3, 0.03e-3);
        let radius = [1.0e-3];
        for b in boundaries {
            let (mut first, mut later) = (Vec::new(), Vec::new());
            b.ghosts(&[x0], &radius, &mut first);
            b.ghosts(&[x1], &radius, &mut later);
            assert_eq!((first.len(), later.len()), (1, 1), "{b:?}");
            let moved = first[0].moved_to(x1);
            assert!(
                (moved.position - later[0].position).length() < 1e-18,
                "{b:?}: {:?} against {:?}",
                moved.position,
                later[0].position
            );
            assert_eq!(moved.map, later[0].map);
            assert_eq!(moved.source, later[0].source);
            // Placed again at its own position, a ghost does not move.
            assert!((first[0].moved_to(x0).position - first[0].position).length() < 1e-18);
        }
    }
}

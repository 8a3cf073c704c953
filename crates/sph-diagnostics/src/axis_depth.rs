//! Crater depth on the impact axis, read from the target's volume fraction
//! (docs/diagnostics.md §4.4).
//!
//! The binned profile (`crater_profile`) takes the highest wall particle in each radial
//! bin, so its innermost bin follows single particles: one ring or particle left on the
//! axis, or gone from it, sets the depth. This measure reads a field instead. With one
//! kernel of support radius H for every particle (not the particles' own h, which adapts
//! differently in RZ and 3-D), the target's volume fraction on the axis is
//!
//! ```text
//! φ(z) = Σ_j V_j W(√(s_j² + (z − z_j)²), H),   V_j = m_j/ρ_j,
//! ```
//!
//! over the wall particles (target bodies, not ejecta) within H of the axis, s_j their
//! distance from it. W is the 3-D Wendland C2 kernel (paper §2.4). The floor is the
//! highest z where φ(z, t) ≥ ½ φ(z′, 0), with the undisturbed field taken at
//! z′ = min(z, surface − H), a full support below the surface: dividing by the initial
//! field at the same depth cancels the kernel sum's quadrature error, which depends on the
//! local spacing and on the placement next to the axis and is the same at t = 0 in every
//! geometry. Depth = surface − floor; an untouched target reads a few hundredths of a
//! spacing (the half level of its own surface), not exactly 0.
//!
//! H sets the radial resolution: material within about 0.3 H of the axis carries half
//! the kernel's weight there, so a pit that wide is read and a narrower one is smoothed
//! over. With the default H of 2.5 spacings a pit one spacing in half-width is read; with
//! 5 spacings it is not (test `the_kernel_width_sets_the_narrowest_pit_that_is_read`).
//!
//! One formula serves RZ, a 3-D quarter model and a full 3-D body. An RZ ring is stored
//! with its whole ring mass (`ParticleView`), and every point of the ring is √(r² + Δz²)
//! from a point on the axis. A quarter model's particle carries the mass of its four
//! mirror copies, all the same distance from the axis.

use crate::ejecta::EjectaCriterion;
use crate::error::{ImpactError, finite, positive};
use crate::particles_view::{Geometry, ParticleView};
use sph_kernel::{Kernel, WendlandC2};

/// One wall particle near the axis.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Member {
    /// Squared distance from the axis (m²).
    s2: f64,
    /// Height (m).
    z: f64,
    /// Volume m/ρ (m³).
    volume: f64,
}

/// The target's wall particles within one kernel width H of the impact axis at one
/// instant, sorted by height: what φ(z) is summed over.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisField {
    width: f64,
    members: Vec<Member>,
}

impl AxisField {
    /// The field of `view`'s wall particles (target bodies of `criterion`, not ejecta)
    /// for a kernel of support radius `width` (m). Needs the density array.
    pub fn new(
        view: &ParticleView,
        criterion: &EjectaCriterion,
        geometry: Geometry,
        width: f64,
    ) -> Result<Self, ImpactError> {
        view.validate()?;
        criterion.check()?;
        let width = positive("axis kernel width", finite("axis kernel width", width)?)?;
        let density = view.density.ok_or(ImpactError::MissingField("density"))?;
        let mut members: Vec<Member> = (0..view.len())
            .filter(|&i| criterion.is_target(view.body[i]) && !criterion.is_ejecta(view, i))
            .filter_map(|i| {
                let s = geometry.radius(view.position[i]);
                (s < width).then(|| Member {
                    s2: s * s,
                    z: view.position[i][2],
                    volume: view.mass[i] / density[i],
                })
            })
            .collect();
        members.sort_by(|a, b| a.z.total_cmp(&b.z));
        Ok(Self { width, members })
    }

    /// The kernel's support radius H (m).
    pub fn width(&self) -> f64 {
        self.width
    }

    /// True when no wall particle lies within H of the axis.
    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }

    /// φ(z): the volume fraction on the axis at height `z` (m), ≈ 1 inside an
    /// undisturbed body away from its surface (the kernel sum's quadrature error aside).
    pub fn fraction(&self, z: f64) -> f64 {
        let h = self.width;
        let first = self.members.partition_point(|m| m.z <= z - h);
        self.members[first..]
            .iter()
            .take_while(|m| m.z < z + h)
            .map(|m| {
                let dz = z - m.z;
                m.volume * WendlandC2.w_radial(3, (m.s2 + dz * dz).sqrt(), h)
            })
            .sum()
    }

    /// Height range (m) over which φ can be non-zero; `None` when empty.
    fn extent(&self) -> Option<(f64, f64)> {
        let (lo, hi) = (self.members.first()?, self.members.last()?);
        Some((lo.z - self.width, hi.z + self.width))
    }
}

/// Crater depth on the axis against the undisturbed field of t = 0 (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct AxisDepth {
    initial: AxisField,
    surface_z: f64,
}

impl AxisDepth {
    /// Steps of the downward scan per kernel width; the floor is then bisected.
    const STEPS_PER_WIDTH: f64 = 25.0;

    /// The measure against `initial`, the field of the undisturbed target, whose original
    /// top surface is at `surface_z` (m).
    pub fn new(initial: AxisField, surface_z: f64) -> Result<Self, ImpactError> {
        finite("surface_z", surface_z)?;
        if initial.is_empty() {
            return Err(ImpactError::EmptySelection(
                "no target particle within the axis kernel width of the axis at t = 0",
            ));
        }
        Ok(Self { initial, surface_z })
    }

    /// The kernel width H of the measure (m).
    pub fn width(&self) -> f64 {
        self.initial.width
    }

    /// True if the target at height `z` is at least half as full as it was at t = 0 a
    /// support below the surface (or at `z`, if deeper). Below the initial target there
    /// is nothing to fill.
    fn filled(&self, now: &AxisField, z: f64) -> bool {
        let reference = self
            .initial
            .fraction(z.min(self.surface_z - self.initial.width));
        reference > 0.0 && now.fraction(z) >= 0.5 * reference
    }

    /// The crater floor on the axis (m): the highest z where the target is filled, found
    /// by a scan down from above the highest wall particle in steps of H/25 and bisection.
    /// `None` if the axis is empty down to the bottom of the initial target.
    pub fn floor(&self, now: &AxisField) -> Result<Option<f64>, ImpactError> {
        if now.width != self.initial.width {
            return Err(ImpactError::BadParameter {
                name: "axis kernel width",
                value: now.width,
                reason: "must be the width of the t = 0 field",
            });
        }
        let (Some((_, top)), Some((bottom, _))) = (now.extent(), self.initial.extent()) else {
            return Ok(None);
        };
        let dz = self.initial.width / Self::STEPS_PER_WIDTH;
        let mut z = top;
        while z > bottom {
            if self.filled(now, z) {
                let (mut lo, mut hi) = (z, z + dz);
                // 30 halvings put the floor within dz·1e-9.
                for _ in 0..30 {
                    let mid = 0.5 * (lo + hi);
                    if self.filled(now, mid) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return Ok(Some(0.5 * (lo + hi)));
            }
            z -= dz;
        }
        Ok(None)
    }

    /// Depth of the floor below the original surface (m); NaN when the axis is empty
    /// ([`AxisDepth::floor`] is `None`).
    pub fn depth(&self, now: &AxisField) -> Result<f64, ImpactError> {
        Ok(self.floor(now)?.map_or(f64::NAN, |f| self.surface_z - f))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block of cubic cells `d` wide filling |x|, |y| < `half` and `bottom` < z < 0,
    /// with the cells whose centre lies within `hole` of the axis and above `floor`
    /// removed; density 1000, mass d³ρ.
    fn block(d: f64, half: f64, bottom: f64, hole: f64, floor: f64) -> Vec<[f64; 3]> {
        let n = (half / d).round() as i64;
        let nz = (-bottom / d).round() as i64;
        let mut x = Vec::new();
        for i in -n..n {
            for j in -n..n {
                for k in 0..nz {
                    let p = [
                        (i as f64 + 0.5) * d,
                        (j as f64 + 0.5) * d,
                        -(k as f64 + 0.5) * d,
                    ];
                    if p[0].hypot(p[1]) < hole && p[2] > floor {
                        continue;
                    }
                    x.push(p);
                }
            }
        }
        x
    }

    /// The field of target particles (body 1) at rest at `x` with masses `m` and
    /// density 1000 kg/m³.
    fn at_rest(x: &[[f64; 3]], m: &[f64], geometry: Geometry, width: f64) -> AxisField {
        let v = vec![[0.0; 3]; x.len()];
        let rho = vec![1000.0; x.len()];
        let body = vec![1; x.len()];
        let view = ParticleView::new(x, &v, m, &body).with_density(&rho);
        AxisField::new(&view, &EjectaCriterion::new(&[1], 0.0), geometry, width).unwrap()
    }

    /// The field of the cells `x` of a block `d` wide (mass d³ρ).
    fn field(x: &[[f64; 3]], d: f64, width: f64) -> AxisField {
        at_rest(
            x,
            &vec![d * d * d * 1000.0; x.len()],
            Geometry::ThreeD,
            width,
        )
    }

    #[test]
    fn an_untouched_block_reads_its_surface_and_a_hole_its_floor() {
        let d = 1e-3;
        let width = 2.5 * d;
        let initial = field(&block(d, 6e-3, -20e-3, 0.0, 0.0), d, width);
        // Deep inside the block the fraction is one to the lattice's quadrature error.
        assert!(
            (initial.fraction(-10e-3) - 1.0).abs() < 0.02,
            "{}",
            initial.fraction(-10e-3)
        );
        let depth = AxisDepth::new(initial.clone(), 0.0).unwrap();
        // The undisturbed surface reads within a tenth of a spacing of z = 0.
        let d0 = depth.depth(&initial).unwrap();
        assert!(d0.abs() < 0.1 * d, "{d0}");
        // A hole 3 spacings in radius down to z = −8 mm: its floor is the top of the
        // cells below −8 mm, within a tenth of a spacing.
        let hole = field(&block(d, 6e-3, -20e-3, 3e-3, -8e-3), d, width);
        let d1 = depth.depth(&hole).unwrap();
        assert!((d1 - 8e-3).abs() < 0.1 * d, "{d1}");
    }

    #[test]
    fn the_kernel_width_sets_the_narrowest_pit_that_is_read() {
        // The 2 × 2 column of cells next to the axis removed down to −8 mm: a pit one
        // spacing in half-width, the shape an RZ first column leaves when it moves off
        // the axis. The column carries half of the kernel's weight on the axis out to a
        // radius of about 0.3 H, so the pit is read with H = 2.5 spacings (the default)
        // and smoothed over with H = 5.
        let d = 1e-3;
        let read = |width: f64| {
            let initial = field(&block(d, 8e-3, -20e-3, 0.0, 0.0), d, width);
            let pit = field(&block(d, 8e-3, -20e-3, 0.75e-3, -8e-3), d, width);
            AxisDepth::new(initial, 0.0).unwrap().depth(&pit).unwrap()
        };
        let (narrow, wide) = (read(2.5 * d), read(5.0 * d));
        assert!((narrow - 8e-3).abs() < 0.5 * d, "{narrow}");
        assert!(wide < d, "{wide}");
    }

    #[test]
    fn rings_and_a_quarter_model_read_the_same_floor() {
        // The hole block once as RZ rings (x = r, whole ring mass 2π r d² ρ) and once as
        // the quarter x, y > 0 with four times the mass: equal depths.
        let d = 0.5e-3;
        let width = 2.5 * d;
        let (hole, floor) = (2e-3, -5e-3);
        let all: Vec<[f64; 3]> = (0..16)
            .flat_map(|i| (0..40).map(move |k| [(i as f64 + 0.5) * d, 0.0, -(k as f64 + 0.5) * d]))
            .collect();
        let rings: Vec<[f64; 3]> = all
            .iter()
            .copied()
            .filter(|p| !(p[0] < hole && p[2] > floor))
            .collect();
        let read_rings = |x: &[[f64; 3]]| {
            let m: Vec<f64> = x
                .iter()
                .map(|p| 2.0 * std::f64::consts::PI * p[0] * d * d * 1000.0)
                .collect();
            at_rest(x, &m, Geometry::Axisymmetric, width)
        };
        let rz = AxisDepth::new(read_rings(&all), 0.0).unwrap();
        let rz_depth = rz.depth(&read_rings(&rings)).unwrap();

        let quarter = |x: Vec<[f64; 3]>| {
            let q: Vec<[f64; 3]> = x.into_iter().filter(|p| p[0] > 0.0 && p[1] > 0.0).collect();
            at_rest(
                &q,
                &vec![4.0 * d * d * d * 1000.0; q.len()],
                Geometry::ThreeD,
                width,
            )
        };
        let q3 = AxisDepth::new(quarter(block(d, 8e-3, -20e-3, 0.0, 0.0)), 0.0).unwrap();
        let q3_depth = q3
            .depth(&quarter(block(d, 8e-3, -20e-3, hole, floor)))
            .unwrap();
        assert!((rz_depth - 5e-3).abs() < 0.1 * d, "{rz_depth}");
        assert!((q3_depth - 5e-3).abs() < 0.1 * d, "{q3_depth}");
    }

    #[test]
    fn ejecta_and_other_bodies_are_not_wall() {
        let d = 1e-3;
        let x = block(d, 4e-3, -10e-3, 0.0, 0.0);
        let mut pts = x.clone();
        // A target particle above the surface moving up (ejecta) and a projectile
        // particle in the hole's place: neither counts.
        pts.push([0.0, 0.0, 1e-3]);
        pts.push([0.0, 0.0, 2e-3]);
        let mut v = vec![[0.0; 3]; pts.len()];
        v[x.len()] = [0.0, 0.0, 100.0];
        let m = vec![d * d * d * 1000.0; pts.len()];
        let rho = vec![1000.0; pts.len()];
        let mut body = vec![1; pts.len()];
        body[x.len() + 1] = 0;
        let view = ParticleView::new(&pts, &v, &m, &body).with_density(&rho);
        let f = AxisField::new(
            &view,
            &EjectaCriterion::new(&[1], 0.0),
            Geometry::ThreeD,
            2.5e-3,
        )
        .unwrap();
        assert_eq!(f, field(&x, d, 2.5e-3));
    }

    #[test]
    fn bad_input_is_refused() {
        let x = [[0.0, 0.0, -1e-3]];
        let (v, m, body) = ([[0.0; 3]], [1e-6], [1u16]);
        let c = EjectaCriterion::new(&[1], 0.0);
        let no_density = ParticleView::new(&x, &v, &m, &body);
        assert!(matches!(
            AxisField::new(&no_density, &c, Geometry::ThreeD, 1e-3),
            Err(ImpactError::MissingField("density"))
        ));
        let view = no_density.with_density(&[1000.0]);
        for w in [0.0, -1e-3, f64::NAN] {
            assert!(
                AxisField::new(&view, &c, Geometry::ThreeD, w).is_err(),
                "{w}"
            );
        }
        // Nothing within H of the axis at t = 0: no reference to measure against.
        let far = [[1.0, 0.0, -1e-3]];
        let view = ParticleView::new(&far, &v, &m, &body).with_density(&[1000.0]);
        let empty = AxisField::new(&view, &c, Geometry::ThreeD, 1e-3).unwrap();
        assert!(AxisDepth::new(empty, 0.0).is_err());
        // A field of another width cannot be read against the reference.
        let view = no_density.with_density(&[1000.0]);
        let a = AxisField::new(&view, &c, Geometry::ThreeD, 1e-3).unwrap();
        let b = AxisField::new(&view, &c, Geometry::ThreeD, 2e-3).unwrap();
        assert!(AxisDepth::new(a, 0.0).unwrap().floor(&b).is_err());
    }
}

//! Crater depth on the impact axis, read from the target's volume fraction averaged over
//! a disc about the axis (docs/diagnostics.md §4.4).
//!
//! The binned profile (`crater_profile`) takes the highest wall particle in each radial
//! bin, so its innermost bin follows single particles: one ring or particle left on the
//! axis, or gone from it, sets the depth. This measure reads a field instead. With one
//! kernel of support radius H for every particle (not the particles' own h, which adapts
//! differently in RZ and 3-D), the target's volume fraction averaged over the disc r < R
//! at height z is
//!
//! ```text
//! φ(z) = Σ_j V_j K(s_j, z − z_j),   V_j = m_j/ρ_j,
//! ```
//!
//! over the wall particles (target bodies, not ejecta) within R + H of the axis, s_j their
//! distance from it, K the 3-D Wendland C2 kernel (paper §2.4) averaged over the disc
//! ([`DiscKernel`]). The floor is the highest z where φ(z, t) ≥ ½ φ(z′, 0), with the
//! undisturbed field taken at z′ = min(z, surface − H), a full support below the surface:
//! dividing by the initial field at the same depth cancels the kernel sum's quadrature
//! error, which depends on the local spacing and on the placement next to the axis and is
//! the same at t = 0 in every geometry. Depth = surface − floor; an untouched target reads
//! a few hundredths of a spacing (the half level of its own surface), not exactly 0.
//!
//! Why a disc and not the axis line (R = 0): on the line the kernel falls
//! steeply with a particle's distance from the axis, so the nearest few particles decide
//! φ. After an impact the first column of RZ rings sits evenly 0.5–1 mm off the axis,
//! while in 3-D the same column scatters and a few particles stay close to it; at A_res
//! 0.5 mm three of them carried 64 % of the 3-D line field below the crater
//! (docs/verification.md, RZ against 3-D). Averaged over the disc, every
//! particle weighs as a ring through it, the same in both geometries, and a pit is read
//! when it is about as wide as the disc. The default R is H: a pit two spacings wide is
//! read, a single column leaving or staying is not (tests
//! `a_pit_as_wide_as_the_disc_is_read` and `one_column_does_not_decide_the_depth`).
//!
//! One formula serves RZ, a 3-D quarter model and a full 3-D body. An RZ ring is stored
//! with its whole ring mass (`ParticleView`); K depends on the distance from the axis
//! alone. A quarter model's particle carries the mass of its four mirror copies, all the
//! same distance from the axis. In plane strain (volumes per unit depth) and in 1-D
//! (volumes per unit area) K is the kernel of that dimension averaged over the segment
//! |x| < R, or the 1-D kernel ([`DiscKernel::in_dimension`]; `AxisField::new` picks it
//! from the geometry).

use crate::disc_kernel::DiscKernel;
use crate::ejecta::EjectaCriterion;
use crate::error::{ImpactError, finite};
use crate::particles_view::{Geometry, ParticleView};

/// One wall particle near the axis.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Member {
    /// Distance from the axis (m).
    s: f64,
    /// Height (m).
    z: f64,
    /// Volume m/ρ (m³).
    volume: f64,
}

/// The target's wall particles within R + H of the impact axis at one instant, sorted
/// by height: what φ(z) is summed over.
#[derive(Clone, Debug, PartialEq)]
pub struct AxisField {
    kernel: DiscKernel,
    members: Vec<Member>,
}

impl AxisField {
    /// The field of `view`'s wall particles (target bodies of `criterion`, not ejecta)
    /// for `kernel`: support radius H averaged over the disc r < R. Needs the density
    /// array.
    pub fn new(
        view: &ParticleView,
        criterion: &EjectaCriterion,
        geometry: Geometry,
        kernel: DiscKernel,
    ) -> Result<Self, ImpactError> {
        view.validate()?;
        criterion.check()?;
        let density = view.density.ok_or(ImpactError::MissingField("density"))?;
        // The kernel of the particles' own dimension: volumes are per unit depth in
        // plane strain, per unit area in 1-D.
        let kernel = kernel.in_dimension(geometry.dimension())?;
        let reach = kernel.reach();
        let mut members: Vec<Member> = (0..view.len())
            .filter(|&i| criterion.is_target(view.body[i]) && !criterion.is_ejecta(view, i))
            .filter_map(|i| {
                let s = geometry.radius(view.position[i]);
                (s < reach).then(|| Member {
                    s,
                    z: view.position[i][2],
                    volume: view.mass[i] / density[i],
                })
            })
            .collect();
        members.sort_by(|a, b| a.z.total_cmp(&b.z));
        Ok(Self { kernel, members })
    }

    /// The kernel the field is read with.
    pub fn kernel(&self) -> DiscKernel {
        self.kernel
    }

    /// True when no wall particle lies within R + H of the axis.
    pub fn is_empty(&self) -> bool {
        self.members.is_empty()
    }

    /// φ(z): the volume fraction averaged over the disc r < R at height `z` (m), ≈ 1
    /// inside an undisturbed body away from its surface (the kernel sum's quadrature
    /// error aside).
    pub fn fraction(&self, z: f64) -> f64 {
        let h = self.kernel.support();
        let first = self.members.partition_point(|m| m.z <= z - h);
        self.members[first..]
            .iter()
            .take_while(|m| m.z < z + h)
            .map(|m| m.volume * self.kernel.value(m.s, z - m.z))
            .sum()
    }

    /// Height range (m) over which φ can be non-zero; `None` when empty.
    fn extent(&self) -> Option<(f64, f64)> {
        let (lo, hi) = (self.members.first()?, self.members.last()?);
        let h = self.kernel.support();
        Some((lo.z - h, hi.z + h))
    }
}

/// Crater depth on the axis against the undisturbed field of t = 0 (module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct AxisDepth {
    initial: AxisField,
    surface_z: f64,
    /// The t = 0 field a support below the surface, the reference for every height
    /// above that (kept, not summed again at each step of the scan).
    reference_below_surface: f64,
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
                "no target particle within R + H of the axis at t = 0",
            ));
        }
        let reference_below_surface = initial.fraction(surface_z - initial.kernel.support());
        Ok(Self {
            initial,
            surface_z,
            reference_below_surface,
        })
    }

    /// The kernel of the measure (H and R).
    pub fn kernel(&self) -> DiscKernel {
        self.initial.kernel
    }

    /// True if the target at height `z` is at least half as full as it was at t = 0 a
    /// support below the surface (or at `z`, if deeper). Below the initial target there
    /// is nothing to fill.
    fn filled(&self, now: &AxisField, z: f64) -> bool {
        let below_surface = self.surface_z - self.initial.kernel.support();
        let reference = if z >= below_surface {
            self.reference_below_surface
        } else {
            self.initial.fraction(z)
        };
        reference > 0.0 && now.fraction(z) >= 0.5 * reference
    }

    /// The crater floor on the axis (m): the highest z where the target is filled, found
    /// by a scan down from above the highest wall particle in steps of H/25 and bisection.
    /// `None` if the axis is empty down to the bottom of the initial target.
    pub fn floor(&self, now: &AxisField) -> Result<Option<f64>, ImpactError> {
        if now.kernel != self.initial.kernel {
            return Err(ImpactError::BadParameter {
                name: "axis kernel width",
                value: now.kernel.support(),
                reason: "the field must be read with the t = 0 field's kernel and disc",
            });
        }
        let (Some((_, top)), Some((bottom, _))) = (now.extent(), self.initial.extent()) else {
            return Ok(None);
        };
        let dz = self.initial.kernel.support() / Self::STEPS_PER_WIDTH;
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
    /// density 1000 kg/m³, read with support `width` over a disc of radius `disc`.
    fn at_rest(x: &[[f64; 3]], m: &[f64], geometry: Geometry, width: f64, disc: f64) -> AxisField {
        let v = vec![[0.0; 3]; x.len()];
        let rho = vec![1000.0; x.len()];
        let body = vec![1; x.len()];
        let view = ParticleView::new(x, &v, m, &body).with_density(&rho);
        let kernel = DiscKernel::new(width, disc).unwrap();
        AxisField::new(&view, &EjectaCriterion::new(&[1], 0.0), geometry, kernel).unwrap()
    }

    /// The field of the cells `x` of a block `d` wide (mass d³ρ), H = R = `width`.
    fn field(x: &[[f64; 3]], d: f64, width: f64) -> AxisField {
        field_over(x, d, width, width)
    }

    /// The field of the cells `x` of a block `d` wide, H = `width`, R = `disc`.
    fn field_over(x: &[[f64; 3]], d: f64, width: f64, disc: f64) -> AxisField {
        at_rest(
            x,
            &vec![d * d * d * 1000.0; x.len()],
            Geometry::ThreeD,
            width,
            disc,
        )
    }

    /// The depth of `shape` against the untouched block, both cells `d` wide in a block
    /// 8 mm in half-width and 20 mm deep, H = `width`, R = `disc`.
    fn depth_of(shape: &[[f64; 3]], d: f64, width: f64, disc: f64) -> f64 {
        let initial = field_over(&block(d, 8e-3, -20e-3, 0.0, 0.0), d, width, disc);
        AxisDepth::new(initial, 0.0)
            .unwrap()
            .depth(&field_over(shape, d, width, disc))
            .unwrap()
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
    fn a_pit_as_wide_as_the_disc_is_read() {
        // Cells within R = H = 2.5 spacings of the axis removed down to −8 mm. The walls
        // just outside the disc still reach into it, so the floor reads a little high
        // (7.67 mm when written), within half a spacing.
        let d = 1e-3;
        let width = 2.5 * d;
        let pit = block(d, 8e-3, -20e-3, width, -8e-3);
        let read = depth_of(&pit, d, width, width);
        assert!((read - 8e-3).abs() < 0.5 * d, "{read}");
    }

    #[test]
    fn one_column_does_not_decide_the_depth() {
        // The 2 × 2 column of cells next to the axis (one spacing in half-width) removed
        // from an untouched block down to −8 mm: the pit one column of RZ rings leaves
        // when it moves off the axis. On the axis line it is read at its full depth; over
        // the disc it is a fifth of the area and is not.
        let d = 1e-3;
        let width = 2.5 * d;
        let column_gone = block(d, 8e-3, -20e-3, 0.75e-3, -8e-3);
        let line = depth_of(&column_gone, d, width, 0.0);
        let disc = depth_of(&column_gone, d, width, width);
        assert!((line - 8e-3).abs() < 0.5 * d, "{line}");
        assert!(disc < d, "{disc}");
    }

    #[test]
    fn where_the_material_sits_within_the_disc_matters_little() {
        // A hole of radius 4 spacings down to −8 mm with four particles per layer left
        // in it (the volume of one column), at 45° + k·90° and a distance s0 from the
        // axis: close to it (s0 = 0.8 spacings, as a few 3-D particles stayed at A_res
        // 0.5 mm) or further out (1.6 spacings, as the first RZ column moves). On the
        // axis line the few close particles fill the crater; over the disc they are a
        // fifth of its area wherever they sit, and the floor is read.
        let d = 1e-3;
        let width = 2.5 * d;
        let with_column = |s0: f64| {
            let mut x = block(d, 8e-3, -20e-3, 4e-3, -8e-3);
            for k in 0..8 {
                let z = -(k as f64 + 0.5) * d;
                for q in 0..4 {
                    let a = std::f64::consts::FRAC_PI_4 + q as f64 * std::f64::consts::FRAC_PI_2;
                    x.push([s0 * a.cos(), s0 * a.sin(), z]);
                }
            }
            x
        };
        let (near, far) = (with_column(0.8 * d), with_column(1.6 * d));
        let line = (
            depth_of(&near, d, width, 0.0),
            depth_of(&far, d, width, 0.0),
        );
        let disc = (
            depth_of(&near, d, width, width),
            depth_of(&far, d, width, width),
        );
        assert!(line.0 < d, "{line:?}");
        assert!((line.1 - 8e-3).abs() < 0.5 * d, "{line:?}");
        for depth in [disc.0, disc.1] {
            assert!((depth - 8e-3).abs() < 0.5 * d, "{disc:?}");
        }
        assert!((disc.0 - disc.1).abs() < 0.1 * d, "{disc:?}");
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
            at_rest(x, &m, Geometry::Axisymmetric, width, width)
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
            DiscKernel::new(2.5e-3, 2.5e-3).unwrap(),
        )
        .unwrap();
        assert_eq!(f, field(&x, d, 2.5e-3));
    }

    #[test]
    fn bad_input_is_refused() {
        let x = [[0.0, 0.0, -1e-3]];
        let (v, m, body) = ([[0.0; 3]], [1e-6], [1u16]);
        let c = EjectaCriterion::new(&[1], 0.0);
        let k = |h: f64, r: f64| DiscKernel::new(h, r).unwrap();
        let no_density = ParticleView::new(&x, &v, &m, &body);
        assert!(matches!(
            AxisField::new(&no_density, &c, Geometry::ThreeD, k(1e-3, 1e-3)),
            Err(ImpactError::MissingField("density"))
        ));
        // Nothing within R + H of the axis at t = 0: no reference to measure against.
        let far = [[2.1e-3, 0.0, -1e-3]];
        let view = ParticleView::new(&far, &v, &m, &body).with_density(&[1000.0]);
        let empty = AxisField::new(&view, &c, Geometry::ThreeD, k(1e-3, 1e-3)).unwrap();
        assert!(AxisDepth::new(empty, 0.0).is_err());
        // A field of another width or disc cannot be read against the reference.
        let view = no_density.with_density(&[1000.0]);
        let field = |h, r| AxisField::new(&view, &c, Geometry::ThreeD, k(h, r)).unwrap();
        let depth = AxisDepth::new(field(1e-3, 1e-3), 0.0).unwrap();
        assert!(depth.floor(&field(2e-3, 1e-3)).is_err());
        assert!(depth.floor(&field(1e-3, 0.0)).is_err());
        assert!(depth.floor(&field(1e-3, 1e-3)).is_ok());
    }
}

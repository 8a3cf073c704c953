//! The kernel averaged over a disc about the impact axis: the weight one particle gives
//! the axis depth's volume fraction (docs/diagnostics.md §4.4).
//!
//! A particle at distance s from the axis and height Δz below or above the disc
//! r < R of the plane z contributes, per unit volume, the mean of the 3-D kernel over
//! that disc:
//!
//! ```text
//! K(s, Δz) = 1/(π R²) ∫_{|x⊥| < R} W(√(|x⊥ − c|² + Δz²), H) d²x⊥,   |c| = s.
//! ```
//!
//! In polar coordinates (q, ψ) about the particle's foot c the ψ-integral is the angle
//! α(q) of the circle of radius q about c that lies inside the disc, so
//!
//! ```text
//! K = 1/(π R²) ∫₀^Q W(√(q² + Δz²), H) α(q) q dq,   Q = √(H² − Δz²),
//! α(q) = 2π                                    for q ≤ R − s,
//!      = 0                                     for q ≤ s − R or q ≥ R + s,
//!      = 2 arccos((q² + s² − R²)/(2 q s))      otherwise (law of cosines).
//! ```
//!
//! α has square-root corners at q = |R − s| and R + s. The integral is split there, and
//! each piece [a, b] is mapped by q = a + (b − a) sin²(πu/2), which makes √(q − a) and
//! √(b − q) smooth in u, before an 8-point Gauss–Legendre rule on each half of [0, 1] in
//! u: within 1e-9 of the kernel's peak (one panel: 3e-5; measured against a 20-panel,
//! 40-point rule).
//!
//! K depends on s alone, not on the azimuth, so an RZ ring (with its whole ring mass)
//! and a 3-D particle at the same distance from the axis weigh the same. R = 0 is the
//! limit of a line: K = W(√(s² + Δz²), H), the field on the axis itself.
//!
//! In lower dimensions ([`DiscKernel::in_dimension`]) the same average is taken over
//! what the disc becomes. In plane strain (2-D particles in (x, z), volumes per unit
//! depth) the disc is the segment |x| < R of the line z and W the 2-D kernel:
//!
//! ```text
//! K₂(s, Δz) = 1/(2R) ∫_{−R}^{R} W₂(√((x − s)² + Δz²), H) dx,
//! ```
//!
//! integrated over the part of the segment within the support, |x − s| < Q, by the same
//! smoothed Gauss rule on each side of the peak x = s (within 1e-6 of the peak against a
//! 20 000-point midpoint rule); R = 0 gives
//! W₂(√(s² + Δz²), H). In 1-D (volumes per unit area) the disc is the whole plane z and
//! K₁ = W₁(|Δz|, H).

use crate::error::{ImpactError, finite, positive};
use sph_kernel::{Kernel, WendlandC2};
use std::f64::consts::PI;

/// 8-point Gauss–Legendre nodes and weights on [−1, 1] (the positive half; the rule is
/// symmetric).
const GAUSS_LEGENDRE_8: [(f64, f64); 4] = [
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// The 3-D Wendland C2 kernel of support radius H averaged over the disc r < R about
/// the axis (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiscKernel {
    support: f64,
    radius: f64,
    dimension: usize,
}

impl DiscKernel {
    /// The kernel of support radius `support` (H, m, positive) averaged over a disc of
    /// radius `radius` (R, m, ≥ 0; 0 reads the axis line itself).
    pub fn new(support: f64, radius: f64) -> Result<Self, ImpactError> {
        let support = positive("axis kernel width", support)?;
        let radius = finite("axis disc radius", radius)?;
        if radius < 0.0 {
            return Err(ImpactError::BadParameter {
                name: "axis disc radius",
                value: radius,
                reason: "must be zero (the axis line) or positive",
            });
        }
        Ok(Self {
            support,
            radius,
            dimension: 3,
        })
    }

    /// The same kernel in `dimension` (1, 2 or 3) space dimensions (module docs): the
    /// kernel [`Self::new`] gives is 3-D.
    pub fn in_dimension(self, dimension: usize) -> Result<Self, ImpactError> {
        if !(1..=3).contains(&dimension) {
            return Err(ImpactError::BadParameter {
                name: "axis kernel dimension",
                value: dimension as f64,
                reason: "must be 1, 2 or 3",
            });
        }
        Ok(Self { dimension, ..self })
    }

    /// The number of space dimensions of the kernel.
    pub fn dimension(&self) -> usize {
        self.dimension
    }

    /// The kernel's support radius H (m).
    pub fn support(&self) -> f64 {
        self.support
    }

    /// The disc's radius R (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The farthest a particle can be from the axis and still weigh: R + H (m).
    pub fn reach(&self) -> f64 {
        self.radius + self.support
    }

    /// K(s, Δz) (1/m³) for a particle `s` (m, ≥ 0) from the axis and `dz` (m) above or
    /// below the disc's plane.
    pub fn value(&self, s: f64, dz: f64) -> f64 {
        let (h, r) = (self.support, self.radius);
        let q_max2 = h * h - dz * dz;
        if q_max2 <= 0.0 || s >= r + h {
            return 0.0;
        }
        match self.dimension {
            1 => return WendlandC2.w_radial(1, dz.abs(), h),
            2 => return self.segment_value(s, dz, q_max2.sqrt()),
            _ => {}
        }
        if r == 0.0 {
            return WendlandC2.w_radial(3, (s * s + dz * dz).sqrt(), h);
        }
        let q_max = q_max2.sqrt();
        let integrand =
            |q: f64| WendlandC2.w_radial(3, (q * q + dz * dz).sqrt(), h) * self.angle(s, q) * q;
        let mut edges = [0.0, (r - s).abs(), r + s, q_max];
        edges.sort_by(f64::total_cmp);
        let mut sum = 0.0;
        for pair in edges.windows(2) {
            let (a, b) = (pair[0], pair[1].min(q_max));
            if b > a {
                sum += smoothed_gauss(&integrand, a, b);
            }
        }
        sum / (PI * r * r)
    }

    /// K₂(s, Δz): the 2-D kernel averaged over the segment |x| < R (module docs); `q_max`
    /// is the support's half-width at height Δz, √(H² − Δz²).
    fn segment_value(&self, s: f64, dz: f64, q_max: f64) -> f64 {
        let (h, r) = (self.support, self.radius);
        let w = |x: f64| WendlandC2.w_radial(2, ((x - s) * (x - s) + dz * dz).sqrt(), h);
        if r == 0.0 {
            return w(0.0);
        }
        let (a, b) = ((s - q_max).max(-r), (s + q_max).min(r));
        if b <= a {
            return 0.0;
        }
        // Split at the kernel's peak x = s, where W₂'s q³ term makes the integrand
        // least smooth.
        let total = if a < s && s < b {
            smoothed_gauss(&w, a, s) + smoothed_gauss(&w, s, b)
        } else {
            smoothed_gauss(&w, a, b)
        };
        total / (2.0 * r)
    }

    /// α(q): the angle of the circle of radius `q` about a point `s` from the axis that
    /// lies inside the disc (module docs).
    fn angle(&self, s: f64, q: f64) -> f64 {
        let r = self.radius;
        if q + s <= r {
            2.0 * PI
        } else if q <= s - r || q >= s + r {
            0.0
        } else {
            // Between the two corners the cosine lies in [−1, 1] but for rounding.
            let c = (q * q + s * s - r * r) / (2.0 * q * s);
            2.0 * c.clamp(-1.0, 1.0).acos()
        }
    }
}

/// ∫ₐᵇ f(q) dq with q = a + (b − a) sin²(πu/2), u ∈ [0, 1], and 8-point Gauss–Legendre
/// on [0, ½] and [½, 1] in u: accurate for smooth f and for √(q − a), √(b − q)
/// behaviour at the ends.
fn smoothed_gauss(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let width = b - a;
    let at = |u: f64| {
        let s = (0.5 * PI * u).sin();
        f(a + width * s * s) * 0.5 * PI * width * (PI * u).sin()
    };
    // Each half panel has centre c and half-width ¼.
    [0.25, 0.75]
        .iter()
        .flat_map(|&c| {
            GAUSS_LEGENDRE_8
                .iter()
                .map(move |&(x, w)| 0.25 * w * (at(c + 0.25 * x) + at(c - 0.25 * x)))
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The mean of W over the disc by brute force: a polar midpoint grid about the axis.
    fn brute(k: &DiscKernel, s: f64, dz: f64) -> f64 {
        let (nr, nt) = (800, 800);
        let r = k.radius();
        let mut sum = 0.0;
        for i in 0..nr {
            let rho = (i as f64 + 0.5) / nr as f64 * r;
            for j in 0..nt {
                let t = (j as f64 + 0.5) / nt as f64 * 2.0 * PI;
                let d2 = rho * rho + s * s - 2.0 * rho * s * t.cos() + dz * dz;
                sum += WendlandC2.w_radial(3, d2.sqrt(), k.support()) * rho;
            }
        }
        sum * (r / nr as f64) * (2.0 * PI / nt as f64) / (PI * r * r)
    }

    /// In plane strain: the mean of the 2-D kernel over the segment |x| < R by a midpoint
    /// rule, and the whole plane's integral of K₂ is 1 (a body filling the plane reads
    /// φ = 1). In 1-D: the 1-D kernel, whose integral over z is 1.
    #[test]
    fn lower_dimensions_average_over_the_segment_and_the_plane() {
        let h = 1.25e-3;
        let k2 = DiscKernel::new(h, 0.8 * h)
            .unwrap()
            .in_dimension(2)
            .unwrap();
        let peak = WendlandC2.w_radial(2, 0.0, h);
        let r = k2.radius();
        for (s, dz) in [
            (0.0, 0.0),
            (0.3e-3, 0.2e-3),
            (1.0e-3, 0.9e-3),
            (1.9e-3, 0.3e-3),
        ] {
            let n = 20_000;
            let slow = (0..n)
                .map(|i| {
                    let x = -r + (i as f64 + 0.5) / n as f64 * 2.0 * r;
                    WendlandC2.w_radial(2, ((x - s).powi(2) + dz * dz).sqrt(), h)
                })
                .sum::<f64>()
                / n as f64;
            let fast = k2.value(s, dz);
            assert!(
                (fast - slow).abs() < 1e-6 * peak,
                "s {s} dz {dz}: {fast} against {slow}"
            );
        }
        // ∫∫ K₂ dx dz over the plane, x = ±s.
        let (n, span) = (400, r + h);
        let d = span / n as f64;
        let mut total = 0.0;
        for i in 0..n {
            let s = (i as f64 + 0.5) * d;
            for j in 0..2 * n {
                let dz = -h + (j as f64 + 0.5) * h / n as f64;
                total += 2.0 * k2.value(s, dz) * d * h / n as f64;
            }
        }
        assert!((total - 1.0).abs() < 1e-3, "∫∫ K₂ = {total}");
        let k1 = DiscKernel::new(h, h).unwrap().in_dimension(1).unwrap();
        assert_eq!(k1.value(0.0, 0.4e-3), WendlandC2.w_radial(1, 0.4e-3, h));
        let line: f64 = (0..2000)
            .map(|j| k1.value(0.0, -h + (j as f64 + 0.5) * h / 1000.0) * h / 1000.0)
            .sum();
        assert!((line - 1.0).abs() < 1e-5, "∫ K₁ = {line}");
        assert!(DiscKernel::new(h, h).unwrap().in_dimension(4).is_err());
    }

    #[test]
    fn it_is_the_mean_of_the_kernel_over_the_disc() {
        let h = 1.25e-3;
        let k = DiscKernel::new(h, h).unwrap();
        let peak = WendlandC2.w_radial(3, 0.0, h);
        // Inside the disc, on its edge, outside it; in the plane and off it.
        for (s, dz) in [
            (0.0, 0.0),
            (0.3e-3, 0.2e-3),
            (1.25e-3, 0.0),
            (1.0e-3, 0.9e-3),
            (1.9e-3, 0.3e-3),
            (2.4e-3, 0.1e-3),
        ] {
            let (fast, slow) = (k.value(s, dz), brute(&k, s, dz));
            assert!(
                (fast - slow).abs() < 1e-5 * peak,
                "s {s} dz {dz}: {fast} against {slow}"
            );
        }
    }

    #[test]
    fn it_integrates_to_one_over_space() {
        // ∫ K dV = 1/(πR²) ∫_disc ∫ W dV = 1: the field of a uniform medium is one.
        for (h, r) in [(1.0, 1.0), (1.0, 0.3), (1.0, 2.5)] {
            let k = DiscKernel::new(h, r).unwrap();
            let (ns, nz) = (600, 300);
            let (ds, dz) = ((r + h) / ns as f64, h / nz as f64);
            let mut sum = 0.0;
            for i in 0..ns {
                let s = (i as f64 + 0.5) * ds;
                for j in 0..nz {
                    let z = (j as f64 + 0.5) * dz;
                    sum += 2.0 * k.value(s, z) * 2.0 * PI * s * ds * dz;
                }
            }
            assert!((sum - 1.0).abs() < 1e-3, "H {h} R {r}: {sum}");
        }
    }

    #[test]
    fn a_disc_of_no_radius_is_the_axis_line() {
        let h = 2.0;
        let line = DiscKernel::new(h, 0.0).unwrap();
        let thin = DiscKernel::new(h, 1e-4).unwrap();
        for (s, dz) in [(0.0f64, 0.0f64), (0.5, 0.5), (1.2, -0.7), (1.9, 0.1)] {
            let w = WendlandC2.w_radial(3, (s * s + dz * dz).sqrt(), h);
            assert_eq!(line.value(s, dz), w);
            assert!(
                (thin.value(s, dz) - w).abs() < 1e-6 * w.max(1e-3),
                "{s} {dz}"
            );
        }
    }

    #[test]
    fn a_particle_weighs_nearly_alike_anywhere_in_the_inner_disc() {
        // Why the disc (axis_depth.rs): on the line a particle 0.64 H from the axis
        // weighs 6 % of one on it; over a disc of R = H it weighs 88 % (0.881 from a
        // 40-point, 20-panel rule).
        let h = 1.0;
        let (line, disc) = (
            DiscKernel::new(h, 0.0).unwrap(),
            DiscKernel::new(h, h).unwrap(),
        );
        let ratio = |k: &DiscKernel, s: f64| k.value(s, 0.0) / k.value(0.0, 0.0);
        assert!(
            (ratio(&line, 0.64) - 0.0598).abs() < 1e-3,
            "{}",
            ratio(&line, 0.64)
        );
        assert!(
            (ratio(&disc, 0.64) - 0.8809).abs() < 1e-3,
            "{}",
            ratio(&disc, 0.64)
        );
        assert!(ratio(&disc, 0.32) > 0.99, "{}", ratio(&disc, 0.32));
    }

    #[test]
    fn nothing_reaches_beyond_the_support() {
        let k = DiscKernel::new(1.0, 0.5).unwrap();
        assert_eq!(k.reach(), 1.5);
        assert_eq!(k.value(1.5, 0.0), 0.0);
        assert_eq!(k.value(0.0, 1.0), 0.0);
        assert_eq!(k.value(0.0, -1.2), 0.0);
        assert!(k.value(1.45, 0.0) > 0.0);
    }

    #[test]
    fn bad_sizes_are_refused() {
        for (h, r) in [
            (0.0, 1.0),
            (-1.0, 1.0),
            (f64::NAN, 1.0),
            (1.0, -0.1),
            (1.0, f64::INFINITY),
        ] {
            assert!(DiscKernel::new(h, r).is_err(), "{h} {r}");
        }
    }

    proptest! {
        /// K is a mean of W over the disc: between zero and W at the disc's point nearest
        /// the particle.
        #[test]
        fn it_lies_between_zero_and_the_nearest_value(
            s in 0.0..3.0f64, dz in -1.2..1.2f64, r in 0.01..2.0f64,
        ) {
            let k = DiscKernel::new(1.0, r).unwrap();
            let v = k.value(s, dz);
            let nearest = (s - r).max(0.0);
            let bound = WendlandC2.w_radial(3, (nearest * nearest + dz * dz).sqrt(), 1.0);
            prop_assert!(v >= 0.0);
            prop_assert!(v <= bound * (1.0 + 1e-9) + 1e-15, "{} > {}", v, bound);
        }
    }
}

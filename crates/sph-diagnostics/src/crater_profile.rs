//! The crater profile: how deep the target's surface lies below its original height, as a
//! function of the distance from the impact axis (paper §5; docs/diagnostics.md §4).
//!
//! **Method.** Keep the target's *wall* particles: target bodies, not ejecta (same
//! criterion as module `ejecta`), and, if asked, not below a density cut nor above a
//! damage cut. Bin them by radius s from the axis (√(x²+y²) in 3-D, |x| in RZ) in bins
//! [k b, (k+1) b). In each bin the *floor* is the highest particle centre: material still
//! there. The depth is
//!
//! ```text
//! depth(s) = (surface_z − top_offset) − floor(s),
//! ```
//!
//! signed: a raised rim reads negative, nothing is clamped. A bin with no wall particle
//! has depth NaN — no evidence either way; `crater::measure_crater` says how it reads them.
//!
//! With [`CraterOptions::footprint`] a particle sets the floor of every bin within half
//! its own spacing of its radius, so bins narrower than the local spacing still read the
//! top layer. [`CraterProfile::relative_to`] reads a profile against the untouched
//! target's, bin by bin, so that a bed whose top layer lies deeper where its particles
//! are larger reads zero everywhere.

use crate::crater_options::CraterOptions;
use crate::ejecta::EjectaCriterion;
use crate::error::ImpactError;
use crate::particles_view::{Geometry, ParticleView};
use serde::{Deserialize, Serialize};

/// Most radial bins a profile may have (a stray particle far out would otherwise make a
/// huge, almost empty profile).
pub const MAX_PROFILE_BINS: usize = 1 << 22;

/// Crater depth against radius, one entry per radial bin from the axis outwards.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct CraterProfile {
    /// Bin centres (k + ½) b (m).
    pub radius: Vec<f64>,
    /// Signed depth below the original surface (m): positive in the crater, negative on
    /// a raised rim, NaN where the bin holds no wall particle.
    pub depth: Vec<f64>,
}

impl CraterProfile {
    /// Height of the highest raised rim above the original surface (m): the largest
    /// −depth over the non-empty bins, or 0 if nothing stands above the surface.
    pub fn rim_height(&self) -> f64 {
        self.depth
            .iter()
            .filter(|d| !d.is_nan())
            .fold(0.0f64, |h, &d| h.max(-d))
    }

    /// This profile read against `reference` (the same target untouched, same bins):
    /// depth(s) − depth_ref(s), how far the top of the wall material at s has gone down
    /// since. Where the reference has no value (an empty bin, or beyond its last bin:
    /// debris past the target's side) the nearest inner reference bin with one is used,
    /// else the nearest outer one. Errors if the bin widths differ or the reference has
    /// no non-empty bin.
    pub fn relative_to(&self, reference: &CraterProfile) -> Result<CraterProfile, ImpactError> {
        if let (Some(&a), Some(&b)) = (self.radius.first(), reference.radius.first())
            && (a - b).abs() > 1e-9 * a.abs().max(b.abs())
        {
            return Err(ImpactError::BadParameter {
                name: "reference bin",
                value: 2.0 * b,
                reason: "the reference profile's bins differ from this profile's",
            });
        }
        let finite: Vec<usize> = (0..reference.depth.len())
            .filter(|&k| reference.depth[k].is_finite())
            .collect();
        if finite.is_empty() {
            return Err(ImpactError::EmptySelection("no reference surface"));
        }
        let reference_at = |k: usize| {
            // The last finite bin at or inside k, else the first one outside it.
            let i = finite.partition_point(|&j| j <= k);
            reference.depth[finite[i.saturating_sub(1)]]
        };
        Ok(CraterProfile {
            radius: self.radius.clone(),
            depth: self
                .depth
                .iter()
                .enumerate()
                .map(|(k, &d)| d - reference_at(k))
                .collect(),
        })
    }

    /// Number of bins.
    pub fn len(&self) -> usize {
        self.radius.len()
    }

    /// True for a profile of no bins.
    pub fn is_empty(&self) -> bool {
        self.radius.is_empty()
    }
}

/// True if particle `i` is crater wall: a target particle that is not ejecta and passes
/// the density and damage cuts of `options`.
pub fn is_wall(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
    i: usize,
) -> bool {
    if !criterion.is_target(view.body[i]) || criterion.is_ejecta(view, i) {
        return false;
    }
    if let (Some(cut), Some(rho)) = (options.density_cut, view.density)
        && rho[i] < cut.min_fraction * cut.reference_density
    {
        return false;
    }
    if let (Some(max), Some(d)) = (options.max_damage, view.damage)
        && d[i] > max
    {
        return false;
    }
    true
}

/// The crater profile of `view` (validated first). Errors: a bad criterion or option, a
/// cut whose array the view lacks, no wall particle at all, or more than
/// [`MAX_PROFILE_BINS`] bins.
pub fn crater_profile(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
) -> Result<CraterProfile, ImpactError> {
    view.validate()?;
    criterion.check()?;
    options.check()?;
    if options.density_cut.is_some() && view.density.is_none() {
        return Err(ImpactError::MissingField("density"));
    }
    if options.max_damage.is_some() && view.damage.is_none() {
        return Err(ImpactError::MissingField("damage"));
    }
    if options.footprint && view.density.is_none() {
        return Err(ImpactError::MissingField("density"));
    }
    // Each wall particle as (inner, outer) radius of what it covers, in bins, and z.
    let wall: Vec<(f64, f64, f64)> = (0..view.len())
        .filter(|&i| is_wall(view, criterion, options, i))
        .map(|i| {
            let p = view.position[i];
            let s = options.geometry.radius(p);
            let half = match view.density {
                Some(rho) if options.footprint => {
                    0.5 * spacing(options.geometry, s, view.mass[i] / options.copies, rho[i])
                }
                _ => 0.0,
            };
            (
                (s - half).max(0.0) / options.bin,
                (s + half) / options.bin,
                p[2],
            )
        })
        .collect();
    if wall.is_empty() {
        return Err(ImpactError::EmptySelection("no target wall particles"));
    }
    // A particle covers the bins [k b, (k + 1) b) that its span [inner, outer) meets
    // (at least the bin of its centre).
    let last_bin = |inner: f64, outer: f64| (outer.ceil() - 1.0).max(inner.floor());
    let needed = wall.iter().fold(0.0f64, |a, w| a.max(last_bin(w.0, w.1))) + 1.0;
    if needed > MAX_PROFILE_BINS as f64 {
        return Err(ImpactError::TooManyBins {
            what: "crater profile",
            count: needed,
            limit: MAX_PROFILE_BINS,
        });
    }
    let n = needed as usize;
    let mut floor = vec![f64::NEG_INFINITY; n];
    for (inner, outer, z) in wall {
        let last = (last_bin(inner, outer) as usize).min(n - 1);
        for f in &mut floor[(inner.floor() as usize).min(last)..=last] {
            *f = f.max(z);
        }
    }
    let top = criterion.surface_z - options.top_offset;
    Ok(CraterProfile {
        radius: (0..n).map(|k| (k as f64 + 0.5) * options.bin).collect(),
        depth: floor
            .iter()
            .map(|&f| if f.is_finite() { top - f } else { f64::NAN })
            .collect(),
    })
}

/// A particle's own size (m) from its volume: (m/ρ)^(1/3) in 3-D; in RZ, where `mass` is
/// the full ring's, the side w of the ring's cross-section m/(2πρs), with the ring's
/// radius s at least w/2 (a ring on the axis: w³ = m/(πρ)); in plane strain, where
/// `mass` is per unit depth, the side of its square section √(m/ρ); in 1-D, where it is
/// per unit area, its thickness m/ρ.
fn spacing(geometry: Geometry, s: f64, mass: f64, density: f64) -> f64 {
    match geometry {
        Geometry::ThreeD => (mass / density).cbrt(),
        Geometry::Plane => (mass / density).sqrt(),
        Geometry::Line => mass / density,
        Geometry::Axisymmetric => {
            let on_axis = (mass / (std::f64::consts::PI * density)).cbrt();
            if s >= 0.5 * on_axis {
                (mass / (2.0 * std::f64::consts::PI * density * s)).sqrt()
            } else {
                on_axis
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::crater_options::DensityCut;
    use crate::ejecta::tests::Arrays;

    /// RZ columns at r = 0.5, 1.5, 2.5, 4.5 (bin 3 empty), with chosen tops.
    fn columns() -> Arrays {
        let mut p = Vec::new();
        for (r, top) in [(0.5, -3.0), (1.5, -2.0), (2.5, 0.5), (4.5, 0.0)] {
            for k in 0..5 {
                p.push([r, 0.0, top - k as f64]);
            }
        }
        let n = p.len();
        (p, vec![[0.0; 3]; n], vec![1.0; n], vec![1; n])
    }

    #[test]
    fn hand_made_columns() {
        let (p, v, m, b) = columns();
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = EjectaCriterion::new(&[1], 0.0);
        let o = CraterOptions::new(Geometry::Axisymmetric, 1.0);
        let prof = crater_profile(&view, &c, &o).unwrap();
        assert_eq!(prof.radius, vec![0.5, 1.5, 2.5, 3.5, 4.5]);
        assert_eq!(&prof.depth[..3], &[3.0, 2.0, -0.5]);
        assert!(prof.depth[3].is_nan());
        assert_eq!(prof.depth[4], 0.0);
        assert_eq!(prof.rim_height(), 0.5);
        // A top offset of 0.25 m lowers the reference plane.
        let o2 = CraterOptions {
            top_offset: 0.25,
            ..o
        };
        assert_eq!(crater_profile(&view, &c, &o2).unwrap().depth[0], 2.75);
    }

    #[test]
    fn ejecta_projectile_and_cut_particles_are_not_wall() {
        let (mut p, mut v, mut m, mut b) = columns();
        // Rising target particle above the axis bin: ejecta, ignored.
        p.push([0.2, 0.0, 5.0]);
        v.push([0.0, 0.0, 1.0]);
        m.push(1.0);
        b.push(1);
        // Projectile remnant in the crater: not target, ignored.
        p.push([0.3, 0.0, -0.5]);
        v.push([0.0; 3]);
        m.push(1.0);
        b.push(0);
        let n = p.len();
        let mut rho = vec![1000.0; n];
        let mut dmg = vec![0.0; n];
        rho[5] = 100.0; // the top of column 2 (z = −2) is rubble
        dmg[0] = 1.0; // the top of column 1 (z = −3) is fully damaged
        let view = ParticleView::new(&p, &v, &m, &b)
            .with_density(&rho)
            .with_damage(&dmg);
        let c = EjectaCriterion::new(&[1], 0.0);
        let o = CraterOptions::new(Geometry::Axisymmetric, 1.0);
        let prof = crater_profile(&view, &c, &o).unwrap();
        assert_eq!(&prof.depth[..2], &[3.0, 2.0]);
        let cut = CraterOptions {
            density_cut: Some(DensityCut {
                reference_density: 1000.0,
                min_fraction: 0.5,
            }),
            max_damage: Some(0.99),
            ..o
        };
        let prof = crater_profile(&view, &c, &cut).unwrap();
        assert_eq!(&prof.depth[..2], &[4.0, 3.0]);
        let bare = ParticleView::new(&p, &v, &m, &b);
        assert_eq!(
            crater_profile(&bare, &c, &cut),
            Err(ImpactError::MissingField("density"))
        );
    }

    #[test]
    fn errors_instead_of_panics() {
        let (p, v, m, b) = columns();
        let view = ParticleView::new(&p, &v, &m, &b);
        let o = CraterOptions::new(Geometry::ThreeD, 1.0);
        let none = EjectaCriterion::new(&[9], 0.0);
        assert!(matches!(
            crater_profile(&view, &none, &o),
            Err(ImpactError::EmptySelection(_))
        ));
        let tiny = CraterOptions::new(Geometry::ThreeD, 1e-9);
        assert!(matches!(
            crater_profile(&view, &EjectaCriterion::new(&[1], 0.0), &tiny),
            Err(ImpactError::TooManyBins { .. })
        ));
    }

    /// An RZ bed of rings spaced `d` apart (ρ = 1, ring masses 2π r d²), 4 layers deep,
    /// its top layer half a spacing down, out to radius 12.
    fn bed(d: f64) -> (Vec<[f64; 3]>, Vec<f64>) {
        let (mut p, mut m) = (Vec::new(), Vec::new());
        let mut r = 0.5 * d;
        while r < 12.0 {
            for k in 0..4 {
                p.push([r, 0.0, -(k as f64 + 0.5) * d]);
                m.push(2.0 * std::f64::consts::PI * r * d * d);
            }
            r += d;
        }
        (p, m)
    }

    #[test]
    fn a_footprint_covers_the_bins_between_wide_columns() {
        let (p, m) = bed(3.0);
        let n = p.len();
        let (v, b, rho) = (vec![[0.0; 3]; n], vec![1u16; n], vec![1.0; n]);
        let view = ParticleView::new(&p, &v, &m, &b).with_density(&rho);
        let c = EjectaCriterion::new(&[1], 0.0);
        let plain = CraterOptions::new(Geometry::Axisymmetric, 1.0);
        // Centres at r = 1.5, 4.5, 7.5, 10.5: bins 1, 4, 7, 10; the others are empty.
        let d = crater_profile(&view, &c, &plain).unwrap().depth;
        assert_eq!(d.len(), 11);
        assert_eq!(d.iter().filter(|x| x.is_nan()).count(), 7, "{d:?}");
        // Each ring covers its spacing, [r − 1.5, r + 1.5): every bin reads the top layer.
        let wide = CraterOptions {
            footprint: true,
            ..plain
        };
        let d = crater_profile(&view, &c, &wide).unwrap().depth;
        assert_eq!(d, vec![1.5; 12]);
        // The footprint needs the density.
        let bare = ParticleView::new(&p, &v, &m, &b);
        assert_eq!(
            crater_profile(&bare, &c, &wide),
            Err(ImpactError::MissingField("density"))
        );
    }

    #[test]
    fn a_quarter_models_footprint_is_one_copys_size() {
        // A pit on the axis (top at z = −5) beside a unit cube at s = 1.6 with its top
        // at z = 0; the view carries the cube's four mirror copies' mass, 4.
        let p = [[0.0, 0.0, -5.0], [1.6, 0.0, 0.0]];
        let (v, b, m, rho) = ([[0.0; 3]; 2], [1u16; 2], [4.0, 4.0], [1.0; 2]);
        let view = ParticleView::new(&p, &v, &m, &b).with_density(&rho);
        let c = EjectaCriterion::new(&[1], 0.0);
        let whole = CraterOptions {
            footprint: true,
            ..CraterOptions::new(Geometry::ThreeD, 1.0)
        };
        // Read as one particle of volume 4 (side 1.587), the cube reaches into the axis
        // bin and hides the pit.
        assert_eq!(crater_profile(&view, &c, &whole).unwrap().depth[0], 0.0);
        // As one copy of volume 1 it covers [1.1, 2.1): bins 1 and 2 only.
        let quarter = CraterOptions {
            copies: 4.0,
            ..whole
        };
        let d = crater_profile(&view, &c, &quarter).unwrap().depth;
        assert_eq!(d, vec![5.0, 0.0, 0.0]);
    }

    #[test]
    fn the_ring_size_is_its_spacing_off_the_axis_and_bounded_on_it() {
        let ring = |r: f64, d: f64| 2.0 * std::f64::consts::PI * r * d * d * 2.0;
        let w = spacing(Geometry::Axisymmetric, 4.0, ring(4.0, 0.5), 2.0);
        assert!((w - 0.5).abs() < 1e-12, "{w}");
        // On the axis the ring's radius is at least half its side: w³ = m/(πρ).
        let m = 3.0;
        let on = spacing(Geometry::Axisymmetric, 0.0, m, 2.0);
        assert!((on.powi(3) - m / (std::f64::consts::PI * 2.0)).abs() < 1e-12);
        // Continuous where the two meet (s = w/2).
        let at = spacing(Geometry::Axisymmetric, 0.5 * on, m, 2.0);
        assert!((at - on).abs() < 1e-12, "{at} {on}");
        let cube = spacing(Geometry::ThreeD, 7.0, 8.0, 1.0);
        assert_eq!(spacing(Geometry::Plane, 7.0, 8.0, 2.0), 2.0);
        assert_eq!(spacing(Geometry::Line, 0.0, 8.0, 2.0), 4.0);
        assert!((cube - 2.0).abs() < 1e-12);
    }

    #[test]
    fn a_profile_reads_against_its_reference_bin_by_bin() {
        let nan = f64::NAN;
        let prof = |depth: Vec<f64>| CraterProfile {
            radius: (0..depth.len()).map(|k| k as f64 + 0.5).collect(),
            depth,
        };
        let now = prof(vec![nan, 2.0, 3.0, nan, 5.0]);
        let d = now.relative_to(&prof(vec![1.0, nan, 0.5])).unwrap().depth;
        assert!(d[0].is_nan() && d[3].is_nan());
        // Bin 1 takes the reference of bin 0, bin 4 that of the last reference bin.
        assert_eq!((d[1], d[2], d[4]), (1.0, 2.5, 4.5));
        // With nothing inside, the first reference bin outside is used.
        let d = now.relative_to(&prof(vec![nan, 2.0])).unwrap().depth;
        assert_eq!((d[1], d[2]), (0.0, 1.0));
        assert!(now.relative_to(&prof(vec![nan, nan])).is_err());
        let other_bins = CraterProfile {
            radius: vec![1.0, 3.0],
            depth: vec![0.0, 0.0],
        };
        assert!(now.relative_to(&other_bins).is_err());
    }
}

//! Crater depth, diameter (including the spall zone) and central-bowl diameter, read from
//! the crater profile (paper §5 asks for both measurements to be defined precisely; they
//! are here and in docs/diagnostics.md §4).
//!
//! * **Run from the axis.** Walking outwards from the axis, the bins that satisfy a test
//!   form a run until the first non-empty bin that fails it. Empty bins (NaN, no wall
//!   particle — typically a bin narrower than the local particle spacing) carry no
//!   evidence: they neither end a run nor extend it. The run's radius is the outer edge
//!   of its last non-empty bin, so an edge is never placed where there are no particles.
//! * **Diameter** (the experiment's, spall zone included): 2 × the radius of the run of
//!   bins deeper than `depth_threshold`. Contiguity from the axis keeps isolated dents
//!   and debris beyond the rim out. With `spall_damage` set, the run is read from the
//!   *spall profile*, in which target material damaged above it counts as removed
//!   ([`CraterOptions::spall_damage`]); the diameter of the removed material alone is
//!   kept as `diameter_removed`.
//! * **Depth**: the largest depth inside that run; with no run (no crater), the depth of
//!   the innermost non-empty bin (below the threshold, possibly negative).
//! * **Bowl diameter**: 2 × the radius of the run of bins at least `bowl_fraction` × depth
//!   deep: the central pit, as opposed to the shallow spall annulus around it. 0 when the
//!   depth is not positive.
//!
//! With a steep wall, the edge bin holds both floor and untouched surface particles and
//! reads as the surface, so a radius is found to within one bin below the true edge.

use crate::crater_options::CraterOptions;
use crate::crater_profile::{CraterProfile, crater_profile};
use crate::ejecta::EjectaCriterion;
use crate::error::ImpactError;
use crate::particles_view::ParticleView;
use serde::{Deserialize, Serialize};

/// Crater sizes and the profile they were read from.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Crater {
    /// Crater depth below the original surface (m).
    pub depth: f64,
    /// Crater diameter including the spall zone (m); 0 if there is no crater. Equal to
    /// `diameter_removed` without `spall_damage`.
    pub diameter: f64,
    /// Diameter of the run of bins where material was removed (m), spall still in place
    /// counting as surface.
    pub diameter_removed: f64,
    /// Diameter of the central bowl (m); 0 if there is no crater.
    pub bowl_diameter: f64,
    /// Highest raised rim above the original surface (m, ≥ 0).
    pub rim_height: f64,
    /// The depth profile (signed; NaN in empty bins).
    pub profile: CraterProfile,
    /// The profile with spall counted as removed (`spall_damage` set), else `None`.
    pub spall_profile: Option<CraterProfile>,
}

/// Profile and sizes of the crater in `view` (see [`crater_profile`] and
/// [`measure_crater`]).
pub fn crater(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
) -> Result<Crater, ImpactError> {
    crater_against(view, criterion, options, None)
}

/// As [`crater`], with both profiles (removed material and spall) read against
/// `reference`, the profile of the untouched target with the same options
/// ([`CraterProfile::relative_to`]); `None` reads them against the plane
/// `surface_z − top_offset`.
pub fn crater_against(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    options: &CraterOptions,
    reference: Option<&CraterProfile>,
) -> Result<Crater, ImpactError> {
    let read = |o: &CraterOptions| {
        let p = crater_profile(view, criterion, o)?;
        match reference {
            Some(r) => p.relative_to(r),
            None => Ok(p),
        }
    };
    let profile = read(options)?;
    let c = measure_crater(profile, options);
    let Some(spall) = options.spall_damage else {
        return Ok(c);
    };
    let cut = CraterOptions {
        max_damage: Some(options.max_damage.map_or(spall, |m| m.min(spall))),
        ..*options
    };
    match read(&cut) {
        Ok(spall_profile) => Ok(c.with_spall(spall_profile, options)),
        // Every wall particle is spall (a small, wholly fractured target): the whole
        // target would be crater, and no diameter can be read; NaN says so.
        Err(ImpactError::EmptySelection(_)) => Ok(Crater {
            diameter: f64::NAN,
            ..c
        }),
        Err(e) => Err(e),
    }
}

impl Crater {
    /// The crater with its diameter read from `spall_profile` (the run from the axis of
    /// bins deeper than the threshold, as for the removed material); depth, bowl and rim
    /// stay those of the removed material.
    pub fn with_spall(mut self, spall_profile: CraterProfile, options: &CraterOptions) -> Self {
        let n = spall_profile.depth.len().min(spall_profile.radius.len());
        self.diameter = run_from_axis(&spall_profile.depth[..n], |x| x > options.depth_threshold)
            .map_or(0.0, |last| 2.0 * outer_edge(&spall_profile, last));
        self.spall_profile = Some(spall_profile);
        self
    }
}

/// Depth, diameter, bowl diameter and rim height of a profile, using the thresholds of
/// `options` (the module documentation gives the definitions). Never panics: a profile
/// with no non-empty bin gives zeros, and of a hand-built profile with more depths than
/// radii only the bins with both are read.
pub fn measure_crater(profile: CraterProfile, options: &CraterOptions) -> Crater {
    let n = profile.depth.len().min(profile.radius.len());
    let d = &profile.depth[..n];
    let crater_run = run_from_axis(d, |x| x > options.depth_threshold);
    let depth = match crater_run {
        Some(last) => d[..=last]
            .iter()
            .filter(|x| !x.is_nan())
            .fold(f64::MIN, |a, &x| a.max(x)),
        None => d.iter().copied().find(|x| !x.is_nan()).unwrap_or(0.0),
    };
    let diameter = crater_run.map_or(0.0, |last| 2.0 * outer_edge(&profile, last));
    let bowl_level = options.bowl_fraction * depth;
    let bowl_diameter = if crater_run.is_some() && depth > 0.0 {
        run_from_axis(d, |x| x >= bowl_level).map_or(0.0, |last| 2.0 * outer_edge(&profile, last))
    } else {
        0.0
    };
    Crater {
        depth,
        diameter,
        diameter_removed: diameter,
        bowl_diameter,
        rim_height: profile.rim_height(),
        profile,
        spall_profile: None,
    }
}

/// Index of the last non-empty bin of the run from the axis whose depths pass `test`, or
/// `None` if the first non-empty bin fails (or all are empty). Empty bins are skipped.
pub fn run_from_axis(depth: &[f64], test: impl Fn(f64) -> bool) -> Option<usize> {
    let mut last = None;
    for (k, &x) in depth.iter().enumerate() {
        if x.is_nan() {
            continue;
        }
        if !test(x) {
            break;
        }
        last = Some(k);
    }
    last
}

/// Outer edge (m) of bin `k`: centres are (k + ½) b, so the edge is r_k + r_0 = (k + 1) b.
fn outer_edge(profile: &CraterProfile, k: usize) -> f64 {
    profile.radius[k] + profile.radius[0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::particles_view::Geometry;

    fn profile(depth: &[f64]) -> CraterProfile {
        CraterProfile {
            radius: (0..depth.len()).map(|k| k as f64 + 0.5).collect(),
            depth: depth.to_vec(),
        }
    }

    fn opts() -> CraterOptions {
        CraterOptions::new(Geometry::Axisymmetric, 1.0)
    }

    #[test]
    fn bowl_spall_and_rim_by_hand() {
        // Bowl 8, 6, 4 deep; spall 2, 2; rim −0.5; flat; a deep dent further out.
        let c = measure_crater(profile(&[8.0, 6.0, 4.0, 2.0, 2.0, -0.5, 0.0, 5.0]), &opts());
        assert_eq!(c.depth, 8.0);
        assert_eq!(c.diameter, 10.0); // bins 0–4, outer edge 5
        assert_eq!(c.bowl_diameter, 6.0); // depth ≥ ½ × 8: bins 0–2, outer edge 3
        assert_eq!(c.rim_height, 0.5);
    }

    #[test]
    fn empty_bins_neither_end_nor_extend_a_run() {
        let nan = f64::NAN;
        let c = measure_crater(profile(&[nan, 6.0, nan, 2.0, nan, 0.0]), &opts());
        assert_eq!((c.depth, c.diameter, c.bowl_diameter), (6.0, 8.0, 4.0));
        let none = measure_crater(profile(&[nan, 0.5, 3.0]), &opts());
        assert_eq!(
            (none.depth, none.diameter, none.bowl_diameter),
            (0.5, 0.0, 0.0)
        );
        let empty = measure_crater(profile(&[nan, nan]), &opts());
        assert_eq!((empty.depth, empty.diameter), (0.0, 0.0));
        assert_eq!(run_from_axis(&[], |_| true), None);
    }

    #[test]
    fn inconsistent_profile_does_not_panic() {
        let p = CraterProfile {
            radius: vec![0.5],
            depth: vec![3.0, 3.0, 0.0],
        };
        assert_eq!(measure_crater(p, &opts()).diameter, 2.0);
    }

    #[test]
    fn spall_widens_the_diameter_only() {
        // Removed: bowl 8, 6 deep, then surface. Spall profile: the fractured layer
        // 3 deep out to bin 4, deeper under the bowl (crushed rock).
        let c = measure_crater(profile(&[8.0, 6.0, 0.0, 0.5, 0.0, 0.0]), &opts())
            .with_spall(profile(&[12.0, 10.0, 3.0, 3.0, 3.0, 0.0]), &opts());
        assert_eq!((c.diameter, c.diameter_removed), (10.0, 4.0));
        assert_eq!((c.depth, c.bowl_diameter), (8.0, 4.0));
    }

    #[test]
    fn fractured_top_layer_counts_in_the_diameter_of_a_view() {
        use crate::ejecta::EjectaCriterion;
        use crate::particles_view::ParticleView;
        // RZ columns 1 m apart, 5 particles deep: a 3 m bowl in the first, surface
        // beyond; the top two particles of columns 1 and 2 are fully damaged, and so is
        // the bowl's floor (crushed rock).
        let mut p = Vec::new();
        let mut dmg = Vec::new();
        for (k, top) in [-3.0, 0.0, 0.0, 0.0].into_iter().enumerate() {
            for j in 0..5 {
                p.push([k as f64 + 0.5, 0.0, top - j as f64]);
                dmg.push(if k <= 2 && j < 2 { 1.0 } else { 0.0 });
            }
        }
        let n = p.len();
        let (v, m, b) = (vec![[0.0; 3]; n], vec![1.0; n], vec![1u16; n]);
        let view = ParticleView::new(&p, &v, &m, &b).with_damage(&dmg);
        let c = EjectaCriterion::new(&[1], 0.0);
        let plain = opts();
        let with = CraterOptions {
            spall_damage: Some(0.9),
            ..plain
        };
        let a = crater(&view, &c, &plain).unwrap();
        assert_eq!((a.diameter, a.diameter_removed, a.depth), (2.0, 2.0, 3.0));
        assert!(a.spall_profile.is_none());
        let s = crater(&view, &c, &with).unwrap();
        // Spall 2 deep in columns 1–2: the diameter reaches the outer edge of column 2;
        // the depth stays the bowl's 3, not the 5 of the crushed floor.
        assert_eq!((s.diameter, s.diameter_removed, s.depth), (6.0, 2.0, 3.0));
        assert_eq!(s.spall_profile.unwrap().depth, vec![5.0, 2.0, 2.0, 0.0]);
        // A wholly fractured target leaves nothing to read: NaN, not a number made up.
        let all = vec![1.0; n];
        let broken = ParticleView::new(&p, &v, &m, &b).with_damage(&all);
        let w = crater(&broken, &c, &with).unwrap();
        assert!(w.diameter.is_nan() && w.depth == 3.0);
    }

    #[test]
    fn a_bump_is_not_a_crater() {
        let c = measure_crater(profile(&[-1.0, -0.5, 0.0]), &opts());
        assert_eq!(
            (c.depth, c.diameter, c.bowl_diameter, c.rim_height),
            (-1.0, 0.0, 0.0, 1.0)
        );
    }
}

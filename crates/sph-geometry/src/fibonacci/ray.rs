//! The body along one ray x0 + r u: which stretches of a radius interval lie inside.
//!
//! Membership is sampled at equally spaced radii including both ends; where two
//! consecutive samples disagree the crossing is located by bisection. A surface is thus
//! found to round-off whether it cuts the interval obliquely or runs parallel to the
//! layers (a sphere concentric with them); only features thinner than the sample step
//! along the ray can be missed.

use sph_core::glam::DVec3;

/// Bisection steps locating a crossing: the sample step shrinks by 2^-40 (≈1e-12).
const BISECTION_STEPS: usize = 40;

/// Appends to `out` (after clearing it) the inside intervals `(r_in, r_out)` of the ray
/// `origin + r u` for r in `[lo, hi]`, sampled at `samples + 1` radii.
pub(crate) fn inside_intervals(
    inside: &impl Fn(DVec3) -> bool,
    origin: DVec3,
    u: DVec3,
    (lo, hi): (f64, f64),
    samples: usize,
    out: &mut Vec<(f64, f64)>,
) {
    out.clear();
    let at = |r: f64| inside(origin + u * r);
    let step = (hi - lo) / samples as f64;
    let mut prev = at(lo);
    let mut prev_r = lo;
    let mut start = prev.then_some(lo);
    for j in 1..=samples {
        let r = if j == samples {
            hi
        } else {
            lo + j as f64 * step
        };
        let cur = at(r);
        if cur != prev {
            let (mut a, mut b) = (prev_r, r);
            for _ in 0..BISECTION_STEPS {
                let mid = 0.5 * (a + b);
                if at(mid) == prev {
                    a = mid;
                } else {
                    b = mid;
                }
            }
            let crossing = 0.5 * (a + b);
            match start.take() {
                Some(s) => out.push((s, crossing)),
                None => start = Some(crossing),
            }
        }
        prev = cur;
        prev_r = r;
    }
    if let Some(s) = start {
        out.push((s, hi));
    }
}

/// Σ (b³ − a³) over the intervals: 3 × ∫ r² dr, the radial volume weight.
#[inline]
pub(crate) fn cubed_length(intervals: &[(f64, f64)]) -> f64 {
    intervals.iter().map(|&(a, b)| b.powi(3) - a.powi(3)).sum()
}

/// The cubed length of the intervals below and above the radius `split`.
#[inline]
pub(crate) fn cubed_length_split(intervals: &[(f64, f64)], split: f64) -> (f64, f64) {
    let mut below = 0.0;
    let mut above = 0.0;
    for &(a, b) in intervals {
        if b <= split {
            below += b.powi(3) - a.powi(3);
        } else if a >= split {
            above += b.powi(3) - a.powi(3);
        } else {
            below += split.powi(3) - a.powi(3);
            above += b.powi(3) - split.powi(3);
        }
    }
    (below, above)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_crossings_to_round_off() {
        // Inside when 1.3 ≤ |x| ≤ 2.71 (a hollow ball), ray along x.
        let inside = |p: DVec3| (1.3..=2.71).contains(&p.length());
        let mut iv = Vec::new();
        for samples in [1, 3, 8] {
            inside_intervals(&inside, DVec3::ZERO, DVec3::X, (1.0, 3.0), samples, &mut iv);
            if samples == 1 {
                // Both ends outside: the hollow shell between the samples is missed.
                assert!(iv.is_empty());
                continue;
            }
            assert_eq!(iv.len(), 1);
            assert!((iv[0].0 - 1.3).abs() < 1e-11 && (iv[0].1 - 2.71).abs() < 1e-11);
        }
        inside_intervals(&inside, DVec3::ZERO, DVec3::X, (2.0, 2.5), 2, &mut iv);
        assert_eq!(iv, vec![(2.0, 2.5)]);
        // Two separate stretches.
        let two = |p: DVec3| p.x < 1.5 || p.x > 2.5;
        inside_intervals(&two, DVec3::ZERO, DVec3::X, (1.0, 3.0), 4, &mut iv);
        assert_eq!(iv.len(), 2);
        assert!((iv[0].1 - 1.5).abs() < 1e-11 && (iv[1].0 - 2.5).abs() < 1e-11);
    }

    #[test]
    fn cubed_lengths() {
        let iv = [(1.0, 2.0), (3.0, 4.0)];
        assert_eq!(cubed_length(&iv), 7.0 + 37.0);
        assert_eq!(
            cubed_length_split(&iv, 1.5),
            (1.5f64.powi(3) - 1.0, 8.0 - 1.5f64.powi(3) + 37.0)
        );
        assert_eq!(cubed_length_split(&iv, 2.5), (7.0, 37.0));
    }
}

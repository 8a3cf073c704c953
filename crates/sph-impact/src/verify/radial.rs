//! Radial profiles of 2-D/3-D runs: per-particle values against r, and binned means.

use super::outcome::Outcome;
use crate::Simulation;
use sph_core::{Dimension, Vector};
use sph_diagnostics::error_norms;
use sph_diagnostics::exact::RadialState;
use sph_kernel::Kernel;

/// Per-particle radial data, sorted by r.
pub(crate) struct Radial {
    pub r: Vec<f64>,
    pub rho: Vec<f64>,
    pub vr: Vec<f64>,
    pub p: Vec<f64>,
    pub e: Vec<f64>,
    /// Particle volume m/ρ (the norm weight).
    pub w: Vec<f64>,
}

impl Radial {
    /// Collects the radial profile about the origin.
    pub fn of<D: Dimension, K: Kernel>(sim: &Simulation<D, K>) -> Self {
        Self::with(sim, |x, v| {
            let r = x.norm();
            (r, if r > 0.0 { v.dot(x) / r } else { 0.0 })
        })
    }

    /// The profile along coordinate `axis` (a planar problem run in more dimensions):
    /// "r" is that coordinate and "v_r" that velocity component.
    pub fn along<D: Dimension, K: Kernel>(sim: &Simulation<D, K>, axis: usize) -> Self {
        Self::with(sim, |x, v| (x.component(axis), v.component(axis)))
    }

    /// The profile with (r, v_r) of each particle from `coord(x, v)`.
    fn with<D: Dimension, K: Kernel>(
        sim: &Simulation<D, K>,
        coord: impl Fn(D::Vector, D::Vector) -> (f64, f64),
    ) -> Self {
        let (pr, _) = sim.pressure_and_sound_speed();
        let pa = &sim.state.particles;
        let mut idx: Vec<usize> = (0..pa.len()).collect();
        let r_of = |i: usize| coord(pa.position[i], pa.velocity[i]).0;
        idx.sort_by(|&a, &b| r_of(a).total_cmp(&r_of(b)));
        let vr = |i: usize| coord(pa.position[i], pa.velocity[i]).1;
        Radial {
            r: idx.iter().map(|&i| r_of(i)).collect(),
            rho: idx.iter().map(|&i| pa.density[i]).collect(),
            vr: idx.iter().map(|&i| vr(i)).collect(),
            p: idx.iter().map(|&i| pr[i]).collect(),
            e: idx.iter().map(|&i| pa.specific_energy[i]).collect(),
            w: idx.iter().map(|&i| pa.mass[i] / pa.density[i]).collect(),
        }
    }

    /// Mean density in radial bins of width `dr`: (bin centre, mean) for non-empty bins.
    pub fn binned_density(&self, dr: f64) -> (Vec<f64>, Vec<f64>) {
        let nb = (self.r.last().copied().unwrap_or(0.0) / dr).ceil() as usize + 1;
        let (mut s, mut c) = (vec![0.0; nb], vec![0usize; nb]);
        for (r, rho) in self.r.iter().zip(&self.rho) {
            let b = (r / dr) as usize;
            s[b] += rho;
            c[b] += 1;
        }
        (0..nb)
            .filter(|&b| c[b] > 0)
            .map(|b| ((b as f64 + 0.5) * dr, s[b] / c[b] as f64))
            .unzip()
    }

    /// Relative L1 difference of this profile's binned density from `reference`'s,
    /// Σ|ρ̄ − ρ̄_ref| / Σ ρ̄_ref over the bins of width `dr` whose centres lie in
    /// [`lo`, `hi`] and hold particles of both (so a planar profile taken across a 2-D
    /// column is compared by its cross-section means, row scatter averaged out).
    pub fn binned_difference(&self, reference: &Radial, dr: f64, lo: f64, hi: f64) -> f64 {
        let (rc, mine) = self.binned_density(dr);
        let (rr, theirs) = reference.binned_density(dr);
        let bin = |r: f64| (r / dr).floor() as i64;
        let theirs: std::collections::HashMap<i64, f64> =
            rr.iter().map(|&r| bin(r)).zip(theirs).collect();
        let (mut diff, mut norm) = (0.0, 0.0);
        for (r, m) in rc.iter().zip(&mine).filter(|(r, _)| (lo..=hi).contains(*r)) {
            if let Some(t) = theirs.get(&bin(*r)) {
                diff += (m - t).abs();
                norm += t.abs();
            }
        }
        diff / norm
    }

    /// The profile as rows (r, rho, vr, p, e, and the exact columns given).
    pub fn rows(&self, exact: &[(f64, f64, f64, f64)]) -> Vec<Vec<f64>> {
        (0..self.r.len())
            .map(|k| {
                vec![
                    self.r[k],
                    self.rho[k],
                    self.vr[k],
                    self.p[k],
                    self.e[k],
                    exact[k].0,
                    exact[k].1,
                    exact[k].2,
                    exact[k].3,
                ]
            })
            .collect()
    }
}

impl Radial {
    /// L1 and Linf of density, radial velocity, pressure (and specific energy when
    /// `with_e`) against `exact` (one state per particle), over the particles `include`
    /// selects, recorded as `l1_rho`, `linf_rho`, … in `out`.
    pub fn set_norms(
        &self,
        out: &mut Outcome,
        exact: &[RadialState],
        include: impl Fn(usize) -> bool + Copy,
        with_e: bool,
    ) {
        let fields: [Field; 4] = [
            ("rho", &self.rho, |s| s.density),
            ("v", &self.vr, |s| s.velocity),
            ("p", &self.p, |s| s.pressure),
            ("e", &self.e, |s| s.specific_energy),
        ];
        for (name, numerical, pick) in fields.into_iter().take(if with_e { 4 } else { 3 }) {
            let ex: Vec<f64> = exact.iter().map(pick).collect();
            let n = error_norms(numerical, &ex, &self.w, include);
            out.set(&format!("l1_{name}"), n.l1);
            out.set(&format!("linf_{name}"), n.linf);
        }
    }
}

/// A profile field: its name, the particle values and how to read it from an exact state.
type Field<'a> = (&'static str, &'a Vec<f64>, fn(&RadialState) -> f64);

/// Samples the exact density, velocity and pressure on (0, r_max] for the plot.
pub(crate) fn push_exact_curves(out: &mut Outcome, r_max: f64, state: impl Fn(f64) -> RadialState) {
    let samples: Vec<(f64, RadialState)> = (1..=1000)
        .map(|k| k as f64 / 1000.0 * r_max)
        .map(|r| (r, state(r)))
        .collect();
    let curve =
        |pick: fn(&RadialState) -> f64| samples.iter().map(|(r, s)| (*r, pick(s))).collect();
    out.exact.push(("rho".into(), curve(|s| s.density)));
    out.exact.push(("v".into(), curve(|s| s.velocity)));
    out.exact.push(("p".into(), curve(|s| s.pressure)));
}

/// Column names matching [`Radial::rows`].
pub(crate) const RADIAL_COLUMNS: [&str; 9] = [
    "r",
    "rho",
    "vr",
    "p",
    "e",
    "rho_exact",
    "vr_exact",
    "p_exact",
    "e_exact",
];

#[cfg(test)]
mod tests {
    use super::Radial;

    fn profile(r: &[f64], rho: &[f64]) -> Radial {
        Radial {
            r: r.to_vec(),
            rho: rho.to_vec(),
            vr: vec![0.0; r.len()],
            p: vec![0.0; r.len()],
            e: vec![0.0; r.len()],
            w: vec![1.0; r.len()],
        }
    }

    /// Bin means are compared, not particles: two particles of one bin at 3 and 5 read
    /// as 4; a bin outside the window and a bin the reference lacks are left out.
    #[test]
    fn binned_difference_compares_bin_means_inside_the_window() {
        let reference = profile(&[0.15, 0.25, 0.35, 0.95], &[4.0, 2.0, 1.0, 7.0]);
        let column = profile(&[0.12, 0.18, 0.25, 0.55, 0.95], &[3.0, 5.0, 2.2, 9.0, 1.0]);
        let d = column.binned_difference(&reference, 0.1, 0.1, 0.6);
        // Bins 0.1–0.2 (4 against 4) and 0.2–0.3 (2.2 against 2): 0.2 / 6.
        approx::assert_relative_eq!(d, 0.2 / 6.0, max_relative = 1e-12);
    }
}

//! What lies beyond the strongest seeded flaw.
//!
//! Benz–Asphaug seeding deals the body's flaws j = 1, 2, … until every particle holds
//! one: about N (ln N + 0.58) of them, so the strongest seeded flaw has the threshold
//!
//! ```text
//! ε_top = (J / (kV))^(1/m),   J = the number of seeded flaws
//! ```
//!
//! (docs/verification.md, "Damage: tensile bar with Benz–Asphaug flaws"). The Weibull population
//! n(ε) = k ε^m itself has no end: a real body strained past ε_top holds flaws that keep
//! activating. A particle of the seeded body has, on average, 1/N of the body's flaws below any
//! strain, k (V/N) ε^m (N the particles the flaws were dealt over: in RZ the 3-D particles the
//! rings stand for), so with [`FlawTail::Continuum`] its active count continues past its seeded
//! flaws as
//!
//! ```text
//! n_act(ε) = n_tot + k (V/N) (ε^m − ε_top^m),   ε > ε_top,
//! ```
//!
//! a real number, where n_tot is the particle's seeded count (all active there). Below
//! ε_top nothing changes: activation, the slow-rate strength E ε_1 and the size effect are
//! the seeded flaws'.
//!
//! Why it matters: under a fast load the strain at the peak stress passes ε_top, and with
//! the seeded population alone every flaw is active, damage grows at a fixed rate, and
//! the peak stress grows ∝ ε̇ instead of the Grady–Kipp ε̇^(3/(m+3)) (docs/verification.md,
//! tensile bar). With the continued tail and [`crate::GrowthLaw::CrackVolume`] the damage
//! of a particle under ε = ε̇ t past ε_top follows D ∝ k c_g³ ε̇^m t^(m+3), the Grady–Kipp
//! law (Grady & Kipp 1980; Melosh et al. 1992).

use serde::{Deserialize, Serialize};

/// Flaws beyond the strongest seeded one (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FlawTail {
    /// Only the seeded flaws exist (Benz & Asphaug 1995; miluphcuda; Spheral).
    #[default]
    Seeded,
    /// Past the strongest seeded flaw the active count continues as the Weibull
    /// population's mean per particle, k (V/N) ε^m.
    Continuum,
}

/// The continued tail of one seeded body: ε_top and the mean flaw count per particle per
/// unit strain^m, k V/N.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tail {
    /// ε_top, the threshold of the strongest seeded flaw.
    pub top_strain: f64,
    /// ε_top^m.
    top_power: f64,
    /// k V / N.
    kv_per_particle: f64,
    /// m.
    m: f64,
}

impl Tail {
    /// The tail of a body whose strongest seeded flaw is `top_strain`, with kV flaws per
    /// unit strain^m dealt over `n_particles` particles and Weibull exponent `m`.
    pub(crate) fn new(top_strain: f64, kv: f64, n_particles: usize, m: f64) -> Tail {
        Tail {
            top_strain,
            top_power: top_strain.powf(m),
            kv_per_particle: kv / n_particles as f64,
            m,
        }
    }

    /// The active count of a particle with `n_tot` seeded flaws at a strain past ε_top.
    #[inline]
    pub(crate) fn count(&self, n_tot: usize, strain: f64) -> f64 {
        n_tot as f64 + self.kv_per_particle * (strain.powf(self.m) - self.top_power)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tail_starts_at_the_seeded_count_and_follows_the_weibull_density() {
        // kV = 1e30, m = 9, 100 particles: 1e28 flaws per particle per strain^9.
        let (kv, m, n) = (1.0e30_f64, 9.0_f64, 100);
        let top = (500.0 / kv).powf(1.0 / m);
        let tail = Tail::new(top, kv, n, m);
        assert!((tail.count(6, top) - 6.0).abs() < 1e-9);
        // Doubling the strain multiplies the population by 2^9: the particle's mean share
        // of the flaws below 2 ε_top is 2^9 × 500/100 = 2560, of which 5 lay below ε_top.
        let at_double = tail.count(6, 2.0 * top);
        assert!(
            (at_double - (6.0 + 2560.0 - 5.0)).abs() < 1e-6,
            "{at_double}"
        );
    }
}

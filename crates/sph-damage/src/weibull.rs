//! Weibull flaw statistics and the deterministic Benz–Asphaug flaw seeding.
//!
//! A body of volume V holds n(ε) V = k V ε^m flaws with activation strain below ε
//! (paper §3.3). Benz & Asphaug (1995, CPC 87:253, §3) realise this population
//! explicitly: the j-th weakest flaw of the body has threshold
//!
//! ```text
//! ε_j = (j / (kV))^(1/m),   j = 1, 2, …
//! ```
//!
//! (the strain at which n(ε) V = j), and each flaw goes to a particle drawn uniformly at
//! random, until every particle holds at least one flaw. The total number of flaws is
//! then the coupon-collector number, N·H_N ≈ N (ln N + 0.5772) on average, i.e. about
//! ln N + 0.58 flaws per particle (docs/reference/weibull_flaws.md,
//! "Flaw statistics"). The weakest flaw of the body is exactly ε_1 = (kV)^(−1/m), so the body's static
//! strength is σ_b = E (kV)^(−1/m).
//!
//! Seeding is sequential (one random stream, flaws in order j = 1, 2, …), so the flaw
//! set depends only on (k, m, V, N, seed), never on the number of threads.
//!
//! A flaw is stored as its rank j (`u32`), not as its threshold: ε_j follows from j by
//! the formula above, evaluated by the same expression as at seeding, so the thresholds
//! are bit-identical, and the set takes 4 bytes per flaw instead of 8 (≈ 12 flaws per
//! particle in a body of 10⁵ particles: ≈ 50 bytes per particle less, at a few `powf`
//! per damage evaluation).

use crate::error::DamageError;
use crate::params::WeibullParams;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64Mcg;
use serde::{Deserialize, Serialize};

/// ε_min = (kV)^(−1/m): the activation strain of the weakest flaw in a volume V (the
/// strain at which k V ε^m = 1). Benz & Asphaug 1995; docs/reference/weibull_flaws.md,
/// "Flaw statistics".
#[inline]
pub fn min_activation_strain(k: f64, m: f64, volume: f64) -> f64 {
    (k * volume).powf(-1.0 / m)
}

/// Static tensile strength of a volume V: σ_b = E (kV)^(−1/m) (paper §3.3). The size
/// effect d ln σ_b / d ln V = −1/m.
#[inline]
pub fn static_strength(youngs_modulus: f64, k: f64, m: f64, volume: f64) -> f64 {
    youngs_modulus * min_activation_strain(k, m, volume)
}

/// The threshold of the j-th flaw (j ≥ 1) of a body with kV flaws per unit strain^m:
/// ε_j = (j/(kV))^(1/m). `inv_m` = 1/m.
#[inline]
fn threshold(j: u64, kv: f64, inv_m: f64) -> f64 {
    (j as f64 / kv).powf(inv_m)
}

/// The flaws of every particle in compressed-sparse-row form: the ranks j of the flaws
/// of particle i (the j-th weakest of the body, threshold ε_j = (j/(kV))^(1/m)) are
/// `ranks[offsets[i]..offsets[i+1]]`, strictly ascending, at least one per particle.
///
/// Serialisable for checkpoints (`params`, `total_volume`, `seed`, `offsets`, `ranks`,
/// `dealt_over`); deserialisation checks these invariants.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "FlawSetUnchecked")]
pub struct FlawSet {
    params: WeibullParams,
    total_volume: f64,
    seed: u64,
    offsets: Vec<u32>,
    ranks: Vec<u32>,
    /// The particles the flaws were dealt over ([`FlawSet::seed_dealt`]); the particle
    /// count unless dealt over more.
    dealt_over: u64,
    /// kV and 1/m, the threshold formula's constants (derived, not serialised).
    #[serde(skip)]
    kv: f64,
    #[serde(skip)]
    inv_m: f64,
    /// Whether every threshold is positive: the smallest, rank 1's, is (it is 0 only
    /// where (1/(kV))^(1/m) underflows, for an extreme m). Derived, not serialised.
    #[serde(skip)]
    positive: bool,
}

#[derive(Deserialize)]
struct FlawSetUnchecked {
    params: WeibullParams,
    total_volume: f64,
    seed: u64,
    offsets: Vec<u32>,
    ranks: Vec<u32>,
    /// Absent in sets stored before dealing existed: the particle count.
    #[serde(default)]
    dealt_over: Option<u64>,
}

impl TryFrom<FlawSetUnchecked> for FlawSet {
    type Error = DamageError;
    fn try_from(raw: FlawSetUnchecked) -> Result<Self, DamageError> {
        let corrupt = |reason| Err(DamageError::CorruptFlawSet { reason });
        if !(raw.total_volume.is_finite() && raw.total_volume > 0.0) {
            return corrupt("total volume is not positive and finite");
        }
        if raw.offsets.len() < 2 || raw.offsets[0] != 0 {
            return corrupt("offsets must start at 0 and cover at least one particle");
        }
        if raw.offsets.last().map(|&o| o as usize) != Some(raw.ranks.len()) {
            return corrupt("the last offset must equal the number of flaws");
        }
        for w in raw.offsets.windows(2) {
            if w[1] <= w[0] {
                return corrupt("every particle needs at least one flaw (offsets increasing)");
            }
            let r = &raw.ranks[w[0] as usize..w[1] as usize];
            if r[0] == 0 {
                return corrupt("flaw ranks start at 1");
            }
            if !r.windows(2).all(|p| p[0] < p[1]) {
                return corrupt("flaw ranks must be strictly ascending per particle");
            }
        }
        let kv = raw.params.k() * raw.total_volume;
        if !(kv.is_finite() && kv > 0.0) {
            return corrupt("k*V is not positive and finite");
        }
        let n = (raw.offsets.len() - 1) as u64;
        let dealt_over = raw.dealt_over.unwrap_or(n);
        if dealt_over < n {
            return corrupt("the flaws were dealt over fewer particles than keep them");
        }
        Ok(FlawSet {
            params: raw.params,
            total_volume: raw.total_volume,
            seed: raw.seed,
            offsets: raw.offsets,
            ranks: raw.ranks,
            dealt_over,
            kv,
            inv_m: 1.0 / raw.params.m(),
            positive: threshold(1, kv, 1.0 / raw.params.m()) > 0.0,
        })
    }
}

/// A uniform integer in `0..n` (n ≥ 1) from raw 64-bit outputs, by Lemire's multiply-
/// and-reject method (Lemire 2019, ACM TOMACS 29:3). Written out here rather than taken
/// from `rand`'s distributions so that the flaw set of a seed stays the same whatever
/// `rand` version samples ranges; rand_pcg's output stream is itself value-stable.
#[inline]
fn uniform_below<R: Rng>(rng: &mut R, n: u64) -> u64 {
    let mut product = u128::from(rng.next_u64()) * u128::from(n);
    let mut low = product as u64;
    if low < n {
        // Reject the values that would make some outcomes more likely.
        let threshold = n.wrapping_neg() % n;
        while low < threshold {
            product = u128::from(rng.next_u64()) * u128::from(n);
            low = product as u64;
        }
    }
    (product >> 64) as u64
}

impl FlawSet {
    /// The most particles a body can be seeded for (10⁸: its ≈ 1.9e9 flaws are counted
    /// in `u32`).
    pub const MAX_PARTICLES: usize = 100_000_000;

    /// Seeds flaws for `n_particles` particles of a body of total volume `total_volume`
    /// (m³) by the Benz–Asphaug procedure (module docs), with the random stream
    /// `Pcg64Mcg::seed_from_u64(seed)`. Same arguments → identical flaw set.
    pub fn seed_benz_asphaug(
        params: WeibullParams,
        n_particles: usize,
        total_volume: f64,
        seed: u64,
    ) -> Result<FlawSet, DamageError> {
        Self::seed_dealt(params, n_particles, n_particles, total_volume, seed)
    }

    /// Deals the flaws of a body of volume `total_volume` over `dealt_over` particles by
    /// the Benz–Asphaug procedure and keeps the flaws of the first `n_particles` of them
    /// (`n_particles ≤ dealt_over`). Each kept particle then has the flaws of one particle
    /// of a body of `dealt_over` particles: its weakest flaw has rank ~`dealt_over`, and
    /// about ln(`dealt_over`) + 0.58 flaws.
    ///
    /// An axisymmetric ring stands for the ≈ 2πr/Δ particles of a 3-D run around the
    /// axis; dealt over the rings alone, each ring would draw the flaws of its whole
    /// volume and be weaker than every particle it stands for. Dealt over the 3-D count,
    /// a ring's damage against strain follows that of a 3-D particle (docs/scenes.md,
    /// RZ). Since every dealt particle is equally likely to own each flaw, the first
    /// `n_particles` are as good a sample as any. With `dealt_over` = `n_particles` this
    /// is [`Self::seed_benz_asphaug`], bit for bit.
    pub fn seed_dealt(
        params: WeibullParams,
        n_particles: usize,
        dealt_over: usize,
        total_volume: f64,
        seed: u64,
    ) -> Result<FlawSet, DamageError> {
        if n_particles == 0 {
            return Err(DamageError::NoParticles);
        }
        // The flaws are counted in u32 (ranks and offsets): ≈ N (ln N + 0.58) of them,
        // 1.9e9 for the limit, well inside 2^32 whatever the draw.
        let limit = Self::MAX_PARTICLES;
        for count in [n_particles, dealt_over] {
            if count > limit {
                return Err(DamageError::TooManyParticles { count, limit });
            }
        }
        if dealt_over < n_particles {
            return Err(DamageError::Parameter {
                field: "dealt_over",
                value: dealt_over as f64,
                reason: "the flaws must be dealt over at least the particles that keep them",
            });
        }
        if !(total_volume.is_finite() && total_volume > 0.0) {
            return Err(DamageError::Parameter {
                field: "total_volume",
                value: total_volume,
                reason: "must be positive and finite",
            });
        }
        let kv = params.k() * total_volume;
        if !(kv.is_finite() && kv > 0.0) {
            return Err(DamageError::Parameter {
                field: "k*V",
                value: kv,
                reason: "the expected flaw count per unit strain^m must be positive and finite",
            });
        }

        // Pass 1: draw the owner of flaws j = 1, 2, … until every dealt particle has
        // one; record the owner of each kept flaw, and its rank j when some draws go to
        // particles that keep nothing (otherwise j is the draw's position, as in 3-D).
        let (n, all) = (n_particles, dealt_over);
        let as_u32 = |v: usize| {
            u32::try_from(v).map_err(|_| DamageError::TooManyParticles { count: all, limit })
        };
        let mut rng = Pcg64Mcg::seed_from_u64(seed);
        let mut counts = vec![0usize; n];
        // Particles n..all keep no flaws: only whether they have one yet matters.
        let mut others_covered = vec![false; all - n];
        let expected = (n as f64 * ((all as f64).ln() + 1.0)) as usize + 1;
        let mut owner: Vec<u32> = Vec::with_capacity(expected);
        let mut rank: Vec<u32> = Vec::new();
        let (mut uncovered, mut j) = (all, 0usize);
        while uncovered > 0 {
            let p = uniform_below(&mut rng, all as u64) as usize;
            j += 1;
            if p < n {
                if counts[p] == 0 {
                    uncovered -= 1;
                }
                counts[p] += 1;
                owner.push(p as u32);
                if all > n {
                    rank.push(as_u32(j)?);
                }
            } else if !others_covered[p - n] {
                others_covered[p - n] = true;
                uncovered -= 1;
            }
        }
        drop(others_covered);

        // Pass 2: CSR by a stable counting sort; flaws arrive in increasing j, so each
        // particle's ranks come out ascending.
        let mut offsets = Vec::with_capacity(n + 1);
        offsets.push(0u32);
        let mut total = 0usize;
        for &c in &counts {
            total += c;
            offsets.push(as_u32(total)?);
        }
        drop(counts);
        let mut cursor: Vec<u32> = offsets[..n].to_vec();
        let mut ranks = vec![0u32; total];
        for (k, &p) in owner.iter().enumerate() {
            let slot = &mut cursor[p as usize];
            ranks[*slot as usize] = match rank.get(k) {
                Some(&r) => r,
                None => as_u32(k + 1)?,
            };
            *slot += 1;
        }
        Ok(FlawSet {
            params,
            total_volume,
            seed,
            offsets,
            ranks,
            dealt_over: all as u64,
            kv,
            inv_m: 1.0 / params.m(),
            positive: threshold(1, kv, 1.0 / params.m()) > 0.0,
        })
    }

    /// As [`FlawSet::seed_benz_asphaug`], with the body volume V = Σ V_i from the
    /// particle volumes (m³, each positive and finite).
    pub fn seed_benz_asphaug_volumes(
        params: WeibullParams,
        volumes: &[f64],
        seed: u64,
    ) -> Result<FlawSet, DamageError> {
        Self::seed_volumes_dealt(params, volumes, volumes.len(), seed)
    }

    /// As [`FlawSet::seed_dealt`], with the body volume V = Σ V_i from the volumes of the
    /// particles that keep flaws (m³, each positive and finite).
    pub fn seed_volumes_dealt(
        params: WeibullParams,
        volumes: &[f64],
        dealt_over: usize,
        seed: u64,
    ) -> Result<FlawSet, DamageError> {
        for (index, &v) in volumes.iter().enumerate() {
            if !(v.is_finite() && v > 0.0) {
                return Err(DamageError::ParticleValue {
                    index,
                    field: "volume",
                    value: v,
                    reason: "must be positive and finite",
                });
            }
        }
        let total: f64 = volumes.iter().sum();
        Self::seed_dealt(params, volumes.len(), dealt_over, total, seed)
    }

    /// The threshold of the j-th weakest flaw of the body (j ≥ 1), ε_j = (j/(kV))^(1/m),
    /// computed exactly as in the seeding. `None` for j = 0.
    pub fn body_threshold(&self, j: u64) -> Option<f64> {
        (j >= 1).then(|| threshold(j, self.kv, self.inv_m))
    }

    /// ε_j of a stored rank.
    #[inline]
    fn rank_threshold(&self, j: u32) -> f64 {
        threshold(u64::from(j), self.kv, self.inv_m)
    }

    /// The Weibull parameters used.
    pub fn params(&self) -> WeibullParams {
        self.params
    }

    /// The body volume V used, m³.
    pub fn total_volume(&self) -> f64 {
        self.total_volume
    }

    /// The seed used.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The number of particles the flaws were dealt over (≥ [`Self::n_particles`];
    /// [`Self::seed_dealt`]).
    pub fn dealt_over(&self) -> u64 {
        self.dealt_over
    }

    /// Number of particles.
    pub fn n_particles(&self) -> usize {
        self.offsets.len() - 1
    }

    /// Total number of flaws in the body.
    pub fn total_flaws(&self) -> usize {
        self.ranks.len()
    }

    /// Mean flaws per particle (≈ ln N + 0.58 for Benz–Asphaug seeding).
    pub fn mean_flaws_per_particle(&self) -> f64 {
        self.total_flaws() as f64 / self.n_particles() as f64
    }

    /// Ranks j of the flaws of particle `i` (its flaws are the j-th weakest of the
    /// body), ascending; `None` if `i` is out of range.
    #[inline]
    pub fn ranks(&self, i: usize) -> Option<&[u32]> {
        let start = *self.offsets.get(i)? as usize;
        let end = *self.offsets.get(i + 1)? as usize;
        Some(&self.ranks[start..end])
    }

    /// Activation strains ε_j of particle `i`, ascending (computed from the ranks into
    /// a new vector: for inspection; the damage model uses [`Self::activated`]); `None`
    /// if `i` is out of range.
    pub fn thresholds(&self, i: usize) -> Option<Vec<f64>> {
        self.ranks(i)
            .map(|r| r.iter().map(|&j| self.rank_threshold(j)).collect())
    }

    /// Number of flaws of particle `i`.
    #[inline]
    pub fn n_flaws(&self, i: usize) -> Option<usize> {
        self.ranks(i).map(<[u32]>::len)
    }

    /// The threshold of the strongest flaw of the set (the largest stored rank; ε_J for
    /// J = [`Self::total_flaws`] when seeded by [`Self::seed_benz_asphaug`]).
    pub fn strongest_threshold(&self) -> f64 {
        let top = self.ranks.iter().copied().max().unwrap_or(1);
        self.rank_threshold(top)
    }

    /// Weakest flaw of particle `i`: the strain at which it starts to crack.
    #[inline]
    pub fn min_threshold(&self, i: usize) -> Option<f64> {
        self.ranks(i).map(|r| self.rank_threshold(r[0]))
    }

    /// Number of flaws of particle `i` activated at local strain `strain`, i.e. with
    /// threshold ≤ strain (a NaN or negative strain activates none).
    #[inline]
    pub fn activated(&self, i: usize, strain: f64) -> Option<usize> {
        let r = self.ranks(i)?;
        // A NaN or negative strain activates none (thresholds are ≥ 0), and a zero
        // strain none where every threshold is positive (ranks j ≥ 1, checked when the
        // set is made or read): decided without a power, as most of a body at rest or
        // in compression is.
        if !(strain >= 0.0) || (strain == 0.0 && self.positive) {
            return Some(0);
        }
        // Most particles are below their weakest flaw or past their strongest: one or
        // two thresholds decide, the bisection is for the rest.
        let n = r.len();
        Some(if !(self.rank_threshold(r[0]) <= strain) {
            0
        } else if self.rank_threshold(r[n - 1]) <= strain {
            n
        } else {
            1 + r[1..n - 1].partition_point(|&j| self.rank_threshold(j) <= strain)
        })
    }

    /// Heap and inline memory held, bytes.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of::<Self>()
            + self.offsets.capacity() * std::mem::size_of::<u32>()
            + self.ranks.capacity() * std::mem::size_of::<u32>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generator replaying fixed outputs, to drive the rejection branch.
    struct Replay(Vec<u64>, usize);
    impl rand::TryRng for Replay {
        type Error = core::convert::Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Self::Error> {
            Ok(self.try_next_u64()? as u32)
        }
        fn try_next_u64(&mut self) -> Result<u64, Self::Error> {
            self.1 += 1;
            Ok(self.0[self.1 - 1])
        }
        fn try_fill_bytes(&mut self, _dst: &mut [u8]) -> Result<(), Self::Error> {
            Ok(())
        }
    }

    #[test]
    fn uniform_below_maps_the_64_bit_range_by_its_high_product_word() {
        // n = 3: 2^64 mod 3 = 1, so only the raw value 0 (low word 0 < 1) is rejected.
        let mut r = Replay(vec![0, u64::MAX, 1 << 63], 0);
        assert_eq!(uniform_below(&mut r, 3), 2); // 0 rejected, then ⌊(2^64−1)·3/2^64⌋ = 2
        assert_eq!(r.1, 2);
        assert_eq!(uniform_below(&mut r, 3), 1); // ⌊2^63·3/2^64⌋ = 1
        let mut one = Replay(vec![12345], 0);
        assert_eq!(uniform_below(&mut one, 1), 0);
    }

    #[test]
    fn uniform_below_is_uniform() {
        // χ² over 7 bins of 70 000 draws; the 0.1 % critical value for 6 d.o.f. is 22.5.
        let mut rng = Pcg64Mcg::seed_from_u64(1);
        let mut bins = [0u32; 7];
        for _ in 0..70_000 {
            bins[uniform_below(&mut rng, 7) as usize] += 1;
        }
        let chi2: f64 = bins
            .iter()
            .map(|&b| (b as f64 - 10_000.0).powi(2) / 10_000.0)
            .sum();
        assert!(chi2 < 22.5, "{chi2} {bins:?}");
    }

    #[test]
    fn threshold_formula_point_values() {
        // kV = 1e10, m = 10: ε_j = (j/1e10)^(1/10), so ε_1 = 0.1 and ε_(1e10) = 1.
        assert!((threshold(1, 1e10, 0.1) - 0.1).abs() < 1e-16);
        assert_eq!(threshold(10_000_000_000, 1e10, 0.1), 1.0);
        assert!((min_activation_strain(1e9, 10.0, 10.0) - 0.1).abs() < 1e-16);
        assert!((static_strength(5e10, 1e9, 10.0, 10.0) - 5e9).abs() < 1e-5);
    }
}

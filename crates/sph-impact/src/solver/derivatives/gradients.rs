//! Pass 1: per real particle, the velocity, pressure and energy gradients, the linear
//! correction M⁻¹ and the grad-h factor Ω, from sums over its neighbours.

use super::*;
use crate::solver::chunks::{chunks_or_none, rows_or_empty};
use crate::solver::state::PairProbe;
use crate::solver::warm_threads::for_each_awake;
use sph_core::PickedRows;

/// Per-particle gradients (pass 1).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Gradients<D: Dimension> {
    pub velocity: D::Tensor,
    pub pressure: D::Vector,
    /// The grad-h factor Ω_i = 1 + h_i/(dρ_i) Σ_j m_j ∂W(r_ij, h_i)/∂h.
    pub omega: f64,
    /// The velocity gradient that drives the deviatoric stress (linearly corrected when
    /// `strain_rate_correction` is on). The Jaumann rate is formed from it when the stress
    /// is updated, so pass 2 does not hold a stress rate per particle.
    pub strain_velocity: D::Tensor,
}

impl<D: Dimension> Flat for Gradients<D> {
    const LEN: usize = 2 * D::DIM * D::DIM + D::DIM + 1;
    fn put(&self, out: &mut Vec<f64>) {
        put_tensor(&self.velocity, out);
        put_vector(self.pressure, out);
        out.push(self.omega);
        put_tensor(&self.strain_velocity, out);
    }
    fn get(v: &[f64]) -> Self {
        let (t, d) = (D::DIM * D::DIM, D::DIM);
        Gradients {
            velocity: get_tensor(v),
            pressure: get_vector(&v[t..]),
            omega: v[t + d],
            strain_velocity: get_tensor(&v[t + d + 1..]),
        }
    }
}

/// The result of pass 1: the gradients, and what only some schemes use, each empty
/// otherwise, so that it costs no memory at the stage's peak where it is not used: the
/// linear gradient corrections M_i⁻ᵀ (identity where M is singular) when
/// `gradient_correction` or `momentum_correction` is on (72 bytes per particle in 3-D),
/// and ∇e from the same-material pairs, for the energy diffusion's reconstruction, when
/// the extended state carries the specific energies (24 bytes).
#[derive(Clone, Debug)]
pub(crate) struct GradientSet<D: Dimension> {
    pub each: Vec<Gradients<D>>,
    pub correction: Vec<D::Tensor>,
    pub energy: Vec<D::Vector>,
}

/// What pass 1 must produce beyond ∇v and ∇P.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct GradientOptions {
    /// Linear-corrected ∇v, ∇P and ∇e (`gradient_correction`).
    pub correct: bool,
    /// A linear-corrected strain rate (`strain_rate_correction`, with stresses).
    pub correct_strain: bool,
    /// Keep the corrections M⁻ᵀ for the momentum equation (`momentum_correction`).
    pub keep_correction: bool,
    /// The grad-h factor Ω (`grad_h`); else Ω = 1 and its sums are skipped.
    pub grad_h: bool,
}

impl GradientOptions {
    /// The study's scheme on a solid (`SchemeConfig::default` with strength): the
    /// strain rate linearly corrected, the grad-h factor, no other correction.
    pub const STUDY: Self = GradientOptions {
        correct: false,
        correct_strain: true,
        keep_correction: false,
        grad_h: true,
    };

    /// Whether pass 1 over `ext` runs with the study's choices: these options, no
    /// energy gradient (no specific energies carried) and no decoupling of fractured
    /// material (no adhesion flags).
    fn is_study<D: Dimension>(&self, ext: &Extended<'_, D>) -> bool {
        *self == Self::STUDY && ext.specific_energy.is_empty() && ext.adhesion.is_empty()
    }

    /// Whether the moment matrix M (and its inverse) is needed.
    fn needs_moments(&self) -> bool {
        self.correct || self.correct_strain || self.keep_correction
    }
}

/// Pass 1's sums of one particle: Σ V_j (v_j − v_i) ⊗ ∇W̄, Σ V_j (P_j − P_i) ∇W̄, the
/// moment matrix Σ V_j (x_j − x_i) ⊗ ∇W̄, Σ V_j (e_j − e_i) ∇W̄ and Σ m_j ∂W/∂h.
struct Sums<D: Dimension> {
    l: D::Tensor,
    gp: D::Vector,
    m: D::Tensor,
    ge: D::Vector,
    dwdh: f64,
}

/// One pair's terms of pass 1 before the partner's volume: (f_j − f_i) ⊗ ∇_i W̄ and
/// (x_j − x_i) ⊗ ∇_i W̄ are the same seen from i and from j (both factors change sign),
/// so a pair evaluated once adds them to both sides with the other's volume. `None`:
/// not summed (a decoupled pair's velocity gradient, energies across materials, M
/// when unused).
struct PairGradients<D: Dimension> {
    l: Option<D::Tensor>,
    gp: D::Vector,
    ge: Option<D::Vector>,
    m: Option<D::Tensor>,
}

impl<D: Dimension> PairGradients<D> {
    /// Adds the terms times the partner's volume `vol`, and `dwdh` (m_partner ∂W/∂h).
    #[inline(always)]
    fn add_to(&self, s: &mut Sums<D>, vol: f64, dwdh: f64) {
        if let Some(l) = self.l {
            s.l += l * vol;
        }
        s.gp += self.gp * vol;
        if let Some(ge) = self.ge {
            s.ge += ge * vol;
        }
        if let Some(m) = self.m {
            s.m += m * vol;
        }
        s.dwdh += dwdh;
    }
}

/// Pass 1 over the rows `own`, in blocks of `rows` rows from its first (all of them in a
/// single process; a rank's share on several, or its own rows in a local state,
/// solver/ranks/local.rs: either way the first at a block's start in the global order). With `generic` the loop that reads the options runs even where they are
/// the study's. With `pick`, `list` holds every listed pair of a Verlet list and pass 1
/// picks the stage's pairs from it as it reads each row (`probe`'s test, as
/// `NeighborList::select_pairs` would pick them), handing back each block's picked rows
/// for [`sph_core::PairSelection::assemble`].
pub(crate) fn gradients<D: Dimension, P: PairKernel<D>>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    options: GradientOptions,
    (rows, own): (usize, Range<usize>),
    (generic, pick): (bool, Option<&PairProbe<D>>),
) -> (GradientSet<D>, Vec<PickedRows>) {
    // The study's options as constants of the loop where they are the run's
    // (`GradientOptions::STUDY`, as pair_scheme.rs does for pass 2) unless `generic`
    // asks for the loop that reads them; the same arithmetic either way.
    let study = !generic && options.is_study(ext);
    per_case!(gradients_in(ext, list, pk, options, rows, own, pick), study)
}

/// [`gradients`] for one geometry (`RZ`) and, with `STUDY`, the study's options
/// ([`GradientOptions::STUDY`], no energy gradient, no decoupling), fixed at compile
/// time.
fn gradients_in<D: Dimension, P: PairKernel<D>, const RZ: bool, const STUDY: bool>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    options: GradientOptions,
    rows: usize,
    own: Range<usize>,
    pick: Option<&PairProbe<D>>,
) -> (GradientSet<D>, Vec<PickedRows>) {
    let GradientOptions {
        correct,
        correct_strain,
        keep_correction,
        grad_h,
    } = options;
    let moments = options.needs_moments();
    let rz = RZ;
    // The 2-D density of the pair sums: η = ρ r in RZ (ring masses per radian).
    let eta = |k: usize| {
        if rz {
            ext.density[k] * ext.smoothed_radius[k]
        } else {
            ext.density[k]
        }
    };
    let energy = !ext.specific_energy.is_empty();
    let d = D::DIM as f64;
    let volume = volumes::<D, RZ>(ext);
    // The pair (i, j) with dx = x_j − x_i, added to i's sums and, for a pair inside the
    // block (`to_j`), to j's: every term is (f_j − f_i) ⊗ ∇_i W̄ or dx ⊗ ∇_i W̄ times the
    // partner's volume, the same product for both sides (both factors change sign).
    let add_pair =
        |q: &Partner<D>, i: usize, j: usize, sums_i: &mut Sums<D>, to_j: Option<&mut Sums<D>>| {
            // The choices, constants of this closure's code with STUDY (it runs on the
            // pool's threads, where a captured value would be a load).
            let (grad_h, moments, energy, decouple) = if STUDY {
                let o = GradientOptions::STUDY;
                (o.grad_h, o.needs_moments(), false, false)
            } else {
                (grad_h, moments, energy, true)
            };
            let xi = q.position[i];
            let dx = q.position[j] - xi;
            let dist = dx.norm();
            // ∇_i W̄ and, for the grad-h factor, each side's own ∂W/∂h times the partner's
            // mass (j's only when the pair is evaluated for both).
            let (g, dwdh_i, dwdh_j) = match (grad_h, to_j.is_some()) {
                (true, true) => {
                    let (g, wi, wj) = pk.grad_and_dw_dh(i, j, -dx, dist);
                    (g, q.mass[j] * wi, q.mass[i] * wj)
                }
                (true, false) => (
                    pk.grad_at(i, j, -dx, dist),
                    q.mass[j] * pk.dw_dh_own_at(i, dx, dist),
                    0.0,
                ),
                (false, _) => (pk.grad_at(i, j, -dx, dist), 0.0, 0.0),
            };
            let dv = q.velocity[j] - q.velocity[i];
            // A decoupled pair (fractured rock separating) shares no velocity gradient;
            // it still counts in M and ∇P, as in Spheral's FSISPH.
            let terms = PairGradients {
                l: (!(decouple && decoupled(ext, i, j, -dx, -dv))).then(|| D::Tensor::outer(dv, g)),
                gp: g * (q.pressure[j] - q.pressure[i]),
                ge: (energy && q.material[i] == q.material[j])
                    .then(|| g * (q.specific_energy[j] - q.specific_energy[i])),
                // M only where it is used (an outer product per pair).
                m: moments.then(|| D::Tensor::outer(dx, g)),
            };
            terms.add_to(sums_i, q.volume[j], dwdh_i);
            if let Some(sums_j) = to_j {
                terms.add_to(sums_j, q.volume[i], dwdh_j);
            }
        };
    let finish = |i: usize, s: &Sums<D>| -> (Gradients<D>, D::Tensor, D::Vector) {
        let omega = if grad_h {
            1.0 + pk.h(i) / (d * eta(i)) * s.dwdh
        } else {
            1.0
        };
        // L = L_raw M⁻¹ and ∇P = M⁻ᵀ ∇P_raw are exact for linear fields. A nearly
        // singular M (a particle with too few neighbours) keeps the raw estimates.
        // M⁻¹ when either use wants it: the continuity equation and reconstruction
        // (`correct`), and the strain rate that drives the deviatoric stress.
        let inv = if moments {
            well_conditioned_inverse(&s.m)
        } else {
            None
        };
        let l = s.l;
        let strain_velocity = match (correct_strain, inv) {
            (true, Some(mi)) => l.mul_tensor(&mi),
            _ => l,
        };
        let c = inv.map_or(D::Tensor::IDENTITY, |mi| mi.transpose());
        match (correct, inv) {
            (true, Some(mi)) => (
                Gradients {
                    velocity: l.mul_tensor(&mi),
                    pressure: mi.transpose().mul_vec(s.gp),
                    omega,
                    strain_velocity,
                },
                c,
                mi.transpose().mul_vec(s.ge),
            ),
            _ => (
                Gradients {
                    velocity: l,
                    pressure: s.gp,
                    omega,
                    strain_velocity,
                },
                c,
                s.ge,
            ),
        }
    };
    // Each block of rows sums its pairs (pair_blocks.rs), then finishes its rows.
    let n = ext.n_real;
    let keep = correct || keep_correction;
    // Each block's rows: their gradients, and where kept their corrections and ∇e.
    let fill = |start: usize,
                out: &mut [Gradients<D>],
                mut corr: Option<&mut [D::Tensor]>,
                mut grad_e: Option<&mut [D::Vector]>|
     -> Option<PickedRows> {
        let end = start + out.len();
        let mut sums: Vec<Sums<D>> = (start..end)
            .map(|i| Sums {
                l: D::Tensor::ZERO,
                gp: D::Vector::ZERO,
                m: D::Tensor::ZERO,
                ge: D::Vector::ZERO,
                // Self term of Σ m ∂W/∂h: ∂W(0,h)/∂h = −d W(0,h)/h.
                dwdh: if grad_h {
                    -d * ext.mass[i] * pk.w(i, i, D::Vector::ZERO) / pk.h(i)
                } else {
                    0.0
                },
            })
            .collect();
        let q = Partner::cut(
            ext,
            &volume,
            Columns {
                damage: false,
                rz: false,
                astress_hoop: false,
                energy,
            },
        );
        let mut scratch = Vec::new();
        // The stage's pairs picked from the Verlet list here, where the row is decoded
        // and the partners' data read anyway (solver/simulation/verlet.rs).
        let mut picker = pick.map(|probe| {
            let keep = move |i: usize, j: u32| probe.interacts(i, j as usize);
            (list.list().picker(), keep)
        });
        for i in start..end {
            let row = match picker.as_mut() {
                Some((picker, keep)) => picker.row(i, keep, &mut scratch),
                None => list.row(i, &mut scratch),
            };
            for &j in row {
                let j = j as usize;
                match pair_blocks::visit(i, j, start, end) {
                    pair_blocks::Visit::Done => {}
                    pair_blocks::Visit::OwnOnly => add_pair(&q, i, j, &mut sums[i - start], None),
                    pair_blocks::Visit::Both => {
                        let (lo, hi) = sums.split_at_mut(j - start);
                        add_pair(&q, i, j, &mut lo[i - start], Some(&mut hi[0]));
                    }
                }
            }
        }
        for (k, s) in sums.iter().enumerate() {
            let (g, c, ge) = finish(start + k, s);
            out[k] = g;
            if let Some(corr) = corr.as_deref_mut() {
                corr[k] = c;
            }
            if let Some(grad_e) = grad_e.as_deref_mut() {
                grad_e[k] = ge;
            }
        }
        picker.map(|(picker, keep)| picker.finish(&keep))
    };
    let unset = Gradients {
        velocity: D::Tensor::ZERO,
        pressure: D::Vector::ZERO,
        omega: 1.0,
        strain_velocity: D::Tensor::ZERO,
    };
    let mut each = vec![unset; n];
    let mut correction = if keep {
        vec![D::Tensor::IDENTITY; n]
    } else {
        Vec::new()
    };
    let mut grad_e = if energy {
        vec![D::Vector::ZERO; n]
    } else {
        Vec::new()
    };
    // Only the rows `own` (this rank's; solver/ranks.rs): the other rows stay unset.
    let n_blocks = own.len().div_ceil(rows);
    let corr = chunks_or_none(rows_or_empty(&mut correction, &own), rows, n_blocks);
    let ge = chunks_or_none(rows_or_empty(&mut grad_e, &own), rows, n_blocks);
    // The blocks to the threads one task each: a task of several blocks left the other
    // thread idle at the end of the pass where blocks are few (RZ: 26); and the thread
    // that finishes first does not sleep while the last blocks run (warm_threads.rs).
    let mut picked: Vec<Option<PickedRows>> = (0..n_blocks).map(|_| None).collect();
    let tasks = each[own.clone()]
        .par_chunks_mut(rows)
        .zip(corr)
        .zip(ge)
        .zip(picked.par_iter_mut())
        .enumerate();
    for_each_awake(tasks, |(b, (((out, corr), ge), picked))| {
        *picked = fill(own.start + b * rows, out, corr, ge)
    });
    (
        GradientSet {
            each,
            correction,
            energy: grad_e,
        },
        picked.into_iter().flatten().collect(),
    )
}

/// M⁻¹ if M is invertible and not too far from the identity (condition number of its
/// symmetric part below 100), else None.
fn well_conditioned_inverse<T: Tensor>(m: &T) -> Option<T> {
    let s = m.symmetric();
    if gershgorin_well_conditioned(&s) || eigenvalues_well_conditioned(&s) {
        m.inverse()
    } else {
        None
    }
}

/// Whether the symmetric `s` has eigenvalues 0 < λ_min and λ_max ≤ 100 λ_min, written as
/// the refusal it has always been (so a NaN λ_max is not refused, as before).
fn eigenvalues_well_conditioned<T: Tensor>(s: &T) -> bool {
    let values = s.sym_eigenvalues();
    let (lo, hi) = (values[0], values[T::Vector::DIM - 1]);
    let refused = !(lo > 0.0) || hi > 100.0 * lo;
    !refused
}

/// Whether Gershgorin's discs alone (`Tensor::gershgorin`) show the symmetric `s` well
/// conditioned: lb = min(s_ii − R_i) > 0 and ub = max(s_ii + R_i) ≤ 99 lb give
/// 0 < lb ≤ λ_min and λ_max ≤ 99 λ_min. The margin to the test's 100 (and lb ≥ ‖s‖/99)
/// is far beyond the computed eigenvalues' error, so [`well_conditioned_inverse`] decides
/// as from the eigenvalues, without them: the common case of an M near the identity
/// (pass 1 of every particle away from a surface) skips the eigenvalue solver's square
/// root and trigonometry. A matrix with a non-finite entry goes to the eigenvalues.
fn gershgorin_well_conditioned<T: Tensor>(s: &T) -> bool {
    s.gershgorin()
        .is_some_and(|(lb, ub, _)| lb > 0.0 && ub <= 99.0 * lb)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use sph_core::glam::{DMat2, DMat3};

    /// The decision from the eigenvalues alone, as before the Gershgorin test.
    fn by_eigenvalues<T: Tensor>(m: &T) -> Option<T> {
        if eigenvalues_well_conditioned(&m.symmetric()) {
            m.inverse()
        } else {
            None
        }
    }

    proptest! {
        /// Moment matrices around the identity, from nearly it to singular, indefinite
        /// and badly conditioned (perturbations up to 10× the diagonal): the inverse,
        /// or none, is the eigenvalues' to the bit.
        #[test]
        fn the_gershgorin_test_decides_as_the_eigenvalues(
            entries in proptest::array::uniform9(-1.0_f64..1.0),
            log_size in -4.0_f64..1.0,
            scale in 1e-6_f64..1e6,
        ) {
            let size = 10f64.powf(log_size);
            let m3 = (DMat3::IDENTITY + DMat3::from_cols_array(&entries) * size) * scale;
            prop_assert_eq!(
                well_conditioned_inverse(&m3).map(|m| m.to_cols_array()),
                by_eigenvalues(&m3).map(|m| m.to_cols_array())
            );
            let m2 = (DMat2::IDENTITY
                + DMat2::from_cols_array(&[entries[0], entries[1], entries[2], entries[3]]) * size)
                * scale;
            prop_assert_eq!(
                well_conditioned_inverse(&m2).map(|m| m.to_cols_array()),
                by_eigenvalues(&m2).map(|m| m.to_cols_array())
            );
        }
    }

    #[test]
    fn the_gershgorin_test_accepts_a_near_identity_and_defers_otherwise() {
        let near = DMat3::IDENTITY + DMat3::from_cols_array(&[0.01; 9]);
        assert!(gershgorin_well_conditioned(&near.symmetric()));
        // Condition number 50, but discs that overlap 0: left to the eigenvalues.
        let wide = DMat3::from_diagonal(sph_core::glam::DVec3::new(1.0, 1.0, 50.0))
            + DMat3::from_cols_array(&[0.0, 0.9, 0.9, 0.9, 0.0, 0.9, 0.9, 0.9, 0.0]);
        assert!(!gershgorin_well_conditioned(&wide.symmetric()));
        assert_eq!(well_conditioned_inverse(&wide), by_eigenvalues(&wide));
        // Indefinite: none.
        let indefinite = DMat3::from_diagonal(sph_core::glam::DVec3::new(1.0, -1.0, 1.0));
        assert!(well_conditioned_inverse(&indefinite).is_none());
    }
}

//! Pass 2: per real particle, dρ/dt, dv/dt and de/dt from the pair force (paper §2), with
//! the pair rules of `solver/pair_rules/` and, in RZ, the hoop gauge and the artificial
//! stress' hoop part.

use super::pair_scheme::PairScheme;
use super::switch::viscosity_switch_factors;
use super::*;
use crate::solver::chunks::{chunks_or_none, rows_or_empty};
use crate::solver::pair_rules::{PairRule, PairView};
use crate::solver::warm_threads::for_each_awake;

/// Per-particle time derivatives and time-step ingredients (pass 2).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Rates<D: Dimension> {
    pub drho: f64,
    pub dv: D::Vector,
    pub de: f64,
    /// Largest approach speed max_j max(0, −v_ij·r̂) among the neighbours.
    pub approach: f64,
    /// W_i = Σ_j m_j F_ij (v*_ij·∇W): with it de/dt = W_i − v_i·(dv/dt) in the compatible
    /// form, which lets the final RK2 update use the time-centred velocity.
    pub work: f64,
}

impl<D: Dimension> Flat for Rates<D> {
    const LEN: usize = D::DIM + 4;
    fn put(&self, out: &mut Vec<f64>) {
        out.push(self.drho);
        put_vector(self.dv, out);
        out.extend([self.de, self.approach, self.work]);
    }
    fn get(v: &[f64]) -> Self {
        let d = D::DIM;
        Rates {
            drho: v[0],
            dv: get_vector(&v[1..]),
            de: v[d + 1],
            approach: v[d + 2],
            work: v[d + 3],
        }
    }
}

impl<D: Dimension> Rates<D> {
    const ZERO: Self = Rates {
        drho: 0.0,
        dv: D::Vector::ZERO,
        de: 0.0,
        approach: 0.0,
        work: 0.0,
    };
}

/// What a set of i's pairs adds to its rates (pass 2): dv/dt, dρ/dt (dη/dt in RZ), de/dt,
/// the compatible form's work, and in RZ the sums of the hoop gauge and of the artificial
/// stress' hoop part.
#[derive(Clone, Copy, Debug)]
struct PairPart<D: Dimension> {
    dv: D::Vector,
    drho: f64,
    de: f64,
    work: f64,
    gauge_a: f64,
    gauge_g: f64,
    astress_hoop: f64,
}

impl<D: Dimension> PairPart<D> {
    const ZERO: Self = PairPart {
        dv: D::Vector::ZERO,
        drho: 0.0,
        de: 0.0,
        work: 0.0,
        gauge_a: 0.0,
        gauge_g: 0.0,
        astress_hoop: 0.0,
    };

    fn add(&mut self, other: &Self) {
        self.dv += other.dv;
        self.drho += other.drho;
        self.de += other.de;
        self.work += other.work;
        self.gauge_a += other.gauge_a;
        self.gauge_g += other.gauge_g;
        self.astress_hoop += other.astress_hoop;
    }
}

/// What a row of pass 2 reads of its own particle once, for all its pairs.
struct Row<D: Dimension> {
    x: D::Vector,
    v: D::Vector,
    r: f64,
    rho: f64,
    p: f64,
    c: f64,
    material: u16,
    s_undamaged: D::Tensor,
    d: f64,
    eta: f64,
}

/// One side's view of an evaluated pair (pass 2): its index, ∇W̄ from its side, its
/// dv/dt and the artificial-stress part of it, its velocity and that less the partner's,
/// both weights r, its pressure and coupled deviatoric stress, both densities η and the
/// partner's mass.
struct Share<D: Dimension> {
    index: usize,
    g: D::Vector,
    force: D::Vector,
    a_force: D::Vector,
    v: D::Vector,
    vrel: D::Vector,
    r: f64,
    r_partner: f64,
    p: f64,
    s: D::Tensor,
    eta: f64,
    eta_partner: f64,
    m_partner: f64,
}

/// An evaluated pair (pass 2): its approach speed −v_ij·r̂, and unless it does not
/// interact, its shares for i and j (j's is zero unless asked for), whether j is a
/// contact wall's ghost, and r̂.
struct PairEval<D: Dimension> {
    approach: f64,
    parts: Option<(PairPart<D>, PairPart<D>)>,
    contact: bool,
    r_hat: D::Vector,
}

impl<D: Dimension> PairEval<D> {
    /// A pair that does not interact and does not approach.
    const QUIET: Self = PairEval {
        approach: 0.0,
        parts: None,
        contact: false,
        r_hat: D::Vector::ZERO,
    };
}

/// The result of pass 2: the rates of every real particle, and what only some particles
/// or geometries have, kept apart so that a 3-D run does not hold them per particle.
#[derive(Clone, Debug)]
pub(crate) struct PairRates<D: Dimension> {
    pub each: Vec<Rates<D>>,
    /// (i, the part of dv_i/dt exerted by ghosts) for the particles that have ghost
    /// neighbours (boundaries), ascending in i: their impulse is accounted so that
    /// momentum balances to round-off even with walls.
    pub boundary: Vec<(u32, D::Vector)>,
    /// RZ only (empty in Cartesian runs): the pair sums' own estimate of ∂r/∂r,
    /// ŝ_i = r_i Σ_j V_j ∂_r W_ij plus Σ_j V_j r_j ∂_r W_ij with V_j = m_j/(ρ_j R̂_j), which
    /// the hoop force uses so that a uniform stress is in equilibrium also next to the
    /// axis (axisymmetric.rs).
    pub hoop_gauge: Vec<f64>,
}

/// Pass 2 over the rows `own`, in blocks of `rows` rows from its first (as pass 1,
/// gradients.rs): the other rows' rates and hoop gauges stay unset, and `boundary`
/// lists only these rows' particles. With `generic` the loop that reads the scheme's
/// choices runs even where the scheme is the study's (pair_scheme.rs).
pub(crate) fn rates<D: Dimension, P: PairKernel<D>>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    grads: Option<&GradientSet<D>>,
    (scheme, generic): (&SchemeConfig, bool),
    (rows, own): (usize, Range<usize>),
    rule: &impl PairRule<D>,
) -> PairRates<D> {
    // The study's choices as constants of the loop where the scheme makes them, unless
    // `generic` asks for the loop that reads them (pair_scheme.rs); the same arithmetic
    // either way.
    let study = !generic && PairScheme::is_study(scheme);
    per_case!(
        rates_in(ext, list, pk, grads, scheme, rows, own, rule),
        study
    )
}

/// [`rates`] for one geometry (`RZ`) and, with `STUDY`, the study's choices of the
/// scheme ([`PairScheme::study`]), fixed at compile time.
fn rates_in<D: Dimension, P: PairKernel<D>, const RZ: bool, const STUDY: bool>(
    ext: &Extended<'_, D>,
    list: Pairs<'_>,
    pk: &P,
    grads: Option<&GradientSet<D>>,
    scheme: &SchemeConfig,
    rows: usize,
    own: Range<usize>,
    rule: &impl PairRule<D>,
) -> PairRates<D> {
    // What the loop reads of the scheme per pair: constants when STUDY. Each closure
    // below that runs on the pool's threads picks them itself, so that they are
    // constants of its own code (a captured value would be a load).
    let ps = PairScheme::pick::<STUDY>(scheme);
    let solid = ext.has_stress();
    let damaged = !ext.damage.is_empty();
    let astress = scheme.artificial_stress;
    let use_astress = !ext.astress.is_empty();
    // FSISPH's energy diffusion reads the specific energies and pass 1's ∇e (empty
    // otherwise).
    let carries_energy = !ext.specific_energy.is_empty();
    let grad_e: &[D::Vector] = grads.map_or(&[], |g| &g.energy);
    // The gradient corrections M⁻ᵀ of the real particles, for the momentum and the
    // continuity equations where the scheme asks for them.
    let corrections = grads.map(|g| g.correction.as_slice());
    // RZ: the pair terms carry the weights r (pressure and stress r σ, density η = ρ r;
    // axisymmetric.rs); Cartesian runs have r = 1 throughout.
    let rz = RZ;
    let radius = |k: usize| if rz { ext.radius[k] } else { 1.0 };
    let smooth_r = |k: usize| if rz { ext.smoothed_radius[k] } else { 1.0 };
    // The viscosity switch's factor of each real particle (empty without a switch); a
    // ghost takes its source's, since |∇·v| and |∇×v| do not change under a mirror.
    let switch = viscosity_switch_factors(ext, pk, grads, scheme);
    // RZ: each particle's volume m/η, which the hoop gauge's sums weigh the pairs with.
    let volume = if rz {
        volumes::<D, RZ>(ext)
    } else {
        Vec::new()
    };
    let switch_of = |k: usize| switch[ext.source[k] as usize];
    // RZ: the hoop component R_θθ of particle i's artificial stress, which its hoop
    // force balances (`finish`).
    let hoop_astress = |i: usize| {
        if rz && use_astress {
            ext.astress_hoop[i]
        } else {
            0.0
        }
    };
    // What a row reads of its own particle once, for all its pairs.
    let row = |i: usize| Row::<D> {
        x: ext.position[i],
        v: ext.velocity[i],
        r: radius(i),
        rho: ext.density[i],
        p: ext.pressure[i],
        c: ext.sound_speed[i],
        material: ext.material[i],
        // Particle i's undamaged deviatoric stress in D dimensions (the in-plane block);
        // each pair weakens it by its damage coupling.
        s_undamaged: if solid {
            D::project(&ext.undamaged_stress(i))
        } else {
            D::Tensor::ZERO
        },
        d: if damaged { ext.damage[i] } else { 0.0 },
        eta: ext.density[i] * smooth_r(i),
    };
    // The pair (i, j), evaluated once: its approach speed and, unless it does not
    // interact, its shares for i and (with `both`) for j.
    let eval = |i: usize, a: &Row<D>, j: usize, both: bool, q: &Partner<D>| -> PairEval<D> {
        let ps = PairScheme::pick::<STUDY>(scheme);
        let visc = ps.viscosity;
        let diffuse = ps.energy_diffusion > 0.0 && carries_energy;
        let momentum_corrections = corrections.filter(|_| ps.momentum_correction);
        // One side's share of the pair (`share`), with what it reads of the scheme.
        let sharing = Sharing {
            continuity_corrections: corrections.filter(|_| ps.gradient_correction),
            density: ps.density,
            energy: ps.energy,
            solid,
        };
        let r = a.x - q.position[j];
        let dist = r.norm();
        if dist == 0.0 {
            // Coincident particles exert no force (∇W = 0) and define no axis.
            return PairEval::QUIET;
        }
        let r_hat = r / dist;
        let g = pk.grad_at(i, j, r, dist);
        if g == D::Vector::ZERO {
            // Out of both supports: a pair of a list kept from the step's first stage
            // (NeighbourSearch::EachStep) that has moved apart since. A fresh list holds
            // no such pair.
            return PairEval::QUIET;
        }
        let (vj, rhoj, pj, cj, mj) = (
            q.velocity[j],
            q.density[j],
            q.pressure[j],
            q.sound_speed[j],
            q.mass[j],
        );
        let (vi, rhoi, pi, ci, ri, di) = (a.v, a.rho, a.p, a.c, a.r, a.d);
        let dj = if damaged { q.damage[j] } else { 0.0 };
        let same_material = a.material == q.material[j];
        let vij = vi - vj;
        let approach = -vij.dot(r_hat);
        // Fractured rock separating in tension does not interact at all
        // (sph_damage::decoupling); the test is symmetric in (i, j).
        if decoupled(ext, i, j, r, vij) {
            return PairEval {
                approach,
                ..PairEval::QUIET
            };
        }

        // Left (j) and right (i) states along r̂, reconstructed to the midpoint.
        let (mut ui, mut uj) = (vi.dot(r_hat), vj.dot(r_hat));
        let (mut pfi, mut pfj) = (pi, pj);
        // Both sides' velocity gradients, for the limited viscosity, and energy
        // gradients, for the energy diffusion.
        let mut l_pair = None;
        let mut ge_pair = (D::Vector::ZERO, D::Vector::ZERO);
        if let Some(gr) = grads.map(|g| &g.each) {
            let gi = &gr[i];
            let src = &gr[q.source[j] as usize];
            // A ghost's gradients are its source's, mapped: M L Mᵀ and M ∇P.
            let m = &ext.map(j);
            let (lj, gpj) = if j < ext.n_real {
                (src.velocity, src.pressure)
            } else {
                (
                    m.mul_tensor(&src.velocity).mul_tensor(&m.transpose()),
                    m.mul_vec(src.pressure),
                )
            };
            l_pair = Some((gi.velocity, lj));
            if diffuse {
                let src_e = grad_e[q.source[j] as usize];
                ge_pair = (
                    grad_e[i],
                    if j < ext.n_real {
                        src_e
                    } else {
                        m.mul_vec(src_e)
                    },
                );
            }
            let half = r * 0.5;
            let dui = r_hat.dot(gi.velocity.mul_vec(-half));
            let duj = r_hat.dot(lj.mul_vec(half));
            (ui, uj) = reconstruct(ui, uj, dui, duj, ps.limiter);
            (pfi, pfj) = reconstruct(pi, pj, gi.pressure.dot(-half), gpj.dot(half), ps.limiter);
        }
        let right = SideState {
            density: rhoi,
            velocity: ui,
            pressure: pfi,
            sound_speed: ci,
        };
        let left = SideState {
            density: rhoj,
            velocity: uj,
            pressure: pfj,
            sound_speed: cj,
        };
        let mut v_star = interface_velocity(
            &PairInterface {
                v_i: vi,
                v_j: vj,
                r_hat,
                right,
                left,
                damage_i: di,
                damage_j: dj,
                same_material,
            },
            ps.riemann,
            ps.coupling,
        );
        // FSISPH's density stabilisation (Spheral SolidFSISPHEvaluateDerivatives.cc):
        // within one material, v* += f_D κ c̄ (1 + min(0, max(−1, v_ij·r̂/c̄)))
        // clamp((P_j − P_i)/(K_i + K_j), ±¼) r̂, with K + 4G/3 = ρ c_L² and the
        // reconstructed pressures; symmetric in (i, j), so conservation is unchanged.
        if ps.density_stabilization > 0.0
            && same_material
            && let Some(dv) = pair_rules::density_stabilization(
                ext,
                (i, j),
                (
                    Side {
                        rho: rhoi,
                        c: ci,
                        p: pfi,
                        d: di,
                    },
                    Side {
                        rho: rhoj,
                        c: cj,
                        p: pfj,
                        d: dj,
                    },
                ),
                ps.density_stabilization,
                vij,
                r_hat,
            )
        {
            v_star += dv;
        }

        let rj = if rz { q.radius[j] } else { 1.0 };
        let (etai, etaj) = (a.eta, rhoj * if rz { q.smoothed_radius[j] } else { 1.0 });
        let r_bar = 0.5 * (ri + rj);
        let pi_ij = pair_rules::viscous_pressure(
            ext,
            (i, j),
            &visc,
            (scheme.viscosity_length_factor, scheme.n_target),
            &ViscosityPair {
                v: (vi, vj),
                vij,
                gradients: l_pair,
                r,
                dist,
                rho: (rhoi, rhoj),
                c: (ci, cj),
                h: (pk.h(i), pk.h(j)),
                weights: (ri, rj),
                switch: (!switch.is_empty()).then(|| (switch_of(i), switch_of(j))),
            },
        );
        let (a_unit, f_astress) = if use_astress {
            pair_rules::artificial_stress::<D, P, RZ>(
                ext,
                pk,
                &astress,
                (i, j),
                (r, dist),
                r_hat,
                g,
                // f_ij for the hoop force only where a side has one: a row whose
                // R_θθ is 0 adds no hoop force whatever its sum (`finish`).
                rz && (q.astress_hoop[i] != 0.0 || q.astress_hoop[j] != 0.0),
            )
        } else {
            (D::Vector::ZERO, 0.0)
        };
        // The pressure part of the pair force: the particles' pressures (the
        // study's σ_i + σ_j), or twice the pair's Riemann star pressure.
        let p_pair = match ps.momentum {
            MomentumForm::ParticlePressure => ri * pi + rj * pj,
            MomentumForm::StarPressure => 2.0 * r_bar * ps.riemann.star(&left, &right).pressure,
        };
        // The pair's deviatoric stresses, weakened by damage: each particle's own
        // (1 − D) across a material interface, the scheme's coupling within a body.
        let (si, sj) = if solid {
            pair_rules::coupled_stresses(
                ext,
                &ps.stress_coupling,
                (i, j),
                a.s_undamaged,
                (di, dj),
                (pi, pj),
                same_material,
                r_hat,
            )
        } else {
            (D::Tensor::ZERO, D::Tensor::ZERO)
        };
        // The pair force per unit mass of i and of the partner: dv_i/dt gets m_j F and
        // dv_j/dt gets −m_i F, with F = [(σ_i + σ_j)/(η_iη_j) − Π]∇W + the artificial
        // stress, σ = (1 − D) S − P_D I; F is antisymmetric in (i, j) through ∇W.
        let mut f_pair = match momentum_corrections {
            // σ_i (C_i∇W) + σ_j (C_j∇W), C = M⁻ᵀ (a ghost's is its source's, mapped
            // like a tensor): antisymmetric in (i, j) like the plain form.
            Some(c) if ps.momentum == MomentumForm::ParticlePressure => {
                let cj = if j < ext.n_real {
                    c[j]
                } else {
                    let m = ext.map(j);
                    m.mul_tensor(&c[ext.source[j] as usize])
                        .mul_tensor(&m.transpose())
                };
                let (gi, gj) = (c[i].mul_vec(g), cj.mul_vec(g));
                let mut f =
                    (gi * (-ri * pi) + gj * (-rj * pj)) / (etai * etaj) - g * pi_ij + a_unit;
                if solid {
                    f += (si.mul_vec(gi) * ri + sj.mul_vec(gj) * rj) / (etai * etaj);
                }
                f
            }
            _ => {
                let coef = -p_pair / (etai * etaj) - pi_ij;
                let mut f = g * coef + a_unit;
                if solid {
                    f += (si * ri + sj * rj).mul_vec(g) / (etai * etaj);
                }
                f
            }
        };
        // The user's own pair force (pair_rules/user.rs), compiled away without one.
        if let Some(f) = rule.force(&PairView {
            r,
            dist,
            r_hat,
            grad_w: g,
            velocity: (vi, vj),
            density: (rhoi, rhoj),
            pressure: (pi, pj),
            material: (a.material, q.material[j]),
            support: (pk.h(i), pk.h(j)),
        }) {
            f_pair += f;
        }
        let force = f_pair * mj;
        // An unbonded interface (two different materials) carries no tension: a pair
        // whose force would pull i toward j does not interact at all (no force, and
        // no density or energy change, so the opening gap does not stretch either
        // side). The test is the same for (i, j) and (j, i), so momentum balances.
        let contact = ext.is_unilateral(j);
        if !contact && ps.unbonded_interfaces && !same_material && force.dot(r_hat) < 0.0 {
            return PairEval {
                approach,
                ..PairEval::QUIET
            };
        }
        let mut to_i = share::<D, RZ>(
            &sharing,
            &Share {
                index: i,
                g,
                force,
                a_force: a_unit * mj,
                v: vi,
                vrel: vij,
                r: ri,
                r_partner: rj,
                p: pi,
                s: si,
                eta: etai,
                eta_partner: etaj,
                m_partner: mj,
            },
            v_star,
            pi_ij,
            f_astress,
            if rz { q.volume[j] } else { 0.0 },
        );
        let mut to_j = if both {
            let mi = ext.mass[i];
            share::<D, RZ>(
                &sharing,
                &Share {
                    index: j,
                    g: -g,
                    force: f_pair * -mi,
                    a_force: a_unit * -mi,
                    v: vj,
                    vrel: -vij,
                    r: rj,
                    r_partner: ri,
                    p: pj,
                    s: sj,
                    eta: etaj,
                    eta_partner: etai,
                    m_partner: mi,
                },
                v_star,
                pi_ij,
                f_astress,
                if rz { volume[i] } else { 0.0 },
            )
        } else {
            PairPart::ZERO
        };
        // FSISPH's energy diffusion between same-material pairs (Spheral
        // SolidFSISPHEvaluateDerivatives.cc): κ c_eff (ẽ_i − ẽ_j) η·∇W̄/(ρ̄ |η|²) with
        // ẽ the energies reconstructed to the midpoint (Spheral's limiter), c_eff = max(0, min(c̄,
        // c̄ + v_ij·r̂)) and η = r/h̄. Antisymmetric in (i, j), so Σ m e is unchanged.
        if diffuse && same_material {
            let diffusion = pair_rules::energy_diffusion(
                ext,
                (i, j),
                ps.energy_diffusion,
                &DiffusionPair {
                    energy_gradients: ge_pair,
                    r,
                    r_hat,
                    vij,
                    g,
                    h: (pk.h(i), pk.h(j)),
                    eta: (etai, etaj),
                    c: (ci, cj),
                },
            );
            to_i.work += mj * diffusion;
            to_i.de += mj * diffusion;
            if both {
                let mi = ext.mass[i];
                to_j.work -= mi * diffusion;
                to_j.de -= mi * diffusion;
            }
        }
        PairEval {
            approach,
            parts: Some((to_i, to_j)),
            contact,
            r_hat,
        }
    };
    // Particle i's rates and hoop gauge (1 outside RZ) from its completed pair sums.
    let finish = |i: usize, own: &PairPart<D>, approach: f64| -> (Rates<D>, f64) {
        let mut out = Rates {
            drho: own.drho,
            dv: own.dv,
            de: own.de,
            approach,
            work: own.work,
        };
        let mut hoop_gauge = 1.0;
        // The grad-h factor makes the continuity equation the time derivative of the
        // summation density with h ∝ ρ^(−1/d) (Springel & Hernquist 2002; Price
        // 2012, eq. 39); without it the density drifts wherever h changes fast, as
        // across a strong shock. Ω is clamped to [0.5, 2] (far from its usual ≈ 1 only
        // for particles that have lost most neighbours).
        if scheme.grad_h
            && let Some(gr) = grads
        {
            out.drho /= gr.each[i].omega.clamp(0.5, 2.0);
        }
        if rz {
            let ri = ext.radius[i];
            // ŝ = r_i Σ V_j ∂_r W + Σ V_j r_j ∂_r W balances the pair sums' estimate of
            // ∂(r σ_rr)/∂r for a uniform stress, which the axis' mirror images and R̂
            // bias within two support radii of the axis. Farther out that bias is gone
            // and ŝ instead measures free surfaces and density jumps (∝ r_i/h at a
            // surface), where it would turn σ_rr ≠ σ_θθ into a spurious radial force:
            // there the gauge is the exact ∂r/∂r = 1, blended smoothly. Within the zone
            // it is kept in the range a lattice next to the axis gives it, widened
            // (HOOP_GAUGE_RANGE), for bodies only a few support radii across, whose free
            // surface lies inside the zone. axisymmetric.rs.
            let keep = axis_zone(ri / pk.h(i));
            let s_hat =
                (ri * own.gauge_a + own.gauge_g).clamp(HOOP_GAUGE_RANGE.0, HOOP_GAUGE_RANGE.1);
            hoop_gauge = keep * s_hat + (1.0 - keep);
            // The hoop part of the artificial stress: −R_θθ,i Σ_j m_j f_ij^n (r_j − r_i)/
            // (r_i r_j) ∂_r W_ij along r, so that a uniform R exerts no force, as in
            // Cartesian runs (without it a uniform tension pulled rings toward the axis
            // at (0.25–0.75) ε|P|/(ρ r)). Its work goes to the internal energy: in the
            // compatible form through de = W − v·(dv/dt), in the study's form here.
            let a_r = -hoop_astress(i) * own.astress_hoop;
            if a_r != 0.0 {
                let mut a = D::Vector::ZERO;
                a.set_component(0, a_r);
                out.dv += a;
                if ps.energy == EnergyForm::Study {
                    out.de -= ext.velocity[i].component(0) * a_r;
                }
            }
        }
        (out, hoop_gauge)
    };
    // Each block of rows (pair_blocks.rs) sums its pairs, then finishes its rows in
    // place and lists its boundary particles; the lists come back in block order.
    let n = ext.n_real;
    let mut each = vec![Rates::ZERO; n];
    let mut hoop_gauge = if rz { vec![1.0; n] } else { Vec::new() };
    let fill = |start: usize, out: &mut [Rates<D>], mut gauge: Option<&mut [f64]>| {
        let end = start + out.len();
        let mut own = vec![PairPart::<D>::ZERO; out.len()];
        let mut approach = vec![0.0_f64; out.len()];
        let mut boundary = Vec::new();
        let q = Partner::cut(
            ext,
            &volume,
            Columns {
                damage: damaged,
                rz,
                astress_hoop: rz && use_astress,
                energy: false,
            },
        );
        let mut scratch = Vec::new();
        for i in start..end {
            let a = row(i);
            let k = i - start;
            // i's sums over the ghosts of contact walls, decided on below.
            let (mut wall, mut wall_normal) = (PairPart::<D>::ZERO, D::Vector::ZERO);
            let mut dv_boundary = D::Vector::ZERO;
            for &j in list.row(i, &mut scratch) {
                let j = j as usize;
                let both = match pair_blocks::visit(i, j, start, end) {
                    pair_blocks::Visit::Done => continue,
                    pair_blocks::Visit::OwnOnly => false,
                    pair_blocks::Visit::Both => true,
                };
                let e = eval(i, &a, j, both, &q);
                approach[k] = approach[k].max(e.approach);
                if both {
                    approach[j - start] = approach[j - start].max(e.approach);
                }
                let Some((to_i, to_j)) = e.parts else {
                    continue;
                };
                if e.contact {
                    wall.add(&to_i);
                    wall_normal += e.r_hat;
                } else {
                    if j >= ext.n_real {
                        dv_boundary += to_i.dv;
                    }
                    own[k].add(&to_i);
                    if both {
                        own[j - start].add(&to_j);
                    }
                }
            }
            // A contact wall (`Boundary::Contact`, an anvil) pushes but cannot pull: its
            // ghosts act on i as a mirror's do while their total force pushes i away from
            // the wall (along Σ r̂, from the ghosts to i), and not at all when it would
            // pull i toward it: i is then at a free surface and may lift off. The
            // decision is on the total, as a contact's traction is: deciding pair by pair
            // dropped the oblique pairs that a tension along the wall makes attractive,
            // with their share of the push, and drove material pressed onto the wall into
            // it (test `a_contact_wall_in_compression_acts_as_a_mirror_under_lateral_tension`).
            if wall.dv.dot(wall_normal) > 0.0 {
                dv_boundary += wall.dv;
                own[k].add(&wall);
            }
            if dv_boundary != D::Vector::ZERO {
                boundary.push((i as u32, dv_boundary));
            }
        }
        for (k, slot) in out.iter_mut().enumerate() {
            let (r, g) = finish(start + k, &own[k], approach[k]);
            *slot = r;
            if let Some(gauge) = gauge.as_deref_mut() {
                gauge[k] = g;
            }
        }
        boundary
    };
    // The blocks go to the threads one task each, as in pass 1 (warm_threads.rs); the
    // boundary lists still come back in block order. The hoop gauge is RZ's only.
    let n_blocks = own.len().div_ceil(rows);
    let mut lists = vec![Vec::new(); n_blocks];
    let gauge = chunks_or_none(rows_or_empty(&mut hoop_gauge, &own), rows, n_blocks);
    let tasks = each[own.clone()]
        .par_chunks_mut(rows)
        .zip(gauge)
        .zip(lists.par_iter_mut())
        .enumerate();
    for_each_awake(tasks, |(b, ((out, gauge), list))| {
        *list = fill(own.start + b * rows, out, gauge)
    });
    let boundary = lists.into_iter().flatten().collect();
    PairRates {
        each,
        boundary,
        hoop_gauge,
    }
}

/// What [`share`] reads of the scheme.
struct Sharing<'a, D: Dimension> {
    /// The continuity equation's gradient corrections, when on.
    continuity_corrections: Option<&'a [D::Tensor]>,
    density: DensityForm,
    energy: EnergyForm,
    solid: bool,
}

/// One side's share of the pair: `g` is ∇W̄ seen from that side, `force` its dv/dt,
/// `a_force` its artificial-stress part, `vrel` its velocity less the partner's; in RZ
/// `vol_partner` is the partner's volume m/η ([`volumes`]), which weighs the hoop
/// gauge's sums. Always inlined into the pair loop, which calls it once or twice per pair.
#[inline(always)]
fn share<D: Dimension, const RZ: bool>(
    ctx: &Sharing<'_, D>,
    side: &Share<D>,
    v_star: D::Vector,
    pi_ij: f64,
    f_astress: f64,
    vol_partner: f64,
) -> PairPart<D> {
    let mut part = PairPart {
        dv: side.force,
        ..PairPart::ZERO
    };
    let g = side.g;
    if RZ {
        let vx = vol_partner * g.component(0);
        part.gauge_a = vx;
        part.gauge_g = vx * side.r_partner;
        // 1/r_i + 1/r_j = 2/r_j + (r_j − r_i)/(r_i r_j): the first part is the
        // Cartesian pair term of R/r (zero for a uniform R on a complete
        // lattice), the second the geometric part the hoop force cancels.
        part.astress_hoop = side.m_partner * f_astress * (side.r_partner - side.r)
            / (side.r * side.r_partner)
            * g.component(0);
    }
    // The continuity equation uses the corrected gradient when enabled.
    let gc = match ctx.continuity_corrections {
        Some(c) => c[side.index].mul_vec(g),
        None => g,
    };
    let dvs = (side.v - v_star).dot(gc);
    part.drho = match ctx.density {
        DensityForm::Volume => 2.0 * side.eta * side.m_partner / side.eta_partner * dvs,
        DensityForm::Mass => 2.0 * side.m_partner * dvs,
        // Summation density is recomputed from positions each stage.
        DensityForm::Summation => 0.0,
    };
    // Energy: the compatible form pairs with the plain (antisymmetric) gradient
    // of the momentum equation, which is what makes it exactly conservative.
    part.de = match ctx.energy {
        EnergyForm::Compatible => {
            part.work = side.force.dot(v_star);
            -side.force.dot(side.v - v_star)
        }
        EnergyForm::Study => {
            // −2 m_j/(ρ_iρ_j) (v_i − v*)·(σ_i ∇W) with σ_i = S_i − P_i I, plus
            // the viscous and artificial-stress heating.
            let eta2 = side.eta * side.eta_partner;
            let shear = if ctx.solid {
                -2.0 * side.m_partner * side.r / eta2 * (side.v - v_star).dot(side.s.mul_vec(g))
            } else {
                0.0
            };
            shear
                + side.m_partner
                    * (2.0 * side.r * side.p / eta2 * (side.v - v_star).dot(g)
                        + 0.5 * pi_ij * side.vrel.dot(g))
                - 0.5 * side.vrel.dot(side.a_force)
        }
    };
    part
}

/// The range the hoop gauge ŝ is kept in (axisymmetric.rs). On a uniform lattice next to
/// the axis ŝ takes 0.43–1.21 (measured: 0.427, 1.124, 1.213, 1.063, 1.005 in the first
/// five columns at h = 4Δ; 0.570, 1.178, 0.988 at h = 2.5Δ). Far outside that, ŝ is no
/// longer measuring the axis but a free surface or a density jump inside the axis zone,
/// where its size grows like r/h with either sign: −2.73 on the outer surface of a
/// Taylor rod 4 spacings across (its whole radius within two support radii of the
/// axis), which turned the hoop force around; its rim jetted and the run stopped with a
/// NaN at 26 µs. An estimate of ∂r/∂r = 1 cannot be negative. The bounds widen the
/// lattice's range by about a fifth below and a third above; docs/verification.md (RZ)
/// lists the scan they were chosen from and what each problem gives with them.
const HOOP_GAUGE_RANGE: (f64, f64) = (0.35, 1.6);

/// Weight of the axis part of the hoop gauge at q = r/h: 1 within two support radii of
/// the axis (where the mirror images and R̂ reach a particle or its neighbours), 0 beyond
/// three, smooth in between.
fn axis_zone(q: f64) -> f64 {
    let t = (q - 2.0).clamp(0.0, 1.0);
    1.0 - t * t * (3.0 - 2.0 * t)
}

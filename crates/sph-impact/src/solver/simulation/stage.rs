//! One derivative evaluation of the RK2 step (a stage): the EOS pass, damage and the
//! damaged moduli, the neighbour search, the gradient and pair passes, the boundary
//! ghosts' forces, the RZ hoop terms, and the time-step vote of the state evaluated.

use super::*;

/// The derivatives of one state, with what the stress update and the time-step vote read
/// of it.
pub(super) struct Stage<D: Dimension> {
    pub(super) rates: Vec<Rates<D>>,
    /// (i, the ghosts' part of dv_i/dt) for the particles with ghost neighbours.
    pub(super) boundary: Vec<(u32, D::Vector)>,
    pub(super) grads: Option<GradientSet<D>>,
    pub(super) sound_speed: Vec<f64>,
    pub(super) pressure: Vec<f64>,
    /// Shear modulus per particle (0 for fluids).
    pub(super) shear_modulus: Vec<f64>,
    /// Damage rates and bounds (empty without damage).
    pub(super) damage_rates: Vec<DamageRate>,
    /// Tensor-damage growth (empty unless some material's damage is a tensor).
    pub(super) tensor_rates: Vec<TensorRate>,
}

/// A stage's neighbour list and the ghosts its indices count, kept for the step's second
/// stage when the list is built once per step ([`NeighbourSearch::EachStep`]), or for as
/// long as it holds with a Verlet list ([`NeighbourSearch::Verlet`]).
pub(super) struct Topology<D: Dimension> {
    list: NeighborList,
    ghosts: Vec<PlacedGhost<D>>,
    /// Each rank's blocks, whose rows the list holds (solver/ranks.rs).
    shares: Vec<Range<usize>>,
    /// A Verlet list's build (simulation/verlet.rs); `None` for a list of exact pairs.
    pub(super) skin: Option<SkinBuild<D>>,
}

impl<D: Dimension> Topology<D> {
    /// The ghosts the list's indices count, as placed at its search.
    pub(super) fn ghosts(&self) -> &[PlacedGhost<D>] {
        &self.ghosts
    }
}

/// What the pair passes give a stage ([`Simulation::pair_passes`]).
struct PassesOut<D: Dimension> {
    grads: Option<GradientSet<D>>,
    rates: PairRates<D>,
    /// The instant pass 2 began.
    pass_2: Instant,
    /// The seconds of the gathers after pass 1 and after pass 2.
    exchange: [f64; 2],
    /// The stage's pairs of a Verlet list when pass 1 picked them.
    selection: Option<PairSelection>,
}

/// A stage of a rank's local state (solver/ranks/local.rs): its own rows, which alone the
/// search and the pair passes read, and the halo along which the halo's pass-1 values
/// come from their owners over `ranks`.
pub(super) struct LocalRun<'a> {
    pub(super) own: Range<usize>,
    pub(super) halo: &'a Halo,
    pub(super) ranks: &'a dyn Ranks,
}

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// Pass 1 (when `options` asks for it) and pass 2 with the pair kernel `pk`, their
    /// blocks of rows shared out among `ranks` as `shares` gives them (solver/ranks.rs),
    /// each gathered by all. With `pick` (one process, and pass 1 asked for), `list` is
    /// a Verlet list's every listed pair and pass 1 picks the stage's pairs from it with
    /// the probe's test, for pass 2 and the caller.
    fn pair_passes<P: PairKernel<D>>(
        &self,
        ext: &Extended<'_, D>,
        list: Pairs<'_>,
        pk: &P,
        options: Option<GradientOptions>,
        (rows, shares): (usize, &[Range<usize>]),
        (ranks, pick): (&dyn Ranks, Option<PairProbe<D>>),
        local: Option<&LocalRun<'_>>,
    ) -> Result<PassesOut<D>, SolverError> {
        let n = ext.n_real;
        let size = ranks.size();
        let rows_of: Vec<Range<usize>> = match local {
            Some(l) => vec![l.own.clone()],
            None => shares
                .iter()
                .map(|b| pair_blocks::rows_of(b, rows, n))
                .collect(),
        };
        let (mut g, picked) = match options {
            Some(o) => {
                let (g, picked) = gradients(
                    ext,
                    list,
                    pk,
                    o,
                    (rows, rows_of[ranks.rank()].clone()),
                    (self.generic_pair_loop, pick.as_ref()),
                );
                (Some(g), picked)
            }
            None => (None, Vec::new()),
        };
        // The stage's pairs of a Verlet list, as pass 1 picked them (`pick`; the rows
        // of no block, the ghosts', picked here by the same test). The probe is freed
        // here, before pass 2 and the stage's memory peak.
        let selection = pick.map(|probe| {
            PairSelection::assemble(list.list(), picked, |i, j| probe.interacts(i, j as usize))
        });
        let list = match &selection {
            Some(s) => Pairs::selected(list.list(), s),
            None => list,
        };
        let t = Instant::now();
        if let (Some(l), Some(g)) = (local, &mut g) {
            // A local state: the halo's gradients from their owners, which summed them.
            l.halo.fill(l.ranks, &mut g.each);
            if !g.correction.is_empty() {
                let len = ranks::tensor_len::<D>();
                let get = ranks::get_tensor::<D::Tensor>;
                l.halo
                    .fill_by(l.ranks, &mut g.correction, len, ranks::put_tensor, get);
            }
            if !g.energy.is_empty() {
                let put = |v: &D::Vector, out: &mut Vec<f64>| ranks::put_vector(*v, out);
                let get = ranks::get_vector::<D::Vector>;
                l.halo.fill_by(l.ranks, &mut g.energy, D::DIM, put, get);
            }
        }
        if size > 1
            && let Some(g) = &mut g
        {
            // Pass 2 reads the gradients of the particles its rows list (and of the
            // ghosts' sources): this rank's halo, asked of their owners.
            let read = ranks::rows_read(list, &ext.source, rows_of[ranks.rank()].clone(), n);
            let halo = ranks::Halo::new(ranks, &read, &rows_of);
            halo.fill(ranks, &mut g.each);
            if !g.correction.is_empty() {
                halo.fill_by(
                    ranks,
                    &mut g.correction,
                    ranks::tensor_len::<D>(),
                    ranks::put_tensor,
                    ranks::get_tensor::<D::Tensor>,
                );
            }
            if !g.energy.is_empty() {
                halo.fill_by(
                    ranks,
                    &mut g.energy,
                    D::DIM,
                    |v, out| ranks::put_vector(*v, out),
                    ranks::get_vector::<D::Vector>,
                );
            }
            // Every rank's per-particle work reads every particle's strain-rate
            // gradient (the stress update, the viscosity switch, the tensor damage's
            // spin) and, with ASPH, ∇v (the smoothing tensor's evolution).
            let asph = !ext.h_tensor.is_empty();
            let t = ranks::tensor_len::<D>();
            ranks::gather_rows_by(
                ranks,
                &mut g.each,
                &rows_of,
                if asph { 2 * t } else { t },
                |x, out| {
                    ranks::put_tensor(&x.strain_velocity, out);
                    if asph {
                        ranks::put_tensor(&x.velocity, out);
                    }
                },
                |x, v| {
                    x.strain_velocity = ranks::get_tensor(v);
                    if asph {
                        x.velocity = ranks::get_tensor(&v[t..]);
                    }
                },
            );
        }
        let t3 = Instant::now();
        let exchange_gradients = (t3 - t).as_secs_f64();
        let mut r = rates(
            ext,
            list,
            pk,
            g.as_ref(),
            (&self.scheme, self.generic_pair_loop),
            (rows, rows_of[ranks.rank()].clone()),
            &self.pair_rule,
        );
        let t = Instant::now();
        if size > 1 {
            ranks::gather_rows(ranks, &mut r.each, &rows_of);
            if !r.hoop_gauge.is_empty() {
                ranks::gather_rows(ranks, &mut r.hoop_gauge, &rows_of);
            }
            r.boundary = ranks::gather_list(ranks, &r.boundary);
        }
        Ok(PassesOut {
            grads: g,
            rates: r,
            pass_2: t3,
            exchange: [exchange_gradients, t.elapsed().as_secs_f64()],
            selection,
        })
    }

    /// Each of `size` ranks' blocks of the pair passes (of `rows` rows, over `n` real
    /// particles): balanced by the blocks' costs at the last evaluation, or by their rows
    /// when there is none (solver/ranks.rs). Every rank computes the same.
    fn shares(&self, n: usize, rows: usize, size: usize) -> Vec<Range<usize>> {
        let n_blocks = n.div_ceil(rows);
        if size == 1 {
            return std::iter::once(0..n_blocks).collect();
        }
        if self.block_costs.len() == n_blocks {
            ranks::shares(&self.block_costs, size)
        } else {
            let rows: Vec<u64> = (0..n_blocks)
                .map(|b| pair_blocks::rows_of(&(b..b + 1), rows, n).len() as u64)
                .collect();
            ranks::shares(&rows, size)
        }
    }

    /// Particle spacing Δx_i = (smallest support semi-axis)/n_target.
    pub(super) fn spacing(&self, state: &State<D>, i: usize) -> f64 {
        let h_min = if state.h_tensor.is_empty() {
            state.particles.smoothing_length[i]
        } else {
            1.0 / state.h_tensor[i].sym_eigenvalues()[D::DIM - 1]
        };
        h_min / self.scheme.n_target
    }

    /// Derivatives of `state`. With `reuse`, the neighbour list and ghosts of an earlier
    /// stage are used (the ghosts placed again from their sources' present positions)
    /// instead of a new search; with `keep`, this stage's are returned for such reuse.
    /// With a Verlet list (`SchemeConfig::skin`) a kept list is searched with the skin
    /// and a reused one must hold (`SkinBuild::holds`, checked by the caller).
    pub(super) fn stage(
        &mut self,
        state: &mut State<D>,
        reuse: Option<Topology<D>>,
        keep: bool,
        ranks: &dyn Ranks,
        local: Option<&LocalRun<'_>>,
    ) -> Result<(Stage<D>, Option<Topology<D>>), SolverError> {
        let t0 = Instant::now();
        // P, c, D, P_D (which the pair terms see, paper §2), G, c_L and the adhesion
        // flags, in one pass (simulation/particle_terms.rs).
        let ParticleTerms {
            pressure,
            mut sound_speed,
            damage,
            pressure_d,
            mut shear_modulus,
            signal,
            adhesion,
        } = self.particle_terms(state, None);
        let mut t1 = Instant::now();
        let support: Vec<f64> = if state.h_tensor.is_empty() {
            state.particles.smoothing_length.clone()
        } else {
            state
                .h_tensor
                .iter()
                .map(|h| 1.0 / h.sym_eigenvalues()[0])
                .collect()
        };
        // Only what the pair passes read stays alive through them (peak memory): the
        // undamaged pressure and the supports are spent, and P_D, c_L (a solid's signal
        // speed in the pair's Riemann problem and viscosity, paper §2.1) and D move into
        // the extended arrays, which are read back for the real particles below.
        drop(pressure);
        // A Verlet list's skin, where this stage keeps or reuses one.
        let skin = self.scheme.skin().filter(|_| keep || reuse.is_some());
        let placement_reach = match (skin, &reuse) {
            (Some(s), None) => verlet::reach(&support, s),
            _ => Vec::new(),
        };
        let columns = RealColumns::take(&mut state.particles);
        let mut ext = Extended::build(
            state,
            columns,
            &state.stress,
            pressure_d,
            signal,
            damage,
            &support,
            &self.boundaries,
            match (&reuse, skin) {
                (Some(t), Some(_)) => Ghosts::SkinReplay(&t.ghosts),
                (None, Some(_)) => Ghosts::SkinPlace {
                    reach: &placement_reach,
                },
                (Some(t), None) => Ghosts::Replay(&t.ghosts),
                (None, None) => Ghosts::Place { record: keep },
            },
        );
        drop(placement_reach);
        ext.coupling = self.scheme.stress_coupling;
        if !adhesion.is_empty() {
            ext.adhesion = ext.over_ghosts(adhesion);
        }
        let bulk_viscosity = self.scheme.viscosity.sound_speed == ViscositySoundSpeed::Bulk;
        if bulk_viscosity {
            ext.bulk_sound_speed = ext.over_ghosts(sound_speed.clone());
        }
        if self.scheme.energy_diffusion > 0.0 {
            ext.specific_energy = ext.over_ghosts(state.particles.specific_energy.clone());
        }
        drop(support);
        let n_real = ext.n_real;
        // D of the real particles (empty without damage).
        let n_damage = ext.damage.len().min(n_real);
        if !state.damage_tensor.is_empty() {
            // The pairs project each particle's damage tensor on their direction; a
            // scalar material's D enters as D I.
            let tensor_form: Vec<bool> = self.materials.iter().map(has_tensor_damage).collect();
            let tensors = (0..n_real)
                .map(|i| {
                    if tensor_form[state.particles.material[i] as usize] {
                        state.damage_tensor[i]
                    } else {
                        sph_core::glam::DMat3::IDENTITY * ext.damage[i]
                    }
                })
                .collect();
            ext.set_damage_tensor(tensors);
        }
        let rz = self.scheme.geometry == Geometry::Axisymmetric;
        if rz {
            // Each particle's radius r and kernel-smoothed radius R̂ (ghosts included),
            // in one pass.
            let table = self.smoothed_radius.as_ref().expect("RZ has the table");
            (ext.radius, ext.smoothed_radius) = ext
                .position
                .par_iter()
                .zip(&ext.h)
                .map(|(x, &h)| {
                    let r = radius(*x);
                    (r, table.at(r, h))
                })
                .unzip();
            // A mirror ghost stands for the same area of material as its source, so its
            // ring mass per radian scales with its own radius: ρ A r' (a wall normal to
            // r is a cylinder; the axis and walls normal to z leave r unchanged).
            for k in ext.n_real..ext.position.len() {
                let src = ext.source[k] as usize;
                ext.mass[k] *= ext.radius[k] / ext.radius[src];
            }
            // The artificial stress' Δp is the ring's (r, z) spacing at its present radius
            // (a mirror or wall ghost has its source's: it stands for the same area).
            if !self.scheme.artificial_stress.is_off() {
                let (source, radius) = (&ext.source, &ext.radius);
                ext.spacing0
                    .par_iter_mut()
                    .zip(source)
                    .for_each(|(spacing, &src)| {
                        let src = src as usize;
                        *spacing = reference_spacing(
                            state.spacing0[src],
                            self.radius0[src],
                            radius[src],
                            self.scheme.h_max_factor,
                        );
                    });
            }
        }
        let rows = self
            .pair_block_rows
            .unwrap_or_else(|| pair_blocks::block_rows(n_real));
        let size = ranks.size();
        let t_search = Instant::now();
        let (list, shares, built) = match reuse {
            Some(t) => (t.list, t.shares, t.skin),
            None => {
                let shares = self.shares(n_real, rows, size);
                // On several ranks each searches the rows of its own blocks (and the
                // particles that reach them), unless the summation density reads every row.
                let mine = if let Some(l) = local {
                    l.own.clone()
                } else if size > 1 && self.scheme.density != DensityForm::Summation {
                    pair_blocks::rows_of(&shares[ranks.rank()], rows, n_real)
                } else {
                    0..ext.position.len()
                };
                let searched = if let Some(s) = skin {
                    // Every pair within the reach (1 + s) h: the ghosts' reach is their
                    // sources', as Ghosts::SkinPlace placed them with.
                    let reach = verlet::reach(&ext.h, s);
                    ScalarSupport::new(&reach).and_then(|support| {
                        self.search.neighbors_of_rows(&ext.position, &support, mine)
                    })
                } else if ext.h_tensor.is_empty() {
                    ScalarSupport::new(&ext.h).and_then(|support| {
                        self.search.neighbors_of_rows(&ext.position, &support, mine)
                    })
                } else {
                    TensorSupport::new(&ext.h_tensor).and_then(|support| {
                        self.search.neighbors_of_rows(&ext.position, &support, mine)
                    })
                };
                let list = match searched {
                    Ok(list) => list,
                    Err(e) => {
                        // A failed search gives the real particles' columns back first.
                        ext.release_pair_columns()
                            .put_back(&mut state.particles, n_real);
                        return Err(e.into());
                    }
                };
                if size > 1 {
                    // Every block's cost, for the next evaluation's shares.
                    let own = shares[ranks.rank()].clone();
                    let costs: Vec<f64> = own
                        .map(|b| pair_blocks::rows_of(&(b..b + 1), rows, n_real))
                        .map(|r| r.map(|i| list.count(i) as u64 + 1).sum::<u64>() as f64)
                        .collect();
                    self.block_costs = ranks
                        .all_gather(costs)
                        .values
                        .iter()
                        .map(|&c| c as u64)
                        .collect();
                }
                self.timings.searches += 1;
                let built = skin.map(|s| {
                    SkinBuild::new(
                        s,
                        &state.particles.id,
                        (&ext.position[..n_real], &ext.h[..n_real]),
                        &self.boundaries,
                    )
                });
                (list, shares, built)
            }
        };
        let need_grads = self.scheme.limiter != sph_riemann::Limiter::None
            || !state.h_tensor.is_empty()
            || self.scheme.gradient_correction
            || self.scheme.momentum_correction
            || self.scheme.grad_h
            || self.scheme.viscosity.switch != sph_riemann::ViscositySwitch::None
            || self.scheme.energy_diffusion > 0.0
            || !state.stress.is_empty();
        // A Verlet list's pairs of this stage, picked for the passes (simulation/verlet.rs);
        // the list itself is kept as searched. In one process pass 1 picks them as it
        // reads the rows (`pair_passes`), unless the summation density reads them first.
        let pass_1_picks = size == 1 && need_grads && self.scheme.density != DensityForm::Summation;
        // `probe`: the test pass 1 is to pick the pairs with, if it does.
        let (picked, probe) = match ext.skin.then(|| ext.pair_probe()) {
            Some(probe) if !pass_1_picks => (
                Some(list.select_pairs(|i, j| probe.interacts(i, j as usize))),
                None,
            ),
            probe => (None, probe),
        };
        let pairs = match &picked {
            Some(selection) => Pairs::selected(&list, selection),
            None => Pairs::all(&list),
        };
        let search = t_search.elapsed().as_secs_f64();
        // The neighbours listed for the real particles (on several ranks from the blocks'
        // costs, since each rank's list holds its own rows only), in parallel: an
        // integer sum, the same in any order.
        let count = |pairs: Pairs<'_>| {
            (0..n_real)
                .into_par_iter()
                .with_min_len(1024)
                .map(|i| pairs.count(i) as u64)
                .sum::<u64>()
        };
        let mut entries = if size > 1 {
            self.block_costs.iter().sum::<u64>() - n_real as u64
        } else if probe.is_some() {
            0 // counted once pass 1 has picked them, below
        } else {
            count(pairs)
        };
        if self.scheme.density == DensityForm::Summation {
            // Density from the positions, then the EOS again with it (real and ghosts).
            let rho = if ext.h_tensor.is_empty() {
                summation_density(
                    &ext,
                    pairs,
                    &ScalarPairKernel::new(self.kernel, &ext.h, D::DIM),
                    self.smoothed_radius.as_ref(),
                )
            } else {
                summation_density(
                    &ext,
                    pairs,
                    &TensorPairKernel {
                        kernel: self.kernel,
                        h_tensor: &ext.h_tensor,
                        h: &ext.h,
                    },
                    self.smoothed_radius.as_ref(),
                )
            };
            state.particles.density = rho;
            let t = Instant::now();
            let terms = self.particle_terms(state, Some(&ext.damage[..n_damage]));
            let (pressure_d, signal) = (terms.pressure_d, terms.signal);
            (sound_speed, shear_modulus) = (terms.sound_speed, terms.shear_modulus);
            if !terms.adhesion.is_empty() {
                ext.adhesion = ext.over_ghosts(terms.adhesion);
            }
            if bulk_viscosity {
                ext.bulk_sound_speed = ext.over_ghosts(sound_speed.clone());
            }
            t1 += t.elapsed();
            for k in 0..ext.position.len() {
                let s = ext.source[k] as usize;
                ext.density[k] = state.particles.density[s];
                ext.pressure[k] = pressure_d[s];
                ext.sound_speed[k] = signal[s];
            }
        }
        if !self.scheme.artificial_stress.is_off() {
            (ext.astress, ext.astress_on, ext.astress_hoop) =
                artificial_stresses(&ext, &self.scheme.artificial_stress, rz);
        }
        let t2 = Instant::now();
        let options = GradientOptions {
            correct: self.scheme.gradient_correction,
            correct_strain: self.scheme.strain_rate_correction && !state.stress.is_empty(),
            keep_correction: self.scheme.momentum_correction,
            grad_h: self.scheme.grad_h,
        };
        let (options, blocks) = (need_grads.then_some(options), (rows, shares.as_slice()));
        let pick = (ranks, probe);
        let passes = if ext.h_tensor.is_empty() {
            let pk = ScalarPairKernel::new(self.kernel, &ext.h, D::DIM);
            self.pair_passes(&ext, pairs, &pk, options, blocks, pick, local)
        } else {
            let pk = TensorPairKernel {
                kernel: self.kernel,
                h_tensor: &ext.h_tensor,
                h: &ext.h,
            };
            self.pair_passes(&ext, pairs, &pk, options, blocks, pick, local)
        };
        let passes = match passes {
            Ok(passes) => passes,
            Err(e) => {
                ext.release_pair_columns()
                    .put_back(&mut state.particles, n_real);
                return Err(e);
            }
        };
        let PassesOut {
            grads,
            rates: rates_out,
            pass_2: t3,
            exchange,
            selection,
        } = passes;
        if let Some(s) = &selection {
            entries = count(Pairs::selected(&list, s));
        }
        // The pairs are spent: free this stage's selection and the columns only the
        // passes read before the damage rates allocate theirs.
        drop((picked, selection));
        ext.release_pair_columns()
            .put_back(&mut state.particles, n_real);
        let PairRates {
            each: mut rates_out,
            boundary,
            hoop_gauge,
        } = rates_out;
        if rz {
            // The hoop stress is weakened by the damage across the hoop direction: D for
            // a scalar damage, D_θθ of a tensor (θ is a principal direction in RZ).
            let hoop_damage: Vec<f64> = if ext.damage_tensor.is_empty() {
                Vec::new()
            } else {
                ext.damage_tensor[..n_real]
                    .iter()
                    .map(|d| d.z_axis.z.clamp(0.0, 1.0))
                    .collect()
            };
            add_hoop_terms(
                &HoopInput {
                    particles: &state.particles,
                    stress: &state.stress,
                    damage: if hoop_damage.is_empty() {
                        &ext.damage[..n_damage]
                    } else {
                        &hoop_damage
                    },
                    pressure: &ext.pressure[..n_real],
                    coupling: self.scheme.stress_coupling,
                    energy: self.scheme.energy,
                    smoothed_radius: self.smoothed_radius.as_ref().expect("RZ has the table"),
                },
                &mut rates_out,
                &hoop_gauge,
            );
        }
        drop(hoop_gauge);
        // The crack-growth length R_s: the spacing, or the support radius (CrackLength).
        let crack_length = match self.scheme.crack_length {
            CrackLength::Spacing => 1.0,
            CrackLength::Support => self.scheme.n_target,
        };
        let spacing: Vec<f64> = if n_damage == 0 {
            Vec::new()
        } else {
            (0..state.particles.len())
                .into_par_iter()
                .map(|i| self.spacing(state, i) * crack_length)
                .collect()
        };
        // Tensor damage turns with the particle's spin Ω = ½ (L − Lᵀ).
        let spin: Vec<sph_core::glam::DMat3> = match &grads {
            Some(gr) if !state.damage_tensor.is_empty() => gr
                .each
                .iter()
                .take(n_real)
                .map(|g| sph_strength::spin(&D::embed(&g.strain_velocity)))
                .collect(),
            _ => Vec::new(),
        };
        let damage_input = DamageStageInput {
            stress: &state.stress,
            pressure: &ext.pressure[..n_real],
            sound_speed: &sound_speed,
            shear_modulus: &shear_modulus,
            damage: &ext.damage[..n_damage],
            coupling: self.scheme.stress_coupling,
            spacing: &spacing,
            spin: &spin,
        };
        let damage_rates = damage_rates(state, &self.materials, &damage_input);
        let tensor_rates = tensor_damage_rates(state, &self.materials, &damage_input);
        let t4 = Instant::now();
        self.timings.eos += (t1 - t0).as_secs_f64();
        self.timings.neighbours += search;
        self.timings.setup += (t2 - t1).as_secs_f64() - search;
        self.timings.gradients += (t3 - t2).as_secs_f64() - exchange[0];
        self.timings.pairs += (t4 - t3).as_secs_f64() - exchange[1];
        self.timings.exchange += exchange[0] + exchange[1];
        self.timings.derivative_evaluations += n_real as u64;
        self.timings.neighbour_entries += entries;
        let mut pressure_d = std::mem::take(&mut ext.pressure);
        pressure_d.truncate(n_real);
        let topology = keep.then(|| Topology {
            list,
            ghosts: std::mem::take(&mut ext.placed),
            shares,
            skin: built,
        });
        Ok((
            Stage {
                rates: rates_out,
                boundary,
                grads,
                sound_speed,
                pressure: pressure_d,
                shear_modulus,
                damage_rates,
                tensor_rates,
            },
            topology,
        ))
    }

    /// The smallest time-step vote of a stage.
    pub(super) fn vote(&self, state: &State<D>, stage: &Stage<D>) -> TimestepVote {
        let p = &state.particles;
        let none = TimestepVote {
            dt: f64::INFINITY,
            particle_id: 0,
            reason: crate::solver::timestep::REASON_NONE,
        };
        // In parallel, reduced in particle order: `min` keeps the earlier vote on a tie
        // and is associative, so the vote (its particle and reason too) is the serial
        // loop's on any number of threads.
        (0..p.len())
            .into_par_iter()
            .map(|i| {
                let dx = self.spacing(state, i);
                let r = &stage.rates[i];
                let mut best =
                    none.min(density_vote(self.scheme.cfl, p.density[i], r.drho, p.id[i]));
                // For a solid the signal is the longitudinal wave: c_L² = c² + 4G/(3ρ)
                // (paper §2.5).
                let c_signal = sph_damage::longitudinal_speed(
                    stage.sound_speed[i],
                    stage.shear_modulus[i],
                    p.density[i],
                );
                best = best.min(cfl_vote(self.scheme.cfl, dx, c_signal, r.approach, p.id[i]));
                best.min(acceleration_vote(self.scheme.cfl, dx, r.dv.norm(), p.id[i]))
            })
            .reduce(|| none, TimestepVote::min)
    }
}

/// The artificial-stress tensor R of every particle, ghosts included, from its total
/// stress σ = (1 − D) S − P_D I (paper §2.3; S itself where damage acts on the yield
/// strength only), whether it is nonzero, and in RZ (the rings' radii set) its hoop
/// component R_θθ from σ_θθ = (1 − D) S_θθ − P_D (axisymmetric.rs; empty otherwise), in
/// one pass (`rz` for an RZ run). In RZ R is stored as R (1/r): the pair term weighs it
/// like the stress, once per particle rather than per pair; R_θθ tells the pair loop
/// where a side needs the kernel ratio f_ij for the hoop force.
pub(super) fn artificial_stresses<D: Dimension>(
    ext: &Extended<'_, D>,
    a: &sph_riemann::ArtificialStress,
    rz: bool,
) -> (Vec<D::Tensor>, Vec<bool>, Vec<f64>) {
    let n = ext.position.len();
    let mut tensors = vec![D::Tensor::ZERO; n];
    let mut on = vec![false; n];
    let mut hoops = if rz { vec![0.0; n] } else { Vec::new() };
    tensors
        .par_chunks_mut(PASS_CHUNK)
        .zip(on.par_chunks_mut(PASS_CHUNK))
        .zip(chunks_or_none(&mut hoops, n.div_ceil(PASS_CHUNK)))
        .enumerate()
        .for_each(|(c, ((tensors, on), mut hoops))| {
            for i in 0..tensors.len() {
                let k = c * PASS_CHUNK + i;
                let p = ext.pressure[k];
                let sigma = if !ext.has_stress() {
                    D::Tensor::IDENTITY * (-p)
                } else {
                    D::project(&ext.stress(k)) - D::Tensor::IDENTITY * p
                };
                let r = a.tensor(&sigma, p, ext.density[k]);
                tensors[i] = match ext.radius.get(k) {
                    Some(&w) => r * (1.0 / w),
                    None => r,
                };
                on[i] = tensors[i] != D::Tensor::ZERO;
                if let Some(hoops) = hoops.as_deref_mut() {
                    let s_tt = if ext.has_stress() {
                        ext.stress(k).z_axis.z
                    } else {
                        0.0
                    };
                    hoops[i] = a.hoop(s_tt - p, p, ext.density[k]);
                }
            }
        });
    (tensors, on, hoops)
}

/// P and c of every particle.
pub(super) fn eos_pass<D: Dimension>(
    p: &Particles<D>,
    materials: &[Material],
) -> (Vec<f64>, Vec<f64>) {
    let pc: Vec<(f64, f64)> = (0..p.len())
        .into_par_iter()
        .map(|i| {
            let pt = materials[p.material[i] as usize]
                .eos
                .evaluate(p.density[i], p.specific_energy[i]);
            (pt.pressure, pt.sound_speed)
        })
        .collect();
    pc.into_iter().unzip()
}

//! One derivative evaluation of a rank's local state (solver/ranks/local.rs): the first
//! step of a decomposition that distributes the particles (docs/mpi.md, "Distributed
//! particles: the design"), not yet used by the run. The search and both pair passes
//! read the rank's own rows only, in blocks of the global order's size from the first,
//! and the halo's pass-1 values come from their owners between the passes; so the own
//! rows' rates are those the whole state's stage gives them, to the bit.

use super::*;
use crate::solver::ranks::LocalState;
use stage::LocalRun;

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// The stage of `local` (a rank's own rows and halo from `exchange_halo`, the global
    /// order `n_global` particles long, the rank's range starting at one of its pair
    /// blocks), every rank calling it over `ranks`. Its rates are meant for the own rows;
    /// the halo's are not (their pairs are not all there). The summation density, which
    /// reads every row, is refused. Only its test calls it until the run distributes
    /// the particles (docs/mpi.md, "Distributed particles: the design").
    #[cfg_attr(not(test), allow(dead_code))]
    pub(super) fn local_stage(
        &mut self,
        local: &mut LocalState<D>,
        n_global: usize,
        ranks: &dyn Ranks,
    ) -> Result<Stage<D>, SolverError> {
        if self.scheme.density == DensityForm::Summation {
            return Err(SolverError::Exchange(
                "a local state's stage cannot use the summation density, which reads the \
                 halo's rows"
                    .into(),
            ));
        }
        let rows = self
            .pair_block_rows
            .unwrap_or_else(|| pair_blocks::block_rows(n_global));
        let first = local.global.get(local.own.start).copied().unwrap_or(0) as usize;
        if !first.is_multiple_of(rows) {
            return Err(SolverError::Exchange(format!(
                "the rank's first row {first} is not at the start of a pair block of {rows}"
            )));
        }
        let saved = self.pair_block_rows.replace(rows);
        let LocalState {
            state, own, halo, ..
        } = local;
        let run = LocalRun {
            own: own.clone(),
            halo,
            ranks,
        };
        let out = self.stage(state, None, false, &OneRank, Some(&run));
        self.pair_block_rows = saved;
        out.map(|(stage, _)| stage)
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::{Scene, SceneSimulation};
    use crate::solver::ranks::{Flat, OneRank, exchange_halo, test_threads::Threads};
    use crate::solver::simulation::pair_blocks;
    use std::sync::{Barrier, Mutex};

    /// On the 3-D smoke scene (solid, damage, artificial stress) shared among 2 and 3
    /// ranks as threads, each rank's local stage gives its own rows the rates (every
    /// f64 of dρ/dt, dv/dt, de/dt, the approach speed and the work) of the whole state's
    /// stage, to the bit.
    #[test]
    fn a_local_stage_gives_the_own_rows_the_whole_stages_rates() {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let text = std::fs::read_to_string(root.join("../../examples/scenes/smoke.toml")).unwrap();
        let scene = Scene::from_toml_str(&text, "smoke.toml").unwrap();
        let build = || match scene.build().unwrap().simulation {
            SceneSimulation::ThreeD(sim) => sim,
            _ => unreachable!("a 3-D scene"),
        };
        let mut whole = build();
        let mut state = whole.state.clone();
        let (expected, _) = whole
            .stage(&mut state, None, false, &OneRank, None)
            .unwrap();
        let bits = |r: &super::Rates<_>| {
            let mut v = Vec::new();
            r.put(&mut v);
            v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>()
        };
        let n = state.particles.len();
        let rows = pair_blocks::block_rows(n);
        let blocks = n.div_ceil(rows);
        for size in [2, 3] {
            // Each rank a contiguous range of whole blocks.
            let cuts: Vec<usize> = (0..=size)
                .map(|k| (k * blocks / size * rows).min(n))
                .collect();
            let posted = Mutex::new(vec![Vec::new(); size]);
            let all_here = Barrier::new(size);
            let results: Vec<Vec<(u64, Vec<u64>)>> = std::thread::scope(|scope| {
                let handles: Vec<_> = (0..size)
                    .map(|rank| {
                        let (posted, all_here, cuts) = (&posted, &all_here, &cuts);
                        let build = &build;
                        scope.spawn(move || {
                            let ranks = Threads::new(rank, size, posted, all_here);
                            let mut sim = build();
                            let mut all = sim.state.clone();
                            let mine: Vec<bool> = (0..n)
                                .map(|i| (cuts[rank]..cuts[rank + 1]).contains(&i))
                                .collect();
                            let own = all.split_off(&mine);
                            // The search's reach with a Verlet list's skin, and a margin.
                            let reach: Vec<f64> = own
                                .particles
                                .smoothing_length
                                .iter()
                                .map(|h| 1.5 * h)
                                .collect();
                            let boundaries = sim.boundaries.clone();
                            let mut local =
                                exchange_halo(&ranks, &own, cuts[rank] as u64, &reach, &boundaries)
                                    .unwrap();
                            let stage = sim.local_stage(&mut local, n, &ranks).unwrap();
                            local
                                .own
                                .clone()
                                .map(|k| (local.global[k], bits(&stage.rates[k])))
                                .collect()
                        })
                    })
                    .collect();
                handles.into_iter().map(|h| h.join().unwrap()).collect()
            });
            let mut checked = 0;
            for (rank, rows) in results.iter().enumerate() {
                for (g, got) in rows {
                    assert_eq!(
                        got,
                        &bits(&expected.rates[*g as usize]),
                        "row {g}, rank {rank} of {size}"
                    );
                    checked += 1;
                }
            }
            assert_eq!(checked, n, "every row checked once");
        }
    }
}

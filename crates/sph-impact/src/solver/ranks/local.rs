//! A rank's own particles and copies of its halo: the state's exchange that a
//! decomposition distributing the particles needs before each search (docs/mpi.md,
//! "Distributed particles: the design"). Not yet used by the run, which replicates the
//! state on every rank.
//!
//! Each rank owns a contiguous range of the global (Morton) order. It describes its rows
//! by boxes (`sph_core::regions_of_rows`) and every rank receives every rank's boxes; the
//! owner of a particle then sends it, with every field it owns, to each rank one of whose
//! boxes it may pair with (`sph_core::Region::may_pair`: closer than the larger of the two
//! reaches). A particle's images across the boundaries count as it does: the ghosts a
//! rank places from its own and halo particles must include those a single process places
//! for its rows, so a particle is sent where one of its images reaches a box. The images
//! are chained over the boundaries in their order, as the extended arrays place them
//! (a corner's ghost is a ghost's ghost, solver/state.rs). The received particles keep
//! their owners' order and the ranks' ranges ascend, so the local state is in global
//! order: every own row lists its partners in the order a single process does.

use super::{Halo, Ranks, get_vector, put_vector};
use crate::solver::boundary::{Boundary, Ghost};
use crate::solver::{SolverError, State};
use sph_core::{Dimension, Region, ScalarSupport, Vector, regions_of_rows};
use std::ops::Range;

/// Each region box at most this many of its particles' largest reach across, as the
/// partial search's boxes are (sph-core `HALO_REGION_SIZE`).
const REGION_SIZE: f64 = 4.0;

/// A rank's particles for a distributed run: its own, and copies of the other ranks'
/// particles that may pair with them or whose images may (its halo), in global order.
#[derive(Clone, Debug)]
pub struct LocalState<D: Dimension> {
    /// The particles with every field they own: the halo below the rank's range, its own
    /// rows, the halo above.
    pub state: State<D>,
    /// Each particle's row in the global order, ascending.
    pub global: Vec<u64>,
    /// The rows of `state` that are the rank's own.
    pub own: Range<usize>,
    /// Which particles go to which rank and where each rank's arrive, as local rows:
    /// [`LocalState::refresh`] sends along it, and the stage the halo's pass-1 values
    /// (`Halo::fill`, the replicated run's exchange by rows).
    pub(crate) halo: Halo,
}

/// Every rank calls this with its own particles `own` (rows `first..first + n` of the
/// global order, the ranks' ranges ascending with the rank), each particle's reach
/// (its support radius, with a Verlet list's skin where the halo is to last while the
/// list holds) and the run's boundaries (the RZ axis among them); each gets its
/// [`LocalState`]. Two collectives: an all-gather of the boxes and an exchange of the
/// particles.
pub fn exchange_halo<D: Dimension>(
    ranks: &dyn Ranks,
    own: &State<D>,
    first: u64,
    reach: &[f64],
    boundaries: &[Boundary<D>],
) -> Result<LocalState<D>, SolverError> {
    let n = own.particles.len();
    if reach.len() != n {
        return Err(SolverError::Exchange(format!(
            "{} reaches for {n} particles",
            reach.len()
        )));
    }
    let positions = &own.particles.position;
    let core = |e: sph_core::CoreError| SolverError::Exchange(e.to_string());
    let support = ScalarSupport::new(reach).map_err(core)?;
    let regions = regions_of_rows(positions, &support, 0..n, REGION_SIZE).map_err(core)?;
    let all = ranks.all_gather(put_regions(&regions));
    let (me, size) = (ranks.rank(), ranks.size());
    // Each particle's position and its images, once, for the tests against every rank.
    let images: Vec<Vec<D::Vector>> = positions
        .iter()
        .zip(reach)
        .map(|(&x, &r)| images_of(x, r, boundaries))
        .collect();
    // The own rows, which the local state holds too; each message copies some of them.
    let mut copy = own.clone();
    let mut messages = Vec::with_capacity(size);
    let mut sent = vec![Vec::new(); size];
    for k in 0..size {
        if k == me {
            messages.push(Vec::new());
            continue;
        }
        let theirs = get_regions::<D::Vector>(all.part(k));
        let send: Vec<bool> = images
            .iter()
            .zip(reach)
            .map(|(points, &r)| {
                points
                    .iter()
                    .any(|&x| theirs.iter().any(|b| b.may_pair(x, r)))
            })
            .collect();
        let rows: Vec<u64> = (first..first + n as u64)
            .zip(&send)
            .filter_map(|(g, &s)| s.then_some(g))
            .collect();
        sent[k] = (0..n as u32).filter(|&i| send[i as usize]).collect();
        messages.push(encode(&copy.copy_rows(&send), &rows)?);
    }
    let received = ranks.exchange(messages);
    let mut state = State {
        time: own.time,
        step: own.step,
        ..State::default()
    };
    let (mut global, mut own_rows) = (Vec::new(), 0..0);
    // The rows of the local state each rank's particles arrive in (none from itself).
    let mut receive = Vec::with_capacity(size);
    for (k, message) in received.into_iter().enumerate() {
        let start = global.len();
        if k == me {
            own_rows = start..start + n;
            state.append(&mut copy);
            global.extend(first..first + n as u64);
            receive.push(Vec::new());
        } else {
            let (mut part, rows) = decode::<D>(&message, k)?;
            state.append(&mut part);
            global.extend(rows);
            receive.push((start as u32..global.len() as u32).collect());
        }
    }
    if !global.windows(2).all(|w| w[0] < w[1]) {
        return Err(SolverError::Exchange(
            "the ranks' ranges of the global order do not ascend with the rank".into(),
        ));
    }
    // The rows sent, as rows of the local state.
    let shift = own_rows.start as u32;
    let send = sent
        .into_iter()
        .map(|rows| rows.into_iter().map(|i| i + shift).collect())
        .collect();
    Ok(LocalState {
        state,
        global,
        own: own_rows,
        halo: Halo { receive, send },
    })
}

impl<D: Dimension> LocalState<D> {
    /// Sends the halo again with its present fields: the same particles to the same
    /// ranks, each owner reading them from its own rows, and each rank overwrites its
    /// halo rows with them (a stage's refresh: the membership is kept while a Verlet
    /// list holds, the skin in the reach covering the motion). Every rank calls it.
    pub fn refresh(&mut self, ranks: &dyn Ranks) -> Result<(), SolverError> {
        let n = self.state.particles.len();
        let mut messages = Vec::with_capacity(ranks.size());
        for rows in &self.halo.send {
            if rows.is_empty() {
                messages.push(Vec::new());
                continue;
            }
            let mut keep = vec![false; n];
            for &j in rows {
                keep[j as usize] = true;
            }
            let global: Vec<u64> = rows.iter().map(|&j| self.global[j as usize]).collect();
            messages.push(encode(&self.state.copy_rows(&keep), &global)?);
        }
        for (k, message) in ranks.exchange(messages).into_iter().enumerate() {
            let rows = &self.halo.receive[k];
            let Some(&start) = rows.first() else {
                continue;
            };
            let (mut part, got) = decode::<D>(&message, k)?;
            if got
                .iter()
                .zip(rows)
                .any(|(&g, &j)| g != self.global[j as usize])
                || got.len() != rows.len()
            {
                return Err(SolverError::Exchange(format!(
                    "rank {k} sent other particles than those of its first exchange"
                )));
            }
            // A rank's particles arrive in consecutive rows (global order).
            self.state.overwrite_rows(start as usize, &mut part);
        }
        Ok(())
    }
}

/// `x` and its images across `boundaries` within `reach`, chained in the boundaries'
/// order as the extended arrays place ghosts (a later boundary images the earlier
/// images too).
fn images_of<D: Dimension>(x: D::Vector, reach: f64, boundaries: &[Boundary<D>]) -> Vec<D::Vector> {
    let mut points = vec![x];
    let mut made: Vec<Ghost<D>> = Vec::new();
    for b in boundaries {
        made.clear();
        for &p in &points {
            b.ghosts_within(0, p, reach, &mut made);
        }
        points.extend(made.iter().map(|g| g.position));
    }
    points
}

/// The boxes as f64s: per box its lower and upper corners and its reach.
fn put_regions<V: Vector>(regions: &[Region<V>]) -> Vec<f64> {
    let mut out = Vec::with_capacity(regions.len() * (2 * V::DIM + 1));
    for b in regions {
        put_vector(b.lo, &mut out);
        put_vector(b.hi, &mut out);
        out.push(b.reach);
    }
    out
}

/// The boxes [`put_regions`] wrote.
fn get_regions<V: Vector>(v: &[f64]) -> Vec<Region<V>> {
    v.chunks_exact(2 * V::DIM + 1)
        .map(|c| Region {
            lo: get_vector(c),
            hi: get_vector(&c[V::DIM..]),
            reach: c[2 * V::DIM],
        })
        .collect()
}

/// A message of particles: their count, their global rows, then their state in CBOR,
/// its length in bytes and the bytes eight to an f64 (bit patterns, not values).
fn encode<D: Dimension>(part: &State<D>, rows: &[u64]) -> Result<Vec<f64>, SolverError> {
    let mut bytes = Vec::new();
    ciborium::into_writer(part, &mut bytes)
        .map_err(|e| SolverError::Exchange(format!("cannot encode the particles: {e}")))?;
    let mut out = Vec::with_capacity(2 + rows.len() + bytes.len() / 8 + 1);
    out.push(f64::from_bits(rows.len() as u64));
    out.extend(rows.iter().map(|&g| f64::from_bits(g)));
    out.push(f64::from_bits(bytes.len() as u64));
    out.extend(bytes.chunks(8).map(|c| {
        let mut word = [0u8; 8];
        word[..c.len()].copy_from_slice(c);
        f64::from_bits(u64::from_le_bytes(word))
    }));
    Ok(out)
}

/// The particles and global rows of a message [`encode`] wrote, from rank `from`.
fn decode<D: Dimension>(message: &[f64], from: usize) -> Result<(State<D>, Vec<u64>), SolverError> {
    let bad = |what: &str| SolverError::Exchange(format!("message from rank {from}: {what}"));
    let word = |k: usize| {
        message
            .get(k)
            .map(|x| x.to_bits())
            .ok_or_else(|| bad("cut short"))
    };
    let count = word(0)? as usize;
    let rows: Vec<u64> = (1..=count).map(word).collect::<Result<_, _>>()?;
    let length = word(count + 1)? as usize;
    let words = message.get(count + 2..).ok_or_else(|| bad("cut short"))?;
    let bytes: Vec<u8> = words
        .iter()
        .flat_map(|x| x.to_bits().to_le_bytes())
        .collect();
    let bytes = bytes.get(..length).ok_or_else(|| bad("cut short"))?;
    let state: State<D> =
        ciborium::from_reader(bytes).map_err(|e| bad(&format!("cannot decode ({e})")))?;
    if state.particles.len() != rows.len() {
        return Err(bad("particle count differs from its rows'"));
    }
    Ok((state, rows))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::ranks::test_threads::Threads;
    use sph_core::Particles;
    use sph_core::dimension::Dim3;
    use sph_core::glam::{DMat3, DVec3};
    use std::sync::{Barrier, Mutex};

    /// A cloud of `n` particles in the unit cube with supports over two octaves, with the
    /// stress and damage in use so that every field kind travels: sorted along x
    /// (`slabs`), so that a rank's rows are a slab and its halo a layer, or in a fixed
    /// pseudo-random order, which spreads every rank over the whole cube (the rule must
    /// not depend on the order).
    fn cloud(n: usize, slabs: bool) -> State<Dim3> {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut position: Vec<DVec3> = (0..n).map(|_| DVec3::new(next(), next(), next())).collect();
        if slabs {
            position.sort_by(|a, b| a.x.total_cmp(&b.x));
        }
        let smoothing_length: Vec<f64> = (0..n).map(|_| 0.04 * 4f64.powf(next())).collect();
        let particles = Particles {
            velocity: position.iter().map(|x| *x * 10.0).collect(),
            mass: vec![1e-3; n],
            density: (0..n).map(|i| 2700.0 + i as f64).collect(),
            specific_energy: vec![1e4; n],
            material: vec![0; n],
            id: (0..n as u64).collect(),
            position,
            smoothing_length,
        };
        State {
            stress: (0..n)
                .map(|i| DMat3::from_diagonal(DVec3::splat(i as f64)))
                .collect(),
            damage_state: (0..n).map(|i| i as f64 / n as f64).collect(),
            particles,
            ..State::default()
        }
    }

    /// The positions (as bits) of every partner of each row `rows` among `positions` and
    /// their ghosts, placed as the extended arrays place them (each boundary in turn
    /// images every position so far, its own earlier images included), with the search's
    /// criterion |x_i − x_j| < max(h_i, h_j).
    fn partners(
        positions: &[DVec3],
        h: &[f64],
        boundaries: &[Boundary<Dim3>],
        rows: Range<usize>,
    ) -> Vec<Vec<[u64; 3]>> {
        let (mut x, mut r) = (positions.to_vec(), h.to_vec());
        let mut made = Vec::new();
        for b in boundaries {
            made.clear();
            b.ghosts(&x, &r, &mut made);
            for g in &made {
                x.push(g.position);
                r.push(r[g.source]);
            }
        }
        rows.map(|i| {
            let mut found: Vec<[u64; 3]> = (0..x.len())
                .filter(|&j| j != i && (x[i] - x[j]).length() < h[i].max(r[j]))
                .map(|j| x[j].to_array().map(f64::to_bits))
                .collect();
            found.sort_unstable();
            found
        })
        .collect()
    }

    /// Each rank's local state, searched alone, gives its rows the partners (real and
    /// ghosts, by position to the bit) that a search over every particle gives them,
    /// across a wall, a periodic pair of faces and their corner; and it holds every
    /// field of its particles as their owners hold them, in global order.
    #[test]
    fn a_ranks_local_state_gives_its_rows_the_partners_of_every_particle() {
        for slabs in [true, false] {
            check_local_states(&cloud(1500, slabs), slabs);
        }
    }

    /// [`a_refresh_and_a_share_give_the_halo_its_owners_present_values`] on `locals`.
    fn check_refresh(mut locals: Vec<LocalState<Dim3>>) {
        let size = locals.len();
        let moved = |g: u64| DVec3::new(1e-3, -2e-3, 3e-3) * (g % 7) as f64;
        for local in &mut locals {
            for k in local.own.clone() {
                let g = local.global[k];
                local.state.particles.position[k] += moved(g);
                local.state.stress[k] *= 2.0;
            }
        }
        let posted = Mutex::new(vec![Vec::new(); size]);
        let all_here = Barrier::new(size);
        let shared: Vec<(LocalState<Dim3>, Vec<[f64; 2]>)> = std::thread::scope(|scope| {
            let handles: Vec<_> = locals
                .into_iter()
                .enumerate()
                .map(|(rank, mut local)| {
                    let (posted, all_here) = (&posted, &all_here);
                    scope.spawn(move || {
                        let ranks = Threads::new(rank, size, posted, all_here);
                        local.refresh(&ranks).unwrap();
                        // Two values per particle, set on the own rows only.
                        let mut values = vec![[f64::NAN; 2]; local.global.len()];
                        for k in local.own.clone() {
                            let g = local.global[k] as f64;
                            values[k] = [g, -g];
                        }
                        let put = |x: &[f64; 2], out: &mut Vec<f64>| out.extend_from_slice(x);
                        local
                            .halo
                            .fill_by(&ranks, &mut values, 2, put, |v| [v[0], v[1]]);
                        (local, values)
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        for (local, values) in &shared {
            for (k, &g) in local.global.iter().enumerate() {
                let owner = &shared
                    .iter()
                    .find(|(l, _)| l.global[l.own.clone()].contains(&g))
                    .expect("every particle has an owner")
                    .0;
                let o = owner.own.start + (g - owner.global[owner.own.start]) as usize;
                let (p, q) = (&local.state.particles, &owner.state.particles);
                assert_eq!(p.position[k].to_array(), q.position[o].to_array());
                assert_eq!(local.state.stress[k], owner.state.stress[o]);
                assert_eq!(values[k], [g as f64, -(g as f64)]);
            }
        }
    }

    /// A wall at z = 0 and a periodic pair of faces in x, whose corner images chain.
    fn wall_and_period() -> [Boundary<Dim3>; 2] {
        [
            Boundary::Wall {
                point: DVec3::ZERO,
                normal: DVec3::Z,
            },
            Boundary::Periodic {
                axis: 0,
                lo: 0.0,
                hi: 1.0,
            },
        ]
    }

    /// The first row of each of `size` equal ranges of `n` rows, and `n`.
    fn cuts(n: usize, size: usize) -> Vec<usize> {
        (0..=size).map(|k| k * n / size).collect()
    }

    /// Each rank's local state, the ranks (as threads) owning the rows between `cuts`.
    fn local_states(
        whole: &State<Dim3>,
        cuts: &[usize],
        boundaries: &[Boundary<Dim3>],
    ) -> Vec<LocalState<Dim3>> {
        let (n, size) = (whole.particles.len(), cuts.len() - 1);
        let posted = Mutex::new(vec![Vec::new(); size]);
        let all_here = Barrier::new(size);
        std::thread::scope(|scope| {
            let handles: Vec<_> = (0..size)
                .map(|rank| {
                    let (posted, all_here) = (&posted, &all_here);
                    scope.spawn(move || {
                        let mut all = whole.clone();
                        let mine: Vec<bool> = (0..n)
                            .map(|i| (cuts[rank]..cuts[rank + 1]).contains(&i))
                            .collect();
                        let own = all.split_off(&mine);
                        let ranks = Threads::new(rank, size, posted, all_here);
                        let h = own.particles.smoothing_length.clone();
                        exchange_halo(&ranks, &own, cuts[rank] as u64, &h, boundaries).unwrap()
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        })
    }

    /// After every rank moves its own particles and changes their stress, a refresh gives
    /// every halo row its owner's new fields, and the halo's `fill` its owner's values.
    #[test]
    fn a_refresh_and_a_share_give_the_halo_its_owners_present_values() {
        let whole = cloud(1500, true);
        for size in [2, 3, 5] {
            let locals = local_states(&whole, &cuts(1500, size), &wall_and_period());
            check_refresh(locals);
        }
    }

    /// [`a_ranks_local_state_gives_its_rows_the_partners_of_every_particle`] on `whole`.
    fn check_local_states(whole: &State<Dim3>, slabs: bool) {
        let boundaries = wall_and_period();
        let p = &whole.particles;
        let n = p.len();
        let expected = partners(&p.position, &p.smoothing_length, &boundaries, 0..n);
        for size in [1, 2, 3, 5] {
            let cuts = cuts(n, size);
            let locals = local_states(whole, &cuts, &boundaries);
            for (rank, local) in locals.iter().enumerate() {
                let q = &local.state.particles;
                let g: Vec<usize> = local.global.iter().map(|&g| g as usize).collect();
                assert_eq!(local.own.len(), cuts[rank + 1] - cuts[rank]);
                assert_eq!(g[local.own.start], cuts[rank]);
                assert!(g.windows(2).all(|w| w[0] < w[1]), "global order");
                for (k, &i) in g.iter().enumerate() {
                    assert_eq!(q.position[k].to_array(), p.position[i].to_array());
                    assert_eq!(q.velocity[k].to_array(), p.velocity[i].to_array());
                    assert_eq!(q.id[k], p.id[i]);
                    assert_eq!(local.state.stress[k], whole.stress[i]);
                    assert_eq!(local.state.damage_state[k], whole.damage_state[i]);
                }
                let found = partners(
                    &q.position,
                    &q.smoothing_length,
                    &boundaries,
                    local.own.clone(),
                );
                for (k, row) in found.iter().enumerate() {
                    let i = g[local.own.start + k];
                    assert_eq!(row, &expected[i], "row {i} on rank {rank} of {size}");
                }
                let (own, halo) = (local.own.len(), g.len() - local.own.len());
                println!("{size} ranks, rank {rank}: {own} own, {halo} halo");
                // In slabs the boxes pick a layer, not every other rank's particle.
                if slabs && size == 5 {
                    assert!(
                        halo < (n - own) / 2,
                        "rank {rank}: halo {halo} of {}",
                        n - own
                    );
                }
            }
        }
    }
}

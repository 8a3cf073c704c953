//! ParaView output: a snapshot per output interval and `run.pvd` listing them with their
//! times (docs/scenes.md lists the arrays).
//!
//! On one rank a snapshot is `snapshots/NNNNN.vtu`. Over N > 1 MPI ranks (docs/mpi.md)
//! each rank writes its piece, `snapshots/NNNNN_K.vtu` (K the rank), and rank 0, once
//! every piece is on disk, `snapshots/NNNNN.pvtu`, which joins them for ParaView; the
//! collection lists the `.pvtu`. Piece K holds the particles
//! [K n / N, (K + 1) n / N) of the state's order, a region along the Morton curve.

use crate::run::arrays::Arrays;
use crate::run::atomic;
use crate::run::error::RunError;
use crate::scene::{SceneDimension, SimOf};
use crate::solver::Ranks;
use sph_diagnostics::pvtu::write_pvtu_to;
use sph_diagnostics::{Pvd, VtuWriter};
use std::ops::Range;
use std::path::Path;

/// The arrays of a snapshot beside those the diagnostics share ([`Arrays`]): pressure,
/// the stress tensor in the scene's frame and, where a material has a thermal model,
/// temperature.
struct Fields {
    pressure: Vec<f64>,
    stress: Vec<[f64; 9]>,
    temperature: Vec<f64>,
}

impl Fields {
    fn of<D: SceneDimension>(sim: &SimOf<D>) -> Self {
        let s = &sim.state;
        let (pressure, _) = sim.pressure_and_sound_speed();
        let stress = s
            .stress
            .iter()
            .map(|m| D::tensor_to_scene(m).to_cols_array())
            .collect();
        // Temperature only where a material has a thermal model (NaN for the others,
        // which the solver holds at 300 K without one); no array when none has.
        let thermal = sim.materials.iter().any(|m| m.thermal.is_some());
        let temperature = if thermal {
            (0..s.particles.len())
                .map(|i| {
                    sim.materials[s.particles.material[i] as usize]
                        .thermal
                        .as_ref()
                        .map_or(f64::NAN, |t| t.temperature(s.particles.specific_energy[i]))
                })
                .collect()
        } else {
            Vec::new()
        };
        Self {
            pressure,
            stress,
            temperature,
        }
    }

    /// The writer of every particle. Points, vectors and the stress tensor are in the
    /// scene's frame: an RZ ring is the point (r, 0, z) with (v_r, 0, v_z), its
    /// deviatoric stress in (r, θ, z) components and its whole mass.
    fn writer<'a, D: SceneDimension>(&'a self, sim: &'a SimOf<D>, a: &'a Arrays) -> VtuWriter<'a> {
        let s = &sim.state;
        let mut w = VtuWriter::new(s.particles.len());
        w.points(&a.position)
            .vector("velocity", &a.velocity)
            .scalar("density", &a.density)
            .scalar("pressure", &self.pressure)
            .scalar("damage", &a.damage)
            .scalar("specific_energy", &a.specific_energy)
            .scalar("mass", &a.mass)
            .scalar("smoothing_length", &s.particles.smoothing_length)
            .uint16("material", &a.body)
            .uint64("id", &s.particles.id);
        if !self.stress.is_empty() {
            w.tensor("deviatoric_stress", &self.stress);
            w.scalar("plastic_strain", &s.plastic_strain);
        }
        if !self.temperature.is_empty() {
            w.scalar("temperature", &self.temperature);
        }
        w
    }
}

/// The particles of rank `rank`'s piece out of `n` shared by `size` ranks.
pub(crate) fn piece_rows(n: usize, rank: usize, size: usize) -> Range<usize> {
    n * rank / size..n * (rank + 1) / size
}

/// The name of snapshot `index`'s file in `snapshots/`: the `.vtu` on one rank, else the
/// `.pvtu` (`piece: None`) or rank K's piece (`Some(K)`).
fn file_name(index: usize, size: usize, piece: Option<usize>) -> String {
    match (size, piece) {
        (1, _) => format!("{index:05}.vtu"),
        (_, None) => format!("{index:05}.pvtu"),
        (_, Some(k)) => format!("{index:05}_{k}.vtu"),
    }
}

/// The snapshot number a file of `snapshots/` belongs to (its leading digits: `00012`
/// of `00012.vtu`, `00012.pvtu` and `00012_3.vtu`), if any.
pub(crate) fn snapshot_number(file: &str) -> Option<usize> {
    let digits = file.len() - file.trim_start_matches(|c: char| c.is_ascii_digit()).len();
    file[..digits].parse().ok()
}

/// Writes this rank's part of snapshot `index` of `sim` into `dir/snapshots/`: the whole
/// `.vtu` on one rank, else its piece, waiting for every rank's (an error names the
/// ranks whose pieces failed). Rank 0 (`pvd: Some`) then writes the `.pvtu` and adds the
/// snapshot to `dir/run.pvd`, rewritten so that an interrupted run can still be opened.
fn write_part<D: SceneDimension>(
    sim: &SimOf<D>,
    arrays: &Arrays,
    dir: &Path,
    index: usize,
    ranks: &dyn Ranks,
    pvd: Option<&mut Pvd>,
) -> Result<(), RunError> {
    let fields = Fields::of::<D>(sim);
    let whole = fields.writer::<D>(sim, arrays);
    let (rank, size) = (ranks.rank(), ranks.size());
    let snapshots = dir.join("snapshots");
    let path = snapshots.join(file_name(index, size, Some(rank)));
    // On one rank the piece is every particle: the whole .vtu.
    let rows = piece_rows(sim.state.particles.len(), rank, size);
    let written = atomic::write_with(&path, false, |f| whole.piece(rows).write_to(f));
    // Every piece on disk before the .pvtu (and any checkpoint) that lists it.
    let ok = ranks.all_gather(vec![if written.is_ok() { 1.0 } else { 0.0 }]);
    written?;
    let failed: Vec<String> = (0..size)
        .filter(|&k| ok.part(k) != [1.0])
        .map(|k| k.to_string())
        .collect();
    if !failed.is_empty() {
        return Err(RunError::Diagnostics(format!(
            "snapshot {index}: rank(s) {} could not write their piece",
            failed.join(", ")
        )));
    }
    let Some(pvd) = pvd else {
        return Ok(());
    };
    let name = file_name(index, size, None);
    if size > 1 {
        let sources: Vec<String> = (0..size).map(|k| file_name(index, size, Some(k))).collect();
        atomic::write_with(&snapshots.join(&name), false, |f| {
            write_pvtu_to(f, &whole, &sources)
        })?;
    }
    pvd.push(sim.state.time, format!("snapshots/{name}"));
    write_pvd(pvd, dir)
}

/// Rank 0: writes snapshot number `index` of `sim` (its `.vtu`, or its piece and, once
/// the other ranks have written theirs, the `.pvtu`) and adds it to `dir/run.pvd`.
pub(crate) fn write_snapshot<D: SceneDimension>(
    sim: &SimOf<D>,
    arrays: &Arrays,
    dir: &Path,
    index: usize,
    pvd: &mut Pvd,
    ranks: &dyn Ranks,
) -> Result<(), RunError> {
    write_part::<D>(sim, arrays, dir, index, ranks, Some(pvd))
}

/// A rank other than 0: writes its piece of snapshot `index` of `sim` (rank 0 writes the
/// `.pvtu` that lists it).
pub(crate) fn write_piece<D: SceneDimension>(
    sim: &SimOf<D>,
    copies: f64,
    dir: &Path,
    index: usize,
    ranks: &dyn Ranks,
) -> Result<(), RunError> {
    write_part::<D>(sim, &Arrays::of::<D>(sim, copies), dir, index, ranks, None)
}

/// Writes `dir/run.pvd` (via a temporary name).
pub(crate) fn write_pvd(pvd: &Pvd, dir: &Path) -> Result<(), RunError> {
    atomic::write_with(&dir.join("run.pvd"), false, |f| pvd.write_to(f))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pieces_cover_the_particles_in_order_and_differ_by_at_most_one() {
        for n in [0, 1, 5, 64, 1001] {
            for size in 1..=7 {
                let rows: Vec<_> = (0..size).map(|k| piece_rows(n, k, size)).collect();
                assert_eq!(rows[0].start, 0);
                assert_eq!(rows[size - 1].end, n);
                for w in rows.windows(2) {
                    assert_eq!(w[0].end, w[1].start);
                }
                let (lo, hi) = (n / size, n.div_ceil(size));
                assert!(
                    rows.iter().all(|r| (lo..=hi).contains(&r.len())),
                    "{rows:?}"
                );
            }
        }
    }

    #[test]
    fn file_names_and_their_snapshot_numbers() {
        assert_eq!(file_name(7, 1, Some(0)), "00007.vtu");
        assert_eq!(file_name(7, 1, None), "00007.vtu");
        assert_eq!(file_name(7, 4, None), "00007.pvtu");
        assert_eq!(file_name(7, 4, Some(3)), "00007_3.vtu");
        for name in ["00007.vtu", "00007.pvtu", "00007_3.vtu", "00007.vtu.part"] {
            assert_eq!(snapshot_number(name), Some(7), "{name}");
        }
        assert_eq!(snapshot_number("123456_12.vtu"), Some(123456));
        assert_eq!(snapshot_number("notes.txt"), None);
        assert_eq!(snapshot_number(".vtu"), None);
    }
}

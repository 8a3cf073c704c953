//! ParaView output: `snapshots/NNNNN.vtu` per snapshot and `run.pvd` listing them with
//! their times (docs/scenes.md lists the arrays).

use crate::run::arrays::Arrays;
use crate::run::atomic;
use crate::run::error::RunError;
use crate::scene::{SceneDimension, SimOf};
use sph_diagnostics::{Pvd, VtuWriter};
use std::path::Path;

/// Writes snapshot number `index` of `sim` into `dir/snapshots/` and rewrites
/// `dir/run.pvd` with it added (so an interrupted run can still be opened). Points,
/// vectors and the stress tensor are in the scene's frame: an RZ ring is the point
/// (r, 0, z) with (v_r, 0, v_z), its deviatoric stress in (r, θ, z) components and its
/// whole mass.
pub(crate) fn write_snapshot<D: SceneDimension>(
    sim: &SimOf<D>,
    arrays: &Arrays,
    pressure: &[f64],
    dir: &Path,
    index: usize,
    pvd: &mut Pvd,
) -> Result<(), RunError> {
    let name = format!("snapshots/{index:05}.vtu");
    let path = dir.join(&name);
    let s = &sim.state;
    let n = s.particles.len();
    let stress: Vec<[f64; 9]> = s
        .stress
        .iter()
        .map(|m| D::tensor_to_scene(m).to_cols_array())
        .collect();
    // Temperature only where a material has a thermal model (NaN for the others, which
    // the solver holds at 300 K without one); no array when none has.
    let thermal = sim.materials.iter().any(|m| m.thermal.is_some());
    let temperature: Vec<f64> = if thermal {
        (0..n)
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
    let mut w = VtuWriter::new(n);
    w.points(&arrays.position)
        .vector("velocity", &arrays.velocity)
        .scalar("density", &arrays.density)
        .scalar("pressure", pressure)
        .scalar("damage", &arrays.damage)
        .scalar("specific_energy", &arrays.specific_energy)
        .scalar("mass", &arrays.mass)
        .scalar("smoothing_length", &s.particles.smoothing_length)
        .uint16("material", &arrays.body)
        .uint64("id", &s.particles.id);
    if !stress.is_empty() {
        w.tensor("deviatoric_stress", &stress);
        w.scalar("plastic_strain", &s.plastic_strain);
    }
    if thermal {
        w.scalar("temperature", &temperature);
    }
    atomic::write_with(&path, false, |f| w.write_to(f))?;
    pvd.push(s.time, name);
    write_pvd(pvd, dir)
}

/// Writes `dir/run.pvd` (via a temporary name).
pub(crate) fn write_pvd(pvd: &Pvd, dir: &Path) -> Result<(), RunError> {
    atomic::write_with(&dir.join("run.pvd"), false, |f| pvd.write_to(f))
}

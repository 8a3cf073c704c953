//! Checkpoints (restart files): with `RunOptions::checkpoint` a run writes
//! `checkpoint.cbor` into its directory at every snapshot before the end, and with
//! `RunOptions::resume` a run continues from it (docs/scenes.md, "Checkpoints").
//!
//! A checkpoint holds what the run carries from step to step and cannot rebuild: the
//! solver's evolving state ([`SolverCheckpoint`]), the output cadence, the snapshots
//! so far, the last crater reading, the work done, and the number of `history.csv` rows
//! written. What the set-up rebuilds (the particles at t = 0, the materials and their
//! flaws, the diagnostics' calibration on the initial state, the initial totals) is
//! rebuilt from the scene, which must be the one the checkpoint was written for. A
//! resumed run then steps on bit for bit as the run that wrote it would have.
//!
//! The format is CBOR (serde): binary, and exact for every f64.

use crate::run::RunOptions;
use crate::run::error::RunError;
use crate::scene::{Scene, SceneDimension};
use crate::solver::SolverCheckpoint;
use serde::{Deserialize, Serialize};
use std::io::{BufReader, BufWriter, Write};
use std::path::Path;

/// The checkpoint's file name in the run directory.
pub const CHECKPOINT_FILE: &str = "checkpoint.cbor";

/// Bumped whenever the layout changes; a file of another format is refused.
const FORMAT: u32 = 2;

/// What is checked before the (large) solver state is read.
#[derive(Deserialize)]
struct Header {
    format: u32,
    version: String,
    geometry: String,
}

/// A run's checkpoint.
#[derive(Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct RunCheckpoint<D: SceneDimension> {
    pub format: u32,
    /// The writing program's version.
    pub version: String,
    /// The geometry (`GeometryKind` in Debug form).
    pub geometry: String,
    /// The scene as JSON (the summary's form), to recognise it on resume.
    pub scene: String,
    pub resolution_scale: f64,
    /// The end time of the run that wrote it (s).
    pub end_time: f64,
    /// The next snapshot time (s).
    pub next_snapshot: f64,
    /// The next snapshot's number.
    pub snapshot_index: usize,
    /// The snapshots written so far (time, file).
    pub pvd: Vec<(f64, String)>,
    /// The last snapshot's reading: crater depth, diameter, axis depth (m) and β from the
    /// detached ejecta (format 2 on).
    pub crater: [f64; 4],
    /// Steps and particle-steps done so far.
    pub steps: u64,
    pub particle_steps: u64,
    /// Wall time so far: the stepping alone, and the whole run (s).
    pub stepping_s: f64,
    pub wall_s: f64,
    /// Rows of `history.csv` written up to this checkpoint (the header not counted).
    pub history_rows: usize,
    /// The simulated times of the checkpoints the run has resumed from so far.
    pub resumed_from_s: Vec<f64>,
    pub solver: SolverCheckpoint<D::Dim>,
}

/// The scene's name of a checkpoint's geometry tag (the `GeometryKind` in Debug form,
/// kept so that checkpoints of earlier versions still read; "3d" for a quarter model's).
fn geometry_name(tag: &str) -> String {
    use crate::scene::GeometryKind::*;
    [ThreeD, Rz, Plane, Line]
        .into_iter()
        .find(|g| format!("{g:?}") == tag)
        .map_or_else(|| tag.to_owned(), |g| g.name().to_owned())
}

impl<D: SceneDimension> RunCheckpoint<D> {
    /// The scene in the form stored and compared.
    pub fn scene_text(scene: &Scene) -> Result<String, RunError> {
        serde_json::to_string(scene)
            .map_err(|e| RunError::Diagnostics(format!("scene as JSON: {e}")))
    }

    /// The program's format, version and geometry tags.
    pub fn tags() -> (u32, String, String) {
        (
            FORMAT,
            env!("CARGO_PKG_VERSION").to_owned(),
            format!("{:?}", D::KIND),
        )
    }

    /// Writes `dir/checkpoint.cbor`, through a temporary file renamed over it, so that
    /// a run stopped while writing keeps its previous checkpoint.
    pub fn write(&self, dir: &Path) -> Result<(), RunError> {
        let path = dir.join(CHECKPOINT_FILE);
        let part = dir.join(format!("{CHECKPOINT_FILE}.part"));
        let file = std::fs::File::create(&part).map_err(|e| RunError::io(&part, e))?;
        let mut w = BufWriter::new(file);
        ciborium::into_writer(self, &mut w).map_err(|e| RunError::io(&part, e))?;
        w.flush().map_err(|e| RunError::io(&part, e))?;
        w.get_ref().sync_all().map_err(|e| RunError::io(&part, e))?;
        std::fs::rename(&part, &path).map_err(|e| RunError::io(&path, e))
    }

    /// Reads `dir/checkpoint.cbor` and checks that it was written by this program's
    /// format for this geometry, for `scene` at the options' resolution, and that the
    /// run's end time lies beyond it.
    pub fn read(
        dir: &Path,
        scene: &Scene,
        options: &RunOptions,
        end_time: f64,
    ) -> Result<Self, RunError> {
        let path = dir.join(CHECKPOINT_FILE);
        let refuse = |reason: String| RunError::Resume {
            path: path.display().to_string(),
            reason,
        };
        let open = || -> Result<BufReader<std::fs::File>, RunError> {
            std::fs::File::open(&path).map(BufReader::new).map_err(|e| {
                refuse(format!(
                    "cannot open it ({e}); was the run started with --checkpoint?"
                ))
            })
        };
        let header: Header = ciborium::from_reader(open()?)
            .map_err(|e| refuse(format!("not a checkpoint ({e})")))?;
        let (format, version, geometry) = Self::tags();
        if header.format != format {
            return Err(refuse(format!(
                "its format is {}, this program reads {format} (written by version {})",
                header.format, header.version
            )));
        }
        if header.geometry != geometry {
            return Err(refuse(format!(
                "it is a geometry = \"{}\" run, the scene's geometry is \"{}\"",
                geometry_name(&header.geometry),
                D::KIND.name()
            )));
        }
        let c: Self =
            ciborium::from_reader(open()?).map_err(|e| refuse(format!("cannot read it ({e})")))?;
        if c.version != version {
            return Err(refuse(format!(
                "it was written by version {}, this is {version}",
                c.version
            )));
        }
        if c.scene != Self::scene_text(scene)? {
            return Err(refuse(
                "it was written for another scene (the scene file changed)".to_owned(),
            ));
        }
        if c.resolution_scale != options.resolution_scale {
            return Err(refuse(format!(
                "it was written at --resolution-scale {}, not {}",
                c.resolution_scale, options.resolution_scale
            )));
        }
        let t = c.solver.state.time;
        if !(end_time > t) {
            return Err(refuse(format!(
                "it is at t = {t:e} s, at or past the end time {end_time:e} s"
            )));
        }
        Ok(c)
    }
}

//! Checkpoints (restart files): with `RunOptions::checkpoint` a run writes a checkpoint
//! into `checkpoints/` in its directory at every snapshot before the end, and on a stop
//! request (SIGINT, SIGTERM) after the step under way; it keeps the last
//! `RunOptions::keep_checkpoints` of them. With `RunOptions::resume` a run continues from
//! the newest, or from `RunOptions::resume_from` (docs/scenes.md, "Checkpoints").
//!
//! A checkpoint holds what the run carries from step to step and cannot rebuild: the
//! solver's evolving state ([`SolverCheckpoint`]), the output cadence, the snapshots
//! so far, the last crater reading, the work done, and the number of `history.csv` rows
//! written. What the set-up rebuilds (the particles at t = 0, the materials and their
//! flaws, the diagnostics' calibration on the initial state, the initial totals) is
//! rebuilt from the scene, which must be the one the checkpoint was written for (the
//! scene itself is stored and compared). A resumed run then steps on bit for bit as the
//! run that wrote it would have.
//!
//! The file is a fixed frame around CBOR (serde; exact for every f64): the magic
//! [`MAGIC`], the frame's version, the payload's length and its CRC-32, then the
//! payload. A file whose length or checksum does not match (a flipped bit, a truncated
//! copy), or whose times and counts are not those of a run (a negative time, a NaN next
//! snapshot, a zero first step), is refused with the reason.

use crate::run::RunOptions;
use crate::run::atomic;
use crate::run::error::RunError;
use crate::scene::{Scene, SceneDimension};
use crate::solver::SolverCheckpoint;
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::{Path, PathBuf};

/// The sub-directory of the run directory that holds the checkpoints.
pub const CHECKPOINT_DIR: &str = "checkpoints";

/// The first bytes of every checkpoint file.
pub const MAGIC: &[u8; 8] = b"SPHICKPT";

/// The frame's version (the layout of the bytes after [`MAGIC`]).
const FRAME: u32 = 1;

/// Bytes of the frame before the payload: magic, frame version, length, CRC-32.
const FRAME_BYTES: usize = 8 + 4 + 8 + 4;

/// Bumped whenever the payload's layout changes; a file of another format is refused.
const FORMAT: u32 = 3;

/// A checkpoint's file name: the steps done, zero-padded so that names sort by step.
fn file_name(steps: u64) -> String {
    format!("step-{steps:012}.cbor")
}

/// The checkpoints in `dir/checkpoints/`, oldest first, with the steps each was
/// written after.
pub fn checkpoints(dir: &Path) -> Vec<(u64, PathBuf)> {
    let Ok(entries) = std::fs::read_dir(dir.join(CHECKPOINT_DIR)) else {
        return Vec::new();
    };
    let mut found: Vec<(u64, PathBuf)> = entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let steps = name
                .strip_prefix("step-")?
                .strip_suffix(".cbor")?
                .parse()
                .ok()?;
            Some((steps, e.path()))
        })
        .collect();
    found.sort();
    found
}

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

    /// Writes the checkpoint into `dir/checkpoints/` (via a temporary name, synced to
    /// disk, then renamed) and removes the oldest beyond the last `keep`. Returns the
    /// file written.
    pub fn write(&self, dir: &Path, keep: usize) -> Result<PathBuf, RunError> {
        let folder = dir.join(CHECKPOINT_DIR);
        std::fs::create_dir_all(&folder).map_err(|e| RunError::io(&folder, e))?;
        let path = folder.join(file_name(self.steps));
        let mut payload = Vec::new();
        ciborium::into_writer(self, &mut payload).map_err(|e| RunError::io(&path, e))?;
        atomic::write_with(&path, true, |w| {
            w.write_all(MAGIC)?;
            w.write_all(&FRAME.to_le_bytes())?;
            w.write_all(&(payload.len() as u64).to_le_bytes())?;
            w.write_all(&crc32fast::hash(&payload).to_le_bytes())?;
            w.write_all(&payload)
        })?;
        let all = checkpoints(dir);
        for (_, old) in &all[..all.len().saturating_sub(keep.max(1))] {
            std::fs::remove_file(old).map_err(|e| RunError::io(old, e))?;
        }
        Ok(path)
    }

    /// The checkpoint to resume from: `options.resume_from` when given (a path, or a
    /// file name in `dir/checkpoints/`), else the newest in `dir/checkpoints/`.
    pub fn choose(dir: &Path, options: &RunOptions) -> Result<PathBuf, RunError> {
        if let Some(from) = &options.resume_from {
            let inside = dir.join(CHECKPOINT_DIR).join(from);
            return Ok(if from.is_file() || !inside.is_file() {
                from.clone()
            } else {
                inside
            });
        }
        checkpoints(dir)
            .pop()
            .map(|(_, p)| p)
            .ok_or_else(|| RunError::Resume {
                path: dir.join(CHECKPOINT_DIR).display().to_string(),
                reason: if dir.join("checkpoint.cbor").is_file() {
                    "no checkpoint there, only checkpoint.cbor of an earlier version (format \
                     2), which this version does not read"
                        .to_owned()
                } else {
                    "no checkpoint there; was the run started with --checkpoint?".to_owned()
                },
            })
    }

    /// Reads the checkpoint at `path` and checks its frame (length, CRC-32), that it was
    /// written by this program's format for this geometry, for `scene` at the options'
    /// resolution, that its times and counts are a run's, and that the run's end time
    /// lies beyond it.
    pub fn read(
        path: &Path,
        scene: &Scene,
        options: &RunOptions,
        end_time: f64,
    ) -> Result<Self, RunError> {
        let refuse = |reason: String| RunError::Resume {
            path: path.display().to_string(),
            reason,
        };
        let bytes = std::fs::read(path).map_err(|e| refuse(format!("cannot read it ({e})")))?;
        let payload = unframe(&bytes).map_err(refuse)?;
        let header: Header = ciborium::from_reader(payload)
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
            ciborium::from_reader(payload).map_err(|e| refuse(format!("cannot read it ({e})")))?;
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
        c.check_times().map_err(refuse)?;
        let t = c.solver.state.time;
        if !(end_time > t) {
            return Err(refuse(format!(
                "it is at t = {t:e} s, at or past the end time {end_time:e} s"
            )));
        }
        Ok(c)
    }

    /// The times and counts must be those of a run in progress: a checksum guards the
    /// bytes, this guards against a file written wrong.
    fn check_times(&self) -> Result<(), String> {
        let t = self.solver.state.time;
        if !(t.is_finite() && t >= 0.0) {
            return Err(format!("its time {t:e} s is not a run's"));
        }
        if !(self.end_time.is_finite() && self.end_time > 0.0) {
            return Err(format!("its end time {:e} s is not a run's", self.end_time));
        }
        if !(self.next_snapshot.is_finite() && self.next_snapshot > t) {
            return Err(format!(
                "its next snapshot time {:e} s does not lie after its time {t:e} s",
                self.next_snapshot
            ));
        }
        if let Some(dt) = self.solver.first_dt
            && !(dt.is_finite() && dt > 0.0)
        {
            return Err(format!("its first time step {dt:e} s is not positive"));
        }
        if self.solver.state.step != self.steps || self.particle_steps < self.steps {
            return Err(format!(
                "its step counts disagree ({} in the solver, {} in the run, {} particle-steps)",
                self.solver.state.step, self.steps, self.particle_steps
            ));
        }
        if self.snapshot_index != self.pvd.len() || self.snapshot_index == 0 {
            return Err(format!(
                "it lists {} snapshots but names {} as the next",
                self.pvd.len(),
                self.snapshot_index
            ));
        }
        if !(self.stepping_s.is_finite() && self.wall_s.is_finite()) {
            return Err("its wall times are not finite".to_owned());
        }
        Ok(())
    }
}

/// The payload of a framed checkpoint, or why the frame is bad.
fn unframe(bytes: &[u8]) -> Result<&[u8], String> {
    if bytes.len() < FRAME_BYTES || &bytes[..8] != MAGIC {
        return Err("not a checkpoint (it does not start with this program's magic bytes)".into());
    }
    let word = |at: usize, n: usize| {
        let mut b = [0u8; 8];
        b[..n].copy_from_slice(&bytes[at..at + n]);
        u64::from_le_bytes(b)
    };
    let frame = word(8, 4);
    if frame != u64::from(FRAME) {
        return Err(format!(
            "its frame version is {frame}, this program reads {FRAME}"
        ));
    }
    let length = word(12, 8);
    let payload = &bytes[FRAME_BYTES..];
    if payload.len() as u64 != length {
        return Err(format!(
            "it is truncated or padded: {} bytes of payload where its frame says {length}",
            payload.len()
        ));
    }
    let crc = word(20, 4) as u32;
    if crc32fast::hash(payload) != crc {
        return Err("it is corrupt: the checksum (CRC-32) of its contents does not match".into());
    }
    Ok(payload)
}

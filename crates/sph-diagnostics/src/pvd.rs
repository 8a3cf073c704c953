//! A ParaView collection (`.pvd`): the list of `.vtu` snapshots with their times, so
//! ParaView plays a run as one time series (docs/diagnostics.md §7).

use crate::xml::escape_attribute;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// Time series of snapshot files, in the order pushed.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Pvd {
    entries: Vec<(f64, String)>,
}

impl Pvd {
    /// An empty collection.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds snapshot `file` at `time` (s). `file` is relative to the `.pvd`'s directory
    /// (ParaView resolves it that way), e.g. `"run/step_0010.vtu"`.
    pub fn push(&mut self, time: f64, file: impl Into<String>) -> &mut Self {
        self.entries.push((time, file.into()));
        self
    }

    /// The snapshots so far, (time, file), in the order pushed (to rebuild the
    /// collection when a run resumes).
    pub fn entries(&self) -> &[(f64, String)] {
        &self.entries
    }

    /// Number of snapshots.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// True if no snapshot was pushed.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Writes the collection at `path` (created or truncated). A non-finite time is an
    /// `InvalidInput` error.
    pub fn write(&self, path: impl AsRef<Path>) -> io::Result<()> {
        self.check()?;
        let mut w = BufWriter::new(File::create(path)?);
        self.write_to(&mut w)?;
        w.flush()
    }

    /// Writes the XML document to `w`.
    pub fn write_to<W: Write>(&self, w: &mut W) -> io::Result<()> {
        self.check()?;
        writeln!(w, "<?xml version=\"1.0\"?>")?;
        writeln!(
            w,
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">"
        )?;
        writeln!(w, "  <Collection>")?;
        for (time, file) in &self.entries {
            // `{:e}` is the shortest text that reads back to the same f64.
            writeln!(
                w,
                "    <DataSet timestep=\"{time:e}\" group=\"\" part=\"0\" file=\"{}\"/>",
                escape_attribute(file)
            )?;
        }
        writeln!(w, "  </Collection>")?;
        writeln!(w, "</VTKFile>")
    }

    fn check(&self) -> io::Result<()> {
        match self.entries.iter().find(|e| !e.0.is_finite()) {
            Some((t, f)) => Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!("snapshot \"{f}\" has time {t}, which is not finite"),
            )),
            None => Ok(()),
        }
    }
}

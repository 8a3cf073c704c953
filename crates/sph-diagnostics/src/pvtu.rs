//! A parallel VTU file (`.pvtu`): the header that joins several `.vtu` pieces, each
//! written by one process, into one data set for ParaView/VisIt (VTK File Formats,
//! "Parallel File Formats"). It declares the point-data arrays once (name, type,
//! components) and lists the pieces by file name, relative to the `.pvtu`'s directory.
//!
//! ```no_run
//! use sph_diagnostics::VtuWriter;
//! use sph_diagnostics::pvtu::write_pvtu;
//! let x = [[0.0, 0.0, 0.0], [1e-3, 0.0, 0.0]];
//! let rho = [2876.0, 2880.0];
//! let mut w = VtuWriter::new(2);
//! w.points(&x).scalar("density", &rho);
//! // Two processes would each write their half; here one writes both.
//! w.piece(0..1).write("out/00000_0.vtu")?;
//! w.piece(1..2).write("out/00000_1.vtu")?;
//! write_pvtu("out/00000.pvtu", &w, &["00000_0.vtu", "00000_1.vtu"])?;
//! # Ok::<(), std::io::Error>(())
//! ```

use crate::vtu::{VtuWriter, open_file};
use crate::xml::escape_attribute;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// Writes at `path` the `.pvtu` of the arrays `layout` declares (any piece's writer, or
/// the whole's: only the names, types and components are read) for the pieces `sources`.
pub fn write_pvtu(
    path: impl AsRef<Path>,
    layout: &VtuWriter,
    sources: &[impl AsRef<str>],
) -> io::Result<()> {
    check(layout, sources)?;
    let mut w = BufWriter::new(File::create(path)?);
    write_pvtu_to(&mut w, layout, sources)?;
    w.flush()
}

/// Writes the `.pvtu` XML document of [`write_pvtu`] to `w`.
pub fn write_pvtu_to<W: Write>(
    w: &mut W,
    layout: &VtuWriter,
    sources: &[impl AsRef<str>],
) -> io::Result<()> {
    check(layout, sources)?;
    open_file(w, "PUnstructuredGrid")?;
    // No ghost points: every point is in exactly one piece.
    writeln!(w, "  <PUnstructuredGrid GhostLevel=\"0\">")?;
    writeln!(w, "    <PPointData>")?;
    for (name, ty, components) in layout.declarations() {
        declare(w, name, ty, components)?;
    }
    writeln!(w, "    </PPointData>")?;
    writeln!(w, "    <PPoints>")?;
    declare(w, "Points", "Float64", 3)?;
    writeln!(w, "    </PPoints>")?;
    for s in sources {
        writeln!(
            w,
            "    <Piece Source=\"{}\"/>",
            escape_attribute(s.as_ref())
        )?;
    }
    writeln!(w, "  </PUnstructuredGrid>")?;
    writeln!(w, "</VTKFile>")
}

fn declare<W: Write>(w: &mut W, name: &str, ty: &str, components: usize) -> io::Result<()> {
    writeln!(
        w,
        "      <PDataArray type=\"{ty}\" Name=\"{}\" NumberOfComponents=\"{components}\"/>",
        escape_attribute(name)
    )
}

/// The layout's own mistakes (as [`VtuWriter::write`] reports them), or no pieces.
fn check(layout: &VtuWriter, sources: &[impl AsRef<str>]) -> io::Result<()> {
    layout.ready()?;
    if sources.is_empty() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "a parallel VTU file needs at least one piece",
        ));
    }
    match sources.iter().find(|s| s.as_ref().is_empty()) {
        Some(_) => Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "a piece of a parallel VTU file has an empty file name",
        )),
        None => Ok(()),
    }
}

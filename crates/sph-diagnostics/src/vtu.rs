//! Particles as a VTK XML UnstructuredGrid (`.vtu`) for ParaView/VisIt: one VTK_VERTEX
//! cell per particle, point-data arrays, inline base64 binary (docs/diagnostics.md §7).
//!
//! Format (VTK File Formats, "XML File Formats"; version 1.0 with `header_type="UInt64"`
//! so arrays over 4 GiB are allowed): each `DataArray` holds base64 of one byte stream —
//! an 8-byte little-endian byte count, then the little-endian values — encoded as a
//! single stream, which is how VTK's own writer writes uncompressed data and how its
//! reader expects it. Inline binary is ≈ ⅓ larger than raw but keeps one self-contained,
//! valid XML file, and is about 3× smaller than ASCII at full f64 precision.
//!
//! ```no_run
//! use sph_diagnostics::vtu::VtuWriter;
//! let x = [[0.0, 0.0, 0.0], [1e-3, 0.0, 0.0]];
//! let rho = [2876.0, 2880.0];
//! let mut w = VtuWriter::new(2);
//! w.points(&x).scalar("density", &rho);
//! w.write("out/step_0000.vtu")?;
//! # Ok::<(), std::io::Error>(())
//! ```

use crate::xml::escape_attribute;
use base64::engine::GeneralPurpose;
use base64::engine::general_purpose::STANDARD;
use base64::write::EncoderWriter;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::ops::Range;
use std::path::Path;

/// VTK cell type of a single point.
const VTK_VERTEX: u8 = 1;

/// Builder of one `.vtu` file; borrows the arrays until it is written. Mistakes (wrong
/// length, repeated or empty name, no points) are reported by [`write`] as
/// `io::ErrorKind::InvalidInput`, naming the array.
///
/// [`write`]: VtuWriter::write
#[derive(Debug)]
pub struct VtuWriter<'a> {
    n_points: usize,
    points: Option<&'a [[f64; 3]]>,
    arrays: Vec<(String, Data<'a>)>,
    problem: Option<String>,
}

/// One point-data array.
#[derive(Clone, Copy, Debug)]
enum Data<'a> {
    Scalar(&'a [f64]),
    Vector(&'a [[f64; 3]]),
    Tensor(&'a [[f64; 9]]),
    Int(&'a [i32]),
    UInt16(&'a [u16]),
    UInt64(&'a [u64]),
}

impl<'a> Data<'a> {
    fn len(&self) -> usize {
        match self {
            Data::Scalar(a) => a.len(),
            Data::Vector(a) => a.len(),
            Data::Tensor(a) => a.len(),
            Data::Int(a) => a.len(),
            Data::UInt16(a) => a.len(),
            Data::UInt64(a) => a.len(),
        }
    }

    /// The entries of `rows` (a range inside the array).
    fn slice(&self, rows: Range<usize>) -> Data<'a> {
        match *self {
            Data::Scalar(a) => Data::Scalar(&a[rows]),
            Data::Vector(a) => Data::Vector(&a[rows]),
            Data::Tensor(a) => Data::Tensor(&a[rows]),
            Data::Int(a) => Data::Int(&a[rows]),
            Data::UInt16(a) => Data::UInt16(&a[rows]),
            Data::UInt64(a) => Data::UInt64(&a[rows]),
        }
    }

    /// (VTK type name, components, bytes per component).
    fn layout(&self) -> (&'static str, usize, usize) {
        match self {
            Data::Scalar(_) => ("Float64", 1, 8),
            Data::Vector(_) => ("Float64", 3, 8),
            Data::Tensor(_) => ("Float64", 9, 8),
            Data::Int(_) => ("Int32", 1, 4),
            Data::UInt16(_) => ("UInt16", 1, 2),
            Data::UInt64(_) => ("UInt64", 1, 8),
        }
    }

    fn write_values(&self, w: &mut impl Write) -> io::Result<()> {
        match self {
            Data::Scalar(a) => a.iter().try_for_each(|v| w.write_all(&v.to_le_bytes())),
            Data::Vector(a) => a
                .iter()
                .flatten()
                .try_for_each(|v| w.write_all(&v.to_le_bytes())),
            Data::Tensor(a) => a
                .iter()
                .flatten()
                .try_for_each(|v| w.write_all(&v.to_le_bytes())),
            Data::Int(a) => a.iter().try_for_each(|v| w.write_all(&v.to_le_bytes())),
            Data::UInt16(a) => a.iter().try_for_each(|v| w.write_all(&v.to_le_bytes())),
            Data::UInt64(a) => a.iter().try_for_each(|v| w.write_all(&v.to_le_bytes())),
        }
    }
}

impl<'a> VtuWriter<'a> {
    /// A writer for `n_points` particles.
    pub fn new(n_points: usize) -> Self {
        Self {
            n_points,
            points: None,
            arrays: Vec::new(),
            problem: None,
        }
    }

    /// Particle positions (m).
    pub fn points(&mut self, points: &'a [[f64; 3]]) -> &mut Self {
        self.check_len("points", points.len());
        self.points = Some(points);
        self
    }

    /// A scalar point-data array (Float64), e.g. density (kg/m³).
    pub fn scalar(&mut self, name: &str, values: &'a [f64]) -> &mut Self {
        self.add(name, Data::Scalar(values))
    }

    /// A 3-component point-data array (Float64), e.g. velocity (m/s).
    pub fn vector(&mut self, name: &str, values: &'a [[f64; 3]]) -> &mut Self {
        self.add(name, Data::Vector(values))
    }

    /// A 9-component point-data array (Float64, row-major 3×3), e.g. stress (Pa);
    /// ParaView shows 9 components as a tensor.
    pub fn tensor(&mut self, name: &str, values: &'a [[f64; 9]]) -> &mut Self {
        self.add(name, Data::Tensor(values))
    }

    /// An integer point-data array (Int32), e.g. a fragment label.
    pub fn int(&mut self, name: &str, values: &'a [i32]) -> &mut Self {
        self.add(name, Data::Int(values))
    }

    /// A 16-bit unsigned point-data array (UInt16), e.g. the body id.
    pub fn uint16(&mut self, name: &str, values: &'a [u16]) -> &mut Self {
        self.add(name, Data::UInt16(values))
    }

    /// A 64-bit unsigned point-data array (UInt64), e.g. the particles' stable ids.
    pub fn uint64(&mut self, name: &str, values: &'a [u64]) -> &mut Self {
        self.add(name, Data::UInt64(values))
    }

    /// The same arrays restricted to the points `rows` (a piece of a parallel file,
    /// [`crate::pvtu`]): each piece is a complete `.vtu` of its own points, and the
    /// pieces of consecutive ranges hold, in order, the values of the whole. A range
    /// outside the points is reported by [`write`](VtuWriter::write).
    pub fn piece(&self, rows: Range<usize>) -> VtuWriter<'a> {
        let mut p = VtuWriter::new(rows.len());
        p.problem = self.problem.clone();
        if rows.start > rows.end || rows.end > self.n_points {
            p.note(format!(
                "piece {}..{} lies outside the {} points",
                rows.start, rows.end, self.n_points
            ));
            return p;
        }
        p.points = self.points.map(|x| &x[rows.clone()]);
        p.arrays = self
            .arrays
            .iter()
            .map(|(name, data)| (name.clone(), data.slice(rows.clone())))
            .collect();
        p
    }

    /// The point-data arrays as (name, VTK type, components), in the order added.
    pub(crate) fn declarations(&self) -> impl Iterator<Item = (&str, &'static str, usize)> {
        self.arrays.iter().map(|(name, data)| {
            let (ty, components, _) = data.layout();
            (name.as_str(), ty, components)
        })
    }

    /// Writes the file at `path` (created or truncated).
    pub fn write(&self, path: impl AsRef<Path>) -> io::Result<()> {
        self.ready()?;
        let mut w = BufWriter::new(File::create(path)?);
        self.write_to(&mut w)?;
        w.flush()
    }

    /// Writes the XML document to `w`.
    pub fn write_to<W: Write>(&self, w: &mut W) -> io::Result<()> {
        let points = self.ready()?;
        let n = self.n_points;
        open_file(w, "UnstructuredGrid")?;
        writeln!(w, "  <UnstructuredGrid>")?;
        writeln!(
            w,
            "    <Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{n}\">"
        )?;
        writeln!(w, "      <PointData>")?;
        for (name, data) in &self.arrays {
            data_array(w, name, *data)?;
        }
        writeln!(w, "      </PointData>")?;
        writeln!(w, "      <Points>")?;
        data_array(w, "Points", Data::Vector(points))?;
        writeln!(w, "      </Points>")?;
        writeln!(w, "      <Cells>")?;
        // Cell k is the vertex of point k: connectivity k, offset k + 1, type VERTEX.
        raw_array(w, "connectivity", "Int64", 1, 8 * n, |s| {
            (0..n as i64).try_for_each(|k| s.write_all(&k.to_le_bytes()))
        })?;
        raw_array(w, "offsets", "Int64", 1, 8 * n, |s| {
            (1..=n as i64).try_for_each(|k| s.write_all(&k.to_le_bytes()))
        })?;
        raw_array(w, "types", "UInt8", 1, n, |s| {
            (0..n).try_for_each(|_| s.write_all(&[VTK_VERTEX]))
        })?;
        writeln!(w, "      </Cells>")?;
        writeln!(w, "    </Piece>")?;
        writeln!(w, "  </UnstructuredGrid>")?;
        writeln!(w, "</VTKFile>")
    }

    fn add(&mut self, name: &str, data: Data<'a>) -> &mut Self {
        if name.is_empty() {
            self.note("a point-data array has an empty name".to_string());
        } else if self.arrays.iter().any(|(n, _)| n == name) {
            self.note(format!("point-data array \"{name}\" is given twice"));
        }
        self.check_len(name, data.len());
        self.arrays.push((name.to_string(), data));
        self
    }

    fn check_len(&mut self, name: &str, len: usize) {
        if len != self.n_points {
            let n = self.n_points;
            self.note(format!("\"{name}\" has {len} entries for {n} points"));
        }
    }

    /// Keeps the first mistake: later ones are often its consequences.
    fn note(&mut self, problem: String) {
        self.problem.get_or_insert(problem);
    }

    pub(crate) fn ready(&self) -> io::Result<&'a [[f64; 3]]> {
        if let Some(p) = &self.problem {
            return Err(io::Error::new(io::ErrorKind::InvalidInput, p.clone()));
        }
        self.points.ok_or_else(|| {
            io::Error::new(
                io::ErrorKind::InvalidInput,
                "no points given to the VTU writer",
            )
        })
    }
}

/// The XML declaration and the opening `VTKFile` tag of a file of type `kind` (its
/// version 1.0, with UInt64 byte counts: see the module's documentation).
pub(crate) fn open_file<W: Write>(w: &mut W, kind: &str) -> io::Result<()> {
    writeln!(w, "<?xml version=\"1.0\"?>")?;
    writeln!(
        w,
        "<VTKFile type=\"{kind}\" version=\"1.0\" byte_order=\"LittleEndian\" \
         header_type=\"UInt64\">"
    )
}

fn data_array<W: Write>(w: &mut W, name: &str, data: Data) -> io::Result<()> {
    let (ty, components, size) = data.layout();
    raw_array(
        w,
        name,
        ty,
        components,
        data.len() * components * size,
        |s| data.write_values(s),
    )
}

/// One `DataArray` element: base64 of the UInt64 byte count followed by the values.
fn raw_array<W: Write>(
    w: &mut W,
    name: &str,
    ty: &str,
    components: usize,
    bytes: usize,
    values: impl FnOnce(&mut EncoderWriter<'_, GeneralPurpose, &mut W>) -> io::Result<()>,
) -> io::Result<()> {
    write!(
        w,
        "        <DataArray type=\"{ty}\" Name=\"{}\" NumberOfComponents=\"{components}\" \
         format=\"binary\">\n          ",
        escape_attribute(name)
    )?;
    {
        let mut s = EncoderWriter::new(&mut *w, &STANDARD);
        s.write_all(&(bytes as u64).to_le_bytes())?;
        values(&mut s)?;
        s.finish()?;
    }
    writeln!(w, "\n        </DataArray>")
}

//! PNG output through the pure-Rust `png` crate: 8-bit RGB, no interlacing.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use super::canvas::Canvas;
use super::error::PlotError;

impl Canvas {
    /// Encodes the canvas as PNG into `w`.
    pub fn write_png<W: Write>(&self, w: W) -> Result<(), PlotError> {
        let mut enc = png::Encoder::new(w, self.width(), self.height());
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        // Plots are mostly flat colour: fast deflate already compresses them well.
        enc.set_compression(png::Compression::Fast);
        let mut writer = enc.write_header()?;
        writer.write_image_data(self.data())?;
        writer.finish()?;
        Ok(())
    }

    /// The PNG file contents.
    pub fn to_png(&self) -> Result<Vec<u8>, PlotError> {
        let mut out = Vec::new();
        self.write_png(&mut out)?;
        Ok(out)
    }

    /// Writes the canvas to a PNG file at `path`, replacing any file there.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), PlotError> {
        let path = path.as_ref();
        let io_err = |source| PlotError::Io {
            path: path.to_path_buf(),
            source,
        };
        let file = File::create(path).map_err(io_err)?;
        let mut buf = BufWriter::new(file);
        // A failed write surfaces inside the encoder's error; report it as I/O on `path`.
        self.write_png(&mut buf).map_err(|e| match e {
            PlotError::Png(png::EncodingError::IoError(source)) => io_err(source),
            e => e,
        })?;
        buf.flush().map_err(io_err)?;
        Ok(())
    }
}

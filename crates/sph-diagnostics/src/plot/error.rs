//! Typed errors of the plotting module.

use std::path::PathBuf;
use thiserror::Error;

/// Why a plot could not be built, rendered or written.
#[derive(Debug, Error)]
pub enum PlotError {
    /// Writing the image file failed.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file being written.
        path: PathBuf,
        /// The underlying I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The PNG encoder rejected the image or failed while writing it.
    #[error("PNG encoding failed: {0}")]
    Png(#[from] png::EncodingError),
    /// Two arrays of one series differ in length.
    #[error("series {series}: {what} has {len} values, expected {expected}")]
    LengthMismatch {
        /// The series label, or `#n` for the n-th unlabelled series of its panel.
        series: String,
        /// Which array is wrong ("y", "values", "edges").
        what: &'static str,
        /// Its length.
        len: usize,
        /// The length it must have.
        expected: usize,
    },
    /// A series has no point that can be drawn (empty, or every point non-finite).
    #[error("series {series}: none of its {total} points is finite")]
    NoFinitePoints {
        /// The series label, or `#n`.
        series: String,
        /// How many points it has.
        total: usize,
    },
    /// A style or plot parameter is outside its range.
    #[error("{what} = {value}: {reason}")]
    BadParameter {
        /// The parameter name.
        what: &'static str,
        /// Its value.
        value: f64,
        /// Why it is rejected.
        reason: &'static str,
    },
    /// Axis limits are unusable (not finite, not increasing, or not positive on a log axis).
    #[error("{axis} limits [{lo}, {hi}]: {reason}")]
    BadLimits {
        /// "x", "y" or "colour".
        axis: &'static str,
        /// Lower limit.
        lo: f64,
        /// Upper limit.
        hi: f64,
        /// Why they are rejected.
        reason: &'static str,
    },
    /// A log axis has no positive value to show.
    #[error("panel ({row}, {col}): {axis} axis is logarithmic but no plotted value is > 0")]
    NoPositiveData {
        /// Panel row.
        row: usize,
        /// Panel column.
        col: usize,
        /// "x" or "y".
        axis: &'static str,
    },
    /// The image size is zero or too large.
    #[error("image size {width}×{height} px: each side must be in 1..={max}")]
    BadSize {
        /// Requested width.
        width: u32,
        /// Requested height.
        height: u32,
        /// Largest accepted side.
        max: u32,
    },
    /// A panel position outside its grid.
    #[error("panel ({row}, {col}) lies outside a {rows}×{cols} grid")]
    BadPanel {
        /// Requested row.
        row: usize,
        /// Requested column.
        col: usize,
        /// Grid rows.
        rows: usize,
        /// Grid columns.
        cols: usize,
    },
    /// A panel is too small for its labels and ticks.
    #[error("panel ({row}, {col}) is too small: {width}×{height} px left for the plot area")]
    PanelTooSmall {
        /// Panel row.
        row: usize,
        /// Panel column.
        col: usize,
        /// Plot-area width left after the margins (may be ≤ 0).
        width: i64,
        /// Plot-area height left after the margins (may be ≤ 0).
        height: i64,
    },
}

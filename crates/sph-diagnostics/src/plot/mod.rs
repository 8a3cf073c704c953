//! PNG plots with no system fonts and no native libraries: verification profiles
//! (particles against an exact curve), time histories, histograms and colour-mapped
//! cross-sections, on one or several panels.
//!
//! Everything is drawn by this module on an RGB [`Canvas`] (thick anti-aliased lines,
//! markers, rectangles, text from a built-in 5×9 bitmap font) and encoded by the pure-Rust
//! `png` crate, so images are identical on every machine.
//!
//! ```
//! use sph_diagnostics::plot::{BLACK, BLUE, Figure, Style};
//!
//! let x: Vec<f64> = (0..200).map(|i| i as f64 / 199.0).collect();
//! let exact: Vec<f64> = x.iter().map(|&x| if x < 0.5 { 1.0 } else { 0.125 }).collect();
//! let mut particles = exact.clone();
//! particles[7] = f64::NAN; // a bad particle: skipped and counted, not hidden
//!
//! let mut fig = Figure::new(800, 600);
//! fig.title("Sod, t = 0.2");
//! let ax = fig.panel(0, 0, 1, 1)?;
//! ax.xlabel("x (m)").ylabel("ρ (kg/m³)");
//! let added = ax.scatter(&x, &particles, Style::points(BLUE).label("SPH"))?;
//! assert_eq!(added.non_finite, 1);
//! ax.line(&x, &exact, Style::line(BLACK).label("exact"))?;
//!
//! let (canvas, report) = fig.render()?; // or fig.save_png("sod.png")?
//! assert_eq!(report.skipped(), 1);
//! assert!(canvas.to_png()?.starts_with(b"\x89PNG"));
//! # Ok::<(), sph_diagnostics::plot::PlotError>(())
//! ```

mod axes;
mod canvas;
mod color;
mod colorbar;
mod draw_series;
mod error;
mod figure;
pub mod font;
mod histogram;
mod legend;
mod limits;
mod marker;
mod png_out;
mod raster;
mod render;
mod report;
mod scale;
mod series;
mod style;
mod text;
pub mod ticks;

pub use axes::{Axes, LegendPos};
pub use canvas::{Canvas, MAX_SIDE, Rect};
pub use color::{
    BLACK, BLUE, BROWN, Colormap, GREEN, GREY, LIGHT_GREY, ORANGE, PALETTE, PURPLE, RED, Rgb, WHITE,
};
pub use error::PlotError;
pub use figure::{Figure, MAX_TEXT_SCALE};
pub use histogram::{Binned, bin};
pub use raster::{MIN_DASH, Stroke};
pub use report::{PanelReport, RenderReport, SeriesReport};
pub use scale::Scale;
pub use series::{ColorScale, PointCount};
pub use style::{Marker, Style};
pub use text::{HAlign, TextStyle, VAlign};
pub use ticks::{Tick, TickSet};

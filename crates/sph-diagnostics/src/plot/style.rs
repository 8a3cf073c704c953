//! How a series is drawn: colour, line width and dashes, marker shape and size, opacity,
//! legend label.

use super::color::{BLACK, Rgb};
use super::error::PlotError;
use super::raster::MIN_DASH;

/// Marker shapes for scatter series and legend entries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Marker {
    /// Filled disc (the default).
    #[default]
    Circle,
    /// Ring: a disc outline, for points drawn over a curve that must stay visible.
    OpenCircle,
    /// Filled square.
    Square,
    /// Filled diamond.
    Diamond,
    /// Filled triangle, apex up.
    Triangle,
    /// Plus sign.
    Plus,
    /// Diagonal cross.
    Cross,
}

/// Drawing style of one series. Build with [`Style::points`], [`Style::line`] or
/// [`Style::bars`] and refine with the chained setters.
#[derive(Clone, Debug, PartialEq)]
pub struct Style {
    /// Ink colour (line, marker or bar fill).
    pub color: Rgb,
    /// Line width in pixels (lines; bar outlines use 1 px).
    pub width: f64,
    /// Dash pattern: lengths of drawn and blank parts in pixels; `None` for solid.
    pub dash: Option<(f64, f64)>,
    /// Marker shape (scatter series, and the legend sample of one).
    pub marker: Marker,
    /// Marker diameter in pixels.
    pub size: f64,
    /// Opacity in [0, 1].
    pub alpha: f64,
    /// Legend label; series without one are left out of the legend.
    pub label: Option<String>,
}

impl Style {
    /// Small filled discs, 3 px across: particles.
    pub fn points(color: Rgb) -> Self {
        Self {
            color,
            width: 1.5,
            dash: None,
            marker: Marker::Circle,
            size: 3.0,
            alpha: 1.0,
            label: None,
        }
    }

    /// A solid line 1.5 px wide: exact solutions, time histories.
    pub fn line(color: Rgb) -> Self {
        Self {
            width: 1.5,
            ..Self::points(color)
        }
    }

    /// Filled bars with an outline: histograms.
    pub fn bars(color: Rgb) -> Self {
        Self {
            alpha: 0.8,
            ..Self::points(color)
        }
    }

    /// Sets the legend label.
    pub fn label(mut self, label: impl Into<String>) -> Self {
        self.label = Some(label.into());
        self
    }

    /// Sets the line width in pixels.
    pub fn width(mut self, width: f64) -> Self {
        self.width = width;
        self
    }

    /// Dashes of `on` pixels separated by gaps of `off` pixels.
    pub fn dashed(mut self, on: f64, off: f64) -> Self {
        self.dash = Some((on, off));
        self
    }

    /// Sets the marker shape.
    pub fn marker(mut self, marker: Marker) -> Self {
        self.marker = marker;
        self
    }

    /// Sets the marker diameter in pixels.
    pub fn size(mut self, size: f64) -> Self {
        self.size = size;
        self
    }

    /// Sets the opacity, 0 (invisible) to 1 (opaque).
    pub fn alpha(mut self, alpha: f64) -> Self {
        self.alpha = alpha;
        self
    }

    /// Checks every numeric field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), PlotError> {
        let bad = |what, value, reason| {
            Err(PlotError::BadParameter {
                what,
                value,
                reason,
            })
        };
        if !(self.width > 0.0 && self.width <= 100.0) {
            return bad("width", self.width, "line width must be in (0, 100] px");
        }
        if !(self.size > 0.0 && self.size <= 100.0) {
            return bad("size", self.size, "marker size must be in (0, 100] px");
        }
        if !(0.0..=1.0).contains(&self.alpha) {
            return bad("alpha", self.alpha, "opacity must be in [0, 1]");
        }
        if let Some((on, off)) = self.dash {
            if !(on >= MIN_DASH && on.is_finite()) {
                return bad("dash on", on, "dash length must be finite and >= 0.5 px");
            }
            if !(off >= MIN_DASH && off.is_finite()) {
                return bad("dash off", off, "gap length must be finite and >= 0.5 px");
            }
        }
        Ok(())
    }
}

impl Default for Style {
    fn default() -> Self {
        Self::line(BLACK)
    }
}

//! The data of one plotted series, validated and copied when it is added to an
//! [`Axes`](super::Axes).

use super::color::Colormap;
use super::error::PlotError;
use super::style::Style;

/// Points of a series as added: how many there were and how many had a non-finite
/// coordinate (or value) and will not be drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct PointCount {
    /// Points given.
    pub total: usize,
    /// Points with a NaN or infinite coordinate or value: skipped, not drawn.
    pub non_finite: usize,
}

/// How values of a colour-mapped series become colours, and the colour bar's label.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorScale {
    /// The colour map.
    pub map: Colormap,
    /// Value range mapped onto the whole map; `None` takes the finite values' range.
    /// Values outside an explicit range take the end colours and are counted in
    /// [`SeriesReport::outside_color_range`](super::SeriesReport::outside_color_range).
    pub range: Option<(f64, f64)>,
    /// Label of the colour bar.
    pub label: String,
}

impl ColorScale {
    /// `map` over the data's own range, unlabelled.
    pub fn new(map: Colormap) -> Self {
        Self {
            map,
            range: None,
            label: String::new(),
        }
    }

    /// Fixes the value range, e.g. (0, 1) for damage.
    pub fn range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }

    /// Sets the colour-bar label.
    pub fn label(mut self, label: impl Into<String>) -> Self {
        self.label = label.into();
        self
    }

    /// Checks an explicit range: finite and increasing.
    pub fn validate(&self) -> Result<(), PlotError> {
        match self.range {
            Some((lo, hi)) if !(lo.is_finite() && hi.is_finite() && hi > lo) => {
                Err(PlotError::BadLimits {
                    axis: "colour",
                    lo,
                    hi,
                    reason: "must be finite with lo < hi",
                })
            }
            _ => Ok(()),
        }
    }
}

/// What a series draws.
#[derive(Clone, Debug)]
pub(crate) enum Kind {
    /// Connected points.
    Line,
    /// Markers.
    Scatter,
    /// Markers coloured by a value.
    ColorScatter { values: Vec<f64>, scale: ColorScale },
    /// Bars over [edges[i], edges[i+1]] of height y[i]; `x` holds the edges.
    Bars,
    /// A horizontal line at y[0] across the plot.
    HLine,
    /// A vertical line at x[0] across the plot.
    VLine,
}

/// One series as stored by its axes.
#[derive(Clone, Debug)]
pub(crate) struct Series {
    pub kind: Kind,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub style: Style,
    pub count: PointCount,
}

impl Series {
    /// The name used in error messages: the label, or `#index`.
    pub fn name(style: &Style, index: usize) -> String {
        style
            .label
            .clone()
            .unwrap_or_else(|| format!("#{index} (unlabelled)"))
    }

    /// Whether bar `i` (or point `i`) has finite data.
    pub fn finite_at(&self, i: usize) -> bool {
        match &self.kind {
            Kind::Bars => {
                self.x[i].is_finite() && self.x[i + 1].is_finite() && self.y[i].is_finite()
            }
            Kind::ColorScatter { values, .. } => {
                self.x[i].is_finite() && self.y[i].is_finite() && values[i].is_finite()
            }
            Kind::HLine => self.y[0].is_finite(),
            Kind::VLine => self.x[0].is_finite(),
            Kind::Line | Kind::Scatter => self.x[i].is_finite() && self.y[i].is_finite(),
        }
    }

    /// Number of points (bars count once each).
    pub fn len(&self) -> usize {
        match self.kind {
            Kind::HLine | Kind::VLine => 1,
            _ => self.y.len(),
        }
    }
}

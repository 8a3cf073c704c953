//! One panel of a figure: its series, scales, limits and labels.

use super::error::PlotError;
use super::histogram::{Binned, bin};
use super::scale::Scale;
use super::series::{ColorScale, Kind, PointCount, Series};
use super::style::Style;
use super::ticks::Tick;

/// Where the legend goes inside the plot area.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum LegendPos {
    /// The place covering the fewest data points among the corners and the edge
    /// centres (ties: upper right, upper left, lower right, lower left, top, bottom,
    /// right, left).
    #[default]
    Best,
    /// Upper right corner.
    UpperRight,
    /// Upper left corner.
    UpperLeft,
    /// Lower right corner.
    LowerRight,
    /// Lower left corner.
    LowerLeft,
    /// No legend.
    Off,
}

/// A panel: series plus how to show them. Obtained from
/// [`Figure::panel`](super::Figure::panel); setters chain.
#[derive(Clone, Debug, Default)]
pub struct Axes {
    pub(crate) title: String,
    pub(crate) xlabel: String,
    pub(crate) ylabel: String,
    pub(crate) xscale: Scale,
    pub(crate) yscale: Scale,
    pub(crate) xlim: Option<(f64, f64)>,
    pub(crate) ylim: Option<(f64, f64)>,
    pub(crate) no_grid: bool,
    pub(crate) legend: LegendPos,
    pub(crate) equal_aspect: bool,
    /// Ticks placed by the caller on x (`xticks`), instead of the nice steps.
    pub(crate) xticks: Option<Vec<Tick>>,
    pub(crate) series: Vec<Series>,
}

/// Checks user limits: finite and increasing.
fn check_limits(axis: &'static str, lo: f64, hi: f64) -> Result<(), PlotError> {
    if lo.is_finite() && hi.is_finite() && hi > lo {
        Ok(())
    } else {
        Err(PlotError::BadLimits {
            axis,
            lo,
            hi,
            reason: "must be finite with lo < hi",
        })
    }
}

impl Axes {
    /// Sets the title, drawn above the plot area.
    pub fn title(&mut self, title: impl Into<String>) -> &mut Self {
        self.title = title.into();
        self
    }

    /// Sets the x-axis label (quantity and unit, e.g. "x (m)").
    pub fn xlabel(&mut self, label: impl Into<String>) -> &mut Self {
        self.xlabel = label.into();
        self
    }

    /// Sets the y-axis label.
    pub fn ylabel(&mut self, label: impl Into<String>) -> &mut Self {
        self.ylabel = label.into();
        self
    }

    /// Sets the x scale.
    pub fn xscale(&mut self, scale: Scale) -> &mut Self {
        self.xscale = scale;
        self
    }

    /// Sets the y scale.
    pub fn yscale(&mut self, scale: Scale) -> &mut Self {
        self.yscale = scale;
        self
    }

    /// Fixes the x range instead of fitting it to the data. On a log axis both limits
    /// must also be > 0 (checked when rendering, since the scale may change later).
    pub fn xlim(&mut self, lo: f64, hi: f64) -> Result<&mut Self, PlotError> {
        check_limits("x", lo, hi)?;
        self.xlim = Some((lo, hi));
        Ok(self)
    }

    /// Fixes the y range instead of fitting it to the data.
    pub fn ylim(&mut self, lo: f64, hi: f64) -> Result<&mut Self, PlotError> {
        check_limits("y", lo, hi)?;
        self.ylim = Some((lo, hi));
        Ok(self)
    }

    /// Places the x ticks at `ticks` (value, label), instead of at nice steps: for an
    /// axis of categories, such as the points of a study drawn as bars at 0, 1, 2, …
    /// The values must be finite and increasing; those outside the axis range are not
    /// drawn, and where the labels would overlap every second one is dropped, then every
    /// fourth, as often as needed.
    pub fn xticks(&mut self, ticks: &[(f64, String)]) -> Result<&mut Self, PlotError> {
        if let Some(&(v, _)) = ticks.iter().find(|(v, _)| !v.is_finite()) {
            return Err(PlotError::BadParameter {
                what: "x tick",
                value: v,
                reason: "must be finite",
            });
        }
        if let Some(w) = ticks.windows(2).find(|w| !(w[1].0 > w[0].0)) {
            return Err(PlotError::BadParameter {
                what: "x tick",
                value: w[1].0,
                reason: "must be greater than the tick before it",
            });
        }
        self.xticks = Some(
            ticks
                .iter()
                .map(|(value, label)| Tick {
                    value: *value,
                    label: label.clone(),
                })
                .collect(),
        );
        Ok(self)
    }

    /// Shows (default) or hides grid lines at the major ticks.
    pub fn grid(&mut self, on: bool) -> &mut Self {
        self.no_grid = !on;
        self
    }

    /// Places the legend (default [`LegendPos::Best`]; it lists labelled series only).
    pub fn legend(&mut self, pos: LegendPos) -> &mut Self {
        self.legend = pos;
        self
    }

    /// One data unit spans as many pixels on x as on y (cross-sections of a crater):
    /// the range of one axis is widened about its centre. Needs two linear axes.
    pub fn equal_aspect(&mut self, on: bool) -> &mut Self {
        self.equal_aspect = on;
        self
    }

    /// Adds a series after validating style and lengths.
    fn push(
        &mut self,
        kind: Kind,
        x: &[f64],
        y: &[f64],
        style: Style,
    ) -> Result<PointCount, PlotError> {
        style.validate()?;
        let name = Series::name(&style, self.series.len());
        let mut s = Series {
            kind,
            x: x.to_vec(),
            y: y.to_vec(),
            style,
            count: PointCount::default(),
        };
        let n = s.len();
        let non_finite = (0..n).filter(|&i| !s.finite_at(i)).count();
        if n == non_finite {
            return Err(PlotError::NoFinitePoints {
                series: name,
                total: n,
            });
        }
        s.count = PointCount {
            total: n,
            non_finite,
        };
        let count = s.count;
        self.series.push(s);
        Ok(count)
    }

    /// Checks that `other` has as many values as x.
    fn same_len(
        &self,
        style: &Style,
        what: &'static str,
        len: usize,
        expected: usize,
    ) -> Result<(), PlotError> {
        if len == expected {
            Ok(())
        } else {
            Err(PlotError::LengthMismatch {
                series: Series::name(style, self.series.len()),
                what,
                len,
                expected,
            })
        }
    }

    /// A line through (`x[i]`, `y[i]`) in order: an exact solution, a time history.
    /// Non-finite points break the line and are counted.
    pub fn line(&mut self, x: &[f64], y: &[f64], style: Style) -> Result<PointCount, PlotError> {
        self.same_len(&style, "y", y.len(), x.len())?;
        self.push(Kind::Line, x, y, style)
    }

    /// Markers at (`x[i]`, `y[i]`): particles. Non-finite points are skipped and counted.
    pub fn scatter(&mut self, x: &[f64], y: &[f64], style: Style) -> Result<PointCount, PlotError> {
        self.same_len(&style, "y", y.len(), x.len())?;
        self.push(Kind::Scatter, x, y, style)
    }

    /// Markers at (`x[i]`, `y[i]`) coloured by `values[i]` through `scale`, with a colour bar
    /// beside the plot (the bar shows the first colour-mapped series of the panel).
    /// The style's colour is used only for the legend sample's outline.
    pub fn scatter_colored(
        &mut self,
        x: &[f64],
        y: &[f64],
        values: &[f64],
        scale: ColorScale,
        style: Style,
    ) -> Result<PointCount, PlotError> {
        self.same_len(&style, "y", y.len(), x.len())?;
        self.same_len(&style, "values", values.len(), x.len())?;
        scale.validate()?;
        let kind = Kind::ColorScatter {
            values: values.to_vec(),
            scale,
        };
        self.push(kind, x, y, style)
    }

    /// Bars: bar i spans [`edges[i]`, `edges[i+1]`] and rises from 0 (linear y) or from the
    /// bottom of the plot (log y) to `heights[i]`.
    pub fn bars(
        &mut self,
        edges: &[f64],
        heights: &[f64],
        style: Style,
    ) -> Result<PointCount, PlotError> {
        self.same_len(&style, "edges", edges.len(), heights.len() + 1)?;
        self.push(Kind::Bars, edges, heights, style)
    }

    /// Histogram of `data` in `bins` equal bins (see [`bin`]): bars of the number of
    /// values per bin. Returns the bins; non-finite values are counted, not binned.
    pub fn histogram(
        &mut self,
        data: &[f64],
        bins: usize,
        style: Style,
    ) -> Result<Binned, PlotError> {
        let binned = bin(data, bins, &Series::name(&style, self.series.len()))?;
        self.bars(&binned.edges, &binned.counts, style)?;
        Ok(binned)
    }

    /// A horizontal reference line at `y` across the plot (does not widen the x range).
    pub fn hline(&mut self, y: f64, style: Style) -> Result<PointCount, PlotError> {
        self.push(Kind::HLine, &[], &[y], style)
    }

    /// A vertical reference line at `x` across the plot (does not widen the y range).
    pub fn vline(&mut self, x: f64, style: Style) -> Result<PointCount, PlotError> {
        self.push(Kind::VLine, &[x], &[], style)
    }

    /// Number of series added.
    pub fn series_count(&self) -> usize {
        self.series.len()
    }
}

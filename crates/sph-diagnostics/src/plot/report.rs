//! What rendering left out: per series, the points that were not drawn and why.

/// Accounting of one series after rendering.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SeriesReport {
    /// Its legend label, if any.
    pub label: Option<String>,
    /// Points (or bars) given.
    pub total: usize,
    /// Skipped: a coordinate or value was NaN or infinite.
    pub non_finite: usize,
    /// Skipped: finite, but ≤ 0 on a log axis.
    pub outside_log_domain: usize,
    /// Drawable but outside the axis limits, hence clipped (possibly partly visible).
    pub outside_view: usize,
    /// Colour-mapped points whose value lies outside an explicit colour range; drawn in
    /// the end colour of the map.
    pub outside_color_range: usize,
}

impl SeriesReport {
    /// Points not drawn at all: non-finite or outside the log domain.
    pub fn skipped(&self) -> usize {
        self.non_finite + self.outside_log_domain
    }
}

/// Accounting of one panel.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PanelReport {
    /// Grid row.
    pub row: usize,
    /// Grid column.
    pub col: usize,
    /// One entry per series, in the order added.
    pub series: Vec<SeriesReport>,
    /// The labels of the x ticks drawn, left to right.
    pub x_ticks: Vec<String>,
}

/// Accounting of a rendered figure.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RenderReport {
    /// One entry per panel, in the order the panels were created.
    pub panels: Vec<PanelReport>,
}

impl RenderReport {
    /// Points not drawn in the whole figure (non-finite or outside a log domain).
    pub fn skipped(&self) -> usize {
        self.panels
            .iter()
            .flat_map(|p| &p.series)
            .map(SeriesReport::skipped)
            .sum()
    }
}

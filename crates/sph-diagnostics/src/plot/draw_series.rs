//! Drawing the series of a panel inside its plot area, with the accounting of what
//! was not drawn.

use super::canvas::{Canvas, Rect, alpha8};
use super::color::{BLACK, Rgb};
use super::marker::Stamp;
use super::raster::Stroke;
use super::report::SeriesReport;
use super::scale::AxisMap;
use super::series::{ColorScale, Kind, Series};

/// Most pixel positions kept per series for choosing the legend corner.
const MAX_SAMPLES: usize = 20_000;

/// What the series renderer needs of the panel.
pub(crate) struct Frame<'a> {
    pub xm: AxisMap,
    pub ym: AxisMap,
    pub plot: Rect,
    /// Pixel positions of drawn ink, for placing the legend.
    pub samples: &'a mut Vec<[f64; 2]>,
}

/// Colour range of a colour-mapped series: explicit, or the finite values' extent.
pub(crate) fn color_range(values: &[f64], scale: &ColorScale) -> (f64, f64) {
    if let Some(r) = scale.range {
        return r;
    }
    let (lo, hi) = values
        .iter()
        .filter(|v| v.is_finite())
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    if lo > hi {
        (0.0, 1.0)
    } else if lo == hi {
        (lo - 0.5, hi + 0.5)
    } else {
        (lo, hi)
    }
}

/// Keeps every k-th of `pts` so that at most `MAX_SAMPLES` are added.
fn sample(samples: &mut Vec<[f64; 2]>, pts: &[[f64; 2]]) {
    let stride = pts.len().div_ceil(MAX_SAMPLES).max(1);
    samples.extend(pts.iter().step_by(stride).filter(|p| p[0].is_finite()));
}

impl Frame<'_> {
    /// Pixel position of point i, or why it is not drawn.
    fn point(&self, s: &Series, i: usize, rep: &mut SeriesReport) -> Option<[f64; 2]> {
        if !s.finite_at(i) {
            return None; // counted once, when the series was added
        }
        match (self.xm.px(s.x[i]), self.ym.px(s.y[i])) {
            (Some(px), Some(py)) => {
                if !(self.xm.contains(s.x[i]) && self.ym.contains(s.y[i])) {
                    rep.outside_view += 1;
                }
                Some([px, py])
            }
            _ => {
                rep.outside_log_domain += 1;
                None
            }
        }
    }

    /// Draws `s` and reports on it.
    pub fn draw(&mut self, canvas: &mut Canvas, s: &Series) -> SeriesReport {
        let mut rep = SeriesReport {
            label: s.style.label.clone(),
            total: s.count.total,
            non_finite: s.count.non_finite,
            ..SeriesReport::default()
        };
        let st = &s.style;
        let stroke = Stroke {
            width: st.width,
            color: st.color,
            alpha: st.alpha,
            dash: st.dash,
        };
        match &s.kind {
            Kind::Line => {
                let pts: Vec<[f64; 2]> = (0..s.len())
                    .map(|i| self.point(s, i, &mut rep).unwrap_or([f64::NAN; 2]))
                    .collect();
                canvas.polyline(&pts, &stroke);
                // Lines cover the space between their points too.
                let mut dense = Vec::new();
                for w in pts.windows(2) {
                    let n =
                        (((w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])) / 4.0).clamp(1.0, 200.0);
                    for k in 0..n as usize {
                        let t = k as f64 / n;
                        dense.push([
                            w[0][0] + t * (w[1][0] - w[0][0]),
                            w[0][1] + t * (w[1][1] - w[0][1]),
                        ]);
                    }
                }
                sample(self.samples, &dense);
            }
            Kind::Scatter => {
                let pts: Vec<[f64; 2]> = (0..s.len())
                    .filter_map(|i| self.point(s, i, &mut rep))
                    .collect();
                canvas.markers(&pts, st.marker, st.size, st.color, st.alpha);
                sample(self.samples, &pts);
            }
            Kind::ColorScatter { values, scale } => {
                let (lo, hi) = color_range(values, scale);
                let stamp = Stamp::new(st.marker, st.size, canvas.antialias());
                let a = alpha8(st.alpha);
                let mut pts = Vec::with_capacity(s.len());
                for i in 0..s.len() {
                    if let Some(p) = self.point(s, i, &mut rep) {
                        let v = values[i];
                        if v < lo || v > hi {
                            rep.outside_color_range += 1;
                        }
                        canvas.stamp(&stamp, p, scale.map.at((v - lo) / (hi - lo)), a);
                        pts.push(p);
                    }
                }
                sample(self.samples, &pts);
            }
            Kind::Bars => self.bars(canvas, s, &mut rep),
            Kind::HLine | Kind::VLine => {
                let horizontal = matches!(s.kind, Kind::HLine);
                let (v, map) = if horizontal {
                    (s.y[0], &self.ym)
                } else {
                    (s.x[0], &self.xm)
                };
                match map.px(v) {
                    Some(p) => {
                        if !map.contains(v) {
                            rep.outside_view += 1;
                        }
                        let (a, b) = if horizontal {
                            ([self.plot.x0 as f64, p], [self.plot.x1 as f64, p])
                        } else {
                            ([p, self.plot.y0 as f64], [p, self.plot.y1 as f64])
                        };
                        canvas.line(a, b, &stroke);
                        sample(self.samples, &[a, b]);
                    }
                    None if v.is_finite() => rep.outside_log_domain += 1,
                    None => {}
                }
            }
        }
        rep
    }

    /// Samples a filled rectangle for legend placement: its outline every 2 px (any
    /// overlap with a legend box crosses it) and its inside every 8 px (a box wholly
    /// inside a bar). Coordinates are limited to the plot area.
    fn sample_rect(&mut self, xa: f64, xb: f64, ya: f64, yb: f64) {
        let p = &self.plot;
        let (xa, xb) = (xa.max(p.x0 as f64), xb.min(p.x1 as f64));
        let (ya, yb) = (ya.max(p.y0 as f64), yb.min(p.y1 as f64));
        if xa > xb || ya > yb {
            return;
        }
        let grid = |a: f64, b: f64, step: f64| {
            let n = ((b - a) / step).ceil().max(1.0);
            (0..=n as usize).map(move |k| a + (b - a) * k as f64 / n)
        };
        for x in grid(xa, xb, 2.0) {
            self.samples.extend([[x, ya], [x, yb]]);
        }
        for y in grid(ya, yb, 2.0) {
            self.samples.extend([[xa, y], [xb, y]]);
        }
        for x in grid(xa, xb, 8.0) {
            for y in grid(ya, yb, 8.0) {
                self.samples.push([x, y]);
            }
        }
    }

    /// Bars from the baseline (0, or the bottom of a log axis) to each height.
    fn bars(&mut self, canvas: &mut Canvas, s: &Series, rep: &mut SeriesReport) {
        let st = &s.style;
        let base = self.ym.px(0.0).unwrap_or(self.plot.y1 as f64 + 0.5);
        let outline = Rgb::lerp(st.color, BLACK, 0.35);
        for i in 0..s.len() {
            if !s.finite_at(i) {
                continue;
            }
            let (e0, e1, h) = (s.x[i], s.x[i + 1], s.y[i]);
            let (Some(x0), Some(x1), Some(y)) = (self.xm.px(e0), self.xm.px(e1), self.ym.px(h))
            else {
                rep.outside_log_domain += 1;
                continue;
            };
            if !(self.xm.contains(e0) && self.xm.contains(e1) && self.ym.contains(h)) {
                rep.outside_view += 1;
            }
            let r = Rect::new(
                x0.min(x1).round().clamp(-1e9, 1e9) as i64,
                y.min(base).round().clamp(-1e9, 1e9) as i64,
                x0.max(x1).round().clamp(-1e9, 1e9) as i64,
                y.max(base).round().clamp(-1e9, 1e9) as i64,
            );
            if r.is_empty() {
                continue;
            }
            canvas.fill_rect(r, st.color, alpha8(st.alpha));
            canvas.stroke_rect(Rect::new(r.x0, r.y0, r.x1 + 1, r.y1 + 1), 1, outline);
            self.sample_rect(x0.min(x1), x0.max(x1), y.min(base), y.max(base));
        }
    }
}

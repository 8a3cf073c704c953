//! The legend: a framed box in a corner of the plot area listing the labelled series,
//! each with a sample of its line, marker or bar.

use super::axes::LegendPos;
use super::canvas::{Canvas, Rect, alpha8};
use super::color::{BLACK, GREY, WHITE};
use super::font;
use super::marker::Stamp;
use super::raster::Stroke;
use super::series::{Kind, Series};
use super::text::{HAlign, TextStyle, VAlign};

/// Inner padding and distance from the plot frame, pixels.
const PAD: i64 = 8;
/// Length of a line sample, pixels.
const SAMPLE: i64 = 30;

/// Draws the legend of `series` in `plot` at `pos`, placing a `Best` legend in the
/// corner that covers the fewest of `samples` (pixel positions of drawn data).
pub(crate) fn draw(
    canvas: &mut Canvas,
    series: &[Series],
    plot: Rect,
    pos: LegendPos,
    scale: u32,
    samples: &[[f64; 2]],
) {
    let entries: Vec<&Series> = series.iter().filter(|s| s.style.label.is_some()).collect();
    if entries.is_empty() || pos == LegendPos::Off {
        return;
    }
    let s = scale as i64;
    let biggest_marker = entries
        .iter()
        .filter(|e| matches!(e.kind, Kind::Scatter | Kind::ColorScatter { .. }))
        .map(|e| e.style.size.ceil() as i64)
        .max()
        .unwrap_or(0);
    let row_h = (font::text_height(scale) as i64).max(biggest_marker) + 4 * s;
    let text_w = entries
        .iter()
        .map(|e| font::text_width(e.style.label.as_deref().unwrap_or(""), scale) as i64)
        .max()
        .unwrap_or(0);
    let w = PAD + SAMPLE + PAD + text_w + PAD;
    let h = PAD + row_h * entries.len() as i64 + PAD - 4 * s;
    let corners = [
        (LegendPos::UpperRight, plot.x1 - PAD - w, plot.y0 + PAD),
        (LegendPos::UpperLeft, plot.x0 + PAD, plot.y0 + PAD),
        (LegendPos::LowerRight, plot.x1 - PAD - w, plot.y1 - PAD - h),
        (LegendPos::LowerLeft, plot.x0 + PAD, plot.y1 - PAD - h),
    ];
    let (x0, y0) = match corners.iter().find(|c| c.0 == pos) {
        Some(&(_, x, y)) => (x, y),
        None => {
            // Edge centres are tried after the corners.
            let (xc, yc) = ((plot.x0 + plot.x1 - w) / 2, (plot.y0 + plot.y1 - h) / 2);
            let candidates = [
                corners[0],
                corners[1],
                corners[2],
                corners[3],
                (LegendPos::Best, xc, plot.y0 + PAD),
                (LegendPos::Best, xc, plot.y1 - PAD - h),
                (LegendPos::Best, plot.x1 - PAD - w, yc),
                (LegendPos::Best, plot.x0 + PAD, yc),
            ];
            // Best: fewest covered samples; `min_by_key` keeps the first of equals.
            let covered = |x: i64, y: i64| {
                samples
                    .iter()
                    .filter(|p| {
                        p[0] >= x as f64
                            && p[0] < (x + w) as f64
                            && p[1] >= y as f64
                            && p[1] < (y + h) as f64
                    })
                    .count()
            };
            let best = candidates
                .iter()
                .min_by_key(|c| covered(c.1, c.2))
                .unwrap_or(&corners[0]);
            (best.1, best.2)
        }
    };
    let bx = Rect::new(x0, y0, x0 + w, y0 + h);
    canvas.fill_rect(bx, WHITE, alpha8(0.85));
    canvas.stroke_rect(bx, 1, GREY);
    let text = TextStyle::new(scale)
        .anchor(HAlign::Left, VAlign::Middle)
        .color(BLACK);
    for (k, e) in entries.iter().enumerate() {
        // Centre of the capitals of row k (the descender rows hang below).
        let cy = y0 + PAD + k as i64 * row_h + (row_h - 4 * s - 2 * s) / 2;
        let sx = x0 + PAD;
        let st = &e.style;
        let mid = [(sx + SAMPLE / 2) as f64 + 0.5, cy as f64 + 0.5];
        match &e.kind {
            Kind::Line | Kind::HLine | Kind::VLine => {
                let stroke = Stroke {
                    width: st.width,
                    color: st.color,
                    alpha: st.alpha,
                    dash: st.dash,
                };
                canvas.line([sx as f64, mid[1]], [(sx + SAMPLE) as f64, mid[1]], &stroke);
            }
            Kind::Scatter => {
                canvas.markers(&[mid], st.marker, st.size.max(5.0), st.color, st.alpha);
            }
            Kind::ColorScatter { scale: cs, .. } => {
                // Three markers along the sample, low, middle and high colours.
                let stamp = Stamp::new(st.marker, st.size.max(5.0), canvas.antialias());
                for (j, t) in [0.1, 0.5, 0.9].into_iter().enumerate() {
                    let p = [(sx + 5 + 10 * j as i64) as f64 + 0.5, mid[1]];
                    canvas.stamp(&stamp, p, cs.map.at(t), alpha8(st.alpha));
                }
            }
            Kind::Bars => {
                let half = (5 * s).min(row_h / 2 - 1);
                let r = Rect::new(sx + 4, cy - half, sx + SAMPLE - 4, cy + half + 1);
                canvas.fill_rect(r, st.color, alpha8(st.alpha));
                canvas.stroke_rect(r, 1, super::color::Rgb::lerp(st.color, BLACK, 0.35));
            }
        }
        canvas.text(
            sx + SAMPLE + PAD,
            cy,
            st.label.as_deref().unwrap_or(""),
            &text,
        );
    }
}

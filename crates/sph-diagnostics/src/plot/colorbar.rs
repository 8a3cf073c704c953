//! The colour bar of a colour-mapped series: a vertical gradient beside the plot area
//! with ticks, tick labels and the scale's label.

use super::canvas::{Canvas, Rect};
use super::color::BLACK;
use super::font;
use super::series::ColorScale;
use super::text::{HAlign, TextStyle, VAlign};
use super::ticks::TickSet;

/// Gap between plot frame and bar, pixels.
pub(crate) const GAP: i64 = 16;
/// Bar width, pixels.
pub(crate) const BAR: i64 = 16;
/// Tick length, pixels.
const TICK: i64 = 4;

/// The ticks of a bar `h_px` tall over [lo, hi].
pub(crate) fn ticks(lo: f64, hi: f64, h_px: i64, scale: u32) -> TickSet {
    let max = (h_px / (4 * font::text_height(scale) as i64)).clamp(2, 8) as usize;
    TickSet::linear(lo, hi, max)
}

/// Width the bar needs right of the plot frame, labels included.
pub(crate) fn width(ticks: &TickSet, cs: &ColorScale, scale: u32) -> i64 {
    let labels = ticks
        .major
        .iter()
        .map(|t| font::text_width(&t.label, scale) as i64)
        .max()
        .unwrap_or(0);
    let title = if cs.label.is_empty() {
        0
    } else {
        8 + font::text_height(scale) as i64
    };
    GAP + BAR + TICK + 4 + labels + title
}

/// Draws the bar for [lo, hi] beside `plot` (rows of `plot`, starting `GAP` right of it).
pub(crate) fn draw(
    canvas: &mut Canvas,
    plot: Rect,
    cs: &ColorScale,
    (lo, hi): (f64, f64),
    ticks: &TickSet,
    scale: u32,
) {
    let x0 = plot.x1 + GAP;
    let bar = Rect::new(x0, plot.y0, x0 + BAR, plot.y1);
    let h = bar.height().max(1);
    for y in bar.y0..bar.y1 {
        // Bottom row shows lo, top row hi.
        let t = (bar.y1 - 1 - y) as f64 / (h - 1).max(1) as f64;
        canvas.fill_rect(Rect::new(bar.x0, y, bar.x1, y + 1), cs.map.at(t), 255);
    }
    canvas.stroke_rect(
        Rect::new(bar.x0 - 1, bar.y0 - 1, bar.x1 + 1, bar.y1 + 1),
        1,
        BLACK,
    );
    let text = TextStyle::new(scale).anchor(HAlign::Left, VAlign::Middle);
    let mut label_w = 0;
    for t in &ticks.major {
        let f = (t.value - lo) / (hi - lo);
        let y = (bar.y1 as f64 - 0.5 - f * (h - 1) as f64).floor() as i64;
        canvas.fill_rect(
            Rect::new(bar.x1 + 1, y, bar.x1 + 1 + TICK, y + 1),
            BLACK,
            255,
        );
        canvas.text(bar.x1 + 1 + TICK + 4, y, &t.label, &text);
        label_w = label_w.max(font::text_width(&t.label, scale) as i64);
    }
    if !cs.label.is_empty() {
        let x = bar.x1 + 1 + TICK + 4 + label_w + 8;
        let style = TextStyle::new(scale)
            .anchor(HAlign::Center, VAlign::Top)
            .vertical();
        canvas.text(x, (bar.y0 + bar.y1) / 2, &cs.label, &style);
    }
}

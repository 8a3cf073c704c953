//! Rendering one panel: layout of title, labels, ticks and colour bar around the plot
//! area, then grid, series, frame, ticks, text and legend.
//!
//! The vertical layout is fixed by text heights alone; the y ticks follow from the plot
//! height, their label widths fix the left margin, and the x ticks are then thinned
//! until their labels do not touch.

use super::axes::Axes;
use super::canvas::{Canvas, Rect};
use super::color::{BLACK, LIGHT_GREY, Rgb};
use super::colorbar;
use super::draw_series::{Frame, color_range};
use super::error::PlotError;
use super::font;
use super::legend;
use super::limits::{Which, equalise, limits};
use super::report::PanelReport;
use super::scale::{AxisMap, Scale};
use super::series::Kind;
use super::text::{HAlign, TextStyle, VAlign};
use super::ticks::{Tick, TickSet};

/// Outer padding of a panel, pixels.
const PAD: i64 = 10;
/// Major and minor tick lengths, pixels.
const TICK: i64 = 6;
const MINOR: i64 = 3;
/// Gap between a tick and its label, pixels.
const GAP: i64 = 5;
/// Smallest plot area accepted, pixels.
const MIN_PLOT: i64 = 24;
/// Grid lines at minor ticks of log axes.
const MINOR_GRID: Rgb = Rgb::new(242, 242, 242);

/// Ticks of an axis over [lo, hi] with at most `max` labels.
fn tick_set(scale: Scale, (lo, hi): (f64, f64), max: usize) -> TickSet {
    match scale {
        Scale::Linear => TickSet::linear(lo, hi, max),
        Scale::Log => TickSet::log(lo, hi, max),
    }
}

/// Whether consecutive x labels, centred at their ticks, keep `min_gap` pixels apart.
fn x_labels_fit(ticks: &TickSet, map: &AxisMap, scale: u32, min_gap: f64) -> bool {
    ticks.major.windows(2).all(|w| {
        let (Some(a), Some(b)) = (map.px(w[0].value), map.px(w[1].value)) else {
            return true;
        };
        let half = 0.5
            * (font::text_width(&w[0].label, scale) + font::text_width(&w[1].label, scale)) as f64;
        (b - a).abs() >= half + min_gap
    })
}

/// The caller's ticks (`Axes::xticks`) within [lo, hi], every 2^k-th one kept for the
/// smallest k whose labels keep `min_gap` pixels apart (the first tick always kept).
fn placed_ticks(
    ticks: &[Tick],
    (lo, hi): (f64, f64),
    map: &AxisMap,
    scale: u32,
    min_gap: f64,
) -> TickSet {
    let inside: Vec<Tick> = ticks
        .iter()
        .filter(|t| t.value >= lo && t.value <= hi)
        .cloned()
        .collect();
    let mut stride = 1;
    loop {
        let set = TickSet {
            major: inside.iter().step_by(stride).cloned().collect(),
            minor: Vec::new(),
        };
        if set.major.len() <= 1 || x_labels_fit(&set, map, scale, min_gap) {
            return set;
        }
        stride *= 2;
    }
}

/// `text` as drawn within `max` pixels at `scale`: whole where it fits, else its first
/// and last characters about an ellipsis in the middle (the end of a dotted metric name,
/// `…incipient_melting`, is as telling as its start).
pub(crate) fn fitted(text: &str, max: i64, scale: u32) -> std::borrow::Cow<'_, str> {
    if font::text_width(text, scale) as i64 <= max {
        return text.into();
    }
    let chars: Vec<char> = text.chars().collect();
    let room = ((max.max(0) as u32 / scale + 1) / font::ADVANCE) as usize;
    if room <= 1 {
        return "…".into();
    }
    let kept = room - 1;
    let head = kept / 2;
    let tail = kept - head;
    let mut out: String = chars[..head].iter().collect();
    out.push('…');
    out.extend(&chars[chars.len() - tail..]);
    out.into()
}

/// Draws `ax` inside `area` of `canvas` with text at integer `scale`.
pub(crate) fn panel(
    canvas: &mut Canvas,
    ax: &Axes,
    area: Rect,
    scale: u32,
    (row, col): (usize, usize),
) -> Result<PanelReport, PlotError> {
    let s = scale as i64;
    let lh = font::text_height(scale) as i64;
    let cap = font::CAP_HEIGHT as i64 * s;
    let mut xl = limits(ax, Which::X, row, col)?;
    let mut yl = limits(ax, Which::Y, row, col)?;

    // Vertical layout.
    let title_h = if ax.title.is_empty() { 0 } else { lh + 8 };
    let top = area.y0 + PAD + title_h + cap / 2 + 2;
    let xlabel_h = if ax.xlabel.is_empty() { 0 } else { lh + 6 };
    let bottom = area.y1 - PAD - xlabel_h - lh - GAP - TICK;
    let plot_h = bottom - top;

    // Colour bar of the first colour-mapped series.
    let cbar = ax.series.iter().find_map(|sr| match &sr.kind {
        Kind::ColorScatter { values, scale: cs } => Some((cs, color_range(values, cs))),
        _ => None,
    });
    let cbar_ticks = cbar.map(|(_, (lo, hi))| colorbar::ticks(lo, hi, plot_h, scale));
    let cbar_w = match (cbar, &cbar_ticks) {
        (Some((cs, _)), Some(t)) => colorbar::width(t, cs, scale),
        _ => 0,
    };

    // Horizontal layout: y ticks first (they depend on the height only).
    // Labels at least 2.5 text heights apart.
    let y_max = (2 * plot_h / (5 * lh)).clamp(2, 10) as usize;
    let mut yt = tick_set(ax.yscale, yl, y_max);
    let ylabel_w = if ax.ylabel.is_empty() { 0 } else { lh + 8 };
    let ytick_w = |t: &TickSet| {
        t.major
            .iter()
            .map(|t| font::text_width(&t.label, scale) as i64)
            .max()
            .unwrap_or(0)
    };
    let mut left = area.x0 + PAD + ylabel_w + ytick_w(&yt) + GAP + TICK;
    // Half of a typical last x label may reach past the frame.
    let right_reserve = if cbar_w > 0 {
        cbar_w
    } else {
        3 * font::ADVANCE as i64 * s
    };
    let right = area.x1 - PAD - right_reserve;
    let plot_w = right - left;
    if plot_w < MIN_PLOT || plot_h < MIN_PLOT {
        return Err(PlotError::PanelTooSmall {
            row,
            col,
            width: plot_w,
            height: plot_h,
        });
    }
    if ax.equal_aspect {
        if ax.xscale != Scale::Linear || ax.yscale != Scale::Linear {
            return Err(PlotError::BadParameter {
                what: "equal_aspect",
                value: 1.0,
                reason: "equal aspect needs two linear axes",
            });
        }
        (xl, yl) = equalise(xl, yl, plot_w as f64, plot_h as f64);
        yt = tick_set(ax.yscale, yl, y_max);
        left = area.x0 + PAD + ylabel_w + ytick_w(&yt) + GAP + TICK;
    }
    let plot = Rect::new(left, top, right, bottom);
    // Data limits map onto the centres of the frame lines, which lie just outside the
    // plot area: a tick at a limit coincides with the frame.
    let xm = AxisMap::new(ax.xscale, xl.0, xl.1, left as f64 - 0.5, right as f64 + 0.5);
    let ym = AxisMap::new(ax.yscale, yl.0, yl.1, bottom as f64 + 0.5, top as f64 - 0.5);

    // Start from a tick per 6 characters and thin until the labels keep 2 characters apart.
    let mut x_max = ((plot.width() / (6 * s * font::ADVANCE as i64)) as usize).clamp(2, 12);
    let min_gap = 2.0 * font::ADVANCE as f64 * s as f64;
    let xt = match &ax.xticks {
        Some(ticks) => placed_ticks(ticks, xl, &xm, scale, min_gap),
        None => {
            let mut xt = tick_set(ax.xscale, xl, x_max);
            while x_max > 2 && !x_labels_fit(&xt, &xm, scale, min_gap) {
                x_max -= 1;
                xt = tick_set(ax.xscale, xl, x_max);
            }
            xt
        }
    };

    // Grid.
    if !ax.no_grid {
        let vgrid = |c: &mut Canvas, v: f64, col: Rgb| {
            if let Some(p) = xm.px(v) {
                let x = p.floor() as i64;
                c.fill_rect(Rect::new(x, plot.y0, x + 1, plot.y1), col, 255);
            }
        };
        let hgrid = |c: &mut Canvas, v: f64, col: Rgb| {
            if let Some(p) = ym.px(v) {
                let y = p.floor() as i64;
                c.fill_rect(Rect::new(plot.x0, y, plot.x1, y + 1), col, 255);
            }
        };
        canvas.set_clip(Some(plot));
        xt.minor.iter().for_each(|&v| vgrid(canvas, v, MINOR_GRID));
        yt.minor.iter().for_each(|&v| hgrid(canvas, v, MINOR_GRID));
        xt.major
            .iter()
            .for_each(|t| vgrid(canvas, t.value, LIGHT_GREY));
        yt.major
            .iter()
            .for_each(|t| hgrid(canvas, t.value, LIGHT_GREY));
    }

    // Series, clipped to the plot area.
    canvas.set_clip(Some(plot));
    let mut samples = Vec::new();
    let mut frame = Frame {
        xm,
        ym,
        plot,
        samples: &mut samples,
    };
    let series = ax.series.iter().map(|sr| frame.draw(canvas, sr)).collect();
    legend::draw(canvas, &ax.series, plot, ax.legend, scale, &samples);
    canvas.set_clip(None);

    // Frame and ticks.
    canvas.stroke_rect(
        Rect::new(plot.x0 - 1, plot.y0 - 1, plot.x1 + 1, plot.y1 + 1),
        1,
        BLACK,
    );
    let below = plot.y1 + 1;
    let xlabel_style = TextStyle::new(scale).anchor(HAlign::Center, VAlign::Top);
    for (v, len) in xt
        .minor
        .iter()
        .map(|&v| (v, MINOR))
        .chain(xt.major.iter().map(|t| (t.value, TICK)))
    {
        if let Some(p) = xm.px(v) {
            let x = p.floor() as i64;
            canvas.fill_rect(Rect::new(x, below, x + 1, below + len), BLACK, 255);
        }
    }
    for t in &xt.major {
        if let Some(p) = xm.px(t.value) {
            canvas.text(
                p.floor() as i64,
                below + TICK + GAP,
                &t.label,
                &xlabel_style,
            );
        }
    }
    let ylabel_style = TextStyle::new(scale).anchor(HAlign::Right, VAlign::Middle);
    let leftof = plot.x0 - 1;
    for (v, len) in yt
        .minor
        .iter()
        .map(|&v| (v, MINOR))
        .chain(yt.major.iter().map(|t| (t.value, TICK)))
    {
        if let Some(p) = ym.px(v) {
            let y = p.floor() as i64;
            canvas.fill_rect(Rect::new(leftof - len, y, leftof, y + 1), BLACK, 255);
        }
    }
    for t in &yt.major {
        if let Some(p) = ym.px(t.value) {
            canvas.text(
                leftof - TICK - GAP,
                p.floor() as i64,
                &t.label,
                &ylabel_style,
            );
        }
    }

    // Axis labels and title, each cut in its middle where it is longer than its side of
    // the plot (the title: than the panel about the plot's centre), so that neighbouring
    // panels' text never overlaps.
    let cx = (plot.x0 + plot.x1) / 2;
    if !ax.xlabel.is_empty() {
        let y = below + TICK + GAP + lh + 6;
        let text = fitted(&ax.xlabel, plot.width(), scale);
        canvas.text(cx, y, &text, &xlabel_style);
    }
    if !ax.ylabel.is_empty() {
        let style = TextStyle::new(scale)
            .anchor(HAlign::Center, VAlign::Top)
            .vertical();
        let text = fitted(&ax.ylabel, plot.y1 - plot.y0, scale);
        canvas.text(area.x0 + PAD, (plot.y0 + plot.y1) / 2, &text, &style);
    }
    if !ax.title.is_empty() {
        let style = TextStyle::new(scale).anchor(HAlign::Center, VAlign::Top);
        // Centred on the plot, which sits right of the panel's centre: the room is
        // twice the nearer side's.
        let half = (cx - area.x0).min(area.x1 - cx) - PAD;
        let text = fitted(&ax.title, 2 * half, scale);
        // Drawn twice one pixel apart: a bold title.
        canvas.text(cx, area.y0 + PAD, &text, &style);
        canvas.text(cx + 1, area.y0 + PAD, &text, &style);
    }
    if let (Some((cs, range)), Some(t)) = (cbar, &cbar_ticks) {
        colorbar::draw(canvas, plot, cs, range, t, scale);
    }
    Ok(PanelReport {
        row,
        col,
        series,
        x_ticks: xt.major.iter().map(|t| t.label.clone()).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_longer_than_its_room_is_cut_in_the_middle() {
        let name = "projectile_phase_fractions.incipient_melting";
        // Fits: unchanged.
        assert_eq!(fitted(name, 10_000, 1), name);
        // Too long: within the room, both ends kept about the ellipsis, which the font
        // draws (not as a missing glyph's box).
        for (max, scale) in [(120, 1), (240, 2), (61, 1)] {
            let cut = fitted(name, max, scale);
            assert!(
                font::text_width(&cut, scale) as i64 <= max,
                "{cut} at {max}"
            );
            let (head, tail) = cut.split_once('…').unwrap();
            assert!(name.starts_with(head) && name.ends_with(tail), "{cut}");
            assert!(tail.len() >= head.len() && !head.is_empty(), "{cut}");
        }
        assert_eq!(fitted(name, 3, 1), "…");
        assert!(font::glyph('…').is_some());
    }
}

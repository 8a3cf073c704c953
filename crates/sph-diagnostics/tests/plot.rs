//! Tests of the plotting module: PNG container, ticks, rasterisation, font, data
//! accounting and errors. The demo figures are `#[ignore]`d tests that write PNGs to
//! /tmp for a person to look at: `cargo test -p sph-diagnostics --test plot -- --ignored`.

use proptest::prelude::*;
use sph_diagnostics::exact::{GasState, RiemannSolution};
use sph_diagnostics::plot::ticks::{linear_labels, nice_step};
use sph_diagnostics::plot::{
    BLACK, BLUE, Canvas, ColorScale, Colormap, Figure, LegendPos, Marker, ORANGE, PlotError, RED,
    Rgb, Scale, Stroke, Style, TextStyle, TickSet, WHITE, bin, font,
};
use std::time::Instant;

fn values(t: &TickSet) -> Vec<f64> {
    t.major.iter().map(|t| t.value).collect()
}

fn labels(t: &TickSet) -> Vec<&str> {
    t.major.iter().map(|t| t.label.as_str()).collect()
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| (x - y).abs() <= 1e-12 * y.abs().max(1e-300))
}

/// Deterministic pseudo-random numbers in [0, 1) (no RNG dependency needed here).
fn jitter(i: usize) -> f64 {
    let v = ((i as f64 + 1.0) * 12.9898).sin() * 43_758.545_3;
    v - v.floor()
}

// ---------------------------------------------------------------- PNG container

#[test]
fn png_file_has_signature_and_ihdr_dimensions() {
    let mut fig = Figure::new(321, 203);
    fig.axes()
        .line(&[0.0, 1.0], &[0.0, 1.0], Style::line(BLACK))
        .unwrap();
    let path = std::env::temp_dir().join(format!("sph_plot_ihdr_{}.png", std::process::id()));
    fig.save_png(&path).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    // First chunk: length 13, type IHDR, width, height (big-endian), depth 8, colour type 2 (RGB).
    assert_eq!(u32::from_be_bytes(bytes[8..12].try_into().unwrap()), 13);
    assert_eq!(&bytes[12..16], b"IHDR");
    assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 321);
    assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 203);
    assert_eq!(bytes[24], 8);
    assert_eq!(bytes[25], 2);
    assert_eq!(&bytes[bytes.len() - 8..bytes.len() - 4], b"IEND");
}

#[test]
fn save_into_missing_directory_is_an_io_error_naming_the_path() {
    let fig = Figure::new(50, 50);
    let path = std::env::temp_dir()
        .join("sph_plot_no_such_dir")
        .join("x.png");
    match fig.save_png(&path) {
        Err(PlotError::Io { path: p, .. }) => assert_eq!(p, path),
        other => panic!("expected Io error, got {other:?}"),
    }
}

// ---------------------------------------------------------------- ticks

#[test]
fn ticks_unit_interval() {
    let t = TickSet::linear(0.0, 1.0, 6);
    assert!(close(&values(&t), &[0.0, 0.2, 0.4, 0.6, 0.8, 1.0]));
    assert_eq!(labels(&t), ["0.0", "0.2", "0.4", "0.6", "0.8", "1.0"]);
}

#[test]
fn ticks_small_numbers_use_a_common_exponent() {
    let t = TickSet::linear(0.0003, 0.0017, 7);
    assert!(close(
        &values(&t),
        &[0.0004, 0.0006, 0.0008, 0.0010, 0.0012, 0.0014, 0.0016]
    ));
    assert_eq!(
        labels(&t),
        [
            "0.4e-3", "0.6e-3", "0.8e-3", "1.0e-3", "1.2e-3", "1.4e-3", "1.6e-3"
        ]
    );
    // Fewer ticks allowed: the next nice step, 2.5e-4, then 5e-4.
    let t = TickSet::linear(0.0003, 0.0017, 6);
    assert!(close(
        &values(&t),
        &[0.0005, 0.00075, 0.0010, 0.00125, 0.0015]
    ));
    assert_eq!(
        labels(&t),
        ["0.50e-3", "0.75e-3", "1.00e-3", "1.25e-3", "1.50e-3"]
    );
    let t = TickSet::linear(0.0003, 0.0017, 4);
    assert_eq!(labels(&t), ["0.5e-3", "1.0e-3", "1.5e-3"]);
}

#[test]
fn ticks_with_step_2_5_get_two_decimals() {
    // 0.2 would give 6 ticks, more than 5: 0.25 gives 5.
    let t = TickSet::linear(1.73, 2.87, 5);
    assert!(close(&values(&t), &[1.75, 2.0, 2.25, 2.5, 2.75]));
    assert_eq!(labels(&t), ["1.75", "2.00", "2.25", "2.50", "2.75"]);
}

#[test]
fn ticks_straddling_zero() {
    let t = TickSet::linear(-2.5, 7.0, 6);
    assert!(close(&values(&t), &[-2.0, 0.0, 2.0, 4.0, 6.0]));
    assert_eq!(labels(&t), ["-2", "0", "2", "4", "6"]);
    assert_eq!(nice_step(-2.5, 7.0, 6), Some(2.0));
}

#[test]
fn ticks_large_linear_numbers() {
    let t = TickSet::linear(1e5, 3e7, 7);
    assert!(close(&values(&t), &[5e6, 1e7, 1.5e7, 2e7, 2.5e7, 3e7]));
    assert_eq!(
        labels(&t),
        ["0.5e7", "1.0e7", "1.5e7", "2.0e7", "2.5e7", "3.0e7"]
    );
}

#[test]
fn ticks_log_decades_with_minor_ticks() {
    let t = TickSet::log(1e5, 3e7, 8);
    assert!(close(&values(&t), &[1e5, 1e6, 1e7]));
    assert_eq!(labels(&t), ["1e5", "1e6", "1e7"]);
    // 2..9 × 1e5, 2..9 × 1e6, 2 and 3 × 1e7.
    assert_eq!(t.minor.len(), 8 + 8 + 2);
    assert!(close(&t.minor[..2], &[2e5, 3e5]));
    assert!(close(&t.minor[16..], &[2e7, 3e7]));
}

#[test]
fn ticks_log_plain_labels_near_one_and_thinning() {
    let t = TickSet::log(0.01, 1000.0, 8);
    assert_eq!(labels(&t), ["0.01", "0.1", "1", "10", "100", "1000"]);
    // 21 decades, at most 6 labels: every 4th decade, no minor ticks.
    let t = TickSet::log(1e-10, 1e10, 6);
    assert_eq!(labels(&t), ["1e-8", "1e-4", "1", "1e4", "1e8"]);
    assert!(t.minor.is_empty());
}

#[test]
fn ticks_log_within_one_decade_use_1_2_5() {
    let t = TickSet::log(1.5, 60.0, 8);
    assert!(close(&values(&t), &[2.0, 5.0, 10.0, 20.0, 50.0]));
    assert_eq!(labels(&t), ["2", "5", "10", "20", "50"]);
}

#[test]
fn ticks_reject_unusable_ranges() {
    assert_eq!(nice_step(1.0, 1.0, 6), None);
    assert_eq!(nice_step(2.0, 1.0, 6), None);
    assert_eq!(nice_step(f64::NAN, 1.0, 6), None);
    assert!(TickSet::linear(0.0, 1.0, 1).major.is_empty());
    assert!(TickSet::log(-1.0, 10.0, 6).major.is_empty());
    // A range of 1e-13 relative width cannot be subdivided.
    assert_eq!(nice_step(1.0, 1.0 + 1e-13, 6), None);
}

#[test]
fn tick_labels_have_no_negative_zero() {
    assert_eq!(linear_labels(&[-0.0, 0.5], 0.5), ["0.0", "0.5"]);
}

// ---------------------------------------------------------------- rasterisation

#[test]
fn placed_x_ticks_replace_the_nice_steps_and_thin_where_labels_crowd() {
    let bars = |n: usize, width: u32| {
        let mut fig = Figure::new(width, 300);
        let ax = fig.panel(0, 0, 1, 1).unwrap();
        let ticks: Vec<(f64, String)> = (0..n).map(|k| (k as f64, format!("{}", 10 + k))).collect();
        ax.xticks(&ticks).unwrap();
        for k in 0..n {
            let x = k as f64;
            ax.bars(&[x - 0.35, x + 0.35], &[1.0 + x], Style::bars(BLUE))
                .unwrap();
        }
        fig.render().unwrap().1.panels[0].x_ticks.clone()
    };
    // Three bars: a tick under each, with the caller's labels (nice steps would
    // label 0, 0.5, 1, 1.5, 2).
    assert_eq!(bars(3, 400), ["10", "11", "12"]);
    // Forty bars in a narrow panel: every 2^k-th label, starting from the first.
    let thinned = bars(40, 300);
    assert!(thinned.len() < 40 && thinned.len() >= 2, "{thinned:?}");
    let stride: usize = thinned[1].parse::<usize>().unwrap() - 10;
    assert!(stride.is_power_of_two() && stride > 1, "{thinned:?}");
    assert_eq!(thinned[0], "10");
    // Unusable ticks are refused.
    let mut fig = Figure::new(300, 300);
    let ax = fig.panel(0, 0, 1, 1).unwrap();
    let e = ax
        .xticks(&[(1.0, "a".into()), (1.0, "b".into())])
        .unwrap_err();
    assert!(
        matches!(e, PlotError::BadParameter { what: "x tick", .. }),
        "{e}"
    );
    let e = ax.xticks(&[(f64::NAN, "a".into())]).unwrap_err();
    assert!(
        matches!(e, PlotError::BadParameter { what: "x tick", .. }),
        "{e}"
    );
}

#[test]
fn diagonal_line_colours_the_pixels_it_crosses() {
    let (w, h) = (100u32, 80u32);
    for aa in [false, true] {
        let mut c = Canvas::new(w, h, WHITE).unwrap();
        c.set_antialias(aa);
        c.line([0.0, 0.0], [w as f64, h as f64], &Stroke::solid(1.0, BLACK));
        for x in 0..w as i64 {
            // The line passes through column x at y = 0.8 (x + ½): the pixel there.
            let y = ((x as f64 + 0.5) * h as f64 / w as f64).floor() as i64;
            let p = c.pixel(x, y).unwrap();
            assert!(p.r < 110, "aa={aa}: pixel ({x},{y}) = {p:?} not inked");
        }
        // Pixels two rows off the line stay white.
        for x in 0..w as i64 {
            let y = ((x as f64 + 0.5) * h as f64 / w as f64).floor() as i64;
            for off in [-3i64, 3] {
                if let Some(p) = c.pixel(x, y + off) {
                    assert_eq!(p, WHITE, "aa={aa}: pixel ({x},{}) inked", y + off);
                }
            }
        }
    }
}

#[test]
fn thick_line_has_its_width() {
    let mut c = Canvas::new(60, 40, WHITE).unwrap();
    c.set_antialias(false);
    c.line([5.0, 20.0], [55.0, 20.0], &Stroke::solid(6.0, RED));
    let inked = (0..40).filter(|&y| c.pixel(30, y) == Some(RED)).count();
    assert_eq!(inked, 6);
}

#[test]
fn dashed_line_has_gaps_in_proportion() {
    let mut c = Canvas::new(400, 10, WHITE).unwrap();
    c.set_antialias(false);
    let stroke = Stroke {
        dash: Some((10.0, 10.0)),
        ..Stroke::solid(1.0, BLACK)
    };
    c.line([0.0, 5.5], [400.0, 5.5], &stroke);
    let inked = (0..400).filter(|&x| c.pixel(x, 5) == Some(BLACK)).count();
    // 20 dashes of 10 px (caps included) on 400 px.
    assert!((195..=205).contains(&inked), "inked {inked}");
}

#[test]
fn non_finite_point_breaks_a_polyline() {
    let mut c = Canvas::new(100, 20, WHITE).unwrap();
    c.set_antialias(false);
    let pts = [
        [0.0, 10.5],
        [40.0, 10.5],
        [f64::NAN, 0.0],
        [60.0, 10.5],
        [100.0, 10.5],
    ];
    c.polyline(&pts, &Stroke::solid(1.0, BLACK));
    assert_eq!(c.pixel(20, 10), Some(BLACK));
    assert_eq!(c.pixel(50, 10), Some(WHITE));
    assert_eq!(c.pixel(80, 10), Some(BLACK));
}

#[test]
fn filled_circle_and_clip() {
    let mut c = Canvas::new(40, 40, WHITE).unwrap();
    c.set_antialias(false);
    c.fill_circle([20.0, 20.0], 8.0, BLUE);
    assert_eq!(c.pixel(20, 20), Some(BLUE));
    assert_eq!(c.pixel(20, 13), Some(BLUE));
    assert_eq!(c.pixel(20, 10), Some(WHITE));
    let mut c = Canvas::new(40, 40, WHITE).unwrap();
    c.set_clip(Some(sph_diagnostics::plot::Rect::new(0, 0, 20, 40)));
    c.fill_circle([20.0, 20.0], 8.0, BLUE);
    assert_eq!(c.pixel(18, 20), Some(BLUE));
    assert_eq!(c.pixel(22, 20), Some(WHITE));
}

#[test]
fn canvas_size_is_checked() {
    assert!(matches!(
        Canvas::new(0, 10, WHITE),
        Err(PlotError::BadSize { .. })
    ));
    assert!(matches!(
        Canvas::new(10, 100_000, WHITE),
        Err(PlotError::BadSize { .. })
    ));
}

// ---------------------------------------------------------------- font

/// Pixels inked by `ch` drawn alone at scale 1.
fn render_char(ch: char) -> Vec<(i64, i64)> {
    let mut c = Canvas::new(8, 12, WHITE).unwrap();
    c.text(1, 1, &ch.to_string(), &TextStyle::new(1));
    (0..12)
        .flat_map(|y| (0..8).map(move |x| (x, y)))
        .filter(|&(x, y)| c.pixel(x, y) != Some(WHITE))
        .collect()
}

#[test]
fn every_printable_ascii_character_has_ink_and_a_glyph_of_its_own() {
    assert!(render_char(' ').is_empty());
    let chars: Vec<char> = (33u8..=126).map(char::from).collect();
    let drawn: Vec<_> = chars.iter().map(|&ch| render_char(ch)).collect();
    for (ch, px) in chars.iter().zip(&drawn) {
        assert!(!px.is_empty(), "{ch:?} draws nothing");
        assert!(font::glyph(*ch).is_some());
    }
    for i in 0..chars.len() {
        for j in i + 1..chars.len() {
            assert_ne!(
                drawn[i], drawn[j],
                "{:?} and {:?} look the same",
                chars[i], chars[j]
            );
        }
    }
}

#[test]
fn greek_and_symbols_have_glyphs_distinct_from_ascii() {
    let ascii: Vec<_> = (32u8..=126)
        .map(|b| font::glyph(b as char).unwrap())
        .collect();
    for ch in "ρσεγαβθμτφΔ×±°²³·".chars() {
        let g = font::glyph(ch).unwrap_or_else(|| panic!("no glyph for {ch}"));
        assert!(!ascii.contains(&g), "{ch} duplicates an ASCII glyph");
    }
    // The minus sign is the hyphen's glyph; an unknown character is drawn as a box.
    assert_eq!(font::glyph('\u{2212}'), font::glyph('-'));
    assert_eq!(font::glyph('\u{2013}'), font::glyph('-'));
    assert_eq!(font::glyph('\u{2014}'), font::glyph('-'));
    // The micro sign of "µs" is drawn as the Greek μ, not as the missing-glyph box.
    assert_eq!(font::glyph('\u{b5}'), font::glyph('μ'));
    assert!(font::glyph('☃').is_none());
    assert!(!render_char('☃').is_empty());
}

#[test]
fn text_scales_and_rotates() {
    assert_eq!(font::text_width("abc", 1), 17);
    assert_eq!(font::text_width("abc", 3), 51);
    let mut c = Canvas::new(100, 100, WHITE).unwrap();
    c.text(50, 80, "HHHH", &TextStyle::new(2).vertical());
    let inked: Vec<(i64, i64)> = (0..100)
        .flat_map(|y| (0..100).map(move |x| (x, y)))
        .filter(|&(x, y)| c.pixel(x, y) != Some(WHITE))
        .collect();
    let (xs, ys): (Vec<i64>, Vec<i64>) = inked.iter().copied().unzip();
    let (w, h) = (
        xs.iter().max().unwrap() - xs.iter().min().unwrap() + 1,
        ys.iter().max().unwrap() - ys.iter().min().unwrap() + 1,
    );
    // Upright "HHHH" at scale 2 is 46 × 14 px; rotated it is 14 × 46, above (50, 80).
    assert_eq!((w, h), (14, 46));
    assert_eq!(*ys.iter().max().unwrap(), 79);
}

// ---------------------------------------------------------------- figures, data accounting, errors

#[test]
fn scatter_of_1e5_points_renders() {
    let n = 100_000;
    let x: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
    let y: Vec<f64> = (0..n)
        .map(|i| (6.0 * x[i]).sin() + 0.1 * jitter(i))
        .collect();
    let mut fig = Figure::new(800, 600);
    let ax = fig.axes();
    ax.scatter(&x, &y, Style::points(BLUE).size(2.0)).unwrap();
    let t = Instant::now();
    let (canvas, report) = fig.render().unwrap();
    let t_render = t.elapsed().as_secs_f64();
    let png = canvas.to_png().unwrap();
    eprintln!(
        "scatter of 1e5 points: render {:.1} ms, PNG encode {:.1} ms ({} bytes)",
        t_render * 1e3,
        (t.elapsed().as_secs_f64() - t_render) * 1e3,
        png.len()
    );
    assert_eq!(report.panels[0].series[0].total, n);
    assert_eq!(report.skipped(), 0);
}

#[test]
fn non_finite_points_are_skipped_and_counted() {
    let mut fig = Figure::new(300, 200);
    let ax = fig.axes();
    let x = [0.0, 1.0, 2.0, f64::INFINITY, 4.0];
    let y = [1.0, f64::NAN, 3.0, 4.0, 5.0];
    let c = ax.scatter(&x, &y, Style::points(RED)).unwrap();
    assert_eq!((c.total, c.non_finite), (5, 2));
    let (_, report) = fig.render().unwrap();
    assert_eq!(report.panels[0].series[0].non_finite, 2);
    assert_eq!(report.skipped(), 2);
}

#[test]
fn log_axis_counts_non_positive_values() {
    let mut fig = Figure::new(400, 300);
    let ax = fig.axes();
    ax.yscale(Scale::Log);
    ax.line(
        &[0.0, 1.0, 2.0, 3.0],
        &[1.0, -1.0, 0.0, 100.0],
        Style::line(BLACK),
    )
    .unwrap();
    let (_, report) = fig.render().unwrap();
    assert_eq!(report.panels[0].series[0].outside_log_domain, 2);
    assert_eq!(report.skipped(), 2);

    let mut fig = Figure::new(400, 300);
    fig.axes()
        .xscale(Scale::Log)
        .scatter(&[-1.0, 0.0], &[1.0, 2.0], Style::points(BLACK))
        .unwrap();
    assert!(matches!(
        fig.render(),
        Err(PlotError::NoPositiveData { axis: "x", .. })
    ));
}

#[test]
fn points_outside_fixed_limits_are_counted_as_outside_view() {
    let mut fig = Figure::new(400, 300);
    let ax = fig.axes();
    ax.xlim(0.0, 1.0).unwrap();
    ax.scatter(&[0.5, 1.5, -2.0], &[0.0, 0.0, 0.0], Style::points(BLACK))
        .unwrap();
    let (_, report) = fig.render().unwrap();
    assert_eq!(report.panels[0].series[0].outside_view, 2);
    assert_eq!(report.skipped(), 0);
}

#[test]
fn bad_data_and_parameters_are_typed_errors() {
    let mut fig = Figure::new(400, 300);
    let ax = fig.axes();
    match ax.line(&[0.0, 1.0], &[0.0], Style::line(BLACK).label("exact")) {
        Err(PlotError::LengthMismatch {
            series,
            what: "y",
            len: 1,
            expected: 2,
        }) => assert_eq!(series, "exact"),
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        ax.scatter(&[f64::NAN; 3], &[1.0; 3], Style::points(BLACK)),
        Err(PlotError::NoFinitePoints { total: 3, .. })
    ));
    assert!(matches!(
        ax.scatter(&[], &[], Style::points(BLACK)),
        Err(PlotError::NoFinitePoints { total: 0, .. })
    ));
    assert!(matches!(
        ax.line(&[0.0, 1.0], &[0.0, 1.0], Style::line(BLACK).width(0.0)),
        Err(PlotError::BadParameter { what: "width", .. })
    ));
    assert!(matches!(
        ax.line(&[0.0, 1.0], &[0.0, 1.0], Style::line(BLACK).alpha(1.5)),
        Err(PlotError::BadParameter { what: "alpha", .. })
    ));
    assert!(matches!(
        ax.line(
            &[0.0, 1.0],
            &[0.0, 1.0],
            Style::line(BLACK).dashed(0.1, 3.0)
        ),
        Err(PlotError::BadParameter {
            what: "dash on",
            ..
        })
    ));
    assert!(matches!(
        ax.xlim(1.0, 0.0),
        Err(PlotError::BadLimits { axis: "x", .. })
    ));
    assert!(matches!(
        ax.ylim(0.0, f64::NAN),
        Err(PlotError::BadLimits { axis: "y", .. })
    ));
    assert!(matches!(
        ax.bars(&[0.0, 1.0], &[1.0, 2.0], Style::bars(BLUE)),
        Err(PlotError::LengthMismatch {
            what: "edges",
            len: 2,
            expected: 3,
            ..
        })
    ));
    assert!(matches!(
        ax.scatter_colored(
            &[0.0],
            &[0.0],
            &[0.5],
            ColorScale::new(Colormap::Viridis).range(1.0, 0.0),
            Style::points(BLACK)
        ),
        Err(PlotError::BadLimits { axis: "colour", .. })
    ));
    assert!(matches!(
        ax.histogram(&[1.0], 0, Style::bars(BLUE)),
        Err(PlotError::BadParameter { what: "bins", .. })
    ));
    assert_eq!(ax.series_count(), 0, "rejected series must not be kept");
    assert!(matches!(
        fig.panel(2, 0, 2, 2),
        Err(PlotError::BadPanel { row: 2, .. })
    ));
    assert!(matches!(
        fig.text_scale(4),
        Err(PlotError::BadParameter {
            what: "text_scale",
            ..
        })
    ));
    assert!(matches!(
        Figure::new(0, 10).render(),
        Err(PlotError::BadSize { .. })
    ));

    let mut fig = Figure::new(400, 300);
    fig.axes().yscale(Scale::Log).ylim(0.0, 1.0).unwrap();
    assert!(matches!(
        fig.render(),
        Err(PlotError::BadLimits { axis: "y", .. })
    ));

    let mut fig = Figure::new(60, 60);
    fig.axes()
        .title("t")
        .xlabel("x")
        .ylabel("y")
        .line(&[0.0, 1.0], &[0.0, 1.0], Style::line(BLACK))
        .unwrap();
    assert!(matches!(fig.render(), Err(PlotError::PanelTooSmall { .. })));
}

#[test]
fn histogram_bins_every_finite_value_once() {
    let data: Vec<f64> = (0..1000).map(jitter).chain([f64::NAN, 1.0]).collect();
    let b = bin(&data, 10, "d").unwrap();
    assert_eq!(b.counts.iter().sum::<f64>(), 1001.0);
    assert_eq!(b.count.non_finite, 1);
    assert_eq!(b.edges.len(), 11);
    assert_eq!(*b.edges.last().unwrap(), 1.0);
    // One repeated value: one bin of width 1 around it.
    let b = bin(&[2.0, 2.0], 1, "d").unwrap();
    assert_eq!(b.edges, [1.5, 2.5]);
    assert_eq!(b.counts, [2.0]);
}

#[test]
fn colour_maps_and_out_of_range_values() {
    assert_eq!(Colormap::Viridis.at(0.0), Rgb::new(68, 1, 84));
    assert_eq!(Colormap::Viridis.at(0.5), Rgb::new(33, 144, 140));
    assert_eq!(Colormap::Viridis.at(1.0), Rgb::new(253, 231, 37));
    assert_eq!(Colormap::Greys.at(0.5), Rgb::new(128, 128, 128));
    let mut fig = Figure::new(500, 400);
    let cs = ColorScale::new(Colormap::Viridis)
        .range(0.0, 1.0)
        .label("D");
    fig.axes()
        .scatter_colored(
            &[0.0, 1.0, 2.0],
            &[0.0, 1.0, 2.0],
            &[0.5, 1.2, -0.1],
            cs,
            Style::points(BLACK),
        )
        .unwrap();
    let (_, report) = fig.render().unwrap();
    assert_eq!(report.panels[0].series[0].outside_color_range, 2);
}

#[test]
fn every_marker_and_series_kind_renders() {
    let mut fig = Figure::new(900, 600);
    let x: Vec<f64> = (0..20).map(|i| i as f64).collect();
    let y: Vec<f64> = x.iter().map(|v| v * v + 1.0).collect();
    let markers = [
        Marker::Circle,
        Marker::OpenCircle,
        Marker::Square,
        Marker::Diamond,
        Marker::Triangle,
        Marker::Plus,
        Marker::Cross,
    ];
    {
        let ax = fig.panel(0, 0, 1, 2).unwrap();
        for (k, m) in markers.iter().enumerate() {
            let yk: Vec<f64> = y.iter().map(|v| v + 50.0 * k as f64).collect();
            ax.scatter(
                &x,
                &yk,
                Style::points(RED)
                    .marker(*m)
                    .size(7.0)
                    .label(format!("{m:?}")),
            )
            .unwrap();
        }
        ax.hline(200.0, Style::line(BLACK).dashed(6.0, 4.0))
            .unwrap();
        ax.vline(5.0, Style::line(BLACK)).unwrap();
        ax.legend(LegendPos::UpperLeft);
    }
    {
        let ax = fig.panel(0, 1, 1, 2).unwrap();
        ax.yscale(Scale::Log)
            .histogram(&y, 5, Style::bars(ORANGE).label("y"))
            .unwrap();
    }
    let (canvas, report) = fig.render().unwrap();
    assert_eq!(report.panels.len(), 2);
    assert_eq!(report.skipped(), 0);
    let inked = canvas
        .data()
        .chunks(3)
        .filter(|p| p != &[255, 255, 255])
        .count();
    assert!(inked > 10_000, "only {inked} pixels drawn");
}

// ---------------------------------------------------------------- invariants

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Linear ticks: between 2 and max of them (max ≥ 4), inside the range, evenly
    /// spaced by a 1-2-2.5-5 step, with distinct labels.
    #[test]
    fn linear_ticks_are_nice_inside_and_distinct(
        lo in -1e6f64..1e6,
        width_exp in -6f64..8.0,
        max in 4usize..=10,
    ) {
        let hi = lo + 10f64.powf(width_exp);
        prop_assume!(hi - lo > 1e-11 * lo.abs().max(hi.abs()));
        let t = TickSet::linear(lo, hi, max);
        let v = values(&t);
        prop_assert!((2..=max).contains(&v.len()), "{} ticks for [{lo}, {hi}], max {max}", v.len());
        let step = nice_step(lo, hi, max).unwrap();
        let m = step / 10f64.powf(step.log10().floor());
        prop_assert!([1.0, 2.0, 2.5, 5.0, 10.0].iter().any(|n| (m - n).abs() < 1e-9), "step {step}");
        // Exact up to the rounding of values of magnitude |lo|, |hi|.
        let tol = 4.0 * f64::EPSILON * lo.abs().max(hi.abs()) + 1e-12 * step;
        prop_assert!(v.iter().all(|&x| x >= lo - tol && x <= hi + tol));
        for w in v.windows(2) {
            prop_assert!(((w[1] - w[0]) - step).abs() <= tol, "spacing {} vs step {step}", w[1] - w[0]);
        }
        let l = labels(&t);
        for i in 0..l.len() {
            for j in i + 1..l.len() {
                prop_assert_ne!(l[i], l[j]);
            }
        }
    }

    /// Strokes of any coordinates (huge, NaN) and widths neither panic nor ink outside the clip.
    #[test]
    fn strokes_stay_inside_the_clip(
        pts in proptest::collection::vec((-1e12f64..1e12, -1e12f64..1e12, 0u8..8), 2..12),
        width in 0.1f64..20.0,
        dashed in any::<bool>(),
    ) {
        let mut c = Canvas::new(64, 48, WHITE).unwrap();
        c.set_clip(Some(sph_diagnostics::plot::Rect::new(10, 5, 50, 40)));
        // Small coordinates most of the time, so that something is drawn.
        let p: Vec<[f64; 2]> = pts
            .iter()
            .map(|&(x, y, k)| match k {
                0 => [f64::NAN, y],
                1 => [x, y],
                _ => [x.rem_euclid(80.0) - 8.0, y.rem_euclid(60.0) - 6.0],
            })
            .collect();
        let stroke = Stroke { dash: dashed.then_some((3.0, 2.0)), ..Stroke::solid(width, RED) };
        c.polyline(&p, &stroke);
        for y in 0..48 {
            for x in 0..64 {
                if !(10..50).contains(&x) || !(5..40).contains(&y) {
                    prop_assert_eq!(c.pixel(x, y), Some(WHITE));
                }
            }
        }
    }

    /// Any data renders or fails with a typed error; no panic, and the report's counts
    /// add up to what was given.
    #[test]
    fn figures_of_arbitrary_data_render_or_fail_cleanly(
        data in proptest::collection::vec((prop_oneof![Just(f64::NAN), Just(f64::INFINITY), -1e30f64..1e30, -1.0f64..1.0], -1e3f64..1e3), 1..40),
        log_x in any::<bool>(),
        log_y in any::<bool>(),
    ) {
        let (x, y): (Vec<f64>, Vec<f64>) = data.into_iter().unzip();
        let mut fig = Figure::new(320, 240);
        let ax = fig.axes();
        if log_x { ax.xscale(Scale::Log); }
        if log_y { ax.yscale(Scale::Log); }
        let added = match ax.scatter(&x, &y, Style::points(BLUE)) {
            Ok(c) => c,
            Err(PlotError::NoFinitePoints { .. }) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        };
        match fig.render() {
            Ok((_, report)) => {
                let r = &report.panels[0].series[0];
                prop_assert_eq!(r.total, x.len());
                prop_assert_eq!(r.non_finite, added.non_finite);
                prop_assert!(r.skipped() <= r.total);
            }
            Err(PlotError::NoPositiveData { .. }) => prop_assert!(log_x || log_y),
            Err(e) => return Err(TestCaseError::fail(format!("{e}"))),
        }
    }
}

// ---------------------------------------------------------------- demos for the eye

/// Sod's shock tube at t = 0.2 (Toro test 1) on 2×2 panels: "particles" (the exact
/// solution sampled with noise and smearing, standing in for an SPH run) against the
/// exact solution.
#[test]
#[ignore = "writes /tmp/plot_demo.png for a person to look at"]
fn demo_sod_2x2() {
    let sod = RiemannSolution::solve(
        GasState {
            density: 1.0,
            velocity: 0.0,
            pressure: 1.0,
        },
        GasState {
            density: 0.125,
            velocity: 0.0,
            pressure: 0.1,
        },
        1.4,
    )
    .unwrap();
    let (t, x0) = (0.2, 0.5);
    let state = |x: f64| sod.sample((x - x0) / t);
    let xe: Vec<f64> = (0..=2000).map(|i| i as f64 / 2000.0).collect();
    let xp: Vec<f64> = (0..400).map(|i| (i as f64 + 0.5) / 400.0).collect();
    // Smear over ±0.01 (a stand-in for SPH's smoothing); 1 % noise is added below.
    let smeared = |x: f64, f: &dyn Fn(GasState) -> f64| {
        (-2..=2)
            .map(|k| f(state(x + 0.005 * k as f64)))
            .sum::<f64>()
            / 5.0
    };
    type Field = (&'static str, &'static str, fn(GasState) -> f64);
    let fields: [Field; 4] = [
        ("density", "ρ (kg/m³)", |s| s.density),
        ("velocity", "v (m/s)", |s| s.velocity),
        ("pressure", "p (Pa)", |s| s.pressure),
        ("specific internal energy", "e (J/kg)", |s| {
            s.pressure / ((1.4 - 1.0) * s.density)
        }),
    ];
    let mut fig = Figure::new(1200, 900);
    fig.title("Sod shock tube, t = 0.2 s");
    for (k, (name, unit, f)) in fields.iter().enumerate() {
        let ye: Vec<f64> = xe.iter().map(|&x| f(state(x))).collect();
        let yp: Vec<f64> = xp
            .iter()
            .enumerate()
            .map(|(i, &x)| smeared(x, f) * (1.0 + 0.01 * (jitter(i + 97 * k) - 0.5)))
            .collect();
        let ax = fig.panel(k / 2, k % 2, 2, 2).unwrap();
        ax.title(*name).xlabel("x (m)").ylabel(*unit);
        ax.scatter(
            &xp,
            &yp,
            Style::points(BLUE).size(4.0).label("SPH, 400 particles"),
        )
        .unwrap();
        ax.line(&xe, &ye, Style::line(BLACK).label("exact"))
            .unwrap();
    }
    let t0 = Instant::now();
    let (canvas, report) = fig.render().unwrap();
    let t1 = Instant::now();
    canvas.save_png("/tmp/plot_demo.png").unwrap();
    eprintln!(
        "2x2 Sod figure: render {:.1} ms, PNG encode+write {:.1} ms",
        (t1 - t0).as_secs_f64() * 1e3,
        t1.elapsed().as_secs_f64() * 1e3
    );
    assert_eq!(report.skipped(), 0);
}

/// The other series kinds: a log-log time history with small numbers, a histogram, and a
/// damage cross-section with a colour bar and equal aspect.
#[test]
#[ignore = "writes /tmp/plot_demo2.png for a person to look at"]
fn demo_other_kinds() {
    let mut fig = Figure::new(1500, 500);
    {
        let ax = fig.panel(0, 0, 1, 3).unwrap();
        let t: Vec<f64> = (0..60)
            .map(|i| 1e-6 * 10f64.powf(i as f64 / 20.0))
            .collect();
        // Sedov–Taylor blast: R ∝ t^(2/5).
        let r: Vec<f64> = t
            .iter()
            .map(|t| 0.03 * (t / 1e-6f64).powf(0.4) * 1e-3)
            .collect();
        let rn: Vec<f64> = r
            .iter()
            .enumerate()
            .map(|(i, r)| r * (1.0 + 0.05 * (jitter(i) - 0.5)))
            .collect();
        ax.title("shock radius").xlabel("t (s)").ylabel("R (m)");
        ax.xscale(Scale::Log).yscale(Scale::Log);
        ax.scatter(
            &t,
            &rn,
            Style::points(RED)
                .marker(Marker::OpenCircle)
                .size(7.0)
                .label("SPH"),
        )
        .unwrap();
        ax.line(
            &t,
            &r,
            Style::line(BLACK).dashed(8.0, 5.0).label("R ~ t^0.4"),
        )
        .unwrap();
    }
    {
        let ax = fig.panel(0, 1, 1, 3).unwrap();
        let v: Vec<f64> = (0..5000)
            .map(|i| {
                1.5e3
                    * ((-2.0 * (jitter(i) + 1e-12).ln()).sqrt()
                        * (std::f64::consts::TAU * jitter(i + 7919)).cos())
                    + 4e3
            })
            .collect();
        ax.title("ejecta speed").xlabel("v (m/s)").ylabel("count");
        ax.histogram(&v, 30, Style::bars(BLUE).label("5000 particles"))
            .unwrap();
    }
    {
        let ax = fig.panel(0, 2, 1, 3).unwrap();
        let (mut x, mut y, mut d) = (Vec::new(), Vec::new(), Vec::new());
        for i in 0..120 {
            for j in 0..60 {
                let (px, py) = (-0.06 + i as f64 * 1e-3, -j as f64 * 1e-3);
                let r = (px * px + (py - 0.004).powi(2)).sqrt();
                x.push(px);
                y.push(py);
                d.push((1.2 - r / 0.03).clamp(0.0, 1.0));
            }
        }
        ax.title("damage")
            .xlabel("r (m)")
            .ylabel("z (m)")
            .equal_aspect(true);
        ax.scatter_colored(
            &x,
            &y,
            &d,
            ColorScale::new(Colormap::Viridis)
                .range(0.0, 1.0)
                .label("D"),
            Style::points(BLACK).size(4.0),
        )
        .unwrap();
    }
    let report = fig.save_png("/tmp/plot_demo2.png").unwrap();
    assert_eq!(report.skipped(), 0);
}

/// Every glyph at scales 1, 2 and 3, for checking the font by eye.
#[test]
#[ignore = "writes /tmp/plot_font.png for a person to look at"]
fn demo_font_specimen() {
    let ascii: String = (32u8..=126).map(char::from).collect();
    let lines = [
        &ascii[..48],
        &ascii[48..],
        "ρσεγαβθμτφΔ×±°²³· ☃",
        "ρ (kg/m³)  σ_y = 1.2e8 Pa  Δt = 3.5e-9 s",
    ];
    let mut c = Canvas::new(900, 330, WHITE).unwrap();
    let mut y = 10;
    for scale in 1..=3u32 {
        for line in lines {
            c.text(10, y, line, &TextStyle::new(scale));
            y += 11 * scale as i64;
        }
        y += 10;
    }
    c.save_png("/tmp/plot_font.png").unwrap();
}

/// A small single panel with text scale 1, negative and tiny numbers.
#[test]
#[ignore = "writes /tmp/plot_small.png for a person to look at"]
fn demo_small_panel() {
    let t: Vec<f64> = (0..300).map(|i| i as f64 * 1e-7).collect();
    let e: Vec<f64> = t
        .iter()
        .map(|t| -2.5e-4 * (1.0 - (-t / 5e-6).exp()))
        .collect();
    let mut fig = Figure::new(400, 300);
    fig.text_scale(1).unwrap();
    let ax = fig.axes();
    ax.title("energy error").xlabel("t (s)").ylabel("ΔE/E");
    ax.line(&t, &e, Style::line(RED).width(2.0).label("ΔE/E"))
        .unwrap();
    ax.hline(0.0, Style::line(BLACK).dashed(4.0, 3.0).width(1.0))
        .unwrap();
    fig.save_png("/tmp/plot_small.png").unwrap();
}

/// A figure title wider than the figure at its usual scale is drawn smaller so that it
/// fits (the speed-vs-error plot's title was cut off at both edges).
#[test]
fn a_long_figure_title_shrinks_to_fit_the_width() {
    let title = "Basalt impact at 3.9 km/s: error against Table 2 vs runtime";
    let mut fig = Figure::new(500, 300);
    fig.title(title);
    fig.axes()
        .line(&[0.0, 1.0], &[0.0, 1.0], Style::line(BLACK))
        .unwrap();
    let (canvas, _) = fig.render().unwrap();
    // The title's band: from y = 10 down by the tallest scale it could have.
    let band = 10..10 + font::text_height(3) as i64;
    let inked = |x: i64| band.clone().any(|y| canvas.pixel(x, y) != Some(WHITE));
    let columns: Vec<i64> = (0..500).filter(|&x| inked(x)).collect();
    let (first, last) = (columns[0], *columns.last().unwrap());
    println!("title ink from x = {first} to {last} of 500");
    assert!(first >= 5 && last <= 494, "{first}..{last}");
    assert!(last - first > 250, "{first}..{last}");
}

//! Plots of verification outcomes: particles against the exact solution.

use crate::verify::{Outcome, Picture};
use sph_diagnostics::plot::{BLACK, BLUE, Figure, PALETTE, PlotError, Style};
use std::path::Path;

/// Writes a 2×2 figure (density, velocity, pressure, specific energy against the
/// coordinate) with the exact curves where the outcome has them.
pub fn profile_plot(outcome: &Outcome, path: &Path) -> Result<(), PlotError> {
    let prof = &outcome.profile;
    let Some(coord_name) = prof.columns.first() else {
        return Ok(());
    };
    let coord = prof.column(coord_name).unwrap_or_default();
    let mut fig = Figure::new(1200, 900);
    fig.title(format!(
        "{}: particles (blue) against the exact solution (black)",
        outcome.problem
    ));
    let velocity = if prof.columns.iter().any(|c| c == "vr") {
        "vr"
    } else {
        "v"
    };
    let panels = [
        ("rho", "density"),
        (velocity, "velocity"),
        ("p", "pressure"),
        ("e", "specific energy"),
    ];
    for (k, (col, label)) in panels.iter().enumerate() {
        let ax = fig.panel(k / 2, k % 2, 2, 2)?;
        ax.title(*label).xlabel(coord_name.as_str()).ylabel(*col);
        if let Some(values) = prof.column(col) {
            ax.scatter(&coord, &values, Style::points(BLUE).size(3.0).label("SPH"))?;
        }
        let exact_key = if *col == "vr" { "v" } else { col };
        if let Some((_, pts)) = outcome.exact.iter().find(|(name, _)| name == exact_key) {
            let (x, y): (Vec<f64>, Vec<f64>) = pts.iter().cloned().unzip();
            ax.line(&x, &y, Style::line(BLACK).label("exact"))?;
        } else if let Some(ex) = prof.column(&format!("{col}_exact")) {
            ax.line(&coord, &ex, Style::line(BLACK).label("exact"))?;
        }
    }
    fig.save_png(path)?;
    Ok(())
}

/// Writes one [`Picture`] as a PNG: its panels in a grid, particle clouds as points and
/// curves as lines, coloured in palette order.
pub fn picture(p: &Picture, path: &Path) -> Result<(), PlotError> {
    let cols = p.columns.max(1);
    let rows = p.panels.len().div_ceil(cols).max(1);
    let mut fig = Figure::new(600 * cols as u32, 500 * rows as u32);
    fig.title(p.title.clone());
    for (k, panel) in p.panels.iter().enumerate() {
        let ax = fig.panel(k / cols, k % cols, rows, cols)?;
        ax.title(panel.title.clone())
            .xlabel(panel.labels.0.clone())
            .ylabel(panel.labels.1.clone())
            .equal_aspect(panel.equal_aspect);
        let mut color = PALETTE.iter().cycle();
        for (label, x, y) in &panel.points {
            let c = *color.next().unwrap_or(&BLUE);
            ax.scatter(x, y, Style::points(c).size(2.0).label(label.clone()))?;
        }
        for (label, x, y) in &panel.lines {
            let c = *color.next().unwrap_or(&BLACK);
            ax.line(x, y, Style::line(c).label(label.clone()))?;
        }
    }
    fig.save_png(path)?;
    Ok(())
}

//! Plots of verification outcomes: particles against the exact solution.

use crate::verify::Outcome;
use sph_diagnostics::plot::{BLACK, BLUE, Figure, PlotError, Style};
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

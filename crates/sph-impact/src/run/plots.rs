//! The run's PNG plots: the crater cross-section coloured by damage, β(t) and crater
//! size(t), the ejecta distribution against v_z/U, and the projectile's specific-energy
//! histogram with the melting and vaporisation thresholds.

use crate::run::arrays::Arrays;
use crate::run::error::RunError;
use crate::run::history::HistoryRow;
use crate::scene::GeometryKind;
use sph_diagnostics::plot::{
    BLACK, BLUE, ColorScale, Colormap, Figure, GREEN, GREY, Marker, ORANGE, PlotError, RED, Style,
};
use sph_diagnostics::{EjectaBin, MassHistogram};
use sph_eos::ThermalModel;
use std::path::Path;

/// Renders `fig` and writes it to `path` via a temporary name.
fn save(fig: &Figure, path: &Path) -> Result<(), RunError> {
    let (canvas, _) = fig.render().map_err(plot_err(path))?;
    let png = canvas.to_png().map_err(|e| RunError::io(path, e))?;
    crate::run::atomic::write_bytes(path, &png)
}

/// A figure that cannot be drawn (as against a file that cannot be written): the run
/// goes on without it.
fn plot_err(path: &Path) -> impl Fn(PlotError) -> RunError + '_ {
    move |e| RunError::Plot {
        path: path.display().to_string(),
        message: e.to_string(),
    }
}

/// `y` against `x` on `ax`, unless no point of it is finite (β of a scene without an
/// impact speed, say): then the series is left out and named in `skipped`.
fn line_if_finite(
    ax: &mut sph_diagnostics::plot::Axes,
    x: &[f64],
    y: &[f64],
    style: Style,
    skipped: &mut Vec<String>,
) -> Result<(), PlotError> {
    if x.iter().zip(y).any(|(a, b)| a.is_finite() && b.is_finite()) {
        ax.line(x, y, style).map(|_| ())
    } else {
        skipped.push(style.label.unwrap_or_else(|| "a series".to_owned()));
        Ok(())
    }
}

/// x against z of the particles in the slab |y| < their own spacing (in RZ: r against z
/// of every ring), coloured by damage; the projectile's particles are ringed.
pub(crate) fn cross_section(
    a: &Arrays,
    spacing: &[f64],
    surface_z: f64,
    projectile: u16,
    geometry: GeometryKind,
    path: &Path,
) -> Result<(), RunError> {
    let e = plot_err(path);
    let sel: Vec<usize> = (0..a.position.len())
        .filter(|&i| a.position[i][1].abs() < spacing[i])
        .collect();
    let x: Vec<f64> = sel.iter().map(|&i| a.position[i][0] * 1e3).collect();
    let z: Vec<f64> = sel.iter().map(|&i| a.position[i][2] * 1e3).collect();
    let d: Vec<f64> = sel.iter().map(|&i| a.damage[i]).collect();
    let mut fig = Figure::new(1200, 900);
    let rz = geometry == GeometryKind::Rz;
    // Plane-strain and 1-D particles all lie in y = 0: the selection keeps every one.
    // Frame the target: a few fast ejecta far above it would otherwise shrink the crater
    // to a corner. The frame spans what lies below the original surface, with half its
    // width of room above; what it leaves out is counted in the title.
    let frame = section_frame(&x, &z, surface_z * 1e3);
    let outside = frame.map_or(0, |f| {
        x.iter()
            .zip(&z)
            .filter(|(x, z)| !(f.0..=f.1).contains(*x) || !(f.2..=f.3).contains(*z))
            .count()
    });
    let what = if rz {
        "RZ half-plane (every ring), coloured by damage D"
    } else if geometry == GeometryKind::Plane {
        "Plane-strain section y = 0 (every particle), coloured by damage D"
    } else if geometry == GeometryKind::Line {
        "1-D column on the z axis (every particle), coloured by damage D"
    } else {
        "Cross-section |y| < particle spacing, coloured by damage D"
    };
    fig.title(if outside > 0 {
        format!("{what}; {outside} outside the frame")
    } else {
        what.to_owned()
    });
    let ax = fig.axes();
    ax.xlabel(if rz { "r (mm)" } else { "x (mm)" })
        .ylabel("z (mm)")
        .equal_aspect(true);
    if let Some((x0, x1, z0, z1)) = frame {
        ax.xlim(x0, x1).map_err(&e)?;
        ax.ylim(z0, z1).map_err(&e)?;
    }
    let scale = ColorScale {
        map: Colormap::Viridis,
        range: Some((0.0, 1.0)),
        label: "damage D".into(),
    };
    ax.scatter_colored(&x, &z, &d, scale, Style::points(BLACK).size(4.0))
        .map_err(&e)?;
    let (px, pz): (Vec<f64>, Vec<f64>) = sel
        .iter()
        .zip(x.iter().zip(&z))
        .filter(|(i, _)| a.body[**i] == projectile)
        .map(|(_, (x, z))| (*x, *z))
        .unzip();
    ax.scatter(
        &px,
        &pz,
        Style::points(RED)
            .marker(Marker::OpenCircle)
            .size(7.0)
            .label("projectile"),
    )
    .map_err(&e)?;
    if surface_z.is_finite() {
        ax.hline(
            surface_z * 1e3,
            Style::line(GREY).dashed(6.0, 4.0).label("original surface"),
        )
        .map_err(&e)?;
    }
    save(&fig, path)
}

/// The section's frame (x0, x1, z0, z1), same units as the points: the bounds of the
/// points at or below `surface` widened by 5 % of their width, and half the width above
/// the surface. `None` when no point lies at or below it (or the surface is not finite).
fn section_frame(x: &[f64], z: &[f64], surface: f64) -> Option<(f64, f64, f64, f64)> {
    if !surface.is_finite() {
        return None;
    }
    let (mut x0, mut x1, mut z0) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY);
    for (&x, &z) in x.iter().zip(z).filter(|(_, z)| **z <= surface) {
        x0 = x0.min(x);
        x1 = x1.max(x);
        z0 = z0.min(z);
    }
    let width = x1 - x0;
    (width > 0.0).then(|| {
        let m = 0.05 * width;
        (x0 - m, x1 + m, z0 - m, surface + 0.5 * width)
    })
}

/// β(t) and crater depth and diameter against time.
/// Returns the series left out because none of their points is finite.
pub(crate) fn histories(rows: &[HistoryRow], path: &Path) -> Result<Vec<String>, RunError> {
    let e = plot_err(path);
    let t: Vec<f64> = rows.iter().map(|r| r.t * 1e6).collect();
    let beta: Vec<f64> = rows.iter().map(|r| r.beta).collect();
    let beta_t: Vec<f64> = rows.iter().map(|r| r.beta_target).collect();
    let beta_p: Vec<f64> = rows.iter().map(|r| r.beta_pendulum).collect();
    let measured: Vec<&HistoryRow> = rows.iter().filter(|r| r.crater_measured).collect();
    let tc: Vec<f64> = measured.iter().map(|r| r.t * 1e6).collect();
    let depth: Vec<f64> = measured.iter().map(|r| r.crater_depth * 1e3).collect();
    let diam: Vec<f64> = measured.iter().map(|r| r.crater_diameter * 1e3).collect();
    let mut fig = Figure::new(1200, 1000);
    let mut skipped = Vec::new();
    let ax = fig.panel(0, 0, 2, 1).map_err(&e)?;
    ax.title("beta").xlabel("t (us)").ylabel("beta");
    line_if_finite(
        ax,
        &t,
        &beta,
        Style::line(BLUE).label("beta = 1 + P_ej/P_imp"),
        &mut skipped,
    )
    .map_err(&e)?;
    line_if_finite(
        ax,
        &t,
        &beta_t,
        Style::line(ORANGE)
            .dashed(6.0, 4.0)
            .label("beta from target"),
        &mut skipped,
    )
    .map_err(&e)?;
    line_if_finite(
        ax,
        &t,
        &beta_p,
        Style::line(GREEN)
            .dashed(2.0, 4.0)
            .label("beta as a pendulum sees it"),
        &mut skipped,
    )
    .map_err(&e)?;
    let ax = fig.panel(1, 0, 2, 1).map_err(&e)?;
    ax.title("crater").xlabel("t (us)").ylabel("mm");
    line_if_finite(
        ax,
        &tc,
        &diam,
        Style::line(BLUE).label("diameter"),
        &mut skipped,
    )
    .map_err(&e)?;
    line_if_finite(
        ax,
        &tc,
        &depth,
        Style::line(RED).label("depth"),
        &mut skipped,
    )
    .map_err(&e)?;
    fig.title(if skipped.is_empty() {
        "Momentum transfer and crater size against time".to_owned()
    } else {
        format!(
            "Momentum transfer and crater size against time (undefined, not drawn: {})",
            skipped.join(", ")
        )
    });
    save(&fig, path)?;
    Ok(skipped)
}

/// Ejecta mass and axial momentum per v_z/U bin.
pub(crate) fn ejecta(bins: &[EjectaBin], path: &Path) -> Result<(), RunError> {
    let e = plot_err(path);
    let mut fig = Figure::new(1200, 1000);
    fig.title("Ejecta against normalised axial speed v_z/U");
    let mut edges: Vec<f64> = bins.iter().map(|b| b.v_over_u_lo).collect();
    edges.push(bins.last().map_or(1.0, |b| b.v_over_u_hi));
    let mass: Vec<f64> = bins.iter().map(|b| b.mass * 1e3).collect();
    let mom: Vec<f64> = bins.iter().map(|b| b.momentum_z).collect();
    let ax = fig.panel(0, 0, 2, 1).map_err(&e)?;
    ax.title("mass").xlabel("v_z/U").ylabel("ejecta mass (g)");
    if bins.is_empty() {
        ax.line(
            &[0.0, 1.0],
            &[0.0, 0.0],
            Style::line(GREY).label("no ejecta"),
        )
        .map_err(&e)?;
    } else {
        ax.bars(&edges, &mass, Style::bars(BLUE)).map_err(&e)?;
    }
    let ax = fig.panel(1, 0, 2, 1).map_err(&e)?;
    ax.title("axial momentum").xlabel("v_z/U").ylabel("kg m/s");
    if bins.is_empty() {
        ax.line(
            &[0.0, 1.0],
            &[0.0, 0.0],
            Style::line(GREY).label("no ejecta"),
        )
        .map_err(&e)?;
    } else {
        ax.bars(&edges, &mom, Style::bars(ORANGE)).map_err(&e)?;
    }
    save(&fig, path)
}

/// The projectile's mass per specific-energy bin, with the thermal model's thresholds.
pub(crate) fn projectile_energy(
    hist: &MassHistogram,
    thermal: Option<&ThermalModel>,
    path: &Path,
) -> Result<(), RunError> {
    let e = plot_err(path);
    let mut fig = Figure::new(1200, 800);
    fig.title("Projectile specific internal energy");
    let ax = fig.axes();
    ax.xlabel("e (MJ/kg)").ylabel("mass fraction per bin");
    let total = hist.total().max(f64::MIN_POSITIVE);
    let edges: Vec<f64> = hist.edges.iter().map(|x| x * 1e-6).collect();
    let frac: Vec<f64> = hist.mass.iter().map(|m| m / total).collect();
    ax.bars(&edges, &frac, Style::bars(BLUE)).map_err(&e)?;
    if let Some(t) = thermal {
        let lines = [
            (t.incipient_melting_energy(), "melting starts", ORANGE),
            (t.complete_melting_energy(), "melting complete", RED),
            (
                t.incipient_vaporisation_energy(),
                "vaporisation starts",
                GREY,
            ),
            (
                t.complete_vaporisation_energy(),
                "vaporisation complete",
                BLACK,
            ),
        ];
        for (x, label, c) in lines {
            ax.vline(x * 1e-6, Style::line(c).dashed(6.0, 4.0).label(label))
                .map_err(&e)?;
        }
    }
    save(&fig, path)
}

#[cfg(test)]
mod tests {
    use super::section_frame;

    #[test]
    fn the_frame_holds_the_target_and_leaves_out_far_ejecta() {
        // A 10 × 5 bed below z = 0 and one ejecta particle 500 above it.
        let x = [0.0, 10.0, 5.0, 3.0];
        let z = [-5.0, 0.0, -2.0, 500.0];
        let (x0, x1, z0, z1) = section_frame(&x, &z, 0.0).unwrap();
        assert_eq!((x0, x1, z0, z1), (-0.5, 10.5, -5.5, 5.0));
        assert!(z[3] > z1);
        assert_eq!(section_frame(&x, &z, f64::NAN), None);
        assert_eq!(section_frame(&[1.0], &[1.0], 0.0), None);
    }
}

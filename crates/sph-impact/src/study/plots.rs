//! The study's plots: for each parameter with numeric values, `plot_<parameter>.png` with
//! one panel per metric against that parameter. Points that differ only in that
//! parameter are joined by a line (one colour per combination of the other parameters);
//! a reference value is a dashed black line. Only finished points are drawn.

use crate::study::error::StudyError;
use crate::study::table::{PointStatus, StudyTable};
use sph_diagnostics::plot::{BLACK, Figure, LegendPos, PALETTE, Scale, Style};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Writes the plots into `dir` and returns their paths.
pub fn write_plots(table: &StudyTable, dir: &Path) -> Result<Vec<PathBuf>, StudyError> {
    let mut written = Vec::new();
    let done: Vec<_> = table
        .rows
        .iter()
        .filter(|r| r.status == PointStatus::Done)
        .collect();
    if done.is_empty() || table.metrics.is_empty() {
        return Ok(written);
    }
    for (k, parameter) in table.parameters.iter().enumerate() {
        let Some(xs) = done
            .iter()
            .map(|r| r.values[k].as_f64())
            .collect::<Option<Vec<f64>>>()
        else {
            continue;
        };
        // The series: the points that share the values of every other parameter.
        let mut series: BTreeMap<String, Vec<usize>> = BTreeMap::new();
        for (n, r) in done.iter().enumerate() {
            let others: Vec<String> = table
                .parameters
                .iter()
                .zip(&r.values)
                .enumerate()
                .filter(|(j, _)| *j != k)
                .map(|(_, (p, v))| format!("{} = {}", short(p), crate::study::table::json_cell(v)))
                .collect();
            series.entry(others.join(", ")).or_default().push(n);
        }
        let (lo, hi) = xs
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            });
        let log_x = lo > 0.0 && hi / lo >= 100.0;
        let n_metrics = table.metrics.len();
        let cols = n_metrics.min(3);
        let rows = n_metrics.div_ceil(cols);
        let mut fig = Figure::new(520 * cols as u32, 420 * rows as u32);
        fig.title(if table.description.is_empty() {
            format!("study: the metrics against {parameter}")
        } else {
            table.description.clone()
        });
        for (m, metric) in table.metrics.iter().enumerate() {
            let plot_err = |e: sph_diagnostics::plot::PlotError| StudyError::failed(e.to_string());
            let ax = fig
                .panel(m / cols, m % cols, rows, cols)
                .map_err(plot_err)?;
            ax.title(metric.clone())
                .xlabel(parameter.clone())
                .ylabel(metric.clone());
            if log_x {
                ax.xscale(Scale::Log);
            }
            for (s, (label, members)) in series.iter().enumerate() {
                let mut pts: Vec<(f64, f64)> = members
                    .iter()
                    .map(|&n| (xs[n], done[n].metrics[m]))
                    .filter(|(_, y)| y.is_finite())
                    .collect();
                pts.sort_by(|a, b| a.0.total_cmp(&b.0));
                let (x, y): (Vec<f64>, Vec<f64>) = pts.into_iter().unzip();
                let color = PALETTE[s % PALETTE.len()];
                let mut style = Style::line(color);
                if !label.is_empty() && series.len() <= 8 {
                    style = style.label(label.clone());
                }
                ax.line(&x, &y, style).map_err(plot_err)?;
                ax.scatter(&x, &y, Style::points(color).size(7.0))
                    .map_err(plot_err)?;
            }
            for (rm, value, _) in &table.references {
                if rm == metric {
                    ax.hline(
                        *value,
                        Style::line(BLACK).dashed(6.0, 4.0).label("reference"),
                    )
                    .map_err(plot_err)?;
                }
            }
            ax.grid(true).legend(LegendPos::Best);
        }
        let path = dir.join(format!("plot_{}.png", crate::study::plain_name(parameter)));
        fig.save_png(&path).map_err(|e| StudyError::io(&path, e))?;
        written.push(path);
    }
    Ok(written)
}

/// The last part of a path, for legends (`body.target.material.damage.k` → `damage.k`).
fn short(path: &str) -> String {
    let parts: Vec<&str> = path.split('.').collect();
    parts[parts.len().saturating_sub(2)..].join(".")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_for_legends_and_files() {
        assert_eq!(short("body.target.material.damage.k"), "damage.k");
        assert_eq!(short("seed"), "seed");
        assert_eq!(
            crate::study::plain_name("body.projectile.velocity[2]"),
            "body.projectile.velocity_2_"
        );
    }
}

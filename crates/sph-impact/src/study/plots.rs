//! The study's plots: for each parameter, `plot_<parameter>.png` with one panel per metric
//! against that parameter. Where its values are numbers, points that differ only in that
//! parameter are joined by a line (one colour per combination of the other parameters);
//! where they are not (a model's name, a placement's table), each point is a bar of its
//! own colour, its value in the legend. A reference value is a dashed black line. Only
//! finished points are drawn.

use crate::study::error::StudyError;
use crate::study::table::{PointStatus, StudyTable};
use sph_diagnostics::plot::{Axes, BLACK, Figure, LegendPos, PALETTE, PlotError, Scale, Style};
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
            written.push(categories(table, &done, k, dir)?);
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
        let fallback = format!("study: the metrics against {parameter}");
        let (mut fig, cols, rows) = panel_grid(table.metrics.len(), &table.description, fallback);
        for (m, metric) in table.metrics.iter().enumerate() {
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
            references(ax, table, metric)?;
        }
        written.push(save_plot(&fig, dir, parameter)?);
    }
    Ok(written)
}

/// The plot of parameter `k` whose values are not all numbers: per metric, a bar for each
/// finished point in `done` (at x = its position among them), labelled with the point's
/// number and its value of the parameter.
fn categories(
    table: &StudyTable,
    done: &[&crate::study::table::PointRow],
    k: usize,
    dir: &Path,
) -> Result<PathBuf, StudyError> {
    let fig = categories_figure(table, done, k)?;
    save_plot(&fig, dir, &table.parameters[k])
}

/// The figure of [`categories`].
fn categories_figure(
    table: &StudyTable,
    done: &[&crate::study::table::PointRow],
    k: usize,
) -> Result<Figure, StudyError> {
    let parameter = &table.parameters[k];
    let fallback = format!("study: the metrics for each {parameter}");
    let (mut fig, cols, rows) = panel_grid(table.metrics.len(), &table.description, fallback);
    for (m, metric) in table.metrics.iter().enumerate() {
        let ax = fig
            .panel(m / cols, m % cols, rows, cols)
            .map_err(plot_err)?;
        ax.title(metric.clone())
            .xlabel(format!("point ({})", short(parameter)))
            .ylabel(metric.clone());
        // A tick under each bar, labelled with its point's number (nice steps would
        // put fractional point numbers between the bars).
        let ticks: Vec<(f64, String)> = done
            .iter()
            .enumerate()
            .map(|(n, row)| (n as f64, row.index.to_string()))
            .collect();
        ax.xticks(&ticks).map_err(plot_err)?;
        for (n, row) in done.iter().enumerate() {
            let y = row.metrics[m];
            if !y.is_finite() {
                continue;
            }
            let x = n as f64;
            let mut style = Style::bars(PALETTE[n % PALETTE.len()]);
            // The legend in the first panel only: the others repeat its colours.
            if m == 0 {
                style = style.label(format!("{}: {}", row.index, legend_value(&row.values[k])));
            }
            ax.bars(&[x - 0.35, x + 0.35], &[y], style)
                .map_err(plot_err)?;
        }
        references(ax, table, metric)?;
    }
    Ok(fig)
}

/// The study's references of `metric` as dashed black lines; then the grid and legend.
fn references(ax: &mut Axes, table: &StudyTable, metric: &str) -> Result<(), StudyError> {
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
    Ok(())
}

/// A figure of `panels` panels, three to a row, titled `description` (`fallback` when it
/// is empty), with its columns and rows.
pub(crate) fn panel_grid(
    panels: usize,
    description: &str,
    fallback: String,
) -> (Figure, usize, usize) {
    let cols = panels.clamp(1, 3);
    let rows = panels.div_ceil(cols);
    let mut fig = Figure::new(520 * cols as u32, 420 * rows as u32);
    fig.title(if description.is_empty() {
        fallback
    } else {
        description.to_string()
    });
    (fig, cols, rows)
}

/// Saves `fig` as `dir/plot_<parameter>.png` and returns its path.
pub(crate) fn save_plot(fig: &Figure, dir: &Path, parameter: &str) -> Result<PathBuf, StudyError> {
    let path = dir.join(format!("plot_{}.png", crate::study::plain_name(parameter)));
    fig.save_png(&path).map_err(|e| StudyError::io(&path, e))?;
    Ok(path)
}

/// A plotting error as the study's.
pub(crate) fn plot_err(e: PlotError) -> StudyError {
    StudyError::failed(e.to_string())
}

/// A value in a legend: a table's `kind` (a placement's, a model's) when it has one,
/// else the value as the study's table writes it, cut to fit a panel.
fn legend_value(v: &serde_json::Value) -> String {
    match v.get("kind").or_else(|| v.get("model")) {
        Some(serde_json::Value::String(kind)) => abbreviated(kind),
        _ => abbreviated(&crate::study::table::json_cell(v)),
    }
}

/// `text` cut to at most 28 characters (an ellipsis ending the cut ones), for legends.
fn abbreviated(text: &str) -> String {
    const MAX: usize = 28;
    if text.chars().count() <= MAX {
        text.to_string()
    } else {
        let mut cut: String = text.chars().take(MAX - 1).collect();
        cut.push('…');
        cut
    }
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
    fn a_parameter_that_is_not_a_number_gets_a_bar_per_point() {
        let table = model_table();
        let dir = std::env::temp_dir().join(format!("sph-plots-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let written = write_plots(&table, &dir).unwrap();
        let names: Vec<String> = written
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            names,
            [
                "plot_body.projectile.material.strength.png",
                "plot_solver.n_target.png"
            ]
        );
        for p in &written {
            assert_eq!(&std::fs::read(p).unwrap()[1..4], b"PNG");
        }
        std::fs::remove_dir_all(dir).unwrap();
    }

    /// A study of the projectile's strength model (not a number) and n_target: points
    /// 0 and 2 finished, point 1 failed.
    fn model_table() -> StudyTable {
        use crate::study::table::PointRow;
        let row = |index: usize, model: &str, beta: f64, status| PointRow {
            index,
            values: vec![serde_json::json!(model), serde_json::json!(2.5)],
            status,
            metrics: vec![beta],
            errors: vec![],
            error: None,
            wall_time_s: None,
        };
        StudyTable {
            description: String::new(),
            parameters: vec![
                "body.projectile.material.strength".into(),
                "solver.n_target".into(),
            ],
            metrics: vec!["beta".into()],
            references: vec![("beta".into(), 2.51, "experiment".into())],
            rows: vec![
                row(0, "johnson-cook", 1.73, PointStatus::Done),
                row(1, "von-mises", f64::NAN, PointStatus::Failed),
                row(2, "steinberg-guinan", 1.72, PointStatus::Done),
            ],
        }
    }

    #[test]
    fn the_bars_of_points_are_ticked_with_their_numbers() {
        let table = model_table();
        let done: Vec<_> = table
            .rows
            .iter()
            .filter(|r| r.status == PointStatus::Done)
            .collect();
        let (_, report) = categories_figure(&table, &done, 0)
            .unwrap()
            .render()
            .unwrap();
        // One tick per finished point at its bar (x = 0 and 1), labelled with the
        // point's number, not its place (nor 0, 0.5, 1, as nice steps would have it).
        assert_eq!(report.panels[0].x_ticks, ["0", "2"]);
    }

    #[test]
    fn long_legend_values_are_cut_with_an_ellipsis() {
        assert_eq!(abbreviated("johnson-cook"), "johnson-cook");
        let long = "x".repeat(60);
        let cut = abbreviated(&long);
        assert_eq!(cut.chars().count(), 28);
        assert!(cut.ends_with('…'));
        let placement = serde_json::json!({"kind": "lattice", "spacing": 0.0005});
        assert_eq!(legend_value(&placement), "lattice");
        assert_eq!(
            legend_value(&serde_json::json!("steinberg-guinan")),
            "steinberg-guinan"
        );
        assert_eq!(
            legend_value(&serde_json::json!({"spacing": 0.5})),
            "{\"spacing\":0.5}"
        );
    }

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

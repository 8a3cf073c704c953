//! A fit's plots: for each free parameter, `plot_<parameter>.png` with one panel per
//! fitted metric, per derived metric and for the objective, each against that parameter
//! over the search's finished runs (points, the best run ringed in black), a target as a
//! dashed black line and a constraint's bounds as dotted ones. With several free
//! parameters a panel is the projection of the runs on one of them. A directory's plots
//! can be drawn again from its `fit.csv` alone ([`redraw_fit_plots`]).

use crate::study::axis::Spacing;
use crate::study::error::StudyError;
use crate::study::fit::{Evaluation, Fit, FitReport};
use crate::study::plots::{panel_grid, plot_err, save_plot};
use crate::study::table::PointStatus;
use sph_diagnostics::plot::{BLACK, LegendPos, PALETTE, Scale, Style};
use std::path::{Path, PathBuf};

/// Writes the plots into `dir` and returns their paths (none before a run has finished).
pub(crate) fn write_fit_plots(
    fit: &Fit,
    report: &FitReport,
    dir: &Path,
) -> Result<Vec<PathBuf>, StudyError> {
    let done: Vec<usize> = (0..report.runs.len())
        .filter(|&n| report.runs[n].status == PointStatus::Done)
        .collect();
    let mut written = Vec::new();
    if done.is_empty() {
        return Ok(written);
    }
    let fitted: Vec<_> = fit.fitted_targets().collect();
    // The panels: each fitted metric (its target), each derived one (its constraint's
    // bounds), the objective.
    let mut panels: Vec<(String, Vec<(f64, bool)>)> = fitted
        .iter()
        .map(|t| (t.column(), vec![(t.value, true)]))
        .collect();
    for d in &fit.study.derived {
        let bounds = fit
            .constraints
            .iter()
            .filter(|c| c.derived == d.name)
            .flat_map(|c| [c.min, c.max])
            .flatten()
            .map(|b| (b, false))
            .collect();
        panels.push((d.name.clone(), bounds));
    }
    panels.push(("objective".into(), Vec::new()));
    for (k, free) in fit.free.iter().enumerate() {
        let fallback = format!("fit: the runs against {}", free.path);
        let (mut fig, cols, rows) = panel_grid(panels.len(), &fit.study.description, fallback);
        for (m, (name, lines)) in panels.iter().enumerate() {
            let y_of = |n: usize| {
                let run = &report.runs[n];
                run.metrics.get(m).copied().unwrap_or(run.objective)
            };
            let (x, y): (Vec<f64>, Vec<f64>) = done
                .iter()
                .map(|&n| (report.runs[n].values[k], y_of(n)))
                .filter(|(_, y)| y.is_finite())
                .unzip();
            let ax = fig
                .panel(m / cols, m % cols, rows, cols)
                .map_err(plot_err)?;
            ax.title(name.clone())
                .xlabel(free.path.clone())
                .ylabel(name.clone());
            if free.scale == Spacing::Log {
                ax.xscale(Scale::Log);
            }
            ax.scatter(&x, &y, Style::points(PALETTE[0]).size(7.0).label("runs"))
                .map_err(plot_err)?;
            if let Some(b) = report.best {
                let (bx, by) = (report.runs[b].values[k], y_of(b));
                if by.is_finite() {
                    ax.scatter(&[bx], &[by], Style::points(BLACK).size(12.0).label("best"))
                        .map_err(plot_err)?;
                }
            }
            for (i, &(value, target)) in lines.iter().enumerate() {
                let style = if target {
                    Style::line(BLACK).dashed(6.0, 4.0).label("target")
                } else if i == 0 {
                    Style::line(BLACK).dashed(2.0, 3.0).label("constraint")
                } else {
                    Style::line(BLACK).dashed(2.0, 3.0)
                };
                ax.hline(value, style).map_err(plot_err)?;
            }
            ax.grid(true).legend(LegendPos::Best);
        }
        written.push(save_plot(&fig, dir, &free.path)?);
    }
    Ok(written)
}

/// Draws the plots of `fit` again from `dir/fit.csv`, without running anything: for a
/// fit directory that the search can no longer replay (made before a change of the fit
/// file or of the program). The file's columns must be the fit's (run, the free
/// parameters, status, the fitted and derived metrics, objective); the best run is the
/// finished one with the smallest objective.
pub fn redraw_fit_plots(fit: &Fit, dir: &Path) -> Result<Vec<PathBuf>, StudyError> {
    let path = dir.join("fit.csv");
    let text = std::fs::read_to_string(&path).map_err(|e| StudyError::io(&path, e))?;
    let mut lines = text.lines();
    let mut expected: Vec<String> = vec!["run".into()];
    expected.extend(fit.free.iter().map(|f| f.path.clone()));
    expected.push("status".into());
    expected.extend(fit.fitted_targets().map(|t| t.column()));
    expected.extend(fit.study.derived.iter().map(|d| d.name.clone()));
    expected.push("objective".into());
    let header = lines.next().unwrap_or_default();
    if header != expected.join(",") {
        return Err(StudyError::bad(format!(
            "{}: its columns are `{header}`, the fit's are `{}`: not this fit's runs",
            path.display(),
            expected.join(",")
        )));
    }
    let number = |cell: &str, line: usize| -> Result<f64, StudyError> {
        if cell.is_empty() {
            return Ok(f64::NAN);
        }
        cell.parse().map_err(|_| {
            StudyError::bad(format!(
                "{}:{line}: `{cell}` is not a number",
                path.display()
            ))
        })
    };
    let free = fit.free.len();
    let mut runs = Vec::new();
    for (k, line) in lines.enumerate() {
        let n = k + 2;
        let cells: Vec<&str> = line.split(',').collect();
        if cells.len() != expected.len() {
            return Err(StudyError::bad(format!(
                "{}:{n}: {} cells, the header has {}",
                path.display(),
                cells.len(),
                expected.len()
            )));
        }
        let status = match cells[1 + free] {
            "done" => PointStatus::Done,
            "failed" => PointStatus::Failed,
            "pending" => PointStatus::Pending,
            other => {
                return Err(StudyError::bad(format!(
                    "{}:{n}: status `{other}` is none of done, failed, pending",
                    path.display()
                )));
            }
        };
        let index = cells[0]
            .parse()
            .map_err(|_| StudyError::bad(format!("{}:{n}: run `{}`", path.display(), cells[0])))?;
        let values = cells[1..=free]
            .iter()
            .map(|c| number(c, n))
            .collect::<Result<Vec<f64>, _>>()?;
        let numbers = cells[2 + free..]
            .iter()
            .map(|c| number(c, n))
            .collect::<Result<Vec<f64>, _>>()?;
        let (metrics, objective) = numbers.split_at(numbers.len() - 1);
        runs.push(Evaluation {
            index,
            values,
            status,
            metrics: metrics.to_vec(),
            objective: objective[0],
        });
    }
    let best = (0..runs.len())
        .filter(|&n| runs[n].status == PointStatus::Done && runs[n].objective.is_finite())
        .min_by(|&a, &b| runs[a].objective.total_cmp(&runs[b].objective));
    let report = FitReport {
        runs,
        best,
        sensitivity: Vec::new(),
        ended: String::new(),
        hold_out: Vec::new(),
    };
    write_fit_plots(fit, &report, dir)
}

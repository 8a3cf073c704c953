//! The speed-vs-error study of the basalt impacts (docs/validation.md): reads the
//! `summary.json` of finished runs, prints each run's runtime and the error of crater
//! diameter, depth and β against paper Table 2, and plots |error| against wall time.
//!
//! ```text
//! cargo run --release -p sph-examples --example speed_vs_error -- \
//!     RUN_DIR... [--at T] [--plot docs/validation_speed_vs_error.png]
//! ```
//!
//! Each run's experiment is the Table 2 row at its impact speed (`impact_speed_m_s`).
//! Runs that ended at different times compare with `--at T` (seconds): the numbers are
//! then the last `history.csv` row at or before T, and the runtime to T is the run's wall
//! time prorated by its steps to T (the particle count of a run does not change, so its
//! cost per step is nearly constant).
//!
//! The plot joins the runs of one geometry (RZ, 3-D) in order of wall time, one line per
//! number and geometry, so that grids of one geometry read as a series and a run of the
//! other geometry stands beside them (RZ discs on solid lines, 3-D squares on dashed).

use clap::Parser;
use sph_diagnostics::Figure;
use sph_diagnostics::plot::{BLUE, GREEN, GREY, LegendPos, Marker, RED, Scale, Style};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(Parser, Debug)]
#[command(about = "Runtime against the error of Ø, depth and β for finished basalt runs")]
struct Args {
    /// Run directories, each with a summary.json.
    #[arg(required = true)]
    runs: Vec<PathBuf>,
    /// Compare at this simulated time (s) from each run's history.csv instead of at its
    /// end; every run must have reached it.
    #[arg(long)]
    at: Option<f64>,
    /// Where to write the plot (PNG).
    #[arg(long, default_value = "speed_vs_error.png")]
    plot: PathBuf,
}

/// What the study needs of one run's summary.
struct Run {
    name: String,
    speed: &'static str,
    geometry: String,
    particles: f64,
    wall: f64,
    end_time: f64,
    /// Signed relative errors of Ø, depth, β.
    errors: [f64; 3],
}

/// The plot's series a run belongs to: "RZ", or "3-D" for the full and quarter models.
fn family_of(r: &Run) -> &'static str {
    if r.geometry == "rz" { "RZ" } else { "3-D" }
}

fn read(dir: &Path, at: Option<f64>) -> Result<Run, String> {
    let path = dir.join("summary.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let json: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let num = |key: &str| {
        json.get(key)
            .and_then(serde_json::Value::as_f64)
            .ok_or_else(|| format!("{}: no number `{key}`", path.display()))
    };
    let u = num("impact_speed_m_s")?;
    let e = sph_examples::experiment_at(u)
        .ok_or_else(|| format!("{}: impact speed {u} m/s is not in Table 2", path.display()))?;
    let rel = |x: f64, r: f64| x / r - 1.0;
    let (end_time, wall, diameter, depth, beta) = match at {
        None => (
            num("end_time_s")?,
            num("wall_time_s")?,
            num("crater_diameter_m")?,
            num("crater_depth_m")?,
            num("beta")?,
        ),
        Some(t) => {
            let path = dir.join("history.csv");
            let text =
                std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
            let row = sph_examples::history_row_at(&text, t)
                .map_err(|e| format!("{}: {e}", path.display()))?;
            let wall = num("wall_time_s")? * row.step / num("steps")?;
            (t, wall, row.crater_diameter, row.crater_depth, row.beta)
        }
    };
    Ok(Run {
        name: dir.display().to_string(),
        speed: e.speed,
        geometry: json["geometry"].as_str().unwrap_or("?").to_owned(),
        particles: num("particles")?,
        wall,
        end_time,
        errors: [
            rel(diameter, e.diameter),
            rel(depth, e.depth),
            rel(beta, e.beta),
        ],
    })
}

fn main() -> ExitCode {
    let args = Args::parse();
    let mut runs = Vec::new();
    for dir in &args.runs {
        match read(dir, args.at) {
            Ok(r) => runs.push(r),
            Err(m) => {
                eprintln!("error: {m}");
                return ExitCode::FAILURE;
            }
        }
    }
    runs.sort_by(|a, b| a.wall.total_cmp(&b.wall));
    let (when, wall) = match args.at {
        None => ("t_end (µs)", "wall (s)"),
        Some(_) => ("at (µs)", "wall to then (s, prorated by steps)"),
    };
    println!(
        "| run | km/s | geometry | particles | {when} | {wall} | Ø error | depth error | β error |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for r in &runs {
        let [d, h, b] = r.errors.map(|x| format!("{:+.1} %", 100.0 * x));
        println!(
            "| {} | {} | {} | {} | {:.0} | {:.0} | {d} | {h} | {b} |",
            r.name,
            r.speed,
            r.geometry,
            r.particles,
            r.end_time * 1e6,
            r.wall
        );
    }
    if runs.iter().any(|r| r.speed != runs[0].speed) {
        println!("no plot: the runs are of different speeds (the plot compares one speed)");
        return ExitCode::SUCCESS;
    }
    let mut fig = Figure::new(1000, 700);
    fig.title(format!(
        "Basalt impact at {} km/s: error against Table 2 vs runtime",
        runs[0].speed
    ));
    let plotted = (|| {
        let ax = fig.panel(0, 0, 1, 1)?;
        ax.xlabel(match args.at {
            None => "wall time (s)".to_owned(),
            Some(t) => format!("wall time to {:.0} µs (s)", t * 1e6),
        })
        .ylabel("|error| (%)")
        .xscale(Scale::Log)
        .grid(true);
        // Headroom above the largest error keeps the legend (upper right) off the points.
        let top = runs
            .iter()
            .flat_map(|r| r.errors)
            .map(|e| 100.0 * e.abs())
            .filter(|e| e.is_finite())
            .fold(20.0, f64::max);
        ax.ylim(0.0, 1.6 * top)?.legend(LegendPos::UpperRight);
        for (family, marker, dashed) in
            [("RZ", Marker::Circle, false), ("3-D", Marker::Square, true)]
        {
            let members: Vec<&Run> = runs.iter().filter(|r| family_of(r) == family).collect();
            if members.is_empty() {
                continue;
            }
            let wall: Vec<f64> = members.iter().map(|r| r.wall).collect();
            for (k, (name, color)) in [("diameter", BLUE), ("depth", RED), ("beta", GREEN)]
                .into_iter()
                .enumerate()
            {
                let err: Vec<f64> = members.iter().map(|r| 100.0 * r.errors[k].abs()).collect();
                let line = Style::line(color).label(format!("{name} ({family})"));
                let line = if dashed { line.dashed(4.0, 3.0) } else { line };
                ax.line(&wall, &err, line)?;
                ax.scatter(&wall, &err, Style::points(color).marker(marker).size(9.0))?;
            }
        }
        ax.hline(
            20.0,
            Style::line(GREY).dashed(6.0, 4.0).label("20 % target"),
        )?;
        fig.save_png(&args.plot)
    })();
    match plotted {
        Ok(_) => {
            println!("plot: {}", args.plot.display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {}: {e}", args.plot.display());
            ExitCode::FAILURE
        }
    }
}

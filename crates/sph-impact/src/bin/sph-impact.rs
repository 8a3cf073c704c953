//! The `sph-impact` command-line program.

use clap::{Parser, Subcommand};
use sph_impact::verify::Problem;
use std::path::PathBuf;
use std::process::ExitCode;

/// Riemann-SPH for hypervelocity impact.
#[derive(Parser, Debug)]
#[command(name = "sph-impact", version, about)]
struct Cli {
    /// Worker threads (default: all cores).
    #[arg(long, global = true)]
    threads: Option<usize>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run one verification problem and compare with its exact solution.
    Verify {
        /// sod, toro123, toro3, noh-planar, noh-cylindrical, noh-spherical, sedov-2d, sedov-3d,
        /// elastic-bar, hel-impact, spin, contact
        problem: Problem,
        /// Resolution (problem-specific: see docs/verification.md).
        #[arg(long)]
        resolution: Option<usize>,
        /// Scheme overrides as JSON, e.g. '{"limiter":"minmod","cfl":0.2}' (fields of
        /// SchemeConfig; unknown fields are rejected).
        #[arg(long)]
        scheme: Option<String>,
        /// Write profile.csv, metrics.json and plot.png into this directory.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Print the metrics as one JSON object.
        #[arg(long)]
        json: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(t) = cli.threads
        && let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build_global()
    {
        eprintln!("error: cannot start {t} threads: {e}");
        return ExitCode::from(2);
    }
    match cli.command {
        Command::Verify {
            problem,
            resolution,
            scheme,
            out,
            json,
        } => match sph_impact::cli::verify(
            problem,
            resolution,
            scheme.as_deref(),
            out.as_deref(),
            json,
        ) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
    }
}

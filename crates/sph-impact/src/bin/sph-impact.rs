//! The `sph-impact` command-line program.
//!
//! Exit codes: 0 ok, 1 a failed run, 2 bad input (a bad scene, option or argument);
//! every failure prints one line `error: …` on standard error.

use clap::{Parser, Subcommand};
use sph_impact::cli::CommandError;
use sph_impact::run::RunOptions;
use sph_impact::verify::{Problem, SedovDeposit};
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
    /// Run an impact scene (TOML; docs/scenes.md) and write snapshots, history,
    /// summary and plots into the run directory.
    Run {
        /// The scene file.
        scene: PathBuf,
        /// Run directory (default: the scene's [output] directory, else out/<scene name>).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Simulated end time in seconds, instead of the scene's.
        #[arg(long)]
        end_time: Option<f64>,
        /// Divide every particle spacing by this (2 = twice as fine, 0.5 = twice as coarse).
        #[arg(long, default_value_t = 1.0)]
        resolution_scale: f64,
        /// No progress bar and no result lines (for scripts).
        #[arg(long)]
        quiet: bool,
        /// Write a checkpoint (checkpoint.cbor in the run directory) at every snapshot
        /// before the end, so that a stopped run can be resumed.
        #[arg(long)]
        checkpoint: bool,
        /// Continue the run in the run directory from its checkpoint (same scene and
        /// --resolution-scale; --end-time may be later), instead of starting at t = 0.
        #[arg(long)]
        resume: bool,
    },
    /// Validate a scene, place its bodies, and estimate the run's first time step, steps,
    /// runtime and memory.
    Check {
        /// The scene file.
        scene: PathBuf,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
        /// Divide every particle spacing by this.
        #[arg(long, default_value_t = 1.0)]
        resolution_scale: f64,
        /// Simulated end time in seconds, instead of the scene's.
        #[arg(long)]
        end_time: Option<f64>,
    },
    /// List the built-in materials and their parameters.
    Materials {
        /// Print one JSON array with every parameter and source.
        #[arg(long)]
        json: bool,
    },
    /// Run one verification problem and compare with its exact solution.
    Verify {
        /// sod, toro123, toro3, noh-planar, noh-cylindrical, noh-spherical, sedov-2d, sedov-3d,
        /// elastic-bar, hel-impact, spin, contact, plate, rings, taylor, tensile-bar
        problem: Problem,
        /// Resolution (problem-specific: see docs/verification.md).
        #[arg(long)]
        resolution: Option<usize>,
        /// Scheme overrides as JSON, e.g. '{"limiter":"minmod","cfl":0.2}' (fields of
        /// SchemeConfig; unknown fields are rejected).
        #[arg(long)]
        scheme: Option<String>,
        /// Write profile.csv, metrics.json, plot.png (and history.csv where the problem samples
        /// quantities in time) into this directory.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Print the metrics as one JSON object.
        #[arg(long)]
        json: bool,
        /// Geometry: `3d` (the problem's own), `rz` (axisymmetric: noh-planar,
        /// noh-spherical, sedov-3d, taylor, hel-impact, contact), `plane` (noh-planar
        /// only: the RZ run's column in plane 2-D, for comparison) or `rings` (taylor
        /// only: 3-D with the rod placed as RZ rings revolved about the axis).
        #[arg(long, default_value = "3d", value_parser = ["3d", "rz", "plane", "rings"])]
        geometry: String,
        /// Sedov only: how the blast energy goes into the centre, `top-hat` (default:
        /// equal specific energy within one support radius) or `kernel` (kernel-weighted).
        #[arg(long)]
        deposit: Option<SedovDeposit>,
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
        return ExitCode::from(CommandError::BAD_INPUT);
    }
    let result = match cli.command {
        Command::Run {
            scene,
            out,
            end_time,
            resolution_scale,
            quiet,
            checkpoint,
            resume,
        } => {
            let options = RunOptions {
                threads: cli.threads,
                end_time,
                resolution_scale,
                quiet,
                checkpoint,
                resume,
            };
            sph_impact::cli::run_scene(&scene, out.as_deref(), &options).map(|_| ())
        }
        Command::Check {
            scene,
            json,
            resolution_scale,
            end_time,
        } => sph_impact::cli::check_scene(&scene, json, cli.threads, resolution_scale, end_time)
            .map(|_| ()),
        Command::Materials { json } => sph_impact::cli::materials(json),
        Command::Verify {
            problem,
            resolution,
            scheme,
            out,
            json,
            geometry,
            deposit,
        } => sph_impact::cli::verify(
            problem,
            resolution,
            scheme.as_deref(),
            out.as_deref(),
            json,
            match geometry.as_str() {
                "rz" => sph_impact::cli::VerifyGeometry::Rz,
                "plane" => sph_impact::cli::VerifyGeometry::Plane,
                "rings" => sph_impact::cli::VerifyGeometry::Rings,
                _ => sph_impact::cli::VerifyGeometry::Own,
            },
            deposit,
        )
        .map_err(CommandError::failed),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.code)
        }
    }
}

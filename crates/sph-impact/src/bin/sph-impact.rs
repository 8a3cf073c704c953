//! The `sph-impact` command-line program.
//!
//! Exit codes: 0 ok, 1 a failed run, 2 bad input (a bad scene, option or argument),
//! 130 a run interrupted by SIGINT or SIGTERM (after writing a checkpoint); every
//! failure prints one line `error: …` on standard error.

use clap::{Parser, Subcommand};
use sph_impact::cli::CommandError;
use sph_impact::run::{RunOptions, StopFlag};
use sph_impact::solver::Ranks;
use sph_impact::verify::{Problem, SedovDeposit};
use std::path::PathBuf;
use std::process::ExitCode;

/// Riemann-SPH for hypervelocity impact.
#[derive(Parser, Debug)]
#[command(name = "sph-impact", version, about)]
struct Cli {
    /// Worker threads, 1 to 1024 (default: all cores).
    #[arg(long, global = true)]
    threads: Option<usize>,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run an impact scene (TOML; docs/scenes.md) and write snapshots, history,
    /// summary and plots into the run directory.
    // A negative number is an option's value (refused with its own message), not a flag.
    #[command(allow_negative_numbers = true)]
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
        /// Write a checkpoint (into checkpoints/ in the run directory) at every snapshot
        /// before the end, so that a stopped run can be resumed. SIGINT or SIGTERM writes
        /// one in any case.
        #[arg(long)]
        checkpoint: bool,
        /// How many checkpoints to keep (the newest).
        #[arg(long, default_value_t = 3)]
        keep_checkpoints: usize,
        /// Continue the run in the run directory from its newest checkpoint (same scene
        /// and --resolution-scale; --end-time may be later), instead of starting at t = 0.
        #[arg(long)]
        resume: bool,
        /// With --resume: continue from this checkpoint (a path, or a file name in
        /// checkpoints/) instead of the newest.
        #[arg(long, requires = "resume")]
        resume_from: Option<PathBuf>,
        /// Clear the run directory of a previous run's files before starting (without it,
        /// a directory holding them is refused).
        #[arg(long, conflicts_with = "resume")]
        overwrite: bool,
    },
    /// Validate a scene, place its bodies, and estimate the run's first time step, steps,
    /// runtime and memory.
    // A negative number is an option's value (refused with its own message), not a flag.
    #[command(allow_negative_numbers = true)]
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
    /// Run a parameter study (TOML; docs/studies.md): the base scene at every
    /// combination of the parameters' values, points side by side, resumable; writes
    /// study.csv, study.json and study.md into the study directory.
    // A negative number is an option's value (refused with its own message), not a flag.
    #[command(allow_negative_numbers = true)]
    Study {
        /// The study file.
        study: PathBuf,
        /// Study directory (default: out/<study file stem>). Run again with the same
        /// directory to continue a stopped study.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Points run at a time (default: the cores divided by the study's
        /// threads_per_run).
        #[arg(long)]
        jobs: Option<usize>,
        /// Run again the points that failed before.
        #[arg(long)]
        retry_failed: bool,
        /// Run at most this many points now, then stop (e.g. within a batch job's limit).
        #[arg(long)]
        max_points: Option<usize>,
        /// Run only point K (from 0), without writing the table: one task of a job array.
        #[arg(long, value_name = "K", conflicts_with_all = ["max_points", "collect", "emit"])]
        point: Option<usize>,
        /// Write the table from the points already run, without running any.
        #[arg(long, conflicts_with_all = ["max_points", "emit"])]
        collect: bool,
        /// Write the points' scenes and a job-array script into the study directory
        /// instead of running: `slurm` (study.sbatch).
        #[arg(long, value_parser = ["slurm"])]
        emit: Option<String>,
        /// Run every point at this resolution scale instead of the file's
        /// `resolution_scale` (e.g. 1 for the study's A_res 0.5 mm). Give it again to
        /// continue the study directory: one made at another scale is refused.
        #[arg(long, value_name = "S")]
        resolution_scale: Option<f64>,
        /// No progress lines and no table on standard output.
        #[arg(long)]
        quiet: bool,
    },
    /// Fit free parameters of a scene to target metrics under constraints (TOML;
    /// docs/studies.md, "Fits"): Nelder–Mead over runs, resumable; writes fit.csv,
    /// fit.json and fit.md.
    // A negative number is an option's value (refused with its own message), not a flag.
    #[command(allow_negative_numbers = true)]
    Fit {
        /// The fit file.
        fit: PathBuf,
        /// Fit directory (default: out/<fit file stem>). Run again with the same
        /// directory to continue a stopped fit, or one given a larger budget.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Runs at a time: the fitted cases of one point (and the hold-out cases) run side
        /// by side, each with the fit's `threads_per_run` (default 1).
        #[arg(long, default_value_t = 1)]
        jobs: usize,
        /// Run the fit's scene and its cases at this resolution scale instead of the
        /// file's `resolution_scale`. Give it again to continue the fit directory: one
        /// made at another scale is refused.
        #[arg(long, value_name = "S")]
        resolution_scale: Option<f64>,
        /// No table on standard output.
        #[arg(long)]
        quiet: bool,
        /// Only draw the plots again from the directory's fit.csv, without running (for
        /// a directory the search can no longer replay).
        #[arg(long)]
        plots: bool,
    },
    /// List the built-in materials and their parameters.
    Materials {
        /// Print one JSON array with every parameter and source.
        #[arg(long)]
        json: bool,
    },
    /// Run one verification problem and compare with its exact solution.
    // A negative number is an option's value (refused with its own message), not a flag.
    #[command(allow_negative_numbers = true)]
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
    if let Err(message) = processor_supported() {
        return finish(Err(CommandError::failed(message)));
    }
    keep_freed_memory();
    let cli = Cli::parse();
    // With the `mpi` feature every rank runs the command (`mpirun -n N sph-impact run
    // SCENE`; docs/mpi.md); an error on one stops them all.
    #[cfg(feature = "mpi")]
    let result = sph_impact::mpi_world::over_world(|ranks| command(cli, ranks));
    #[cfg(not(feature = "mpi"))]
    let result = command(cli, &sph_impact::solver::OneRank);
    finish(result)
}

/// Refuses, with a message, a processor that lacks the instructions this build was
/// compiled for: the workspace builds x86-64 code for the x86-64-v3 level
/// (.cargo/config.toml), which would otherwise stop with "illegal instruction" somewhere
/// in the run. Checked first in `main`, before any floating-point work.
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
fn processor_supported() -> Result<(), String> {
    if std::arch::is_x86_feature_detected!("avx2")
        && std::arch::is_x86_feature_detected!("fma")
        && std::arch::is_x86_feature_detected!("bmi2")
    {
        Ok(())
    } else {
        Err(
            "this processor lacks AVX2, FMA or BMI2, which this build of sph-impact \
             uses (x86-64-v3, .cargo/config.toml); build it for the baseline with \
             `RUSTFLAGS= cargo build --release`"
                .to_string(),
        )
    }
}

/// A build for the baseline (or another architecture) runs on any processor of it.
#[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
fn processor_supported() -> Result<(), String> {
    Ok(())
}

/// Tells glibc's allocator to keep the memory a stage frees for the next stage instead
/// of handing it back to the kernel.
///
/// Every stage of a step allocates its arrays (the extended state, the neighbour lists,
/// the gradients and rates) and frees them at its end. With glibc's defaults the freed
/// top of the heap above 128 kB goes back to the kernel (`madvise`, or `munmap` for
/// blocks above the mmap threshold), and the next stage page-faults it in again, zeroed:
/// on the RZ scene at 0.5 mm about 470 faults (1.9 MB) a stage, 8 % of its run time on
/// one thread (docs/performance.md, "Freed memory kept"). Blocks up to 32 MiB (glibc's
/// largest mmap threshold) then come from the heap and its top is never trimmed; the
/// peak resident size is unchanged, and the memory is returned when the program ends.
/// No effect on results. Other C libraries and systems keep their allocator's defaults.
#[cfg(all(target_os = "linux", target_env = "gnu"))]
#[allow(unsafe_code)]
fn keep_freed_memory() {
    // SAFETY: mallopt only sets two of the allocator's parameters. It is called first
    // in main, before any other thread exists, and both values are within the ranges
    // glibc documents (it refuses, returning 0, what is not: the defaults then stay,
    // which is harmless).
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, 32 << 20);
        libc::mallopt(libc::M_TRIM_THRESHOLD, i32::MAX);
    }
}

/// Other systems keep their allocator's defaults.
#[cfg(not(all(target_os = "linux", target_env = "gnu")))]
fn keep_freed_memory() {}

/// The command of `cli`, as rank `ranks.rank()` of `ranks.size()`.
fn command(cli: Cli, ranks: &dyn Ranks) -> Result<(), CommandError> {
    // Checked before the pool is built: rayon takes 0 for "all cores" and would try to
    // start any number of threads.
    if let Some(t) = cli.threads {
        sph_impact::cli::check_threads(t)?;
    }
    if let Some(t) = cli.threads
        && let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(t)
            .build_global()
    {
        return Err(CommandError::bad_input(format!(
            "cannot start {t} threads: {e}"
        )));
    }
    let Some(command) = cli.command else {
        return Err(CommandError::bad_input(
            "no command given: run, check, study, fit, materials or verify (`sph-impact --help` \
             says more)",
        ));
    };
    if ranks.size() > 1 && !matches!(command, Command::Run { .. }) {
        return Err(CommandError::bad_input(format!(
            "only `run` runs over several MPI ranks ({} here): run the others on one",
            ranks.size()
        )));
    }
    match command {
        Command::Run {
            scene,
            out,
            end_time,
            resolution_scale,
            quiet,
            checkpoint,
            keep_checkpoints,
            resume,
            resume_from,
            overwrite,
        } => {
            let options = RunOptions {
                threads: cli.threads,
                end_time,
                resolution_scale,
                quiet,
                checkpoint,
                keep_checkpoints,
                resume,
                resume_from,
                overwrite,
                stop: StopFlag::new(),
            };
            // SIGINT/SIGTERM finish the step, write a checkpoint and a partial summary,
            // and exit with 130 (on rank 0, which tells the other ranks to end).
            catch_signals(&options.stop)?;
            if ranks.rank() == 0 {
                sph_impact::cli::run_scene_over(&scene, out.as_deref(), &options, ranks).map(|_| ())
            } else {
                sph_impact::cli::follow_scene(&scene, out.as_deref(), &options, ranks)
            }
        }
        Command::Check {
            scene,
            json,
            resolution_scale,
            end_time,
        } => sph_impact::cli::check_scene(&scene, json, cli.threads, resolution_scale, end_time)
            .map(|_| ()),
        Command::Study {
            study,
            out,
            jobs,
            retry_failed,
            max_points,
            point,
            collect,
            emit,
            resolution_scale,
            quiet,
        } => {
            if emit.is_some() {
                return sph_impact::cli::study_emit_slurm(
                    &study,
                    out.as_deref(),
                    resolution_scale,
                    quiet,
                );
            }
            let options = sph_impact::study::StudyOptions {
                // 0: the cores divided by the study's threads per run (cli::study).
                jobs: jobs.unwrap_or(0),
                retry_failed,
                max_points: if collect { Some(0) } else { max_points },
                only: point,
                quiet,
                stop: StopFlag::new(),
            };
            catch_signals(&options.stop)?;
            sph_impact::cli::study(&study, out.as_deref(), resolution_scale, &options).map(|_| ())
        }
        Command::Fit {
            fit,
            out,
            resolution_scale,
            plots: true,
            ..
        } => sph_impact::cli::fit_plots(&fit, out.as_deref(), resolution_scale),
        Command::Fit {
            fit,
            out,
            jobs,
            resolution_scale,
            quiet,
            plots: false,
        } => {
            let options = sph_impact::study::StudyOptions {
                jobs,
                quiet,
                ..Default::default()
            };
            catch_signals(&options.stop)?;
            sph_impact::cli::fit(&fit, out.as_deref(), resolution_scale, &options).map(|_| ())
        }
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
        ),
    }
}

/// SIGINT and SIGTERM raise `stop` (the run, or each point of a study or fit, ends at a
/// checkpoint).
fn catch_signals(stop: &StopFlag) -> Result<(), CommandError> {
    stop.on_signals()
        .map_err(|e| CommandError::failed(format!("cannot catch SIGINT/SIGTERM: {e}")))
}

/// The exit code of a command's result, with its error printed.
fn finish(result: Result<(), CommandError>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // Messages quote names, keys and paths from the input: escaped, they cannot
            // drive the terminal.
            eprintln!("error: {}", sph_impact::input::printable(&e.to_string()));
            ExitCode::from(e.code)
        }
    }
}

//! The bundled basalt-impact example (paper §6): a 6 mm aluminium 2024 sphere into a
//! Ø123.3 × 123.3 mm basalt cylinder, run end to end and compared with the experiment
//! (paper Table 2).
//!
//! By default it runs the 3.9 km/s case in axisymmetric (RZ) geometry from the bundled
//! scene `examples/scenes/basalt_3.9kms_rz.toml` (the same bodies and settings as the 3-D
//! `basalt_3.9kms.toml`, plus free flight of the ejecta above 20 mm), at resolution scale
//! 0.5 (A_res = 1 mm instead of the study's 0.5 mm) to the study's 400 µs: 458 s on two
//! shared threads (docs/validation.md, "Free flight"). At the end it prints crater
//! diameter, bowl diameter, depth and β beside the experiment's values.
//!
//! ```text
//! cargo run --release -p sph-examples --example basalt_impact -- \
//!     [--speed 3.9] [--resolution-scale F] [--end-time T] [--3d] [--out DIR] [--threads N]
//!     [--checkpoint] [--resume | --overwrite]
//! ```
//!
//! A second run into the same directory is refused unless `--resume` continues the first
//! (from its checkpoint) or `--overwrite` clears it. Ctrl-C finishes the step, writes a
//! checkpoint and exits with 130; `--resume` then continues the run.
//!
//! `--resolution-scale 1` is the study's resolution (A_res = 0.5 mm; about four times the
//! cost of the default in RZ). `--3d` runs the 3-D scene instead (coarse by default:
//! resolution scale 0.25 to 40 µs; the study's resolution takes days).

use clap::Parser;
use sph_impact::run::{RunOptions, RunSummary, run};
use sph_impact::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Run the study's Al-sphere-into-basalt impact and compare it with the experiment.
#[derive(Parser, Debug)]
struct Args {
    /// Impact speed in km/s: one of the study's three experiments.
    #[arg(long, default_value = "3.9", value_parser = ["2.3", "3.47", "3.9"])]
    speed: String,
    /// Particle spacings are divided by this (default 0.5 in RZ, 0.25 in 3-D; 1 is the
    /// study's A_res = 0.5 mm).
    #[arg(long)]
    resolution_scale: Option<f64>,
    /// Simulated end time in seconds (default: the scene's 400 µs in RZ, 40 µs in 3-D).
    #[arg(long)]
    end_time: Option<f64>,
    /// Run the 3-D scene instead of the axisymmetric (RZ) one.
    #[arg(long = "3d")]
    three_d: bool,
    /// Run directory (default out/basalt_impact_<speed>, with `_3d` for a 3-D run).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long)]
    threads: Option<usize>,
    /// Write a checkpoint at every snapshot (docs/scenes.md, "Checkpoints").
    #[arg(long)]
    checkpoint: bool,
    /// Continue the run in the run directory from its newest checkpoint.
    #[arg(long)]
    resume: bool,
    /// Clear the run directory of a previous run first.
    #[arg(long, conflicts_with = "resume")]
    overwrite: bool,
}

/// The bundled scene file of a speed.
fn scene_path(speed: &str, three_d: bool) -> PathBuf {
    let suffix = if three_d { "" } else { "_rz" };
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(format!("basalt_{speed}kms{suffix}.toml"))
}

/// A time in µs, to the precision it needs.
fn micro(t: f64) -> String {
    let us = t * 1e6;
    if us >= 10.0 {
        format!("{us:.0} µs")
    } else {
        format!("{us:.3} µs")
    }
}

/// "+12.3 %" for x against the reference.
fn relative(x: f64, reference: f64) -> String {
    if x.is_finite() {
        format!("{:+.1} %", 100.0 * (x / reference - 1.0))
    } else {
        "—".into()
    }
}

/// The comparison with Table 2.
fn print_comparison(s: &RunSummary, e: &sph_examples::Experiment) {
    println!(
        "\nresult at t = {} against paper Table 2 ({} km/s):",
        micro(s.end_time_s),
        e.speed
    );
    println!(
        "  {:<22} {:>10} {:>11} {:>10} {:>14}",
        "", "this run", "experiment", "error", "study's sim"
    );
    let mm = |x: f64| format!("{:.1} mm", x * 1e3);
    // A size of this run with nothing in Table 2 to compare it with.
    let run_only = |name, x: f64| (name, mm(x), "—".into(), "—".into(), "—".into());
    let rows = [
        (
            "crater diameter",
            mm(s.crater_diameter_m),
            mm(e.diameter),
            relative(s.crater_diameter_m, e.diameter),
            mm(e.study.0),
        ),
        run_only("  without spall", s.crater_diameter_removed_m),
        run_only("bowl diameter", s.bowl_diameter_m),
        (
            "crater depth",
            mm(s.crater_depth_m),
            mm(e.depth),
            relative(s.crater_depth_m, e.depth),
            mm(e.study.1),
        ),
        (
            // docs/diagnostics.md §4.4: the volume fraction averaged over a disc about
            // the axis, not one bin.
            "  on the axis",
            mm(s.crater_axis_depth_m),
            mm(e.depth),
            relative(s.crater_axis_depth_m, e.depth),
            "—".into(),
        ),
        (
            "β (from the ejecta)",
            format!("{:.3}", s.beta),
            format!("{:.2}", e.beta),
            relative(s.beta, e.beta),
            format!("{:.2}", e.study.2),
        ),
    ];
    for (name, run, exp, err, study) in rows {
        println!("  {name:<22} {run:>10} {exp:>11} {err:>10} {study:>14}");
    }
    println!(
        "  (β from the target's momentum {:.3}; as the experiment's pendulum sees it, with \
         escaping projectile debris, {:.3}; ejecta {:.3e} kg; energy change {:.1e})",
        s.beta_target, s.beta_pendulum, s.ejecta_mass_kg, s.energy_error
    );
    println!(
        "  (β moved by {} over the second half of the run; the study reads it once settled)",
        relative(1.0 + s.beta_change_last_half, 1.0)
    );
    // docs/diagnostics.md §3.1: equal to β once every ejectum has left the target's reach.
    println!(
        "  (β from the ejecta out of the target's reach {:.3}: {} of β still touches the target)",
        s.beta_detached,
        relative(1.0 + (s.beta - s.beta_detached) / s.beta, 1.0)
    );
}

fn main() -> ExitCode {
    let args = Args::parse();
    let experiment = sph_examples::TABLE_2
        .iter()
        .find(|e| e.speed == args.speed)
        .expect("clap accepts only the three speeds");
    let path = scene_path(&args.speed, args.three_d);
    let scene = match Scene::from_toml_file(&path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let (default_scale, default_end) = if args.three_d {
        (0.25, 40e-6)
    } else {
        (0.5, scene.end_time)
    };
    let scale = args.resolution_scale.unwrap_or(default_scale);
    let end_time = args.end_time.unwrap_or(default_end);
    let out = args.out.clone().unwrap_or_else(|| {
        let suffix = if args.three_d { "_3d" } else { "" };
        PathBuf::from(format!("out/basalt_impact_{}{suffix}", args.speed))
    });
    let threads = args.threads.unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
    });

    println!(
        "Basalt impact (paper §6): Al 2024 sphere Ø6 mm at {} km/s into basalt Ø123.3 × 123.3 mm",
        args.speed
    );
    println!("scene             {}", path.display());
    println!(
        "geometry          {}",
        if args.three_d {
            "3-D"
        } else {
            "axisymmetric (RZ): particles are rings about the impact axis"
        }
    );
    let a_res = scene
        .bodies
        .iter()
        .map(|b| b.placement.finest_spacing())
        .fold(f64::INFINITY, f64::min);
    println!(
        "resolution scale  {scale}{} → finest spacing {:.3} mm (the study: 0.5 mm)",
        if args.resolution_scale.is_none() {
            " (default)"
        } else {
            ""
        },
        a_res / scale * 1e3
    );
    println!(
        "end time          {}{} (the study: 400 µs)",
        micro(end_time),
        if args.end_time.is_none() {
            " (default)"
        } else {
            ""
        }
    );
    let s = scene.scheme();
    println!(
        "scheme            {:?}, n_target {}, CFL {}, artificial stress ε = {}",
        s.kernel, s.n_target, s.cfl, s.artificial_stress.epsilon
    );
    match scene.check_report(scale, threads, Some(end_time)) {
        Ok(r) => println!(
            "particles         {} ({}); estimated ≥ {:.0} steps, ≥ {:.1} min on {} thread(s)",
            r.particles,
            r.bodies
                .iter()
                .map(|b| format!("{} {}", b.name, b.particles))
                .collect::<Vec<_>>()
                .join(", "),
            r.steps,
            r.runtime_s / 60.0,
            threads
        ),
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    println!("run directory     {}\n", out.display());

    let options = RunOptions {
        threads: Some(threads),
        end_time: Some(end_time),
        resolution_scale: scale,
        checkpoint: args.checkpoint,
        resume: args.resume,
        overwrite: args.overwrite,
        ..RunOptions::default()
    };
    if let Err(e) = options.stop.on_signals() {
        eprintln!("error: cannot catch SIGINT/SIGTERM: {e}");
        return ExitCode::from(1);
    }
    match run(&scene, &out, &options) {
        Ok(summary) => {
            print_comparison(&summary, experiment);
            println!(
                "\ncost: {} particles, {} steps, {:.0} s wall, {:.3e} particle-steps/s on {} thread(s)",
                summary.particles,
                summary.steps,
                summary.wall_time_s,
                summary.particle_steps_per_s,
                summary.threads
            );
            if end_time < 400e-6 {
                println!(
                    "(the crater and β still grow before 400 µs: compare at the study's end time)"
                );
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(if e.is_interrupted() {
                130
            } else if e.is_bad_input() {
                2
            } else {
                1
            })
        }
    }
}

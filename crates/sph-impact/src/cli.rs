//! What the command-line subcommands do, as library functions (testable).

use crate::verify::Problem;
use std::path::Path;

/// The geometry `sph-impact verify` runs a problem in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VerifyGeometry {
    /// The problem's own (1-D, 2-D or 3-D).
    Own,
    /// Axisymmetric RZ ([`Problem::run_rz`]).
    Rz,
    /// `noh-planar` only: the RZ run's column as a plane 2-D column
    /// ([`Problem::run_plane_column`]), to separate the RZ terms' error from 2-D SPH's.
    Plane,
    /// `taylor` only: 3-D with the rod placed as RZ rings revolved about the axis
    /// ([`Problem::run_rings`]), a placement without the cubic lattice's in-plane axes.
    Rings,
}

/// `sph-impact verify`: run, print metrics (a table or one JSON object), and write the
/// outputs into `out` when given. A bad resolution, scheme or combination of options is
/// bad input (exit code 2); a run that fails or outputs that cannot be written, a failure
/// (1).
pub fn verify(
    problem: Problem,
    resolution: Option<usize>,
    scheme: Option<&str>,
    out: Option<&Path>,
    json: bool,
    geometry: VerifyGeometry,
    deposit: Option<crate::verify::SedovDeposit>,
) -> Result<(), CommandError> {
    let scheme =
        scheme_with_overrides(problem.default_scheme(), scheme).map_err(CommandError::bad_input)?;
    let rz = geometry == VerifyGeometry::Rz;
    let outcome = match (deposit, geometry) {
        (Some(_), VerifyGeometry::Plane | VerifyGeometry::Rings) => {
            return Err(CommandError::bad_input(
                "--deposit is for the Sedov problems, --geometry plane for noh-planar and \
                 --geometry rings for taylor",
            ));
        }
        (Some(d), _) => problem.run_sedov(resolution, scheme, d, rz),
        (None, VerifyGeometry::Rz) => problem.run_rz(resolution, scheme),
        (None, VerifyGeometry::Plane) => problem.run_plane_column(resolution, scheme),
        (None, VerifyGeometry::Rings) => problem.run_rings(resolution, scheme),
        (None, VerifyGeometry::Own) => problem.run_with(resolution, scheme),
    }
    .map_err(|e| {
        // What the run was asked for, not how it went: a resolution out of range or too
        // large for memory, a scheme the solver rejects, a form the problem lacks.
        if matches!(
            e,
            crate::SolverError::BadConfig { .. }
                | crate::SolverError::NoSuchForm { .. }
                | crate::SolverError::TooLarge { .. }
        ) {
            CommandError::bad_input(e)
        } else {
            CommandError::failed(e)
        }
    })?;
    let failed = |e: &dyn std::fmt::Display| CommandError::failed(e);
    if json {
        let text = serde_json::to_string(&outcome.metrics).map_err(|e| failed(&e))?;
        write_stdout(&format!("{text}\n"))?;
    } else {
        let mut text = format!(
            "{} (resolution {})\n",
            problem.name(),
            resolution.unwrap_or(problem.resolution_doc().1)
        );
        for (k, v) in &outcome.metrics {
            text.push_str(&format!("  {k:<32} {v}\n"));
        }
        write_stdout(&text)?;
    }
    if let Some(dir) = out {
        let at =
            |path: &Path, e: &dyn std::fmt::Display| failed(&format!("{}: {e}", path.display()));
        std::fs::create_dir_all(dir).map_err(|e| at(dir, &e))?;
        let write = |name: &str, text: String| {
            std::fs::write(dir.join(name), text).map_err(|e| at(&dir.join(name), &e))
        };
        write("profile.csv", outcome.profile.to_csv())?;
        if !outcome.history.rows.is_empty() {
            write("history.csv", outcome.history.to_csv())?;
        }
        write(
            "metrics.json",
            serde_json::to_string_pretty(&outcome.metrics).map_err(|e| failed(&e))?,
        )?;
        crate::plot::profile_plot(&outcome, &dir.join("plot.png")).map_err(|e| failed(&e))?;
        for p in &outcome.pictures {
            let path = dir.join(format!("{}.png", p.name));
            crate::plot::picture(p, &path).map_err(|e| at(&path, &e))?;
        }
    }
    Ok(())
}

/// `sph-impact study FILE`: reads and checks the study, runs its unfinished points into
/// `out` (default `out/<study file stem>`), writes its table and prints it (Markdown).
/// `options.jobs` 0 runs as many points at a time as the cores hold runs of the study's
/// `threads_per_run`.
/// A point that fails is recorded and the others run on; the command then fails (exit 1)
/// naming how many failed. A stop request (SIGINT, SIGTERM) ends the running points at a
/// checkpoint, which the next call resumes from (exit 130).
pub fn study(
    file: &Path,
    out: Option<&Path>,
    scale: Option<f64>,
    options: &crate::study::StudyOptions,
) -> Result<crate::study::StudyTable, CommandError> {
    use crate::study::{PointStatus, run_study};
    let study = read_study(file, scale)?;
    let dir = study_directory(file, out);
    let mut options = options.clone();
    if options.jobs == 0 {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        options.jobs = (cores / study.threads_per_run).max(1);
    }
    let options = &options;
    let table = run_study(&study, &dir, options).map_err(study_error)?;
    if let Some(k) = options.only {
        // One task of a job array: its point's outcome is the exit code.
        let row = &table.rows[k];
        return match row.status {
            PointStatus::Failed => Err(CommandError::failed(format!(
                "point {k} failed: {}",
                row.error.as_deref().unwrap_or_default()
            ))),
            PointStatus::Pending if options.stop.requested() => Err(CommandError {
                code: CommandError::INTERRUPTED,
                message: format!("point {k} stopped; the same command continues it"),
            }),
            _ => Ok(table),
        };
    }
    if !options.quiet {
        write_stdout(&format!(
            "study directory      {}\n\n{}",
            crate::input::printable(&dir.display().to_string()),
            table.to_markdown()
        ))?;
    }
    let count = |s: PointStatus| table.rows.iter().filter(|r| r.status == s).count();
    if options.stop.requested() {
        return Err(CommandError {
            code: CommandError::INTERRUPTED,
            message: format!(
                "study stopped: {} of {} points done; the same command continues it",
                count(PointStatus::Done),
                table.rows.len()
            ),
        });
    }
    let failed = count(PointStatus::Failed);
    if failed > 0 {
        return Err(CommandError::failed(format!(
            "{failed} of {} points failed (their errors are in study.md; --retry-failed runs them again)",
            table.rows.len()
        )));
    }
    Ok(table)
}

/// `sph-impact fit FILE`: reads and checks the fit, runs the search into `out` (default
/// `out/<fit file stem>`), writes `fit.csv`, `fit.json`, `fit.md` and prints `fit.md`.
/// A stop request ends it at a checkpoint (exit 130); the same command continues it.
pub fn fit(
    file: &Path,
    out: Option<&Path>,
    scale: Option<f64>,
    options: &crate::study::StudyOptions,
) -> Result<crate::study::FitReport, CommandError> {
    let fit = read_fit(file, scale)?;
    let dir = study_directory(file, out);
    let report = crate::study::run_fit(&fit, &dir, options).map_err(study_error)?;
    if !options.quiet {
        let md = std::fs::read_to_string(dir.join("fit.md")).unwrap_or_default();
        write_stdout(&format!(
            "fit directory        {}\n\n{md}",
            crate::input::printable(&dir.display().to_string())
        ))?;
    }
    if options.stop.requested() {
        return Err(CommandError {
            code: CommandError::INTERRUPTED,
            message: "fit stopped; the same command continues it".into(),
        });
    }
    Ok(report)
}

/// `sph-impact fit FILE --plots`: draws the fit's plots again from its directory's
/// fit.csv, without running, and prints their paths.
pub fn fit_plots(file: &Path, out: Option<&Path>, scale: Option<f64>) -> Result<(), CommandError> {
    let fit = read_fit(file, scale)?;
    let dir = study_directory(file, out);
    let written = crate::study::redraw_fit_plots(&fit, &dir).map_err(study_error)?;
    let lines: Vec<String> = written
        .iter()
        .map(|p| crate::input::printable(&p.display().to_string()).into_owned())
        .collect();
    write_stdout(&(lines.join("\n") + "\n"))
}

/// The study of `file`, at `scale` (`--resolution-scale`) when given instead of its own.
fn read_study(file: &Path, scale: Option<f64>) -> Result<crate::study::Study, CommandError> {
    let mut study = crate::study::Study::from_toml_file(file).map_err(CommandError::bad_input)?;
    if let Some(s) = scale {
        study
            .set_resolution_scale(s)
            .map_err(CommandError::bad_input)?;
    }
    Ok(study)
}

/// The fit of `file`, at `scale` (`--resolution-scale`) when given instead of its own.
fn read_fit(file: &Path, scale: Option<f64>) -> Result<crate::study::Fit, CommandError> {
    let mut fit = crate::study::Fit::from_toml_file(file).map_err(CommandError::bad_input)?;
    if let Some(s) = scale {
        fit.set_resolution_scale(s)
            .map_err(CommandError::bad_input)?;
    }
    Ok(fit)
}

/// The study directory: `--out`, else `out/<study file stem>`.
fn study_directory(file: &Path, out: Option<&Path>) -> std::path::PathBuf {
    match out {
        Some(d) => d.to_owned(),
        None => Path::new("out").join(
            file.file_stem()
                .map_or_else(|| "study".into(), |s| s.to_string_lossy().into_owned()),
        ),
    }
}

fn study_error(e: crate::study::StudyError) -> CommandError {
    if e.bad_input {
        CommandError::bad_input(e)
    } else {
        CommandError::failed(e)
    }
}

/// `sph-impact study FILE --emit slurm`: writes the points' scenes and `study.sbatch`
/// into the study directory (study::emit_slurm) and prints the script's path.
pub fn study_emit_slurm(
    file: &Path,
    out: Option<&Path>,
    scale: Option<f64>,
    quiet: bool,
) -> Result<(), CommandError> {
    let study = read_study(file, scale)?;
    let dir = study_directory(file, out);
    let script = crate::study::emit_slurm(&study, file, &dir, scale).map_err(study_error)?;
    if !quiet {
        write_stdout(&format!(
            "{} points; submit with: sbatch {}\n",
            study.points().len(),
            crate::input::printable(&script.display().to_string())
        ))?;
    }
    Ok(())
}

/// Writes `text` to standard output. A closed pipe (`sph-impact materials | head -1`) is
/// no failure — the reader took what it wanted — so the text is dropped and the command
/// still succeeds; any other write error fails it (exit code 1). `println!` would panic
/// instead (exit code 101).
pub fn write_stdout(text: &str) -> Result<(), CommandError> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CommandError::failed(format!(
            "cannot write to standard output: {e}"
        ))),
        _ => Ok(()),
    }
}

/// The most worker threads `--threads` accepts: more than the hardware threads of the
/// largest machines. More threads than cores only share the cores, and the parallel
/// loops' cost grows with the thread count: `check` of the smoke scene on two cores took
/// 0.01 s with 128 threads, 0.2 s with 512, 3.3 s with 1024, 17 s with 2048 and 62 s
/// with 4096; 100 000 seemed to hang.
pub const MAX_THREADS: usize = 1024;

/// Checks a `--threads` value: 1 to [`MAX_THREADS`] (bad input otherwise, naming the
/// limit).
pub fn check_threads(threads: usize) -> Result<usize, CommandError> {
    if (1..=MAX_THREADS).contains(&threads) {
        Ok(threads)
    } else {
        Err(CommandError::bad_input(format!(
            "--threads {threads}: must be from 1 to {MAX_THREADS}"
        )))
    }
}

/// The scheme `base` with the fields given in the JSON object `overrides` replaced
/// (nested objects merge field by field; unknown fields are an error).
pub fn scheme_with_overrides(
    base: crate::SchemeConfig,
    overrides: Option<&str>,
) -> Result<crate::SchemeConfig, String> {
    let Some(text) = overrides else {
        return Ok(base);
    };
    let patch: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("--scheme: not JSON: {e}"))?;
    if !patch.is_object() {
        return Err("--scheme: expected a JSON object of scheme fields".into());
    }
    let mut merged = serde_json::to_value(&base).map_err(|e| e.to_string())?;
    merge(&mut merged, patch.clone());
    let scheme: crate::SchemeConfig =
        serde_json::from_value(merged).map_err(|e| format!("--scheme: {e}"))?;
    // serde drops extra keys next to the tag of a unit variant (`{"kind": "scalar",
    // "max_aspect": 4}`); every key given must survive the round trip.
    let kept = serde_json::to_value(&scheme).map_err(|e| e.to_string())?;
    match dropped_key(&patch, &kept) {
        Some(key) => Err(format!(
            "--scheme: unknown field `{key}` (not a setting of the scheme as given)"
        )),
        None => Ok(scheme),
    }
}

/// The first key path of `patch` missing from `kept`, as `a.b.c`.
fn dropped_key(patch: &serde_json::Value, kept: &serde_json::Value) -> Option<String> {
    let (serde_json::Value::Object(p), serde_json::Value::Object(k)) = (patch, kept) else {
        return None;
    };
    p.iter().find_map(|(key, value)| match k.get(key) {
        None => Some(key.clone()),
        Some(inner) => dropped_key(value, inner).map(|rest| format!("{key}.{rest}")),
    })
}

fn merge(into: &mut serde_json::Value, patch: serde_json::Value) {
    match (into, patch) {
        (serde_json::Value::Object(a), serde_json::Value::Object(b)) => {
            for (k, v) in b {
                match a.get_mut(&k) {
                    // A tagged enum (one with "kind") is replaced whole, not merged.
                    Some(slot) if slot.is_object() && v.is_object() && v.get("kind").is_none() => {
                        merge(slot, v)
                    }
                    _ => {
                        a.insert(k, v);
                    }
                }
            }
        }
        (slot, v) => *slot = v,
    }
}

/// A command's failure and the process exit code it maps to: 2 for bad input (the
/// scene, the options), 1 for a run that failed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct CommandError {
    /// The exit code.
    pub code: u8,
    /// One line saying what went wrong.
    pub message: String,
}

impl CommandError {
    /// Exit code for bad input.
    pub const BAD_INPUT: u8 = 2;
    /// Exit code for a failed run.
    pub const FAILED: u8 = 1;
    /// Exit code for a run stopped by SIGINT or SIGTERM (128 + SIGINT's number, as a
    /// shell reports a process it interrupted).
    pub const INTERRUPTED: u8 = 130;

    /// A bad-input error.
    pub fn bad_input(message: impl std::fmt::Display) -> Self {
        Self {
            code: Self::BAD_INPUT,
            message: message.to_string(),
        }
    }

    /// A failed-run error.
    pub fn failed(message: impl std::fmt::Display) -> Self {
        Self {
            code: Self::FAILED,
            message: message.to_string(),
        }
    }
}

/// The run directory: `--out`, else the scene's `[output] directory`, else
/// `out/<scene file stem>`.
pub fn run_directory(
    scene_path: &Path,
    scene: &crate::scene::Scene,
    out: Option<&Path>,
) -> std::path::PathBuf {
    if let Some(o) = out {
        return o.to_owned();
    }
    if let Some(d) = &scene.output.directory {
        return d.into();
    }
    let stem = scene_path
        .file_stem()
        .map_or_else(|| "run".into(), |s| s.to_string_lossy().into_owned());
    Path::new("out").join(stem)
}

/// `sph-impact run SCENE`: reads the scene, runs it into the run directory and prints
/// the main results (unless `options.quiet`).
pub fn run_scene(
    scene_path: &Path,
    out: Option<&Path>,
    options: &crate::run::RunOptions,
) -> Result<crate::run::RunSummary, CommandError> {
    run_scene_over(scene_path, out, options, &crate::solver::OneRank)
}

/// The command error of a run's error: its exit code by kind.
fn run_error(e: crate::run::RunError) -> CommandError {
    if e.is_interrupted() {
        CommandError {
            code: CommandError::INTERRUPTED,
            message: e.to_string(),
        }
    } else if e.is_bad_input() {
        CommandError::bad_input(e)
    } else {
        CommandError::failed(e)
    }
}

/// [`run_scene`] as rank 0 of `ranks` (`mpirun -n N sph-impact run SCENE`; docs/mpi.md):
/// the other ranks call [`follow_scene`] with the same arguments.
pub fn run_scene_over(
    scene_path: &Path,
    out: Option<&Path>,
    options: &crate::run::RunOptions,
    ranks: &dyn crate::solver::Ranks,
) -> Result<crate::run::RunSummary, CommandError> {
    let scene = crate::scene::Scene::from_toml_file(scene_path).map_err(CommandError::bad_input)?;
    let dir = run_directory(scene_path, &scene, out);
    let summary = crate::run::run_over(&scene, &dir, options, ranks).map_err(run_error)?;
    if !options.quiet {
        write_stdout(&result_lines(&dir, &summary))?;
    }
    Ok(summary)
}

/// `sph-impact run SCENE` on a rank other than 0 of `ranks`: steps the scene in lockstep
/// with rank 0 ([`crate::run::follow`]), which writes the run directory and prints; this
/// rank writes its pieces of the snapshots there.
pub fn follow_scene(
    scene_path: &Path,
    out: Option<&Path>,
    options: &crate::run::RunOptions,
    ranks: &dyn crate::solver::Ranks,
) -> Result<(), CommandError> {
    let scene = crate::scene::Scene::from_toml_file(scene_path).map_err(CommandError::bad_input)?;
    let dir = run_directory(scene_path, &scene, out);
    crate::run::follow(&scene, &dir, options, ranks).map_err(run_error)
}

/// The result lines `sph-impact run` prints: the run directory, crater, β and cost.
fn result_lines(dir: &Path, summary: &crate::run::RunSummary) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "run directory        {}",
        crate::input::printable(&dir.display().to_string())
    );
    let geometry = summary.geometry;
    if geometry == crate::scene::GeometryKind::Line {
        let _ = writeln!(
            s,
            "crater depth         {:.2} mm (1-D: no diameter)",
            summary.crater_depth_m * 1e3
        );
    } else {
        let (size, what) = if geometry == crate::scene::GeometryKind::Plane {
            ("trench width", "plane strain")
        } else {
            ("crater diameter", "")
        };
        let _ = writeln!(
            s,
            "{size:<20} {:.2} mm (bowl {:.2} mm), depth {:.2} mm{}",
            summary.crater_diameter_m * 1e3,
            summary.bowl_diameter_m * 1e3,
            summary.crater_depth_m * 1e3,
            if what.is_empty() {
                String::new()
            } else {
                format!(" ({what})")
            }
        );
    }
    let _ = writeln!(
        s,
        "beta                 {:.4} (from the target: {:.4}; as a pendulum sees it: {:.4}); \
         ejecta {:.4e} {}",
        summary.beta,
        summary.beta_target,
        summary.beta_pendulum,
        summary.ejecta_mass_kg,
        geometry.mass_unit()
    );
    let _ = writeln!(
        s,
        "cost                 {} particles, {} steps, {:.1} s wall, {:.3e} particle-steps/s",
        summary.particles, summary.steps, summary.wall_time_s, summary.particle_steps_per_s
    );
    s
}

/// `sph-impact check SCENE`: validates the scene, places its bodies and prints per body
/// the particle count, mass and ρ·V, and the estimated first dt, steps, runtime and
/// memory (as text or one JSON object).
pub fn check_scene(
    scene_path: &Path,
    json: bool,
    threads: Option<usize>,
    resolution_scale: f64,
    end_time: Option<f64>,
) -> Result<crate::scene::CheckReport, CommandError> {
    let scene = crate::scene::Scene::from_toml_file(scene_path).map_err(CommandError::bad_input)?;
    let threads = threads.unwrap_or_else(rayon::current_num_threads);
    let report = scene
        .check_report(resolution_scale, threads, end_time)
        .map_err(CommandError::bad_input)?;
    if json {
        let text = serde_json::to_string(&report).map_err(CommandError::failed)?;
        write_stdout(&format!("{text}\n"))?;
    } else {
        write_stdout(&report.to_text())?;
    }
    Ok(report)
}

/// `sph-impact materials`: the built-in materials as a Markdown table, or with `json`
/// one JSON array with every parameter (the material's TOML form as an object).
pub fn materials(json: bool) -> Result<(), CommandError> {
    let lib = crate::materials::library();
    if !json {
        return write_stdout(&format!(
            "{}\n`sph-impact materials --json` lists every parameter and its source.\n",
            crate::materials::table(&lib)
        ));
    }
    let mut out = Vec::new();
    for m in &lib {
        let toml_text = m.to_toml().map_err(CommandError::failed)?;
        let parameters: toml::Table = toml::from_str(&toml_text).map_err(CommandError::failed)?;
        out.push(serde_json::json!({
            "name": m.name,
            "density_kg_m3": m.density,
            "shear_modulus_pa": m.shear_modulus,
            "bulk_modulus_pa": m.bulk_modulus(),
            "youngs_modulus_pa": m.youngs_modulus(),
            "poisson_ratio": m.poisson_ratio(),
            "longitudinal_wave_speed_m_s": m.longitudinal_wave_speed(),
            "eos": sph_eos::EquationOfState::name(&m.eos),
            "strength": sph_strength::StrengthModel::name(&m.strength),
            "damage": m.damage.name(),
            "key_parameters": m.key_parameters(),
            "parameters": parameters,
            "sources": m.sources,
        }));
    }
    let text = serde_json::to_string_pretty(&out).map_err(CommandError::failed)?;
    write_stdout(&format!("{text}\n"))
}

#[cfg(test)]
mod tests {
    use super::scheme_with_overrides;

    /// A misspelt or misplaced field anywhere in `--scheme` is an error naming it, not a
    /// silently ignored key (before, `{"smoothing":{"asph":{…}}}` ran the scalar scheme).
    #[test]
    fn scheme_overrides_reject_unknown_fields_at_every_level() {
        let base = crate::SchemeConfig::default;
        for (text, field) in [
            (r#"{"bogus": 1}"#, "bogus"),
            (r#"{"viscosity": {"alhpa": 0.5}}"#, "alhpa"),
            (r#"{"artificial_stress": {"eps": 0.2}}"#, "eps"),
            (r#"{"smoothing": {"asph": {"max_aspect": 4.0}}}"#, "asph"),
            (
                r#"{"smoothing": {"kind": "asph", "max_aspect": 4.0, "x": 1}}"#,
                "x",
            ),
            (r#"{"riemann": {"kind": "acoustic", "speed": 1}}"#, "speed"),
            (
                r#"{"smoothing": {"kind": "scalar", "max_aspect": 4.0}}"#,
                "max_aspect",
            ),
        ] {
            let e = scheme_with_overrides(base(), Some(text)).unwrap_err();
            assert!(e.contains(field), "{text}: {e}");
        }
        let asph = r#"{"smoothing": {"kind": "asph", "max_aspect": 4.0}}"#;
        let s = scheme_with_overrides(base(), Some(asph)).unwrap();
        assert_eq!(s.smoothing, crate::SmoothingMode::Asph { max_aspect: 4.0 });
        let v = scheme_with_overrides(base(), Some(r#"{"viscosity": {"alpha": 0.5}}"#)).unwrap();
        assert_eq!((v.viscosity.alpha, v.viscosity.beta), (0.5, 1.0));
    }
}

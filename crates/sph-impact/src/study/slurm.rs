//! A study as a Slurm job array: `sph-impact study FILE --out DIR --emit slurm` writes each
//! point's scene into the study directory and `DIR/study.sbatch`, whose task k runs point
//! k (`study FILE --out DIR --point k`, with the point's own scene, seed and run
//! directory); once the array has finished, `study FILE --out DIR --collect` makes the
//! table. A task that fails leaves its point recorded as failed; resubmitting the array
//! runs only the points not done (a finished point's task returns at once).

use crate::study::error::StudyError;
use crate::study::runner::{check_stored_scene, point_dir, stored_scene, write_whole};
use crate::study::study::Study;
use std::path::{Path, PathBuf};

/// Writes the points' scenes and `study.sbatch` into `dir` (created if needed) for the
/// study read from `study_file`, and returns the script's path. The script names the
/// study file and directory by absolute path, so it runs from any directory; the program
/// is `$SPH_IMPACT` if set, else `sph-impact` on the `PATH`.
pub fn emit_slurm(
    study: &Study,
    study_file: &Path,
    dir: &Path,
    scale: Option<f64>,
) -> Result<PathBuf, StudyError> {
    std::fs::create_dir_all(dir).map_err(|e| StudyError::io(dir, e))?;
    let points = study.points();
    for point in &points {
        let scene = stored_scene(study, point)?;
        let pdir = point_dir(dir, point.index);
        check_stored_scene(&pdir, &scene, point)?;
        std::fs::create_dir_all(&pdir).map_err(|e| StudyError::io(&pdir, e))?;
        write_whole(&pdir.join("scene.toml"), scene.as_bytes())?;
    }
    let abs = |p: &Path| std::fs::canonicalize(p).map_err(|e| StudyError::io(p, e));
    let (file, out) = (abs(study_file)?, abs(dir)?);
    let name = study_file
        .file_stem()
        .map_or_else(|| "study".into(), |s| s.to_string_lossy().into_owned());
    let logs = out.join("logs");
    std::fs::create_dir_all(&logs).map_err(|e| StudyError::io(&logs, e))?;
    let script = format!(
        "#!/bin/bash\n\
         # {n} points of the study {file}, one per task of a Slurm job array\n\
         # (docs/studies.md, \"On a cluster\"). Submit: sbatch {script}\n\
         # Then: sph-impact study {file} --out {out}{scale} --collect\n\
         #SBATCH --job-name={name}\n\
         #SBATCH --array=0-{last}\n\
         #SBATCH --ntasks=1\n\
         #SBATCH --cpus-per-task={threads}\n\
         #SBATCH --output={logs}/%A_%a.out\n\
         set -euo pipefail\n\
         exec \"${{SPH_IMPACT:-sph-impact}}\" study {qfile} --out {qout}{scale} --point \"$SLURM_ARRAY_TASK_ID\" --quiet\n",
        n = points.len(),
        file = file.display(),
        script = out.join("study.sbatch").display(),
        out = out.display(),
        name = crate::study::plain_name(&name),
        last = points.len() - 1,
        threads = study.threads_per_run,
        logs = logs.display(),
        qfile = shell_quote(&file.display().to_string()),
        qout = shell_quote(&out.display().to_string()),
        // A scale given on the command line in place of the file's: every task, and the
        // collection, must run with it (the points' scenes record it).
        scale = scale.map_or_else(String::new, |s| format!(" --resolution-scale {s:?}")),
    );
    let path = out.join("study.sbatch");
    write_whole(&path, script.as_bytes())?;
    Ok(path)
}

/// `s` in single quotes for the shell.
fn shell_quote(s: &str) -> String {
    format!("'{}'", s.replace('\'', "'\\''"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quoting_for_the_shell() {
        assert_eq!(shell_quote("/a b/it's"), "'/a b/it'\\''s'");
        assert_eq!(crate::study::plain_name("n target$x"), "n_target_x");
    }
}

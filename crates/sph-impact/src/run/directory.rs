//! The run directory and what a run writes there. A directory that holds a previous
//! run's files is never silently reused: a new run refuses it unless it resumes the
//! previous run (`RunOptions::resume`) or is told to clear it first
//! (`RunOptions::overwrite`), which removes the run's own files and nothing else.

use crate::run::error::RunError;
use std::path::Path;

/// The files a run writes at the top of its directory (the plots, the history, the
/// collection, the summary; `checkpoint.cbor` is the single checkpoint of earlier
/// versions).
pub const RUN_FILES: [&str; 8] = [
    "history.csv",
    "run.pvd",
    "summary.json",
    "crater_section.png",
    "history.png",
    "ejecta.png",
    "projectile_energy.png",
    "checkpoint.cbor",
];

/// The sub-directories a run writes its series into: the snapshots and the checkpoints.
pub const RUN_SUBDIRS: [&str; 2] = ["snapshots", crate::run::checkpoint::CHECKPOINT_DIR];

/// True for a name a run writes: one of [`RUN_FILES`] or its temporary `.part` name.
fn is_run_file(name: &str) -> bool {
    let base = name.strip_suffix(".part").unwrap_or(name);
    RUN_FILES.contains(&base)
}

/// True for a file a run writes into one of [`RUN_SUBDIRS`].
fn is_series_file(name: &str) -> bool {
    let base = name.strip_suffix(".part").unwrap_or(name);
    base.ends_with(".vtu") || base.ends_with(".pvtu") || base.ends_with(".cbor")
}

/// The previous run's files in `dir` (names relative to it, sorted); empty for a
/// missing or fresh directory.
pub fn previous_run_files(dir: &Path) -> Result<Vec<String>, RunError> {
    let mut found = Vec::new();
    let list = |d: &Path| -> Result<Vec<String>, RunError> {
        match std::fs::read_dir(d) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Vec::new()),
            Err(e) => Err(RunError::io(d, e)),
            Ok(entries) => Ok(entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()),
        }
    };
    for name in list(dir)? {
        if is_run_file(&name) {
            found.push(name);
        }
    }
    for sub in RUN_SUBDIRS {
        for name in list(&dir.join(sub))? {
            if is_series_file(&name) {
                found.push(format!("{sub}/{name}"));
            }
        }
    }
    found.sort();
    Ok(found)
}

/// Removes the previous run's files from `dir` (and its series directories once
/// empty); other files stay.
pub fn clear_previous_run(dir: &Path) -> Result<(), RunError> {
    for name in previous_run_files(dir)? {
        let path = dir.join(&name);
        std::fs::remove_file(&path).map_err(|e| RunError::io(&path, e))?;
    }
    for sub in RUN_SUBDIRS {
        // Left in place when the user keeps files of their own there.
        let _ = std::fs::remove_dir(dir.join(sub));
    }
    Ok(())
}

/// Makes `dir` ready for a run from t = 0: refused when it holds a previous run's files
/// unless `overwrite`, which clears them first.
pub(crate) fn prepare_fresh(dir: &Path, overwrite: bool) -> Result<(), RunError> {
    let found = previous_run_files(dir)?;
    if !found.is_empty() {
        if !overwrite {
            let shown: Vec<&str> = found.iter().take(4).map(String::as_str).collect();
            let more = found.len().saturating_sub(shown.len());
            return Err(RunError::DirectoryInUse {
                path: dir.display().to_string(),
                files: if more > 0 {
                    format!("{} and {more} more", shown.join(", "))
                } else {
                    shown.join(", ")
                },
            });
        }
        clear_previous_run(dir)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_runs_own_files_count_and_are_cleared() {
        let dir = std::env::temp_dir().join(format!("sph-rundir-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("snapshots")).unwrap();
        std::fs::write(dir.join("notes.txt"), "mine").unwrap();
        assert!(previous_run_files(&dir).unwrap().is_empty());
        prepare_fresh(&dir, false).unwrap();
        std::fs::write(dir.join("history.csv"), "t_s\n").unwrap();
        std::fs::write(dir.join("snapshots/00000.vtu"), "x").unwrap();
        // A snapshot of a run over two MPI ranks: the .pvtu and its pieces.
        for name in ["00001.pvtu", "00001_0.vtu", "00001_1.vtu"] {
            std::fs::write(dir.join("snapshots").join(name), "x").unwrap();
        }
        std::fs::write(dir.join("summary.json.part"), "x").unwrap();
        let mut found = previous_run_files(&dir).unwrap();
        found.sort();
        assert_eq!(
            found,
            [
                "history.csv",
                "snapshots/00000.vtu",
                "snapshots/00001.pvtu",
                "snapshots/00001_0.vtu",
                "snapshots/00001_1.vtu",
                "summary.json.part"
            ]
        );
        let e = prepare_fresh(&dir, false).unwrap_err();
        assert!(e.is_bad_input(), "{e}");
        assert!(e.to_string().contains("--overwrite"), "{e}");
        assert!(dir.join("history.csv").exists());
        prepare_fresh(&dir, true).unwrap();
        assert!(previous_run_files(&dir).unwrap().is_empty());
        assert!(!dir.join("snapshots").exists());
        assert_eq!(
            std::fs::read_to_string(dir.join("notes.txt")).unwrap(),
            "mine"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

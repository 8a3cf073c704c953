//! Whole-file writes: every output a run writes in one go (snapshot, collection, plot,
//! summary, checkpoint) goes to `NAME.part` beside its final name and is renamed over it
//! once complete, so that a run killed or failed while writing leaves the previous file
//! (or none), never half of one. A rename within one directory is atomic on POSIX file
//! systems.

use crate::run::error::RunError;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The temporary name `path` is written under before the rename.
pub(crate) fn part_path(path: &Path) -> PathBuf {
    let mut name = path.file_name().unwrap_or_default().to_os_string();
    name.push(".part");
    path.with_file_name(name)
}

/// Writes `path` through `fill`, via its `.part` name. With `sync`, the data reach the
/// disk before the rename (for a checkpoint, which a resumed run must find whole even
/// after a power cut).
pub(crate) fn write_with(
    path: &Path,
    sync: bool,
    fill: impl FnOnce(&mut BufWriter<std::fs::File>) -> std::io::Result<()>,
) -> Result<(), RunError> {
    let part = part_path(path);
    let result = (|| -> std::io::Result<()> {
        let mut w = BufWriter::new(std::fs::File::create(&part)?);
        fill(&mut w)?;
        w.flush()?;
        if sync {
            w.get_ref().sync_all()?;
        }
        Ok(())
    })();
    if let Err(e) = result {
        // A full disk must not leave a stray part file behind either.
        let _ = std::fs::remove_file(&part);
        return Err(RunError::io(path, e));
    }
    std::fs::rename(&part, path).map_err(|e| RunError::io(path, e))
}

/// Writes `bytes` to `path` via its `.part` name.
pub(crate) fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), RunError> {
    write_with(path, false, |w| w.write_all(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_write_keeps_the_previous_file_and_leaves_no_part() {
        let dir = std::env::temp_dir().join(format!("sph-atomic-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("summary.json");
        write_bytes(&path, b"first").unwrap();
        let e = write_with(&path, true, |w| {
            w.write_all(b"half of the sec")?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(e.to_string().contains("disk full"), "{e}");
        assert_eq!(std::fs::read(&path).unwrap(), b"first");
        assert!(!part_path(&path).exists());
        write_bytes(&path, b"second").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"second");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

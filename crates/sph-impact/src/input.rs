//! Reading the user's files and quoting the user's text: scene and material files are
//! read up to [`MAX_INPUT_BYTES`] (a device such as `/dev/zero`, a pipe without end or a
//! huge file is refused, not read to the end), and messages that quote names, keys or
//! paths escape their control characters ([`printable`]).

use std::borrow::Cow;
use std::io::Read;
use std::path::Path;

/// The largest scene or material file read (bytes): 64 MiB. The largest bundled scene is
/// a few kilobytes, and a scene of 100 000 bodies about 20 MB; without a bound,
/// `/dev/zero` given as a scene read 4 GB before failing.
pub const MAX_INPUT_BYTES: u64 = 64 * 1024 * 1024;

/// The text of the file at `path`, read up to `limit` bytes; the error (the operating
/// system's message, or why the file is refused) does not name the path.
///
/// A regular file longer than `limit` is refused from its size alone; anything else (a
/// device, a pipe) is read until `limit` + 1 bytes show that it is longer.
pub fn read_text(path: &Path, limit: u64) -> Result<String, String> {
    let too_large = || {
        format!(
            "larger than {limit} bytes ({} MiB), the most a scene or material file may hold",
            limit / (1024 * 1024)
        )
    };
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let meta = file.metadata().map_err(|e| e.to_string())?;
    if meta.is_dir() {
        return Err("is a directory, not a file".into());
    }
    if meta.is_file() && meta.len() > limit {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    String::from_utf8(bytes).map_err(|e| format!("not UTF-8 text: {e}"))
}

/// `text` with every control character written as its escape (`\u{1b}`), so that a
/// message quoting the user's text (a name, a key, a path) cannot drive the terminal it
/// is printed on. Text without control characters is returned as it is.
pub fn printable(text: &str) -> Cow<'_, str> {
    if !text.chars().any(char::is_control) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_read_up_to_the_limit() {
        let dir = std::env::temp_dir().join(format!("sph-impact-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("ten.toml");
        std::fs::write(&path, "0123456789").unwrap();
        assert_eq!(read_text(&path, 10).unwrap(), "0123456789");
        let e = read_text(&path, 9).unwrap_err();
        assert!(e.contains("larger than 9 bytes"), "{e}");
        std::fs::write(&path, [0xff, 0xfe]).unwrap();
        assert!(read_text(&path, 10).unwrap_err().contains("not UTF-8"));
        assert!(read_text(&dir, 10).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// An endless device is read only up to the limit.
    #[cfg(unix)]
    #[test]
    fn an_endless_file_is_refused() {
        let t = std::time::Instant::now();
        let e = read_text(Path::new("/dev/zero"), 1024 * 1024).unwrap_err();
        assert!(e.contains("larger than 1048576 bytes"), "{e}");
        assert!(t.elapsed().as_secs_f64() < 10.0);
    }

    #[test]
    fn control_characters_are_escaped() {
        assert!(matches!(printable("basalt target"), Cow::Borrowed(_)));
        assert_eq!(printable("a\u{1b}[31mb\tc"), "a\\u{1b}[31mb\\u{9}c");
    }
}

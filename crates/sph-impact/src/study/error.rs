//! Errors of a study: where in the study file (file:line:column), the key, and what is
//! wrong, on one line.

use crate::materials::Location;
use std::fmt;

/// A study error. Bad study files are located (``study.toml:12:9: `parameter[1].path`: …``);
/// errors of a running study (a run directory that cannot be written) name the
/// path.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyError {
    /// Where in the study file, when the error is about a key of it.
    pub location: Option<Box<Location>>,
    /// The key as a dotted path (`parameter[1].range.count`).
    pub key: Option<String>,
    /// What is wrong.
    pub message: String,
    /// True when the input is at fault (a bad study file or option), false for a failure
    /// while running (a directory that cannot be written).
    pub bad_input: bool,
}

impl StudyError {
    /// Bad input about `key`, not yet located.
    pub fn at_key(key: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            location: None,
            key: Some(key.into()),
            message: message.into(),
            bad_input: true,
        }
    }

    /// Bad input about the study as a whole.
    pub fn bad(message: impl Into<String>) -> Self {
        Self {
            location: None,
            key: None,
            message: message.into(),
            bad_input: true,
        }
    }

    /// A failure while running (input and output).
    pub fn failed(message: impl Into<String>) -> Self {
        Self {
            location: None,
            key: None,
            message: message.into(),
            bad_input: false,
        }
    }

    /// An I/O failure on `path`.
    pub(crate) fn io(path: &std::path::Path, e: impl fmt::Display) -> Self {
        Self::failed(format!("{}: {e}", path.display()))
    }
}

impl fmt::Display for StudyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut line = String::new();
        if let Some(l) = &self.location {
            line.push_str(&format!("{l}: "));
        }
        if let Some(k) = &self.key {
            line.push_str(&format!("`{k}`: "));
        }
        line.push_str(
            &self
                .message
                .split('\n')
                .map(str::trim)
                .collect::<Vec<_>>()
                .join(" "),
        );
        f.write_str(&crate::input::printable(&line))
    }
}

impl std::error::Error for StudyError {}

//! Scene errors: one line each, naming the file, line and column, the body and the key
//! (`scene.toml:12:3: body "target": `material`: unknown material "basalt-x" (known: …)`).

use crate::materials::Location;
use std::fmt;
use thiserror::Error;

/// What is wrong with a scene.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum SceneErrorKind {
    /// The TOML does not parse, has an unknown key or a value of the wrong type; the
    /// parser's message (which names the key and the accepted ones).
    #[error("{0}")]
    Syntax(String),
    /// The scene has no `[[body]]`.
    #[error("no bodies: a scene needs at least one [[body]] table")]
    NoBodies,
    /// A body name is used twice.
    #[error("body name \"{0}\" is used twice (body names must be unique)")]
    DuplicateBody(String),
    /// A name that should refer to a body does not.
    #[error("no body named \"{name}\" (bodies: {known})")]
    MissingBody {
        /// The name given.
        name: String,
        /// The scene's body names, comma separated.
        known: String,
    },
    /// `material = "…"` names no built-in material.
    #[error("unknown material \"{name}\" (known: {known})")]
    UnknownMaterial {
        /// The name given.
        name: String,
        /// The built-in names, comma separated.
        known: String,
    },
    /// An inline material is invalid; the material library's message.
    #[error("{0}")]
    Material(String),
    /// A number out of its range.
    #[error("{} is invalid: {reason}", shown(*value))]
    Invalid {
        /// The value given.
        value: f64,
        /// The allowed range, or why.
        reason: String,
    },
    /// A shape or placement the geometry crate rejects.
    #[error("{0}")]
    Geometry(String),
    /// Particles of one body lie inside another body's shape.
    #[error(
        "overlaps body \"{other}\": {count} of its particles lie inside the shape of \"{other}\" \
         (the first at ({:.6}, {:.6}, {:.6}) m)",
        first[0], first[1], first[2]
    )]
    Overlap {
        /// The other body.
        other: String,
        /// How many particles of this body are inside it.
        count: usize,
        /// The first such particle's position (m).
        first: [f64; 3],
    },
    /// A body of an axisymmetric (RZ) scene, or one placed as rings, is not symmetric
    /// about the z axis; what is wrong and what is accepted.
    #[error(
        "not axisymmetric about the z axis (geometry = \"rz\" and placement kind \"rings\" need it): {0}"
    )]
    NotAxisymmetric(String),
    /// The solver settings are out of range, or the solver rejected the set-up.
    #[error("{0}")]
    Solver(String),
    /// The scene file could not be read.
    #[error("cannot read the scene: {0}")]
    Io(String),
}

/// A scene error with its place: the file location (for scenes read from TOML), the
/// body it concerns and the key as a dotted path (`body[1].material.density`).
#[derive(Clone, Debug, Error, PartialEq)]
pub struct SceneError {
    /// Where in the file (`None` for scenes built in Rust). Boxed to keep `Result`s small.
    pub location: Option<Box<Location>>,
    /// The body's name, for errors inside a `[[body]]`.
    pub body: Option<String>,
    /// The key as a full dotted path from the file's top (`end_time`,
    /// `body[0].shape.radius`); `None` when the error concerns no key.
    pub key: Option<String>,
    /// What is wrong.
    pub kind: SceneErrorKind,
}

impl SceneError {
    /// An error about `key` (full dotted path), not yet located.
    pub fn at_key(key: impl Into<String>, kind: SceneErrorKind) -> Self {
        Self {
            location: None,
            body: None,
            key: Some(key.into()),
            kind,
        }
    }

    /// An error about body `index` named `name`, at `key` within the body
    /// (`material.density`; empty for the body as a whole).
    pub fn in_body(index: usize, name: &str, key: &str, kind: SceneErrorKind) -> Self {
        let path = if key.is_empty() {
            format!("body[{index}]")
        } else {
            format!("body[{index}].{key}")
        };
        Self {
            location: None,
            body: Some(name.to_owned()),
            key: Some(path),
            kind,
        }
    }

    /// An error concerning no particular key.
    pub fn general(kind: SceneErrorKind) -> Self {
        Self {
            location: None,
            body: None,
            key: None,
            kind,
        }
    }

    /// The line of the location (0 for the file as a whole), if located.
    pub fn line(&self) -> Option<usize> {
        self.location.as_ref().map(|l| l.line)
    }

    /// The key relative to its body (`material.density` rather than
    /// `body[1].material.density`), as the message shows it.
    pub fn display_key(&self) -> Option<&str> {
        let key = self.key.as_deref()?;
        if self.body.is_some()
            && key.starts_with("body[")
            && let Some(end) = key.find(']')
        {
            let rest = key[end + 1..].trim_start_matches('.');
            return (!rest.is_empty()).then_some(rest);
        }
        Some(key)
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use fmt::Write;
        let mut line = String::new();
        if let Some(l) = &self.location {
            write!(line, "{l}: ")?;
        }
        if let Some(b) = &self.body {
            write!(line, "body \"{b}\": ")?;
        }
        if let Some(k) = self.display_key() {
            write!(line, "`{k}`: ")?;
        }
        // Messages are one line: a parser message spanning lines is joined.
        let text = self.kind.to_string();
        line.push_str(
            &text
                .split('\n')
                .map(str::trim)
                .collect::<Vec<_>>()
                .join(" "),
        );
        // Names, keys and paths come from the file: their control characters are
        // escaped, so that the message cannot drive the terminal.
        f.write_str(&crate::input::printable(&line))
    }
}

/// A value as a message shows it: plainly in [1e-4, 1e6), else in scientific notation
/// (1e-300 in full is 300 digits), both the shortest text that reads back to it.
pub fn shown(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

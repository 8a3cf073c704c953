//! Typed errors of the material library. Every variant names the material and the field
//! as a dotted path (`density`, `shear_modulus`, `eos.E_cv`, `strength.cohesion`,
//! `damage.k`, `thermal.T_melt`, ...), and errors from a TOML file carry the file and
//! line ([`Location`]).

use std::fmt;
use thiserror::Error;

/// Where in a material file an error was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Location {
    /// The file name (or the `origin` given to
    /// [`MaterialSpec::from_toml_str`](crate::materials::MaterialSpec::from_toml_str)).
    pub origin: String,
    /// Line, counted from 1; 0 when the error concerns the file as a whole (a missing
    /// top-level key has no line).
    pub line: usize,
    /// Column (in characters), counted from 1; 0 together with `line = 0`.
    pub column: usize,
}

impl Location {
    /// The location of byte `offset` of `text`.
    pub(crate) fn at_offset(origin: &str, text: &str, offset: usize) -> Self {
        let offset = offset.min(text.len());
        let before = &text[..offset];
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        Self {
            origin: origin.to_owned(),
            line: before.matches('\n').count() + 1,
            column: before[line_start..].chars().count() + 1,
        }
    }

    /// The file as a whole (no line).
    pub(crate) fn whole_file(origin: &str) -> Self {
        Self {
            origin: origin.to_owned(),
            line: 0,
            column: 0,
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}", self.origin)
        } else {
            write!(f, "{}:{}:{}", self.origin, self.line, self.column)
        }
    }
}

/// "`origin:line:column`: " or nothing.
fn at(location: &Option<Box<Location>>) -> String {
    match location {
        Some(l) => format!("{l}: "),
        None => String::new(),
    }
}

/// Errors from building, validating, reading or writing a material.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum MaterialError {
    /// A parameter is out of its range or inconsistent with another one.
    #[error("{}material `{material}`: `{field}` = {value} is invalid: {reason}", at(.location))]
    Invalid {
        /// Material name.
        material: String,
        /// Dotted field path, e.g. `"eos.E_cv"`.
        field: String,
        /// The offending value.
        value: f64,
        /// What is wrong.
        reason: String,
        /// Where, for TOML input.
        location: Option<Box<Location>>,
    },
    /// Two parts of a material do not fit together (e.g. a temperature-dependent strength
    /// model without thermal data), or a model fails at the reference state.
    #[error("{}material `{material}`: `{field}`: {reason}", at(.location))]
    Inconsistent {
        /// Material name.
        material: String,
        /// Dotted field path of the part at fault.
        field: String,
        /// What does not fit.
        reason: String,
        /// Where, for TOML input.
        location: Option<Box<Location>>,
    },
    /// A required parameter is not given.
    #[error("{}material `{material}`: missing `{field}` ({needed_by})", at(.location))]
    Missing {
        /// Material name.
        material: String,
        /// Dotted field path of the missing key.
        field: String,
        /// Why it is needed (which model asks for it).
        needed_by: String,
        /// Where (the section header; the whole file for a top-level key).
        location: Option<Box<Location>>,
    },
    /// A value has the wrong type (a string where a number belongs, ...).
    #[error("{}material `{material}`: `{field}` must be {expected}, found {found}", at(.location))]
    WrongType {
        /// Material name.
        material: String,
        /// Dotted field path.
        field: String,
        /// The type wanted.
        expected: &'static str,
        /// What was found.
        found: String,
        /// Where.
        location: Option<Box<Location>>,
    },
    /// A model, preset, base material or option name is not known.
    #[error(
        "{}material `{material}`: `{field}` = \"{name}\" is not known; known: {}",
        at(.location),
        .known.join(", ")
    )]
    UnknownName {
        /// Material name.
        material: String,
        /// Dotted field path (`eos.model`, `strength.preset`, `base`, ...).
        field: String,
        /// The name given.
        name: String,
        /// The names that would have been accepted.
        known: Vec<String>,
        /// Where.
        location: Option<Box<Location>>,
    },
    /// A key that exists in the section but does not belong to the chosen model (e.g.
    /// `c0`, a Mie–Grüneisen parameter, under `model = "tillotson"`).
    #[error(
        "{}material `{material}`: key `{field}` is not a parameter of {context}; {}",
        at(.location),
        if .allowed.is_empty() {
            "it has none".to_owned()
        } else {
            format!("its parameters are: {}", .allowed.join(", "))
        }
    )]
    UnexpectedKey {
        /// Material name.
        material: String,
        /// Dotted field path of the key.
        field: String,
        /// Which model, e.g. "eos model `tillotson`".
        context: String,
        /// The keys that model takes.
        allowed: Vec<String>,
        /// Where.
        location: Option<Box<Location>>,
    },
    /// The TOML text does not parse, has an unknown key (every table rejects unknown
    /// keys) or a value of the wrong shape; the message is the parser's.
    #[error("{location}: {}{message}", .key.as_ref().map(|k| format!("`{k}`: ")).unwrap_or_default())]
    Toml {
        /// Where.
        location: Location,
        /// The dotted key at that place, when it can be told from the text.
        key: Option<String>,
        /// The parser's message (names the unknown key and the accepted ones).
        message: String,
    },
    /// No built-in material of that name.
    #[error("material `{name}` is not in the library; known materials: {}", .known.join(", "))]
    UnknownMaterial {
        /// The name asked for.
        name: String,
        /// The built-in names.
        known: Vec<String>,
    },
    /// The material file could not be read.
    #[error("cannot read material file `{path}`: {message}")]
    Io {
        /// The path.
        path: String,
        /// The operating system's message.
        message: String,
    },
    /// A user-defined model (a trait object) has no TOML form.
    #[error(
        "material `{material}`: the {component} is a user-defined model and cannot be written as TOML"
    )]
    NotSerializable {
        /// Material name.
        material: String,
        /// `"EOS"` or `"strength model"`.
        component: &'static str,
    },
}

impl MaterialError {
    /// The dotted field path the error is about, if it is about one field.
    pub fn field(&self) -> Option<&str> {
        match self {
            Self::Invalid { field, .. }
            | Self::Inconsistent { field, .. }
            | Self::Missing { field, .. }
            | Self::WrongType { field, .. }
            | Self::UnknownName { field, .. }
            | Self::UnexpectedKey { field, .. } => Some(field),
            Self::Toml { key, .. } => key.as_deref(),
            _ => None,
        }
    }

    /// Where in a file the error was found (TOML input only).
    pub fn location(&self) -> Option<&Location> {
        match self {
            Self::Invalid { location, .. }
            | Self::Inconsistent { location, .. }
            | Self::Missing { location, .. }
            | Self::WrongType { location, .. }
            | Self::UnknownName { location, .. }
            | Self::UnexpectedKey { location, .. } => location.as_deref(),
            Self::Toml { location, .. } => Some(location),
            _ => None,
        }
    }

    /// The line of [`Self::location`] (0 for the file as a whole).
    pub fn line(&self) -> Option<usize> {
        self.location().map(|l| l.line)
    }

    /// Sets the location if the error has none yet (used when validation of a material
    /// read from a file finds a problem in a field the reader knows the place of).
    pub(crate) fn or_located(mut self, place: Option<Location>) -> Self {
        let slot = match &mut self {
            Self::Invalid { location, .. }
            | Self::Inconsistent { location, .. }
            | Self::Missing { location, .. }
            | Self::WrongType { location, .. }
            | Self::UnknownName { location, .. }
            | Self::UnexpectedKey { location, .. } => location,
            _ => return self,
        };
        if slot.is_none() {
            *slot = place.map(Box::new);
        }
        self
    }
}

//! Reading a scene from TOML: parse with serde (unknown keys rejected everywhere), then
//! check; every error is located in the file through the [`SourceMap`].

use crate::scene::Scene;
use crate::scene::error::{SceneError, SceneErrorKind};
use crate::scene::spans::{SourceMap, body_index};
use std::path::Path;

impl Scene {
    /// Reads and [`check`](Scene::check)s a scene; `origin` (a file name) prefixes every
    /// error's location.
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, SceneError> {
        let map = SourceMap::new(origin, text).map_err(|e| syntax_error(&e, origin, text, None))?;
        let mut scene: Scene =
            toml::from_str(text).map_err(|e| syntax_error(&e, origin, text, Some(&map)))?;
        scene.source = map;
        scene.every_key_read(text).map_err(|e| scene.locate(e))?;
        scene.check().map_err(|e| scene.locate(e))?;
        Ok(scene)
    }

    /// Reads a scene file ([`Self::from_toml_str`] with the path as origin); a file
    /// larger than [`crate::input::MAX_INPUT_BYTES`] (or without end, as `/dev/zero`) is
    /// refused after reading at most that much.
    pub fn from_toml_file(path: impl AsRef<Path>) -> Result<Self, SceneError> {
        let path = path.as_ref();
        let text = crate::input::read_text(path, crate::input::MAX_INPUT_BYTES).map_err(|e| {
            SceneError::general(SceneErrorKind::Io(format!("{}: {e}", path.display())))
        })?;
        Self::from_toml_str(&text, &path.display().to_string())
    }

    /// Every key of `text` must have been read into the scene, and every table written as
    /// one: serde drops a key beside the tag of a variant without fields (`riemann = {
    /// kind = "acoustic", waves = "davis" }`) and reads a struct from an array by position
    /// (`viscosity = [1.0, 1.0]`). The scene written back must hold each key of the text
    /// where the text has it. Inline materials are left to their own reader, which
    /// refuses unknown keys itself.
    fn every_key_read(&self, text: &str) -> Result<(), SceneError> {
        let (Ok(given), Ok(kept)) = (
            toml::from_str::<toml::Table>(text),
            toml::Table::try_from(self),
        ) else {
            return Ok(());
        };
        match unread(&given, &kept, "") {
            None => Ok(()),
            Some((key, what)) => Err(SceneError::at_key(key, SceneErrorKind::Syntax(what))),
        }
    }

    /// Adds the file location (and the body's name) to an error that has none, from the
    /// error's key. Errors of scenes built in Rust are returned as they are.
    pub fn locate(&self, mut e: SceneError) -> SceneError {
        if e.location.is_none() && self.source.is_file() {
            e.location = Some(Box::new(match &e.key {
                Some(k) => self.source.locate(k),
                None => self.source.locate(""),
            }));
        }
        e
    }
}

/// A parser error as a scene error: its place, the key there (from the source map when
/// the text parsed as TOML), the body it is in, and the parser's message.
fn syntax_error(
    e: &toml::de::Error,
    origin: &str,
    text: &str,
    map: Option<&SourceMap>,
) -> SceneError {
    let offset = e.span().map_or(0, |s| s.start);
    let message = e.message().replace("unknown field", "unknown key");
    let mut err = SceneError::general(SceneErrorKind::Syntax(message.clone()));
    let Some(map) = map else {
        err.location = Some(Box::new(crate::materials::Location::at_offset(
            origin, text, offset,
        )));
        return err;
    };
    err.location = Some(Box::new(map.location_at(offset)));
    let mut key = map.path_at(offset);
    // "missing field `x`": the parser reports the table that lacks it; name `table.x`,
    // or for the top level the file as a whole.
    if let Some(name) = message
        .strip_prefix("missing field `")
        .and_then(|r| r.split('`').next())
    {
        let table = e.span().and_then(|s| map.path_of_value(&s));
        key = Some(match &table {
            Some(t) => format!("{t}.{name}"),
            None => name.to_owned(),
        });
        if table.is_none() {
            err.location = Some(Box::new(crate::materials::Location::whole_file(origin)));
        }
    }
    // "unknown key `x`": point at `x` itself, inside the table the parser reported.
    if let Some(name) = message
        .strip_prefix("unknown key `")
        .and_then(|r| r.split('`').next())
    {
        let child = match &key {
            Some(k) => format!("{k}.{name}"),
            None => name.to_owned(),
        };
        if let Some(loc) = map.locate_key(&child) {
            err.location = Some(Box::new(loc));
            key = Some(child);
        } else if key.is_none() {
            key = Some(child);
        }
    }
    if let Some(i) = key.as_deref().and_then(body_index) {
        err.body = Some(
            map.body_name(i)
                .map_or_else(|| format!("#{}", i + 1), str::to_owned),
        );
    }
    err.key = key;
    err
}

/// The first key of `given` that `kept` lacks, or a table of `kept` that `given` wrote as
/// an array, as (its path, what is wrong).
fn unread(given: &toml::Table, kept: &toml::Table, path: &str) -> Option<(String, String)> {
    use toml::Value::{Array, Table};
    for (key, value) in given {
        let here = if path.is_empty() {
            key.clone()
        } else {
            format!("{path}.{key}")
        };
        let Some(k) = kept.get(key) else {
            return Some((
                here,
                format!("unknown key `{key}` (not a setting beside the others given)"),
            ));
        };
        match (value, k) {
            (Array(_), Table(_)) => {
                return Some((here, "expected a table, found an array".to_owned()));
            }
            // An inline material is checked by the material reader.
            (Table(_), _) if key == "material" && path.starts_with("body[") => {}
            (Table(g), Table(k)) => {
                if let Some(found) = unread(g, k, &here) {
                    return Some(found);
                }
            }
            (Array(g), Array(k)) => {
                for (i, (g, k)) in g.iter().zip(k).enumerate() {
                    if let (Table(g), Table(k)) = (g, k)
                        && let Some(found) = unread(g, k, &format!("{here}[{i}]"))
                    {
                        return Some(found);
                    }
                }
            }
            _ => {}
        }
    }
    None
}

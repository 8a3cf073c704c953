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
        scene.check().map_err(|e| scene.locate(e))?;
        Ok(scene)
    }

    /// Reads a scene file ([`Self::from_toml_str`] with the path as origin).
    pub fn from_toml_file(path: impl AsRef<Path>) -> Result<Self, SceneError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|e| {
            SceneError::general(SceneErrorKind::Io(format!("{}: {e}", path.display())))
        })?;
        Self::from_toml_str(&text, &path.display().to_string())
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

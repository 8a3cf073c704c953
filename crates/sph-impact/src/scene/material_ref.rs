//! A body's material: a built-in by name (`material = "basalt-study"`) or an inline
//! material table in the format of a material file (docs/materials.md: `base = …`,
//! presets, sections), e.g. `material = { base = "basalt-study", strength = { cohesion =
//! 30e6 } }`. An inline table without `name` takes the body's name.

use crate::materials::{BUILTIN_NAMES, MaterialError, MaterialSpec, builtin};
use crate::scene::error::SceneErrorKind;
use serde::de::{self, MapAccess, Visitor};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// Where a body's material comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum MaterialRef {
    /// A built-in material ([`crate::materials::library()`]).
    Builtin(String),
    /// An inline material table, read like a material file.
    Inline(toml::Table),
    /// A material given in Rust (written out as its TOML form).
    Spec(Box<MaterialSpec>),
}

impl From<&str> for MaterialRef {
    fn from(name: &str) -> Self {
        MaterialRef::Builtin(name.to_owned())
    }
}

impl From<MaterialSpec> for MaterialRef {
    fn from(spec: MaterialSpec) -> Self {
        MaterialRef::Spec(Box::new(spec))
    }
}

impl MaterialRef {
    /// The material, validated. For body `body` (an inline table's default name). `Err`
    /// is (key below `material`, empty for the reference itself; what is wrong).
    pub fn resolve(&self, body: &str) -> Result<MaterialSpec, (String, SceneErrorKind)> {
        match self {
            MaterialRef::Builtin(name) => builtin(name).map_err(|_| {
                (
                    String::new(),
                    SceneErrorKind::UnknownMaterial {
                        name: name.clone(),
                        known: BUILTIN_NAMES.join(", "),
                    },
                )
            }),
            MaterialRef::Inline(table) => {
                let mut table = table.clone();
                table
                    .entry("name")
                    .or_insert_with(|| toml::Value::String(body.to_owned()));
                let text = toml::to_string(&table)
                    .map_err(|e| (String::new(), SceneErrorKind::Material(e.to_string())))?;
                MaterialSpec::from_toml_str(&text, "inline").map_err(|e| {
                    (
                        e.field().unwrap_or_default().to_owned(),
                        SceneErrorKind::Material(without_location(&e)),
                    )
                })
            }
            MaterialRef::Spec(spec) => spec.validate().map(|()| (**spec).clone()).map_err(|e| {
                (
                    e.field().unwrap_or_default().to_owned(),
                    SceneErrorKind::Material(e.to_string()),
                )
            }),
        }
    }
}

/// The material library's message without its `inline:line:column: ` prefix: the place
/// in the scene file replaces it.
fn without_location(e: &MaterialError) -> String {
    let mut text = e.to_string();
    if let Some(l) = e.location()
        && let Some(rest) = text.strip_prefix(&format!("{l}: "))
    {
        text = rest.to_owned();
    }
    // A parser error repeats the key, which the scene error names already.
    if let MaterialError::Toml { key: Some(k), .. } = e
        && let Some(rest) = text.strip_prefix(&format!("`{k}`: "))
    {
        text = rest.replace("unknown field", "unknown key");
    }
    text
}

impl Serialize for MaterialRef {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            MaterialRef::Builtin(name) => s.serialize_str(name),
            MaterialRef::Inline(table) => table.serialize(s),
            MaterialRef::Spec(spec) => {
                let text = spec.to_toml().map_err(serde::ser::Error::custom)?;
                let table: toml::Table =
                    toml::from_str(&text).map_err(serde::ser::Error::custom)?;
                table.serialize(s)
            }
        }
    }
}

impl<'de> Deserialize<'de> for MaterialRef {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = MaterialRef;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a built-in material name or an inline material table")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<MaterialRef, E> {
                Ok(MaterialRef::Builtin(v.to_owned()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<MaterialRef, A::Error> {
                toml::Table::deserialize(de::value::MapAccessDeserializer::new(map))
                    .map(MaterialRef::Inline)
            }
        }
        d.deserialize_any(V)
    }
}

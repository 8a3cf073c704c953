//! Where each key of a scene file is: a map from the dotted path of every key
//! (`end_time`, `body[1].material.eos.A`) to its byte spans, read from the TOML parser's
//! spanned tree. Errors found after parsing (an unknown material, overlapping bodies) are
//! located through it, so every message names file, line and column.

use crate::materials::Location;
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// The spans of one key.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Entry {
    key: Range<usize>,
    value: Range<usize>,
}

/// The keys of one scene file and their places.
#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    origin: String,
    text: String,
    entries: HashMap<String, Entry>,
    /// `name` of each `[[body]]`, as written (for errors the parser reports).
    body_names: Vec<Option<String>>,
}

/// Locations are not part of a scene's value: two scenes that say the same are equal
/// wherever they were read from.
impl PartialEq for SourceMap {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl SourceMap {
    /// Indexes `text` (which must parse as TOML); `origin` names the file in messages.
    pub(crate) fn new(origin: &str, text: &str) -> Result<Self, toml::de::Error> {
        let root = DeTable::parse(text)?;
        let mut map = Self {
            origin: origin.to_owned(),
            text: text.to_owned(),
            ..Self::default()
        };
        map.walk_table("", root.get_ref());
        if let Some(bodies) = root.get_ref().get("body").map(Spanned::get_ref)
            && let DeValue::Array(items) = bodies
        {
            map.body_names = items
                .iter()
                .map(|b| {
                    b.get_ref()
                        .get("name")
                        .and_then(|n| n.get_ref().as_str().map(str::to_owned))
                })
                .collect();
        }
        Ok(map)
    }

    /// True for a scene read from text.
    pub fn is_file(&self) -> bool {
        !self.origin.is_empty()
    }

    /// The file's name.
    pub fn origin(&self) -> &str {
        &self.origin
    }

    fn walk_table(&mut self, prefix: &str, table: &DeTable<'_>) {
        for (k, v) in table.iter() {
            let path = if prefix.is_empty() {
                k.get_ref().to_string()
            } else {
                format!("{prefix}.{}", k.get_ref())
            };
            self.entries.insert(
                path.clone(),
                Entry {
                    key: k.span(),
                    value: v.span(),
                },
            );
            self.walk_value(&path, v);
        }
    }

    fn walk_value(&mut self, path: &str, v: &Spanned<DeValue<'_>>) {
        match v.get_ref() {
            DeValue::Table(t) => self.walk_table(path, t),
            DeValue::Array(items) => {
                for (i, item) in items.iter().enumerate() {
                    let p = format!("{path}[{i}]");
                    self.entries.insert(
                        p.clone(),
                        Entry {
                            key: item.span(),
                            value: item.span(),
                        },
                    );
                    self.walk_value(&p, item);
                }
            }
            _ => {}
        }
    }

    /// The location of byte `offset`.
    pub(crate) fn location_at(&self, offset: usize) -> Location {
        Location::at_offset(&self.origin, &self.text, offset)
    }

    /// The location of `path`'s value (for a key that names a value: the value is what is
    /// wrong), else of its closest written ancestor (a missing key is reported at its
    /// table), else the file as a whole.
    pub fn locate(&self, path: &str) -> Location {
        let mut p = path.to_owned();
        loop {
            if let Some(e) = self.entries.get(&p) {
                return self.location_at(e.value.start);
            }
            match parent(&p) {
                Some(q) => p = q,
                None => return Location::whole_file(&self.origin),
            }
        }
    }

    /// The location of `path`'s key itself (for unknown keys).
    pub(crate) fn locate_key(&self, path: &str) -> Option<Location> {
        self.entries
            .get(path)
            .map(|e| self.location_at(e.key.start))
    }

    /// The deepest key whose value holds byte `offset`, as a dotted path.
    pub(crate) fn path_at(&self, offset: usize) -> Option<String> {
        self.entries
            .iter()
            .filter(|(_, e)| {
                (e.value.start <= offset && offset < e.value.end.max(e.value.start + 1))
                    || (e.key.start <= offset && offset < e.key.end)
            })
            .min_by_key(|(p, e)| (e.value.end - e.value.start, std::cmp::Reverse(p.len())))
            .map(|(p, _)| p.clone())
    }

    /// The key whose value spans exactly `span` (a table the parser reports as a whole).
    pub(crate) fn path_of_value(&self, span: &Range<usize>) -> Option<String> {
        self.entries
            .iter()
            .filter(|(_, e)| e.value == *span)
            .max_by_key(|(p, _)| p.len())
            .map(|(p, _)| p.clone())
    }

    /// The name written in `[[body]]` number `index`.
    pub(crate) fn body_name(&self, index: usize) -> Option<&str> {
        self.body_names.get(index).and_then(|n| n.as_deref())
    }
}

/// `a.b[2].c` → `a.b[2]` → `a.b` → `a` → none.
fn parent(path: &str) -> Option<String> {
    if path.ends_with(']') {
        return path.rfind('[').map(|i| path[..i].to_owned());
    }
    path.rfind('.').map(|i| path[..i].to_owned())
}

/// The index of the body a path is in (`body[3].shape` → 3).
pub(crate) fn body_index(path: &str) -> Option<usize> {
    path.strip_prefix("body[")?.split(']').next()?.parse().ok()
}

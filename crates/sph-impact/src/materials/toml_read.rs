//! Reading a material from TOML. The format (docs/materials.md has the full reference):
//!
//! ```toml
//! name = "my-basalt"          # required
//! base = "basalt-study"       # optional: start from a built-in and override fields
//! density = 2876.0            # kg/m^3, the EOS reference density
//! shear_modulus = 22.7e9      # Pa; 0 or absent for a fluid
//! sources = ["eos: ...", "strength: ..."]
//!
//! [eos]                       # model = "..." + parameters, or preset = "..." (+ overrides)
//! [strength]                  # absent: no strength (or the base's)
//! [damage]                    # absent: no damage (or the base's)
//! [thermal]                   # absent: no thermal data (or the base's)
//! ```
//!
//! Each section starts from its `preset` if one is given, else from the base material's
//! section when the model is the same, else from nothing; the keys written in the file
//! then override. Every error names the file, the line and the key.

use crate::materials::build::{
    Cx, DAMAGE_MODELS, EOS_MODELS, STRENGTH_MODELS, Source, build_damage, build_eos,
    build_strength, build_thermal,
};
use crate::materials::damage_spec::DamageSpec;
use crate::materials::error::{Location, MaterialError};
use crate::materials::library::{BUILTIN_NAMES, builtin};
use crate::materials::presets::{PresetKind, presets};
use crate::materials::sections::{
    Param, Section, Value, damage_section, eos_section, strength_section, thermal_section,
};
use crate::materials::spec::MaterialSpec;
use crate::materials::toml_schema::{MaterialFile, Scalar};
use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

impl MaterialSpec {
    /// Reads a material from TOML text; `origin` (a file name) prefixes every error's
    /// location. The material is validated ([`MaterialSpec::validate`]).
    ///
    /// ```
    /// use sph_impact::materials::MaterialSpec;
    /// let text = r#"
    /// name = "weaker-basalt"
    /// base = "basalt-study"
    ///
    /// [strength]
    /// cohesion = 10e6
    /// "#;
    /// let m = MaterialSpec::from_toml_str(text, "weaker.toml")?;
    /// assert_eq!(m.density, 2876.0);
    ///
    /// let bad = "name = \"x\"\ndensity = 2876\n\n[eos]\npreset = \"basalt-study\"\nE_iv = 2e7\n";
    /// let err = MaterialSpec::from_toml_str(bad, "bad.toml").unwrap_err();
    /// assert_eq!(err.field(), Some("eos.E_cv"));
    /// assert_eq!(err.line(), Some(5)); // E_cv comes from the preset on line 5
    /// # Ok::<(), sph_impact::materials::MaterialError>(())
    /// ```
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, MaterialError> {
        let file: MaterialFile = toml::from_str(text).map_err(|e| parse_error(&e, text, origin))?;
        let mut reader = Reader {
            source: Source { origin, text },
            material: "<unnamed>".into(),
            index: HashMap::new(),
        };
        reader.read(file).map_err(|e| reader.locate(e))
    }

    /// Reads a material file ([`Self::from_toml_str`] with the path as origin); a file
    /// larger than [`crate::input::MAX_INPUT_BYTES`] (or without end) is refused after
    /// reading at most that much.
    pub fn from_toml_file(path: impl AsRef<Path>) -> Result<Self, MaterialError> {
        let path = path.as_ref();
        let text =
            crate::input::read_text(path, crate::input::MAX_INPUT_BYTES).map_err(|message| {
                MaterialError::Io {
                    path: path.display().to_string(),
                    message,
                }
            })?;
        Self::from_toml_str(&text, &path.display().to_string())
    }
}

/// A parser error (syntax, unknown key, wrong value shape) with its place and key.
fn parse_error(e: &toml::de::Error, text: &str, origin: &str) -> MaterialError {
    let offset = e.span().map_or(0, |s| s.start);
    MaterialError::Toml {
        location: Location::at_offset(origin, text, offset),
        key: key_at(text, offset),
        message: e.message().to_owned(),
    }
}

/// The dotted key of the `key = value` line holding byte `offset`, with the table header
/// above it (`eos.A`), read from the text; `None` off such a line.
fn key_at(text: &str, offset: usize) -> Option<String> {
    let offset = offset.min(text.len());
    let line_start = text[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[offset..].find('\n').map_or(text.len(), |i| offset + i);
    let line = &text[line_start..line_end];
    let key = line[..line.find('=')?].trim().trim_matches('"');
    if key.is_empty() || key.starts_with('[') || key.starts_with('#') || key.contains(' ') {
        return None;
    }
    let table = text[..line_start]
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        .and_then(|l| l.trim_start_matches('[').split(']').next())
        .map(str::trim);
    Some(match table {
        Some(t) if !t.is_empty() => format!("{t}.{key}"),
        _ => key.to_owned(),
    })
}

/// A section table as read: the header's span and the keys with their values.
type RawSection = (Range<usize>, Vec<(&'static str, Spanned<Scalar>)>);

/// A section after presets and the base were applied.
struct Resolved {
    sec: Section,
    header: Option<Range<usize>>,
    fallback: Option<Range<usize>>,
}

struct Reader<'a> {
    source: Source<'a>,
    material: String,
    /// Byte span of every key written in the file, by dotted path (`density`, `eos.A`,
    /// `eos` for the section header, ...).
    index: HashMap<String, Range<usize>>,
}

impl Reader<'_> {
    fn location(&self, span: &Range<usize>) -> Location {
        Location::at_offset(self.source.origin, self.source.text, span.start)
    }

    /// Attaches the place of the error's field (or its section, or the `base` line) to an
    /// error that has none.
    fn locate(&self, e: MaterialError) -> MaterialError {
        // The field itself; for a model that came from a preset, the preset; else the
        // section header; else the `base` line.
        let span = e
            .field()
            .and_then(|f| {
                let section = f.split('.').next().unwrap_or(f);
                self.index
                    .get(f)
                    .or_else(|| self.index.get(&format!("{section}.preset")))
                    .or_else(|| self.index.get(section))
            })
            .or_else(|| self.index.get("base"));
        let place = match span {
            Some(s) => self.location(s),
            None => Location::whole_file(self.source.origin),
        };
        e.or_located(Some(place))
    }

    fn cx<'s>(&'s self, section: &'static str, r: &Resolved) -> Cx<'s> {
        Cx {
            material: &self.material,
            section,
            source: Some(self.source),
            header: r.header.clone(),
            fallback: r.fallback.clone(),
        }
    }

    fn wrong_type(
        &self,
        field: &str,
        expected: &'static str,
        found: String,
        span: &Range<usize>,
    ) -> MaterialError {
        MaterialError::WrongType {
            material: self.material.clone(),
            field: field.to_owned(),
            expected,
            found,
            location: Some(Box::new(self.location(span))),
        }
    }

    fn missing(
        &self,
        field: &str,
        needed_by: String,
        span: Option<&Range<usize>>,
    ) -> MaterialError {
        MaterialError::Missing {
            material: self.material.clone(),
            field: field.to_owned(),
            needed_by,
            location: Some(Box::new(match span {
                Some(s) => self.location(s),
                None => Location::whole_file(self.source.origin),
            })),
        }
    }

    /// A top-level number (`density`, `shear_modulus`).
    fn number(
        &mut self,
        v: Option<Spanned<Scalar>>,
        key: &str,
    ) -> Result<Option<f64>, MaterialError> {
        let Some(v) = v else { return Ok(None) };
        let span = v.span();
        self.index.insert(key.to_owned(), span.clone());
        match v.into_inner() {
            Scalar::Num(x) => Ok(Some(x)),
            Scalar::Str(s) => {
                Err(self.wrong_type(key, "a number", format!("the string \"{s}\""), &span))
            }
            Scalar::Bool(b) => {
                Err(self.wrong_type(key, "a number", format!("the boolean {b}"), &span))
            }
        }
    }

    fn read(&mut self, file: MaterialFile) -> Result<MaterialSpec, MaterialError> {
        let Some(name) = file.name else {
            return Err(self.missing(
                "name",
                "every material file names its material".into(),
                None,
            ));
        };
        self.index.insert("name".into(), name.span());
        self.material = name.into_inner();

        let base = match file.base {
            None => None,
            Some(b) => {
                let span = b.span();
                self.index.insert("base".into(), span.clone());
                let b = b.into_inner();
                Some(builtin(&b).map_err(|_| MaterialError::UnknownName {
                    material: self.material.clone(),
                    field: "base".into(),
                    name: b,
                    known: BUILTIN_NAMES.iter().map(|s| s.to_string()).collect(),
                    location: Some(Box::new(self.location(&span))),
                })?)
            }
        };
        let base_span = self.index.get("base").cloned();

        let density = self
            .number(file.density, "density")?
            .or(base.as_ref().map(|b| b.density))
            .ok_or_else(|| {
                self.missing(
                    "density",
                    "the reference density in kg/m^3 of every material".into(),
                    None,
                )
            })?;
        if !(density.is_finite() && density > 0.0) {
            return Err(self.invalid("density", density, "must be positive and finite"));
        }
        let g_file = self.number(file.shear_modulus, "shear_modulus")?;

        // Equation of state.
        let raw = file.eos.map(|t| (t.span(), t.into_inner().into_entries()));
        let base_sec = base.as_ref().and_then(|b| eos_section(&b.eos));
        let Some(r) = self.resolve(PresetKind::Eos, raw, base_sec, &base_span)? else {
            return Err(self.missing(
                "eos",
                "every material needs an equation of state: an [eos] section with `model` or `preset`".into(),
                None,
            ));
        };
        let eos = build_eos(&r.sec, &self.cx("eos", &r), density)?;

        // Strength, with the material's shear modulus.
        let raw = file
            .strength
            .map(|t| (t.span(), t.into_inner().into_entries()));
        let base_sec = base.as_ref().and_then(|b| strength_section(&b.strength));
        let r = self
            .resolve(PresetKind::Strength, raw, base_sec, &base_span)?
            .unwrap_or(Resolved {
                sec: Section::new(Some("none")),
                header: None,
                fallback: None,
            });
        let model = r.sec.model.clone().unwrap_or_default();
        let shear_modulus = if model == "none" {
            g_file.unwrap_or(0.0)
        } else {
            let g = g_file
                .or(base.as_ref().map(|b| b.shear_modulus))
                .ok_or_else(|| {
                    self.missing(
                        "shear_modulus",
                        format!("strength model `{model}` needs the shear modulus G in Pa"),
                        r.fallback.as_ref().or(r.header.as_ref()),
                    )
                })?;
            if !(g.is_finite() && g > 0.0) {
                return Err(self.invalid(
                    "shear_modulus",
                    g,
                    &format!("must be positive for a material with strength (model `{model}`)"),
                ));
            }
            g
        };
        let strength = build_strength(&r.sec, &self.cx("strength", &r), shear_modulus, density)?;

        // Damage and thermal data.
        let raw = file
            .damage
            .map(|t| (t.span(), t.into_inner().into_entries()));
        let base_sec = base.as_ref().and_then(|b| damage_section(&b.damage));
        let damage = match self.resolve(PresetKind::Damage, raw, base_sec, &base_span)? {
            Some(r) => build_damage(&r.sec, &self.cx("damage", &r))?,
            None => DamageSpec::None,
        };
        let raw = file
            .thermal
            .map(|t| (t.span(), t.into_inner().into_entries()));
        let base_sec = base
            .as_ref()
            .and_then(|b| b.thermal.as_ref().map(thermal_section));
        let thermal = match self.resolve(PresetKind::Thermal, raw, base_sec, &base_span)? {
            Some(r) => Some(build_thermal(&r.sec, &self.cx("thermal", &r))?),
            None => None,
        };

        let mut sources = Vec::new();
        if let Some(b) = &base {
            sources.extend(b.sources.iter().cloned());
            let mut set: Vec<(&String, &Range<usize>)> = self
                .index
                .iter()
                .filter(|(k, _)| {
                    !matches!(
                        k.as_str(),
                        "name" | "base" | "eos" | "strength" | "damage" | "thermal"
                    )
                })
                .collect();
            set.sort_by_key(|(_, s)| s.start);
            let set: Vec<&str> = set.iter().map(|(k, _)| k.as_str()).collect();
            sources.push(format!(
                "derived from the built-in material `{}`; set in {}: {}",
                b.name,
                self.source.origin,
                if set.is_empty() {
                    "nothing".into()
                } else {
                    set.join(", ")
                }
            ));
        }
        sources.extend(file.sources.unwrap_or_default());

        let spec = MaterialSpec {
            name: self.material.clone(),
            density,
            shear_modulus,
            eos,
            strength,
            damage,
            thermal,
            sources,
        };
        spec.validate()?;
        Ok(spec)
    }

    fn invalid(&self, field: &str, value: f64, reason: &str) -> MaterialError {
        MaterialError::Invalid {
            material: self.material.clone(),
            field: field.to_owned(),
            value,
            reason: reason.to_owned(),
            location: self.index.get(field).map(|s| Box::new(self.location(s))),
        }
    }

    /// Applies preset, base and the file's keys to one section. `None` when the file
    /// has no such section and there is no base.
    fn resolve(
        &mut self,
        kind: PresetKind,
        raw: Option<RawSection>,
        base: Option<Section>,
        base_span: &Option<Range<usize>>,
    ) -> Result<Option<Resolved>, MaterialError> {
        let section = kind.section();
        let Some((header, entries)) = raw else {
            return Ok(base.map(|sec| Resolved {
                sec,
                header: None,
                fallback: base_span.clone(),
            }));
        };
        self.index.insert(section.to_owned(), header.clone());
        let (mut model, mut preset, mut params) = (None, None, Vec::new());
        for (key, v) in entries {
            let span = v.span();
            let field = format!("{section}.{key}");
            self.index.insert(field.clone(), span.clone());
            let value = match v.into_inner() {
                Scalar::Num(x) => Value::Num(x),
                Scalar::Str(s) => Value::Str(s),
                Scalar::Bool(b) => {
                    return Err(self.wrong_type(
                        &field,
                        "a number or a name",
                        format!("the boolean {b}"),
                        &span,
                    ));
                }
            };
            match (key, value) {
                ("model" | "preset", Value::Num(x)) => {
                    return Err(self.wrong_type(
                        &field,
                        "a name",
                        format!("the number {x}"),
                        &span,
                    ));
                }
                ("model", Value::Str(s)) => model = Some((s, span)),
                ("preset", Value::Str(s)) => preset = Some((s, span)),
                (key, value) => params.push(Param {
                    key,
                    value,
                    span: Some(span),
                }),
            }
        }

        let (mut sec, fallback) = if let Some((p, pspan)) = preset {
            let all = presets(kind);
            let Some((_, psec)) = all.iter().find(|(n, _)| *n == p) else {
                return Err(MaterialError::UnknownName {
                    material: self.material.clone(),
                    field: format!("{section}.preset"),
                    name: p,
                    known: all.into_iter().map(|(n, _)| n).collect(),
                    location: Some(Box::new(self.location(&pspan))),
                });
            };
            if let Some((m, mspan)) = &model
                && psec.model.as_deref() != Some(m.as_str())
            {
                return Err(MaterialError::Inconsistent {
                    material: self.material.clone(),
                    field: format!("{section}.model"),
                    reason: format!(
                        "preset `{p}` is a `{}` set, not `{m}`",
                        psec.model.as_deref().unwrap_or("")
                    ),
                    location: Some(Box::new(self.location(mspan))),
                });
            }
            (psec.clone(), Some(pspan))
        } else if let Some((m, _)) = &model {
            match base {
                Some(b) if b.model.as_deref() == Some(m.as_str()) => (b, base_span.clone()),
                _ => (Section::new(Some(m)), None),
            }
        } else {
            match base {
                Some(b) => (b, base_span.clone()),
                None if kind == PresetKind::Thermal => (Section::new(None), None),
                None => {
                    let models: Vec<&str> = match kind {
                        PresetKind::Eos => EOS_MODELS.iter().map(|(m, _)| *m).collect(),
                        PresetKind::Strength => STRENGTH_MODELS.iter().map(|(m, _)| *m).collect(),
                        _ => DAMAGE_MODELS.iter().map(|(m, _)| *m).collect(),
                    };
                    return Err(self.missing(
                        &format!("{section}.model"),
                        format!(
                            "[{section}] needs `model` (one of {}) or `preset`",
                            models.join(", ")
                        ),
                        Some(&header),
                    ));
                }
            }
        };
        if let Some((m, mspan)) = model {
            sec.model = Some(m);
            sec.model_span = Some(mspan);
        }
        for p in params {
            sec.set(p);
        }
        Ok(Some(Resolved {
            sec,
            header: Some(header),
            fallback,
        }))
    }
}

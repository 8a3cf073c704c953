//! Writing a material as TOML, every parameter explicit, in the format
//! [`MaterialSpec::from_toml_str`] reads back to an equal material.

use crate::materials::error::MaterialError;
use crate::materials::sections::{
    Section, Value, damage_section, eos_section, strength_section, thermal_section,
};
use crate::materials::spec::MaterialSpec;
use std::fmt::Write;

impl MaterialSpec {
    /// The material as a TOML material file with every parameter written out (no presets).
    /// Validates first; user-defined models have no TOML form
    /// ([`MaterialError::NotSerializable`]).
    ///
    /// ```
    /// use sph_impact::materials::MaterialSpec;
    /// let al = MaterialSpec::aluminium_2024_jc();
    /// let text = al.to_toml()?;
    /// assert!(text.contains("model = \"johnson-cook\""));
    /// assert_eq!(MaterialSpec::from_toml_str(&text, "al.toml")?, al);
    /// # Ok::<(), sph_impact::materials::MaterialError>(())
    /// ```
    pub fn to_toml(&self) -> Result<String, MaterialError> {
        self.validate()?;
        let not_serializable = |component| MaterialError::NotSerializable {
            material: self.name.clone(),
            component,
        };
        let eos = eos_section(&self.eos).ok_or_else(|| not_serializable("EOS"))?;
        let strength =
            strength_section(&self.strength).ok_or_else(|| not_serializable("strength model"))?;
        let damage =
            damage_section(&self.damage).ok_or_else(|| not_serializable("damage model"))?;

        let mut out = String::new();
        let w = &mut out;
        // Writing to a String cannot fail.
        let _ = writeln!(
            w,
            "# Material `{}`, SI units (sph-impact material file).",
            self.name
        );
        let _ = writeln!(w, "name = {}", quote(&self.name));
        let _ = writeln!(w, "density = {}", number(self.density));
        let _ = writeln!(w, "shear_modulus = {}", number(self.shear_modulus));
        if !self.sources.is_empty() {
            let _ = writeln!(w, "sources = [");
            for s in &self.sources {
                let _ = writeln!(w, "    {},", quote(s));
            }
            let _ = writeln!(w, "]");
        }
        write_section(w, "eos", &eos);
        write_section(w, "strength", &strength);
        write_section(w, "damage", &damage);
        if let Some(t) = &self.thermal {
            write_section(w, "thermal", &thermal_section(t));
        }
        Ok(out)
    }
}

fn write_section(w: &mut String, name: &str, s: &Section) {
    let _ = writeln!(w, "\n[{name}]");
    if let Some(m) = &s.model {
        let _ = writeln!(w, "model = {}", quote(m));
    }
    for p in &s.params {
        let v = match &p.value {
            Value::Num(x) => number(*x),
            Value::Str(x) => quote(x),
        };
        let _ = writeln!(w, "{} = {v}", p.key);
    }
}

/// A TOML string literal (escaped by the toml crate).
fn quote(s: &str) -> String {
    toml::Value::String(s.to_owned()).to_string()
}

/// A TOML float that reads back to the same f64: Rust's shortest round-trip digits,
/// positional between 1e-3 and 1e6 (`2876.0`), exponent form otherwise (`2.67e10`).
pub(crate) fn number(v: f64) -> String {
    if v == 0.0 || !v.is_finite() || (1e-3..1e6).contains(&v.abs()) {
        // `{:?}` always shows a fraction or exponent, as TOML floats need; ±inf is `inf`.
        format!("{v:?}")
    } else {
        format!("{v:e}")
    }
}

//! Human-readable output for the `sph-impact materials` command: one material in full
//! ([`MaterialSpec::describe`]) and a Markdown table of several ([`table`]).

use crate::materials::damage_spec::DamageSpec;
use crate::materials::sections::{
    Section, Value, damage_section, eos_section, strength_section, thermal_section,
};
use crate::materials::spec::MaterialSpec;
use crate::materials::toml_write::number;
use sph_eos::EquationOfState;
use sph_strength::{BuiltinStrength, StrengthModel};
use std::fmt::Write;

/// `v` rounded to `digits` significant digits, positional, trailing zeros dropped
/// (`53.06`, `4451`, `22.7`).
fn sig(v: f64, digits: i32) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (digits - 1 - v.abs().log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

/// `key = value, ...` of a section, values exact.
fn params(s: &Section) -> String {
    s.params
        .iter()
        .map(|p| match &p.value {
            Value::Num(x) => format!("{} = {}", p.key, number(*x)),
            Value::Str(x) => format!("{} = {x}", p.key),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

impl MaterialSpec {
    /// A multi-line description: every model with all its parameters, the derived
    /// elastic constants and the sources.
    ///
    /// ```
    /// let text = sph_impact::materials::MaterialSpec::basalt_study().describe();
    /// assert!(text.contains("lundborg"));
    /// assert!(text.contains("E = 53.06 GPa"));
    /// ```
    pub fn describe(&self) -> String {
        let mut out = String::new();
        let w = &mut out;
        let _ = writeln!(
            w,
            "{}{}",
            self.name,
            if self.is_fluid() { " (fluid)" } else { "" }
        );
        let _ = writeln!(w, "  density   {} kg/m^3", number(self.density));
        let _ = match eos_section(&self.eos) {
            Some(s) => writeln!(w, "  EOS       {}: {}", self.eos.name(), params(&s)),
            None => {
                let show = |v: Option<f64>| v.map_or("none".into(), number);
                writeln!(
                    w,
                    "  EOS       {} (user-defined; rho0 = {} kg/m^3, c0 = {} m/s)",
                    self.eos.name(),
                    show(self.eos.reference_density()),
                    show(self.eos.reference_sound_speed())
                )
            }
        };
        let _ = match strength_section(&self.strength) {
            Some(s) if s.params.is_empty() => writeln!(w, "  strength  {}", self.strength.name()),
            Some(s) => writeln!(w, "  strength  {}: {}", self.strength.name(), params(&s)),
            None => writeln!(w, "  strength  {} (user-defined)", self.strength.name()),
        };
        let _ = match damage_section(&self.damage) {
            Some(d) if d.params.is_empty() => writeln!(w, "  damage    {}", self.damage.name()),
            Some(d) => writeln!(w, "  damage    {}: {}", self.damage.name(), params(&d)),
            None => writeln!(w, "  damage    {} (user-defined)", self.damage.name()),
        };
        let _ = match &self.thermal {
            Some(t) => writeln!(
                w,
                "  thermal   {}; melting {}-{} MJ/kg, vaporisation {}-{} MJ/kg",
                params(&thermal_section(t)),
                sig(t.incipient_melting_energy() / 1e6, 4),
                sig(t.complete_melting_energy() / 1e6, 4),
                sig(t.incipient_vaporisation_energy() / 1e6, 4),
                sig(t.complete_vaporisation_energy() / 1e6, 4),
            ),
            None => writeln!(w, "  thermal   none"),
        };
        let mut elastic = format!("G = {} GPa", sig(self.shear_modulus / 1e9, 4));
        if let (Some(k), Some(e), Some(nu), Some(cl)) = (
            self.bulk_modulus(),
            self.youngs_modulus(),
            self.poisson_ratio(),
            self.longitudinal_wave_speed(),
        ) {
            let _ = write!(
                elastic,
                ", K = {} GPa, E = {} GPa, nu = {}, c_L = {} m/s, c_s = {} m/s",
                sig(k / 1e9, 4),
                sig(e / 1e9, 4),
                sig(nu, 4),
                sig(cl, 4),
                sig(self.shear_wave_speed(), 4)
            );
        }
        let _ = writeln!(w, "  elastic   {elastic} (reference state)");
        for (i, s) in self.sources.iter().enumerate() {
            let _ = writeln!(w, "  {}  {s}", if i == 0 { "sources " } else { "        " });
        }
        out
    }

    /// The parameters that set the strength and damage at a glance, e.g.
    /// `Y0 26.5 MPa, mu 0.6, Y_M 300 MPa, mu_d 0.6; k 2.7e41 m^-3, m 10`.
    pub fn key_parameters(&self) -> String {
        let mpa = |v: f64| sig(v / 1e6, 4);
        let strength = match &self.strength.builtin() {
            None => format!("{} (user-defined)", self.strength.name()),
            Some(BuiltinStrength::None) => String::new(),
            Some(BuiltinStrength::VonMises(m)) => {
                let p = m.params();
                match p.hardening {
                    Some(h) => format!("Y {} MPa, H {} MPa", mpa(p.yield_strength), mpa(h.modulus)),
                    None => format!("Y {} MPa", mpa(p.yield_strength)),
                }
            }
            Some(BuiltinStrength::DruckerPrager(m)) => {
                let p = m.params();
                frictional(p.cohesion, p.friction, p.limit_strength, p.damaged_friction)
            }
            Some(BuiltinStrength::Lundborg(m)) => {
                let p = m.params();
                frictional(p.cohesion, p.friction, p.limit_strength, p.damaged_friction)
            }
            Some(BuiltinStrength::JohnsonCook(m)) => {
                let p = m.params();
                format!(
                    "A {} MPa, B {} MPa, n {}, C {}, m {}, T_m {} K",
                    mpa(p.a),
                    mpa(p.b),
                    p.n,
                    p.c,
                    p.m,
                    p.melt_temperature
                )
            }
            Some(BuiltinStrength::SteinbergGuinan(m)) => {
                let p = m.params();
                format!(
                    "Y0 {} MPa, Y_max {} MPa, beta {}, n {}",
                    mpa(p.yield_strength),
                    mpa(p.max_yield_strength),
                    p.hardening_coefficient,
                    p.hardening_exponent
                )
            }
        };
        let damage = match &self.damage {
            DamageSpec::None => String::new(),
            DamageSpec::MaxTensileStress { sigma_b, .. } => {
                format!("sigma_b {} MPa", mpa(*sigma_b))
            }
            DamageSpec::BenzAsphaug { k, m, .. } => format!("k {k:e} m^-3, m {m}"),
            DamageSpec::Custom(_) => "user-defined".to_owned(),
        };
        match (strength.is_empty(), damage.is_empty()) {
            (false, false) => format!("{strength}; {damage}"),
            (true, _) => damage,
            (_, true) => strength,
        }
    }
}

/// A Markdown table of materials: name, density, models, G, K, E, c_L and the key
/// strength and damage parameters.
///
/// ```
/// let t = sph_impact::materials::table(&sph_impact::materials::library());
/// assert!(t.lines().nth(2).unwrap().starts_with("| basalt-study | 2876 |"));
/// ```
pub fn table(materials: &[MaterialSpec]) -> String {
    let mut out = String::from(
        "| material | rho0 (kg/m^3) | EOS | strength | damage | G (GPa) | K (GPa) | E (GPa) | c_L (m/s) | key parameters |\n\
         |---|---|---|---|---|---|---|---|---|---|\n",
    );
    let opt = |v: Option<f64>, scale: f64| v.map_or("-".into(), |x| sig(x / scale, 4));
    for m in materials {
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            m.name,
            sig(m.density, 4),
            m.eos.name(),
            m.strength.name(),
            m.damage.name(),
            sig(m.shear_modulus / 1e9, 4),
            opt(m.bulk_modulus(), 1e9),
            opt(m.youngs_modulus(), 1e9),
            opt(m.longitudinal_wave_speed(), 1.0),
            m.key_parameters()
        );
    }
    out
}

/// The parameters of a pressure-dependent (frictional) strength model.
fn frictional(cohesion: f64, friction: f64, limit: f64, damaged_friction: f64) -> String {
    let mpa = |v: f64| sig(v / 1e6, 4);
    format!(
        "Y0 {} MPa, mu {}, Y_M {} MPa, mu_d {}",
        mpa(cohesion),
        friction,
        mpa(limit),
        damaged_friction
    )
}

//! # Material models
//!
//! A material is the composition of (paper §3; design.md):
//!
//! - an equation of state ([`EosChoice`]: Tillotson, Mie–Grüneisen, Murnaghan, linear
//!   elastic, ideal gas, or the user's own `EquationOfState`);
//! - a strength model ([`StrengthChoice`]: none, von Mises, Drucker–Prager, Lundborg,
//!   Johnson–Cook, Steinberg–Guinan, or the user's own `StrengthModel`);
//! - a damage model as a specification ([`DamageSpec`]: none, maximum tensile stress,
//!   Benz–Asphaug), turned into a model per body with its seeded flaws by
//!   [`DamageSpec::build`];
//! - thermal data (`sph_eos::ThermalModel`: T(e) with melting and vaporisation);
//! - the reference density and shear modulus, from which K, E, ν and the longitudinal
//!   wave speed c_L = √((K + 4G/3)/ρ) follow;
//! - the sources of its parameters.
//!
//! [`MaterialSpec`] holds them and [`MaterialSpec::validate`]s their consistency (density
//! = EOS ρ0, G = the strength model's G, temperature-dependent strength has thermal data,
//! damage parameters in range). [`library()`] lists the built-in materials with their
//! sources (the study's basalt and aluminium 2024, granite, iron, copper, ice), and
//! material files are read and written as TOML ([`MaterialSpec::from_toml_file`],
//! [`MaterialSpec::to_toml`]) with typed errors naming file, line and key.
//!
//! ```
//! use sph_impact::materials::{builtin, DamageSpec, MaterialSpec};
//!
//! let basalt = builtin("basalt-study")?;
//! basalt.validate()?;
//! assert!(!basalt.is_fluid());
//! // E = 9KG/(3K + G) with K = A = 26.7 GPa, G = 22.7 GPa (paper §3.3).
//! assert!((basalt.youngs_modulus().unwrap() / 53.06e9 - 1.0).abs() < 1e-3);
//! // c_L = √((K + 4G/3)/ρ): 4593.3 m/s at the 2700 kg/m³ of docs/verification.md, "Solid
//! // dynamics: elastic bars".
//! assert!((basalt.longitudinal_wave_speed_at(2700.0).unwrap() - 4593.3).abs() < 0.1);
//!
//! // Benz–Asphaug flaws are seeded per body: same volumes and seed, same flaws.
//! let volumes = vec![1.0e-9; 100];
//! assert_eq!(basalt.damage.build(&volumes, 7)?, basalt.damage.build(&volumes, 7)?);
//!
//! // A material file overriding one parameter of a built-in.
//! let text = "name = \"strong-basalt\"\nbase = \"basalt-study\"\n[strength]\ncohesion = 30e6\n";
//! let strong = MaterialSpec::from_toml_str(text, "strong.toml")?;
//! assert_eq!(strong.density, 2876.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The solver still takes the fluid-only [`crate::Material`];
//! [`MaterialSpec::hydrodynamic_material`] gives it until the solver adopts
//! [`MaterialSpec`].

mod build;
mod damage_spec;
mod describe;
mod eos_choice;
mod error;
pub mod library;
pub mod parameter_sets;
mod presets;
mod sections;
mod spec;
mod strength_choice;
mod toml_read;
mod toml_schema;
mod toml_write;

pub use damage_spec::{CustomDamage, DamageSpec};
pub use describe::table;
pub use eos_choice::EosChoice;
pub use error::{Location, MaterialError};
pub use library::{BUILTIN_NAMES, builtin, library};
pub use presets::{PresetKind, preset_names};
pub use spec::{MAX_DENSITY, MaterialSpec, REFERENCE_TEMPERATURE};
pub use strength_choice::StrengthChoice;

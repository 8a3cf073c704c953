//! # sph-eos
//!
//! Equations of state for SPH behind the [`EquationOfState`] trait: pressure, bulk sound
//! speed and the derivatives ∂P/∂ρ|_e, ∂P/∂e|_ρ from density ρ (kg/m³) and specific
//! internal energy e (J/kg), in SI units, compression positive.
//!
//! - [`IdealGas`]: P = (γ − 1)ρe.
//! - [`Tillotson`]: Tillotson (1962), all four regions as in docs/reference/tillotson.md, Bμ²
//!   kept, analytic derivatives, no hidden cutoffs; named parameter sets
//!   ([`TillotsonParams::basalt_study`], [`TillotsonParams::aluminium_study`], ...).
//! - [`MieGruneisen`]: Mie–Grüneisen on a linear U_s–u_p Hugoniot.
//! - [`Murnaghan`] and [`LinearElastic`].
//! - [`ThermalModel`]: temperature from e with latent-heat plateaus at T_melt and T_vap, and
//!   melt/vapour fractions (paper §3.1), with handbook data for aluminium and basalt.
//! - [`hugoniot`]: the principal shock Hugoniot of any EOS at a given particle velocity.
//!
//! Sound speed everywhere: c² = ∂P/∂ρ|_e + (P/ρ²) ∂P/∂e|_ρ, floored at a documented
//! fraction of the reference sound speed and flagged ([`EosPoint::sound_speed_floored`]),
//! never silently clamped.
//!
//! ```
//! use sph_eos::{EquationOfState, Tillotson, TillotsonParams, TillotsonRegion, hugoniot};
//!
//! let basalt = Tillotson::new(TillotsonParams::basalt_ba99())?;
//! // docs/reference/tillotson.md, "Check points": ρ = 1.1 ρ0, e = 0 gives
//! // P = Aμ + Bμ² = 2.937 GPa.
//! let p = basalt.evaluate(1.1 * 2700.0, 0.0);
//! assert!((p.pressure - 2.937e9).abs() < 1e-6 * 2.937e9);
//! assert!(!p.sound_speed_floored);
//! assert_eq!(basalt.region(0.8 * 2700.0, 1.0e7), TillotsonRegion::Intermediate);
//!
//! // Symmetric basalt–basalt impact at 5 km/s: u_p = 2.5 km/s, U_s ≈ 7.13 km/s.
//! let h = hugoniot(&basalt, 2700.0, 2500.0)?;
//! assert!((h.shock_speed - 7130.5).abs() < 1.0);
//!
//! // Object-safe: mix EOSs behind one type.
//! let eoss: Vec<Box<dyn EquationOfState>> = vec![
//!     Box::new(basalt),
//!     Box::new(sph_eos::IdealGas::with_gamma(1.5)?),
//! ];
//! assert_eq!(eoss[1].pressure(1.0, 2.0), 1.0); // (γ − 1)ρe
//! # Ok::<(), sph_eos::EosError>(())
//! ```
//!
//! Temperature with latent heats:
//!
//! ```
//! use sph_eos::ThermalModel;
//! let al = ThermalModel::aluminium();
//! let e_half = al.incipient_melting_energy() + 0.5 * al.params().L_melt;
//! assert_eq!(al.temperature(e_half), al.params().T_melt); // on the melting plateau
//! assert!((al.melt_fraction(e_half) - 0.5).abs() < 1e-12);
//! ```
//!
//! ## Feature flags
//! None.

mod eos;
mod error;
mod hugoniot;
mod ideal_gas;
mod mie_gruneisen;
mod murnaghan;
mod thermal;
mod thermal_materials;
mod tillotson;
mod tillotson_materials;

pub use eos::{DEFAULT_SOUND_SPEED_FLOOR_FRACTION, EosPoint, EquationOfState};
pub use error::EosError;
pub use hugoniot::{HugoniotState, hugoniot};
pub use ideal_gas::{IdealGas, IdealGasParams};
pub use mie_gruneisen::{MieGruneisen, MieGruneisenParams};
pub use murnaghan::{LinearElastic, LinearElasticParams, Murnaghan, MurnaghanParams};
pub use thermal::{ThermalModel, ThermalParams, ThermalState};
pub use tillotson::{Tillotson, TillotsonParams, TillotsonRegion};

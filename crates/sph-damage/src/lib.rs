//! # sph-damage
//!
//! Damage D ∈ [0, 1] of brittle solids, scalar or directional ([`tensor`]), (paper §3.3) behind the [`DamageModel`]
//! trait: the maximum-tensile-stress model ([`MaxTensileStress`]), Benz–Asphaug
//! Weibull flaws with crack growth ([`BenzAsphaug`], flaws in a [`FlawSet`] seeded
//! reproducibly with rand_pcg, optionally continued past the strongest seeded flaw,
//! [`FlawTail`]), and [`NoDamage`]; and, added to either, shear failure from plastic
//! strain ([`PlasticFailure`], Collins et al. 2004). Damage weakens tension and the
//! deviatoric stress elsewhere (paper §2, sph-strength); this crate only evolves D.
//!
//! All quantities are f64 in SI units, stress and strain tension-positive.
//!
//! The solver integrates s = D^(1/3) (see [`model`] for why, and for the local strain
//! ε = σ_1/((1 − D)E) that activates flaws), then applies the model's bounds with
//! [`apply_bounds`], which reports every clamp.
//!
//! ```
//! use sph_damage::{
//!     apply_bounds, youngs_modulus, BenzAsphaug, BenzAsphaugParams, BoundAction,
//!     DamageInput, DamageModel, WeibullParams,
//! };
//!
//! // The study's basalt target: Ø123.3 × 123.3 mm cylinder, k = 2.7e41 m⁻³, m = 10.
//! let weibull = WeibullParams::BASALT_STUDY;
//! let e = youngs_modulus(26.7e9, 22.7e9); // 53.06 GPa
//! let volume = std::f64::consts::PI * 0.06165_f64.powi(2) * 0.1233;
//! let sigma_b = weibull.static_strength(e, volume);
//! assert!((sigma_b / 7.34e6 - 1.0).abs() < 5e-3); // paper §3.3: 7.34 MPa
//!
//! // Seed 1000 particles' flaws (reproducible: same seed, same flaws).
//! let model = BenzAsphaug::seed(BenzAsphaugParams::new(weibull, 42), 1000, volume).unwrap();
//! assert!(model.flaws().n_flaws(0).unwrap() >= 1);
//!
//! // A particle strained just past its weakest flaw starts to crack.
//! let eps = model.flaws().min_threshold(7).unwrap();
//! let input = DamageInput {
//!     max_principal_stress: 1.001 * eps * e,
//!     youngs_modulus: e,
//!     longitudinal_wave_speed: 4593.3,
//!     particle_size: 1.0e-3,
//!     damage: 0.0,
//!     principal_strain: None,
//! };
//! let eval = model.evaluate(7, &input);
//! assert!(eval.rate > 0.0); // d(D^(1/3))/dt = n_act · 0.4 c_L / R_s
//! // One explicit step of s = D^(1/3), bounded by D ≤ n_act/n_tot.
//! let s = 0.0 + 1.0e-6 * eval.rate;
//! let bounded = apply_bounds(model.variable(), s, eval.bounds);
//! assert!(bounded.damage <= eval.bounds.max);
//! assert_eq!(bounded.action, BoundAction::CappedAtMax); // 1 µs lets the crack outgrow the cap
//! ```
//!
//! ## Feature flags
//! None.

pub mod activation;
pub mod benz_asphaug;
pub mod body;
pub mod choice;
pub mod coupling;
pub mod decoupling;
pub mod elastic;
pub mod error;
pub mod flaw_tail;
pub mod model;
pub mod none;
pub mod params;
pub mod pressure;
pub mod shear_failure;
pub mod tensile;
pub mod tensor;
pub mod weibull;

pub use activation::ActivationStrain;
pub use benz_asphaug::{BenzAsphaug, BenzAsphaugParams, CRACK_SPEED_FRACTION_BA94, GrowthLaw};
pub use body::{BodyDamage, BodyParticles};
pub use choice::BuiltinDamage;
pub use coupling::{StressCoupling, fsisph_factor, pair_is_tensile, pair_max_factor};
pub use elastic::{longitudinal_speed, longitudinal_wave_speed, poisson_ratio, youngs_modulus};
pub use error::DamageError;
pub use flaw_tail::FlawTail;
pub use model::{
    BoundAction, Bounded, DamageBounds, DamageEval, DamageInput, DamageModel, DamageVariable,
    apply_bounds, max_principal_stress, max_principal_stress_bound,
};
pub use none::NoDamage;
pub use params::{NamedWeibull, WeibullParams};
pub use pressure::damaged_pressure;
pub use shear_failure::PlasticFailure;
pub use tensile::{MaxTensileStress, TensileFailure};
pub use tensor::{DamageForm, DirectionalGrowth, GrowthOutcome};
pub use weibull::{FlawSet, min_activation_strain, static_strength};

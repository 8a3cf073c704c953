//! Which strain activates the flaws: [`ActivationStrain`].
//!
//! * [`ActivationStrain::Stress`] (default): the local tensile strain of the stress,
//!   ε = σ_1/((1 − D)E) (Benz & Asphaug 1994, Icarus 107:98; 1995, CPC 87:253). Only
//!   tension activates flaws, and only as far as the material carries it: once it yields,
//!   the stress, and with it ε, stops growing.
//! * [`ActivationStrain::PseudoPlastic`]: the largest principal value of the
//!   pseudo-plastic strain ε_pp = ∫ (dS/dt)_elastic / G dt, divided by (1 − D). The
//!   integrand is the elastic (trial) Jaumann rate of the deviatoric stress *before* the
//!   radial return, so ε_pp keeps growing while the material flows plastically: shear
//!   flow activates flaws even under compression, as a strain measure rather than a
//!   stress. In the elastic range ε_pp = S/G = 2e' (e' the deviatoric elastic strain).
//!   This is the default strain of LLNL Spheral's probabilistic (Benz–Asphaug) damage
//!   model (its `PseudoPlasticStrain`), the code the reference study modified (paper
//!   header); the study does not say which strain it used.
//!
//! The solver tracks ε_pp only for materials whose damage model asks for it
//! ([`crate::DamageModel::activation_strain`]) and passes its largest eigenvalue in
//! [`crate::DamageInput::principal_strain`].

use serde::{Deserialize, Serialize};

/// The strain compared with the flaws' activation thresholds (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ActivationStrain {
    /// ε = σ_1/((1 − D)E), σ_1 the largest principal total stress.
    #[default]
    Stress,
    /// ε = λ_max(ε_pp)/(1 − D), ε_pp the integrated elastic trial deviatoric stress rate
    /// over the shear modulus (Spheral's pseudo-plastic strain).
    PseudoPlastic,
}

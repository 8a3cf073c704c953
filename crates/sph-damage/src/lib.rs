//! # sph-damage
//!
//! Scalar damage D ∈ [0, 1] and its evolution.
//!
//! **Status:** scaffold. This crate will own (issue "Material models"): the
//! `DamageModel` trait; maximum tensile stress; Benz–Asphaug Weibull flaws seeded
//! reproducibly with rand_pcg; crack growth at 0.4 × the longitudinal wave speed.

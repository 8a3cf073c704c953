//! # sph-strength
//!
//! Shear strength as a function of pressure, temperature, plastic strain and damage.
//!
//! **Status:** scaffold. This crate will own (issue "Material models"): the
//! `StrengthModel` trait; none (fluid), constant (von Mises), Drucker–Prager, Lundborg,
//! Johnson–Cook, Steinberg–Guinan; damage weakening (paper eqs 12–13); the Jaumann rate
//! of the deviatoric stress and the radial return as plain functions.

//! # sph-eos
//!
//! Equations of state behind the `EquationOfState` trait: pressure and sound speed from
//! density and specific internal energy, with the derivatives the Riemann solver needs.
//!
//! **Status:** scaffold. This crate will own (issues "Riemann-SPH hydrodynamics" and
//! "Material models"): the ideal gas; Tillotson with all four regions, analytic
//! derivatives and a temperature that accounts for the latent heats of melting and
//! vaporisation; Mie–Grüneisen; Murnaghan / linear elastic.

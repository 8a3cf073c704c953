//! # sph-riemann
//!
//! The pair terms of Riemann-SPH.
//!
//! **Status:** scaffold. This crate will own (issue "Riemann-SPH hydrodynamics"): wave
//! speed estimates (acoustic, Davis), the HLLC / acoustic star state, limited linear
//! reconstruction along the pair axis, the interface velocity v* with the damage /
//! material coupling b_ij (paper §2.1), Monaghan artificial viscosity (§2.2) and the
//! artificial stress (§2.3).

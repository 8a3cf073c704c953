//! sph-diagnostics: exact solutions against the reference values of verification.md, and
//! the impact diagnostics and writers on hand-made particle sets.

mod crater;
mod riemann;
mod sedov_noh;
mod vtk;

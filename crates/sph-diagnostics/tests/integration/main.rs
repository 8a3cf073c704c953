//! sph-diagnostics: exact solutions against the reference values of verification.md.

mod riemann;
mod sedov_noh;

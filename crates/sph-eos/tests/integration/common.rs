//! Shared helpers: central differences and relative comparisons.

use sph_eos::EquationOfState;

/// Relative difference |a − b| / |b| (absolute when b = 0).
pub fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// Central differences (∂P/∂ρ|_e, ∂P/∂e|_ρ) with steps hρ, he.
pub fn fd<E: EquationOfState + ?Sized>(
    eos: &E,
    rho: f64,
    e: f64,
    h_rho: f64,
    h_e: f64,
) -> (f64, f64) {
    let dr = (eos.pressure(rho + h_rho, e) - eos.pressure(rho - h_rho, e)) / (2.0 * h_rho);
    let de = (eos.pressure(rho, e + h_e) - eos.pressure(rho, e - h_e)) / (2.0 * h_e);
    (dr, de)
}

/// c² along the isentrope de = (P/ρ²) dρ by a central difference: the thermodynamic
/// definition c² = (∂P/∂ρ)_s, independent of the analytic derivatives.
pub fn isentropic_c2<E: EquationOfState + ?Sized>(eos: &E, rho: f64, e: f64, h: f64) -> f64 {
    let s = eos.pressure(rho, e) / (rho * rho);
    (eos.pressure(rho + h, e + s * h) - eos.pressure(rho - h, e - s * h)) / (2.0 * h)
}

/// |analytic − fd| within `rtol` of the larger magnitude plus `atol`.
pub fn close(analytic: f64, numeric: f64, rtol: f64, atol: f64) -> bool {
    (analytic - numeric).abs() <= rtol * analytic.abs().max(numeric.abs()) + atol
}

//! Principal shock Hugoniot of an EOS from the ambient state (ρ0, e0 = 0, P0 = 0) at a
//! given particle velocity: the reference for planar-impact tests and impedance matching
//! (docs/reference/tillotson.md, "Shock Hugoniot and planar impact").
//!
//! Rankine–Hugoniot jump conditions with e0 = P0 = 0 (e.g. Meyers 1994, *Dynamic Behavior
//! of Materials*, shock-wave chapter):
//! mass ρ0 U_s = ρ (U_s − u_p), momentum P = ρ0 U_s u_p, energy e = ½ P (1/ρ0 − 1/ρ) = ½ u_p².
//! Eliminating U_s leaves one equation for ρ at fixed u_p:
//!
//! F(ρ) = P_EOS(ρ, ½u_p²) − ρ0 u_p² ρ/(ρ − ρ0) = 0,  ρ > ρ0,
//!
//! solved in x = ρ − ρ0 (no cancellation near ρ0) by safeguarded Newton (analytic ∂P/∂ρ
//! from [`EquationOfState::evaluate`]) inside a bisection bracket. F → −∞ as ρ → ρ0⁺; the
//! upper bracket is grown by doubling x and, if it leaves the EOS's range
//! ([`EquationOfState::check_state`], e.g. Mie–Grüneisen's limiting compression), pulled
//! back by bisection towards the last valid point. For an EOS whose P grows with ρ on
//! compression the root is unique.

use crate::eos::EquationOfState;
use crate::error::EosError;

/// One state on the principal Hugoniot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HugoniotState {
    /// Particle velocity u_p behind the shock, m/s (the input).
    pub particle_velocity: f64,
    /// Shocked density ρ, kg/m³.
    pub density: f64,
    /// Shocked pressure P = P_EOS(ρ, e), Pa.
    pub pressure: f64,
    /// Shock speed U_s = u_p ρ/(ρ − ρ0), m/s (mass conservation).
    pub shock_speed: f64,
    /// Specific internal energy behind the shock, e = ½u_p², J/kg.
    pub specific_energy: f64,
    /// Newton/bisection iterations used after bracketing.
    pub iterations: u32,
}

/// The Hugoniot state at particle velocity `particle_velocity` (m/s, ≥ 0) of `eos`
/// starting from (ρ0 = `rho0`, e0 = 0, P0 = 0).
///
/// Errors: ρ0 or u_p not finite/non-negative; P(ρ0, 0) not zero (to 1e-9 ρ0 c²; the
/// jump conditions used assume P0 = 0); no bracket or no convergence. At u_p = 0 it
/// returns ρ0, P0 and U_s = c(ρ0, 0), the weak-shock limit.
pub fn hugoniot<E: EquationOfState + ?Sized>(
    eos: &E,
    rho0: f64,
    particle_velocity: f64,
) -> Result<HugoniotState, EosError> {
    let up = particle_velocity;
    let fail = |reason| EosError::Hugoniot {
        particle_velocity: up,
        rho0,
        reason,
    };
    if !(rho0.is_finite() && rho0 > 0.0) {
        return Err(fail("rho0 must be positive and finite"));
    }
    if !(up.is_finite() && up >= 0.0) {
        return Err(fail(
            "particle velocity must be finite and >= 0 (a shock compresses)",
        ));
    }
    eos.check_state(rho0, 0.0)?;
    let ambient = eos.evaluate(rho0, 0.0);
    if !(ambient.pressure.abs() <= 1e-9 * rho0 * ambient.sound_speed * ambient.sound_speed) {
        return Err(fail(
            "P(rho0, e = 0) must be 0: the jump conditions assume P0 = e0 = 0",
        ));
    }
    if up == 0.0 {
        return Ok(HugoniotState {
            particle_velocity: 0.0,
            density: rho0,
            pressure: ambient.pressure,
            shock_speed: ambient.sound_speed,
            specific_energy: 0.0,
            iterations: 0,
        });
    }

    let e = 0.5 * up * up;
    let q = rho0 * up * up;
    // F(x) and F'(x), or None outside the EOS's range.
    let f = |x: f64| -> Option<(f64, f64)> {
        let rho = rho0 + x;
        eos.check_state(rho, e).ok()?;
        let p = eos.evaluate(rho, e);
        let value = p.pressure - q * rho / x;
        let slope = p.dp_drho + q * rho0 / (x * x);
        (value.is_finite() && slope.is_finite()).then_some((value, slope))
    };

    // Upper bracket: F(hi) > 0.
    let mut x = rho0;
    let mut x_bad = f64::INFINITY; // smallest x found outside the EOS range
    let mut hi = None;
    for _ in 0..400 {
        match f(x) {
            Some((v, _)) if v > 0.0 => {
                hi = Some(x);
                break;
            }
            Some(_) => {
                x = if x_bad.is_finite() {
                    0.5 * (x + x_bad)
                } else {
                    2.0 * x
                };
            }
            None => {
                x_bad = x;
                x *= 0.5;
            }
        }
    }
    let mut hi =
        hi.ok_or_else(|| fail("no density above rho0 where P_EOS exceeds the Rayleigh line"))?;
    // Lower bracket: F(lo) < 0 (F → −∞ as x → 0⁺).
    let mut lo = hi;
    loop {
        lo *= 0.5;
        if lo == 0.0 {
            return Err(fail(
                "no density just above rho0 where P_EOS is below the Rayleigh line",
            ));
        }
        match f(lo) {
            Some((v, _)) if v < 0.0 => break,
            Some((v, _)) if v > 0.0 => hi = lo,
            Some(_) => return Ok(state(eos, rho0, up, e, lo, 0)),
            None => return Err(fail("EOS invalid between rho0 and the upper bracket")),
        }
    }

    // Safeguarded Newton inside [lo, hi].
    let mut x = 0.5 * (lo + hi);
    for it in 1..=200 {
        let Some((v, slope)) = f(x) else {
            return Err(fail("EOS invalid inside the bracket"));
        };
        if v == 0.0 {
            return Ok(state(eos, rho0, up, e, x, it));
        }
        if v < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - v / slope;
        let next = if slope > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let tol = 4.0 * f64::EPSILON * next;
        if (next - x).abs() <= tol || hi - lo <= tol {
            return Ok(state(eos, rho0, up, e, next, it));
        }
        x = next;
    }
    Err(fail("no convergence in 200 iterations"))
}

fn state<E: EquationOfState + ?Sized>(
    eos: &E,
    rho0: f64,
    up: f64,
    e: f64,
    x: f64,
    iterations: u32,
) -> HugoniotState {
    let rho = rho0 + x;
    HugoniotState {
        particle_velocity: up,
        density: rho,
        pressure: eos.pressure(rho, e),
        shock_speed: up * rho / x,
        specific_energy: e,
        iterations,
    }
}

//! The Noh implosion (Noh 1987; docs/verification.md, "Noh"): cold gas of density ρ0 streaming
//! at speed |v0| toward the origin (planar, cylindrical or spherical, d = 1, 2, 3) forms
//! a shock at r_s = (γ − 1)/2·|v0|·t. Inside: v = 0, e = v0²/2,
//! ρ2 = ρ0((γ+1)/(γ−1))^d, P2 = (γ−1)ρ2 e. Outside: v = −|v0|, e = 0,
//! ρ = ρ0(1 + |v0|t/r)^(d−1).

use crate::error::{ExactError, check_geometry, check_positive};

/// The Noh problem.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Noh {
    /// Geometry: 1 planar, 2 cylindrical, 3 spherical.
    pub dim: u32,
    /// Adiabatic index γ.
    pub gamma: f64,
    /// Initial density ρ0.
    pub rho0: f64,
    /// Inflow speed |v0|.
    pub speed: f64,
}

/// The exact state at a radius: density, radial velocity, pressure, specific energy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadialState {
    /// Density.
    pub density: f64,
    /// Radial velocity (negative: inward).
    pub velocity: f64,
    /// Pressure.
    pub pressure: f64,
    /// Specific internal energy.
    pub specific_energy: f64,
}

impl Noh {
    /// Validated problem.
    pub fn new(dim: u32, gamma: f64, rho0: f64, speed: f64) -> Result<Self, ExactError> {
        check_geometry("dim", dim)?;
        if !(gamma > 1.0) {
            return Err(ExactError::BadGamma(gamma));
        }
        check_positive(&[("rho0", rho0), ("speed", speed)])?;
        Ok(Self {
            dim,
            gamma,
            rho0,
            speed,
        })
    }

    /// Shock radius at time t.
    pub fn shock_radius(&self, t: f64) -> f64 {
        0.5 * (self.gamma - 1.0) * self.speed * t
    }

    /// Post-shock density ρ2.
    pub fn post_shock_density(&self) -> f64 {
        self.rho0 * ((self.gamma + 1.0) / (self.gamma - 1.0)).powi(self.dim as i32)
    }

    /// The exact state at radius r ≥ 0 and time t > 0.
    pub fn state(&self, r: f64, t: f64) -> RadialState {
        if r < self.shock_radius(t) {
            let e = 0.5 * self.speed * self.speed;
            let rho = self.post_shock_density();
            RadialState {
                density: rho,
                velocity: 0.0,
                pressure: (self.gamma - 1.0) * rho * e,
                specific_energy: e,
            }
        } else {
            RadialState {
                density: self.rho0 * (1.0 + self.speed * t / r).powi(self.dim as i32 - 1),
                velocity: -self.speed,
                pressure: 0.0,
                specific_energy: 0.0,
            }
        }
    }
}

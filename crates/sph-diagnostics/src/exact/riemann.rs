//! The exact solution of the ideal-gas Riemann problem (Toro, *Riemann Solvers and
//! Numerical Methods for Fluid Dynamics*, 3rd ed., ch. 4; docs/verification.md, "1-D Riemann
//! problems").

use crate::error::ExactError;

/// A primitive state (ρ, u, P) of an ideal gas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GasState {
    /// Density.
    pub density: f64,
    /// Velocity.
    pub velocity: f64,
    /// Pressure.
    pub pressure: f64,
}

/// The solved Riemann problem: the star region and enough to sample it anywhere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RiemannSolution {
    /// Left initial state.
    pub left: GasState,
    /// Right initial state.
    pub right: GasState,
    /// Adiabatic index.
    pub gamma: f64,
    /// Star pressure p*.
    pub p_star: f64,
    /// Star (contact) velocity u*.
    pub u_star: f64,
    /// Density left of the contact in the star region.
    pub rho_star_left: f64,
    /// Density right of the contact.
    pub rho_star_right: f64,
}

fn sound(s: &GasState, gamma: f64) -> f64 {
    (gamma * s.pressure / s.density).sqrt()
}

/// f_K(p) and its derivative (Toro eqs. 4.6–4.7, 4.37).
fn f_k(p: f64, s: &GasState, gamma: f64) -> (f64, f64) {
    let c = sound(s, gamma);
    if p > s.pressure {
        let a = 2.0 / ((gamma + 1.0) * s.density);
        let b = (gamma - 1.0) / (gamma + 1.0) * s.pressure;
        let q = (a / (p + b)).sqrt();
        (
            q * (p - s.pressure),
            q * (1.0 - 0.5 * (p - s.pressure) / (p + b)),
        )
    } else {
        let e = (gamma - 1.0) / (2.0 * gamma);
        let r = p / s.pressure;
        (
            2.0 * c / (gamma - 1.0) * (r.powf(e) - 1.0),
            r.powf(-(gamma + 1.0) / (2.0 * gamma)) / (s.density * c),
        )
    }
}

impl RiemannSolution {
    /// Solves the problem by Newton iteration on f_L(p) + f_R(p) + u_R − u_L = 0 from the
    /// two-rarefaction guess (Toro §4.3), to relative 1e-14.
    pub fn solve(left: GasState, right: GasState, gamma: f64) -> Result<Self, ExactError> {
        for (side, s) in [("left", left), ("right", right)] {
            let physical = s.density > 0.0 && s.pressure > 0.0 && s.velocity.is_finite();
            if !physical {
                return Err(ExactError::BadState {
                    side,
                    density: s.density,
                    pressure: s.pressure,
                });
            }
        }
        if !(gamma > 1.0) {
            return Err(ExactError::BadGamma(gamma));
        }
        let (cl, cr) = (sound(&left, gamma), sound(&right, gamma));
        let du = right.velocity - left.velocity;
        // Pressure positivity condition (Toro eq. 4.40): otherwise vacuum forms.
        if 2.0 * (cl + cr) / (gamma - 1.0) <= du {
            return Err(ExactError::Vacuum);
        }
        let e = (gamma - 1.0) / (2.0 * gamma);
        let mut p = ((cl + cr - 0.5 * (gamma - 1.0) * du)
            / (cl / left.pressure.powf(e) + cr / right.pressure.powf(e)))
        .powf(1.0 / e);
        p = p.max(1e-14 * (left.pressure + right.pressure));
        for _ in 0..200 {
            let (fl, dl) = f_k(p, &left, gamma);
            let (fr, dr) = f_k(p, &right, gamma);
            let step = (fl + fr + du) / (dl + dr);
            let mut next = p - step;
            if next <= 0.0 {
                next = 0.5 * p;
            }
            let change = 2.0 * (next - p).abs() / (next + p);
            p = next;
            if change < 1e-15 {
                break;
            }
        }
        let (fl, _) = f_k(p, &left, gamma);
        let (fr, _) = f_k(p, &right, gamma);
        let u = 0.5 * (left.velocity + right.velocity) + 0.5 * (fr - fl);
        let g = (gamma - 1.0) / (gamma + 1.0);
        let rho_star = |s: &GasState| {
            let r = p / s.pressure;
            if p > s.pressure {
                s.density * (r + g) / (g * r + 1.0)
            } else {
                s.density * r.powf(1.0 / gamma)
            }
        };
        Ok(Self {
            left,
            right,
            gamma,
            p_star: p,
            u_star: u,
            rho_star_left: rho_star(&left),
            rho_star_right: rho_star(&right),
        })
    }

    /// The state at similarity coordinate ξ = (x − x0)/t (Toro §4.5).
    pub fn sample(&self, xi: f64) -> GasState {
        let g = self.gamma;
        let (l, r) = (self.left, self.right);
        let (p, u) = (self.p_star, self.u_star);
        if xi <= u {
            let c = sound(&l, g);
            if p > l.pressure {
                let s = l.velocity
                    - c * ((g + 1.0) / (2.0 * g) * p / l.pressure + (g - 1.0) / (2.0 * g)).sqrt();
                if xi <= s {
                    l
                } else {
                    GasState {
                        density: self.rho_star_left,
                        velocity: u,
                        pressure: p,
                    }
                }
            } else {
                let head = l.velocity - c;
                let c_star = c * (p / l.pressure).powf((g - 1.0) / (2.0 * g));
                let tail = u - c_star;
                if xi <= head {
                    l
                } else if xi >= tail {
                    GasState {
                        density: self.rho_star_left,
                        velocity: u,
                        pressure: p,
                    }
                } else {
                    let k = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * c) * (l.velocity - xi);
                    GasState {
                        density: l.density * k.powf(2.0 / (g - 1.0)),
                        velocity: 2.0 / (g + 1.0) * (c + 0.5 * (g - 1.0) * l.velocity + xi),
                        pressure: l.pressure * k.powf(2.0 * g / (g - 1.0)),
                    }
                }
            }
        } else {
            let c = sound(&r, g);
            if p > r.pressure {
                let s = r.velocity
                    + c * ((g + 1.0) / (2.0 * g) * p / r.pressure + (g - 1.0) / (2.0 * g)).sqrt();
                if xi >= s {
                    r
                } else {
                    GasState {
                        density: self.rho_star_right,
                        velocity: u,
                        pressure: p,
                    }
                }
            } else {
                let head = r.velocity + c;
                let c_star = c * (p / r.pressure).powf((g - 1.0) / (2.0 * g));
                let tail = u + c_star;
                if xi >= head {
                    r
                } else if xi <= tail {
                    GasState {
                        density: self.rho_star_right,
                        velocity: u,
                        pressure: p,
                    }
                } else {
                    let k = 2.0 / (g + 1.0) - (g - 1.0) / ((g + 1.0) * c) * (r.velocity - xi);
                    GasState {
                        density: r.density * k.powf(2.0 / (g - 1.0)),
                        velocity: 2.0 / (g + 1.0) * (-c + 0.5 * (g - 1.0) * r.velocity + xi),
                        pressure: r.pressure * k.powf(2.0 * g / (g - 1.0)),
                    }
                }
            }
        }
    }

    /// Speed of the right-going shock, if the right wave is a shock.
    pub fn right_shock_speed(&self) -> Option<f64> {
        let (g, r) = (self.gamma, self.right);
        (self.p_star > r.pressure).then(|| {
            r.velocity
                + sound(&r, g)
                    * ((g + 1.0) / (2.0 * g) * self.p_star / r.pressure + (g - 1.0) / (2.0 * g))
                        .sqrt()
        })
    }

    /// Speed of the left-going shock, if the left wave is a shock.
    pub fn left_shock_speed(&self) -> Option<f64> {
        let (g, l) = (self.gamma, self.left);
        (self.p_star > l.pressure).then(|| {
            l.velocity
                - sound(&l, g)
                    * ((g + 1.0) / (2.0 * g) * self.p_star / l.pressure + (g - 1.0) / (2.0 * g))
                        .sqrt()
        })
    }
}

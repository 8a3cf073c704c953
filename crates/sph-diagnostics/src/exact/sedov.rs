//! The Sedov–Taylor point blast in a uniform medium (Sedov 1959), in the closed form of
//! Kamm & Timmes (2007, LA-UR-07-2849, "On efficient generation of numerically robust
//! Sedov solutions"), standard case (uniform ambient density, ω = 0), for planar (ν = 1),
//! cylindrical (ν = 2) and spherical (ν = 3) geometry and any γ > 1.
//!
//! The profile is parametrised by the similarity variable V ∈ (V0, V2]; for each λ = r/R
//! the V with λ(V) = λ is found by bisection (λ is monotone in V). The energy integral
//! α (E = α ρ0 R^(ν+2)/t²) gives ξ0 = α^(−1/(ν+2)) and R(t) = ξ0 (E t²/ρ0)^(1/(ν+2)).

use crate::error::{ExactError, check_geometry, check_positive};
use crate::exact::noh::RadialState;

/// The Sedov problem: geometry ν, γ, blast energy E and ambient density ρ0.
///
/// In planar geometry E is the energy per unit area of both half-spaces together; in
/// cylindrical geometry per unit length (A_ν = 2, 2π, 4π; docs/verification.md, "Sedov–Taylor").
#[derive(Clone, Debug, PartialEq)]
pub struct Sedov {
    nu: u32,
    gamma: f64,
    energy: f64,
    rho0: f64,
    alpha: f64,
}

/// Exponents and coefficients of Kamm & Timmes' standard case (their eqs. 5–6, ω = 0).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Coefficients {
    nu: f64,
    gamma: f64,
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    e: f64,
    a0: f64,
    a1: f64,
    a2: f64,
    a3: f64,
    a4: f64,
    a5: f64,
    v0: f64,
    v2: f64,
}

impl Coefficients {
    fn new(nu: u32, g: f64) -> Self {
        let j = nu as f64;
        let j2 = j + 2.0;
        let a = j2 * (g + 1.0) / 4.0;
        let b = (g + 1.0) / (g - 1.0);
        let c = j2 * g / 2.0;
        let d = j2 * (g + 1.0) / (j2 * (g + 1.0) - 2.0 * (2.0 + j * (g - 1.0)));
        let e = (2.0 + j * (g - 1.0)) / 2.0;
        let a0 = 2.0 / j2;
        let a2 = -(g - 1.0) / (2.0 * (g - 1.0) + j);
        let a1 = j2 * g / (2.0 + j * (g - 1.0)) * (2.0 * j * (2.0 - g) / (g * j2 * j2) - a2);
        let a3 = j / (2.0 * (g - 1.0) + j);
        let a4 = j2 * j * a1 / (j * (2.0 - g));
        let a5 = -2.0 * j / (j * (2.0 - g));
        Self {
            nu: j,
            gamma: g,
            a,
            b,
            c,
            d,
            e,
            a0,
            a1,
            a2,
            a3,
            a4,
            a5,
            v0: 2.0 / (j2 * g),
            v2: 4.0 / (j2 * (g + 1.0)),
        }
    }

    /// (λ, f, g, h) at V: radius, velocity, density and pressure relative to the shock
    /// values (Kamm & Timmes eq. 4 with ω = 0).
    fn at(&self, v: f64) -> (f64, f64, f64, f64) {
        let x1 = self.a * v;
        let x2 = self.b * (self.c * v - 1.0);
        let x3 = self.d * (1.0 - self.e * v);
        let x4 = self.b * (1.0 - self.c * v / self.gamma);
        let lambda = x1.powf(-self.a0) * x2.powf(-self.a2) * x3.powf(-self.a1);
        let f = x1 * lambda;
        let g = x2.powf(self.a3) * x3.powf(self.a4) * x4.powf(self.a5);
        let h =
            x1.powf(self.a0 * self.nu) * x3.powf(self.a4 - 2.0 * self.a1) * x4.powf(1.0 + self.a5);
        (lambda, f, g, h)
    }

    /// V with λ(V) = lambda, by bisection on (V0, V2].
    fn v_of_lambda(&self, lambda: f64) -> f64 {
        let (mut lo, mut hi) = (self.v0, self.v2);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if self.at(mid).0 < lambda {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-16 * hi {
                break;
            }
        }
        0.5 * (lo + hi)
    }
}

impl Sedov {
    /// The solution for geometry `nu` (1, 2, 3), adiabatic index `gamma` (1 < γ < 2 for
    /// the standard closed form; γ = 2 and above hit singular exponents), blast energy
    /// and ambient density.
    pub fn new(nu: u32, gamma: f64, energy: f64, rho0: f64) -> Result<Self, ExactError> {
        check_geometry("nu", nu)?;
        if !(gamma > 1.0 && gamma < 2.0) {
            return Err(ExactError::BadParameter {
                name: "gamma",
                value: gamma,
                reason: "the closed form needs 1 < γ < 2",
            });
        }
        check_positive(&[("energy", energy), ("rho0", rho0)])?;
        let mut s = Self {
            nu,
            gamma,
            energy,
            rho0,
            alpha: 0.0,
        };
        s.alpha = s.energy_integral();
        Ok(s)
    }

    /// α of E = α ρ0 R^(ν+2)/t² (docs/verification.md, "Sedov–Taylor"):
    /// α = 8 A_ν/((γ²−1)(ν+2)²) ∫₀¹ (g f² + h) λ^(ν−1) dλ, integrated in V with
    /// composite Gauss–Legendre on a grid refined toward the centre.
    fn energy_integral(&self) -> f64 {
        let co = Coefficients::new(self.nu, self.gamma);
        let nu = self.nu as f64;
        let area =
            [2.0, 2.0 * std::f64::consts::PI, 4.0 * std::f64::consts::PI][self.nu as usize - 1];
        // Integrate over λ directly with many panels; the integrand is smooth in λ and
        // vanishes strongly at the centre.
        let panels = 4000;
        let gl = [
            (-0.774_596_669_241_483_4, 5.0 / 9.0),
            (0.0, 8.0 / 9.0),
            (0.774_596_669_241_483_4, 5.0 / 9.0),
        ];
        let mut sum = 0.0;
        for p in 0..panels {
            let (a, b) = (p as f64 / panels as f64, (p + 1) as f64 / panels as f64);
            for (x, w) in gl {
                let lam = 0.5 * (a + b) + 0.5 * (b - a) * x;
                let v = co.v_of_lambda(lam);
                let (_, _, g, h) = co.at(v);
                let f = co.a * v * lam;
                sum += 0.5 * (b - a) * w * (g * f * f + h) * lam.powf(nu - 1.0);
            }
        }
        8.0 * area / ((self.gamma * self.gamma - 1.0) * (nu + 2.0) * (nu + 2.0)) * sum
    }

    /// The energy integral α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }

    /// ξ0 = α^(−1/(ν+2)).
    pub fn xi0(&self) -> f64 {
        self.alpha.powf(-1.0 / (self.nu as f64 + 2.0))
    }

    /// Shock radius R(t) = ξ0 (E t²/ρ0)^(1/(ν+2)).
    pub fn shock_radius(&self, t: f64) -> f64 {
        self.xi0() * (self.energy * t * t / self.rho0).powf(1.0 / (self.nu as f64 + 2.0))
    }

    /// Profile relative to the shock state at λ = r/R ∈ [0, 1]: (v/v2, ρ/ρ2, P/P2).
    pub fn relative_profile(&self, lambda: f64) -> (f64, f64, f64) {
        let co = Coefficients::new(self.nu, self.gamma);
        if lambda >= 1.0 {
            return (1.0, 1.0, 1.0);
        }
        if lambda <= 0.0 {
            // The centre: v = ρ = 0 and the pressure plateau value (the limit V → V0).
            let (_, _, _, h) = co.at(co.v0 * (1.0 + 1e-13));
            return (0.0, 0.0, h);
        }
        let v = co.v_of_lambda(lambda);
        let (_, _, g, h) = co.at(v);
        // f = x1 λ identically. Using the requested λ (not λ(V) at the bisected V) keeps f
        // accurate near the centre, where for γ = 1.4 in 3-D λ ∝ (cV − 1)^0.105 puts V
        // within round-off of V0 for λ < 0.05.
        (co.a * v * lambda, g, h)
    }

    /// The exact state at radius r and time t > 0 (ambient pressure zero).
    pub fn state(&self, r: f64, t: f64) -> RadialState {
        let big_r = self.shock_radius(t);
        if r >= big_r {
            return RadialState {
                density: self.rho0,
                velocity: 0.0,
                pressure: 0.0,
                specific_energy: 0.0,
            };
        }
        let g = self.gamma;
        let vs = 2.0 * big_r / ((self.nu as f64 + 2.0) * t);
        let (rho2, u2, p2) = (
            self.rho0 * (g + 1.0) / (g - 1.0),
            2.0 * vs / (g + 1.0),
            2.0 * self.rho0 * vs * vs / (g + 1.0),
        );
        let (f, gg, h) = self.relative_profile(r / big_r);
        let (rho, p) = (rho2 * gg, p2 * h);
        RadialState {
            density: rho,
            velocity: u2 * f,
            pressure: p,
            specific_energy: if rho > 0.0 {
                p / ((g - 1.0) * rho)
            } else {
                f64::INFINITY
            },
        }
    }
}

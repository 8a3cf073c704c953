//! The one-dimensional state on each side of a pair's Riemann problem.

/// One side of the 1-D Riemann problem along the pair axis: density (kg/m³), normal
/// velocity u = v·r̂ (m/s), pressure (Pa, compression positive; for a solid the damaged
/// normal pressure) and signal speed c (m/s; the longitudinal wave speed for a solid).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SideState {
    /// Density ρ.
    pub density: f64,
    /// Velocity along the pair axis.
    pub velocity: f64,
    /// Pressure.
    pub pressure: f64,
    /// Sound (signal) speed.
    pub sound_speed: f64,
}

impl SideState {
    /// Acoustic impedance Z = ρ c.
    #[inline]
    pub fn impedance(&self) -> f64 {
        self.density * self.sound_speed
    }
}

/// The star state between the two waves: the interface (contact) velocity u* and
/// pressure P*.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StarState {
    /// Interface velocity u* along the pair axis.
    pub velocity: f64,
    /// Interface pressure P*.
    pub pressure: f64,
}

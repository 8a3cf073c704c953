//! The damaged pressure P_D: damage weakens tension, not compression (paper §2).
//!
//! σ = (1 − D) S − P_D I with P_D = (1 − D) P for P < 0 (tension) and P otherwise, so a
//! fully damaged particle carries no tension but still resists compression (paper §2;
//! Benz & Asphaug 1994, Icarus 107:98).

/// P_D = (1 − D) P in tension (P < 0), P in compression (paper §2).
#[inline]
pub fn damaged_pressure(pressure: f64, damage: f64) -> f64 {
    if pressure < 0.0 {
        (1.0 - damage) * pressure
    } else {
        pressure
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn damaged_pressure_weakens_tension_only() {
        assert_eq!(damaged_pressure(-10.0, 0.25), -7.5);
        assert_eq!(damaged_pressure(-10.0, 1.0), 0.0);
        assert_eq!(damaged_pressure(10.0, 0.7), 10.0);
        assert_eq!(damaged_pressure(0.0, 0.7), 0.0);
    }
}

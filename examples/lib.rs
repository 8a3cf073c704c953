//! Shared helpers of the examples: the experiment they compare with.

/// One experiment of paper Table 2 (Al 2024 sphere, D = 6 mm, into basalt), with the
/// study's own simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Experiment {
    /// Impact speed as in the scene file names (km/s).
    pub speed: &'static str,
    /// Impact speed (m/s).
    pub speed_m_s: f64,
    /// Crater diameter (m), spall zone included.
    pub diameter: f64,
    /// Crater depth (m).
    pub depth: f64,
    /// Momentum-transfer factor.
    pub beta: f64,
    /// The study's simulation: diameter (m), depth (m), β.
    pub study: (f64, f64, f64),
}

/// Paper Table 2.
pub const TABLE_2: [Experiment; 3] = [
    Experiment {
        speed: "2.3",
        speed_m_s: 2300.0,
        diameter: 42e-3,
        depth: 10e-3,
        beta: 1.96,
        study: (35e-3, 10e-3, 1.57),
    },
    Experiment {
        speed: "3.47",
        speed_m_s: 3470.0,
        diameter: 52e-3,
        depth: 12e-3,
        beta: 2.39,
        study: (43e-3, 14e-3, 2.02),
    },
    Experiment {
        speed: "3.9",
        speed_m_s: 3900.0,
        diameter: 55e-3,
        depth: 13.5e-3,
        beta: 2.51,
        study: (48e-3, 15e-3, 2.19),
    },
];

/// The experiment of Table 2 at impact speed `u` (m/s), within 1 %.
pub fn experiment_at(u: f64) -> Option<&'static Experiment> {
    TABLE_2
        .iter()
        .find(|e| (u / e.speed_m_s - 1.0).abs() < 0.01)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn experiments_are_found_by_speed() {
        assert_eq!(experiment_at(3900.0).unwrap().beta, 2.51);
        assert_eq!(experiment_at(2310.0).unwrap().speed, "2.3");
        assert!(experiment_at(3000.0).is_none());
    }
}

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

/// The numbers of one row of a run's `history.csv` that the examples compare.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HistoryRow {
    /// Simulated time (s).
    pub t: f64,
    /// Steps taken to `t`.
    pub step: f64,
    /// β from the ejecta.
    pub beta: f64,
    /// Crater depth (m).
    pub crater_depth: f64,
    /// Crater diameter, spall included (m).
    pub crater_diameter: f64,
}

/// The last row of the `history.csv` text `csv` at or before time `t` (s), found by the
/// column names. An error, naming the line, for a missing column or a bad number, and
/// when the history ends before `t` (a run that stopped early is not read as if it had
/// reached `t`).
pub fn history_row_at(csv: &str, t: f64) -> Result<HistoryRow, String> {
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap_or("").split(',').collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .ok_or_else(|| format!("no column `{name}`"))
    };
    let cols = [
        col("t_s")?,
        col("step")?,
        col("beta")?,
        col("crater_depth_m")?,
        col("crater_diameter_m")?,
    ];
    let (mut found, mut last_t) = (None, f64::NAN);
    for (k, line) in lines.enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        let mut v = [0.0; 5];
        for (slot, &c) in v.iter_mut().zip(&cols) {
            *slot = fields
                .get(c)
                .and_then(|f| f.parse().ok())
                .ok_or_else(|| format!("line {}: no number in column {}", k + 2, c + 1))?;
        }
        last_t = v[0];
        // A relative tolerance, so that t = 1.5e-4 finds the row written at 1.5e-4.
        if v[0] <= t * (1.0 + 1e-9) {
            found = Some(HistoryRow {
                t: v[0],
                step: v[1],
                beta: v[2],
                crater_depth: v[3],
                crater_diameter: v[4],
            });
        }
    }
    if !(last_t >= t * (1.0 - 1e-9)) {
        return Err(format!(
            "the run ended at {:.1} µs, before {:.1} µs",
            last_t * 1e6,
            t * 1e6
        ));
    }
    found.ok_or_else(|| format!("no row at or before {t} s"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const HISTORY: &str = "t_s,step,dt_s,beta,beta_target,crater_depth_m,crater_diameter_m\n\
                           0e0,0,0e0,1,1,0,0\n\
                           1e-5,100,1e-9,1.5,1.5,0.004,0.01\n\
                           2e-5,180,1e-9,1.7,1.7,0.006,0.02\n";

    #[test]
    fn history_rows_are_read_at_or_before_the_time() {
        let row = history_row_at(HISTORY, 1.5e-5).unwrap();
        assert_eq!((row.t, row.step, row.beta), (1e-5, 100.0, 1.5));
        let row = history_row_at(HISTORY, 2e-5).unwrap();
        assert_eq!((row.crater_depth, row.crater_diameter), (0.006, 0.02));
    }

    #[test]
    fn a_history_that_ends_early_or_lacks_a_column_is_an_error() {
        let e = history_row_at(HISTORY, 3e-5).unwrap_err();
        assert!(e.contains("ended at 20.0 µs"), "{e}");
        let e = history_row_at("t_s,step,beta\n0,0,1\n", 0.0).unwrap_err();
        assert!(e.contains("crater_depth_m"), "{e}");
        let e = history_row_at(&HISTORY.replace("1.5,1.5", "x,1.5"), 1e-5).unwrap_err();
        assert!(e.contains("line 3"), "{e}");
    }

    #[test]
    fn experiments_are_found_by_speed() {
        assert_eq!(experiment_at(3900.0).unwrap().beta, 2.51);
        assert_eq!(experiment_at(2310.0).unwrap().speed, "2.3");
        assert!(experiment_at(3000.0).is_none());
    }
}

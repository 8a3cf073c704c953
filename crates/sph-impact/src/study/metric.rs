//! A study's metrics: numbers read from each point's `summary.json` (docs/scenes.md,
//! "Outputs of `run`") by their key.
//!
//! A metric is a key of `summary.json` (`crater_diameter_m`, `beta`), a dotted path into
//! one of its objects (`last.kinetic`, `timings.pairs`) or an element of one of its arrays
//! (`damage[1].fully_damaged_mass_kg`). A null (NaN in the run) reads as NaN.

use serde_json::Value;

/// The top-level keys of `summary.json` (`crate::run::RunSummary`), against which a
/// study's metrics are checked before any point runs. The study's run test compares the
/// list with a summary written by a run.
pub const SUMMARY_KEYS: &[&str] = &[
    "complete",
    "time_reached_s",
    "geometry",
    "totals_per",
    "crater_diameter_m",
    "crater_diameter_removed_m",
    "bowl_diameter_m",
    "crater_depth_m",
    "crater_axis_depth_m",
    "crater_axis_kernel_width_m",
    "crater_axis_disc_radius_m",
    "rim_height_m",
    "beta",
    "beta_target",
    "beta_pendulum",
    "beta_detached",
    "beta_change_last_half",
    "ejecta_mass_kg",
    "ejecta_momentum_z_kg_m_s",
    "projectile_mass_kg",
    "impact_speed_m_s",
    "particles",
    "steps",
    "end_time_s",
    "wall_time_s",
    "particle_steps_per_s",
    "neighbours_per_particle",
    "threads",
    "resolution_scale",
    "version",
    "scene",
    "scheme",
    "bodies",
    "damage",
    "projectile_phase_fractions",
    "ejecta_distribution",
    "crater_profile",
    "initial",
    "last",
    "energy_error",
    "timings",
    "damage_events",
    "density_floor_events",
    "axis_crossings",
    "axis_crossings_midpoint",
    "free_flight_particles",
    "resumed_from_s",
    "warnings",
];

/// Whether `metric` starts with a key of `summary.json`; `Err` says why not.
pub fn check_name(metric: &str) -> Result<(), String> {
    let first = metric.split(['.', '[']).next().unwrap_or_default();
    if SUMMARY_KEYS.contains(&first) {
        Ok(())
    } else {
        Err(format!(
            "`{first}` is not a key of summary.json (docs/scenes.md, \"Outputs of `run`\")"
        ))
    }
}

/// The number at `metric` in a parsed `summary.json`; `Err` says what is missing or not a
/// number.
pub fn read(summary: &Value, metric: &str) -> Result<f64, String> {
    let mut v = summary;
    for segment in metric.split('.') {
        let (key, index) = match segment.find('[') {
            Some(open) => {
                let i = segment[open + 1..]
                    .strip_suffix(']')
                    .and_then(|i| i.parse::<usize>().ok())
                    .ok_or_else(|| format!("`{segment}`: an index is written `key[0]`"))?;
                (&segment[..open], Some(i))
            }
            None => (segment, None),
        };
        v = v
            .get(key)
            .ok_or_else(|| format!("summary.json has no `{key}` in `{metric}`"))?;
        if let Some(i) = index {
            v = v
                .get(i)
                .ok_or_else(|| format!("`{key}` has no element [{i}] in `{metric}`"))?;
        }
    }
    match v {
        Value::Null => Ok(f64::NAN),
        Value::Bool(b) => Ok(if *b { 1.0 } else { 0.0 }),
        Value::Number(n) => n
            .as_f64()
            .ok_or_else(|| format!("`{metric}` is not a number")),
        _ => Err(format!(
            "`{metric}` is not a number in summary.json (an object, array or text)"
        )),
    }
}

/// The `metrics` of a finished point (its `run/summary.json` under `point_dir`), NaN
/// where one cannot be read, with the first reason one could not.
pub(crate) fn read_point(
    point_dir: &std::path::Path,
    metrics: impl IntoIterator<Item = impl AsRef<str>>,
) -> Result<(Vec<f64>, Option<String>), crate::study::StudyError> {
    use crate::study::StudyError;
    let path = point_dir.join("run").join("summary.json");
    let text = std::fs::read_to_string(&path).map_err(|e| StudyError::io(&path, e))?;
    let summary: Value = serde_json::from_str(&text)
        .map_err(|e| StudyError::failed(format!("{}: {e}", path.display())))?;
    let mut error = None;
    let values = metrics
        .into_iter()
        .map(|m| {
            read(&summary, m.as_ref()).unwrap_or_else(|e| {
                error.get_or_insert(e);
                f64::NAN
            })
        })
        .collect();
    Ok((values, error))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_paths_elements_and_nulls_are_read() {
        let s: Value = serde_json::from_str(
            r#"{"beta": 2.1, "complete": true, "last": {"kinetic": 5.0},
                "damage": [{"mean_damage": 0.1}, {"mean_damage": 0.4}], "rim_height_m": null,
                "version": "0.2.0"}"#,
        )
        .unwrap();
        assert_eq!(read(&s, "beta"), Ok(2.1));
        assert_eq!(read(&s, "complete"), Ok(1.0));
        assert_eq!(read(&s, "last.kinetic"), Ok(5.0));
        assert_eq!(read(&s, "damage[1].mean_damage"), Ok(0.4));
        assert!(read(&s, "rim_height_m").unwrap().is_nan());
        assert!(read(&s, "version").unwrap_err().contains("not a number"));
        assert!(
            read(&s, "damage[2].mean_damage")
                .unwrap_err()
                .contains("no element [2]")
        );
        assert!(
            read(&s, "last.potential")
                .unwrap_err()
                .contains("no `potential`")
        );
    }

    #[test]
    fn names_are_checked_against_the_summary_keys() {
        assert!(check_name("crater_diameter_m").is_ok());
        assert!(check_name("damage[1].mean_damage").is_ok());
        assert!(check_name("timings.pairs").is_ok());
        assert!(
            check_name("crater_diamter_m")
                .unwrap_err()
                .contains("not a key")
        );
    }
}

//! What the command-line subcommands do, as library functions (testable).

use crate::verify::Problem;
use std::path::Path;

/// `sph-impact verify`: run, print metrics (a table or one JSON object), and write the
/// outputs into `out` when given.
pub fn verify(
    problem: Problem,
    resolution: Option<usize>,
    scheme: Option<&str>,
    out: Option<&Path>,
    json: bool,
) -> Result<(), String> {
    let scheme = scheme_with_overrides(problem.default_scheme(), scheme)?;
    let outcome = problem
        .run_with(resolution, scheme)
        .map_err(|e| e.to_string())?;
    if json {
        println!(
            "{}",
            serde_json::to_string(&outcome.metrics).map_err(|e| e.to_string())?
        );
    } else {
        println!(
            "{} (resolution {})",
            problem.name(),
            resolution.unwrap_or(problem.resolution_doc().1)
        );
        for (k, v) in &outcome.metrics {
            println!("  {k:<32} {v}");
        }
    }
    if let Some(dir) = out {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let write = |name: &str, text: String| {
            std::fs::write(dir.join(name), text)
                .map_err(|e| format!("{}: {e}", dir.join(name).display()))
        };
        write("profile.csv", outcome.profile.to_csv())?;
        write(
            "metrics.json",
            serde_json::to_string_pretty(&outcome.metrics).map_err(|e| e.to_string())?,
        )?;
        crate::plot::profile_plot(&outcome, &dir.join("plot.png")).map_err(|e| e.to_string())?;
        for p in &outcome.pictures {
            let path = dir.join(format!("{}.png", p.name));
            crate::plot::picture(p, &path).map_err(|e| format!("{}: {e}", path.display()))?;
        }
    }
    Ok(())
}

/// The scheme `base` with the fields given in the JSON object `overrides` replaced
/// (nested objects merge field by field; unknown fields are an error).
pub fn scheme_with_overrides(
    base: crate::SchemeConfig,
    overrides: Option<&str>,
) -> Result<crate::SchemeConfig, String> {
    let Some(text) = overrides else {
        return Ok(base);
    };
    let patch: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("--scheme: not JSON: {e}"))?;
    if !patch.is_object() {
        return Err("--scheme: expected a JSON object of scheme fields".into());
    }
    let mut merged = serde_json::to_value(&base).map_err(|e| e.to_string())?;
    merge(&mut merged, patch);
    serde_json::from_value(merged).map_err(|e| format!("--scheme: {e}"))
}

fn merge(into: &mut serde_json::Value, patch: serde_json::Value) {
    match (into, patch) {
        (serde_json::Value::Object(a), serde_json::Value::Object(b)) => {
            for (k, v) in b {
                match a.get_mut(&k) {
                    // A tagged enum (one with "kind") is replaced whole, not merged.
                    Some(slot) if slot.is_object() && v.is_object() && v.get("kind").is_none() => {
                        merge(slot, v)
                    }
                    _ => {
                        a.insert(k, v);
                    }
                }
            }
        }
        (slot, v) => *slot = v,
    }
}

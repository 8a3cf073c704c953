//! A study's axes: the values each parameter takes, and the points of the study (every
//! combination of one value from each axis).

use serde::{Deserialize, Serialize};
use toml::Value;

/// How a numeric range is spaced.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Spacing {
    /// Equal steps.
    #[default]
    Linear,
    /// Equal ratios (for a Weibull k, a strength, a rate): both ends must be positive.
    Log,
}

/// `count` values from `from` to `to` (both included).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Range {
    /// The first value.
    pub from: f64,
    /// The last value (larger than `from`).
    pub to: f64,
    /// How many values (at least 2).
    pub count: usize,
    /// Linear (default) or log spacing.
    #[serde(default)]
    pub scale: Spacing,
}

impl Range {
    /// The values, or what is wrong with the range (as (key, message)).
    pub fn values(&self) -> Result<Vec<f64>, (&'static str, String)> {
        let Range {
            from,
            to,
            count,
            scale,
        } = *self;
        if !from.is_finite() || !to.is_finite() {
            return Err(("from", "the ends must be finite numbers".into()));
        }
        if from >= to {
            return Err((
                "to",
                format!("the range is empty or reversed: from {from} to {to}"),
            ));
        }
        if count < 2 {
            return Err((
                "count",
                format!("a range needs at least 2 values, not {count} (use `values` for one)"),
            ));
        }
        if scale == Spacing::Log && from <= 0.0 {
            return Err((
                "from",
                format!("a log range needs positive ends, not {from}"),
            ));
        }
        let n = (count - 1) as f64;
        Ok((0..count)
            .map(|i| {
                // The ends exactly as written, the steps in between.
                if i == 0 {
                    from
                } else if i + 1 == count {
                    to
                } else {
                    let t = i as f64 / n;
                    match scale {
                        Spacing::Linear => from + (to - from) * t,
                        Spacing::Log => from * (to / from).powf(t),
                    }
                }
            })
            .collect())
    }
}

/// One axis of a study: one or more scene paths set together, and the values they take
/// (one tuple per value of the axis; a single path has one-element tuples).
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// The scene paths (study::scene_path).
    pub paths: Vec<String>,
    /// Each value of the axis: one value per path.
    pub values: Vec<Vec<Value>>,
}

impl Axis {
    /// One path taking each of `values`.
    pub fn list(path: impl Into<String>, values: impl IntoIterator<Item = Value>) -> Self {
        Self {
            paths: vec![path.into()],
            values: values.into_iter().map(|v| vec![v]).collect(),
        }
    }

    /// Several paths set together, one tuple per value of the axis (Weibull (m, k) pairs).
    pub fn linked(paths: Vec<String>, tuples: Vec<Vec<Value>>) -> Self {
        Self {
            paths,
            values: tuples,
        }
    }
}

/// One point of a study: its number (from 0, in the order of [`points`]) and the value of
/// every path.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Its number.
    pub index: usize,
    /// (path, value) for every path of every axis, in the axes' order.
    pub settings: Vec<(String, Value)>,
}

/// Every combination of one value of each axis; the first axis varies slowest. No axes:
/// one point, the base scene.
pub fn points(axes: &[Axis]) -> Vec<Point> {
    let mut combos: Vec<Vec<(String, Value)>> = vec![Vec::new()];
    for axis in axes {
        let mut next = Vec::with_capacity(combos.len() * axis.values.len());
        for c in &combos {
            for tuple in &axis.values {
                let mut s = c.clone();
                s.extend(axis.paths.iter().cloned().zip(tuple.iter().cloned()));
                next.push(s);
            }
        }
        combos = next;
    }
    combos
        .into_iter()
        .enumerate()
        .map(|(index, settings)| Point { index, settings })
        .collect()
}

/// A value as a table cell: numbers in their shortest exact form, strings bare, anything
/// else as inline TOML.
pub fn cell(value: &Value) -> String {
    match value {
        Value::Float(x) => format!("{x:?}"),
        Value::Integer(i) => i.to_string(),
        Value::String(s) => s.clone(),
        Value::Boolean(b) => b.to_string(),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_linear_range_keeps_its_ends_and_steps_evenly() {
        let r = Range {
            from: 2.0,
            to: 3.0,
            count: 3,
            scale: Spacing::Linear,
        };
        assert_eq!(r.values().unwrap(), vec![2.0, 2.5, 3.0]);
    }

    #[test]
    fn a_log_range_steps_by_equal_ratios() {
        let r = Range {
            from: 1e38,
            to: 1e42,
            count: 5,
            scale: Spacing::Log,
        };
        let v = r.values().unwrap();
        assert_eq!((v[0], v[4]), (1e38, 1e42));
        for w in v.windows(2) {
            assert!((w[1] / w[0] / 10.0 - 1.0).abs() < 1e-12, "{v:?}");
        }
    }

    #[test]
    fn bad_ranges_name_the_key_at_fault() {
        let r = |from, to, count, scale| Range {
            from,
            to,
            count,
            scale,
        };
        let lin = Spacing::Linear;
        assert_eq!(r(3.0, 2.0, 3, lin).values().unwrap_err().0, "to");
        assert_eq!(r(2.0, 2.0, 3, lin).values().unwrap_err().0, "to");
        assert_eq!(r(2.0, 3.0, 1, lin).values().unwrap_err().0, "count");
        assert_eq!(
            r(-1.0, 3.0, 3, Spacing::Log).values().unwrap_err().0,
            "from"
        );
        assert_eq!(r(f64::NAN, 3.0, 3, lin).values().unwrap_err().0, "from");
    }

    /// The points are the product of the axes, first axis slowest; a linked axis sets its
    /// paths together.
    #[test]
    fn points_are_every_combination_with_linked_paths_together() {
        let f = Value::Float;
        let axes = [
            Axis::list("solver.n_target", [f(2.0), f(3.0)]),
            Axis::linked(
                vec!["m".into(), "k".into()],
                vec![
                    vec![f(9.0), f(1e38)],
                    vec![f(10.0), f(2.7e41)],
                    vec![f(11.0), f(1e44)],
                ],
            ),
        ];
        let p = points(&axes);
        assert_eq!(p.len(), 6);
        assert_eq!(p[4].index, 4);
        assert_eq!(
            p[4].settings,
            vec![
                ("solver.n_target".to_string(), f(3.0)),
                ("m".to_string(), f(10.0)),
                ("k".to_string(), f(2.7e41)),
            ]
        );
        assert_eq!(points(&[]).len(), 1);
    }

    #[test]
    fn cells_are_exact_and_plain() {
        assert_eq!(cell(&Value::Float(2.7e41)), "2.7e41");
        assert_eq!(cell(&Value::Float(0.1)), "0.1");
        assert_eq!(cell(&Value::Integer(7)), "7");
        assert_eq!(cell(&Value::String("rz".into())), "rz");
    }
}

//! Tick positions and labels: "nice" steps 1, 2, 2.5, 5 × 10^k on linear axes (the
//! nice-number idea of Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990),
//! decades with 2…9 minor ticks on log axes.
//!
//! Ticks lie inside the axis range; the range itself is not widened to tick values, so
//! the view shows the data and nothing else.

/// One labelled tick.
#[derive(Clone, Debug, PartialEq)]
pub struct Tick {
    /// Data value at the tick.
    pub value: f64,
    /// Its label.
    pub label: String,
}

/// The ticks of one axis: labelled major ticks and unlabelled minor ticks.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct TickSet {
    /// Labelled ticks, increasing.
    pub major: Vec<Tick>,
    /// Unlabelled ticks (log axes: 2…9 × 10^k), increasing.
    pub minor: Vec<f64>,
}

/// Values that differ from a multiple of the step by less than this fraction of a
/// step count as on the multiple (absorbs rounding of lo/step).
const SNAP: f64 = 1e-9;

/// Mantissas of nice steps. 2.5 fills the gap between 2 and 5, where the tick count
/// would otherwise jump by a factor 2.5.
const MANTISSAS: [f64; 4] = [1.0, 2.0, 2.5, 5.0];

/// Nice steps near `raw`: 1, 2, 2.5, 5 × 10^k for the decade of `raw` and its
/// neighbours, increasing.
fn candidate_steps(raw: f64) -> Vec<f64> {
    let e = raw.log10().floor() as i32;
    let mut steps = Vec::with_capacity(16);
    for k in (e - 1)..=(e + 2) {
        for m in MANTISSAS {
            steps.push(m * 10f64.powi(k));
        }
    }
    steps
}

/// Integer range of multiples k of `step` with lo ≤ k·step ≤ hi.
fn multiples(lo: f64, hi: f64, step: f64) -> (i64, i64) {
    let k0 = (lo / step - SNAP).ceil() as i64;
    let k1 = (hi / step + SNAP).floor() as i64;
    (k0, k1)
}

/// The nice step for [lo, hi]: the smallest of 1, 2, 2.5, 5 × 10^k that puts at most
/// `max_ticks` ticks inside the range. `None` for an empty, reversed or non-finite range
/// or `max_ticks` < 2.
pub fn nice_step(lo: f64, hi: f64, max_ticks: usize) -> Option<f64> {
    if !(lo.is_finite() && hi.is_finite() && hi > lo) || max_ticks < 2 {
        return None;
    }
    // A range below ~1e-12 of its magnitude cannot be subdivided in f64.
    if hi - lo <= 1e-12 * lo.abs().max(hi.abs()) {
        return None;
    }
    let raw = (hi - lo) / max_ticks as f64;
    candidate_steps(raw).into_iter().find(|&step| {
        let (k0, k1) = multiples(lo, hi, step);
        k1 - k0 < max_ticks as i64
    })
}

/// Tick values on a linear axis: multiples of [`nice_step`] inside [lo, hi]. Empty when
/// the range is unusable.
pub fn linear_ticks(lo: f64, hi: f64, max_ticks: usize) -> Vec<f64> {
    let Some(step) = nice_step(lo, hi, max_ticks) else {
        return Vec::new();
    };
    let (k0, k1) = multiples(lo, hi, step);
    // k·step rather than repeated addition: no accumulated rounding, and k = 0 gives 0
    // exactly.
    (k0..=k1).map(|k| k as f64 * step).collect()
}

/// Labels for evenly spaced `ticks` with spacing `step`: all with the same number of
/// decimals, so that the labels of one axis line up. Magnitudes ≥ 1e4 or < 1e-2 use a
/// common power of ten written into each label ("1.2e-3"), never a separate offset text
/// a reader could miss.
pub fn linear_labels(ticks: &[f64], step: f64) -> Vec<String> {
    let max_abs = ticks.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    if max_abs == 0.0 || !step.is_finite() || step <= 0.0 {
        return ticks.iter().map(|_| "0".to_string()).collect();
    }
    if (1e-2..1e4).contains(&max_abs) {
        let decimals = decimals_for(step);
        ticks.iter().map(|&t| fixed(t, decimals)).collect()
    } else {
        let e = (max_abs.log10() + SNAP).floor() as i32;
        let scale = 10f64.powi(e);
        let decimals = decimals_for(step / scale);
        ticks
            .iter()
            .map(|&t| {
                if t == 0.0 {
                    "0".to_string()
                } else {
                    format!("{}e{}", fixed(t / scale, decimals), e)
                }
            })
            .collect()
    }
}

/// Fewest decimals that write multiples of `step` exactly (0.25 → 2, 0.2 → 1, 5 → 0).
fn decimals_for(step: f64) -> usize {
    (0..=15)
        .find(|&d| {
            let m = step * 10f64.powi(d as i32);
            (m - m.round()).abs() <= 1e-6 * m
        })
        .unwrap_or(15)
}

/// `v` with `decimals` digits after the point, without a "-0".
fn fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Label of a power of ten or a 2×/5× multiple on a log axis: plain for 0.01 … 1000,
/// "Me±k" otherwise.
pub fn log_label(v: f64) -> String {
    let e = (v.log10() + SNAP).floor() as i32;
    let m = (v / 10f64.powi(e)).round();
    if (-2..=3).contains(&e) {
        fixed(m * 10f64.powi(e), (-e).max(0) as usize)
    } else {
        format!("{m}e{e}")
    }
}

impl TickSet {
    /// Ticks of a linear axis over [lo, hi] with at most `max_ticks` labelled ticks.
    pub fn linear(lo: f64, hi: f64, max_ticks: usize) -> TickSet {
        let values = linear_ticks(lo, hi, max_ticks);
        let step = nice_step(lo, hi, max_ticks).unwrap_or(0.0);
        let labels = linear_labels(&values, step);
        TickSet {
            major: values
                .into_iter()
                .zip(labels)
                .map(|(value, label)| Tick { value, label })
                .collect(),
            minor: Vec::new(),
        }
    }

    /// Ticks of a log axis over [lo, hi] (both > 0): labelled powers of ten with minor
    /// ticks at 2…9 × 10^k. Many decades are thinned to at most `max_ticks` labels (minor
    /// ticks are then dropped); less than two decades inside the range are filled with
    /// 2× and 5× labels, and failing that the linear ticks of the range are used.
    pub fn log(lo: f64, hi: f64, max_ticks: usize) -> TickSet {
        if !(lo > 0.0 && hi > lo && hi.is_finite()) || max_ticks < 2 {
            return TickSet::default();
        }
        let inside = |v: f64| v >= lo * (1.0 - SNAP) && v <= hi * (1.0 + SNAP);
        let e0 = (lo.log10() - SNAP).floor() as i32;
        let e1 = (hi.log10() + SNAP).ceil() as i32;
        let decades: Vec<i32> = (e0..=e1).filter(|&e| inside(10f64.powi(e))).collect();
        if decades.len() >= 2 {
            let every = decades.len().div_ceil(max_ticks);
            let major: Vec<Tick> = decades
                .iter()
                .filter(|&&e| e.rem_euclid(every as i32) == 0)
                .map(|&e| {
                    let value = 10f64.powi(e);
                    Tick {
                        value,
                        label: log_label(value),
                    }
                })
                .collect();
            let minor = if every == 1 {
                (e0..=e1)
                    .flat_map(|e| (2..=9).map(move |m| m as f64 * 10f64.powi(e)))
                    .filter(|&v| inside(v))
                    .collect()
            } else {
                Vec::new()
            };
            return TickSet { major, minor };
        }
        // Less than two decades: label 1, 2, 5 × 10^k.
        let values: Vec<f64> = (e0..=e1)
            .flat_map(|e| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(e)))
            .filter(|&v| inside(v))
            .collect();
        if values.len() >= 2 && values.len() <= max_ticks {
            let minor = (e0..=e1)
                .flat_map(|e| [3.0, 4.0, 6.0, 7.0, 8.0, 9.0].map(|m| m * 10f64.powi(e)))
                .filter(|&v| inside(v))
                .collect();
            return TickSet {
                major: values
                    .into_iter()
                    .map(|value| Tick {
                        value,
                        label: log_label(value),
                    })
                    .collect(),
                minor,
            };
        }
        TickSet::linear(lo, hi, max_ticks)
    }
}

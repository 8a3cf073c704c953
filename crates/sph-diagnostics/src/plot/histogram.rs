//! Binning of data into equal-width bins for histograms.

use super::error::PlotError;
use super::series::PointCount;

/// Data binned into equal-width bins.
#[derive(Clone, Debug, PartialEq)]
pub struct Binned {
    /// Bin edges, one more than bins, increasing.
    pub edges: Vec<f64>,
    /// Number of values per bin.
    pub counts: Vec<f64>,
    /// Values given, and how many were non-finite (not binned).
    pub count: PointCount,
}

/// Bins the finite values of `data` into `bins` equal bins over [min, max]; the maximum
/// goes into the last bin. A single repeated value v gets the range [v − ½, v + ½].
/// `series` names the data in errors.
pub fn bin(data: &[f64], bins: usize, series: &str) -> Result<Binned, PlotError> {
    if bins == 0 {
        return Err(PlotError::BadParameter {
            what: "bins",
            value: 0.0,
            reason: "a histogram needs at least one bin",
        });
    }
    let finite: Vec<f64> = data.iter().copied().filter(|v| v.is_finite()).collect();
    if finite.is_empty() {
        return Err(PlotError::NoFinitePoints {
            series: series.to_string(),
            total: data.len(),
        });
    }
    let (mut lo, mut hi) = finite
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
    if hi == lo {
        lo -= 0.5;
        hi += 0.5;
    }
    let width = (hi - lo) / bins as f64;
    let mut counts = vec![0.0; bins];
    for v in &finite {
        let k = (((v - lo) / width) as usize).min(bins - 1);
        counts[k] += 1.0;
    }
    Ok(Binned {
        edges: (0..=bins).map(|k| lo + k as f64 * width).collect(),
        counts,
        count: PointCount {
            total: data.len(),
            non_finite: data.len() - finite.len(),
        },
    })
}

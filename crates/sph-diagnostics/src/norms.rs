//! Error norms of verification.md: L1 = Σ w_i |f_i − f_exact(x_i)| / Σ w_i with w_i the
//! particle's cell width (1-D) or volume, Linf = max |e_i|, and the convergence order
//! p = log(L1(N1)/L1(N2)) / log(N2/N1).

use serde::{Deserialize, Serialize};

/// L1 and Linf of one field.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ErrorNorms {
    /// Weighted L1 norm.
    pub l1: f64,
    /// Maximum absolute error.
    pub linf: f64,
    /// Number of samples used.
    pub samples: usize,
}

/// Norms of `numerical − exact` with weights `w` (cell widths or volumes), over the
/// samples for which `include` is true. Returns zero norms for no samples.
pub fn error_norms(
    numerical: &[f64],
    exact: &[f64],
    weights: &[f64],
    include: impl Fn(usize) -> bool,
) -> ErrorNorms {
    assert_eq!(numerical.len(), exact.len(), "one exact value per sample");
    assert_eq!(numerical.len(), weights.len(), "one weight per sample");
    let (mut s, mut sw, mut linf, mut n) = (0.0, 0.0, 0.0f64, 0);
    for i in 0..numerical.len() {
        if !include(i) {
            continue;
        }
        let e = (numerical[i] - exact[i]).abs();
        s += weights[i] * e;
        sw += weights[i];
        linf = linf.max(e);
        n += 1;
    }
    ErrorNorms {
        l1: if sw > 0.0 { s / sw } else { 0.0 },
        linf,
        samples: n,
    }
}

/// Convergence order between resolutions n1 < n2 with errors e1, e2.
pub fn convergence_order(n1: f64, e1: f64, n2: f64, e2: f64) -> f64 {
    (e1 / e2).ln() / (n2 / n1).ln()
}

/// Least-squares slope of log y against log x (e.g. shock radius against time).
pub fn log_log_slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let lx: Vec<f64> = x.iter().map(|v| v.ln()).collect();
    let ly: Vec<f64> = y.iter().map(|v| v.ln()).collect();
    let (mx, my) = (lx.iter().sum::<f64>() / n, ly.iter().sum::<f64>() / n);
    let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_computed_norms() {
        let n = error_norms(&[1.0, 2.0, 4.0], &[1.0, 1.0, 1.0], &[1.0, 1.0, 2.0], |_| {
            true
        });
        assert_eq!(n.l1, (0.0 + 1.0 + 6.0) / 4.0);
        assert_eq!(n.linf, 3.0);
        let m = error_norms(&[1.0, 2.0, 4.0], &[1.0, 1.0, 1.0], &[1.0, 1.0, 2.0], |i| {
            i < 2
        });
        assert_eq!((m.l1, m.samples), (0.5, 2));
        assert!((convergence_order(100.0, 0.04, 200.0, 0.01) - 2.0).abs() < 1e-14);
        assert!(
            (log_log_slope(
                &[1.0, 2.0, 4.0],
                &[3.0, 3.0 * 2f64.powf(0.4), 3.0 * 4f64.powf(0.4)]
            ) - 0.4)
                .abs()
                < 1e-14
        );
    }
}

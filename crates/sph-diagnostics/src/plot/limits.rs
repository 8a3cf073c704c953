//! Axis limits fitted to the data: the range of every drawable value plus a 4 % margin
//! (in log10 on log axes), unless the user fixed them.

use super::axes::Axes;
use super::error::PlotError;
use super::scale::Scale;
use super::series::Kind;

/// Fraction of the data range added on each side.
const MARGIN: f64 = 0.04;

/// Which axis.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Which {
    X,
    Y,
}

impl Which {
    fn name(self) -> &'static str {
        match self {
            Which::X => "x",
            Which::Y => "y",
        }
    }
}

/// Range of the values of `ax` shown on axis `w`; also whether a bar baseline at 0
/// is the lower end (bars then start on the axis, without a margin below).
fn data_range(ax: &Axes, w: Which) -> Option<(f64, f64, bool)> {
    let scale = match w {
        Which::X => ax.xscale,
        Which::Y => ax.yscale,
    };
    let ok = |v: f64| scale.forward(v).is_some();
    let (mut lo, mut hi) = (f64::MAX, f64::MIN);
    let mut take = |v: f64| {
        if ok(v) {
            lo = lo.min(v);
            hi = hi.max(v);
        }
    };
    let mut baseline = false;
    for s in &ax.series {
        match (&s.kind, w) {
            (Kind::HLine, Which::Y) => take(s.y[0]),
            (Kind::VLine, Which::X) => take(s.x[0]),
            (Kind::HLine, Which::X) | (Kind::VLine, Which::Y) => {}
            (Kind::Bars, Which::X) => {
                for i in 0..s.len() {
                    if s.finite_at(i) {
                        take(s.x[i]);
                        take(s.x[i + 1]);
                    }
                }
            }
            (Kind::Bars, Which::Y) => {
                for i in 0..s.len() {
                    if s.finite_at(i) {
                        take(s.y[i]);
                    }
                }
                if scale == Scale::Linear {
                    take(0.0);
                    baseline = true;
                }
            }
            (_, _) => {
                let vals = if w == Which::X { &s.x } else { &s.y };
                for (i, &v) in vals.iter().enumerate() {
                    if s.finite_at(i) {
                        take(v);
                    }
                }
            }
        }
    }
    (lo <= hi).then_some((lo, hi, baseline && lo == 0.0))
}

/// The limits of axis `w` of `ax` (panel `row`, `col` for messages).
pub(crate) fn limits(ax: &Axes, w: Which, row: usize, col: usize) -> Result<(f64, f64), PlotError> {
    let (scale, user) = match w {
        Which::X => (ax.xscale, ax.xlim),
        Which::Y => (ax.yscale, ax.ylim),
    };
    if let Some((lo, hi)) = user {
        if scale == Scale::Log && !(lo > 0.0) {
            return Err(PlotError::BadLimits {
                axis: w.name(),
                lo,
                hi,
                reason: "a log axis needs positive limits",
            });
        }
        return Ok((lo, hi));
    }
    let Some((lo, hi, sticky_zero)) = data_range(ax, w) else {
        return match scale {
            Scale::Log if !ax.series.is_empty() => Err(PlotError::NoPositiveData {
                row,
                col,
                axis: w.name(),
            }),
            Scale::Log => Ok((1.0, 10.0)),
            Scale::Linear => Ok((0.0, 1.0)),
        };
    };
    Ok(match scale {
        Scale::Linear => {
            if hi > lo {
                let m = MARGIN * (hi - lo);
                (if sticky_zero { lo } else { lo - m }, hi + m)
            } else {
                let m = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
                (lo - m, hi + m)
            }
        }
        Scale::Log => {
            let (l, h) = (lo.log10(), hi.log10());
            let m = if h > l { MARGIN * (h - l) } else { 0.5 };
            (10f64.powf(l - m), 10f64.powf(h + m))
        }
    })
}

/// Widens one of the linear ranges so that a data unit spans the same number of
/// pixels on both axes of a plot area `w_px` × `h_px`.
pub(crate) fn equalise(
    x: (f64, f64),
    y: (f64, f64),
    w_px: f64,
    h_px: f64,
) -> ((f64, f64), (f64, f64)) {
    let (dx, dy) = (x.1 - x.0, y.1 - y.0);
    if dx / w_px > dy / h_px {
        let half = 0.5 * dx * h_px / w_px;
        let c = 0.5 * (y.0 + y.1);
        (x, (c - half, c + half))
    } else {
        let half = 0.5 * dy * w_px / h_px;
        let c = 0.5 * (x.0 + x.1);
        ((c - half, c + half), y)
    }
}

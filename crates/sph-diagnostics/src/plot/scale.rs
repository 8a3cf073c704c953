//! Axis scales and the map from data values to pixel positions.

/// How an axis maps data to position.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Scale {
    /// Position proportional to the value.
    #[default]
    Linear,
    /// Position proportional to log10 of the value; values ≤ 0 cannot be shown and are
    /// counted in the render report.
    Log,
}

impl Scale {
    /// The value in axis coordinates (itself, or its log10), `None` when it cannot be
    /// shown (non-finite, or ≤ 0 on a log axis).
    pub fn forward(self, v: f64) -> Option<f64> {
        match self {
            Scale::Linear if v.is_finite() => Some(v),
            Scale::Log if v.is_finite() && v > 0.0 => Some(v.log10()),
            _ => None,
        }
    }

    /// Inverse of [`Scale::forward`].
    pub fn inverse(self, u: f64) -> f64 {
        match self {
            Scale::Linear => u,
            Scale::Log => 10f64.powf(u),
        }
    }
}

/// Maps one axis: data interval [lo, hi] onto pixels [p0, p1] (p1 < p0 for a y axis,
/// whose pixel rows grow downwards).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct AxisMap {
    pub scale: Scale,
    /// Limits in axis coordinates (log10 for a log axis).
    pub u0: f64,
    pub u1: f64,
    pub p0: f64,
    pub p1: f64,
}

impl AxisMap {
    /// `lo`, `hi` are data limits, already checked to be usable for `scale`.
    pub fn new(scale: Scale, lo: f64, hi: f64, p0: f64, p1: f64) -> Self {
        let f = |v: f64| scale.forward(v).unwrap_or(0.0);
        Self {
            scale,
            u0: f(lo),
            u1: f(hi),
            p0,
            p1,
        }
    }

    /// Pixel position of axis coordinate `u`.
    pub fn px_u(&self, u: f64) -> f64 {
        self.p0 + (u - self.u0) / (self.u1 - self.u0) * (self.p1 - self.p0)
    }

    /// Pixel position of data value `v`, `None` if it cannot be shown on this scale.
    pub fn px(&self, v: f64) -> Option<f64> {
        self.scale.forward(v).map(|u| self.px_u(u))
    }

    /// Whether the data value lies inside the limits (tolerating rounding).
    pub fn contains(&self, v: f64) -> bool {
        match self.scale.forward(v) {
            Some(u) => {
                let tol = 1e-9 * (self.u1 - self.u0).abs();
                u >= self.u0.min(self.u1) - tol && u <= self.u0.max(self.u1) + tol
            }
            None => false,
        }
    }
}

//! The spherical layering of the variable-resolution placement (paper §4).
//!
//! Layer k has spacing r_k = A_res q^k. The paper gives the spacing and the point count
//! N_k = floor(4πR_k²/r_k²) of a layer of radius R_k but leaves R_k itself implicit.
//! This crate's choice: layer k owns the spherical shell [b_(k−1), b_k] with
//! b_(−1) = 0 and b_k = Σ_(i≤k) r_i, so every shell is exactly one spacing thick and
//! the shells tile space without gaps; the layer sits in the middle of its shell,
//! R_k = (b_(k−1) + b_k)/2. Then
//!
//! * consecutive layers are (r_k + r_(k+1))/2 apart radially, the mean of their
//!   spacings, so the radial spacing matches the tangential one (area per point
//!   4πR_k²/N_k ≥ r_k²);
//! * the first layer has R_0 = A_res/2 and N_0 = floor(π) = 3 points, so no particle
//!   sits exactly on the origin and every layer has at least 3 points;
//! * each shell's volume is (4π/3)(b_k³ − b_(k−1)³) = 4πR_k² r_k (1 + r_k²/(12R_k²)),
//!   so N_k points of volume ≈ r_k³ each fill it up to that small curvature term and
//!   the floor in N_k.

use crate::error::{GeometryError, positive_finite};
use std::f64::consts::PI;

/// Largest number of layers the layering builds before refusing (guards against a
/// spacing many orders of magnitude below the body size at q = 1).
pub const MAX_SHELLS: usize = 10_000_000;

/// One layer of the variable-resolution placement and the shell it owns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shell {
    /// Layer index k (0 at the origin).
    pub index: usize,
    /// Spacing r_k = A_res q^k (m).
    pub spacing: f64,
    /// Inner radius b_(k−1) of the shell (m).
    pub inner: f64,
    /// Outer radius b_k of the shell (m).
    pub outer: f64,
    /// Radius R_k = (b_(k−1) + b_k)/2 of the layer's points (m).
    pub radius: f64,
    /// Points on the full sphere, N_k = floor(4πR_k²/r_k²).
    pub count: usize,
}

impl Shell {
    /// Volume of the full shell, (4π/3)(b_k³ − b_(k−1)³).
    pub fn volume(&self) -> f64 {
        4.0 / 3.0 * PI * (self.outer.powi(3) - self.inner.powi(3))
    }
}

/// N = floor(4πR²/r²): the points of a layer of radius R and spacing r (paper §4).
pub fn shell_point_count(radius: f64, spacing: f64) -> usize {
    (4.0 * PI * radius * radius / (spacing * spacing)).floor() as usize
}

/// All layers whose shell starts within `reach` of the origin (b_(k−1) ≤ reach), for
/// first spacing `first_spacing` = A_res > 0 and ratio `ratio` = q ≥ 1.
///
/// Layer k has spacing r_k = A_res q^k, owns the shell [b_(k−1), b_k] with
/// b_(−1) = 0 and b_k = Σ_(i≤k) r_i, and puts its N_k = floor(4πR_k²/r_k²) points at the
/// mid radius R_k = (b_(k−1) + b_k)/2. The paper leaves R_k implicit; this choice makes
/// the shells tile space (each exactly one spacing thick), puts consecutive layers
/// (r_k + r_(k+1))/2 apart so the radial spacing matches the tangential one, starts with
/// 3 points at R_0 = A_res/2 (none on the origin), and gives each shell the volume
/// 4πR_k² r_k (1 + r_k²/(12R_k²)) ≈ N_k r_k³.
pub fn shells(first_spacing: f64, ratio: f64, reach: f64) -> Result<Vec<Shell>, GeometryError> {
    let a = positive_finite("FibonacciPlacement.first_spacing (A_res)", first_spacing)?;
    check_ratio(ratio)?;
    if !(reach >= 0.0 && reach.is_finite()) {
        return Err(GeometryError::InvalidParameter {
            field: "shells(reach)",
            value: reach,
            requirement: "must be non-negative and finite",
        });
    }
    // Closed-form layer count, b_(k−1) ≤ reach: k ≤ reach/a (q = 1) or
    // k ≤ ln(1 + (q − 1) reach/a)/ln q.
    let predicted = if ratio == 1.0 {
        reach / a
    } else {
        (1.0 + (ratio - 1.0) * reach / a).ln() / ratio.ln()
    };
    if predicted > MAX_SHELLS as f64 {
        return Err(GeometryError::TooManyPoints {
            body: format!("layering to radius {reach} m"),
            operation: "variable-resolution layering",
            estimate: 3.0 * predicted,
            limit: 3.0 * MAX_SHELLS as f64,
        });
    }
    let mut out = Vec::with_capacity(predicted as usize + 2);
    let mut inner = 0.0;
    let mut k = 0usize;
    while inner <= reach {
        // powi of the exact ratio instead of a running product: no drift over
        // hundreds of layers.
        let spacing = a * ratio.powi(k as i32);
        let outer = inner + spacing;
        let radius = 0.5 * (inner + outer);
        out.push(Shell {
            index: k,
            spacing,
            inner,
            outer,
            radius,
            count: shell_point_count(radius, spacing),
        });
        inner = outer;
        k += 1;
    }
    Ok(out)
}

/// q must be finite and at least 1 (q = 1 is the uniform arrangement).
pub(crate) fn check_ratio(ratio: f64) -> Result<f64, GeometryError> {
    if ratio >= 1.0 && ratio.is_finite() {
        Ok(ratio)
    } else {
        Err(GeometryError::InvalidParameter {
            field: "FibonacciPlacement.ratio (q)",
            value: ratio,
            requirement: "must be finite and at least 1",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_count_formula() {
        assert_eq!(shell_point_count(0.5, 1.0), 3); // floor(π)
        assert_eq!(shell_point_count(1.5, 1.0), 28); // floor(9π)
        assert_eq!(shell_point_count(2.0, 0.5), 201); // floor(64π)
        assert_eq!(shell_point_count(1.505, 1.01), 27); // floor(27.9...)
    }

    #[test]
    fn uniform_layers_at_half_integers() {
        let s = shells(0.5, 1.0, 3.0).unwrap();
        // b_(k−1) = 0, 0.5, ..., 3.0 ≤ 3: seven layers, the last starting on the reach.
        assert_eq!(s.len(), 7);
        for (k, sh) in s.iter().enumerate() {
            assert_eq!(sh.index, k);
            assert_eq!(sh.spacing, 0.5);
            assert!((sh.radius - 0.5 * (k as f64 + 0.5)).abs() < 1e-14);
        }
        let counts: Vec<usize> = s.iter().map(|x| x.count).collect();
        assert_eq!(counts, vec![3, 28, 78, 153, 254, 380, 530]);
    }

    #[test]
    fn geometric_layers_tile_space() {
        let (a, q) = (1.0, 1.03);
        let s = shells(a, q, 173.3).unwrap();
        let mut b = 0.0;
        for (k, sh) in s.iter().enumerate() {
            let r = a * q.powi(k as i32);
            assert!((sh.spacing - r).abs() < 1e-12 * r);
            assert_eq!(sh.inner, b);
            assert!((sh.outer - sh.inner - r).abs() < 1e-12 * r);
            assert_eq!(sh.radius, 0.5 * (sh.inner + sh.outer));
            assert_eq!(sh.count, shell_point_count(sh.radius, r));
            // Shell volume vs N_k r_k³: 1 + r²/(12R²), times the floor's 1 + 1/N at most.
            let per_point = sh.volume() / (sh.count as f64 * r.powi(3));
            let smooth = 1.0 + r * r / (12.0 * sh.radius * sh.radius);
            assert!(per_point >= smooth - 1e-12);
            assert!(per_point <= smooth * (1.0 + 1.0 / sh.count as f64) + 1e-12);
            b = sh.outer;
        }
        let last = s.last().unwrap();
        assert!(last.inner <= 173.3 && last.outer > 173.3);
        // Closed form of the outer radius: b_k = a (q^(k+1) − 1)/(q − 1).
        let k = last.index as i32;
        assert!((last.outer - a * (q.powi(k + 1) - 1.0) / (q - 1.0)).abs() < 1e-9);
    }

    #[test]
    fn rejects_bad_parameters() {
        assert!(shells(0.0, 1.01, 1.0).is_err());
        assert!(shells(1.0, 0.99, 1.0).is_err());
        assert!(shells(1.0, f64::NAN, 1.0).is_err());
        assert!(shells(1.0, f64::INFINITY, 1.0).is_err());
        assert!(shells(1.0, 1.0, -1.0).is_err());
        assert!(matches!(
            shells(1e-9, 1.0, 1.0),
            Err(GeometryError::TooManyPoints { .. })
        ));
    }
}

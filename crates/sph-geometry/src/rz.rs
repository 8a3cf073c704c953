//! Particle placement for axisymmetric (RZ) runs: 2-D particles in the meridional
//! half-plane (x = r > 0, y = z), each standing for a ring about the z axis.
//!
//! The body is a 3-D [`Shape`] that is symmetric about the z axis; a point (r, z) of the
//! half-plane is inside when (r, 0, z) is. Each particle's mass is its **ring mass per
//! radian**, m = ρ ∫ r dA over the part of the half-plane it represents (kg/rad), so
//! 2π Σ m is the body's mass; its spacing is the local Δ (m). The returned
//! [`BodyParticles`] keep the 3-D meaning of the totals: `volume` and `exact_volume` are
//! the body's 3-D volume (m³), `raw_mass_error` is 2π Σ m/(ρV) − 1, and
//! `lattice_equivalent_count` is the meridional section's area over Δ_min², the count of
//! a uniform RZ lattice at the finest spacing (the area estimated as Σ m/(ρ r)).
//!
//! * [`rz_lattice`]: a square lattice, r = (a + ½)Δ, z on the layers of
//!   [`cubic_lattice`](crate::cubic_lattice), mass ρΔ²r (the exact ring mass of its cell).
//! * [`RzLayeredPlacement`]: the 2-D analogue of the variable-resolution Fibonacci layers
//!   (paper §4): half-circular layers about an origin on the axis, each one spacing thick,
//!   the spacing growing by q per layer; each particle carries the ring mass of the part
//!   of its annular sector inside the body, and the masses are then rescaled so that the
//!   body has its exact mass, as the 3-D layers do.
//!
//! The lattice's masses are not rescaled: a particle next to the surface carries its whole
//! cell, so Σ m differs from ρV/2π by the raw error (a boundary effect, of either sign), as
//! for the 3-D lattices.

use crate::error::{GeometryError, bounds_of, check_candidates, positive_finite};
use crate::fibonacci::{Shell, shells};
use crate::placement::BodyParticles;
use crate::shape::{Aabb, Shape};
use rayon::prelude::*;
use sph_core::glam::{DVec2, DVec3};
use std::f64::consts::{PI, TAU};

/// The (r, z) box of the meridional section of a 3-D box: r from 0 to the farthest
/// corner's distance from the axis, z as the box.
fn section_bounds(b: &Aabb<DVec3>) -> (f64, f64, f64) {
    let rx = b.min.x.abs().max(b.max.x.abs());
    let ry = b.min.y.abs().max(b.max.y.abs());
    ((rx * rx + ry * ry).sqrt(), b.min.z, b.max.z)
}

/// The 3-D point of (r, z) in the half-plane y = 0.
#[inline]
fn point3(p: DVec2) -> DVec3 {
    DVec3::new(p.x, 0.0, p.y)
}

/// The totals of an RZ placement from its ring masses per radian.
fn finish<S: Shape<DVec3> + ?Sized>(
    shape: &S,
    positions: Vec<DVec2>,
    masses: Vec<f64>,
    spacing: Vec<f64>,
    density: f64,
    min_spacing: f64,
) -> BodyParticles<DVec2> {
    let raw_total = TAU * masses.iter().sum::<f64>();
    let exact_volume = shape.volume();
    let volume = exact_volume.unwrap_or(raw_total / density);
    let area: f64 = positions
        .iter()
        .zip(&masses)
        .map(|(p, m)| m / (density * p.x))
        .sum();
    BodyParticles {
        body: shape.describe(),
        raw_mass_error: exact_volume.map(|v| raw_total / (density * v) - 1.0),
        lattice_equivalent_count: area / (min_spacing * min_spacing),
        positions,
        masses,
        spacing,
        density,
        exact_volume,
        volume,
    }
}

/// Fills the meridional section of an axisymmetric 3-D `shape` with a square lattice of
/// spacing `spacing` (m): r = (a + ½)Δ, a = 0, 1, …, and z on the layers
/// [`cubic_lattice`](crate::cubic_lattice) uses for the same shape (centred on its
/// bounds, cell-centred), so a 3-D and an RZ lattice share their top layer. A site is
/// kept when (r, 0, z) is inside; its mass is the ring mass per radian of its cell,
/// ρΔ²r (kg/rad), for mass density `density` (kg/m³).
pub fn rz_lattice<S: Shape<DVec3> + ?Sized>(
    shape: &S,
    spacing: f64,
    density: f64,
) -> Result<BodyParticles<DVec2>, GeometryError> {
    let a = positive_finite("rz_lattice(spacing)", spacing)?;
    positive_finite("rz_lattice(density)", density)?;
    let bounds = bounds_of(shape, "RZ lattice")?;
    let (r_max, z_min, z_max) = section_bounds(&bounds);
    let nr = ((r_max / a - 1e-9).ceil().max(1.0)) as usize;
    let nz = (((z_max - z_min) / a - 1e-9).ceil().max(1.0)) as usize;
    let candidates = nr as f64 * nz as f64;
    check_candidates(shape, "RZ lattice", candidates)?;
    let zc = 0.5 * (z_min + z_max);
    let positions: Vec<DVec2> = (0..nr * nz)
        .into_par_iter()
        .map(|lin| {
            let (i, j) = (lin % nr, lin / nr);
            DVec2::new(
                (i as f64 + 0.5) * a,
                zc + (j as f64 - 0.5 * (nz - 1) as f64) * a,
            )
        })
        .filter(|&p| shape.contains(point3(p)))
        .collect();
    if positions.is_empty() {
        return Err(GeometryError::EmptyPlacement {
            body: shape.describe(),
            reason: format!(
                "no site of the RZ lattice with spacing {a} m lies inside it (section r ≤ {r_max}, \
                 {z_min} ≤ z ≤ {z_max}); use a smaller spacing"
            ),
        });
    }
    let masses = positions.iter().map(|p| density * a * a * p.x).collect();
    let n = positions.len();
    Ok(finish(shape, positions, masses, vec![a; n], density, a))
}

/// The 2-D (meridional) analogue of the study's variable-resolution layers (paper §4;
/// [`FibonacciPlacement`](crate::FibonacciPlacement) in 3-D).
///
/// About an origin on the axis, (0, origin_z), layer k has spacing Δ_k = A_res q^k and
/// owns the half-annulus b_(k−1) ≤ R ≤ b_k of the half-plane r ≥ 0, with the same radii as
/// the 3-D layers ([`shells`]: b_k = Σ_(i≤k) Δ_i, points at the mid radius R_k). Its n_k
/// points sit at the polar angles θ_j = (j + ½)π/n_k (θ from +z), at
/// r = R_k sin θ_j > 0, z = origin_z + R_k cos θ_j, and own the annular sectors
/// [jπ/n_k, (j+1)π/n_k]. Only points inside the body are kept, each with the ring mass
/// per radian of the part of its sector inside the body: ρ (b_k³ − b_(k−1)³)/3 ·
/// (cos θ_a − cos θ_b) in the interior, times the inside fraction (8 × 8 sub-cells, at
/// least ⅛) at a surface. `raw_mass_error` is 2π Σ m/(ρV) − 1 of these; then, when the
/// shape knows its volume, all masses are rescaled so that 2π Σ m = ρV.
///
/// **Point count.** n_k is the even number nearest π R_k/Δ_k (at least 2), so the arc
/// spacing is Δ_k up to rounding. Even rather than just nearest: then θ = π/2 is a sector
/// boundary in every layer, so the plane z = origin_z (the target's top face when the
/// origin is the impact point, a sphere's equator when it is the centre) is tiled exactly,
/// and no particle sits on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RzLayeredPlacement {
    origin_z: f64,
    first_spacing: f64,
    ratio: f64,
    density: f64,
}

/// n_k: the even number nearest π R/Δ, at least 2.
pub fn rz_layer_point_count(radius: f64, spacing: f64) -> usize {
    2 * ((0.5 * PI * radius / spacing).round() as usize).max(1)
}

impl RzLayeredPlacement {
    /// A placement about (r, z) = (0, `origin_z`) (m, finite) with first-layer spacing
    /// `first_spacing` (A_res > 0, m), ratio `ratio` (q ≥ 1, finite; 1 is uniform) and
    /// mass density `density` (> 0, kg/m³).
    pub fn new(
        origin_z: f64,
        first_spacing: f64,
        ratio: f64,
        density: f64,
    ) -> Result<Self, GeometryError> {
        if !origin_z.is_finite() {
            return Err(GeometryError::InvalidParameter {
                field: "RzLayeredPlacement.origin_z",
                value: origin_z,
                requirement: "must be finite",
            });
        }
        if !(ratio >= 1.0 && ratio.is_finite()) {
            return Err(GeometryError::InvalidParameter {
                field: "RzLayeredPlacement.ratio (q)",
                value: ratio,
                requirement: "must be finite and at least 1",
            });
        }
        Ok(Self {
            origin_z,
            first_spacing: positive_finite(
                "RzLayeredPlacement.first_spacing (A_res)",
                first_spacing,
            )?,
            ratio,
            density: positive_finite("RzLayeredPlacement.density", density)?,
        })
    }

    /// The origin's z (m).
    pub fn origin_z(&self) -> f64 {
        self.origin_z
    }
    /// A_res (m).
    pub fn first_spacing(&self) -> f64 {
        self.first_spacing
    }
    /// q.
    pub fn ratio(&self) -> f64 {
        self.ratio
    }
    /// ρ (kg/m³).
    pub fn density(&self) -> f64 {
        self.density
    }

    /// The layers that can touch a body with 3-D bounds `bounds`.
    fn layers(&self, bounds: &Aabb<DVec3>) -> Result<Vec<Shell>, GeometryError> {
        let (r_max, z_min, z_max) = section_bounds(bounds);
        let dz_far = (z_min - self.origin_z)
            .abs()
            .max((z_max - self.origin_z).abs());
        let reach = (r_max * r_max + dz_far * dz_far).sqrt();
        let near = (z_min - self.origin_z).max(self.origin_z - z_max).max(0.0);
        Ok(shells(self.first_spacing, self.ratio, reach)?
            .into_iter()
            .filter(|s| s.outer >= near)
            .collect())
    }

    /// Fills the meridional section of the axisymmetric 3-D `shape` with particles.
    pub fn place<S: Shape<DVec3> + ?Sized>(
        &self,
        shape: &S,
    ) -> Result<BodyParticles<DVec2>, GeometryError> {
        let bounds = bounds_of(shape, "RZ layered placement")?;
        let layers = self.layers(&bounds)?;
        let candidates: f64 = layers
            .iter()
            .map(|s| rz_layer_point_count(s.radius, s.spacing) as f64)
            .sum();
        check_candidates(shape, "RZ layered placement", candidates)?;
        let per_layer: Vec<Vec<(DVec2, f64, f64)>> =
            layers.par_iter().map(|s| self.layer(s, shape)).collect();
        let n: usize = per_layer.iter().map(Vec::len).sum();
        if n == 0 {
            return Err(GeometryError::EmptyPlacement {
                body: shape.describe(),
                reason: format!(
                    "no point of the {} RZ layers about z = {} m (A_res {} m, q {}) lies inside it",
                    layers.len(),
                    self.origin_z,
                    self.first_spacing,
                    self.ratio
                ),
            });
        }
        let (mut positions, mut masses, mut spacing) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for (p, m, d) in per_layer.into_iter().flatten() {
            positions.push(p);
            masses.push(m);
            spacing.push(d);
        }
        let mut body = finish(
            shape,
            positions,
            masses,
            spacing,
            self.density,
            self.first_spacing,
        );
        // As the 3-D layers do (docs/placement.md §2): the raw error is kept, then the
        // masses are rescaled so that the body has its exact mass.
        if let Some(v) = body.exact_volume {
            let scale = self.density * v / (TAU * body.total_mass());
            body.masses.iter_mut().for_each(|m| *m *= scale);
        }
        Ok(body)
    }

    /// The kept points of one layer: position, ring mass per radian, spacing. A point
    /// inside the body carries the part of its sector inside the body
    /// ([`inside_fraction`](Self::inside_fraction), at least an eighth); the inside part
    /// of a sector whose point is outside goes to the layer's kept point nearest in angle
    /// (lost only when the layer keeps none).
    fn layer<S: Shape<DVec3> + ?Sized>(&self, s: &Shell, shape: &S) -> Vec<(DVec2, f64, f64)> {
        let n = rz_layer_point_count(s.radius, s.spacing);
        let radial = self.density * (s.outer.powi(3) - s.inner.powi(3)) / 3.0;
        let dt = PI / n as f64;
        // (j, point, inside mass, kept)
        let sectors: Vec<(usize, DVec2, f64, bool)> = (0..n)
            .map(|j| {
                let p = self.point(s.radius, (j as f64 + 0.5) * dt);
                let (a, b) = (j as f64 * dt, (j + 1) as f64 * dt);
                let kept = p.x > 0.0 && shape.contains(point3(p));
                let mut inside = self.inside_fraction(s, (a, b), shape);
                if kept {
                    inside = inside.max(0.125);
                }
                (j, p, inside * radial * (a.cos() - b.cos()), kept)
            })
            .collect();
        let mut out: Vec<(usize, DVec2, f64)> = sectors
            .iter()
            .filter(|s| s.3)
            .map(|&(j, p, m, _)| (j, p, m))
            .collect();
        if !out.is_empty() {
            for &(j, _, m, kept) in &sectors {
                if !kept && m > 0.0 {
                    let k = (0..out.len())
                        .min_by_key(|&k| out[k].0.abs_diff(j))
                        .unwrap_or(0);
                    out[k].2 += m;
                }
            }
        }
        out.into_iter().map(|(_, p, m)| (p, m, s.spacing)).collect()
    }

    /// The point (r, z) at distance `radius` from the origin and polar angle `theta` from +z.
    fn point(&self, radius: f64, theta: f64) -> DVec2 {
        DVec2::new(radius * theta.sin(), self.origin_z + radius * theta.cos())
    }

    /// The fraction of the ring volume of the sector [inner, outer] × [θ_a, θ_b] of shell
    /// `s` that lies inside `shape`, by the midpoint rule on 8 × 8 sub-cells weighted by
    /// the ring volume element R² sin θ dR dθ. 1 in the interior; at a surface the particle
    /// then carries the body actually next to it rather than its whole sector (a 2 mm
    /// layer about the centre of a 3 mm sphere reaches 4 mm: the whole sectors would
    /// give the sphere 2.4 times its mass).
    fn inside_fraction<S: Shape<DVec3> + ?Sized>(
        &self,
        s: &Shell,
        (ta, tb): (f64, f64),
        shape: &S,
    ) -> f64 {
        const SUB: usize = 8;
        let (mut inside, mut all) = (0.0, 0.0);
        for i in 0..SUB {
            let radius = s.inner + (i as f64 + 0.5) / SUB as f64 * (s.outer - s.inner);
            for j in 0..SUB {
                let theta = ta + (j as f64 + 0.5) / SUB as f64 * (tb - ta);
                let w = radius * radius * theta.sin();
                all += w;
                if shape.contains(point3(self.point(radius, theta))) {
                    inside += w;
                }
            }
        }
        inside / all
    }
}

//! Mass assignment: which layer's particles represent which part of the body.
//!
//! The body inside shell k along a direction u belongs to layer k's particle in that
//! direction when that particle exists, i.e. when its site x0 + R_k u is inside the
//! body. When it is not (the surface passes between the shell's inner face and R_k, or
//! beyond R_k coming from outside), the stretch is an *orphan*: it goes to the nearest
//! layer along the same ray whose site is inside, which is a 1-D Voronoi rule along the
//! ray. The part of the orphan below R_k tries layer k − 1 first, the part above tries
//! k + 1 first; an orphan with neither neighbour inside (a feature thinner than two
//! layers) is lost and shows up in the raw total-mass error.
//!
//! Without this rule, a surface parallel to the layers (a ball about its centre, the
//! cylinder's side wall near the top face) leaves the outer part of the last shell with
//! no particle, and its volume either disappears or, after normalising the total, is
//! spread over the whole body as a uniform density excess (+7 % for a ball of radius
//! 20 A_res at q = 1.01 about its centre; measured before this rule was added).
//!
//! Two quantities use the same rule:
//!
//! * [`LayerProbe::credits`]: the volume each layer represents, integrated over a dense
//!   Fibonacci sphere of directions (accurate shell totals);
//! * [`LayerProbe::particle_weight`]: the cubed radial length a particle represents
//!   along its own direction, which distributes its layer's volume among the layer's
//!   particles in proportion to the body actually near each of them.

use super::ray::{cubed_length, cubed_length_split, inside_intervals};
use super::shells::Shell;
use super::sphere_points::{PoleFrame, fibonacci_direction};
use crate::shape::{Aabb, Shape};
use sph_core::glam::DVec3;
use std::f64::consts::PI;

/// A particle whose own ray holds almost none of the body (it grazes an edge) still
/// gets this fraction of an interior particle's weight, so no particle is massless.
pub(crate) const MIN_WEIGHT_FRACTION: f64 = 0.125;

/// The layers about one origin, and the body they fill.
pub(crate) struct LayerProbe<'a, S: ?Sized> {
    pub shape: &'a S,
    pub bounds: Aabb<DVec3>,
    pub origin: DVec3,
    /// Consecutive layers; those before the first cannot reach the body.
    pub layers: &'a [Shell],
    /// Sample intervals along a ray across one shell.
    pub samples: usize,
    /// Orientation of the quadrature's Fibonacci spheres.
    pub frame: PoleFrame,
}

/// Volumes (m³) from one layer's direction quadrature.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Credits {
    /// V(shell ∩ body), the geometric volume.
    pub geometric: f64,
    /// The part this layer's own particles represent.
    pub own: f64,
    /// Orphans handed to the layer inside (index − 1).
    pub to_inner: f64,
    /// Orphans handed to the layer outside (index + 1).
    pub to_outer: f64,
    /// Orphans with no neighbour inside the body.
    pub lost: f64,
}

impl<S: Shape<DVec3> + ?Sized> LayerProbe<'_, S> {
    #[inline]
    fn inside(&self, p: DVec3) -> bool {
        self.bounds.contains(p) && self.shape.contains(p)
    }

    /// Whether the site of layer `j` (position in `layers`) along `u` is in the body;
    /// false for layers outside the list.
    #[inline]
    fn site_inside(&self, j: Option<usize>, u: DVec3) -> bool {
        match j.and_then(|j| self.layers.get(j)) {
            Some(s) => self.inside(self.origin + u * s.radius),
            None => false,
        }
    }

    fn intervals(&self, j: usize, u: DVec3, out: &mut Vec<(f64, f64)>) {
        let s = &self.layers[j];
        let inside = |p: DVec3| self.inside(p);
        inside_intervals(
            &inside,
            self.origin,
            u,
            (s.inner, s.outer),
            self.samples,
            out,
        );
    }

    /// The volume layer `k` represents and hands on, from `directions` Fibonacci
    /// directions.
    pub fn credits(&self, k: usize, directions: usize) -> Credits {
        let radius = self.layers[k].radius;
        let mut c = Credits::default();
        let mut iv = Vec::new();
        for n in 1..=directions {
            let u = self.frame.apply(fibonacci_direction(n, directions));
            self.intervals(k, u, &mut iv);
            if iv.is_empty() {
                continue;
            }
            let total = cubed_length(&iv);
            c.geometric += total;
            if self.inside(self.origin + u * radius) {
                c.own += total;
                continue;
            }
            let (below, above) = cubed_length_split(&iv, radius);
            let inner = self.site_inside(k.checked_sub(1), u);
            let outer = self.site_inside(Some(k + 1), u);
            for (part, first_inner) in [(below, true), (above, false)] {
                match (first_inner, inner, outer) {
                    (true, true, _) | (false, true, false) => c.to_inner += part,
                    (false, _, true) | (true, false, true) => c.to_outer += part,
                    _ => c.lost += part,
                }
            }
        }
        // Each direction owns 4π/M of solid angle; ∫ r² dr = Δ(r³)/3.
        let scale = 4.0 * PI / (3.0 * directions as f64);
        Credits {
            geometric: c.geometric * scale,
            own: c.own * scale,
            to_inner: c.to_inner * scale,
            to_outer: c.to_outer * scale,
            lost: c.lost * scale,
        }
    }

    /// The cubed radial length (Σ Δr³) the particle of layer `k` in direction `u`
    /// represents under the orphan rule, floored at [`MIN_WEIGHT_FRACTION`] of a full
    /// shell.
    pub fn particle_weight(&self, k: usize, u: DVec3, iv: &mut Vec<(f64, f64)>) -> f64 {
        self.intervals(k, u, iv);
        let mut w = cubed_length(iv);
        // Orphans of the next layer out: its lower part comes here first; its upper
        // part comes here if layer k + 2 has no site along u.
        if k + 1 < self.layers.len() && !self.site_inside(Some(k + 1), u) {
            self.intervals(k + 1, u, iv);
            let (below, above) = cubed_length_split(iv, self.layers[k + 1].radius);
            w += below;
            if !self.site_inside(Some(k + 2), u) {
                w += above;
            }
        }
        // Orphans of the next layer in: its upper part comes here first; its lower part
        // comes here if layer k − 2 has no site along u.
        if k >= 1 && !self.site_inside(Some(k - 1), u) {
            self.intervals(k - 1, u, iv);
            let (below, above) = cubed_length_split(iv, self.layers[k - 1].radius);
            w += above;
            if !self.site_inside(k.checked_sub(2), u) {
                w += below;
            }
        }
        let s = &self.layers[k];
        w.max(MIN_WEIGHT_FRACTION * (s.outer.powi(3) - s.inner.powi(3)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Sphere;
    use crate::fibonacci::shells;

    /// A ball about the origin whose surface lies below the last layer's radius: the
    /// last shell's body part is an orphan handed inward in full.
    #[test]
    fn concentric_orphans_go_inward() {
        let layers = shells(1.0, 1.0, 10.0).unwrap();
        let ball = Sphere::new(DVec3::ZERO, 5.2).unwrap(); // shell 5 is [5, 6], R_5 = 5.5
        let probe = LayerProbe {
            shape: &ball,
            bounds: ball.bounds().unwrap(),
            origin: DVec3::ZERO,
            layers: &layers,
            samples: 4,
            frame: PoleFrame::Z,
        };
        let c5 = probe.credits(5, 200);
        let exact = 4.0 / 3.0 * PI * (5.2f64.powi(3) - 125.0);
        assert!((c5.geometric / exact - 1.0).abs() < 1e-10);
        assert!((c5.to_inner / exact - 1.0).abs() < 1e-10);
        assert_eq!((c5.own, c5.to_outer, c5.lost), (0.0, 0.0, 0.0));
        let c4 = probe.credits(4, 200);
        assert!((c4.own / c4.geometric - 1.0).abs() < 1e-12 && c4.to_inner == 0.0);
        // The particle of layer 4 takes its own shell and the orphan along its ray.
        let mut iv = Vec::new();
        let w = probe.particle_weight(4, DVec3::Z, &mut iv);
        assert!((w - (5.2f64.powi(3) - 64.0)).abs() < 1e-9, "{w}");
        let w3 = probe.particle_weight(3, DVec3::Z, &mut iv);
        assert!((w3 - (64.0 - 27.0)).abs() < 1e-9);
    }

    /// A ball away from the origin whose near surface falls above a layer's radius:
    /// rays enter the body there and the orphan goes outward.
    #[test]
    fn entering_orphans_go_outward() {
        let layers = shells(1.0, 1.0, 30.0).unwrap();
        // Along +x the body spans [10.7, 20.7]; shell 10 is [10, 11] with R = 10.5.
        let ball = Sphere::new(DVec3::new(15.7, 0.0, 0.0), 5.0).unwrap();
        let probe = LayerProbe {
            shape: &ball,
            bounds: ball.bounds().unwrap(),
            origin: DVec3::ZERO,
            layers: &layers,
            samples: 4,
            frame: PoleFrame::Z,
        };
        let mut iv = Vec::new();
        let w11 = probe.particle_weight(11, DVec3::X, &mut iv);
        assert!(
            (w11 - (12f64.powi(3) - 10.7f64.powi(3))).abs() < 1e-8,
            "{w11}"
        );
        let c10 = probe.credits(10, 2000);
        assert!(c10.own == 0.0 && c10.to_inner == 0.0 && c10.lost == 0.0);
        assert!((c10.to_outer / c10.geometric - 1.0).abs() < 1e-12);
    }
}

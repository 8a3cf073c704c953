//! The two geometries a scene runs in, as solver dimensions — 3-D ([`Dim3`]) and
//! axisymmetric ([`Dim2`] particles in the (r, z) half-plane with
//! [`Geometry::Axisymmetric`]) — and how each maps to the scene's 3-D convention that the
//! diagnostics and the output use (docs/diagnostics.md §1): an RZ particle is the point
//! (r, 0, z) with velocity (v_r, 0, v_z) and the whole ring's mass, 2π × its mass per
//! radian.

use crate::scene::place::PlacedParticles;
use crate::scene::settings::GeometryKind;
use crate::solver::{Geometry, Simulation};
use sph_core::glam::{DMat3, DVec2, DVec3};
use sph_core::{Dim2, Dim3, Dimension};
use sph_geometry::BodyParticles;
use sph_kernel::KernelChoice;
use std::f64::consts::TAU;

/// A scene's simulation, in its geometry.
pub enum SceneSimulation {
    /// Full 3-D.
    ThreeD(Simulation<Dim3, KernelChoice>),
    /// Axisymmetric (RZ): (r, z) particles, masses per radian, totals per radian.
    Rz(Simulation<Dim2, KernelChoice>),
}

impl SceneSimulation {
    /// The geometry.
    pub fn geometry(&self) -> GeometryKind {
        match self {
            Self::ThreeD(_) => GeometryKind::ThreeD,
            Self::Rz(_) => GeometryKind::Rz,
        }
    }

    /// Number of particles (rings in RZ).
    pub fn particle_count(&self) -> usize {
        match self {
            Self::ThreeD(s) => s.state.particles.len(),
            Self::Rz(s) => s.state.particles.len(),
        }
    }

    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        match self {
            Self::ThreeD(s) => s.state.time,
            Self::Rz(s) => s.state.time,
        }
    }

    /// The 3-D simulation, if this is one.
    pub fn three_d(&self) -> Option<&Simulation<Dim3, KernelChoice>> {
        match self {
            Self::ThreeD(s) => Some(s),
            Self::Rz(_) => None,
        }
    }

    /// The RZ simulation, if this is one.
    pub fn rz(&self) -> Option<&Simulation<Dim2, KernelChoice>> {
        match self {
            Self::Rz(s) => Some(s),
            Self::ThreeD(_) => None,
        }
    }
}

/// What building and running a scene needs of its dimension.
pub(crate) trait SceneDimension: Dimension {
    /// The scene geometry it stands for.
    const KIND: GeometryKind;
    /// Solver masses and totals × this = the bodies' (1 in 3-D; 2π in RZ, where they are
    /// per radian).
    const BODY_FACTOR: f64;
    /// The solver geometry.
    const GEOMETRY: Geometry;
    /// The placed particles, if they are of this dimension.
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<Self::Vector>>;
    /// A scene vector (a body's velocity, on the z axis in RZ) as the solver's.
    fn from_scene(v: DVec3) -> Self::Vector;
    /// A solver vector in the scene's convention: itself, or (r, 0, z) in RZ.
    fn to_scene(v: Self::Vector) -> [f64; 3];
    /// A solver 3×3 tensor in the frame of [`Self::to_scene`]: itself, or in RZ the
    /// (r, z, θ) components of the solver (its 2-D plane, then the hoop entry) as
    /// (r, θ, z), the frame of the point (r, 0, z).
    fn tensor_to_scene(t: &DMat3) -> DMat3;
    /// Wraps a simulation of this dimension.
    fn wrap(sim: Simulation<Self, KernelChoice>) -> SceneSimulation;
    /// The number of 3-D particles a body's particles stand for, over which its
    /// Benz–Asphaug flaws are dealt: their own count in 3-D; in RZ each ring's ≈ 2πr/Δ
    /// points around the axis (`sph_geometry::ring_point_count`), so that a ring has the
    /// flaws of one 3-D particle, not of its whole volume.
    fn stands_for(p: &BodyParticles<Self::Vector>) -> usize;
}

impl SceneDimension for Dim3 {
    const KIND: GeometryKind = GeometryKind::ThreeD;
    const BODY_FACTOR: f64 = 1.0;
    const GEOMETRY: Geometry = Geometry::Cartesian;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<DVec3>> {
        match p {
            PlacedParticles::ThreeD(b) | PlacedParticles::Quarter(b) => Some(b),
            PlacedParticles::Rz(_) => None,
        }
    }
    fn from_scene(v: DVec3) -> DVec3 {
        v
    }
    fn to_scene(v: DVec3) -> [f64; 3] {
        v.to_array()
    }
    fn tensor_to_scene(t: &DMat3) -> DMat3 {
        *t
    }
    fn wrap(sim: Simulation<Dim3, KernelChoice>) -> SceneSimulation {
        SceneSimulation::ThreeD(sim)
    }
    fn stands_for(p: &BodyParticles<DVec3>) -> usize {
        p.len()
    }
}

impl SceneDimension for Dim2 {
    const KIND: GeometryKind = GeometryKind::Rz;
    const BODY_FACTOR: f64 = TAU;
    const GEOMETRY: Geometry = Geometry::Axisymmetric;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<DVec2>> {
        match p {
            PlacedParticles::Rz(b) => Some(b),
            PlacedParticles::ThreeD(_) | PlacedParticles::Quarter(_) => None,
        }
    }
    /// (v_r, v_z) of a body moving along the axis: (0, v_z) (x = y = 0 is checked).
    fn from_scene(v: DVec3) -> DVec2 {
        DVec2::new(0.0, v.z)
    }
    fn to_scene(v: DVec2) -> [f64; 3] {
        [v.x, 0.0, v.y]
    }
    fn tensor_to_scene(t: &DMat3) -> DMat3 {
        // Index k of the scene frame (r, θ, z) is index P[k] of the solver's (r, z, θ).
        const P: [usize; 3] = [0, 2, 1];
        DMat3::from_cols_array_2d(&std::array::from_fn(|c| {
            std::array::from_fn(|r| t.col(P[c])[P[r]])
        }))
    }
    fn wrap(sim: Simulation<Dim2, KernelChoice>) -> SceneSimulation {
        SceneSimulation::Rz(sim)
    }
    fn stands_for(p: &BodyParticles<DVec2>) -> usize {
        p.positions
            .iter()
            .zip(&p.spacing)
            .map(|(x, &dx)| sph_geometry::ring_point_count(x.x, dx, 1))
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Particles at `positions`, all of spacing `dx` (the other fields do not matter here).
    fn body<V: sph_core::Vector>(positions: Vec<V>, dx: f64) -> BodyParticles<V> {
        let n = positions.len();
        BodyParticles {
            body: "b".into(),
            positions,
            masses: vec![1.0; n],
            spacing: vec![dx; n],
            density: 1.0,
            exact_volume: None,
            volume: 1.0,
            raw_mass_error: None,
            lattice_equivalent_count: n as f64,
        }
    }

    /// An RZ body stands for the 3-D points of its revolved rings, ≈ 2πr/Δ per ring (the
    /// count its Benz–Asphaug flaws are dealt over); a 3-D body for itself.
    #[test]
    fn rings_stand_for_the_points_around_the_axis() {
        let dx = 1.0e-3;
        let rings = body(
            (0..4)
                .map(|a| DVec2::new((a as f64 + 0.5) * dx, 0.0))
                .collect(),
            dx,
        );
        // round(2π(a + ½)) for a = 0…3: 3, 9, 16, 22.
        assert_eq!(Dim2::stands_for(&rings), 3 + 9 + 16 + 22);
        assert_eq!(Dim3::stands_for(&body(vec![DVec3::ZERO; 7], dx)), 7);
    }

    #[test]
    fn rz_tensor_goes_to_the_r_theta_z_frame() {
        // Solver frame (r, z, θ): S_rr = 1, S_zz = 2, S_θθ = 3, S_rz = 4.
        let s = DMat3::from_cols_array_2d(&[[1.0, 4.0, 0.0], [4.0, 2.0, 0.0], [0.0, 0.0, 3.0]]);
        let t = Dim2::tensor_to_scene(&s);
        // Scene frame (r, θ, z): diagonal 1, 3, 2; S_rz at (0, 2).
        assert_eq!(t.x_axis.to_array(), [1.0, 0.0, 4.0]);
        assert_eq!(t.y_axis.to_array(), [0.0, 3.0, 0.0]);
        assert_eq!(t.z_axis.to_array(), [4.0, 0.0, 2.0]);
        assert_eq!(Dim2::to_scene(DVec2::new(0.5, -2.0)), [0.5, 0.0, -2.0]);
    }
}

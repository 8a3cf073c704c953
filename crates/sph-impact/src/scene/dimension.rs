//! The geometries a scene runs in, as solver dimensions — 3-D ([`In3d`], also the 3-D
//! quarter model), axisymmetric ([`InRz`]: [`Dim2`] particles in the (r, z) half-plane
//! with [`Geometry::Axisymmetric`]), plane strain ([`InPlane`]: [`Dim2`] particles in
//! (x, z)) and uniaxial strain ([`InLine`]: [`Dim1`] particles in z) — and how each maps
//! to the scene's 3-D convention that the diagnostics and the output use
//! (docs/diagnostics.md §1): an RZ particle is the point (r, 0, z) with velocity
//! (v_r, 0, v_z) and the whole ring's mass, 2π × its mass per radian; a plane particle is
//! (x, 0, z) with its mass per metre of depth; a 1-D particle is (0, 0, z) with its mass
//! per square metre.

use crate::scene::place::PlacedParticles;
use crate::scene::settings::GeometryKind;
use crate::solver::{Geometry, Simulation};
use sph_core::glam::{DMat3, DVec2, DVec3};
use sph_core::{Dim1, Dim2, Dim3, Dimension};
use sph_geometry::BodyParticles;
use sph_kernel::KernelChoice;
use std::f64::consts::TAU;

/// A scene's simulation, in its geometry.
pub enum SceneSimulation {
    /// Full 3-D (also the 3-D quarter model).
    ThreeD(Simulation<Dim3, KernelChoice>),
    /// Axisymmetric (RZ): (r, z) particles, masses per radian, totals per radian.
    Rz(Simulation<Dim2, KernelChoice>),
    /// Plane strain: (x, z) particles, masses and totals per metre of depth.
    Plane(Simulation<Dim2, KernelChoice>),
    /// Uniaxial strain (1-D): z particles, masses and totals per square metre.
    Line(Simulation<Dim1, KernelChoice>),
}

/// `$body` with `$s` bound to the simulation, whatever its dimension.
macro_rules! each {
    ($sim:expr, $s:ident => $body:expr) => {
        match $sim {
            SceneSimulation::ThreeD($s) => $body,
            SceneSimulation::Rz($s) | SceneSimulation::Plane($s) => $body,
            SceneSimulation::Line($s) => $body,
        }
    };
}

impl SceneSimulation {
    /// The geometry (3-D for a quarter model too).
    pub fn geometry(&self) -> GeometryKind {
        match self {
            Self::ThreeD(_) => GeometryKind::ThreeD,
            Self::Rz(_) => GeometryKind::Rz,
            Self::Plane(_) => GeometryKind::Plane,
            Self::Line(_) => GeometryKind::Line,
        }
    }

    /// Number of particles (rings in RZ).
    pub fn particle_count(&self) -> usize {
        each!(self, s => s.state.particles.len())
    }

    /// Simulated time (s).
    pub fn time(&self) -> f64 {
        each!(self, s => s.state.time)
    }

    /// The 3-D simulation, if this is one.
    pub fn three_d(&self) -> Option<&Simulation<Dim3, KernelChoice>> {
        match self {
            Self::ThreeD(s) => Some(s),
            _ => None,
        }
    }

    /// The RZ simulation, if this is one.
    pub fn rz(&self) -> Option<&Simulation<Dim2, KernelChoice>> {
        match self {
            Self::Rz(s) => Some(s),
            _ => None,
        }
    }

    /// The plane-strain simulation, if this is one.
    pub fn plane(&self) -> Option<&Simulation<Dim2, KernelChoice>> {
        match self {
            Self::Plane(s) => Some(s),
            _ => None,
        }
    }

    /// The 1-D simulation, if this is one.
    pub fn line(&self) -> Option<&Simulation<Dim1, KernelChoice>> {
        match self {
            Self::Line(s) => Some(s),
            _ => None,
        }
    }
}

/// 3-D, full or quarter: particles are points.
pub(crate) struct In3d;
/// Axisymmetric (RZ): particles are rings, (r, z) in the half-plane r > 0.
pub(crate) struct InRz;
/// Plane strain: particles are prisms along y, (x, z) in the section y = 0.
pub(crate) struct InPlane;
/// Uniaxial strain: particles are plates, z on the axis.
pub(crate) struct InLine;

/// The solver simulation of geometry `G`.
pub(crate) type SimOf<G> = Simulation<<G as SceneDimension>::Dim, KernelChoice>;

/// What building and running a scene needs of its geometry.
pub(crate) trait SceneDimension {
    /// The solver dimension.
    type Dim: Dimension;
    /// The scene geometry it stands for (3-D for a quarter model too).
    const KIND: GeometryKind;
    /// Solver masses and totals × this = the bodies' (1 in 3-D, plane and 1-D; 2π in RZ,
    /// where they are per radian).
    const BODY_FACTOR: f64;
    /// The solver geometry.
    const GEOMETRY: Geometry;
    /// The placed particles, if they are of this geometry.
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<<Self::Dim as Dimension>::Vector>>;
    /// A scene vector (a body's velocity) as the solver's: itself in 3-D; its z on the
    /// axis in RZ and 1-D, (v_x, v_z) in plane strain (the other components are checked
    /// to be zero).
    fn from_scene(v: DVec3) -> <Self::Dim as Dimension>::Vector;
    /// A solver vector in the scene's convention: itself, (r, 0, z) in RZ, (x, 0, z) in
    /// plane strain, (0, 0, z) in 1-D.
    fn to_scene(v: <Self::Dim as Dimension>::Vector) -> [f64; 3];
    /// A solver 3×3 tensor in the frame of [`Self::to_scene`]: itself in 3-D; in RZ the
    /// (r, z, θ) components of the solver (its 2-D plane, then the hoop entry) as
    /// (r, θ, z), the frame of the point (r, 0, z); in plane strain the solver's (x, z, y)
    /// as (x, y, z); in 1-D the solver's (z, x, y) as (x, y, z).
    fn tensor_to_scene(t: &DMat3) -> DMat3;
    /// Wraps a simulation of this geometry.
    fn wrap(sim: SimOf<Self>) -> SceneSimulation;
    /// The number of 3-D particles a body's particles stand for, over which its
    /// Benz–Asphaug flaws are dealt: their own count in 3-D, plane and 1-D (a prism or
    /// plate has the flaws of one 3-D particle of its spacing); in RZ each ring's ≈ 2πr/Δ
    /// points around the axis (`sph_geometry::ring_point_count`), so that a ring has the
    /// flaws of one 3-D particle, not of its whole volume.
    fn stands_for(p: &BodyParticles<<Self::Dim as Dimension>::Vector>) -> usize {
        p.len()
    }
}

/// The solver tensor with the scene's axis k at the solver's axis `P[k]`.
fn permuted(t: &DMat3, p: [usize; 3]) -> DMat3 {
    DMat3::from_cols_array_2d(&std::array::from_fn(|c| {
        std::array::from_fn(|r| t.col(p[c])[p[r]])
    }))
}

impl SceneDimension for In3d {
    type Dim = Dim3;
    const KIND: GeometryKind = GeometryKind::ThreeD;
    const BODY_FACTOR: f64 = 1.0;
    const GEOMETRY: Geometry = Geometry::Cartesian;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<DVec3>> {
        match p {
            PlacedParticles::ThreeD(b) | PlacedParticles::Quarter(b) => Some(b),
            _ => None,
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
    fn wrap(sim: SimOf<Self>) -> SceneSimulation {
        SceneSimulation::ThreeD(sim)
    }
}

impl SceneDimension for InRz {
    type Dim = Dim2;
    const KIND: GeometryKind = GeometryKind::Rz;
    const BODY_FACTOR: f64 = TAU;
    const GEOMETRY: Geometry = Geometry::Axisymmetric;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<DVec2>> {
        match p {
            PlacedParticles::Rz(b) => Some(b),
            _ => None,
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
        permuted(t, [0, 2, 1])
    }
    fn wrap(sim: SimOf<Self>) -> SceneSimulation {
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

impl SceneDimension for InPlane {
    type Dim = Dim2;
    const KIND: GeometryKind = GeometryKind::Plane;
    const BODY_FACTOR: f64 = 1.0;
    const GEOMETRY: Geometry = Geometry::Cartesian;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<DVec2>> {
        match p {
            PlacedParticles::Plane(b) => Some(b),
            _ => None,
        }
    }
    /// (v_x, v_z) (v_y = 0 is checked).
    fn from_scene(v: DVec3) -> DVec2 {
        DVec2::new(v.x, v.z)
    }
    fn to_scene(v: DVec2) -> [f64; 3] {
        [v.x, 0.0, v.y]
    }
    fn tensor_to_scene(t: &DMat3) -> DMat3 {
        // The solver's plane (x, z) first, then the out-of-plane y.
        permuted(t, [0, 2, 1])
    }
    fn wrap(sim: SimOf<Self>) -> SceneSimulation {
        SceneSimulation::Plane(sim)
    }
}

impl SceneDimension for InLine {
    type Dim = Dim1;
    const KIND: GeometryKind = GeometryKind::Line;
    const BODY_FACTOR: f64 = 1.0;
    const GEOMETRY: Geometry = Geometry::Cartesian;
    fn placed(p: &PlacedParticles) -> Option<&BodyParticles<f64>> {
        match p {
            PlacedParticles::Line(b) => Some(b),
            _ => None,
        }
    }
    /// v_z (v_x = v_y = 0 is checked).
    fn from_scene(v: DVec3) -> f64 {
        v.z
    }
    fn to_scene(v: f64) -> [f64; 3] {
        [0.0, 0.0, v]
    }
    fn tensor_to_scene(t: &DMat3) -> DMat3 {
        // The solver's line is its first axis; the two lateral axes follow.
        permuted(t, [1, 2, 0])
    }
    fn wrap(sim: SimOf<Self>) -> SceneSimulation {
        SceneSimulation::Line(sim)
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
        assert_eq!(InRz::stands_for(&rings), 3 + 9 + 16 + 22);
        assert_eq!(In3d::stands_for(&body(vec![DVec3::ZERO; 7], dx)), 7);
        assert_eq!(InPlane::stands_for(&body(vec![DVec2::ZERO; 5], dx)), 5);
    }

    #[test]
    fn rz_tensor_goes_to_the_r_theta_z_frame() {
        // Solver frame (r, z, θ): S_rr = 1, S_zz = 2, S_θθ = 3, S_rz = 4.
        let s = DMat3::from_cols_array_2d(&[[1.0, 4.0, 0.0], [4.0, 2.0, 0.0], [0.0, 0.0, 3.0]]);
        let t = InRz::tensor_to_scene(&s);
        // Scene frame (r, θ, z): diagonal 1, 3, 2; S_rz at (0, 2).
        assert_eq!(t.x_axis.to_array(), [1.0, 0.0, 4.0]);
        assert_eq!(t.y_axis.to_array(), [0.0, 3.0, 0.0]);
        assert_eq!(t.z_axis.to_array(), [4.0, 0.0, 2.0]);
        assert_eq!(InRz::to_scene(DVec2::new(0.5, -2.0)), [0.5, 0.0, -2.0]);
    }
}

//! Taylor bar (docs/verification.md, "Taylor bar"; Wilkins & Guinan 1973 geometry): a copper rod,
//! L0 = 32.4 mm, R0 = 3.2 mm, hits a rigid frictionless anvil at 227 m/s. ρ = 8930 kg/m³,
//! E = 117 GPa, ν = 0.35 (K = 130 GPa, G = 43.33 GPa; linear elastic EOS), von Mises
//! Y = 400 MPa with linear hardening H = 100 MPa; t_end = 80 µs. Reference (FE spread):
//! L_f = 21.42–21.66 mm, R_f = 7.02–7.24 mm; targets 21.5 mm and 7.1 mm.
//!
//! 3-D quarter model: the symmetry planes x = 0 and y = 0 are mirror walls (ghosts), the
//! anvil z = 0 a contact wall (mirror ghosts that push but cannot pull: the rod's foot
//! may lift off where it is in tension, as on a real anvil), the rod a cubic lattice with
//! `n` spacings across R0, or (`RodPlacement::Rings`, `verify taylor --geometry rings`)
//! the RZ run's rings revolved about the axis, whose foot has no preferred azimuth
//! (docs/verification.md).
//! Measured: L_f = the largest z, R_f = the largest distance from the axis (the widest
//! point of the rod: its mushroomed foot), each as the particle centres plus half a
//! spacing (the material edge); the radius of the foot's contact with the anvil (the
//! same over the particles within one spacing of it, which drops a rim lifted by more
//! than half a spacing); the largest plastic strain; and KE(t).

use super::outcome::{Outcome, Panel, Picture, Profile};
use super::setup::elastic_solid;
use super::setup::simulation;
use crate::{Boundary, Material, SchemeConfig, Simulation, SolverError};
use sph_core::glam::{DVec2, DVec3};
use sph_core::{Dim2, Dim3, Dimension, ParticleInit, Particles};
use sph_eos::LinearElastic;
use sph_geometry::{Cylinder, cubic_lattice, revolve, rz_lattice};
use sph_kernel::KernelChoice;
use sph_strength::VonMises;

const RHO: f64 = 8930.0;
const E_YOUNG: f64 = 117.0e9;
const NU: f64 = 0.35;
const LENGTH: f64 = 32.4e-3;
const RADIUS: f64 = 3.2e-3;
const SPEED: f64 = 227.0;
const T_END: f64 = 80.0e-6;

/// The copper of §6a: linear elastic EOS and von Mises with linear hardening.
fn copper() -> Result<(LinearElastic, VonMises), SolverError> {
    let bulk = E_YOUNG / (3.0 * (1.0 - 2.0 * NU));
    let shear = E_YOUNG / (2.0 * (1.0 + NU));
    elastic_solid(RHO, bulk, shear, 400.0e6, Some(100.0e6))
}

/// How the 3-D rod is filled with particles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum RodPlacement {
    /// A cubic lattice offset by half a spacing from the axis (the default).
    Lattice,
    /// The RZ run's square (r, z) lattice revolved about the axis
    /// ([`sph_geometry::revolve`]): rings of points one spacing apart, no preferred
    /// in-plane axes, and the exact mass of the rod.
    Rings,
}

/// Runs with `n` spacings across the rod's radius, the rod placed by `placement`.
pub(crate) fn run(
    n: usize,
    scheme: SchemeConfig,
    placement: RodPlacement,
) -> Result<Outcome, SolverError> {
    let bad = |e: String| SolverError::Material(e);
    let (eos, strength) = copper()?;
    let dx = RADIUS / n as f64;
    let rod = rod()?;
    let body = match placement {
        RodPlacement::Lattice => cubic_lattice(&rod, dx, RHO),
        // A multiple of 4 points per ring: each quadrant holds a quarter of every ring.
        RodPlacement::Rings => rod_rings(&rod, dx).and_then(|rings| revolve(&rings, 4)),
    }
    .map_err(|e| bad(e.to_string()))?;
    let mut p = Particles::<Dim3>::new();
    for (x, m) in body.positions.iter().zip(&body.masses) {
        // The quarter x > 0, y > 0 (both placements keep every particle off the
        // symmetry planes).
        if x.x > 0.0 && x.y > 0.0 {
            p.push(ParticleInit {
                position: *x,
                velocity: DVec3::new(0.0, 0.0, -SPEED),
                mass: *m,
                density: RHO,
                specific_energy: 0.0,
                smoothing_length: scheme.n_target * dx,
                material: 0,
            });
        }
    }
    let z_min0 = p.position.iter().fold(f64::INFINITY, |a, x| a.min(x.z));
    // Walls: the anvil just below the rod's face (half a spacing below the lowest
    // particle centres: where the material surface is), a contact that pushes but cannot
    // pull, and the symmetry planes (mirrors).
    let walls = vec![
        Boundary::Contact {
            point: DVec3::new(0.0, 0.0, z_min0 - 0.5 * dx),
            normal: DVec3::Z,
        },
        Boundary::Wall {
            point: DVec3::ZERO,
            normal: DVec3::X,
        },
        Boundary::Wall {
            point: DVec3::ZERO,
            normal: DVec3::Y,
        },
    ];
    let count = p.len();
    let sim = simulation(
        p,
        vec![Material::solid("copper (bilinear)", eos, strength)],
        scheme,
        walls,
        Some(vec![dx; count]),
    )?;
    let anvil = z_min0 - 0.5 * dx;
    // Quarter model: the full rod's KE0 is four times the quarter's.
    let name = match placement {
        RodPlacement::Lattice => "taylor",
        RodPlacement::Rings => "taylor (3-D, rings)",
    };
    let run = RodRun::simulate(name, n, dx, sim, 4.0, |x| {
        [x.truncate().length(), x.z - anvil]
    })?;
    Ok(run.outcome())
}

/// The undeformed rod: a cylinder of radius R0 and length L0 standing on z = 0.
fn rod() -> Result<Cylinder, SolverError> {
    Cylinder::new(DVec3::ZERO, DVec3::Z, RADIUS, LENGTH)
        .map_err(|e| SolverError::Material(e.to_string()))
}

/// The rod's (r, z) section as a square lattice of rings with `dx` across R0, its layers
/// spread evenly over exactly L0: the lattice's nz = ⌈L0/Δx⌉ layers are stretched along z
/// by L0/(nz Δx) (with their masses), so the rod is neither longer nor heavier than L0
/// when L0/Δx is not a whole number (at 12 across the plain lattice held 122 layers of
/// 0.267 mm, a rod 0.4 % long).
fn rod_rings(
    rod: &Cylinder,
    dx: f64,
) -> Result<sph_geometry::BodyParticles<DVec2>, sph_geometry::GeometryError> {
    let mut rings = rz_lattice(rod, dx, RHO)?;
    let nz = rings
        .positions
        .iter()
        .filter(|x| x.x == rings.positions[0].x)
        .count();
    let stretch = LENGTH / (nz as f64 * dx);
    for (x, m) in rings.positions.iter_mut().zip(rings.masses.iter_mut()) {
        x.y = 0.5 * LENGTH + (x.y - 0.5 * LENGTH) * stretch;
        *m *= stretch;
    }
    Ok(rings)
}

/// The end state of a rod run in (r, height above the anvil) and its KE history.
struct RodRun {
    name: &'static str,
    resolution: usize,
    steps: u64,
    wall_time_s: f64,
    rz: Vec<[f64; 2]>,
    plastic_strain: Vec<f64>,
    times: Vec<f64>,
    kinetic: Vec<f64>,
    /// L(t), R_f(t) and the anvil contact radius at the sample times (m), read as at
    /// the end.
    length: Vec<f64>,
    face_radius: Vec<f64>,
    contact_radius: Vec<f64>,
    /// The modelled part's KE times this is the full rod's (4 for a quarter, 2π for RZ
    /// per radian).
    full_rod_factor: f64,
    /// RZ: rings the axis mirror brought back to r > 0 (`None` in 3-D).
    axis_crossings: Option<(u64, u64)>,
}

impl RodRun {
    /// Runs `sim` to the end time, sampling its kinetic energy, length and face radius
    /// 80 times, and reads the end state as (r, height above the anvil) with `rz`.
    fn simulate<D: Dimension>(
        name: &'static str,
        resolution: usize,
        dx: f64,
        mut sim: Simulation<D, KernelChoice>,
        full_rod_factor: f64,
        rz: impl Fn(D::Vector) -> [f64; 2],
    ) -> Result<Self, SolverError> {
        let wall = std::time::Instant::now();
        let (mut times, mut kinetic) = (Vec::new(), Vec::new());
        let (mut length, mut face_radius, mut contact_radius) =
            (Vec::new(), Vec::new(), Vec::new());
        let (mut steps, samples) = (0, 80);
        let mut shape: Vec<[f64; 2]> = Vec::new();
        for k in 0..=samples {
            if k > 0 {
                steps += sim.run_until(T_END * k as f64 / samples as f64, |_, _| {})?;
            }
            shape = sim
                .state
                .particles
                .position
                .iter()
                .map(|&x| rz(x))
                .collect();
            times.push(sim.state.time);
            kinetic.push(sim.conserved().kinetic);
            length.push(rod_length(&shape, dx));
            face_radius.push(rod_face_radius(&shape, dx));
            contact_radius.push(anvil_contact_radius(&shape, dx));
        }
        Ok(Self {
            name,
            resolution,
            steps,
            wall_time_s: wall.elapsed().as_secs_f64(),
            // The last sample is the end state.
            rz: shape,
            plastic_strain: sim.state.plastic_strain.clone(),
            times,
            kinetic,
            length,
            face_radius,
            contact_radius,
            full_rod_factor,
            axis_crossings: sim.axis_crossing_counts(),
        })
    }

    /// L_f, R_f, the largest plastic strain and where, the KE history, the picture.
    fn outcome(self) -> Outcome {
        let length = *self.length.last().expect("sampled at t = 0 and after");
        let face_radius = *self.face_radius.last().expect("sampled at t = 0 and after");
        let contact = *self
            .contact_radius
            .last()
            .expect("sampled at t = 0 and after");
        let (mut ep_max, mut ep_at) = (0.0f64, [0.0, 0.0]);
        for (i, &ep) in self.plastic_strain.iter().enumerate() {
            if ep > ep_max {
                ep_max = ep;
                ep_at = self.rz[i];
            }
        }
        let ke0 = self.kinetic[0];
        let mut out = Outcome::for_run(
            self.name,
            self.rz.len(),
            self.resolution,
            Some(T_END),
            self.steps,
            self.wall_time_s,
        );
        out.set_axis_crossings(self.axis_crossings);
        out.set("final_length_mm", length * 1e3);
        out.set("final_length_error_relative", length / 21.5e-3 - 1.0);
        out.set("face_radius_mm", face_radius * 1e3);
        out.set("face_radius_error_relative", face_radius / 7.1e-3 - 1.0);
        out.set("anvil_contact_radius_mm", contact * 1e3);
        out.set("plastic_strain_max", ep_max);
        out.set("plastic_strain_max_radius_mm", ep_at[0] * 1e3);
        out.set("plastic_strain_max_height_mm", ep_at[1] * 1e3);
        out.set(
            "kinetic_energy_final_over_initial",
            self.kinetic.last().unwrap_or(&f64::NAN) / ke0,
        );
        out.set(
            "kinetic_energy_initial_full_rod_j",
            self.full_rod_factor * ke0,
        );
        // Profile: the particles' radius, height and plastic strain at the end.
        let mut rows: Vec<Vec<f64>> = (0..self.rz.len())
            .map(|i| vec![self.rz[i][0], self.rz[i][1], self.plastic_strain[i]])
            .collect();
        rows.sort_by(|a, b| a[0].total_cmp(&b[0]));
        let (r, z): (Vec<f64>, Vec<f64>) =
            rows.iter().map(|row| (row[0] * 1e3, row[1] * 1e3)).unzip();
        let t_us: Vec<f64> = self.times.iter().map(|t| t * 1e6).collect();
        let mm = |v: &[f64]| v.iter().map(|x| x * 1e3).collect::<Vec<f64>>();
        out.history = Profile {
            columns: [
                "t",
                "length",
                "face_radius",
                "anvil_contact_radius",
                "kinetic_energy_full_rod",
            ]
            .map(String::from)
            .to_vec(),
            rows: (0..self.times.len())
                .map(|k| {
                    vec![
                        self.times[k],
                        self.length[k],
                        self.face_radius[k],
                        self.contact_radius[k],
                        self.full_rod_factor * self.kinetic[k],
                    ]
                })
                .collect(),
        };
        out.profile = Profile {
            columns: ["r", "z", "plastic_strain"].map(String::from).to_vec(),
            rows,
        };
        out.pictures.push(Picture {
            name: "taylor".into(),
            title: format!(
                "Taylor bar ({}): L_f = {:.2} mm (21.5), R_f = {:.2} mm (7.1)",
                self.name,
                length * 1e3,
                face_radius * 1e3
            ),
            panels: vec![
                Panel {
                    title: "final shape (all particles, r against z)".into(),
                    labels: ("r (mm)".into(), "z (mm)".into()),
                    points: vec![("particles".into(), r, z)],
                    equal_aspect: true,
                    ..Default::default()
                },
                Panel {
                    title: "kinetic energy (modelled part)".into(),
                    labels: ("t (µs)".into(), "KE (J)".into()),
                    lines: vec![("SPH".into(), t_us.clone(), self.kinetic)],
                    ..Default::default()
                },
                Panel {
                    title: "length L, foot radius R_f and its anvil contact".into(),
                    labels: ("t (µs)".into(), "mm".into()),
                    lines: vec![
                        ("L".into(), t_us.clone(), mm(&self.length)),
                        ("R_f".into(), t_us.clone(), mm(&self.face_radius)),
                        ("anvil contact".into(), t_us, mm(&self.contact_radius)),
                    ],
                    ..Default::default()
                },
            ],
            columns: 3,
        });
        out
    }
}

/// L: the top of the rod (highest particle centre + Δx/2) above the anvil, from the
/// particles as (r, height).
fn rod_length(shape: &[[f64; 2]], dx: f64) -> f64 {
    shape.iter().fold(f64::NEG_INFINITY, |a, x| a.max(x[1])) + 0.5 * dx
}

/// R_f: the outermost particle centre, + Δx/2. The rod's widest point is its foot; on
/// the contact anvil the foot's rim may lift off by a fraction of a spacing (0.2 mm at
/// 8 across in 3-D), and the mushroom's radius is what the FE reference
/// and the recovered rods give.
fn rod_face_radius(shape: &[[f64; 2]], dx: f64) -> f64 {
    outer_radius(shape.iter()) + 0.5 * dx
}

/// The foot's contact with the anvil: the outermost particle centre within one spacing
/// of it, + Δx/2. Less than R_f where the rim has lifted.
fn anvil_contact_radius(shape: &[[f64; 2]], dx: f64) -> f64 {
    outer_radius(shape.iter().filter(|x| x[1] < dx)) + 0.5 * dx
}

/// The largest distance from the axis among `points` (r, height), 0 for none.
fn outer_radius<'a>(points: impl Iterator<Item = &'a [f64; 2]>) -> f64 {
    points.map(|x| x[0]).fold(0.0, f64::max)
}

/// The rod in axisymmetric RZ: a square lattice with `n` spacings across R0 in the (r, z)
/// half-plane, each particle a ring of mass ρ Δx² r per radian; the anvil a contact wall
/// below the rod (it pushes but cannot pull), the axis handled by the solver.
pub(crate) fn run_rz(n: usize, mut scheme: SchemeConfig) -> Result<Outcome, SolverError> {
    scheme.geometry = crate::Geometry::Axisymmetric;
    let (eos, strength) = copper()?;
    let dx = RADIUS / n as f64;
    // The same rings as the 3-D run's `RodPlacement::Rings`.
    let rings = rod_rings(&rod()?, dx).map_err(|e| SolverError::Material(e.to_string()))?;
    let mut p = Particles::<Dim2>::new();
    for (x, m) in rings.positions.iter().zip(&rings.masses) {
        p.push(ParticleInit {
            position: *x,
            velocity: DVec2::new(0.0, -SPEED),
            mass: *m,
            density: RHO,
            specific_energy: 0.0,
            smoothing_length: scheme.n_target * dx,
            material: 0,
        });
    }
    let count = p.len();
    let sim = simulation(
        p,
        vec![Material::solid("copper (bilinear)", eos, strength)],
        scheme,
        vec![Boundary::Contact {
            point: DVec2::ZERO,
            normal: DVec2::Y,
        }],
        Some(vec![dx; count]),
    )?;
    let run = RodRun::simulate("taylor (rz)", n, dx, sim, 2.0 * std::f64::consts::PI, |x| {
        [x.x, x.y]
    })?;
    Ok(run.outcome())
}

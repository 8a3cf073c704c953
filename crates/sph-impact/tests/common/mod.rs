//! What the tests that compare two runs of one scene share: the bundled scenes' text,
//! extra `[solver]` keys, the field-by-field gap between two simulations, and stepping a
//! pair of built simulations of any geometry, the 3-D quarter smoke scene, and a 2-D gas
//! blob with a wall and a periodic pair.

// Each test file uses a part of this module.
#![allow(dead_code)]

use sph_core::{Dimension, Vector};
use sph_impact::solver::Simulation;
use sph_kernel::KernelChoice;
use std::path::PathBuf;

/// The text of the bundled scene `name` (examples/scenes).
pub fn scene_text(name: &str) -> String {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes");
    std::fs::read_to_string(root.join(name)).unwrap()
}

/// The RZ smoke scene as a 3-D quarter model (the two symmetry planes' mirror ghosts), on
/// the four-fold symmetric rings placement the quarter needs.
pub fn quarter_smoke_text() -> String {
    let rz = scene_text("smoke_rz.toml");
    let lattice = "placement = { kind = \"lattice\", spacing = 0.25e-3 }";
    let quarter = rz
        .replacen("geometry = \"rz\"", "geometry = \"3d-quarter\"", 1)
        .replacen(
            lattice,
            "placement = { kind = \"rings\", origin = [0.0, 0.0, 2.0e-3], a_res = 0.25e-3, q = 1.0 }",
            1,
        )
        .replacen(
            lattice,
            "placement = { kind = \"rings\", origin = [0.0, 0.0, 0.0], a_res = 0.25e-3, q = 1.05 }",
            1,
        );
    assert!(!quarter.contains("kind = \"lattice\"") && quarter.contains("3d-quarter"));
    quarter
}

/// The smoke scenes of every geometry, each with the mirror ghosts of its kind: none in
/// 3-D, the two symmetry planes of the 3-D quarter, the axis in RZ, the walls of the 1-D
/// flyer plate.
pub fn smoke_cases() -> Vec<(&'static str, String)> {
    vec![
        ("3d", scene_text("smoke.toml")),
        ("3d-quarter", quarter_smoke_text()),
        ("rz", scene_text("smoke_rz.toml")),
        ("plane", scene_text("smoke_plane.toml")),
        ("1d", scene_text("flyer_plate_1d.toml")),
    ]
}

/// `text` with `keys` added to its `[solver]` table (made if it has none).
pub fn with_solver_keys(text: &str, keys: &str) -> String {
    if text.contains("\n[solver]\n") {
        text.replacen("\n[solver]\n", &format!("\n[solver]\n{keys}"), 1)
    } else {
        format!("{text}\n[solver]\n{keys}")
    }
}

/// The largest difference between two runs' fields, each relative to the field's
/// largest magnitude, and that field.
#[derive(Debug, Default)]
pub struct Gap {
    pub worst: f64,
    pub field: &'static str,
}

impl Gap {
    fn add(&mut self, field: &'static str, a: &[f64], b: &[f64]) {
        assert_eq!(a.len(), b.len());
        let scale = a.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        if scale == 0.0 {
            return;
        }
        let diff = a
            .iter()
            .zip(b)
            .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
        if diff / scale >= self.worst {
            self.worst = diff / scale;
            self.field = field;
        }
    }
}

fn flat<D: Dimension>(v: &[D::Vector]) -> Vec<f64> {
    v.iter().flat_map(|x| x.to_array3()).collect()
}

/// The gap between `a` and `b` over position, velocity, density, specific energy, h,
/// the deviatoric stress and the damage.
pub fn gap_of<D: Dimension>(
    a: &Simulation<D, KernelChoice>,
    b: &Simulation<D, KernelChoice>,
) -> Gap {
    let (pa, pb) = (&a.state.particles, &b.state.particles);
    let mut gap = Gap::default();
    gap.add(
        "position",
        &flat::<D>(&pa.position),
        &flat::<D>(&pb.position),
    );
    gap.add(
        "velocity",
        &flat::<D>(&pa.velocity),
        &flat::<D>(&pb.velocity),
    );
    gap.add("density", &pa.density, &pb.density);
    gap.add("specific energy", &pa.specific_energy, &pb.specific_energy);
    gap.add("h", &pa.smoothing_length, &pb.smoothing_length);
    let stress = |s: &Simulation<D, KernelChoice>| -> Vec<f64> {
        s.state
            .stress
            .iter()
            .flat_map(|m| m.to_cols_array())
            .collect()
    };
    gap.add("stress", &stress(a), &stress(b));
    gap.add("damage", &a.state.damage_state, &b.state.damage_state);
    gap
}

/// Calls the generic `$compare(&mut a, &mut b, args…)` on two `SceneSimulation`s of one
/// geometry (a scene builds one).
#[macro_export]
macro_rules! on_both {
    ($a:expr, $b:expr, $compare:ident $(, $arg:expr)*) => {
        match ($a, $b) {
            (SceneSimulation::ThreeD(mut a), SceneSimulation::ThreeD(mut b)) => {
                $compare(&mut a, &mut b $(, $arg)*)
            }
            (SceneSimulation::Rz(mut a), SceneSimulation::Rz(mut b))
            | (SceneSimulation::Plane(mut a), SceneSimulation::Plane(mut b)) => {
                $compare(&mut a, &mut b $(, $arg)*)
            }
            (SceneSimulation::Line(mut a), SceneSimulation::Line(mut b)) => {
                $compare(&mut a, &mut b $(, $arg)*)
            }
            _ => unreachable!("one scene builds one geometry"),
        }
    };
}

/// A 24 × 24 lattice of gas particles in the unit square with scattered pressures and
/// velocities, x-major (so that ranks' rows are slabs across x), and, when `walls`, a
/// reflecting wall at y = 0 and a periodic pair of faces in x.
pub fn gas_blob(
    walls: bool,
) -> (
    sph_core::Particles<sph_core::Dim2>,
    Vec<sph_impact::Boundary<sph_core::Dim2>>,
) {
    use sph_core::glam::DVec2;
    use sph_core::{ParticleInit, Particles};
    use sph_impact::Boundary;
    let mut p = Particles::new();
    let n = 24;
    let dx = 1.0 / n as f64;
    for a in 0..n {
        for b in 0..n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            let s = ((a * 7 + b * 13) % 11) as f64 / 11.0;
            p.push(ParticleInit {
                position: x,
                velocity: DVec2::new(0.3 * (s - 0.5), 0.2 * ((a + b) % 3) as f64 - 0.2),
                mass: dx * dx * (1.0 + 0.5 * s),
                density: 1.0 + 0.5 * s,
                specific_energy: 1.0 + s,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let boundaries = if walls {
        vec![
            Boundary::Wall {
                point: DVec2::ZERO,
                normal: DVec2::Y,
            },
            Boundary::Periodic {
                axis: 0,
                lo: 0.0,
                hi: 1.0,
            },
        ]
    } else {
        Vec::new()
    };
    (p, boundaries)
}

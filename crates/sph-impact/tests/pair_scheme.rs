//! The pair passes run loops compiled with the paper's choices of the scheme as
//! constants where the scheme makes them (solver/derivatives/pair_scheme.rs for pass 2,
//! `GradientOptions::STUDY` for pass 1), and the loops that read them otherwise. Both do
//! the same arithmetic in the same order: the same smoke scene stepped with either gives
//! the same time steps and the same state, to the bit, in every geometry.

mod common;

use common::{gap_of, scene_text};
use sph_core::Dimension;
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::Simulation;
use sph_kernel::KernelChoice;

/// Steps `a` (the loops that read the scheme) and `b` (the default) `steps` times, each
/// with its own time-step vote, and returns the largest relative difference of their
/// fields (`common::Gap`) after checking that every step's dt was the same.
fn compare<D: Dimension>(
    a: &mut Simulation<D, KernelChoice>,
    b: &mut Simulation<D, KernelChoice>,
    steps: usize,
) -> f64 {
    // A solid, so that pass 1 takes its study loop too (the strain rate corrected).
    assert!(!b.state.stress.is_empty());
    a.set_generic_pair_loop(true);
    for step in 0..steps {
        let (sa, sb) = (
            a.step(f64::INFINITY).unwrap(),
            b.step(f64::INFINITY).unwrap(),
        );
        assert_eq!(sa.dt.to_bits(), sb.dt.to_bits(), "step {step}");
    }
    gap_of(a, b).worst
}

#[test]
fn the_study_loop_and_the_generic_loop_agree_to_the_bit() {
    for file in [
        "smoke.toml",
        "smoke_rz.toml",
        "smoke_plane.toml",
        "flyer_plate_1d.toml",
    ] {
        let scene = Scene::from_toml_str(&scene_text(file), file).unwrap();
        assert!(scene.scheme().takes_study_pair_loop(), "{file}");
        let (a, b) = (scene.build().unwrap(), scene.build().unwrap());
        let worst = match (a.simulation, b.simulation) {
            (SceneSimulation::ThreeD(mut a), SceneSimulation::ThreeD(mut b)) => {
                compare(&mut a, &mut b, 20)
            }
            (SceneSimulation::Rz(mut a), SceneSimulation::Rz(mut b))
            | (SceneSimulation::Plane(mut a), SceneSimulation::Plane(mut b)) => {
                compare(&mut a, &mut b, 20)
            }
            (SceneSimulation::Line(mut a), SceneSimulation::Line(mut b)) => {
                compare(&mut a, &mut b, 20)
            }
            _ => unreachable!("one scene, one geometry"),
        };
        assert_eq!(worst, 0.0, "{file}");
    }
}

#[test]
fn the_bundled_impact_scenes_take_the_study_loop() {
    for file in ["basalt_3.9kms.toml", "basalt_3.9kms_rz.toml"] {
        let path = format!(
            "{}/../../examples/scenes/{file}",
            env!("CARGO_MANIFEST_DIR")
        );
        let scene = Scene::from_toml_file(&path).unwrap();
        assert!(scene.scheme().takes_study_pair_loop(), "{file}");
    }
}

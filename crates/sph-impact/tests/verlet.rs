//! A Verlet list (`[solver] neighbour_search = "verlet"`, `neighbour_skin`): one search
//! with the supports enlarged by the skin, kept over stages and steps while it holds every
//! pair (solver/simulation/verlet.rs). The pair passes skip the listed pairs and ghosts a
//! search of the stage's own state would not make, so the results must be those of a
//! search at each stage to the bit, in every geometry and with every kind of ghost, at
//! fewer searches.
//!
//! `cargo test -p sph-impact --release --test verlet -- --nocapture` prints the searches.

mod common;

use common::{gas_blob, smoke_cases, with_solver_keys};
use sph_core::Dimension;
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::{NeighbourSearch, Simulation};
use sph_impact::{Material, SchemeConfig};
use sph_kernel::{Kernel, KernelChoice};

/// The state's every field, to the bit (serde_json writes each f64 so that it reads back
/// the same).
fn bits<D: Dimension, K: Kernel>(sim: &Simulation<D, K>) -> String {
    serde_json::to_string(&sim.state).unwrap()
}

/// Steps `a` (a search at each stage) and `b` (a Verlet list) `steps` times, each
/// choosing its own time step, and checks that they take the same steps and end in the
/// same state; returns the searches each made.
fn compare<D: Dimension, K: Kernel>(
    a: &mut Simulation<D, K>,
    b: &mut Simulation<D, K>,
    steps: usize,
) -> (u64, u64) {
    assert_eq!(a.scheme.neighbour_search, NeighbourSearch::EachStage);
    assert_eq!(b.scheme.neighbour_search, NeighbourSearch::Verlet);
    for step in 0..steps {
        let (sa, sb) = (
            a.step(f64::INFINITY).unwrap(),
            b.step(f64::INFINITY).unwrap(),
        );
        assert_eq!(
            sa.dt.to_bits(),
            sb.dt.to_bits(),
            "step {step}: another time step"
        );
    }
    assert!(bits(a) == bits(b), "another state after {steps} steps");
    (a.timings.searches, b.timings.searches)
}

/// Twenty steps of each smoke scene, with the study's scheme and the FSISPH preset, at
/// the default skin and a thin one: the same bits as a search at each stage, with fewer
/// searches, and the list searched again as the particles move (the impacts run at km/s).
#[test]
fn a_verlet_list_gives_the_bits_of_a_search_at_each_stage_in_every_geometry() {
    let steps = 20;
    let mut rebuilt = 0;
    for (geometry, text) in smoke_cases() {
        for (scheme, text) in [
            ("scene", text.clone()),
            ("fsisph", with_solver_keys(&text, "preset = \"fsisph\"\n")),
        ] {
            for skin in ["", "neighbour_skin = 0.05\n"] {
                let a = Scene::from_toml_str(&text, "scene.toml").unwrap();
                let keys = format!("neighbour_search = \"verlet\"\n{skin}");
                let b =
                    Scene::from_toml_str(&with_solver_keys(&text, &keys), "scene.toml").unwrap();
                let (each_stage, verlet) = on_both!(
                    a.build().unwrap().simulation,
                    b.build().unwrap().simulation,
                    compare,
                    steps
                );
                println!(
                    "{geometry}, {scheme}, skin {}: {verlet} searches against {each_stage}",
                    b.scheme().skin().unwrap()
                );
                assert_eq!(each_stage, 2 * steps as u64);
                assert!(
                    verlet < each_stage,
                    "{geometry}, {scheme}: {verlet} searches"
                );
                if verlet > 1 {
                    rebuilt += 1;
                }
            }
        }
    }
    // The holding test must have sent most runs back to the search at least once.
    assert!(rebuilt >= 10, "only {rebuilt} runs searched again");
}

/// A gas blob with a reflecting wall and a periodic pair of faces (ghosts of ghosts in
/// the corners, ghosts that change sides), with the mass-and-energy density and with
/// summation density: the same bits as a search at each stage.
#[test]
fn a_verlet_list_gives_the_bits_of_a_search_at_each_stage_by_walls_and_periodic_faces() {
    use sph_core::Dim2;
    use sph_impact::solver::DensityForm;
    let build = |density: DensityForm, search: NeighbourSearch, skin: Option<f64>| {
        let (p, boundaries) = gas_blob(true);
        let scheme = SchemeConfig {
            density,
            neighbour_search: search,
            neighbour_skin: skin,
            ..SchemeConfig::default()
        };
        Simulation::<Dim2, _>::new(
            p,
            vec![Material::fluid(
                "gas",
                sph_eos::IdealGas::with_gamma(1.4).unwrap(),
            )],
            scheme,
            KernelChoice::WendlandC2,
            boundaries,
            None,
        )
        .unwrap()
    };
    for density in [DensityForm::Mass, DensityForm::Summation] {
        for skin in [None, Some(0.05), Some(1.0)] {
            let mut a = build(density, NeighbourSearch::EachStage, None);
            let mut b = build(density, NeighbourSearch::Verlet, skin);
            let (each_stage, verlet) = compare(&mut a, &mut b, 40);
            println!("{density:?}, skin {skin:?}: {verlet} searches against {each_stage}");
            assert!(verlet > 1 && verlet < each_stage, "{verlet} searches");
        }
    }
}

//! One neighbour search per RK2 step (`[solver] neighbour_search = "each-step"`,
//! `SchemeConfig::neighbour_search`): the midpoint stage reuses the first stage's list and
//! boundary ghosts, as LLNL Spheral's integrators do. This is a change of numerics, not of
//! the physics: against a search at each stage it must stay close (the pairs it misses
//! enter at the support's edge, where ∇W vanishes), and it must keep what the pair terms
//! guarantee: momentum exact, energy to round-off, the same result on any thread count
//! and across a checkpoint.
//!
//! `cargo test -p sph-impact --release --test neighbour_search -- --nocapture` prints the
//! differences.

mod common;

use common::{gap_of, smoke_cases, with_solver_keys};
use sph_core::Dimension;
use sph_impact::run::{RunOptions, run};
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::{NeighbourSearch, Simulation};
use sph_kernel::KernelChoice;
use std::path::Path;

/// Steps `a` (a search at each stage) and `b` (one per step) `steps` times with the same
/// time steps and returns their gap.
fn compare<D: Dimension>(
    a: &mut Simulation<D, KernelChoice>,
    b: &mut Simulation<D, KernelChoice>,
    steps: usize,
) -> (f64, &'static str) {
    assert_eq!(a.scheme.neighbour_search, NeighbourSearch::EachStage);
    assert_eq!(b.scheme.neighbour_search, NeighbourSearch::EachStep);
    for _ in 0..steps {
        let s = a.step(f64::INFINITY).unwrap();
        b.step(s.dt).unwrap();
    }
    let gap = gap_of(a, b);
    (gap.worst, gap.field)
}

#[test]
fn one_search_per_step_stays_close_to_one_per_stage_in_every_geometry() {
    for (geometry, text) in smoke_cases() {
        for (scheme, text) in [
            ("scene", text.clone()),
            ("fsisph", with_solver_keys(&text, "preset = \"fsisph\"\n")),
        ] {
            let a = Scene::from_toml_str(&text, "scene.toml").unwrap();
            let b = Scene::from_toml_str(
                &with_solver_keys(&text, "neighbour_search = \"each-step\"\n"),
                "scene.toml",
            )
            .unwrap();
            let (worst, field) = on_both!(
                a.build().unwrap().simulation,
                b.build().unwrap().simulation,
                compare,
                20
            );
            println!("{geometry}, {scheme}: largest relative difference {worst:.2e} ({field})");
            // It is another scheme: the midpoint stage saw other pairs and ghosts. The
            // 1-D flyer plate's pairs do not change in its first 20 steps, so there the
            // kept list and the ghosts placed again must give the same result to the bit.
            if geometry == "1d" {
                assert_eq!(worst, 0.0, "{scheme}: the same pairs gave another result");
            } else {
                assert!(worst > 0.0, "{geometry}, {scheme}: nothing changed");
            }
            assert!(
                worst < TOLERANCE,
                "{geometry}, {scheme}: {worst:e} in {field}"
            );
        }
    }
}

/// The largest relative difference allowed after 20 steps of a smoke scene: the
/// deviatoric stress moves most, 1.3e-5 (3-D) to 7.9e-5 (plane strain with the FSISPH
/// preset) of its largest value (`-- --nocapture` prints each).
const TOLERANCE: f64 = 1e-4;

/// Momentum exact and energy to round-off with one search per step, in every geometry,
/// and the same outputs on one thread as on two.
#[test]
fn one_search_per_step_conserves_and_repeats_on_any_thread_count() {
    for (geometry, text) in smoke_cases() {
        let text = with_solver_keys(&text, "neighbour_search = \"each-step\"\n");
        let scene = Scene::from_toml_str(&text, "scene.toml").unwrap();
        let mut summaries = Vec::new();
        for threads in [1, 2] {
            let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
                .join(format!("each-step-{geometry}-{threads}"));
            let _ = std::fs::remove_dir_all(&dir);
            let options = RunOptions {
                quiet: true,
                threads: Some(threads),
                end_time: Some(0.5e-6),
                ..RunOptions::default()
            };
            let s = run(&scene, &dir, &options).unwrap();
            let history = std::fs::read(dir.join("history.csv")).unwrap();
            summaries.push((s, history));
        }
        let (s, history) = &summaries[0];
        println!(
            "{geometry}: beta {:.6} (target {:.6}), energy error {:.2e}, {} steps",
            s.beta, s.beta_target, s.energy_error, s.steps
        );
        assert!(*history == summaries[1].1, "{geometry}: threads differ");
        assert!((s.beta - s.beta_target).abs() < 1e-9, "{geometry}: {s:?}");
        // The impact's axis: the largest component of the initial momentum.
        let m0 = s.initial.momentum.map(f64::abs);
        let axis = (0..3).fold(0, |k, c| if m0[c] > m0[k] { c } else { k });
        let p0 = s.initial.momentum[axis];
        assert!(
            (s.last.momentum[axis] / p0 - 1.0).abs() < 1e-9,
            "{geometry}: momentum {} against {p0}",
            s.last.momentum[axis]
        );
        let tolerance = if geometry == "rz" { 1e-6 } else { 1e-9 };
        assert!(
            s.energy_error.abs() < tolerance,
            "{geometry}: {}",
            s.energy_error
        );
    }
}

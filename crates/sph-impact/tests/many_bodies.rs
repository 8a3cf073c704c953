//! Scenes of many bodies — a rubble pile of 10 000 boulders — are checked, placed and
//! built in time about linear in the number of bodies (the overlap check used to test
//! every pair of bodies: 18 s for 1 000 boulders, 98 s for 2 000), and an overlap among
//! them is still reported as the first overlapping body and the body it overlaps.
//!
//! `cargo test -p sph-impact --release --test many_bodies -- --nocapture` prints the
//! times.

use sph_impact::scene::{Scene, SceneErrorKind};
use std::fmt::Write;
use std::time::Instant;

/// Boulders in the pile.
const BOULDERS: usize = 10_000;
/// Boulders along each side of the square grid.
const SIDE: usize = 100;
/// Distance between boulder centres (m); each boulder is a cube of side 3 mm.
const PITCH: f64 = 4.0e-3;

/// The centre of boulder `k` on the grid, 2 mm above the target.
fn grid_centre(k: usize) -> [f64; 3] {
    let half = 0.5 * SIDE as f64 * PITCH;
    [
        -half + ((k / SIDE) as f64 + 0.5) * PITCH,
        -half + ((k % SIDE) as f64 + 0.5) * PITCH,
        2.0e-3,
    ]
}

/// A scene of a projectile, a target slab and `BOULDERS` small basalt cubes on a square
/// grid above it, each filled by 27 particles of a 1 mm lattice (few, so that the scene
/// stays cheap; cubes, so that so few particles still have the body's exact mass);
/// `moved` puts boulder `k`'s centre at the given point instead.
fn rubble_pile(moved: Option<(usize, [f64; 3])>) -> String {
    let edge = 0.5 * SIDE as f64 * PITCH + 5.0e-3;
    let mut text = String::from(
        r#"end_time = 1.0e-6

[[body]]
name = "projectile"
material = "aluminium-2024-jc"
shape = { kind = "cuboid", min = [-3.0e-3, -3.0e-3, 0.017], max = [3.0e-3, 3.0e-3, 0.023] }
placement = { kind = "lattice", spacing = 1.0e-3 }
velocity = [0.0, 0.0, -3900.0]

[[body]]
name = "target"
material = "basalt-study"
"#,
    );
    writeln!(
        text,
        "shape = {{ kind = \"cuboid\", min = [{}, {}, -0.01], max = [{edge}, {edge}, 0.0] }}\n\
         placement = {{ kind = \"lattice\", spacing = 5.0e-3 }}",
        -edge, -edge
    )
    .unwrap();
    for k in 0..BOULDERS {
        let centre = match moved {
            Some((m, at)) if m == k => at,
            _ => grid_centre(k),
        };
        let [min, max] = [-1.5e-3, 1.5e-3].map(|d| centre.map(|x| x + d));
        writeln!(
            text,
            "\n[[body]]\nname = \"boulder-{k}\"\nmaterial = \"basalt-study\"\n\
             shape = {{ kind = \"cuboid\", min = {min:?}, max = {max:?} }}\n\
             placement = {{ kind = \"lattice\", spacing = 1.0e-3 }}"
        )
        .unwrap();
    }
    text.push_str("\n[diagnostics]\nprojectile = \"projectile\"\ntarget = \"target\"\n");
    text
}

#[test]
fn ten_thousand_boulders_are_checked_placed_and_built_quickly() {
    let text = rubble_pile(None);
    let t0 = Instant::now();
    let scene = Scene::from_toml_str(&text, "rubble.toml").unwrap();
    let read = t0.elapsed().as_secs_f64();
    let t1 = Instant::now();
    let report = scene.check_report(1.0, 1, None).unwrap();
    let check = t1.elapsed().as_secs_f64();
    println!(
        "{} bodies, {} particles: read in {read:.2} s, checked (placement {:.2} s) in \
         {check:.2} s",
        report.bodies.len(),
        report.particles,
        report.placement_s
    );
    assert_eq!(report.bodies.len(), BOULDERS + 2);
    assert_eq!(report.bodies[2].name, "boulder-0");
    // 27 sites of a 1 mm lattice in each 3 mm cube.
    assert!(report.bodies[2..].iter().all(|b| b.particles == 27));
    // The simulation too: one material per body, each with its own flaws.
    let t2 = Instant::now();
    let built = scene.build().unwrap();
    let build = t2.elapsed().as_secs_f64();
    println!("built in {build:.2} s");
    assert_eq!(built.bodies.len(), BOULDERS + 2);
    assert_eq!(built.bodies[BOULDERS + 1].range.end, report.particles);
    // With every pair tested the check took about half an hour; the bound only catches
    // a return to that.
    assert!(read + check + build < 120.0, "{read} + {check} + {build} s");
}

#[test]
fn an_overlap_among_ten_thousand_boulders_names_both() {
    // Boulder 9 000 moved onto boulder 9 001: all its particles lie in the other cube.
    let text = rubble_pile(Some((9_000, grid_centre(9_001))));
    let scene = Scene::from_toml_str(&text, "rubble.toml").unwrap();
    let e = scene.check_report(1.0, 1, None).unwrap_err();
    let m = e.to_string();
    println!("{m}");
    match &e.kind {
        SceneErrorKind::Overlap { other, count, .. } => {
            assert_eq!((other.as_str(), *count), ("boulder-9001", 27), "{m}");
        }
        other => panic!("not an overlap: {other:?}"),
    }
    assert_eq!(e.body.as_deref(), Some("boulder-9000"), "{m}");
    assert!(
        m.contains("body \"boulder-9000\": `shape`: overlaps body \"boulder-9001\": 27 of"),
        "{m}"
    );
    // Moved into the target instead, it is reported against the target, the first body
    // it overlaps.
    let text = rubble_pile(Some((9_000, [0.0, 0.0, -5.0e-3])));
    let e = Scene::from_toml_str(&text, "rubble.toml")
        .unwrap()
        .place(1.0)
        .unwrap_err();
    assert!(
        e.to_string()
            .contains("body \"boulder-9000\": `shape`: overlaps body \"target\": 27 of"),
        "{e}"
    );
}

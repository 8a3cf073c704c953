//! Scenes: every bad-scene case gives a one-line error naming the problem, the key and
//! the line; the bundled scenes round-trip through the parser; `check` on the study's
//! 3.9 km/s scene (3-D and RZ); the smoke scenes (3-D and RZ) run end to end.
//!
//! `cargo test -p sph-impact --test scene -- --nocapture` prints the messages and the
//! check report.

use sph_impact::run::{RunOptions, run};
use sph_impact::scene::{GeometryKind, Scene, SceneErrorKind};
use std::path::{Path, PathBuf};

/// A valid two-body scene; tests replace one line of it.
const BASE: &str = r#"end_time = 1.0e-6
seed = 3

[[body]]
name = "projectile"
material = "aluminium-2024-jc"
shape = { kind = "sphere", centre = [0.0, 0.0, 2.0e-3], radius = 1.5e-3 }
placement = { kind = "lattice", spacing = 0.5e-3 }
velocity = [0.0, 0.0, -3900.0]

[[body]]
name = "target"
material = "basalt-study"
shape = { kind = "cuboid", min = [-4.0e-3, -4.0e-3, -4.0e-3], max = [4.0e-3, 4.0e-3, 0.0] }
placement = { kind = "lattice", spacing = 0.5e-3 }

[diagnostics]
projectile = "projectile"
target = "target"
"#;

/// `BASE` with `from` replaced by `to` (which must occur).
fn edit(from: &str, to: &str) -> String {
    assert!(BASE.contains(from), "{from}");
    BASE.replacen(from, to, 1)
}

/// The one-line message of reading `text`, printed.
fn message(text: &str) -> String {
    let e = Scene::from_toml_str(text, "scene.toml").expect_err("the scene must be rejected");
    let m = e.to_string();
    println!("{m}");
    assert_eq!(m.lines().count(), 1, "one line: {m}");
    m
}

/// One line with what a smoke run produced (particles are rings in RZ).
fn print_result(label: &str, s: &sph_impact::run::RunSummary) {
    println!(
        "{label}: {} particles, {} steps, β {:.4}, crater Ø {:.2} mm, depth {:.2} mm \
         (axis {:.2} mm), {:.2} s",
        s.particles,
        s.steps,
        s.beta,
        s.crater_diameter_m * 1e3,
        s.crater_depth_m * 1e3,
        s.crater_axis_depth_m * 1e3,
        s.wall_time_s
    );
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn scene_file(name: &str) -> PathBuf {
    workspace().join("examples/scenes").join(name)
}

#[test]
fn base_scene_is_valid() {
    let s = Scene::from_toml_str(BASE, "scene.toml").unwrap();
    assert_eq!(s.bodies.len(), 2);
    // [solver] absent: the study's artificial stress.
    assert_eq!(s.scheme().artificial_stress.epsilon, 0.2);
    assert_eq!(s.scheme().artificial_stress.exponent, 4);
}

#[test]
fn no_bodies() {
    let text = "end_time = 1.0e-6\n";
    let m = message(text);
    assert!(m.contains("no bodies"), "{m}");
    assert!(m.starts_with("scene.toml: `body`:"), "{m}");
}

#[test]
fn missing_body() {
    let m = message(&edit("target = \"target\"", "target = \"targt\""));
    assert!(m.contains("no body named \"targt\""), "{m}");
    assert!(m.contains("projectile, target"), "{m}");
    assert!(
        m.starts_with("scene.toml:19:10: `diagnostics.target`:"),
        "{m}"
    );
}

#[test]
fn unknown_material() {
    let m = message(&edit(
        "material = \"basalt-study\"",
        "material = \"basalt-x\"",
    ));
    assert!(
        m.starts_with("scene.toml:13:12: body \"target\": `material`: unknown material \"basalt-x\" (known: basalt-study,"),
        "{m}"
    );
}

#[test]
fn negative_density_in_inline_material() {
    let text = edit(
        "material = \"basalt-study\"",
        "material = { base = \"basalt-study\", density = -2876.0 }",
    );
    let m = message(&text);
    assert!(m.contains("`density` = -2876 is invalid"), "{m}");
    assert!(m.contains("body \"target\": `material.density`"), "{m}");
    assert!(m.starts_with("scene.toml:13:"), "{m}");
    // Zero too, and in a material table of its own.
    let text = edit(
        "material = \"basalt-study\"\n",
        "[body.material]\nbase = \"basalt-study\"\ndensity = 0.0\n",
    );
    // The table must come after the body's plain keys.
    let text = text.replace(
        "[body.material]\nbase = \"basalt-study\"\ndensity = 0.0\nshape",
        "shape",
    );
    let text = text.replace(
        "placement = { kind = \"lattice\", spacing = 0.5e-3 }\n\n[diagnostics]",
        "placement = { kind = \"lattice\", spacing = 0.5e-3 }\n[body.material]\nbase = \"basalt-study\"\ndensity = 0.0\n\n[diagnostics]",
    );
    let m = message(&text);
    assert!(m.contains("`density` = 0 is invalid"), "{m}");
    assert!(
        m.starts_with("scene.toml:17:11: body \"target\": `material.density`"),
        "{m}"
    );
}

#[test]
fn inline_material_is_read_like_a_material_file() {
    let text = edit(
        "material = \"basalt-study\"",
        "material = { base = \"basalt-study\", strength = { cohesion = 30e6 } }",
    );
    let s = Scene::from_toml_str(&text, "scene.toml").unwrap();
    let m = s.materials().unwrap();
    assert_eq!(m[1].name, "target"); // the body's name when the table has none
    assert_eq!(m[1].density, 2876.0);
    // A misspelt key inside it is reported at its place in the scene.
    let text = edit(
        "material = \"basalt-study\"",
        "material = { base = \"basalt-study\", strength = { cohesoin = 30e6 } }",
    );
    let m = message(&text);
    assert!(m.contains("cohesoin"), "{m}");
    assert!(m.starts_with("scene.toml:13:"), "{m}");
}

#[test]
fn overlapping_bodies() {
    // The ball dips 1 mm into the block.
    let text = edit("centre = [0.0, 0.0, 2.0e-3]", "centre = [0.0, 0.0, 0.5e-3]");
    let scene = Scene::from_toml_str(&text, "scene.toml").unwrap();
    let e = scene.place(1.0).unwrap_err();
    let m = e.to_string();
    println!("{m}");
    assert_eq!(m.lines().count(), 1);
    assert!(matches!(e.kind, SceneErrorKind::Overlap { .. }));
    assert!(
        m.starts_with("scene.toml:7:9: body \"projectile\": `shape`: overlaps body \"target\":"),
        "{m}"
    );
    // `build` reports the same.
    assert_eq!(scene.build().err().unwrap().to_string(), m);
}

#[test]
fn unknown_keys() {
    let m = message(&edit("velocity =", "velocty ="));
    assert!(
        m.starts_with(
            "scene.toml:9:1: body \"projectile\": `velocty`: unknown key `velocty`, expected one of"
        ),
        "{m}"
    );
    let m = message(&edit("seed = 3", "sead = 3"));
    assert!(
        m.starts_with("scene.toml:2:1: `sead`: unknown key `sead`"),
        "{m}"
    );
    let m = message(&edit("radius = 1.5e-3", "radius = 1.5e-3, length = 2e-3"));
    assert!(
        m.contains("unknown key `length`, expected `centre` or `radius`"),
        "{m}"
    );
    assert!(m.starts_with("scene.toml:7:"), "{m}");
    let m = message(&format!(
        "{BASE}[solver]\ncfl = 0.2\nkernal = \"wendland-c2\"\n"
    ));
    assert!(
        m.starts_with("scene.toml:22:1: `solver.kernal`: unknown key `kernal`"),
        "{m}"
    );
    // A key beside the scalar smoothing's tag (it has none of its own) is rejected too.
    let m = message(&format!(
        "{BASE}[solver]\nsmoothing = {{ kind = \"scalar\", max_aspect = 4.0 }}\n"
    ));
    assert!(
        m.starts_with("scene.toml:21:32: `solver.smoothing.max_aspect`: unknown key `max_aspect`"),
        "{m}"
    );
}

#[test]
fn end_time_not_positive() {
    for bad in ["0.0", "-1.0e-6"] {
        let m = message(&edit("end_time = 1.0e-6", &format!("end_time = {bad}")));
        assert!(m.starts_with("scene.toml:1:12: `end_time`:"), "{m}");
        assert!(m.contains("the end time (s) must be positive"), "{m}");
    }
    let m = message(&edit("end_time = 1.0e-6\n", ""));
    assert_eq!(m, "scene.toml: `end_time`: missing field `end_time`");
    let m = message(&edit("radius = 1.5e-3 ", ""));
    assert!(
        m.starts_with(
            "scene.toml:7:9: body \"projectile\": `shape.radius`: missing field `radius`"
        ),
        "{m}"
    );
}

#[test]
fn other_bad_values() {
    let m = message(&edit(
        "spacing = 0.5e-3 }\nvelocity",
        "spacing = -0.5e-3 }\nvelocity",
    ));
    assert!(m.starts_with("scene.toml:8:"), "{m}");
    assert!(
        m.contains("body \"projectile\": `placement.spacing`"),
        "{m}"
    );
    // A cuboid target in an RZ scene.
    let m = message(&format!("geometry = \"rz\"\n{BASE}"));
    assert!(
        m.starts_with(
            "scene.toml:15:18: body \"target\": `shape.kind`: not axisymmetric about the z axis"
        ),
        "{m}"
    );
    let m = message(&format!("{BASE}[solver]\ncfl = 2.0\n"));
    assert!(m.starts_with("scene.toml:21:7: `solver.cfl`:"), "{m}");
    let m = message(&format!("{BASE}[solver]\nfragment_density_ratio = 1.0\n"));
    assert!(
        m.starts_with("scene.toml:21:26: `solver.fragment_density_ratio`:"),
        "{m}"
    );
    // The artificial stress' cap on ε fⁿ: positive and finite, or absent.
    let m = message(&format!(
        "{BASE}[solver]\nartificial_stress = {{ epsilon = 0.2, cap = 0.0 }}\n"
    ));
    assert!(m.contains("artificial_stress.cap"), "{m}");
    assert!(m.contains("must be finite and > 0"), "{m}");
    let m = message(&format!("{BASE}spall_damage = 0.0\n"));
    assert!(m.contains("`diagnostics.spall_damage`"), "{m}");
    assert!(m.contains("must be in (0, 1]"), "{m}");
    let m = message(&format!("{BASE}rubble_density = 1.0\n"));
    assert!(m.contains("`diagnostics.rubble_density`"), "{m}");
    assert!(m.contains("must be in [0, 1)"), "{m}");
    let m = message(&format!("{BASE}axis_kernel_width = -1.0e-3\n"));
    assert!(m.contains("`diagnostics.axis_kernel_width`"), "{m}");
    assert!(m.contains("must be positive (m)"), "{m}");
    let m = message(&format!("{BASE}axis_disc_radius = -1.0e-3\n"));
    assert!(m.contains("`diagnostics.axis_disc_radius`"), "{m}");
    assert!(m.contains("must be ≥ 0 (m"), "{m}");
    let m = message(&edit("name = \"target\"", "name = \"projectile\""));
    assert!(m.contains("used twice"), "{m}");
}

/// `[solver] viscosity = { switch = … }` sets the Balsara switch and keeps the study's α
/// and β; a misspelt switch is named with its key and line.
#[test]
fn viscosity_switch_is_read_and_a_bad_one_named() {
    let scene = Scene::from_toml_str(
        &format!("{BASE}[solver]\nviscosity = {{ switch = \"balsara\" }}\n"),
        "scene.toml",
    )
    .unwrap();
    let v = scene.scheme().viscosity;
    assert_eq!(v.switch, sph_riemann::ViscositySwitch::Balsara);
    assert_eq!((v.alpha, v.beta), (1.0, 1.0));
    let plain = Scene::from_toml_str(BASE, "scene.toml").unwrap();
    assert_eq!(
        plain.scheme().viscosity.switch,
        sph_riemann::ViscositySwitch::None
    );
    let m = message(&format!(
        "{BASE}[solver]\nviscosity = {{ switch = \"balsar\" }}\n"
    ));
    assert!(m.starts_with("scene.toml:21:"), "{m}");
    assert!(m.contains("`solver.viscosity.switch`"), "{m}");
}

#[test]
fn the_crater_depth_threshold_defaults_to_one_bin_and_is_checked() {
    // A bad value is refused when the scene is read, naming its line and key.
    let scene = |extra: &str| {
        Scene::from_toml_str(&format!("{BASE}{extra}"), "scene.toml")
            .and_then(|s| s.diagnostic_setup(2.0))
            .map_err(|e| e.to_string())
    };
    // Default: one crater bin, which follows the grid (0.5 mm / 2).
    let d = scene("").unwrap();
    assert_eq!(d.crater_bin, 0.25e-3);
    assert_eq!(d.crater_depth_threshold, d.crater_bin);
    // Given: a fixed length, whatever the resolution.
    let d = scene("crater_depth_threshold = 2e-3\n").unwrap();
    assert_eq!((d.crater_bin, d.crater_depth_threshold), (0.25e-3, 2e-3));
    for bad in ["0.0", "-1e-3"] {
        let m = scene(&format!("crater_depth_threshold = {bad}\n")).unwrap_err();
        assert!(m.starts_with("scene.toml:20:"), "{m}");
        assert!(m.contains("diagnostics.crater_depth_threshold"), "{m}");
        assert!(m.contains("must be positive"), "{m}");
    }
}

#[test]
fn bundled_scenes_round_trip() {
    for name in [
        "basalt_3.9kms.toml",
        "basalt_3.47kms.toml",
        "basalt_2.3kms.toml",
        "smoke.toml",
        "basalt_3.9kms_rz.toml",
        "basalt_3.47kms_rz.toml",
        "basalt_2.3kms_rz.toml",
        "basalt_3.9kms_quarter.toml",
        "smoke_rz.toml",
    ] {
        let path = scene_file(name);
        let scene = Scene::from_toml_file(&path).unwrap();
        let text = scene.to_toml().unwrap();
        let again = Scene::from_toml_str(&text, name).unwrap();
        assert_eq!(again, scene, "{name}:\n{text}");
        if name.starts_with("basalt") {
            // Table 1 of the study.
            let u: f64 = name[7..name.find("kms").unwrap()].parse().unwrap();
            assert_eq!(scene.end_time, 400e-6);
            assert_eq!(scene.bodies[0].velocity, [0.0, 0.0, -u * 1e3]);
            let setup = scene.diagnostic_setup(1.0).unwrap();
            assert!((setup.impact_speed - u * 1e3).abs() < 1e-9);
            // One bin, the default depth threshold of the crater.
            assert_eq!(setup.crater_depth_threshold, setup.crater_bin);
            let s = scene.scheme();
            assert_eq!((s.n_target, s.cfl), (2.5, 0.25));
            assert_eq!(s.artificial_stress.exponent, 4);
            // A Verlet list: a search at each stage's pairs and results, to the bit
            // (tests/verlet.rs), with fewer searches.
            assert_eq!(
                s.neighbour_search,
                sph_impact::solver::NeighbourSearch::Verlet,
                "{name}"
            );
            if let Some(three_d) = name.strip_suffix("_rz.toml") {
                // The same bodies and scheme as the 3-D scene (docs/scenes.md).
                let other = Scene::from_toml_file(scene_file(&format!("{three_d}.toml"))).unwrap();
                assert_eq!(scene.bodies, other.bodies, "{name}");
                assert_eq!(scene.geometry, GeometryKind::Rz);
                assert_eq!(s.geometry, sph_impact::Geometry::Axisymmetric);
                // Ejecta 20 mm up fly on (docs/validation.md, "Free flight").
                assert_eq!(s.free_flight_above, Some(0.02));
            }
            if let Some(three_d) = name.strip_suffix("_quarter.toml") {
                // The 3-D scene's bodies placed as revolved rings, in the quarter.
                let other = Scene::from_toml_file(scene_file(&format!("{three_d}.toml"))).unwrap();
                for (a, b) in scene.bodies.iter().zip(&other.bodies) {
                    assert_eq!(
                        (&a.name, &a.shape, &a.material, a.velocity),
                        (&b.name, &b.shape, &b.material, b.velocity)
                    );
                }
                assert_eq!(scene.geometry, GeometryKind::ThreeDQuarter);
                assert_eq!(s.free_flight_above, Some(0.02));
            }
            assert_eq!(s.artificial_stress.epsilon, 0.2);
            let m = scene.materials().unwrap();
            assert_eq!(
                (m[0].name.as_str(), m[1].name.as_str()),
                ("aluminium-2024-jc", "basalt-study")
            );
        }
    }
}

#[test]
fn check_the_study_scene() {
    let scene = Scene::from_toml_file(scene_file("basalt_3.9kms.toml")).unwrap();
    let t = std::time::Instant::now();
    let report = scene.check_report(1.0, 2, None).unwrap();
    println!("{}", report.to_text());
    println!("check took {:.2} s", t.elapsed().as_secs_f64());
    let p = &report.bodies[0];
    let tgt = &report.bodies[1];
    // docs/placement.md: 896 projectile and 1 004 456 target particles.
    assert_eq!(p.particles, 896);
    assert_eq!(tgt.particles, 1_004_456);
    for b in &report.bodies {
        assert!(
            b.mass_error.unwrap().abs() < 1e-9,
            "{}: {:?}",
            b.name,
            b.mass_error
        );
    }
    // λ Δx / (c_L,Al + U) = 0.25 · 0.5 mm / (6300 + 3900) m/s.
    assert!((report.first_dt_s / (0.25 * 0.5e-3 / (6300.0 + 3900.0)) - 1.0).abs() < 1e-3);
    assert!(report.runtime_s > 0.0);
    // The memory estimate is the bench's measured bytes per particle times the count.
    assert_eq!(
        report.memory_bytes,
        report.particles as f64 * sph_impact::scene::ASSUMED_BYTES_PER_PARTICLE
    );
    assert_eq!(report.particles, 896 + 1_004_456);
}

#[test]
fn smoke_scene_runs_end_to_end() {
    let scene = Scene::from_toml_file(scene_file("smoke.toml")).unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("scene-smoke");
    let _ = std::fs::remove_dir_all(&dir);
    let options = RunOptions {
        quiet: true,
        ..RunOptions::default()
    };
    let summary = run(&scene, &dir, &options).unwrap();
    for f in [
        "summary.json",
        "history.csv",
        "run.pvd",
        "snapshots/00000.vtu",
        "snapshots/00004.vtu",
        "crater_section.png",
        "history.png",
        "ejecta.png",
        "projectile_energy.png",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    for key in [
        "crater_diameter_m",
        "crater_diameter_removed_m",
        "bowl_diameter_m",
        "crater_depth_m",
        "beta",
        "beta_target",
        "beta_pendulum",
        "beta_change_last_half",
        "ejecta_mass_kg",
        "particles",
        "steps",
        "wall_time_s",
        "particle_steps_per_s",
        "neighbours_per_particle",
        "version",
        "scene",
    ] {
        assert!(json.get(key).is_some(), "summary.json lacks {key}");
    }
    assert_eq!(json["scene"]["body"][1]["name"], "target");
    // The mean row length: a 3-D support of n_target 2.5 holds about 65 neighbours in
    // the bulk (docs/performance.md), fewer at the bodies' surfaces.
    let npp = summary.neighbours_per_particle;
    let t = summary.timings;
    assert_eq!(
        npp,
        t.neighbour_entries as f64 / t.derivative_evaluations as f64
    );
    assert!((20.0..70.0).contains(&npp), "{npp} neighbours per particle");
    // β's change over the second half is read from the history as written: the row
    // nearest half the end time against the last row.
    let tb: Vec<(f64, f64)> = std::fs::read_to_string(dir.join("history.csv"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let f: Vec<f64> = l.split(',').take(4).map(|x| x.parse().unwrap()).collect();
            (f[0], f[3])
        })
        .collect();
    let (t_end, beta_end) = *tb.last().unwrap();
    let beta_half = tb
        .iter()
        .min_by(|a, b| {
            (a.0 - t_end / 2.0)
                .abs()
                .total_cmp(&(b.0 - t_end / 2.0).abs())
        })
        .unwrap()
        .1;
    assert!(summary.beta_change_last_half.is_finite(), "{summary:?}");
    assert!(
        (summary.beta_change_last_half - (beta_end - beta_half) / beta_end).abs() < 1e-12,
        "{summary:?}"
    );
    assert_eq!(json["particles"], summary.particles);
    // Momentum is conserved, so both βs agree; energy too (compatible form).
    assert!(
        (summary.beta - summary.beta_target).abs() < 1e-9,
        "{summary:?}"
    );
    assert!(summary.beta >= 1.0);
    // The pendulum leaves rising projectile debris out of the target, which can only
    // add to what the target received.
    assert!(
        summary.beta_pendulum >= summary.beta_target - 1e-12,
        "{summary:?}"
    );
    assert!(summary.energy_error.abs() < 1e-9);
    // Spall only widens: the diameter with fractured rock counted as removed is at least
    // that of the removed material alone.
    assert!(
        summary.crater_diameter_m >= summary.crater_diameter_removed_m,
        "{summary:?}"
    );
    let history = std::fs::read_to_string(dir.join("history.csv")).unwrap();
    assert!(history.starts_with("t_s,step,dt_s,beta,"));
    assert_eq!(history.lines().count() as u64, summary.steps + 2);
    // Every row names the limit that set its step and the particle that set it.
    let reasons = [
        "CFL: sound + approach speed",
        "density change",
        "acceleration",
    ];
    for (k, line) in history.lines().skip(1).enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(
            fields.len(),
            sph_impact::run::HISTORY_COLUMNS.len(),
            "{line}"
        );
        let (reason, id) = (fields[13], fields[14].parse::<u64>().unwrap());
        if k == 0 {
            assert_eq!((reason, id), ("none", 0));
        } else {
            assert!(reasons.contains(&reason), "{line}");
            assert!(id < summary.particles as u64, "{line}");
        }
    }
    // The last row is the final state the summary reports.
    let last: Vec<&str> = history.lines().last().unwrap().split(',').collect();
    assert_eq!(last[15].parse::<f64>().unwrap(), summary.beta_pendulum);
    // The axis depth of the last row is the summary's, measured on the same state.
    let axis_depth = last[16].parse::<f64>().unwrap();
    assert!(axis_depth.is_finite(), "{line:?}", line = last);
    assert_eq!(axis_depth, summary.crater_axis_depth_m);
    assert!(json["crater_axis_depth_m"].is_number(), "{json}");
    // So is β from the detached ejecta, which cannot exceed β from all of them (it is
    // the same sum over fewer particles, each with v_z > 0).
    let beta_detached = last[17].parse::<f64>().unwrap();
    assert_eq!(beta_detached, summary.beta_detached);
    assert!(
        (1.0..=summary.beta).contains(&beta_detached),
        "{beta_detached} {}",
        summary.beta
    );
    assert!(json["beta_detached"].is_number(), "{json}");
    let pvd = std::fs::read_to_string(dir.join("run.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 5);
    print_result("smoke", &summary);
}

#[test]
fn command_line_exit_codes() {
    let exe = env!("CARGO_BIN_EXE_sph-impact");
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("scene-cli");
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, edit("end_time = 1.0e-6", "end_time = -1.0")).unwrap();
    for cmd in ["run", "check"] {
        let out = std::process::Command::new(exe)
            .args([cmd, bad.to_str().unwrap()])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{cmd}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(
            err.starts_with("error: ") && err.contains("bad.toml:1:12: `end_time`"),
            "{err}"
        );
    }
    let out = std::process::Command::new(exe)
        .args(["check", "--json"])
        .arg(scene_file("smoke.toml"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let report: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(report["bodies"][1]["particles"], 2048);
    let out = std::process::Command::new(exe)
        .args(["materials", "--json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let list: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(list[0]["name"], "basalt-study");
    assert_eq!(list[0]["parameters"]["eos"]["model"], "tillotson");
}

/// A valid axisymmetric (RZ) two-body scene; tests replace one line of it.
const RZ_BASE: &str = r#"geometry = "rz"
end_time = 0.2e-6
seed = 3

[[body]]
name = "projectile"
material = "aluminium-2024-jc"
shape = { kind = "sphere", centre = [0.0, 0.0, 2.0e-3], radius = 1.5e-3 }
placement = { kind = "variable", origin = [0.0, 0.0, 2.0e-3], a_res = 0.25e-3, q = 1.0 }
velocity = [0.0, 0.0, -3900.0]

[[body]]
name = "target"
material = "basalt-study"
shape = { kind = "cylinder", base = [0.0, 0.0, -4.0e-3], axis = [0.0, 0.0, 1.0], radius = 4.0e-3, length = 4.0e-3 }
placement = { kind = "variable", origin = [0.0, 0.0, 0.0], a_res = 0.25e-3, q = 1.02 }
"#;

/// `RZ_BASE` with `from` replaced by `to` (which must occur), read: its one-line error.
fn rz_message(from: &str, to: &str) -> String {
    assert!(RZ_BASE.contains(from), "{from}");
    message(&RZ_BASE.replacen(from, to, 1))
}

#[test]
fn rz_scene_builds() {
    let scene = Scene::from_toml_str(RZ_BASE, "scene.toml").unwrap();
    assert_eq!(scene.geometry, GeometryKind::Rz);
    let built = scene.build().unwrap();
    assert_eq!(built.simulation.geometry(), GeometryKind::Rz);
    let sim = built.simulation.rz().expect("an RZ simulation");
    assert_eq!(sim.scheme.geometry, sph_impact::Geometry::Axisymmetric);
    let p = &sim.state.particles;
    assert!(p.position.iter().all(|x| x.x > 0.0));
    // Rings at rest but the projectile's, moving along the axis.
    let proj = &built.bodies[0];
    assert!(
        p.velocity[proj.range.clone()]
            .iter()
            .all(|v| v.x == 0.0 && v.y == -3900.0)
    );
    // Masses per radian: 2π Σ m is each body's mass, within the placement's error of ρV.
    for b in &built.bodies {
        let per_radian: f64 = p.mass[b.range.clone()].iter().sum();
        assert!((std::f64::consts::TAU * per_radian / b.mass - 1.0).abs() < 1e-12);
        assert!(
            b.mass_error().unwrap().abs() < 0.01,
            "{}: {:?}",
            b.name,
            b.mass_error()
        );
    }
    let report = scene.check_report(1.0, 2, None).unwrap();
    println!("{}", report.to_text());
    assert_eq!(report.geometry, GeometryKind::Rz);
    assert_eq!(report.particles, p.len());
}

#[test]
fn rz_shapes_must_be_axisymmetric() {
    let cases = [
        (
            "centre = [0.0, 0.0, 2.0e-3]",
            "centre = [0.5e-3, 0.0, 2.0e-3]",
            "scene.toml:8:37: body \"projectile\": `shape.centre`: not axisymmetric about the z axis",
        ),
        (
            "base = [0.0, 0.0, -4.0e-3]",
            "base = [0.0, 1.0e-3, -4.0e-3]",
            "scene.toml:15:37: body \"target\": `shape.base`:",
        ),
        (
            "axis = [0.0, 0.0, 1.0]",
            "axis = [1.0, 0.0, 0.0]",
            "scene.toml:15:65: body \"target\": `shape.axis`: not axisymmetric about the z axis (geometry = \"rz\" and placement kind \"rings\" need it): the cylinder's axis must be the z axis",
        ),
        (
            "velocity = [0.0, 0.0, -3900.0]",
            "velocity = [100.0, 0.0, -3900.0]",
            "scene.toml:10:12: body \"projectile\": `velocity`:",
        ),
        (
            "origin = [0.0, 0.0, 2.0e-3]",
            "origin = [1.0e-3, 0.0, 2.0e-3]",
            "scene.toml:9:43: body \"projectile\": `placement.origin`:",
        ),
    ];
    for (from, to, start) in cases {
        let m = rz_message(from, to);
        assert!(m.starts_with(start), "{m}");
    }
    // A cuboid has no axis of revolution.
    let m = rz_message(
        "shape = { kind = \"cylinder\", base = [0.0, 0.0, -4.0e-3], axis = [0.0, 0.0, 1.0], radius = 4.0e-3, length = 4.0e-3 }",
        "shape = { kind = \"cuboid\", min = [-4.0e-3, -4.0e-3, -4.0e-3], max = [4.0e-3, 4.0e-3, 0.0] }",
    );
    assert!(
        m.starts_with("scene.toml:15:18: body \"target\": `shape.kind`: not axisymmetric"),
        "{m}"
    );
    assert!(m.contains("spheres and cylinders"), "{m}");
}

/// `RZ_BASE` in 3-D (`geometry`) with both bodies placed as rings.
fn rings_scene(geometry: &str) -> Scene {
    let text = RZ_BASE
        .replacen(
            "geometry = \"rz\"",
            &format!("geometry = \"{geometry}\""),
            1,
        )
        .replace("kind = \"variable\"", "kind = \"rings\"");
    Scene::from_toml_str(&text, "scene.toml").unwrap()
}

#[test]
fn a_quarter_model_runs_as_the_whole_body() {
    // The same rings revolved: the full body holds four copies of the quarter, mirrored,
    // so the quarter between its two mirror planes must follow the full run.
    let options = RunOptions {
        quiet: true,
        end_time: Some(0.1e-6),
        ..RunOptions::default()
    };
    let mut out = Vec::new();
    for geometry in ["3d", "3d-quarter"] {
        let scene = rings_scene(geometry);
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("scene-rings-{geometry}"));
        let _ = std::fs::remove_dir_all(&dir);
        out.push((scene.build().unwrap(), run(&scene, &dir, &options).unwrap()));
    }
    let ((full_built, full), (quarter_built, quarter)) = (&out[0], &out[1]);
    assert_eq!(
        4 * quarter_built.simulation.particle_count(),
        full_built.simulation.particle_count()
    );
    assert_eq!(quarter.geometry, GeometryKind::ThreeDQuarter);
    assert_eq!(full.steps, quarter.steps);
    for (b, q) in full_built.bodies.iter().zip(&quarter_built.bodies) {
        assert!((q.mass / b.mass - 1.0).abs() < 1e-12, "{}", b.name);
        assert!(b.mass_error().unwrap().abs() < 1e-12, "{}", b.name);
    }
    let close = |a: f64, b: f64, what: &str| {
        assert!(
            (a / b - 1.0).abs() < 1e-9,
            "{what}: quarter {a} against full {b}"
        );
    };
    close(
        quarter.initial.momentum[2],
        full.initial.momentum[2],
        "p_z at t = 0",
    );
    close(quarter.last.momentum[2], full.last.momentum[2], "p_z");
    close(quarter.last.kinetic, full.last.kinetic, "kinetic energy");
    close(quarter.last.internal, full.last.internal, "internal energy");
    close(quarter.beta, full.beta, "beta");
    // The axis depth sums each quarter particle as its four copies, equidistant from
    // the axis: the full body's value to the bisection's tolerance.
    assert!(
        (quarter.crater_axis_depth_m - full.crater_axis_depth_m).abs() < 1e-9,
        "axis depth: quarter {} against full {}",
        quarter.crater_axis_depth_m,
        full.crater_axis_depth_m
    );
    println!(
        "full {} particles, quarter {}: KE {:.9e} against {:.9e}, beta {} against {}",
        full_built.simulation.particle_count(),
        quarter_built.simulation.particle_count(),
        full.last.kinetic,
        quarter.last.kinetic,
        full.beta,
        quarter.beta
    );
}

#[test]
fn a_quarter_model_needs_rings() {
    let text = RZ_BASE.replacen("geometry = \"rz\"", "geometry = \"3d-quarter\"", 1);
    let m = message(&text);
    assert!(
        m.starts_with("scene.toml:9:") && m.contains("`placement.kind`") && m.contains("\"rings\""),
        "{m}"
    );
}

#[test]
fn rz_smoke_scene_runs_end_to_end() {
    let scene = Scene::from_toml_file(scene_file("smoke_rz.toml")).unwrap();
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("scene-smoke-rz");
    let _ = std::fs::remove_dir_all(&dir);
    let options = RunOptions {
        quiet: true,
        end_time: Some(0.5e-6),
        ..RunOptions::default()
    };
    let summary = run(&scene, &dir, &options).unwrap();
    for f in [
        "summary.json",
        "history.csv",
        "run.pvd",
        "snapshots/00000.vtu",
        "snapshots/00002.vtu",
        "crater_section.png",
        "history.png",
        "ejecta.png",
        "projectile_energy.png",
    ] {
        assert!(dir.join(f).is_file(), "{f} missing");
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    assert_eq!(json["geometry"], "rz");
    assert_eq!(json["scheme"]["geometry"], "axisymmetric");
    // No ring crossed the axis (the mirror would have brought it back and counted it).
    assert_eq!(json["axis_crossings"], 0);
    assert_eq!(json["axis_crossings_midpoint"], 0);
    // Totals are the whole bodies': the projectile's mass and momentum, not per radian.
    let m_p = summary.projectile_mass_kg;
    assert!(
        (m_p / (2785.0 * 4.0 / 3.0 * std::f64::consts::PI * 1.5e-3f64.powi(3)) - 1.0).abs() < 0.03
    );
    assert!((summary.initial.momentum[2] / (-m_p * 3900.0) - 1.0).abs() < 1e-12);
    assert!((summary.last.momentum[2] / summary.initial.momentum[2] - 1.0).abs() < 1e-9);
    assert!(
        (summary.beta - summary.beta_target).abs() < 1e-9,
        "{summary:?}"
    );
    assert!(summary.beta >= 1.0);
    assert!(
        summary.energy_error.abs() < 1e-6,
        "{}",
        summary.energy_error
    );
    let vtu = std::fs::read_to_string(dir.join("snapshots/00002.vtu")).unwrap();
    assert!(vtu.contains("Name=\"deviatoric_stress\""));
    assert!(
        summary.crater_axis_depth_m.is_finite(),
        "{}",
        summary.crater_axis_depth_m
    );
    print_result("smoke (rz)", &summary);
}

/// Free flight (`[solver] free_flight_above`): the jet above the plane leaves the
/// hydrodynamics, and the run keeps every particle in its outputs and every total.
#[test]
fn rz_smoke_scene_with_free_flight() {
    let text = std::fs::read_to_string(scene_file("smoke_rz.toml")).unwrap();
    let text = text.replacen("[solver]\n", "[solver]\nfree_flight_above = 0.5e-3\n", 1);
    assert!(text.contains("free_flight_above"));
    let scene = Scene::from_toml_str(&text, "smoke_rz.toml").unwrap();
    assert_eq!(scene.scheme().free_flight_above, Some(0.5e-3));
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("scene-smoke-rz-flight");
    let _ = std::fs::remove_dir_all(&dir);
    let options = RunOptions {
        quiet: true,
        ..RunOptions::default()
    };
    let summary = run(&scene, &dir, &options).unwrap();
    println!(
        "in free flight at the end: {} of {} rings",
        summary.free_flight_particles, summary.particles
    );
    assert!(summary.free_flight_particles > 0);
    let plain = Scene::from_toml_file(scene_file("smoke_rz.toml")).unwrap();
    let n = plain.check_report(1.0, 1, None).unwrap().particles;
    assert_eq!(summary.particles, n);
    // Fewer particle-steps than particles × steps: the flying ones are not stepped.
    assert!(summary.particle_steps_per_s > 0.0);
    assert!((summary.last.momentum[2] / summary.initial.momentum[2] - 1.0).abs() < 1e-9);
    assert!(
        (summary.beta - summary.beta_target).abs() < 1e-9,
        "{summary:?}"
    );
    assert!(
        summary.energy_error.abs() < 1e-6,
        "{}",
        summary.energy_error
    );
    // The last snapshot holds every ring.
    let vtu = std::fs::read_to_string(dir.join("snapshots/00004.vtu")).unwrap();
    assert!(vtu.contains(&format!("NumberOfPoints=\"{n}\"")));
    print_result("smoke (rz, free flight)", &summary);
}

#[test]
fn check_the_study_scene_in_rz() {
    let scene = Scene::from_toml_file(scene_file("basalt_3.9kms_rz.toml")).unwrap();
    let report = scene.check_report(1.0, 2, None).unwrap();
    println!("{}", report.to_text());
    // docs/placement.md §6: 56 projectile and 6 362 target rings.
    assert_eq!(report.bodies[0].particles, 56);
    assert_eq!(report.bodies[1].particles, 6362);
    assert!(report.bodies[0].mass_error.unwrap().abs() < 1e-12);
    assert!(report.bodies[1].mass_error.unwrap().abs() < 1e-3);
    // The target's flaws are dealt over the 3-D particles its rings stand for (the
    // projectile's damage is the maximum tensile stress: no flaws).
    assert_eq!(report.bodies[0].flaws_dealt_over, None);
    assert_eq!(report.bodies[1].flaws_dealt_over, Some(1_003_164));
    assert!(
        report
            .to_text()
            .contains("dealt over 1003164 particles of the 3-D body")
    );
    assert!((report.first_dt_s / (0.25 * 0.5e-3 / (6300.0 + 3900.0)) - 1.0).abs() < 1e-3);
}

/// The FSISPH preset (`[solver] preset = "fsisph"`: damaged moduli, decoupling of
/// fractured material, FSISPH's stress and interface coupling, the limited viscosity,
/// corrected gradients) in every geometry: 3-D, the 3-D quarter, RZ with its hoop terms,
/// plane strain and 1-D. Momentum is exact (β from the ejecta equals β from the target,
/// and Σ m v keeps its start value), energy is conserved to round-off (RZ: to 1e-6, as
/// its other runs), and the target is damaged, so the damage rules act.
#[test]
fn the_fsisph_preset_conserves_momentum_and_energy_in_every_geometry() {
    let with_preset = |text: &str| {
        if text.contains("\n[solver]\n") {
            text.replacen("\n[solver]\n", "\n[solver]\npreset = \"fsisph\"\n", 1)
        } else {
            format!("{text}\n[solver]\npreset = \"fsisph\"\n")
        }
    };
    let file = |name: &str| std::fs::read_to_string(scene_file(name)).unwrap();
    let quarter = RZ_BASE
        .replacen("geometry = \"rz\"", "geometry = \"3d-quarter\"", 1)
        .replace("kind = \"variable\"", "kind = \"rings\"");
    let cases = [
        ("3d", file("smoke.toml")),
        ("3d-quarter", quarter),
        ("rz", file("smoke_rz.toml")),
        ("plane", file("smoke_plane.toml")),
        ("1d", file("flyer_plate_1d.toml")),
    ];
    for (geometry, text) in cases {
        let scene = Scene::from_toml_str(&with_preset(&text), "scene.toml").unwrap();
        let scheme = scene.scheme();
        assert!(scheme.damaged_moduli && scheme.decouple_damaged && scheme.momentum_correction);
        assert_eq!(scheme.stress_coupling, sph_damage::StressCoupling::Fsisph);
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("scene-fsisph-{geometry}"));
        let _ = std::fs::remove_dir_all(&dir);
        let options = RunOptions {
            quiet: true,
            end_time: Some(1.0e-6),
            ..RunOptions::default()
        };
        let s = run(&scene, &dir, &options).unwrap();
        let target = s.damage.iter().find(|d| d.body == "target").unwrap();
        println!(
            "{geometry}: beta {:.6} (target {:.6}), energy error {:.2e}, target mean D {:.3}, \
             fully damaged {:.3e} kg, {} steps",
            s.beta,
            s.beta_target,
            s.energy_error,
            target.mean_damage,
            target.fully_damaged_mass_kg,
            s.steps
        );
        assert!((s.beta - s.beta_target).abs() < 1e-9, "{geometry}: {s:?}");
        let p0 = s.initial.momentum[2];
        assert!(
            (s.last.momentum[2] / p0 - 1.0).abs() < 1e-9,
            "{geometry}: p_z {} against {p0}",
            s.last.momentum[2]
        );
        let tolerance = if geometry == "rz" { 1e-6 } else { 1e-9 };
        assert!(
            s.energy_error.abs() < tolerance,
            "{geometry}: {}",
            s.energy_error
        );
        assert!(target.mean_damage > 0.0, "{geometry}: no damage");
    }
}

/// A scene's bodies keep their ranges (each range holds its body's material only), each
/// sorted along a Morton curve (sorting it again changes nothing); and
/// `Simulation::reorder_particles` moves every per-particle field with its particle.
#[test]
fn bodies_are_sorted_along_a_morton_curve_and_reordering_moves_every_field() {
    let scene = Scene::from_toml_str(BASE, "scene.toml").unwrap();
    let built = scene.build().unwrap();
    let sph_impact::scene::SceneSimulation::ThreeD(mut sim) = built.simulation else {
        panic!("a 3-D scene");
    };
    let p = &sim.state.particles;
    for (k, b) in built.bodies.iter().enumerate() {
        assert!(p.material[b.range.clone()].iter().all(|&m| m as usize == k));
        let again = sph_core::morton_order(&p.position[b.range.clone()]).unwrap();
        assert_eq!(
            again,
            sph_core::Permutation::identity(b.range.len()),
            "{}",
            b.name
        );
    }
    assert!(!sim.state.damage_index.is_empty() && !sim.state.stress.is_empty());
    // Fields by particle id before a reversal, then after.
    let fields = |s: &sph_impact::solver::State<sph_core::Dim3>| {
        let mut v: Vec<_> = (0..s.particles.len())
            .map(|i| {
                (
                    s.particles.id[i],
                    s.particles.position[i].to_array(),
                    s.particles.mass[i],
                    s.particles.smoothing_length[i],
                    s.particles.material[i],
                    s.spacing0[i],
                    s.damage_index[i],
                    s.damage_state[i],
                )
            })
            .collect();
        v.sort_by_key(|f| f.0);
        v
    };
    let before = fields(&sim.state);
    let n = sim.state.particles.len();
    let last_id = sim.state.particles.id[n - 1];
    let reversal = sph_core::Permutation::new((0..n).rev().collect()).unwrap();
    sim.reorder_particles(&reversal).unwrap();
    assert_eq!(fields(&sim.state), before);
    assert_eq!(sim.state.particles.id[0], last_id);
    // A permutation of the wrong length is refused.
    assert!(
        sim.reorder_particles(&sph_core::Permutation::identity(n - 1))
            .is_err()
    );
    // The reordered simulation still steps.
    sim.step(f64::INFINITY).unwrap();
}

//! A pair rule of the user's own (`Simulation::with_pair_rule`, solver/pair_rules/user.rs):
//! a rule that adds nothing leaves the run bit for bit as it was, and an antisymmetric
//! force acts in the direction it points while momentum stays conserved, in 3-D and RZ.

use sph_core::{Dimension, Vector};
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::{PairRule, PairView, Simulation};
use sph_kernel::KernelChoice;
use std::path::PathBuf;

fn scene(name: &str) -> Scene {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes");
    let text = std::fs::read_to_string(root.join(name)).unwrap();
    Scene::from_toml_str(&text, name).unwrap()
}

/// A rule of the user's that never adds a force.
struct Nothing;

impl<D: Dimension> PairRule<D> for Nothing {
    fn force(&self, _pair: &PairView<D>) -> Option<D::Vector> {
        None
    }
}

/// Glue between the projectile (body 0) and the target (body 1): a constant attraction
/// `k` along the pair's axis within the larger support radius. F(j, i) = −F(i, j).
struct Glue {
    k: f64,
}

impl<D: Dimension> PairRule<D> for Glue {
    fn force(&self, pair: &PairView<D>) -> Option<D::Vector> {
        let (a, b) = pair.material;
        (a != b).then(|| pair.r_hat * -self.k)
    }
}

/// Σ m v_z of the projectile's particles and the whole momentum's z component.
fn momenta<D: Dimension, R: PairRule<D>>(sim: &Simulation<D, KernelChoice, R>) -> (f64, f64) {
    let p = &sim.state.particles;
    let projectile: f64 = (0..p.len())
        .filter(|&i| p.material[i] == 0)
        .map(|i| p.mass[i] * p.velocity[i].component(D::DIM - 1))
        .sum();
    (projectile, sim.conserved().momentum.component(D::DIM - 1))
}

/// Steps `sim` `n` times with the time steps `dts` (those of the run without a rule).
fn run<D: Dimension, R: PairRule<D>>(sim: &mut Simulation<D, KernelChoice, R>, dts: &[f64]) {
    for &dt in dts {
        sim.step(dt).unwrap();
    }
}

fn check<D: Dimension>(
    plain: Simulation<D, KernelChoice>,
    same: Simulation<D, KernelChoice>,
    glued: Simulation<D, KernelChoice>,
    k: f64,
) {
    let mut plain = plain;
    let dts: Vec<f64> = (0..8)
        .map(|_| plain.step(f64::INFINITY).unwrap().dt)
        .collect();
    let mut same = same.with_pair_rule(Nothing);
    run(&mut same, &dts);
    let bits = |s: &[D::Vector]| -> Vec<u64> {
        s.iter()
            .flat_map(|v| v.to_array3())
            .map(f64::to_bits)
            .collect()
    };
    assert_eq!(
        bits(&same.state.particles.velocity),
        bits(&plain.state.particles.velocity)
    );
    assert_eq!(
        bits(&same.state.particles.position),
        bits(&plain.state.particles.position)
    );
    let (p_plain, total_plain) = momenta(&plain);
    let mut glued = glued.with_pair_rule(Glue { k });
    let total_0 = momenta(&glued).1;
    run(&mut glued, &dts);
    let (p_glued, total_glued) = momenta(&glued);
    eprintln!(
        "p_z projectile: {p_plain:e} plain, {p_glued:e} glued; total {total_0:e} → {total_glued:e}"
    );
    // The target pulls the projectile (moving in −z into it) on: its momentum grows
    // more negative than without the glue.
    assert!(
        p_plain - p_glued > 1e-6 * p_plain.abs(),
        "projectile p_z {p_glued} with the glue, {p_plain} without"
    );
    // The glue is antisymmetric, so the total momentum does not change more than the
    // scheme's own round-off.
    let scale = p_plain.abs();
    assert!(
        (total_glued - total_0).abs() <= 1e-12 * scale,
        "total p_z {total_0} → {total_glued} (scale {scale})"
    );
    assert!((total_plain - total_0).abs() <= 1e-12 * scale);
}

#[test]
fn a_users_pair_rule_is_compiled_in_conserves_momentum_and_a_null_rule_changes_nothing() {
    // A force per unit partner mass large enough to move the projectile's momentum
    // within eight steps: by 1 % in 3-D, by 3e-5 in RZ, whose rings touch fewer
    // partners of the other body in those steps.
    for (name, k) in [("smoke.toml", 1.0e16), ("smoke_rz.toml", 1.0e16)] {
        let s = scene(name);
        let build = || s.build().unwrap().simulation;
        match (build(), build(), build()) {
            (
                SceneSimulation::ThreeD(a),
                SceneSimulation::ThreeD(b),
                SceneSimulation::ThreeD(c),
            ) => check(a, b, c, k),
            (SceneSimulation::Rz(a), SceneSimulation::Rz(b), SceneSimulation::Rz(c)) => {
                check(a, b, c, k)
            }
            _ => unreachable!("the smoke scenes are 3-D and RZ"),
        }
    }
}

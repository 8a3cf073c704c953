//! Solid dynamics in the solver: damage (P_D, (1 − D)S, the damage variable and its
//! bounds), held particles, thread independence with strength, damage and the tensor
//! artificial stress, and the errors of bad set-ups.

use sph_core::glam::DVec2;
use sph_core::{Dim1, Dim2, ParticleInit, Particles};
use sph_damage::{
    ActivationStrain, BenzAsphaug, BenzAsphaugParams, DamageModel, MaxTensileStress,
    PlasticFailure, WeibullParams,
};
use sph_eos::{LinearElastic, LinearElasticParams};
use sph_impact::{Material, SchemeConfig, Simulation};
use sph_kernel::WendlandC2;
use sph_riemann::{ArtificialStress, ArtificialStressForm};
use sph_strength::{VonMises, VonMisesParams};

const RHO: f64 = 2700.0;
const BULK: f64 = 26.7e9;
const SHEAR: f64 = 22.7e9;

fn elastic() -> (LinearElastic, VonMises) {
    (
        LinearElastic::new(LinearElasticParams {
            rho0: RHO,
            K0: BULK,
        })
        .unwrap(),
        VonMises::new(VonMisesParams {
            yield_strength: 1.0e12,
            shear_modulus: SHEAR,
            hardening: None,
        })
        .unwrap(),
    )
}

/// A 1-D bar of `n` particles in homogeneous stretching at `rate`, with 5 held particles
/// beyond each end (no damage there), the bar failing at σ_b.
fn pulled_bar(n: usize, rate: f64, sigma_b: f64) -> Simulation<Dim1, WendlandC2> {
    let (_, strength) = elastic();
    bar(n, rate, strength, MaxTensileStress::new(sigma_b).unwrap())
}

/// A 1-D bar of `n` particles of strength `strength` and damage `damage`, stretched
/// homogeneously at `rate` (compressed for rate < 0), with 5 held particles beyond
/// each end (no damage there).
fn bar(
    n: usize,
    rate: f64,
    strength: VonMises,
    damage: impl sph_damage::DamageModel + 'static,
) -> Simulation<Dim1, WendlandC2> {
    bar_with_shear_failure(n, rate, strength, damage, None)
}

/// [`bar`], with shear failure added to the bar's damage when `shear` is given.
fn bar_with_shear_failure(
    n: usize,
    rate: f64,
    strength: VonMises,
    damage: impl sph_damage::DamageModel + 'static,
    shear: Option<PlasticFailure>,
) -> Simulation<Dim1, WendlandC2> {
    let (eos, _) = elastic();
    let dx = 1.0e-3;
    let hold = 5;
    let mut p = Particles::<Dim1>::new();
    let mut held = Vec::new();
    for k in 0..n + 2 * hold {
        let x = (k as f64 + 0.5 - hold as f64 - 0.5 * n as f64) * dx;
        let inside = k >= hold && k < n + hold;
        if !inside {
            held.push(k);
        }
        p.push(ParticleInit {
            position: x,
            velocity: rate * x,
            mass: RHO * dx,
            density: RHO,
            specific_energy: 0.0,
            smoothing_length: 4.0 * dx,
            material: if inside { 0 } else { 1 },
        });
    }
    let scheme = SchemeConfig {
        n_target: 4.0,
        unbonded_interfaces: false,
        ..Default::default()
    };
    let mut bar = Material::solid("bar", eos, strength).with_damage(damage);
    if let Some(law) = shear {
        bar = bar.with_shear_failure(law);
    }
    let ends = Material::solid("held ends", eos, strength);
    let mut sim =
        Simulation::new(p, vec![bar, ends], scheme, WendlandC2, Vec::new(), None).unwrap();
    sim.hold_velocity(held).unwrap();
    sim
}

/// Mean total σ_xx = (1 − D) S_xx − P_D over the middle half of the bar.
fn mean_stress(sim: &Simulation<Dim1, WendlandC2>, half_length: f64) -> f64 {
    let (p, _) = sim.pressure_and_sound_speed();
    let d = sim.damage();
    let s = &sim.state;
    let (mut sum, mut n) = (0.0, 0);
    for i in 0..s.particles.len() {
        if s.particles.position[i].abs() < 0.5 * half_length {
            let pd = if p[i] < 0.0 {
                (1.0 - d[i]) * p[i]
            } else {
                p[i]
            };
            sum += (1.0 - d[i]) * s.stress[i].x_axis.x - pd;
            n += 1;
        }
    }
    sum / n as f64
}

#[test]
fn a_bar_fails_at_the_tensile_threshold_and_unloads() {
    let (n, rate, sigma_b) = (40, 20.0, 20.0e6);
    let mut sim = pulled_bar(n, rate, sigma_b);
    let p0 = sim.conserved().momentum;
    let scale: f64 = (0..sim.state.particles.len())
        .map(|i| sim.state.particles.mass[i] * sim.state.particles.velocity[i].abs())
        .sum();
    let half = 0.5 * n as f64 * 1.0e-3;
    let (mut peak, mut after_peak_min) = (0.0f64, f64::INFINITY);
    for _ in 0..3000 {
        sim.step(f64::INFINITY).unwrap();
        let s = mean_stress(&sim, half);
        if s > peak {
            peak = s;
            after_peak_min = s;
        } else {
            after_peak_min = after_peak_min.min(s);
        }
        let d = sim.damage();
        assert!(d.iter().all(|&x| (0.0..=1.0).contains(&x)), "{d:?}");
        if peak > 0.0 && s < 0.2 * peak {
            break;
        }
    }
    let d_max = sim.damage().into_iter().fold(0.0, f64::max);
    println!(
        "peak {:.3} MPa (σ_b {:.1} MPa), later minimum {:.3} MPa, max D {d_max}",
        peak / 1e6,
        sigma_b / 1e6,
        after_peak_min / 1e6
    );
    // Failure starts at σ_b; the stress keeps rising while the crack grows through the
    // particle (Δx/c_g ≈ 0.54 µs at M ε̇ ≈ 1.1 MPa/µs).
    assert!(
        peak >= 0.99 * sigma_b && peak < 1.1 * sigma_b,
        "peak {peak}"
    );
    assert!(
        after_peak_min < 0.2 * peak,
        "the bar must unload after failing"
    );
    // The failing particle is (nearly) fully damaged once the bar has unloaded.
    assert!(d_max > 0.99, "max D {d_max}");
    // Held particles: momentum changes by exactly the impulse of the constraint.
    let dp = sim.conserved().momentum - p0;
    assert!(
        (dp - sim.boundary_impulse).abs() <= 1e-12 * scale,
        "Δp {dp} vs impulse {}",
        sim.boundary_impulse
    );
}

/// The pseudo-plastic strain (sph_damage::activation) in a bar squeezed in uniaxial
/// strain: while elastic it is S/G; past yield S stays on the yield surface while the
/// strain keeps growing at the elastic rate; its positive lateral principal value
/// activates flaws in compression, where the stress form activates none.
#[test]
fn pseudo_plastic_strain_grows_through_yield_and_activates_flaws_in_compression() {
    let (n, rate, steps) = (20, -2000.0, 40);
    let von_mises = |y| {
        VonMises::new(VonMisesParams {
            yield_strength: y,
            shear_modulus: SHEAR,
            hardening: None,
        })
        .unwrap()
    };
    // Flaws of 1 mm³ particles with Weibull k (m⁻³), m = 10: basalt's k = 2.7e41 gives
    // thresholds ~1e-3, k = 1e10 thresholds ~1 that nothing here reaches.
    let flaws = |activation, k| {
        let params = BenzAsphaugParams::new(WeibullParams::new(k, 10.0).unwrap(), 7)
            .with_activation(activation);
        BenzAsphaug::seed(params, n, n as f64 * 1.0e-9).unwrap()
    };
    let run = |y, activation, k| {
        let mut sim = bar(n, rate, von_mises(y), flaws(activation, k));
        for _ in 0..steps {
            sim.step(f64::INFINITY).unwrap();
        }
        sim
    };
    let middle = |sim: &Simulation<Dim1, WendlandC2>| {
        (0..sim.state.particles.len())
            .filter(|&i| sim.state.particles.position[i].abs() < 5.0e-3)
            .collect::<Vec<_>>()
    };
    // Elastic and intact: ε_pp = S/G to rounding.
    let elastic = run(1.0e12, ActivationStrain::PseudoPlastic, 1.0e10);
    assert!(elastic.damage().iter().all(|&d| d == 0.0));
    for &i in &middle(&elastic) {
        let (e, s) = (
            elastic.state.pseudo_strain[i],
            elastic.state.stress[i] * (1.0 / SHEAR),
        );
        let scale = s.abs().to_cols_array().into_iter().fold(0.0, f64::max);
        assert!(scale > 1e-4, "the bar is strained: {scale}");
        assert!(
            (e - s)
                .abs()
                .to_cols_array()
                .iter()
                .all(|&x| x <= 1e-9 * scale)
        );
        // Uniaxial compression: S_xx < 0, the lateral S_yy = S_zz = −S_xx/2 > 0.
        assert!(
            e.x_axis.x < 0.0 && e.y_axis.y > 0.0 && e.z_axis.z > 0.0,
            "{e}"
        );
    }
    // Past yield: √(3J2) stays at Y, while ε_pp keeps growing as the elastic strain does.
    let y = 50.0e6;
    let soft = run(y, ActivationStrain::PseudoPlastic, 1.0e10);
    for &i in &middle(&soft) {
        let s = soft.state.stress[i];
        let j2 = 0.5 * (s * s.transpose()).diagonal().element_sum();
        assert!(
            (3.0 * j2).sqrt() <= y * (1.0 + 1e-9),
            "on the yield surface"
        );
        let e_yield = soft.state.pseudo_strain[i].y_axis.y;
        let e_elastic = elastic.state.pseudo_strain[i].y_axis.y;
        assert!(
            e_yield > 2.0 * s.y_axis.y / SHEAR && (e_yield / e_elastic - 1.0).abs() < 0.05,
            "ε_pp {e_yield} against S/G {} and the elastic bar's {e_elastic}",
            s.y_axis.y / SHEAR
        );
    }
    // Basalt's flaws: compression activates them on the pseudo-plastic strain, not on the
    // stress (which is not tracked then).
    let pseudo = run(1.0e12, ActivationStrain::PseudoPlastic, 2.7e41);
    let stress_form = run(1.0e12, ActivationStrain::Stress, 2.7e41);
    assert_eq!(stress_form.state.pseudo_strain.len(), 0, "not tracked");
    let d = pseudo.damage();
    let active = middle(&pseudo).iter().filter(|&&i| d[i] > 0.0).count();
    println!(
        "compression: {active} of {} middle particles damaged (pseudo-plastic)",
        middle(&pseudo).len()
    );
    assert!(
        active > 0,
        "compression activates flaws on the pseudo-plastic strain"
    );
    assert!(
        stress_form.damage().iter().all(|&x| x == 0.0),
        "but not on the stress"
    );
}

/// Shear failure (sph_damage::shear_failure) in a bar squeezed past yield: below the
/// transition pressure each particle's D is its plastic strain over ε_fb, the sum of
/// the increments dε_p/ε_f(P); without the law, and in tension-only damage that never
/// fails, D stays 0.
#[test]
fn shear_failure_damages_a_squeezed_bar_by_its_plastic_strain() {
    let (n, rate, steps) = (20, -2000.0, 40);
    let yielding = VonMises::new(VonMisesParams {
        yield_strength: 50.0e6,
        shear_modulus: SHEAR,
        hardening: None,
    })
    .unwrap();
    let never = || MaxTensileStress::new(1.0e12).unwrap();
    // ε_f = 1e-2 up to 2 GPa, far above this bar's pressure.
    let law = PlasticFailure::new(1.0e-2, 1.0e-11, 1.0e9).unwrap();
    let run = |shear| {
        let mut sim = bar_with_shear_failure(n, rate, yielding, never(), shear);
        for _ in 0..steps {
            sim.step(f64::INFINITY).unwrap();
        }
        sim
    };
    let plain = run(None);
    assert!(plain.damage().iter().all(|&d| d == 0.0));
    assert_eq!(plain.damage_events.shear_raised, 0);
    let sheared = run(Some(law));
    let (p, _) = sheared.pressure_and_sound_speed();
    let d = sheared.damage();
    let mut checked = 0;
    for i in 0..sheared.state.particles.len() {
        if sheared.state.particles.position[i].abs() > 5.0e-3 {
            continue;
        }
        let ep = sheared.state.plastic_strain[i];
        assert!(p[i] > 0.0 && p[i] < 2.0e9, "pressure {}", p[i]);
        assert!(ep > 0.0, "the bar yields: ε_p {ep}");
        assert!(
            (d[i] - (ep / 1.0e-2).min(1.0)).abs() < 1e-9,
            "D {} against ε_p/ε_fb {}",
            d[i],
            ep / 1.0e-2
        );
        checked += 1;
    }
    println!(
        "shear failure: {checked} middle particles, D = ε_p/ε_fb up to {:.3e}; {} updates",
        d.iter().cloned().fold(0.0, f64::max),
        sheared.damage_events.shear_raised
    );
    assert!(checked >= 8);
    assert!(sheared.damage_events.shear_raised > 0);
}

/// A 2-D elastic block with Benz–Asphaug flaws, the tensor artificial stress, expanding
/// from a compressed core (tension develops behind the release).
fn solid_block() -> Simulation<Dim2, WendlandC2> {
    block(|x| x * 200.0, 1.02, sph_damage::DamageForm::Scalar)
}

/// A 20 × 20 block of Δx = 1 mm, its core (r < 4 Δx) compressed to `core` ρ0, moving with
/// `velocity(x)`, with Benz–Asphaug flaws (BA99 basalt) of damage form `form` and the
/// tensor artificial stress.
fn block(
    velocity: impl Fn(DVec2) -> DVec2,
    core: f64,
    form: sph_damage::DamageForm,
) -> Simulation<Dim2, WendlandC2> {
    let (eos, strength) = elastic();
    let n = 20;
    let dx = 1.0e-3;
    let mut p = Particles::<Dim2>::new();
    for a in 0..n {
        for b in 0..n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx)
                - DVec2::splat(0.5 * n as f64 * dx);
            let c = if x.length() < 4.0 * dx { core } else { 1.0 };
            p.push(ParticleInit {
                position: x,
                velocity: velocity(x),
                mass: RHO * dx * dx * c,
                density: c * RHO,
                specific_energy: 0.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let volumes = vec![dx * dx * dx; n * n];
    let flaws = BenzAsphaug::seed_with_volumes(
        BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 11).with_form(form),
        &volumes,
    )
    .unwrap();
    let scheme = SchemeConfig {
        artificial_stress: ArtificialStress {
            epsilon: 0.3,
            exponent: 4,
            form: ArtificialStressForm::Principal,
            cap: None,
        },
        ..Default::default()
    };
    Simulation::new(
        p,
        vec![Material::solid("rock", eos, strength).with_damage(flaws)],
        scheme,
        WendlandC2,
        Vec::new(),
        None,
    )
    .unwrap()
}

/// Tensor damage grows only across the tensile direction: a block in plane pure shear,
/// v = ε̇ (x, −y), is stretched along x and squeezed along y (no strain along z), so its
/// interior cracks across x alone: **D** ≈ D_xx x̂ ⊗ x̂, and the scalar D reported is
/// D_xx.
#[test]
fn tensor_damage_grows_across_the_tensile_direction_only() {
    let mut sim = block(
        |x| DVec2::new(x.x, -x.y) * 4000.0,
        1.0,
        sph_damage::DamageForm::Tensor,
    );
    let interior = |x: DVec2| x.x.abs().max(x.y.abs()) < 5.0e-3;
    let mut steps = 0;
    while steps < 1500 {
        sim.step(f64::INFINITY).unwrap();
        steps += 1;
        let grown = (0..sim.state.particles.len())
            .filter(|&i| {
                interior(sim.state.particles.position[i])
                    && sim.state.damage_tensor[i].x_axis.x > 0.05
            })
            .count();
        if grown >= 10 {
            break;
        }
    }
    let scalar = sim.damage();
    let mut checked = 0;
    for i in 0..sim.state.particles.len() {
        let d = sim.state.damage_tensor[i];
        if !interior(sim.state.particles.position[i]) || d.x_axis.x < 0.05 {
            continue;
        }
        checked += 1;
        let off = d.y_axis.y.abs() + d.z_axis.z.abs() + d.x_axis.y.abs();
        assert!(off < 0.02 * d.x_axis.x, "particle {i}: {d:?}");
        assert!(
            (scalar[i] - d.x_axis.x).abs() < 1e-3 * d.x_axis.x,
            "{} {d:?}",
            scalar[i]
        );
    }
    println!("{checked} interior particles cracked across x after {steps} steps");
    assert!(checked >= 10, "{checked} after {steps} steps");
}

#[test]
fn damaged_solid_is_identical_with_one_and_two_threads() {
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                let mut sim = solid_block();
                for _ in 0..40 {
                    sim.step(f64::INFINITY).unwrap();
                }
                (
                    sim.state.particles.position.clone(),
                    sim.state.damage_state.clone(),
                    sim.state.stress.clone(),
                    sim.damage(),
                )
            })
    };
    let (a, b) = (run(1), run(2));
    let damaged = a.3.iter().filter(|&&d| d > 0.0).count();
    println!(
        "damaged particles after 40 steps: {damaged} of {}",
        a.3.len()
    );
    assert!(damaged > 0, "the test must exercise damage");
    assert_eq!(a.0, b.0);
    assert_eq!(a.1, b.1);
    assert_eq!(a.2, b.2);
}

/// Accelerations in a 15 × 15 block under a uniform shear stress S = diag(s, −s, 0) with
/// one damaged particle in the middle, after one tiny step: of the crack's four nearest
/// neighbours (−y, +y, −x, +x), of the crack itself, and of an intact particle three
/// spacings from the crack and from the edge. `crack` damages the middle particle of a
/// simulation whose damage model is `damage` (no flaw activates: the stress stays far
/// below the thresholds).
fn sheared_block_with_a_crack(
    coupling: sph_damage::StressCoupling,
    damage: sph_damage::BuiltinDamage,
    crack: impl FnOnce(&mut Simulation<Dim2, WendlandC2>, usize),
) -> ([DVec2; 4], DVec2, DVec2) {
    let (eos, strength) = elastic();
    let (n, dx) = (SHEARED_N, 1.0e-3);
    let middle = (n / 2) * n + n / 2;
    let mut p = Particles::<Dim2>::new();
    for a in 0..n {
        for b in 0..n {
            p.push(ParticleInit {
                position: DVec2::new(a as f64 * dx, b as f64 * dx),
                velocity: DVec2::ZERO,
                mass: RHO * dx * dx,
                density: RHO,
                specific_energy: 0.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let scheme = SchemeConfig {
        stress_coupling: coupling,
        ..Default::default()
    };
    let mut sim = Simulation::new(
        p,
        vec![Material::solid("rock", eos, strength).with_damage(damage)],
        scheme,
        WendlandC2,
        Vec::new(),
        None,
    )
    .unwrap();
    let s = sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(
        SHEARED_S, -SHEARED_S, 0.0,
    ));
    sim.state.stress.iter_mut().for_each(|x| *x = s);
    crack(&mut sim, middle);
    let dt = 1e-10;
    sim.step(dt).unwrap();
    let v = &sim.state.particles.velocity;
    let near = [middle - 1, middle + 1, middle - n, middle + n].map(|k| v[k] / dt);
    (near, v[middle] / dt, v[3 * n + 3] / dt)
}

const SHEARED_N: usize = 15;
const SHEARED_S: f64 = 1.0e7;

/// S/(ρ Δx): the scale of one pair's stress term in [`sheared_block_with_a_crack`].
fn sheared_scale() -> f64 {
    SHEARED_S / (RHO * 1.0e-3)
}

/// A maximum-tensile-stress model that never fails at the block's stress.
fn never_failing() -> sph_damage::BuiltinDamage {
    sph_damage::BuiltinDamage::MaxTensileStress(MaxTensileStress::new(1.0e12).unwrap())
}

/// The pair-max damage coupling (sph-damage `coupling`): a fully damaged particle in a
/// block under a uniform shear stress S passes no deviatoric stress to its intact
/// neighbours, where the study's per-particle coupling still lets each neighbour's own S
/// act across the pair. On a uniform lattice the pairs with intact particles cancel, so
/// the neighbour's acceleration is the missing crack pair's term: −S∇W with the
/// per-particle coupling, −2S∇W with pair-max: exactly twice as large.
#[test]
fn pair_max_coupling_opens_a_crack_to_deviatoric_stress() {
    let scalar_crack = |sim: &mut Simulation<Dim2, WendlandC2>, k: usize| {
        sim.state.damage_state[k] = 1.0;
    };
    let (particle, crack_p, far_p) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::Particle,
        never_failing(),
        scalar_crack,
    );
    let (pair_max, crack_m, far_m) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::PairMax,
        never_failing(),
        scalar_crack,
    );
    let scale = sheared_scale();
    for (a, b) in particle.iter().zip(&pair_max) {
        println!("neighbour: per-particle {a:?}, pair-max {b:?} (S/(ρΔx) = {scale:e})");
        assert!(a.length() > 0.1 * scale, "{a:?}");
        assert!((*b - *a * 2.0).length() < 1e-6 * a.length(), "{a:?} {b:?}");
    }
    // The crack particle itself feels nothing in either form (it carries no stress, and
    // its neighbours' uniform S cancels; measured 7e-10 m/s²), nor does an intact particle
    // far from it (measured 0.56 m/s², 1.5e-7 of S/(ρΔx), the lattice's residual at three
    // spacings from the free edge).
    for a in [crack_p, crack_m] {
        assert!(a.length() < 1e-9 * scale, "{a:?}");
    }
    assert!(
        (far_p - far_m).length() < 1e-9 * scale,
        "{far_p:?} {far_m:?}"
    );
    assert!(far_p.length() < 1e-6 * scale, "{far_p:?}");
}

/// Damage acting on the yield strength only (`StressCoupling::YieldOnly`): a half-damaged
/// particle (D = 0.5; its halved von Mises yield is still far above the stress) in the
/// sheared block passes its whole deviatoric stress, so its neighbours feel what they
/// feel in the intact block (the lattice's residual, measured 1e-9 of S/(ρΔx) there).
/// The per-particle coupling leaves out half of the particle's S (−½ S∇W on each
/// neighbour) and pair-max halves both stresses of its pairs (−S∇W, twice that).
#[test]
fn yield_only_coupling_passes_a_damaged_particles_whole_stress() {
    let half_crack = |sim: &mut Simulation<Dim2, WendlandC2>, k: usize| {
        sim.state.damage_state[k] = 0.5;
    };
    let run = |coupling| sheared_block_with_a_crack(coupling, never_failing(), half_crack).0;
    let intact = sheared_block_with_a_crack(
        sph_damage::StressCoupling::YieldOnly,
        never_failing(),
        |_, _| {},
    )
    .0;
    let yield_only = run(sph_damage::StressCoupling::YieldOnly);
    let particle = run(sph_damage::StressCoupling::Particle);
    let pair_max = run(sph_damage::StressCoupling::PairMax);
    let scale = sheared_scale();
    for k in 0..4 {
        let (y, i, a, b) = (yield_only[k], intact[k], particle[k], pair_max[k]);
        println!(
            "neighbour {k}: yield-only {y:?}, intact {i:?}, per-particle {a:?}, pair-max {b:?}"
        );
        assert!((y - i).length() < 1e-6 * scale, "{y:?} {i:?}");
        assert!(a.length() > 0.01 * scale, "{a:?}");
        assert!((b - a * 2.0).length() < 1e-6 * a.length(), "{a:?} {b:?}");
    }
}

/// FSISPH's stress coupling (`StressCoupling::Fsisph`, Spheral's solid FSISPH): the
/// sheared block S = diag(s, −s, 0) with a fully damaged particle in the middle. Along x
/// the pairs are in tension (r̂·(S_i + S_j)·r̂ = 2s > 0), so the crack's pairs pass no
/// deviatoric stress from either side, as pair-max: its x neighbours feel −2S∇W. Along y
/// they are in compression (−2s), so both stresses pass whole: the y neighbours feel only
/// what the crack itself has lost (its von Mises yield is zero at D = 1, so the midpoint's
/// radial return clears its S), which is the per-particle coupling's term.
#[test]
fn fsisph_coupling_opens_a_crack_in_tension_only() {
    // The crack's own stress is cleared from the start, as its zero yield clears it at
    // the midpoint, so that both RK2 stages see the same crack.
    let scalar_crack = |sim: &mut Simulation<Dim2, WendlandC2>, k: usize| {
        sim.state.damage_state[k] = 1.0;
        sim.state.stress[k] = sph_core::glam::DMat3::ZERO;
    };
    let run = |c| sheared_block_with_a_crack(c, never_failing(), scalar_crack);
    let (fsisph, crack_f, _) = run(sph_damage::StressCoupling::Fsisph);
    let (particle, _, _) = run(sph_damage::StressCoupling::Particle);
    let (pair_max, _, _) = run(sph_damage::StressCoupling::PairMax);
    let scale = sheared_scale();
    // near = [−y, +y, −x, +x] neighbours.
    for k in 0..4 {
        let (f, a, b) = (fsisph[k], particle[k], pair_max[k]);
        println!("neighbour {k}: fsisph {f:?}, per-particle {a:?}, pair-max {b:?}");
        let expect = if k < 2 { a } else { b };
        assert!(expect.length() > 0.01 * scale, "{expect:?}");
        assert!(
            (f - expect).length() < 1e-6 * expect.length(),
            "{f:?} {expect:?}"
        );
    }
    assert!(crack_f.length() < 1e-9 * scale, "{crack_f:?}");
}

/// A uniformly damaged region keeps its stress under FSISPH's coupling (f = (1 − ΔD)² = 1
/// for equal damage): the block uniformly at D = 0.5 (whose halved yield is still far
/// above the stress) accelerates exactly as the intact block, where the per-particle
/// coupling halves every stress.
#[test]
fn fsisph_coupling_keeps_the_stress_of_uniform_damage() {
    let uniform = |sim: &mut Simulation<Dim2, WendlandC2>, _: usize| {
        sim.state.damage_state.iter_mut().for_each(|d| *d = 0.5);
    };
    let (f, _, far_f) =
        sheared_block_with_a_crack(sph_damage::StressCoupling::Fsisph, never_failing(), uniform);
    let (i, _, far_i) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::Fsisph,
        never_failing(),
        |_, _| {},
    );
    for (a, b) in f.iter().zip(&i).chain([(&far_f, &far_i)]) {
        assert_eq!(a, b);
    }
}

/// A 1-D chain of 40 particles, all damaged to D = `damage` and stretched to 0.999 ρ0 (in
/// tension), moving with v = a x, without held ends; the scheme decouples fractured
/// material when `decouple` is on. Returns the simulation after one step of 1 ns.
fn damaged_chain(a: f64, damage: f64, decouple: bool) -> Simulation<Dim1, WendlandC2> {
    let (eos, strength) = elastic();
    let dx = 1.0e-3;
    let mut p = Particles::<Dim1>::new();
    for k in 0..40 {
        let x = (k as f64 - 19.5) * dx;
        p.push(ParticleInit {
            position: x,
            velocity: a * x,
            mass: 0.999 * RHO * dx,
            density: 0.999 * RHO,
            specific_energy: 0.0,
            smoothing_length: 2.5 * dx,
            material: 0,
        });
    }
    let scheme = SchemeConfig {
        decouple_damaged: decouple,
        artificial_stress: ArtificialStress {
            epsilon: 0.2,
            exponent: 4,
            form: ArtificialStressForm::Pressure,
            cap: None,
        },
        ..Default::default()
    };
    let mut sim = Simulation::new(
        p,
        vec![Material::solid("rock", eos, strength).with_damage(never_failing())],
        scheme,
        WendlandC2,
        Vec::new(),
        None,
    )
    .unwrap();
    let s = never_failing().variable().from_damage(damage);
    sim.state.damage_state.iter_mut().for_each(|d| *d = s);
    sim.step(1.0e-9).unwrap();
    sim
}

/// Decoupling of fractured material (`SchemeConfig::decouple_damaged`,
/// sph_damage::decoupling): a fully damaged chain (D = 0.95 > 0.9) in tension that is
/// separating has no interactions left: no particle's velocity or density changes. The
/// same chain without the rule is pulled together by its residual tension (P_D = 0.05 P),
/// and so is a chain at D = 0.8 (not fully damaged) with the rule on. Approaching
/// fragments still interact, exactly as without the rule. Momentum is exact in every case.
#[test]
fn fractured_material_separating_in_tension_decouples() {
    let a = 100.0;
    let v0: Vec<f64> = (0..40).map(|k| a * ((k as f64 - 19.5) * 1.0e-3)).collect();
    let moved = |sim: &Simulation<Dim1, WendlandC2>| {
        sim.state
            .particles
            .velocity
            .iter()
            .zip(&v0)
            .map(|(v, v0)| (v - v0).abs())
            .fold(0.0, f64::max)
    };
    // Σ m v against Σ m |v| (zero at the start by symmetry).
    let momentum = |sim: &Simulation<Dim1, WendlandC2>| {
        let p = &sim.state.particles;
        let sum = |f: fn(f64) -> f64| {
            p.velocity
                .iter()
                .zip(&p.mass)
                .map(|(v, m)| f(*v) * m)
                .sum::<f64>()
        };
        sum(|v| v) / sum(f64::abs)
    };
    let decoupled = damaged_chain(a, 0.95, true);
    assert!(decoupled.damage().iter().all(|&d| (d - 0.95).abs() < 1e-12));
    assert_eq!(moved(&decoupled), 0.0);
    assert!(
        decoupled
            .state
            .particles
            .density
            .iter()
            .all(|&r| r == 0.999 * RHO)
    );
    let coupled = damaged_chain(a, 0.95, false);
    let partly = damaged_chain(a, 0.8, true);
    println!(
        "largest velocity change: decoupled 0, coupled {:e}, D = 0.8 {:e} m/s",
        moved(&coupled),
        moved(&partly)
    );
    assert!(moved(&coupled) > 1.0e-6);
    assert!(moved(&partly) > 1.0e-6);
    // Approaching: the rule does not apply.
    let (on, off) = (
        damaged_chain(-a, 0.95, true),
        damaged_chain(-a, 0.95, false),
    );
    assert_eq!(on.state.particles.velocity, off.state.particles.velocity);
    for sim in [&decoupled, &coupled, &partly, &on] {
        assert!(momentum(sim).abs() < 1e-14, "{}", momentum(sim));
    }
}

/// Tensor damage (sph_damage::tensor) under pair-max coupling: a crack normal to x,
/// **D** = x̂ ⊗ x̂, opens the pairs along x exactly as a scalar D = 1 does, and leaves the
/// pairs along y coupled. Along y the neighbours feel only the crack's own lost strength
/// (its yield is weakened by **D**'s largest eigenvalue, to zero for von Mises at
/// D = 1, so the midpoint's radial return clears its S): exactly the per-particle
/// coupling's term, half of what the scalar crack exerts under pair-max.
#[test]
fn tensor_damage_opens_a_crack_only_across_its_plane() {
    // Flaws far stronger than the block's strain (k tiny: thresholds ~1e3): nothing grows.
    let tensor_model = || {
        let params = BenzAsphaugParams::new(WeibullParams::new(1.0, 10.0).unwrap(), 3)
            .with_form(sph_damage::DamageForm::Tensor);
        let volumes = vec![1e-6; SHEARED_N * SHEARED_N];
        sph_damage::BuiltinDamage::BenzAsphaug(
            BenzAsphaug::seed_with_volumes(params, &volumes).unwrap(),
        )
    };
    let scalar_crack = |sim: &mut Simulation<Dim2, WendlandC2>, k: usize| {
        sim.state.damage_state[k] = 1.0;
    };
    let (per_particle, _, _) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::Particle,
        never_failing(),
        scalar_crack,
    );
    let (pair_max, _, _) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::PairMax,
        never_failing(),
        scalar_crack,
    );
    let (tensor, crack, _) = sheared_block_with_a_crack(
        sph_damage::StressCoupling::PairMax,
        tensor_model(),
        |sim, k| {
            sim.state.damage_tensor[k] =
                sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(1.0, 0.0, 0.0));
            sim.state.damage_state[k] = 1.0;
        },
    );
    let scale = sheared_scale();
    println!("per-particle {per_particle:?}\npair-max {pair_max:?}\ntensor {tensor:?}");
    let close = |a: DVec2, b: DVec2, tol: f64| (a - b).length() < tol * b.length();
    // ±y neighbours (along the crack plane): the per-particle term, half the scalar
    // pair-max one. The crack's S is whole in the first stage here (the y pairs are
    // coupled) and cleared in the midpoint one, so the midpoint states differ at second
    // order in the step: measured 7.6e-5 relative.
    for k in 0..2 {
        assert!(per_particle[k].length() > 0.1 * scale);
        assert!(close(tensor[k], per_particle[k], 1e-3), "{:?}", tensor[k]);
        assert!(close(pair_max[k], per_particle[k] * 2.0, 1e-3));
    }
    // ±x neighbours (across it): fully open, as the scalar crack under pair-max
    // (measured 1.5e-8 relative).
    for k in 2..4 {
        assert!(close(tensor[k], pair_max[k], 1e-6), "{:?}", tensor[k]);
    }
    assert!(crack.length() < 1e-9 * scale, "{crack:?}");
}

#[test]
fn damage_without_strength_is_an_error_naming_the_material() {
    let (eos, _) = elastic();
    let mut p = Particles::<Dim1>::new();
    for k in 0..4 {
        p.push(ParticleInit {
            position: k as f64,
            velocity: 0.0,
            mass: 1.0,
            density: RHO,
            specific_energy: 0.0,
            smoothing_length: 2.0,
            material: 0,
        });
    }
    // The error of setting up these particles with one material.
    let refused = |m: Material| {
        Simulation::new(
            p.clone(),
            vec![m],
            SchemeConfig::default(),
            WendlandC2,
            Vec::new(),
            None,
        )
        .err()
        .expect("must fail")
        .to_string()
    };
    let err =
        refused(Material::fluid("water-ish", eos).with_damage(MaxTensileStress::new(1e6).unwrap()));
    assert!(err.contains("water-ish"), "{err}");
    assert!(err.contains("strength"), "{err}");
    // A flaw set seeded for another particle count is refused too.
    let (eos, strength) = elastic();
    let flaws = BenzAsphaug::seed(
        BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 1),
        7,
        1e-6,
    )
    .unwrap();
    let err = refused(Material::solid("rock", eos, strength).with_damage(flaws));
    assert!(err.contains("4 particles"), "{err}");
    // Shear failure needs a scalar D to raise: without a damage model, or with a tensor,
    // the set-up is refused, naming the material.
    let law = PlasticFailure::ROCK_COLLINS2004;
    let tensor = BenzAsphaug::seed(
        BenzAsphaugParams::new(WeibullParams::BASALT_BA99, 1)
            .with_form(sph_damage::DamageForm::Tensor),
        4,
        1e-6,
    )
    .unwrap();
    for m in [
        Material::solid("bare rock", eos, strength).with_shear_failure(law),
        Material::solid("bare rock", eos, strength)
            .with_damage(tensor)
            .with_shear_failure(law),
    ] {
        let err = refused(m);
        assert!(err.contains("bare rock"), "{err}");
        assert!(err.contains("shear failure"), "{err}");
    }
}

// Long verification runs (docs/verification.md); run them with
// `cargo test --release -p sph-impact --test solid -- --ignored --nocapture`.

#[test]
#[ignore = "long: ~2 min in release"]
fn tensile_bar_peak_stress_grows_with_strain_rate_from_the_static_strength() {
    let out = sph_impact::verify::Problem::TensileBar.run(None).unwrap();
    let get = |k: &str| out.get(k).unwrap();
    let e_eps1 = get("static_strength_e_eps1");
    let rates = [2, 3, 4, 5, 6].map(|k| get(&format!("peak_stress_rate_1e{k}")));
    let gk = [2, 3, 4, 5, 6, 7, 8].map(|k| get(&format!("gk_peak_stress_rate_1e{k}")));
    println!("E ε_1 = {e_eps1:e}; peaks {rates:?}; Grady–Kipp form {gk:?}");
    // Failure is never below the first flaw's strength, and faster loading fails later.
    for peaks in [&rates[..], &gk[..]] {
        assert!(peaks[0] >= e_eps1);
        assert!(peaks.windows(2).all(|w| w[1] > w[0]));
    }
    // The Grady–Kipp form (measured at the study's 0.5 mm, N = 100: 1.223 E ε_1 at
    // 1e2 s⁻¹, exponent 0.2452 over 1e4…1e8 s⁻¹): close to E ε_1 when slow, and the
    // issue's 15 % on 3/(m+3) where the peak strain is past the seeded flaws.
    assert!(get("gk_failure_stress_slowest_over_e_eps1") < 1.3);
    assert!(get("gk_window_peak_over_top_strain_min") > 1.0);
    let error = get("gk_rate_exponent_error_relative");
    assert!(error.abs() < 0.15, "exponent error {error}");
}

#[test]
#[ignore = "long: ~2 min in release"]
fn contact_sphere_into_block_runs_clean() {
    let out = sph_impact::verify::Problem::Contact.run(None).unwrap();
    let (first, min) = (
        out.get("sphere_dt_first").unwrap(),
        out.get("sphere_dt_min").unwrap(),
    );
    assert!(out.get("sphere_min_density_ratio").unwrap() > 0.0);
    // No runaway: the smallest step stays within a factor 3 of the first.
    assert!(min > first / 3.0, "dt {first:e} → {min:e}");
    assert!(out.get("pressure_error_relative").unwrap().abs() < 0.05);
}

#[test]
#[ignore = "long: ~4 min in release"]
fn rings_rebound_whole_with_artificial_stress_and_tear_without() {
    // docs/verification.md, "Colliding rubber rings": with artificial stress the rings stay two
    // bodies (friends-of-friends at 1.5 Δp) and rebound; without it they tear.
    let out = sph_impact::verify::Problem::Rings.run(None).unwrap();
    let get = |k: &str| out.get(k).unwrap();
    let (with, with_end) = (
        get("max_fragments_with_stress"),
        get("final_fragments_with_stress"),
    );
    let rebound = get("rebound_speed_over_initial_with_stress");
    let without = get("max_fragments_without_stress");
    let clump = get("min_pair_distance_without_stress");
    println!(
        "with artificial stress: at most {with} pieces, {with_end} at the end, rebound \
         {rebound:+.3} of the impact speed; without: {without} pieces, closest pair \
         {clump} Δp"
    );
    // Never more than the two rings (one while they touch), apart at the end.
    assert!(with <= 2.0 && with_end == 2.0);
    // The right ring moves outward again.
    assert!(rebound > 0.1, "rebound {rebound}");
    assert!(without > 2.0 && clump < 0.5);
    // Conservation in both runs.
    for tag in ["with_stress", "without_stress"] {
        let de = get(&format!("energy_change_relative_{tag}"));
        assert!(de.abs() < 1e-10, "energy change {de} ({tag})");
    }
}

#[test]
#[ignore = "long: ~3 min in release"]
fn taylor_bar_final_length_within_five_percent() {
    // The default: the cubic lattice at 8 across with the study's artificial stress, on
    // the contact anvil (measured with the contact deciding on its ghosts' total force
    // and R_f the widest point: L_f +3.8 %, R_f +4.5 %; deciding pair by pair gave
    // +3.7 %, +0.05 %. The targets of 3 and 5 % are met by RZ at 16 across, `verify taylor
    // --geometry rz --resolution 16`, ~11 min).
    let out = sph_impact::verify::Problem::Taylor.run(None).unwrap();
    let l = out.get("final_length_error_relative").unwrap();
    let r = out.get("face_radius_error_relative").unwrap();
    println!("L_f error {l:+.4}, R_f error {r:+.4}");
    assert!(l.abs() < 0.05, "{l}");
    assert!(r.abs() < 0.05, "{r}");
}

#[test]
#[ignore = "long: ~6 min in release on two threads, ~16 on one"]
fn plate_period_within_five_percent_at_ten_across() {
    // docs/verification.md, "Oscillating plate": T = 0.2540 s within 5 % at V_f = 0.01 with ≥ 10
    // across.
    let out = sph_impact::verify::Problem::Plate.run(Some(10)).unwrap();
    let e = out.get("period_error_relative").unwrap();
    let amp = out.get("tip_amplitude_vf001").unwrap();
    println!("period error {e:+.4}, tip amplitude {amp:.4} m");
    assert!(e.abs() < 0.05, "period error {e}");
    // Against the linear amplitude V_f c0 / ω (23.1 mm).
    let linear = out.get("tip_amplitude_linear_vf001").unwrap();
    assert!(
        (amp / linear - 1.0).abs() < 0.1,
        "tip amplitude {amp} vs {linear}"
    );
    // V_f = 0.05: one piece with artificial stress; without it the plate breaks.
    let with = out.get("max_pieces_vf005_with_stress").unwrap();
    let without = out.get("max_pieces_vf005_without_stress").unwrap();
    println!("V_f = 0.05: {with} piece(s) with artificial stress, {without} without");
    assert_eq!(with, 1.0);
    assert!(without > 1.0, "{without} pieces without artificial stress");
}

/// RZ (axisymmetric.rs): a rod at rest carrying only a hoop stress σ_θθ = −σ0 (σ_rr =
/// σ_zz = σ_rz = 0) is pushed outward by exactly a_r = σ0/(ρ r) — the hoop term alone —
/// everywhere beyond the axis zone, including the particles on the free outer surface.
/// (The pair sums' gauge ∂r/∂r used for the hoop force next to the axis grows like r/h at
/// a free surface; applied there it multiplied this force several times over and made the
/// edge of a Taylor bar's foot jet at kilometres per second.)
#[test]
fn rz_hoop_stress_pushes_a_free_rod_outward_at_sigma_over_rho_r() {
    let (worst, worst_surface) = rz_free_rod_hoop_push(sph_damage::StressCoupling::Particle, None);
    println!("a_r ρ r/σ0 − 1: worst {worst:.3e}, on the outer surface {worst_surface:.3e}");
    assert!(worst < 0.05, "{worst}");
}

/// Damage acting on the yield strength only (`StressCoupling::YieldOnly`, Collins et al.
/// 2004): the rod of the test above, half damaged (D = 0.5; the von Mises yield, halved,
/// is still far above the stress), keeps its whole deviatoric stress in the pair terms
/// and the hoop force, so a_r ρ r/σ0 stays 1, as for the intact rod. The paper's
/// per-particle coupling halves the deviatoric part, so σ_rr = −σ0/6 is no longer zero
/// at the free surfaces and the rod is far from that push (measured: a_r ρ r/σ0 off by
/// up to 0.49).
#[test]
fn rz_yield_only_coupling_keeps_a_damaged_rods_hoop_stress() {
    let (yield_only, yield_only_surface) =
        rz_free_rod_hoop_push(sph_damage::StressCoupling::YieldOnly, Some(0.5));
    let (particle, _) = rz_free_rod_hoop_push(sph_damage::StressCoupling::Particle, Some(0.5));
    println!(
        "yield-only: |a_r ρ r/σ0 − 1| worst {yield_only:.3e} (surface {yield_only_surface:.3e}); \
         per-particle: worst {particle:.3e}"
    );
    assert!(yield_only < 0.05, "{yield_only}");
    assert!(particle > 0.2, "{particle}");
}

/// The principal artificial stress' hoop part acts where only the hoop stress is
/// tensile: an RZ rod under σ = diag(−σ0/2, −σ0/2, σ0) in (r, z, θ) has no tensile
/// in-plane principal stress, so its in-plane R is zero, but R_θθ = −ε σ0/ρ². The pair
/// loop evaluates the kernel ratio f_ij only for pairs that need it; a pair whose in-plane
/// R_i + R_j vanishes still needs it for a side's hoop force. After one tiny step the
/// hoop force's share of every interior ring's acceleration is nonzero and linear in ε.
#[test]
fn rz_principal_artificial_stress_acts_on_a_hoop_only_tension() {
    let radial = |epsilon: f64| -> Vec<(f64, f64)> {
        let (eos, strength) = elastic();
        let sigma0 = 1.0e8;
        let p = rz_rod_at_rest(12, 1.0e-3, RHO);
        let scheme = SchemeConfig {
            geometry: sph_impact::Geometry::Axisymmetric,
            artificial_stress: ArtificialStress {
                epsilon,
                exponent: 4,
                form: ArtificialStressForm::Principal,
                cap: None,
            },
            ..Default::default()
        };
        let material = Material::solid("aluminium", eos, strength);
        let mut sim =
            Simulation::new(p, vec![material], scheme, WendlandC2, Vec::new(), None).unwrap();
        let s = sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(
            -0.5 * sigma0,
            -0.5 * sigma0,
            sigma0,
        ));
        sim.state.stress.iter_mut().for_each(|x| *x = s);
        let dt = 1e-10;
        sim.step(dt).unwrap();
        let q = &sim.state.particles;
        (0..q.len())
            .map(|i| (q.position[i].x, q.velocity[i].x / dt))
            .collect()
    };
    let (off, half, full) = (radial(0.0), radial(0.1), radial(0.2));
    let mut checked = 0;
    for k in 0..off.len() {
        let r = off[k].0;
        // Away from the axis zone and the outer surface.
        if r > 3.0 * 2.5e-3 && r < 10.0e-3 {
            let (d1, d2) = (half[k].1 - off[k].1, full[k].1 - off[k].1);
            assert!(
                d1.abs() > 1e-3 * off[k].1.abs(),
                "ring {k}: hoop part {d1} of {}",
                off[k].1
            );
            assert!(
                (d2 / d1 - 2.0).abs() < 1e-6,
                "ring {k}: {d2} against 2 × {d1}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 12, "{checked}");
}

/// An RZ rod at rest: n × n rings of spacing dx from the axis, at density `rho`, each ring
/// of mass ρ dx² r (per radian), h = 2.5 dx.
fn rz_rod_at_rest(n: usize, dx: f64, rho: f64) -> Particles<Dim2> {
    let mut p = Particles::<Dim2>::new();
    for a in 0..n {
        for b in 0..n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            p.push(ParticleInit {
                position: x,
                velocity: DVec2::ZERO,
                mass: rho * dx * dx * x.x,
                density: rho,
                specific_energy: 0.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    p
}

/// The RZ rod of [`rz_hoop_stress_pushes_a_free_rod_outward_at_sigma_over_rho_r`] under
/// the stress coupling `coupling`, every ring at damage `damage` (none: no damage model),
/// after one tiny step: the largest |a_r ρ r/σ0 − 1| beyond the axis zone, and
/// on the free outer surface.
fn rz_free_rod_hoop_push(coupling: sph_damage::StressCoupling, damage: Option<f64>) -> (f64, f64) {
    let (eos, strength) = elastic();
    let (n, dx, sigma0) = (16, 1.0e-3, 1.0e8);
    // σ = S − P I with P = σ0/3: S = diag(σ0/3, σ0/3, −2σ0/3) in (r, z, θ).
    let p0 = sigma0 / 3.0;
    let rho = RHO * (1.0 + p0 / BULK);
    let p = rz_rod_at_rest(n, dx, rho);
    let scheme = SchemeConfig {
        geometry: sph_impact::Geometry::Axisymmetric,
        stress_coupling: coupling,
        ..Default::default()
    };
    let mut material = Material::solid("aluminium", eos, strength);
    if damage.is_some() {
        material = material.with_damage(never_failing());
    }
    let mut sim = Simulation::new(p, vec![material], scheme, WendlandC2, Vec::new(), None).unwrap();
    let s = sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(p0, p0, -2.0 * p0));
    sim.state.stress.iter_mut().for_each(|x| *x = s);
    if let Some(d) = damage {
        sim.state.damage_state.iter_mut().for_each(|x| *x = d);
    }
    let dt = 1e-10;
    sim.step(dt).unwrap();
    let q = &sim.state.particles;
    let (mut worst, mut worst_surface) = (0.0f64, 0.0f64);
    for i in 0..q.len() {
        let r = q.position[i].x;
        // Beyond the axis zone (three support radii).
        if r > 3.0 * 2.5 * dx {
            let ratio = q.velocity[i].x / dt * rho * r / sigma0;
            let off = (ratio - 1.0).abs();
            worst = worst.max(off);
            if r > (n as f64 - 1.0) * dx {
                worst_surface = worst_surface.max(off);
            }
        }
    }
    (worst, worst_surface)
}

/// RZ Taylor bar 4 spacings across the radius, to 80 µs: the whole rod lies within two
/// support radii of the axis, so its free surface is inside the zone where the hoop force
/// uses the pair sums' gauge ŝ. Unbounded there, ŝ started at −2.73 on the outer column
/// (the hoop force turned around); the rim jetted at 2 km/s from 13 µs and the run
/// stopped with a NaN at 26 µs. Kept within its lattice range the rod comes to rest
/// (measured on the contact anvil with pair-by-pair contact: KE 1.5e-3 of the start at 80 µs, L_f
/// 23.56 mm, R_f 5.92 mm; 164 rings).
#[test]
fn rz_taylor_rod_four_across_comes_to_rest() {
    use sph_impact::verify::Problem;
    let out = Problem::Taylor
        .run_rz(Some(4), Problem::Taylor.default_scheme())
        .expect("the run reaches 80 µs");
    let get = |k: &str| out.get(k).unwrap();
    let ke = get("kinetic_energy_final_over_initial");
    assert!(ke < 0.01, "KE at 80 µs {ke} of the start");
    // Broad physical bounds (the reference is 21.5 and 7.1 mm; 4 across is coarse).
    let (l, r) = (get("final_length_mm"), get("face_radius_mm"));
    assert!((20.0..26.0).contains(&l), "L_f {l} mm");
    assert!((5.0..8.0).contains(&r), "R_f {r} mm");
    // R_f(t) never jumps: the rim moves at most 1 mm per microsecond sample.
    let radius = out.history.column("face_radius").unwrap();
    for w in radius.windows(2) {
        assert!(
            (w[1] - w[0]).abs() < 1e-3,
            "R_f jumped {} -> {}",
            w[0],
            w[1]
        );
    }
}

/// RZ Taylor bar (copper at 227 m/s on a rigid anvil, 8 spacings across the radius) for
/// 15 µs: no particle moves faster than twice the impact speed (measured: 332 m/s, the
/// foot's rim splashing outward). With the hoop gauge applied everywhere, as before it was
/// confined to the axis zone, the rim jets at 11 000 m/s (docs/verification.md, RZ
/// section).
#[test]
fn rz_taylor_foot_does_not_jet() {
    let (rho, e, nu) = (8930.0, 117.0e9, 0.35);
    let eos = LinearElastic::new(LinearElasticParams {
        rho0: rho,
        K0: e / (3.0 * (1.0 - 2.0 * nu)),
    })
    .unwrap();
    let strength = VonMises::new(VonMisesParams {
        yield_strength: 400.0e6,
        shear_modulus: e / (2.0 * (1.0 + nu)),
        hardening: Some(sph_strength::von_mises::LinearHardening { modulus: 100.0e6 }),
    })
    .unwrap();
    let (n, radius, length, speed) = (8, 3.2e-3, 32.4e-3, 227.0);
    let dx = radius / n as f64;
    let mut p = Particles::<Dim2>::new();
    for a in 0..n {
        for b in 0..(length / dx).round() as usize {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            p.push(ParticleInit {
                position: x,
                velocity: DVec2::new(0.0, -speed),
                mass: rho * dx * dx * x.x,
                density: rho,
                specific_energy: 0.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let count = p.len();
    let scheme = SchemeConfig {
        geometry: sph_impact::Geometry::Axisymmetric,
        ..Default::default()
    };
    let mut sim = Simulation::new(
        p,
        vec![Material::solid("copper", eos, strength)],
        scheme,
        WendlandC2,
        vec![sph_impact::Boundary::Wall {
            point: DVec2::ZERO,
            normal: DVec2::Y,
        }],
        Some(vec![dx; count]),
    )
    .unwrap();
    let mut fastest: f64 = 0.0;
    sim.run_until(15.0e-6, |s, _| {
        let v = s
            .state
            .particles
            .velocity
            .iter()
            .fold(0.0f64, |a, v| a.max(v.length()));
        fastest = fastest.max(v);
    })
    .unwrap();
    println!("fastest particle over 15 µs: {fastest:.1} m/s (impact {speed} m/s)");
    assert!(fastest < 2.0 * speed, "{fastest}");
}

/// A bar of 10 solid particles, a lone solid particle far from it at a thousandth of ρ0,
/// and a lone gas particle as thin, stepped once with `scheme`.
fn lone_thin_particles(scheme: SchemeConfig) -> Simulation<Dim1, WendlandC2> {
    let (eos, strength) = elastic();
    let dx = 1.0e-3;
    let mut p = Particles::<Dim1>::new();
    let mut push = |x: f64, rho: f64, material: u16| {
        p.push(ParticleInit {
            position: x,
            velocity: 0.0,
            mass: RHO * dx,
            density: rho,
            specific_energy: if material == 1 { 1.0e3 } else { 0.0 },
            smoothing_length: 2.5 * dx,
            material,
        })
    };
    for k in 0..10 {
        push(k as f64 * dx, RHO, 0);
    }
    push(1.0, 1e-3 * RHO, 0);
    push(2.0, 1e-3 * RHO, 1);
    let gas = Material::fluid("gas", sph_eos::IdealGas::with_gamma(1.4).unwrap());
    let mut sim = Simulation::new(
        p,
        vec![Material::solid("bar", eos, strength), gas],
        scheme,
        WendlandC2,
        Vec::new(),
        None,
    )
    .unwrap();
    sim.step(f64::INFINITY).unwrap();
    sim
}

/// After a step the lone solid sits at its floor m/(h_max_factor Δp0) (counted), the gas
/// is left alone, the bar is untouched; with the floor off the solid stays thin.
#[test]
fn a_solid_density_is_floored_where_its_kernel_stops_growing_and_a_gas_is_not() {
    let sim = lone_thin_particles(SchemeConfig::default());
    let rho = &sim.state.particles.density;
    let floor = RHO * 1.0e-3 / (SchemeConfig::default().h_max_factor * 1.0e-3);
    println!(
        "floor {floor} kg/m³: lone solid {}, lone gas {}",
        rho[10], rho[11]
    );
    assert!((rho[10] / floor - 1.0).abs() < 1e-12, "{}", rho[10]);
    assert_eq!(rho[11], 1e-3 * RHO);
    assert_eq!(sim.density_floor_events, 1);
    assert!(rho[..10].iter().all(|&r| r > 0.5 * RHO));
    let off = lone_thin_particles(SchemeConfig {
        solid_density_floor: false,
        ..Default::default()
    });
    assert_eq!(off.state.particles.density[10], 1e-3 * RHO);
    assert_eq!(off.density_floor_events, 0);
}

/// The study's Al → basalt impact at 3.9 km/s in RZ (basalt_3.9kms_rz.toml at A_res 1 mm,
/// the target cut down to a Ø20 × 10 mm cylinder to keep the test short) with the study's
/// artificial stress, ε = 0.2, n = 4 (paper §2.3, §6).
///
/// With the placement's spacing Δp₀ in f_ij = W(r_ij)/W(Δp) the time step collapsed at
/// 3.4 µs: projectile rings spread over the crater floor (r/r₀ ≈ 2–6) have an (r, z)
/// spacing, and so an h, of Δp₀ √(r₀/r), so f ≈ 5–8 and f⁴ ≈ 10³ for every neighbour at
/// the ordinary spacing; the artificial stress between an aluminium and a basalt ring in
/// mild tension (−30 MPa) reached 10¹⁰–10¹³ m/s² within three steps, its work drove e
/// negative (−2.4e7 J/kg) and the Tillotson tension with it. With Δp = Δp₀ √(r₀/r)
/// (`axisymmetric::reference_spacing`) the run goes on with e ≥ 0 and energy conserved.
#[test]
fn rz_impact_with_the_study_artificial_stress_runs_past_the_old_collapse() {
    let text = r#"geometry = "rz"
end_time = 6.0e-6
seed = 1

[[body]]
name = "projectile"
material = "aluminium-2024-jc"
shape = { kind = "sphere", centre = [0.0, 0.0, 3.5e-3], radius = 3.0e-3 }
placement = { kind = "variable", origin = [0.0, 0.0, 3.5e-3], a_res = 1.0e-3, q = 1.00 }
velocity = [0.0, 0.0, -3900.0]

[[body]]
name = "target"
material = "basalt-study"
shape = { kind = "cylinder", base = [0.0, 0.0, -0.010], axis = [0.0, 0.0, 1.0], radius = 0.010, length = 0.010 }
placement = { kind = "variable", origin = [0.0, 0.0, 0.0], a_res = 1.0e-3, q = 1.01 }

[solver]
artificial_stress = { epsilon = 0.2, n = 4, form = "pressure" }
"#;
    let scene = sph_impact::scene::Scene::from_toml_str(text, "scene.toml").unwrap();
    let mut built = scene.build().unwrap();
    let sph_impact::scene::SceneSimulation::Rz(sim) = &mut built.simulation else {
        panic!("an RZ scene");
    };
    assert_eq!(sim.scheme.artificial_stress.epsilon, 0.2);
    let e0 = sim.conserved().energy();
    let (mut e_min, mut rho_min) = (f64::INFINITY, f64::INFINITY);
    sim.run_until(scene.end_time, |s, _| {
        let p = &s.state.particles;
        e_min = p.specific_energy.iter().fold(e_min, |a, &e| a.min(e));
        rho_min = p.density.iter().fold(rho_min, |a, &r| a.min(r));
    })
    .unwrap();
    let drift = sim.conserved().energy() / e0 - 1.0;
    println!(
        "{} rings to {:.1} µs in {} steps: min e {e_min:.3e} J/kg, min ρ {rho_min:.1} kg/m³, \
         energy change {drift:.2e}",
        sim.state.particles.len(),
        sim.state.time * 1e6,
        sim.state.step
    );
    assert!(sim.state.time >= 6.0e-6 * (1.0 - 1e-12));
    assert!(e_min >= 0.0, "{e_min}");
    assert!(rho_min > 0.0, "{rho_min}");
    assert!(drift.abs() < 1e-4, "{drift}");
}

/// FSISPH's energy diffusion (`SchemeConfig::energy_diffusion`): a chain at rest with a
/// jump in specific energy (a linear-elastic EOS, so the pressure does not see it and
/// nothing moves) conducts heat from the hot half to the cold half, and Σ m e stays
/// what it was to round-off; without the term nothing changes. (Spheral's reconstruction
/// makes the second particle on the hot side overshoot a little, +0.46 % after 20 steps:
/// sph_riemann::spheral_reconstruct.)
#[test]
fn energy_diffusion_conducts_heat_across_a_jump_and_conserves_energy() {
    let run = |kappa: f64| {
        let (eos, strength) = elastic();
        let dx = 1.0e-3;
        let mut p = Particles::<Dim1>::new();
        for k in 0..40 {
            p.push(ParticleInit {
                position: (k as f64 - 19.5) * dx,
                velocity: 0.0,
                mass: RHO * dx,
                density: RHO,
                specific_energy: if k < 20 { 2.0e5 } else { 1.0e5 },
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
        let scheme = SchemeConfig {
            energy_diffusion: kappa,
            ..Default::default()
        };
        let mut sim = Simulation::new(
            p,
            vec![Material::solid("rock", eos, strength)],
            scheme,
            WendlandC2,
            Vec::new(),
            None,
        )
        .unwrap();
        let total = |s: &Simulation<Dim1, WendlandC2>| {
            let p = &s.state.particles;
            p.specific_energy
                .iter()
                .zip(&p.mass)
                .map(|(e, m)| e * m)
                .sum::<f64>()
        };
        let e0 = total(&sim);
        for _ in 0..20 {
            sim.step(f64::INFINITY).unwrap();
        }
        (
            sim.state.particles.specific_energy.clone(),
            total(&sim) / e0 - 1.0,
        )
    };
    let (off, drift_off) = run(0.0);
    let (on, drift_on) = run(0.1);
    println!(
        "energy at the jump: {:?} (off {:?}), drift {drift_on:e}",
        &on[18..22],
        &off[18..22]
    );
    assert!(off.iter().take(20).all(|&e| e == 2.0e5));
    assert!(off.iter().skip(20).all(|&e| e == 1.0e5));
    assert!(on[19] < 2.0e5 && on[20] > 1.0e5, "{:?}", &on[18..22]);
    // Far from the jump nothing has arrived yet.
    assert_eq!(on[0], 2.0e5);
    assert!(drift_on.abs() < 1e-14 && drift_off.abs() < 1e-14);
}

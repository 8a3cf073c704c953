//! Solver tests: conservation, thread independence, and the 1-D verification targets
//! (docs/verification.md). Heavier runs are in `sph-impact verify` and `#[ignore]`d here.

use sph_core::glam::DVec2;
use sph_core::{Dim2, ParticleInit, Particles};
use sph_eos::{IdealGas, LinearElastic, LinearElasticParams};
use sph_impact::verify::{Problem, SedovDeposit};
use sph_impact::{Boundary, Material, SchemeConfig, Simulation};
use sph_kernel::WendlandC2;
use sph_riemann::{MonaghanViscosity, ViscositySwitch};

mod common;

/// A 2-D blob of gas with scattered pressures and velocities, free surface and (when
/// `walls`) one reflecting wall and a periodic pair.
fn blob(walls: bool) -> Simulation<Dim2, WendlandC2> {
    blob_with(walls, SchemeConfig::default())
}

fn blob_with(walls: bool, scheme: SchemeConfig) -> Simulation<Dim2, WendlandC2> {
    let (p, boundaries) = common::gas_blob(walls);
    Simulation::new(
        p,
        vec![Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap())],
        scheme,
        WendlandC2,
        boundaries,
        None,
    )
    .unwrap()
}

/// Runs `steps` steps; returns the conserved sums before and after, and Σ m|v| at the
/// start (the momentum scale).
fn run_steps(
    sim: &mut Simulation<Dim2, WendlandC2>,
    steps: usize,
) -> (
    sph_impact::Conserved<Dim2>,
    sph_impact::Conserved<Dim2>,
    f64,
) {
    let p = &sim.state.particles;
    let scale: f64 = p
        .mass
        .iter()
        .zip(&p.velocity)
        .map(|(m, v)| m * v.length())
        .sum();
    let c0 = sim.conserved();
    for _ in 0..steps {
        sim.step(f64::INFINITY).unwrap();
    }
    (c0, sim.conserved(), scale)
}

/// A 24 × 24 lattice of gas at uniform density and pressure moving with the linear
/// velocity field `v(x)` about the lattice's centre; no boundaries.
fn linear_flow(
    v: impl Fn(DVec2) -> DVec2,
    viscosity: MonaghanViscosity,
) -> Simulation<Dim2, WendlandC2> {
    let mut p = Particles::<Dim2>::new();
    let (n, dx) = (24, 1.0 / 24.0);
    for a in 0..n {
        for b in 0..n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            p.push(ParticleInit {
                position: x,
                velocity: v(x - DVec2::splat(0.5)),
                mass: dx * dx,
                density: 1.0,
                specific_energy: 1.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let scheme = SchemeConfig {
        viscosity,
        ..SchemeConfig::default()
    };
    let gas = Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap());
    Simulation::new(p, vec![gas], scheme, WendlandC2, Vec::new(), None).unwrap()
}

/// The mean heating rate de/dt over the first step of the particles more than two
/// support radii inside the lattice of [`linear_flow`].
fn interior_heating(mut sim: Simulation<Dim2, WendlandC2>) -> f64 {
    let inner = |x: DVec2| (x - DVec2::splat(0.5)).abs().max_element() < 0.5 - 5.0 / 24.0;
    let before: Vec<f64> = sim.state.particles.specific_energy.clone();
    let start: Vec<bool> = sim
        .state
        .particles
        .position
        .iter()
        .map(|&x| inner(x))
        .collect();
    let dt = sim.step(f64::INFINITY).unwrap().dt;
    let p = &sim.state.particles;
    let (mut sum, mut count) = (0.0, 0.0);
    for i in (0..p.len()).filter(|&i| start[i]) {
        sum += (p.specific_energy[i] - before[i]) / dt;
        count += 1.0;
    }
    sum / count
}

/// The Balsara switch (sph_riemann::balsara_factor) turns the Monaghan viscosity off in a
/// simple shear, v_x = γ y (∇·v = 0), and keeps it in a uniform compression, v = −γ x
/// (∇×v = 0). The viscous heating is the heating with the viscosity less the heating
/// without it (the compression's P dV work).
#[test]
fn balsara_switch_stops_shear_heating_and_keeps_compression_heating() {
    // 1/s. The gas sound speed is 0.75 m/s and the switch's length 0.052 m (the viscosity
    // length), so ε c/h ≈ 1.4e-3 1/s ≪ |∇·v| = 2γ.
    let gamma = 50.0;
    let shear = |x: DVec2| DVec2::new(gamma * x.y, 0.0);
    let squeeze = |x: DVec2| -gamma * x;
    let visc = |switch| MonaghanViscosity {
        switch,
        ..MonaghanViscosity::default()
    };
    let inviscid = MonaghanViscosity {
        alpha: 0.0,
        beta: 0.0,
        switch: ViscositySwitch::None,
        ..MonaghanViscosity::default()
    };
    let viscous_heating = |v: &dyn Fn(DVec2) -> DVec2, switch| {
        interior_heating(linear_flow(v, visc(switch))) - interior_heating(linear_flow(v, inviscid))
    };
    let shear_off = viscous_heating(&shear, ViscositySwitch::None);
    let shear_on = viscous_heating(&shear, ViscositySwitch::Balsara);
    let squeeze_off = viscous_heating(&squeeze, ViscositySwitch::None);
    let squeeze_on = viscous_heating(&squeeze, ViscositySwitch::Balsara);
    println!(
        "viscous de/dt: shear {shear_off:e} → {shear_on:e}, compression {squeeze_off:e} → {squeeze_on:e}"
    );
    // Without the switch the shear is heated (the pairs with x_ij y_ij < 0 approach).
    assert!(
        shear_off > 0.01 * squeeze_off,
        "shear heating {shear_off:e}"
    );
    // Switched: 2.0e-3 of it (measured); the residual is the divergence error the pair
    // sums read on the lattice once the step has sheared it.
    assert!(
        shear_on.abs() < 1e-2 * shear_off,
        "switched shear heating {shear_on:e}"
    );
    // Compression: the same heating within the switch's noise floor (f = 1 − 1.4e-5;
    // measured 1.8e-5 apart).
    assert!(squeeze_off > 0.0);
    assert!(((squeeze_on - squeeze_off) / squeeze_off).abs() < 1e-4);
}

#[test]
fn momentum_is_conserved_to_round_off_without_boundaries() {
    let mut sim = blob(false);
    let (c0, c1, scale) = run_steps(&mut sim, 30);
    let rel = (c1.momentum - c0.momentum).length() / scale;
    println!("momentum change / Σ m|v| after 30 steps: {rel:e}");
    assert!(rel < 1e-12, "{rel:e}");
    assert!((c1.mass - c0.mass).abs() < 1e-15 * c0.mass);
}

#[test]
fn corrected_momentum_equation_conserves_momentum_and_energy() {
    // σ_i (M_i⁻ᵀ∇W) + σ_j (M_j⁻ᵀ∇W) is antisymmetric in (i, j): momentum is exact, and
    // the compatible energy equation pairs with whatever pair force is used.
    let scheme = SchemeConfig {
        momentum_correction: true,
        ..SchemeConfig::default()
    };
    let mut sim = blob_with(false, scheme.clone());
    let e0 = sim.conserved().energy();
    let (c0, c1, scale) = run_steps(&mut sim, 30);
    let dp = (c1.momentum - c0.momentum).length() / scale;
    let de = (c1.energy() - e0) / e0;
    println!("corrected momentum: ΔP / Σ m|v| = {dp:e}, ΔE/E = {de:e} after 30 steps");
    assert!(dp < 1e-12, "{dp:e}");
    assert!(de.abs() < 1e-12, "{de:e}");
    // The correction changes the forces (the blob's edges are free surfaces).
    let mut plain = blob(false);
    run_steps(&mut plain, 30);
    let moved = plain
        .state
        .particles
        .position
        .iter()
        .zip(&sim.state.particles.position)
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(moved > 1e-6, "{moved:e}");
    // With walls the ghosts' corrections are their sources', mapped: the wall impulse
    // still balances the momentum change.
    let mut walled = blob_with(true, scheme);
    let (c0, c1, scale) = run_steps(&mut walled, 30);
    let rel = (c1.momentum - c0.momentum - walled.boundary_impulse).length() / scale;
    assert!(rel < 1e-12, "{rel:e}");
}

#[test]
fn momentum_balances_the_boundary_impulse() {
    let mut sim = blob(true);
    let (c0, c1, scale) = run_steps(&mut sim, 30);
    let rel = (c1.momentum - c0.momentum - sim.boundary_impulse).length() / scale;
    println!(
        "(ΔP − wall impulse) / Σ m|v|: {rel:e}; impulse {:?}",
        sim.boundary_impulse
    );
    assert!(rel < 1e-12, "{rel:e}");
    // The wall pushes (its normal is +y); the periodic axis delivers nothing along x.
    assert!(sim.boundary_impulse.y > 0.0);
}

#[test]
fn identical_results_with_one_and_two_threads() {
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                let mut sim = blob(true);
                for _ in 0..10 {
                    sim.step(f64::INFINITY).unwrap();
                }
                sim.state
            })
    };
    let (a, b) = (run(1), run(2));
    assert_eq!(a.time.to_bits(), b.time.to_bits());
    let bits = |s: &sph_impact::State<Dim2>| -> Vec<u64> {
        let p = &s.particles;
        (0..p.len())
            .flat_map(|i| {
                [
                    p.position[i].x,
                    p.position[i].y,
                    p.velocity[i].x,
                    p.velocity[i].y,
                    p.density[i],
                    p.specific_energy[i],
                    p.smoothing_length[i],
                ]
            })
            .map(f64::to_bits)
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
}

#[test]
fn sod_meets_its_targets() {
    let o = Problem::Sod.run(Some(400)).unwrap();
    let get = |k: &str| o.get(k).unwrap();
    println!("{:?}", o.metrics);
    assert!(get("p_star_error_relative").abs() < 0.02);
    assert!(get("u_star_error_relative").abs() < 0.02);
    assert!(get("shock_error_in_spacings").abs() < 1.0);
    assert!(get("momentum_balance_relative") < 1e-12);
    assert!(get("l1_rho") < 0.01);
}

#[test]
fn sod_rejects_a_resolution_that_does_not_fit_the_right_state() {
    let err = Problem::Sod.run(Some(300)).unwrap_err().to_string();
    assert!(err.contains("multiple of 8"), "{err}");
}

#[test]
fn toro_123_stays_positive() {
    let o = Problem::Toro123.run(Some(200)).unwrap();
    assert!(o.get("min_pressure_over_run").unwrap() >= 0.0);
    assert!(o.get("min_density_over_run").unwrap() > 0.0);
}

#[test]
fn toro_3_shock_within_two_percent() {
    let o = Problem::Toro3.run(Some(400)).unwrap();
    let e = o.get("shock_error_relative").unwrap();
    println!(
        "Toro 3 shock at {} (exact 0.78221): {e:+.4}",
        o.get("shock_position").unwrap()
    );
    assert!(e.abs() < 0.02);
}

#[test]
fn planar_noh_meets_its_targets() {
    let o = Problem::NohPlanar.run(Some(100)).unwrap();
    println!("{:?}", o.metrics);
    // docs/verification.md, "Noh": ρ L1 over [0.05, 0.35] ≤ 0.048 at nx = 100, shock at
    // 0.2 ± 1 spacing.
    assert!(
        o.get("l1_rho").unwrap() <= 0.048,
        "{}",
        o.get("l1_rho").unwrap()
    );
    assert!(o.get("shock_error_in_spacings").unwrap().abs() < 1.0);
    assert!(o.get("momentum_balance_relative").unwrap() < 1e-12);
}

#[test]
fn sedov_2d_meets_its_targets() {
    // docs/verification.md, "Sedov–Taylor": shock radius within 2 % of ξ0 (E t²/ρ0)^(1/4) at ≥ 3
    // of the 4 times, log R–log t slope within 2 % of 1/2, energy conserved (80 across: ~10 s in
    // release; docs/verification.md has 200 across).
    let o = Problem::Sedov2d.run(Some(80)).unwrap();
    let errors: Vec<f64> = (1..=4)
        .map(|k| o.get(&format!("shock_radius_error_t{k}")).unwrap())
        .collect();
    println!("Sedov 2-D radius errors {errors:?}, {:?}", o.metrics);
    assert!(errors.iter().filter(|e| e.abs() < 0.02).count() >= 3);
    assert!((o.get("time_slope").unwrap() / 0.5 - 1.0).abs() < 0.02);
    assert!(o.get("energy_change_relative").unwrap().abs() < 1e-3);
    assert!(o.get("momentum_relative").unwrap() < 1e-12);
}

#[test]
fn only_sedov_takes_a_deposit() {
    let err = Problem::Sod
        .run_sedov(
            Some(50),
            Problem::Sod.default_scheme(),
            SedovDeposit::Kernel,
            false,
        )
        .unwrap_err()
        .to_string();
    assert!(err.contains("deposit"), "{err}");
    assert!("spike".parse::<SedovDeposit>().is_err());
    assert_eq!("kernel".parse::<SedovDeposit>(), Ok(SedovDeposit::Kernel));
}

#[test]
#[ignore = "three resolutions; about 30 s in release: cargo test -p sph-impact --release --test solver -- --ignored"]
fn sod_converges() {
    // docs/verification/sod.md, at 400, 800 and 1600: order ≥ 0.8 and every
    // resolution's star state within 2 % and shock within one spacing.
    let runs: Vec<_> = [400, 800, 1600]
        .iter()
        .map(|&n| Problem::Sod.run(Some(n)).unwrap())
        .collect();
    let l1: Vec<f64> = runs.iter().map(|o| o.get("l1_rho").unwrap()).collect();
    let p1 = sph_diagnostics::convergence_order(400.0, l1[0], 800.0, l1[1]);
    let p2 = sph_diagnostics::convergence_order(800.0, l1[1], 1600.0, l1[2]);
    println!("L1(ρ) {l1:?}, orders {p1:.3} {p2:.3}");
    assert!(p1 >= 0.8 && p2 >= 0.8);
    for o in &runs {
        assert!(o.get("p_star_error_relative").unwrap().abs() < 0.02);
        assert!(o.get("u_star_error_relative").unwrap().abs() < 0.02);
        assert!(o.get("shock_error_in_spacings").unwrap().abs() < 1.0);
    }
}

#[test]
fn bad_scheme_and_state_are_typed_errors() {
    let scheme = SchemeConfig {
        cfl: 2.0,
        ..Default::default()
    };
    let mut p = Particles::<Dim2>::new();
    p.push(ParticleInit {
        position: DVec2::ZERO,
        velocity: DVec2::ZERO,
        mass: 1.0,
        density: 1.0,
        specific_energy: 1.0,
        smoothing_length: 0.1,
        material: 3,
    });
    let gas = || vec![Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap())];
    let e = Simulation::new(p.clone(), gas(), scheme, WendlandC2, vec![], None)
        .err()
        .unwrap();
    assert!(e.to_string().contains("cfl"), "{e}");
    let e = Simulation::new(p, gas(), SchemeConfig::default(), WendlandC2, vec![], None)
        .err()
        .unwrap();
    assert!(e.to_string().contains("material id 3"), "{e}");
}

#[test]
fn asph_tensors_stay_positive_definite_and_on_target_volume() {
    // The blob's particles, rebuilt with ASPH (the tensors are initialised by `new`),
    // and a lone particle far away at 1e-3 of the blob's density, whose equivalent radius
    // n_target (m/ρ)^(1/2) would be 32 times its start: it must stop at the cap.
    let mut p = blob(false).state.particles.clone();
    let dx = 1.0 / 24.0;
    p.push(ParticleInit {
        position: DVec2::new(5.0, 5.0),
        velocity: DVec2::ZERO,
        mass: dx * dx,
        density: 1e-3,
        specific_energy: 1.0,
        smoothing_length: 2.5 * dx,
        material: 0,
    });
    let lone = p.len() - 1;
    let mut sim = Simulation::new(
        p,
        vec![Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap())],
        SchemeConfig {
            smoothing: sph_impact::SmoothingMode::Asph { max_aspect: 4.0 },
            ..Default::default()
        },
        WendlandC2,
        Vec::new(),
        None,
    )
    .unwrap();
    let c0 = sim.conserved();
    for _ in 0..20 {
        sim.step(f64::INFINITY).unwrap();
    }
    let s = &sim.state;
    assert_eq!(s.h_tensor.len(), s.particles.len());
    for i in 0..s.particles.len() {
        let h = s.h_tensor[i];
        let e = sph_core::Tensor::sym_eigen(&h);
        assert!(e.values[0] > 0.0, "particle {i}: H not positive definite");
        assert!(
            e.values[1] / e.values[0] <= 4.0 + 1e-9,
            "particle {i}: aspect {}",
            e.values[1] / e.values[0]
        );
        // Equivalent radius det(H)^(-1/2) = n_target (m/ρ)^(1/2), capped at 4× its start.
        let target = (2.5 * (s.particles.mass[i] / s.particles.density[i]).sqrt())
            .min(4.0 * 2.5 * s.spacing0[i]);
        let radius = h.determinant().powf(-0.5);
        assert!(
            (radius / target - 1.0).abs() < 1e-9,
            "particle {i}: radius {radius} target {target}"
        );
    }
    // The lone particle sits at the cap (before the cap, ASPH let it grow to 32×).
    let lone_radius = s.h_tensor[lone].determinant().powf(-0.5);
    assert!(
        (lone_radius / (4.0 * 2.5 * dx) - 1.0).abs() < 1e-9,
        "{lone_radius}"
    );
    let c1 = sim.conserved();
    let scale: f64 = c0.mass;
    assert!((c1.momentum - c0.momentum).length() / scale < 1e-12);
}

#[test]
fn total_energy_is_conserved_to_round_off_without_boundaries() {
    let mut sim = blob(false);
    let e0 = sim.conserved().energy();
    for _ in 0..30 {
        sim.step(f64::INFINITY).unwrap();
    }
    let e1 = sim.conserved().energy();
    let rel = (e1 - e0) / e0;
    println!("relative energy change after 30 steps: {rel:e}");
    assert!(rel.abs() < 1e-12, "{rel:e}");
}

#[test]
fn bad_boundary_is_a_typed_error_naming_it() {
    let p = blob(false).state.particles.clone();
    let walls = vec![
        Boundary::Periodic {
            axis: 0,
            lo: 0.0,
            hi: 1.0,
        },
        Boundary::Wall {
            point: DVec2::ZERO,
            normal: DVec2::new(0.0, 2.0),
        },
    ];
    let e = Simulation::new(
        p,
        vec![Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap())],
        SchemeConfig::default(),
        WendlandC2,
        walls,
        None,
    )
    .err()
    .unwrap();
    let msg = e.to_string();
    assert!(
        msg.starts_with("boundary 1:") && msg.contains("unit vector"),
        "{msg}"
    );
}

#[test]
fn elastic_bars_carry_the_right_wave_and_separate() {
    let o = Problem::ElasticBar.run(Some(100)).unwrap();
    println!("{:?}", o.metrics);
    // docs/verification.md, "Solid dynamics: elastic bars": front at c_L within 1 %, plateau
    // ρ c_L v within 2 %.
    assert!(o.get("front_speed_error_relative").unwrap().abs() < 0.01);
    assert!(o.get("plateau_stress_error_max").unwrap() < 0.02);
    // The unbonded interface lets the bars part (welded, they keep 0.15 % of KE0), and the
    // rebound keeps KE/KE0 ≥ 0.95 (0.994 measured) without creating energy.
    let ke = o.get("rebound_kinetic_energy_ratio").unwrap();
    assert!((0.95..=1.0).contains(&ke), "KE/KE0 = {ke}");
    assert!(o.get("energy_change_relative").unwrap().abs() < 1e-12);
}

#[test]
fn elastic_precursor_has_the_hel_amplitude_at_both_speeds() {
    let o = Problem::HelImpact.run(None).unwrap();
    println!("{:?}", o.metrics);
    // docs/verification.md, "Solid dynamics: elastic–plastic planar impact": precursor amplitude
    // within 3 % of σ_HEL = 0.5075 GPa at V = 400 and 1000 m/s. (Its speed converges at first
    // order: +2.3 % at this resolution, see the ignored test below at twice the resolution.)
    for v in ["v400", "v1000"] {
        assert!(
            o.get(&format!("{v}_precursor_error_relative"))
                .unwrap()
                .abs()
                < 0.03,
            "{v}"
        );
    }
}

#[test]
#[ignore = "long: ~1 min in release (`cargo test --release -p sph-impact --test solver -- --ignored`)"]
fn elastic_precursor_travels_at_the_longitudinal_wave_speed() {
    // 1600 particles per plate (0.25 mm): the half-amplitude front within 2 % of c_L
    // (relative to the material) at both speeds (+1.2 % and +0.9 % measured).
    let o = Problem::HelImpact.run(Some(1600)).unwrap();
    for v in ["v400", "v1000"] {
        let e = o
            .get(&format!("{v}_precursor_speed_error_relative"))
            .unwrap();
        assert!(e.abs() < 0.02, "{v}: {e}");
    }
}

#[test]
fn spinning_disc_conserves_angular_momentum() {
    let o = Problem::Spin.run(None).unwrap();
    println!("{:?}", o.metrics);
    // Issue target: angular momentum conserved to 1e-6 relative over 1000 steps.
    assert!(o.get("angular_momentum_change_max_relative").unwrap() < 1e-6);
    assert!(o.get("energy_change_relative").unwrap().abs() < 1e-12);
}

#[test]
fn aluminium_into_basalt_matches_the_impedance_match() {
    let o = Problem::Contact.run(None).unwrap();
    println!("{:?}", o.metrics);
    // Issue target: the planar shock pressure near the contact within 5 % of the Tillotson
    // impedance match; no negative density.
    assert!(o.get("pressure_error_relative").unwrap().abs() < 0.05);
    assert!(o.get("contact_velocity_error_relative").unwrap().abs() < 0.05);
    assert!(o.get("min_density_over_run").unwrap() > 0.0);
}

/// A uniform gas at rest in RZ next to the axis stays at rest: the hoop force balances the
/// pair forces' part of ∂(r P)/∂r exactly, also within a support radius of the axis.
#[test]
fn rz_uniform_pressure_is_in_equilibrium_next_to_the_axis() {
    let mut sim = rz_gas_block();
    let dt = sim.step(1e-4).unwrap().dt;
    // Particles away from the free surfaces (r < 0.5, 0.5 < z < 1.5) feel no force:
    // exactly within two support radii of the axis, where the hoop force uses the pair
    // sums' own ∂r/∂r; beyond, where it uses the exact 1, to the lattice's first-moment
    // error (a free surface's pressure release here would be ~2e-4 m/s).
    let (near, beyond) = rz_interior_accelerations(&sim, dt);
    println!(
        "largest speed after one step: within 2h of the axis {:e}, beyond {:e}",
        near * dt,
        beyond * dt
    );
    assert!(near * dt < 1e-10, "{near}");
    assert!(beyond * dt < 1e-6, "{beyond}");
}

/// A uniform tension with the artificial stress on (ε = 0.2, the study's) exerts no force
/// in RZ either: the hoop part of the artificial stress balances the geometric part of its
/// r-weighted pair term. Without it (measured before the fix) the rings were pulled toward
/// the axis at a_r = −1.2e-2 in the axis column and −1.7e-3 at r = 0.8, (0.25–0.75)
/// ε|P|/(ρ r) with |P| = 0.01 K; the plane 2-D run has no such force.
#[test]
fn rz_uniform_tension_with_artificial_stress_is_in_equilibrium() {
    let elastic = LinearElastic::new(LinearElasticParams { rho0: 1.0, K0: 1.0 }).unwrap();
    let mut accel = Vec::new();
    for epsilon in [0.0, 0.2] {
        let scheme = SchemeConfig {
            geometry: sph_impact::Geometry::Axisymmetric,
            artificial_stress: sph_riemann::ArtificialStress {
                epsilon,
                ..Default::default()
            },
            ..Default::default()
        };
        // ρ = 0.99 ρ0: P = −0.01 K everywhere.
        let mut sim = rz_block(0.99, Material::fluid("elastic", elastic), scheme);
        let dt = sim.step(1e-4).unwrap().dt;
        let (near, beyond) = rz_interior_accelerations(&sim, dt);
        println!(
            "eps {epsilon}: largest |a| within 2h of the axis {near:e}, beyond {beyond:e} (eps|P|/(rho r) at r = h: {:e})",
            epsilon * 0.01 / (2.5 / 12.0)
        );
        accel.push((near, beyond));
    }
    // With ε = 0.2 as without (measured: 2.6e-8 within 2h of the axis and 7.7e-5 beyond,
    // the pressure's own residuals on this lattice, against ε|P|/(ρ r) ≈ 1e-2).
    let ((near0, beyond0), (near, beyond)) = (accel[0], accel[1]);
    assert!(near0 < 1e-6 && beyond0 < 1e-3, "{near0} {beyond0}");
    assert!((near - near0).abs() < 1e-9, "{near} vs {near0}");
    assert!((beyond - beyond0).abs() < 1e-9, "{beyond} vs {beyond0}");
}

/// The artificial stress' cap (docs/verification.md, "The axis jet"): in a uniform
/// tension, a pair pushed to 0.45 Δp apart is driven apart by the study's unbounded form
/// (ε fⁿ = 5.7 times the tension's pull between them, support 2.5 Δp), and with `cap = 1`
/// the pair term can at most cancel that pull. Plane 2-D block, P = −0.01 K; the pair's
/// separating acceleration after one tiny step, against the same block without the
/// artificial stress. Measured: −0.112 (ε = 0), +0.912 (the study's), +0.056 (cap 1).
#[test]
fn capped_artificial_stress_does_not_drive_a_close_pair_apart() {
    let elastic = LinearElastic::new(LinearElasticParams { rho0: 1.0, K0: 1.0 }).unwrap();
    let (n, dx) = (16, 1.0 / 16.0);
    // The pair: particle `a` at the centre, `b` moved down from the row above to 0.45 dx.
    let (ia, ib) = (8 * n + 8, 8 * n + 9);
    let separating = |astress: sph_riemann::ArtificialStress| {
        let mut p = Particles::<Dim2>::new();
        for a in 0..n {
            for b in 0..n {
                let mut x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
                if a * n + b == ib {
                    x.y -= 0.55 * dx;
                }
                p.push(ParticleInit {
                    position: x,
                    velocity: DVec2::ZERO,
                    mass: 0.99 * dx * dx,
                    density: 0.99,
                    specific_energy: 1.0,
                    smoothing_length: 2.5 * dx,
                    material: 0,
                });
            }
        }
        let scheme = SchemeConfig {
            artificial_stress: astress,
            ..Default::default()
        };
        let material = Material::fluid("elastic", elastic);
        let mut sim =
            Simulation::new(p, vec![material], scheme, WendlandC2, Vec::new(), None).unwrap();
        let dt = sim.step(1e-6).unwrap().dt;
        let s = &sim.state.particles;
        let k = |id: usize| s.id.iter().position(|&i| i == id as u64).unwrap();
        // Relative acceleration of b away from a, along the pair (+y).
        (s.velocity[k(ib)].y - s.velocity[k(ia)].y) / dt
    };
    let study = sph_riemann::ArtificialStress::default();
    let off = separating(sph_riemann::ArtificialStress {
        epsilon: 0.0,
        ..study
    });
    let unbounded = separating(study);
    let capped = separating(sph_riemann::ArtificialStress {
        cap: Some(1.0),
        ..study
    });
    println!("separating acceleration: eps 0 {off:e}, study {unbounded:e}, cap 1 {capped:e}");
    // Without the artificial stress the tension pulls the pair together (the tensile
    // instability); the study's form turns that into a push many times as strong; the cap
    // leaves at most the push that cancels the pull, so much less than the study's.
    assert!(off < 0.0, "{off}");
    assert!(unbounded > 5.0 * off.abs(), "{unbounded} vs {off}");
    assert!(capped < 0.25 * unbounded, "{capped} vs {unbounded}");
    assert!(capped > off, "{capped} vs {off}");
}

/// Free flight: particles above the plane moving up leave the hydrodynamics after the
/// step, fly on at constant velocity, and stay in every total; the rest conserve
/// momentum and energy as before (a dropped pair drops both its forces).
#[test]
fn free_flight_takes_out_particles_above_the_plane_and_keeps_every_total() {
    let scheme = SchemeConfig {
        free_flight_above: Some(0.9),
        ..SchemeConfig::default()
    };
    let mut sim = blob_with(false, scheme);
    let n = sim.state.particles.len();
    let (c0, c1, scale) = run_steps(&mut sim, 5);
    let flying = sim.in_free_flight();
    println!("in free flight after 5 steps: {flying} of {n}");
    assert!(flying > 0);
    assert_eq!(sim.state.particles.len() + flying, n);
    assert!(
        sim.state
            .particles
            .position
            .iter()
            .zip(&sim.state.particles.velocity)
            .all(|(x, v)| !(x.y > 0.9 && v.y > 0.0))
    );
    let rel = (c1.momentum - c0.momentum).length() / scale;
    assert!(rel < 1e-12, "momentum {rel:e}");
    assert!((c1.mass - c0.mass).abs() < 1e-14 * c0.mass);
    let de = (c1.kinetic + c1.internal) / (c0.kinetic + c0.internal) - 1.0;
    assert!(de.abs() < 1e-12, "energy {de:e}");
    // The outputs' view: every particle, the flying ones drifting at their velocity.
    let seen = |sim: &mut Simulation<Dim2, WendlandC2>| {
        sim.with_free_flight(|s| {
            let p = &s.state.particles;
            assert_eq!(p.len(), n);
            let mut ids = p.id.clone();
            ids.sort_unstable();
            assert!(ids.iter().enumerate().all(|(k, &id)| id == k as u64));
            // The flying ones come last, in the order they left.
            (p.len() - s.in_free_flight()..p.len())
                .map(|i| (p.id[i], p.position[i], p.velocity[i]))
                .collect::<Vec<_>>()
        })
    };
    let before = seen(&mut sim);
    assert_eq!(sim.state.particles.len(), n - flying);
    let t0 = sim.state.time;
    sim.step(f64::INFINITY).unwrap();
    let dt = sim.state.time - t0;
    let after = seen(&mut sim);
    assert!(after.len() >= before.len());
    for ((id0, x0, v0), (id1, x1, v1)) in before.iter().zip(&after) {
        assert_eq!((id0, v0), (id1, v1));
        assert!((*x1 - (*x0 + *v0 * dt)).length() < 1e-15, "{x0} → {x1}");
        assert!(x1.y > 0.9 && v1.y > 0.0);
    }
    sim.end_free_flight();
    assert_eq!((sim.state.particles.len(), sim.in_free_flight()), (n, 0));
    sim.state.particles.validate().unwrap();
}

/// In RZ a ring's smoothing length follows its (r, z) area m/(ρ r), with r at least the
/// half-width of its own section: a first-column ring carried onto the axis keeps the
/// lattice's h. With the bare radius its h went to the cap (4 × 2.5 Δx here), and in the
/// RZ Sedov blast at 240 across such a ring kicked its neighbours into a runaway.
#[test]
fn rz_ring_on_the_axis_keeps_a_finite_smoothing_length() {
    let mut sim = rz_gas_block();
    let dx = 1.0 / 12.0;
    // Ring 12: first column, mid-height; onto the axis, its mass unchanged.
    let i = 12;
    assert!((sim.state.particles.position[i].x - 0.5 * dx).abs() < 1e-12);
    sim.state.particles.position[i].x = 1e-4 * dx;
    sim.step(1e-6).unwrap();
    let p = &sim.state.particles;
    let k = p.id.iter().position(|&id| id == i as u64).unwrap();
    let h = p.smoothing_length[k];
    println!(
        "h of the ring on the axis: {:.3} Δx (neighbours 2.5 Δx)",
        h / dx
    );
    assert!((h / (2.5 * dx) - 1.0).abs() < 0.05, "{}", h / dx);
}

/// A ring found across the axis at the end of a step is mirrored back to r > 0 with its
/// radial velocity reversed, and the run counts it, as it counts midpoints across the
/// axis (`Simulation::axis_crossing_counts`, reported by every RZ run: issue 6 asks that
/// no ring crosses). The block at rest counts none.
#[test]
fn rz_axis_crossings_are_mirrored_back_and_counted() {
    let mut sim = rz_gas_block();
    sim.step(1e-4).unwrap();
    assert_eq!(sim.axis_crossing_counts(), Some((0, 0)));
    let dx = 1.0 / 12.0;
    // Ring 12 (first column) put just across the axis, at r = −0.01 Δx and moving on
    // inward, then a step short enough (1e-9) that nothing else moves it: the axis
    // mirror brings it back to r = +0.01 Δx with v_r reversed. (In a run the mirror
    // ghosts push a ring back before it gets there: thrown at the axis from
    // r = 0.001 Δx at ten times the sound speed, the same ring ended its step further
    // out, at r = 0.007 Δx, uncounted.)
    let i = 12;
    sim.state.particles.position[i].x = -1e-2 * dx;
    sim.state.particles.velocity[i] = DVec2::new(-1e-3, 0.0);
    sim.step(1e-9).unwrap();
    let p = &sim.state.particles;
    let k = p.id.iter().position(|&id| id == i as u64).unwrap();
    println!(
        "ring after the step: r = {:.3} Δx, v_r = {:.3} Δx",
        p.position[k].x / dx,
        p.velocity[k].x / dx
    );
    // Its midpoint lay across the axis too (it started there).
    assert_eq!(sim.axis_crossing_counts(), Some((1, 1)));
    assert!(p.position[k].x > 0.0 && p.velocity[k].x > 0.0);
}

/// In RZ a ring moving toward the axis does not leave (its mirror ghosts could still
/// reach it); one moving away does.
#[test]
fn free_flight_in_rz_waits_for_rings_moving_toward_the_axis() {
    let scheme = SchemeConfig {
        geometry: sph_impact::Geometry::Axisymmetric,
        free_flight_above: Some(1.9),
        ..SchemeConfig::default()
    };
    let material = Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap());
    let mut sim = rz_block(1.0, material, scheme);
    let p = &mut sim.state.particles;
    for i in 0..p.len() {
        if p.position[i].y > 1.9 {
            let inward = p.position[i].x < 0.5;
            p.velocity[i] = DVec2::new(if inward { -0.1 } else { 0.1 }, 1.0);
        }
    }
    sim.step(1e-4).unwrap();
    let flying = sim.with_free_flight(|s| {
        let p = &s.state.particles;
        let live = p.len() - s.in_free_flight();
        (live..p.len()).map(|i| p.position[i]).collect::<Vec<_>>()
    });
    println!("rings in free flight: {}", flying.len());
    assert_eq!(flying.len(), 6, "the six top rings beyond r = 0.5");
    assert!(flying.iter().all(|x| x.x > 0.5 && x.y > 1.9));
}

/// [`rz_block`] of an ideal gas (γ = 1.4) at unit density with the default scheme in RZ.
fn rz_gas_block() -> Simulation<Dim2, WendlandC2> {
    let scheme = SchemeConfig {
        geometry: sph_impact::Geometry::Axisymmetric,
        ..SchemeConfig::default()
    };
    let gas = Material::fluid("gas", IdealGas::with_gamma(1.4).unwrap());
    rz_block(1.0, gas, scheme)
}

/// A 12 × 24 lattice of rings (Δx = 1/12, r ∈ (0, 1), z ∈ (0, 2)) at rest at uniform
/// density, h = 2.5 Δx, no boundaries but the axis.
fn rz_block(
    density: f64,
    material: Material,
    scheme: SchemeConfig,
) -> Simulation<Dim2, WendlandC2> {
    let mut p = Particles::<Dim2>::new();
    let (n, dx) = (12, 1.0 / 12.0);
    for a in 0..n {
        for b in 0..2 * n {
            let x = DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx);
            p.push(ParticleInit {
                position: x,
                velocity: DVec2::ZERO,
                mass: density * dx * dx * x.x,
                density,
                specific_energy: 1.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    Simulation::new(p, vec![material], scheme, WendlandC2, Vec::new(), None).unwrap()
}

/// The largest |Δv|/dt of the interior rings of [`rz_block`] after one step (r < 0.5,
/// 0.5 < z < 1.5): within two support radii of the axis, and beyond.
fn rz_interior_accelerations(sim: &Simulation<Dim2, WendlandC2>, dt: f64) -> (f64, f64) {
    let s = &sim.state.particles;
    let h = 2.5 / 12.0;
    let (mut near, mut beyond): (f64, f64) = (0.0, 0.0);
    for i in 0..s.len() {
        let x = s.position[i];
        if x.x < 0.5 && x.y > 0.5 && x.y < 1.5 {
            let a = s.velocity[i].length() / dt;
            if x.x < 2.0 * h {
                near = near.max(a);
            } else {
                beyond = beyond.max(a);
            }
        }
    }
    (near, beyond)
}

/// Spherical Noh in RZ (verification.md, RZ section): at 20 spacings per radius at least
/// as close to the exact solution as the 3-D run at the same resolution (L1(ρ) 9.20), with
/// the total energy and axial momentum of the rings conserved.
#[test]
fn rz_spherical_noh_matches_the_3d_accuracy() {
    let o = Problem::NohSpherical
        .run_rz(Some(20), Problem::NohSpherical.default_scheme())
        .unwrap();
    println!("{:?}", o.metrics);
    assert!(o.get("l1_rho").unwrap() < 9.2);
    assert!(o.get("energy_change_relative").unwrap().abs() < 1e-5);
    assert!((o.get("shock_position").unwrap() - 0.2).abs() < 0.04);
}

/// Planar Noh along z in RZ against the same column in plane 2-D (verification.md, RZ
/// section): with the study's momentum form and viscosity the RZ terms add less than 10 %
/// to the 2-D column's L1(ρ) (measured: 0.231 against 0.227 at 40 rows). The plane column
/// is itself 1.2–2.4 times the 1-D error (2-D SPH's, not the geometry's), but its density
/// profile, averaged over the cross-section, is the 1-D run's within a few per cent.
#[test]
fn rz_planar_noh_matches_the_plane_column_and_the_1d_profile() {
    let mut scheme = Problem::NohPlanar.default_scheme();
    scheme.momentum = sph_impact::MomentumForm::ParticlePressure;
    scheme.viscosity = sph_riemann::MonaghanViscosity {
        alpha: 1.0,
        beta: 1.0,
        ..Default::default()
    };
    let rz = Problem::NohPlanar.run_rz(Some(40), scheme.clone()).unwrap();
    let plane = Problem::NohPlanar
        .run_plane_column(Some(40), scheme)
        .unwrap();
    let (a, b) = (rz.get("l1_rho").unwrap(), plane.get("l1_rho").unwrap());
    println!("L1(ρ): RZ {a:.4}, plane column {b:.4}");
    assert!((a / b - 1.0).abs() < 0.1, "RZ {a} against plane {b}");
    // Issue 6: the RZ column reproduces the 1-D run's density profile (cross-section
    // means along z) within 10 %. Measured 0.052 here, 0.021 at 100 rows.
    let d = rz.get("rho_profile_difference_from_1d").unwrap();
    println!("RZ density profile against 1-D: {d:.4}");
    assert!(d < 0.1, "RZ profile {d} from the 1-D one");
}

/// Asking for a form a problem does not have (RZ, plane column, rings, an energy
/// deposit) names the problem and the forms that exist, before anything is placed.
#[test]
fn a_missing_verify_form_names_the_problem() {
    let scheme = || Problem::Sod.default_scheme();
    let errors = [
        Problem::Sod.run_rz(None, scheme()).unwrap_err(),
        Problem::Sod.run_plane_column(None, scheme()).unwrap_err(),
        Problem::Sod.run_rings(None, scheme()).unwrap_err(),
        Problem::Sod
            .run_sedov(None, scheme(), Default::default(), false)
            .unwrap_err(),
    ];
    for e in errors {
        let text = e.to_string();
        assert!(
            matches!(
                e,
                sph_impact::SolverError::NoSuchForm { problem: "sod", .. }
            ),
            "{text}"
        );
        assert!(text.starts_with("verify sod: "), "{text}");
        assert!(!text.contains("= 0"), "{text}");
    }
}

/// A block pressed onto a contact wall while stretched along it acts on the wall as on a
/// mirror: the wall's total force on each particle of the bottom row pushes, so all of
/// its ghost pairs act, including the oblique ones that the lateral tension makes
/// attractive along the pair's line. Deciding pair by pair drops those,
/// and with them their share of the wall's push: the bottom row, in equilibrium on the
/// mirror (|v_y| < 1e-18 m/s after 1 ns), is then driven into the wall at 1.4e-3 m/s.
#[test]
fn a_contact_wall_in_compression_acts_as_a_mirror_under_lateral_tension() {
    let wall = Boundary::Wall {
        point: DVec2::ZERO,
        normal: DVec2::Y,
    };
    let contact = Boundary::Contact {
        point: DVec2::ZERO,
        normal: DVec2::Y,
    };
    let (mirror, pushed) = (block_on(wall), block_on(contact));
    // The bottom row, away from the block's free sides.
    let bottom = |v: &[(DVec2, DVec2)]| -> Vec<f64> {
        v.iter()
            .filter(|(x, _)| x.y < 1.0e-3 && (x.x - 12.0e-3).abs() < 6.0e-3)
            .map(|(_, v)| v.y)
            .collect()
    };
    let (a, b) = (bottom(&mirror), bottom(&pushed));
    let scale = mirror.iter().fold(0.0f64, |m, (_, v)| m.max(v.length()));
    println!(
        "bottom row v_y: mirror {:e} … {:e}, contact {:e} … {:e}; fastest particle {scale:e} m/s",
        a.iter().cloned().fold(f64::INFINITY, f64::min),
        a.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
        b.iter().cloned().fold(f64::INFINITY, f64::min),
        b.iter().cloned().fold(f64::NEG_INFINITY, f64::max),
    );
    assert_eq!(a.len(), 12);
    for (m, c) in a.iter().zip(&b) {
        assert!(
            (m - c).abs() <= 1e-12 * scale,
            "mirror {m} against contact {c}"
        );
    }
}

/// A 24 × 12 block of elastic solid (basalt-like: ρ0 2700 kg/m³, K 26.7 GPa, G 22.7 GPa,
/// no yield) at ρ0 on `wall` at y = 0, stretched along it and pressed onto it: σ_xx =
/// +100 MPa, σ_yy = −10 MPa (P = 0, S = diag(100, −10, −90) MPa). Positions and velocities
/// after one step of 1 ns.
fn block_on(wall: Boundary<Dim2>) -> Vec<(DVec2, DVec2)> {
    let (dx, rho0) = (1.0e-3, 2700.0);
    let mut p = Particles::<Dim2>::new();
    for a in 0..24 {
        for b in 0..12 {
            p.push(ParticleInit {
                position: DVec2::new((a as f64 + 0.5) * dx, (b as f64 + 0.5) * dx),
                velocity: DVec2::ZERO,
                mass: rho0 * dx * dx,
                density: rho0,
                specific_energy: 0.0,
                smoothing_length: 2.5 * dx,
                material: 0,
            });
        }
    }
    let eos = LinearElastic::new(LinearElasticParams { rho0, K0: 26.7e9 }).unwrap();
    let strength = sph_strength::VonMises::new(sph_strength::VonMisesParams {
        yield_strength: 1.0e12,
        shear_modulus: 22.7e9,
        hardening: None,
    })
    .unwrap();
    let mut sim = Simulation::new(
        p,
        vec![Material::solid("rock", eos, strength)],
        SchemeConfig::default(),
        WendlandC2,
        vec![wall],
        None,
    )
    .unwrap();
    let s = sph_core::glam::DMat3::from_diagonal(sph_core::glam::DVec3::new(1.0e8, -1.0e7, -9.0e7));
    sim.state.stress.iter_mut().for_each(|x| *x = s);
    sim.step(1.0e-9).unwrap();
    let q = &sim.state.particles;
    q.position
        .iter()
        .copied()
        .zip(q.velocity.iter().copied())
        .collect()
}

/// A 1-D column of linear-elastic fluid (ρ0 = 1000 kg/m³, K = 1 GPa) at rest and at the
/// uniform density ρ0 (1 + `strain`), on `wall` at x = 0 and free at its far end: the
/// velocities after one step.
fn column_on(wall: Boundary<sph_core::Dim1>, strain: f64) -> Vec<f64> {
    let (n, dx, rho0) = (40, 1.0e-3, 1000.0);
    let rho = rho0 * (1.0 + strain);
    let mut p = Particles::<sph_core::Dim1>::new();
    for k in 0..n {
        p.push(ParticleInit {
            position: (k as f64 + 0.5) * dx,
            velocity: 0.0,
            mass: rho * dx,
            density: rho,
            specific_energy: 0.0,
            smoothing_length: 2.5 * dx,
            material: 0,
        });
    }
    let eos = LinearElastic::new(LinearElasticParams { rho0, K0: 1.0e9 }).unwrap();
    let mut sim = Simulation::new(
        p,
        vec![Material::fluid("elastic fluid", eos)],
        SchemeConfig::default(),
        WendlandC2,
        vec![wall],
        None,
    )
    .unwrap();
    sim.step(f64::INFINITY).unwrap();
    sim.state.particles.velocity.clone()
}

#[test]
fn contact_wall_pushes_but_does_not_pull() {
    let (wall, contact) = (
        Boundary::Wall {
            point: 0.0,
            normal: 1.0,
        },
        Boundary::Contact {
            point: 0.0,
            normal: 1.0,
        },
    );
    // In tension the mirror wall holds the first particle in place (its ghosts pull it
    // as hard as its real neighbours do), while the contact wall lets go: the first
    // particle then moves off the wall exactly as the free far end moves in.
    let held = column_on(wall, -0.01);
    let released = column_on(contact, -0.01);
    let far_end = *released.last().unwrap();
    println!(
        "tension: wall v0 = {:e}, contact v0 = {:e}, far end {:e} m/s",
        held[0], released[0], far_end
    );
    assert!(far_end < 0.0, "the free end is pulled inward: {far_end}");
    assert!(held[0].abs() < 1e-9 * far_end.abs(), "{}", held[0]);
    assert!(released[0] > 0.0);
    assert!((released[0] + far_end).abs() < 1e-9 * far_end.abs());
    // In compression both walls push alike, to round-off (the contact's ghost pairs
    // are summed apart from the others, so the additions come in another order).
    let (mirror, pushed) = (column_on(wall, 0.01), column_on(contact, 0.01));
    let scale = mirror.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    assert!(scale > 0.0);
    for (a, b) in mirror.iter().zip(&pushed) {
        assert!((a - b).abs() <= 1e-13 * scale, "{a} against {b}");
    }
}

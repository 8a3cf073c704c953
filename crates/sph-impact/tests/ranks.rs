//! A step shared out among ranks (`Simulation::step_over`, solver/ranks.rs) gives the bits
//! of a single process: each rank sums its blocks of the pair passes as one process
//! would, and the ranks gather each other's rows. Here the ranks are threads of the test,
//! exchanging through shared memory as MPI ranks do through messages; the MPI transport
//! itself is tested by tests/mpi.rs (the `mpi` feature).

mod common;

use common::{scene_text, with_solver_keys};
use sph_core::{Dimension, Vector};
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::{Gathered, Ranks, Simulation};
use sph_kernel::KernelChoice;
use std::sync::{Barrier, Mutex};

/// What the ranks of one run share: a barrier and a slot per rank.
struct Hub {
    barrier: Barrier,
    slots: Mutex<Vec<Vec<f64>>>,
    bytes: Mutex<Vec<u8>>,
}

impl Hub {
    fn new(size: usize) -> Self {
        Hub {
            barrier: Barrier::new(size),
            slots: Mutex::new(vec![Vec::new(); size]),
            bytes: Mutex::new(Vec::new()),
        }
    }
}

/// Rank `rank` of the ranks that share `hub`.
struct ThreadRank<'a> {
    rank: usize,
    size: usize,
    hub: &'a Hub,
}

impl Ranks for ThreadRank<'_> {
    fn rank(&self) -> usize {
        self.rank
    }
    fn size(&self) -> usize {
        self.size
    }
    fn all_gather(&self, own: Vec<f64>) -> Gathered {
        self.hub.slots.lock().unwrap()[self.rank] = own;
        self.hub.barrier.wait();
        let all = {
            let slots = self.hub.slots.lock().unwrap();
            Gathered {
                values: slots.concat(),
                lengths: slots.iter().map(Vec::len).collect(),
            }
        };
        // Nobody writes the next round's slot before everyone has read this one.
        self.hub.barrier.wait();
        all
    }
    fn broadcast(&self, data: Vec<u8>) -> Vec<u8> {
        if self.rank == 0 {
            *self.hub.bytes.lock().unwrap() = data;
        }
        self.hub.barrier.wait();
        let all = self.hub.bytes.lock().unwrap().clone();
        self.hub.barrier.wait();
        all
    }
}

/// The fields a step changes, as bits.
fn bits<D: Dimension>(s: &Simulation<D, KernelChoice>) -> Vec<u64> {
    let p = &s.state.particles;
    let mut out: Vec<u64> = Vec::new();
    for k in 0..p.len() {
        out.extend(p.position[k].to_array3().map(f64::to_bits));
        out.extend(p.velocity[k].to_array3().map(f64::to_bits));
        out.push(p.density[k].to_bits());
        out.push(p.specific_energy[k].to_bits());
        out.push(p.smoothing_length[k].to_bits());
    }
    out.extend(
        s.state
            .stress
            .iter()
            .flat_map(|m| m.to_cols_array())
            .map(f64::to_bits),
    );
    out.extend(s.state.damage_state.iter().map(|d| d.to_bits()));
    out.push(s.state.time.to_bits());
    out
}

/// Steps `serial` and, on `size` ranks, each rank's simulation from `build`, `steps`
/// times, and checks that every rank ends with the serial bits.
fn compare<D: Dimension>(
    serial: &mut Simulation<D, KernelChoice>,
    build: &(dyn Fn() -> Simulation<D, KernelChoice> + Sync),
    size: usize,
    steps: usize,
) -> usize {
    for _ in 0..steps {
        serial.step(f64::INFINITY).unwrap();
    }
    let expected = bits(serial);
    let hub = Hub::new(size);
    let ends: Vec<Vec<u64>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..size)
            .map(|rank| {
                let hub = &hub;
                scope.spawn(move || {
                    let mut sim = build();
                    let ranks = ThreadRank { rank, size, hub };
                    for _ in 0..steps {
                        sim.step_over(f64::INFINITY, &ranks).unwrap();
                    }
                    bits(&sim)
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (rank, end) in ends.iter().enumerate() {
        assert!(*end == expected, "rank {rank} of {size} differs");
    }
    serial.state.particles.len()
}

/// Builds `text` once for the serial run and once per rank, and compares them.
fn check(text: &str, size: usize, steps: usize) -> usize {
    let scene = Scene::from_toml_str(text, "scene.toml").unwrap();
    macro_rules! geometry {
        ($variant:ident) => {{
            let build = || match scene.build().unwrap().simulation {
                SceneSimulation::$variant(s) => s,
                _ => unreachable!("one scene builds one geometry"),
            };
            compare(&mut build(), &build, size, steps)
        }};
    }
    match scene.build().unwrap().simulation {
        SceneSimulation::ThreeD(_) => geometry!(ThreeD),
        SceneSimulation::Rz(_) => geometry!(Rz),
        SceneSimulation::Plane(_) => geometry!(Plane),
        SceneSimulation::Line(_) => geometry!(Line),
    }
}

#[test]
fn ranks_give_the_bits_of_one_process_in_every_geometry() {
    for name in [
        "smoke.toml",
        "smoke_rz.toml",
        "smoke_plane.toml",
        "flyer_plate_1d.toml",
    ] {
        let text = scene_text(name);
        for size in [2, 3] {
            let n = check(&text, size, 6);
            println!("{name}: {n} particles, {size} ranks: the same bits");
        }
    }
    // Mirror planes: the pairs of a rank's rows read the gradients of the ghosts'
    // sources, which may belong to another rank (its halo).
    let n = check(&common::quarter_smoke_text(), 3, 6);
    println!("the quarter smoke scene: {n} particles, 3 ranks: the same bits");
}

/// A periodic pair of faces: the ghosts by the face x = 0 copy particles by x = 1, which
/// another rank owns and no row of this rank lists, so a rank's halo must hold the
/// ghosts' sources (solver/ranks/halo.rs).
#[test]
fn ranks_give_the_bits_of_one_process_across_a_periodic_boundary() {
    use sph_impact::{Material, SchemeConfig};
    let build = || {
        let (p, boundaries) = common::gas_blob(true);
        let gas = sph_eos::IdealGas::with_gamma(1.4).unwrap();
        Simulation::new(
            p,
            vec![Material::fluid("gas", gas)],
            SchemeConfig::default(),
            KernelChoice::WendlandC2,
            boundaries,
            None,
        )
        .unwrap()
    };
    for size in [2, 3] {
        compare(&mut build(), &build, size, 6);
    }
}

/// The personalised exchange (`Ranks::exchange`, here its default through the
/// all-gather): each rank receives exactly what each rank addressed to it, empty
/// messages included.
#[test]
fn an_exchange_delivers_each_message_to_its_rank() {
    let size = 4;
    let hub = Hub::new(size);
    // Rank r sends rank k the values 100 r + k, (r + k) % 3 times.
    let message = |r: usize, k: usize| vec![(100 * r + k) as f64; (r + k) % 3];
    std::thread::scope(|scope| {
        for rank in 0..size {
            let hub = &hub;
            scope.spawn(move || {
                let ranks = ThreadRank { rank, size, hub };
                for _ in 0..2 {
                    let got = ranks.exchange((0..size).map(|k| message(rank, k)).collect());
                    let expected: Vec<Vec<f64>> = (0..size).map(|r| message(r, rank)).collect();
                    assert_eq!(got, expected, "rank {rank}");
                }
            });
        }
    });
}

/// The schemes whose pair passes gather more: the FSISPH preset (gradient corrections
/// M⁻ᵀ, energy diffusion, decoupling), ASPH (tensor supports), one search per step.
#[test]
fn ranks_give_the_bits_of_one_process_with_every_pass_option() {
    for (name, keys) in [
        ("smoke.toml", "preset = \"fsisph\"\n"),
        ("smoke_rz.toml", "preset = \"fsisph\"\n"),
        (
            "smoke_rz.toml",
            "smoothing = { kind = \"asph\", max_aspect = 4.0 }\n",
        ),
        ("smoke.toml", "neighbour_search = \"each-step\"\n"),
        ("smoke_rz.toml", "neighbour_search = \"verlet\"\n"),
    ] {
        let text = with_solver_keys(&scene_text(name), keys);
        check(&text, 3, 6);
    }
}

//! Throughput on the scenes users run: the study's 3.9 km/s impact as the bundled 3-D
//! scene at A_res 1 mm (`examples/scenes/basalt_3.9kms.toml`, `--resolution-scale 0.5`)
//! and as the RZ scene at the study's 0.5 mm (`basalt_3.9kms_rz.toml`), full solid physics
//! as bundled. For each, on 1 and 2 threads: a fixed number of RK2 steps after a warm-up,
//! particle-steps per second in all and per core, the share of each solver phase (the
//! neighbour search's among them) and the searches made in the timed steps; then, on the state reached, the neighbours per
//! particle, the candidates the cell list tested per neighbour found, the pair passes'
//! evaluations per pair, pairs across blocks and particles of later blocks listed
//! (`sph_impact::solver::pair_evaluations`), and the memory per particle (peak resident
//! growth and the live heap's peak during the steps). "neighbours" includes a Verlet
//! list's test of whether it holds (`PhaseTimes::neighbours`).
//!
//! ```text
//! cargo bench -p sph-benches --bench scenes                 # both scenes
//! cargo bench -p sph-benches --bench scenes -- rz           # one of them: 3d or rz
//! cargo bench -p sph-benches --bench scenes -- 3d --quick   # 3-D at A_res 2 mm, 2 steps
//! cargo bench -p sph-benches --bench scenes -- 3d --search  # ten searches, no steps
//! cargo bench -p sph-benches --bench scenes -- rz --each-stage # a search at each stage
//! cargo bench -p sph-benches --bench scenes -- rz --each-step # one search per RK2 step
//! cargo bench -p sph-benches --bench scenes -- rz --verlet    # a Verlet list
//! cargo bench -p sph-benches --bench scenes -- 3d --halo    # domains' ghost layers, no steps
//! cargo bench -p sph-benches --bench scenes -- 3d --halo --study-resolution # at A_res 0.5 mm
//! cargo bench -p sph-benches --bench scenes -- rz --allocator-defaults # glibc's own settings
//! ```
//!
//! The allocator is set as the `sph-impact` program sets it (freed memory kept for the
//! next stage, `sph_benches::keep_freed_memory`); `--allocator-defaults` leaves glibc's
//! defaults, to measure what that gives.
//!
//! `--each-stage`, `--each-step` and `--verlet` set `[solver] neighbour_search =
//! "each-stage"`, `"each-step"` or `"verlet"` (its default skin) over the scene's own
//! setting (`SchemeConfig::neighbour_search`); without them each scene runs as bundled,
//! with its Verlet list.

use sph_benches::{Counting, LIVE, PEAK, peak_rss};
use sph_core::{CellList, NeighborSearch, ScalarSupport, regions_of_rows};
use sph_impact::Simulation;
use sph_impact::scene::{Scene, SceneSimulation};
use sph_impact::solver::{NeighbourSearch, shares};
use sph_kernel::KernelChoice;
use std::path::Path;
use std::sync::atomic::Ordering;
use std::time::Instant;

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// One scene to measure.
struct Case {
    /// "3-D" or "RZ".
    label: &'static str,
    file: &'static str,
    resolution_scale: f64,
    warm_up: usize,
    steps: usize,
    /// When the neighbour list is built, over the scene's own setting (`None`: as
    /// bundled).
    search: Option<NeighbourSearch>,
}

/// What one thread count measured.
struct Measured {
    particles: usize,
    rate: f64,
    phases: String,
    neighbour_share: f64,
}

/// Steps `sim` `warm_up` then `steps` times and measures the second part.
fn measure<D: sph_core::Dimension>(sim: &mut Simulation<D, KernelChoice>, case: &Case) -> Measured {
    for _ in 0..case.warm_up {
        sim.step(f64::INFINITY).expect("warm-up step");
    }
    sim.timings = Default::default();
    let n = sim.state.particles.len();
    let t0 = Instant::now();
    for _ in 0..case.steps {
        sim.step(f64::INFINITY).expect("step");
    }
    let wall = t0.elapsed().as_secs_f64();
    let t = sim.timings;
    let tot = t.total();
    let share = |x: f64| 100.0 * x / tot;
    Measured {
        particles: n,
        rate: (n * case.steps) as f64 / wall,
        phases: format!(
            "neighbours {:.1} %, pair set-up {:.1} %, EOS {:.1} %, gradients {:.1} %, pair loop {:.1} %, integration {:.1} %; {} searches",
            share(t.neighbours),
            share(t.setup),
            share(t.eos),
            share(t.gradients),
            share(t.pairs),
            share(t.integration),
            t.searches
        ),
        neighbour_share: share(t.neighbours),
    }
}

/// Neighbours per particle and candidates per neighbour of the cell list on `sim`'s
/// particles with their support radii; prints each grid level's share of the candidates,
/// and the time of one search with cells of 1, 1/2, 1/3 and 1/4 of each level's largest
/// radius (the default is [`sph_core::DEFAULT_CELL_FRACTION`]).
fn search_cost<D: sph_core::Dimension>(sim: &Simulation<D, KernelChoice>) -> (f64, f64) {
    let p = &sim.state.particles;
    let support = ScalarSupport::new(&p.smoothing_length).expect("radii");
    for fraction in [1.0, 0.5, 1.0 / 3.0, 0.25] {
        let mut grid = CellList::new().with_cell_fraction(fraction);
        let t0 = Instant::now();
        let list = grid.neighbors(&p.position, &support).expect("search");
        let wall = t0.elapsed().as_secs_f64();
        println!(
            "  cells of {fraction:.2} × the level's largest radius: one search {wall:.3} s, \
             {:.2} candidates per neighbour",
            grid.candidates() as f64 / list.total_pairs() as f64
        );
    }
    let mut grid = CellList::new();
    let list = grid.neighbors(&p.position, &support).expect("search");
    let pairs = list.total_pairs() as f64;
    for (k, level) in grid.level_stats().iter().enumerate() {
        println!(
            "  grid level {k}: cell {:.3e} m, {} particles, {}, {:.1} % of the candidates",
            level.cell_size,
            level.particles,
            if level.dense { "dense" } else { "sparse" },
            100.0 * level.candidates as f64 / grid.candidates() as f64
        );
    }
    // How the pair passes would evaluate these pairs: once inside a block of rows, from
    // each side across blocks (sph_impact::solver::pair_evaluations).
    let e = sph_impact::solver::pair_evaluations(&list, p.len());
    println!(
        "  pair evaluations per pair {:.3}: {:.1} % of the listed pairs cross blocks of {} rows, \
         whose rows list {:.3} particles of later blocks per particle",
        e.per_pair(),
        100.0 * e.across_share(),
        e.block_rows,
        e.later as f64 / p.len() as f64
    );
    (pairs / p.len() as f64, grid.candidates() as f64 / pairs)
}

/// The case's bundled scene, read from examples/scenes.
fn scene_of(case: &Case) -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/scenes")
        .join(case.file);
    let mut scene = Scene::from_toml_file(&path).expect("scene");
    if let Some(search) = case.search {
        scene.solver.neighbour_search = Some(search);
    }
    scene
}

fn run_case(case: &Case) {
    let scene = scene_of(case);
    // The bundled scenes place at A_res = 0.5 mm (the study's) at scale 1.
    println!(
        "\n{} basalt impact, 3.9 km/s, A_res {} mm ({}, --resolution-scale {}): {} RK2 steps \
         after {} warm-up steps, neighbours searched {}",
        case.label,
        0.5 / case.resolution_scale,
        case.file,
        case.resolution_scale,
        case.steps,
        case.warm_up,
        match scene.solver.neighbour_search {
            None | Some(NeighbourSearch::EachStage) => "at each stage",
            Some(NeighbourSearch::EachStep) => "once per step",
            Some(NeighbourSearch::Verlet) => "into a Verlet list",
        }
    );
    let mut rates = Vec::new();
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| {
            let rss0 = peak_rss();
            let heap0 = LIVE.load(Ordering::Relaxed);
            let built = scene.build_scaled(case.resolution_scale).expect("build");
            PEAK.store(LIVE.load(Ordering::Relaxed), Ordering::Relaxed);
            let (m, cost) = match built.simulation {
                SceneSimulation::ThreeD(mut sim) => {
                    let m = measure(&mut sim, case);
                    (m, search_cost(&sim))
                }
                SceneSimulation::Rz(mut sim) | SceneSimulation::Plane(mut sim) => {
                    let m = measure(&mut sim, case);
                    (m, search_cost(&sim))
                }
                SceneSimulation::Line(mut sim) => {
                    let m = measure(&mut sim, case);
                    (m, search_cost(&sim))
                }
            };
            let n = m.particles as f64;
            println!(
                "{threads} thread(s): {} particles, {:.3e} particle-steps/s ({:.3e} per core); {}",
                m.particles,
                m.rate,
                m.rate / threads as f64,
                m.phases
            );
            if threads == 1 {
                println!(
                    "  neighbours per particle {:.1}, candidates tested per neighbour {:.2}",
                    cost.0, cost.1
                );
                // The resident peak only grows past an earlier, larger case's.
                let rss = peak_rss() - rss0;
                println!(
                    "  memory per particle: {} peak resident growth (VmHWM, set-up \
                     included), {:.0} bytes live-heap peak during the steps",
                    if rss > 0.0 {
                        format!("{:.0} bytes", rss / n)
                    } else {
                        "no".to_owned()
                    },
                    (PEAK.load(Ordering::Relaxed).saturating_sub(heap0)) as f64 / n
                );
            }
            rates.push((m.rate, m.neighbour_share));
        });
    }
    if let [(one, _), (two, _)] = rates[..] {
        println!("  2 threads / 1 thread: {:.2}×", two / one);
    }
}

/// Builds the case's scene and times ten neighbour searches on its initial particles
/// (for profiling the search alone).
fn search_only(case: &Case) {
    let built = scene_of(case)
        .build_scaled(case.resolution_scale)
        .expect("build");
    let SceneSimulation::ThreeD(sim) = built.simulation else {
        println!("--search times the 3-D scene only");
        return;
    };
    let p = &sim.state.particles;
    let support = ScalarSupport::new(&p.smoothing_length).expect("radii");
    let mut grid = CellList::new();
    let t0 = Instant::now();
    for _ in 0..10 {
        grid.neighbors(&p.position, &support).expect("search");
    }
    let whole = t0.elapsed().as_secs_f64() / 10.0;
    println!("{} particles: one search {whole:.3} s", p.len());
    // A rank's search over MPI: the rows of each of N equal contiguous ranges and the
    // particles that pair with them (`CellList::neighbors_of_rows`), one search each.
    let n = p.len();
    for domains in [2usize, 8, 64] {
        let times: Vec<f64> = (0..domains)
            .map(|d| {
                let rows = d * n / domains..(d + 1) * n / domains;
                let t0 = Instant::now();
                grid.neighbors_of_rows(&p.position, &support, rows)
                    .expect("search");
                t0.elapsed().as_secs_f64()
            })
            .collect();
        let mean = times.iter().sum::<f64>() / domains as f64;
        let largest = times.iter().cloned().fold(0.0, f64::max);
        println!(
            "  the rows of one of {domains} domains: one search {mean:.4} s mean, {largest:.4} s largest ({:.2} and {:.2} × the whole search / {domains})",
            mean / (whole / domains as f64),
            largest / (whole / domains as f64)
        );
    }
    // A Verlet list's picking (`NeighborList::select_pairs`, once per stage): the pairs
    // within max(h_i, h_j) of the list searched with the scene's skin, by the solver's
    // test (sph-impact's `PairProbe`).
    if let Some(skin) = sim.scheme.skin() {
        let reach: Vec<f64> = p
            .smoothing_length
            .iter()
            .map(|h| h * (1.0 + skin))
            .collect();
        let list = grid
            .neighbors(&p.position, &ScalarSupport::new(&reach).expect("radii"))
            .expect("search");
        let probe: Vec<_> = p
            .position
            .iter()
            .zip(&p.smoothing_length)
            .map(|(&x, &h)| (x, h))
            .collect();
        let keep = |i: usize, j: u32| {
            let ((xi, hi), (xj, hj)) = (probe[i], probe[j as usize]);
            let s = hi.max(hj);
            (xi - xj).length_squared() < s * s
        };
        let t0 = Instant::now();
        let mut selection = list.select_pairs(keep);
        for _ in 1..10 {
            selection = list.select_pairs(keep);
        }
        let one = t0.elapsed().as_secs_f64() / 10.0;
        let pairs = sph_core::Pairs::selected(&list, &selection);
        let picked = (0..p.len()).map(|i| pairs.count(i)).sum::<usize>();
        println!(
            "  skin {skin}: one picking {one:.4} s, {picked} of {} listed pairs",
            list.total_pairs()
        );
    }
    for skin in [1.05, 1.1, 1.2] {
        let h: Vec<f64> = p.smoothing_length.iter().map(|h| h * skin).collect();
        let support = ScalarSupport::new(&h).expect("radii");
        let t0 = Instant::now();
        let mut pairs = 0;
        for _ in 0..10 {
            pairs = grid
                .neighbors(&p.position, &support)
                .expect("search")
                .total_pairs();
        }
        println!(
            "  radii × {skin}: one search {:.3} s, {pairs} pairs",
            t0.elapsed().as_secs_f64() / 10.0
        );
    }
}

/// Builds the case's scene and, on its initial particles, measures what a decomposition
/// into N domains of contiguous Morton-ordered rows (balanced by neighbour count, as the
/// ranks share the pair blocks; docs/mpi.md) would hold as ghost layers: for each domain
/// its halo, the particles of other domains that a row of its own lists as a neighbour.
/// Prints, for N = 2 … 1024, the mean and largest halo against the domain's own rows, the
/// largest domain against n/N and the largest (own + halo) against n/N.
fn halo_sizes<D: sph_core::Dimension>(sim: &Simulation<D, KernelChoice>) {
    let p = &sim.state.particles;
    let support = ScalarSupport::new(&p.smoothing_length).expect("radii");
    let list = CellList::new()
        .neighbors(&p.position, &support)
        .expect("search");
    let n = p.len();
    // A row's cost is its pair count (and one for the row itself).
    let cost: Vec<u64> = (0..n).map(|i| list.count(i) as u64 + 1).collect();
    println!(
        "{n} particles, {:.1} neighbours per particle; domains of contiguous rows:",
        list.mean_count()
    );
    println!(
        "  domains | halo / own, mean | halo / own, largest | largest own × N/n | largest (own + halo) × N/n | sent by the halo rule / halo, mean | largest"
    );
    for domains in [2usize, 4, 8, 16, 32, 64, 128, 256, 512, 1024] {
        // The ranks' rule for the pair blocks, applied to rows (`sph_impact::solver::shares`).
        let mut owner = vec![0; n];
        let ranges = shares(&cost, domains);
        for (d, rows) in ranges.iter().cloned().enumerate() {
            owner[rows].fill(d);
        }
        let mut own = vec![0usize; domains];
        let mut halo = vec![0usize; domains];
        // The domain that last counted particle j (rows of a domain are contiguous).
        let mut counted = vec![usize::MAX; n];
        for i in 0..n {
            let d = owner[i];
            own[d] += 1;
            for j in list.neighbors(i) {
                let j = j as usize;
                if owner[j] != d && counted[j] != d {
                    counted[j] = d;
                    halo[d] += 1;
                }
            }
        }
        let ratio: Vec<f64> = (0..domains)
            .map(|d| halo[d] as f64 / own[d].max(1) as f64)
            .collect();
        let per = n as f64 / domains as f64;
        // What the rule of `sph_core::halo` would send each domain (boxes of runs of its
        // rows, four reaches across, as the partial search uses), against the exact halo.
        let sent: Vec<usize> = ranges
            .iter()
            .map(|own_rows| {
                let regions =
                    regions_of_rows(&p.position, &support, own_rows.clone(), 4.0).expect("regions");
                let before = sph_core::halo(&regions, &p.position, &support, 0..own_rows.start)
                    .expect("halo");
                let after =
                    sph_core::halo(&regions, &p.position, &support, own_rows.end..n).expect("halo");
                before.len() + after.len()
            })
            .collect();
        let excess: Vec<f64> = (0..domains)
            .map(|d| sent[d] as f64 / halo[d].max(1) as f64)
            .collect();
        println!(
            "  {domains} | {:.3} | {:.3} | {:.2} | {:.2} | {:.2} | {:.2}",
            ratio.iter().sum::<f64>() / domains as f64,
            ratio.iter().cloned().fold(0.0, f64::max),
            *own.iter().max().unwrap() as f64 / per,
            (0..domains).map(|d| own[d] + halo[d]).max().unwrap() as f64 / per,
            excess.iter().sum::<f64>() / domains as f64,
            excess.iter().cloned().fold(0.0, f64::max)
        );
    }
}

/// [`halo_sizes`] on the case's initial particles.
fn halo_only(case: &Case) {
    println!(
        "\n{} scene ({}, --resolution-scale {}):",
        case.label, case.file, case.resolution_scale
    );
    let built = scene_of(case)
        .build_scaled(case.resolution_scale)
        .expect("build");
    match built.simulation {
        SceneSimulation::ThreeD(sim) => halo_sizes(&sim),
        SceneSimulation::Rz(sim) | SceneSimulation::Plane(sim) => halo_sizes(&sim),
        SceneSimulation::Line(sim) => halo_sizes(&sim),
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    // The allocator set as the program sets it, unless `--allocator-defaults` asks for
    // glibc's defaults (to measure what the setting gives, docs/performance.md).
    let allocator_defaults = args.iter().any(|a| a == "--allocator-defaults");
    if !allocator_defaults {
        sph_benches::keep_freed_memory();
    }
    let halo = args.iter().any(|a| a == "--halo");
    let quick = args.iter().any(|a| a == "--quick");
    let search = args.iter().any(|a| a == "--search");
    let search_mode = if args.iter().any(|a| a == "--verlet") {
        Some(NeighbourSearch::Verlet)
    } else if args.iter().any(|a| a == "--each-step") {
        Some(NeighbourSearch::EachStep)
    } else if args.iter().any(|a| a == "--each-stage") {
        Some(NeighbourSearch::EachStage)
    } else {
        None
    };
    // The 3-D scene at the study's own A_res 0.5 mm (1.0 M particles).
    let study = args.iter().any(|a| a == "--study-resolution");
    let want = |name: &str| {
        let picked: Vec<&String> = args.iter().filter(|a| *a == "3d" || *a == "rz").collect();
        picked.is_empty() || picked.iter().any(|a| *a == name)
    };
    let cases = [
        (
            "3d",
            Case {
                label: "3-D",
                file: "basalt_3.9kms.toml",
                resolution_scale: match (quick, study) {
                    (_, true) => 1.0,
                    (true, false) => 0.25,
                    (false, false) => 0.5,
                },
                warm_up: if quick { 1 } else { 2 },
                steps: if quick { 2 } else { 4 },
                search: search_mode,
            },
        ),
        (
            "rz",
            Case {
                label: "RZ",
                file: "basalt_3.9kms_rz.toml",
                resolution_scale: if quick { 0.5 } else { 1.0 },
                warm_up: 20,
                steps: if quick { 50 } else { 400 },
                search: search_mode,
            },
        ),
    ];
    for (name, case) in &cases {
        if want(name) {
            if search {
                search_only(case);
            } else if halo {
                halo_only(case);
            } else {
                run_case(case);
            }
        }
    }
}

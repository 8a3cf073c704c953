//! The halo rule (`sph_core::halo`) misses no pair of the brute-force search, whatever
//! the domains, blocks and radii, and sends little more than the pairs need.

use proptest::prelude::*;
use rand::SeedableRng;
use rand_pcg::Pcg64Mcg;
use sph_core::glam::{DMat2, DVec2, DVec3};
use sph_core::{
    NeighborList, PairCriterion, ScalarSupport, TensorSupport, Vector, brute_force_neighbors, halo,
    morton_order, regions_of_rows,
};

/// The domains: contiguous ranges of the n rows cut at `cuts` (fractions of n).
fn domains(n: usize, cuts: &[f64]) -> Vec<std::ops::Range<usize>> {
    let mut at: Vec<usize> = cuts.iter().map(|c| (c * n as f64) as usize).collect();
    at.push(0);
    at.push(n);
    at.sort_unstable();
    at.windows(2).map(|w| w[0]..w[1]).collect()
}

/// For each domain: (the halo the other domains' owners send it, the exact halo from
/// the list: the particles outside it that pair with one of its rows).
fn halos<V: Vector, C: PairCriterion<V>>(
    x: &[V],
    crit: &C,
    list: &NeighborList,
    domains: &[std::ops::Range<usize>],
    size: f64,
) -> Vec<(Vec<u32>, Vec<u32>)> {
    domains
        .iter()
        .map(|own| {
            let regions = regions_of_rows(x, crit, own.clone(), size).unwrap();
            let mut sent = Vec::new();
            for other in domains.iter().filter(|d| *d != own) {
                sent.extend(halo(&regions, x, crit, other.clone()).unwrap());
            }
            sent.sort_unstable();
            let mut exact: Vec<u32> = own
                .clone()
                .flat_map(|i| list.neighbors(i))
                .filter(|&j| !own.contains(&(j as usize)))
                .collect();
            exact.sort_unstable();
            exact.dedup();
            (sent, exact)
        })
        .collect()
}

/// Every pair across domains is in the receiving domain's halo, and a halo holds no
/// particle of its own domain.
fn complete<V: Vector, C: PairCriterion<V>>(
    x: &[V],
    crit: &C,
    cuts: &[f64],
    size: f64,
) -> Result<(), TestCaseError> {
    let list = brute_force_neighbors(x, crit).unwrap();
    let doms = domains(x.len(), cuts);
    for (own, (sent, exact)) in doms.iter().zip(halos(x, crit, &list, &doms, size)) {
        for j in &exact {
            prop_assert!(
                sent.binary_search(j).is_ok(),
                "particle {} pairs with domain {:?} but is not sent to it",
                j,
                own
            );
        }
        prop_assert!(sent.iter().all(|&j| !own.contains(&(j as usize))));
    }
    Ok(())
}

/// [`complete`] with spherical supports of `scale` × 2^e over the octaves `exps`.
fn complete_scalar<V: Vector>(
    x: &[V],
    scale: f64,
    exps: &[f64],
    cuts: &[f64],
    size: f64,
) -> Result<(), TestCaseError> {
    let h: Vec<f64> = (0..x.len())
        .map(|i| scale * 2f64.powf(exps[i % exps.len()]))
        .collect();
    complete(x, &ScalarSupport::new(&h).unwrap(), cuts, size)
}

fn cloud<V: Vector>(raw: &[(f64, f64, f64)]) -> Vec<V> {
    let mut x: Vec<V> = raw
        .iter()
        .map(|&(a, b, c)| V::from_fn(|k| [a, b, c][k]))
        .collect();
    if let Ok(p) = morton_order(&x) {
        p.apply("position", &mut x).unwrap();
    }
    x
}

fn pt() -> impl Strategy<Value = (f64, f64, f64)> {
    (0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn complete_1d(raw in prop::collection::vec(pt(), 1..200), exps in prop::collection::vec(-7.0f64..0.0, 1..8),
                   cuts in prop::collection::vec(0.0f64..1.0, 0..6), size in 0.1f64..10.0) {
        complete_scalar(&cloud::<f64>(&raw), 0.3, &exps, &cuts, size)?;
    }

    #[test]
    fn complete_3d(raw in prop::collection::vec(pt(), 1..300), exps in prop::collection::vec(-7.0f64..0.0, 1..8),
                   cuts in prop::collection::vec(0.0f64..1.0, 0..8), size in 0.1f64..10.0) {
        complete_scalar(&cloud::<DVec3>(&raw), 0.4, &exps, &cuts, size)?;
    }

    /// ASPH ellipses: the reach is the largest semi-axis.
    #[test]
    fn complete_asph_2d(raw in prop::collection::vec(pt(), 1..200), ax in 3.0f64..30.0, angle in 0.0f64..3.2,
                        cuts in prop::collection::vec(0.0f64..1.0, 0..6), size in 0.1f64..10.0) {
        let x = cloud::<DVec2>(&raw);
        let rot = DMat2::from_angle(angle);
        let h: Vec<DMat2> = (0..x.len()).map(|i| {
            let s = 1.0 + (i % 3) as f64;
            rot * DMat2::from_diagonal(DVec2::new(ax * s, 5.0)) * rot.transpose()
        }).collect();
        complete(&x, &TensorSupport::new(&h).unwrap(), &cuts, size)?;
    }
}

/// On a lattice of Morton-ordered box-shaped domains the rule is exact (the nearest
/// point of a lattice-aligned box to a lattice point is a lattice point); on a cloud with
/// radii over three octaves it sends a margin: 1.42 times the exact halo with boxes of
/// 4 reaches, 1.94 times with one box per domain.
#[test]
fn excess_on_a_lattice_and_a_cloud() {
    let measure = |raw: &[(f64, f64, f64)], h: &dyn Fn(usize) -> f64| {
        let x = cloud::<DVec3>(raw);
        let h: Vec<f64> = (0..x.len()).map(h).collect();
        let crit = ScalarSupport::new(&h).unwrap();
        let list = brute_force_neighbors(&x, &crit).unwrap();
        let doms = domains(x.len(), &[0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875]);
        let ratio = |size: f64| {
            let (sent, exact) = halos(&x, &crit, &list, &doms, size)
                .into_iter()
                .fold((0, 0), |(s, e), (a, b)| (s + a.len(), e + b.len()));
            sent as f64 / exact as f64
        };
        (ratio(4.0), ratio(1e300))
    };
    // 16³ lattice points of spacing 1, reach 2.5: eight 8³ cubes.
    let side = 16;
    let lattice: Vec<(f64, f64, f64)> = (0..side * side * side)
        .map(|i| {
            let c = |k: usize| ((i / k) % side) as f64;
            (c(1), c(side), c(side * side))
        })
        .collect();
    let (fine, whole) = measure(&lattice, &|_| 2.5);
    println!(
        "lattice: halo sent / exact: boxes of 4 reaches {fine:.3}, one box per domain {whole:.3}"
    );
    assert_eq!((fine, whole), (1.0, 1.0));
    // 4 096 points of a fixed pseudo-random cloud in the unit cube, reach 0.05–0.2.
    let mut rng = Pcg64Mcg::seed_from_u64(12345);
    let mut next = || rng.random::<f64>();
    let raw: Vec<(f64, f64, f64)> = (0..4096).map(|_| (next(), next(), next())).collect();
    let (fine, whole) = measure(&raw, &|i| 0.05 * 2f64.powi((i % 3) as i32));
    println!(
        "cloud: halo sent / exact: boxes of 4 reaches {fine:.3}, one box per domain {whole:.3}"
    );
    assert!(fine > 1.0 && fine < whole, "{fine} {whole}");
}

//! The cell list against the O(N²) reference on random clouds.

use proptest::prelude::*;
use sph_core::glam::{DMat2, DMat3, DVec2, DVec3};
use sph_core::{
    CellList, NeighborSearch, ScalarSupport, TensorSupport, Vector, brute_force_neighbors,
};

/// A cloud: a bulk in the unit box, a few coincident copies, a few far outliers.
fn cloud<V: Vector>(raw: &[(f64, f64, f64)], dup: usize, far: usize) -> Vec<V> {
    let mut x: Vec<V> = raw
        .iter()
        .map(|&(a, b, c)| V::from_fn(|k| [a, b, c][k]))
        .collect();
    for k in 0..dup.min(x.len()) {
        x.push(x[k]);
    }
    for k in 0..far {
        x.push(V::from_fn(|d| {
            1.0e4 * (1.0 + k as f64) * if d == 0 { 1.0 } else { -0.5 }
        }));
    }
    x
}

fn radii(n: usize, seed: &[f64]) -> Vec<f64> {
    (0..n).map(|i| seed[i % seed.len()]).collect()
}

fn same_as_brute<V: Vector>(
    x: &[V],
    h: &[f64],
    levels: usize,
    fraction: f64,
) -> Result<(), TestCaseError> {
    let crit = ScalarSupport::new(h).unwrap();
    let fast = CellList::with_max_levels(levels)
        .with_cell_fraction(fraction)
        .neighbors(x, &crit)
        .unwrap();
    let slow = brute_force_neighbors(x, &crit).unwrap();
    prop_assert_eq!(fast, slow);
    Ok(())
}

fn pt() -> impl Strategy<Value = (f64, f64, f64)> {
    (0.0f64..1.0, 0.0f64..1.0, 0.0f64..1.0)
}

/// Cell sizes as a fraction of a level's largest radius, over the allowed range.
fn fraction() -> impl Strategy<Value = f64> {
    prop::sample::select(vec![0.125, 0.3, 0.5, 1.0, 1.7, 4.0])
}

/// The rows `start..end` of a partial search are the full search's; the others empty.
fn partial_rows_match<V: Vector, C: sph_core::PairCriterion<V>>(
    x: &[V],
    crit: &C,
    (a, b): (f64, f64),
) -> Result<(), TestCaseError> {
    let n = x.len();
    let (start, end) = {
        let (p, q) = ((a * n as f64) as usize, (b * n as f64) as usize);
        (p.min(q).min(n), p.max(q).min(n))
    };
    let full = CellList::new().neighbors(x, crit).unwrap();
    let part = CellList::new()
        .neighbors_of_rows(x, crit, start..end)
        .unwrap();
    prop_assert_eq!(part.len(), n);
    for i in 0..n {
        let got: Vec<u32> = part.neighbors(i).collect();
        if (start..end).contains(&i) {
            prop_assert_eq!(got, full.neighbors(i).collect::<Vec<u32>>(), "row {}", i);
        } else {
            prop_assert!(got.is_empty(), "row {} outside {}..{}", i, start, end);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// A rank's search (its rows and the particles that reach them) gives its rows as
    /// the whole search does, with radii over seven octaves.
    #[test]
    fn partial_rows_3d(raw in prop::collection::vec(pt(), 2..300), exps in prop::collection::vec(-7.0f64..0.0, 1..10),
                       a in 0.0f64..1.0, b in 0.0f64..1.0) {
        let hs: Vec<f64> = exps.iter().map(|e| 0.4 * 2f64.powf(*e)).collect();
        let x = cloud::<DVec3>(&raw, 2, 1);
        let h = radii(x.len(), &hs);
        partial_rows_match(&x, &ScalarSupport::new(&h).unwrap(), (a, b))?;
    }

    #[test]
    fn partial_rows_asph_2d(raw in prop::collection::vec(pt(), 2..200), ax in 3.0f64..30.0, angle in 0.0f64..3.2,
                            a in 0.0f64..1.0, b in 0.0f64..1.0) {
        let x = cloud::<DVec2>(&raw, 2, 1);
        let rot = DMat2::from_angle(angle);
        let h: Vec<DMat2> = (0..x.len()).map(|i| {
            let s = 1.0 + (i % 3) as f64;
            rot * DMat2::from_diagonal(DVec2::new(ax * s, 5.0)) * rot.transpose()
        }).collect();
        partial_rows_match(&x, &TensorSupport::new(&h).unwrap(), (a, b))?;
    }

    #[test]
    fn scalar_1d(raw in prop::collection::vec(pt(), 1..300), hs in prop::collection::vec(0.002f64..0.2, 1..8),
                 dup in 0usize..5, far in 0usize..3, levels in 1usize..6, fraction in fraction()) {
        let x = cloud::<f64>(&raw, dup, far);
        same_as_brute(&x, &radii(x.len(), &hs), levels, fraction)?;
    }

    #[test]
    fn scalar_2d(raw in prop::collection::vec(pt(), 1..300), hs in prop::collection::vec(0.01f64..0.3, 1..8),
                 dup in 0usize..5, far in 0usize..3, levels in 1usize..6, fraction in fraction()) {
        let x = cloud::<DVec2>(&raw, dup, far);
        same_as_brute(&x, &radii(x.len(), &hs), levels, fraction)?;
    }

    #[test]
    fn scalar_3d(raw in prop::collection::vec(pt(), 1..300), hs in prop::collection::vec(0.02f64..0.5, 1..8),
                 dup in 0usize..5, far in 0usize..3, levels in 1usize..6, fraction in fraction()) {
        let x = cloud::<DVec3>(&raw, dup, far);
        same_as_brute(&x, &radii(x.len(), &hs), levels, fraction)?;
    }

    #[test]
    fn widely_varying_radii_3d(raw in prop::collection::vec(pt(), 2..300), exps in prop::collection::vec(-7.0f64..0.0, 1..10)) {
        // Radii spanning 2^7: more octaves than levels, so the last level mixes sizes.
        let hs: Vec<f64> = exps.iter().map(|e| 0.4 * 2f64.powf(*e)).collect();
        let x = cloud::<DVec3>(&raw, 2, 1);
        same_as_brute(&x, &radii(x.len(), &hs), 3, 0.5)?;
    }

    #[test]
    fn asph_2d(raw in prop::collection::vec(pt(), 1..200), a in 3.0f64..30.0, b in 3.0f64..30.0, angle in 0.0f64..3.2, dup in 0usize..4, far in 0usize..2) {
        let x = cloud::<DVec2>(&raw, dup, far);
        let rot = DMat2::from_angle(angle);
        let h: Vec<DMat2> = (0..x.len()).map(|i| {
            let s = 1.0 + (i % 3) as f64;
            rot * DMat2::from_diagonal(DVec2::new(a * s, b)) * rot.transpose()
        }).collect();
        let crit = TensorSupport::new(&h).unwrap();
        prop_assert_eq!(CellList::new().neighbors(&x, &crit).unwrap(), brute_force_neighbors(&x, &crit).unwrap());
    }

    #[test]
    fn asph_3d(raw in prop::collection::vec(pt(), 1..200), a in 2.0f64..20.0, b in 2.0f64..20.0, c in 2.0f64..20.0, angle in 0.0f64..3.2, far in 0usize..2) {
        let x = cloud::<DVec3>(&raw, 3, far);
        let rot = DMat3::from_axis_angle(DVec3::new(1.0, 2.0, -1.0).normalize(), angle);
        let h: Vec<DMat3> = (0..x.len()).map(|i| {
            let s = 1.0 + (i % 4) as f64;
            rot * DMat3::from_diagonal(DVec3::new(a, b * s, c)) * rot.transpose()
        }).collect();
        let crit = TensorSupport::new(&h).unwrap();
        prop_assert_eq!(CellList::new().neighbors(&x, &crit).unwrap(), brute_force_neighbors(&x, &crit).unwrap());
    }
}

#[test]
fn lists_are_symmetric_sorted_and_exclude_self() {
    let x: Vec<DVec3> = (0..2000)
        .map(|i| {
            let f = i as f64;
            DVec3::new(
                (f * 0.618).fract(),
                (f * 0.414).fract(),
                (f * 0.732).fract(),
            )
        })
        .collect();
    let h: Vec<f64> = (0..x.len())
        .map(|i| 0.05 + 0.1 * ((i % 7) as f64 / 7.0))
        .collect();
    let list = CellList::new()
        .neighbors(&x, &ScalarSupport::new(&h).unwrap())
        .unwrap();
    for i in 0..x.len() {
        let row: Vec<u32> = list.neighbors(i).collect();
        assert_eq!(row.len(), list.count(i));
        assert!(
            row.windows(2).all(|w| w[0] < w[1]),
            "row {i} not strictly ascending"
        );
        assert!(!row.contains(&(i as u32)));
        for &j in &row {
            assert!(
                list.neighbors(j as usize).any(|k| k == i as u32),
                "{i}->{j} not mutual"
            );
        }
    }
}

#[test]
fn identical_for_one_and_two_threads() {
    let x: Vec<DVec3> = (0..20_000)
        .map(|i| {
            let f = i as f64;
            DVec3::new(
                (f * 0.618_034).fract(),
                (f * 0.414_214).fract(),
                (f * 0.732_051).fract(),
            )
        })
        .collect();
    let h: Vec<f64> = (0..x.len())
        .map(|i| 0.04 + 0.04 * ((i % 5) as f64 / 5.0))
        .collect();
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| {
                CellList::new()
                    .neighbors(&x, &ScalarSupport::new(&h).unwrap())
                    .unwrap()
            })
    };
    assert_eq!(run(1), run(2));
}

#[test]
fn bad_inputs_are_typed_errors() {
    use sph_core::CoreError;
    assert!(matches!(
        ScalarSupport::new(&[1.0, 0.0]),
        Err(CoreError::BadSupportRadius { index: 1, .. })
    ));
    assert!(matches!(
        ScalarSupport::new(&[f64::NAN]),
        Err(CoreError::BadSupportRadius { index: 0, .. })
    ));
    let h = [1.0, 1.0];
    let crit = ScalarSupport::new(&h).unwrap();
    let e = CellList::new()
        .neighbors(&[DVec2::ZERO, DVec2::new(f64::NAN, 0.0)], &crit)
        .unwrap_err();
    assert!(
        matches!(e, CoreError::NonFinitePosition { index: 1, .. }),
        "{e}"
    );
    let e = CellList::new()
        .neighbors(&[DVec2::ZERO], &crit)
        .unwrap_err();
    assert!(matches!(e, CoreError::LengthMismatch { .. }), "{e}");
    // Not positive definite.
    let bad = [DMat2::from_diagonal(DVec2::new(1.0, -1.0))];
    assert!(matches!(
        TensorSupport::new(&bad),
        Err(CoreError::BadSupportTensor { index: 0, .. })
    ));
    // Extent of 1e20 cells.
    let x = [DVec2::ZERO, DVec2::new(1.0e10, 0.0)];
    let tiny = [1e-10, 1e-10];
    let e = CellList::new()
        .neighbors(&x, &ScalarSupport::new(&tiny).unwrap())
        .unwrap_err();
    assert!(matches!(e, CoreError::DomainTooLarge { .. }), "{e}");
}

#[test]
fn tensor_support_accepts_round_off_asymmetry() {
    // Off-diagonal entries of 1e-17 and −1e-17 on a tensor of size 7: symmetric to
    // round-off, must be accepted.
    let h = [DMat2::from_cols(
        DVec2::new(7.0, 1e-17),
        DVec2::new(-1e-17, 7.0),
    )];
    assert!(TensorSupport::new(&h).is_ok());
    let skew = [DMat2::from_cols(
        DVec2::new(7.0, 1e-3),
        DVec2::new(-1e-3, 7.0),
    )];
    assert!(TensorSupport::new(&skew).is_err());
}

#[test]
fn empty_input_gives_empty_list() {
    let x: Vec<DVec3> = Vec::new();
    let list = CellList::new()
        .neighbors(&x, &ScalarSupport::new(&[]).unwrap())
        .unwrap();
    assert!(list.is_empty());
}

#[test]
fn encoded_rows_take_under_two_bytes_per_neighbour_on_a_lattice() {
    // The solver's situation: a 3-D lattice in Morton order, h = 2.5 Δx (≈ 65
    // neighbours). A row is stored as varint gaps, so its size follows how close the
    // neighbours' indices are; 4 bytes per neighbour was the plain u32 list.
    let n = 40;
    let mut x: Vec<DVec3> = (0..n * n * n)
        .map(|k| DVec3::new((k % n) as f64, ((k / n) % n) as f64, (k / (n * n)) as f64))
        .collect();
    let perm = sph_core::morton_order(&x).unwrap();
    perm.apply("position", &mut x).unwrap();
    let h = vec![2.5; x.len()];
    let list = CellList::new()
        .neighbors(&x, &ScalarSupport::new(&h).unwrap())
        .unwrap();
    let pairs = list.total_pairs() as f64;
    let per_neighbour = (list.memory_bytes() as f64 - 4.0 * x.len() as f64) / pairs;
    println!(
        "{} particles, {:.1} neighbours each: {} bytes, {:.2} bytes per neighbour besides the 4-byte row offsets",
        x.len(),
        list.mean_count(),
        list.memory_bytes(),
        per_neighbour
    );
    assert!(per_neighbour < 2.0, "{per_neighbour}");
}

/// The candidates a build tests: at least the pairs it finds, and on a uniform lattice
/// the particles of the cells within each one's radius r: with cells of r, about
/// (3r)³/(4πr³/3) ≈ 6.4 per neighbour; with the default cells of r/2, (2.5r)³/(4πr³/3)
/// ≈ 3.7 (fewer at the lattice's faces, where the spheres are cut).
#[test]
fn candidates_per_neighbour_on_a_lattice() {
    let side = 20;
    let x: Vec<DVec3> = (0..side * side * side)
        .map(|i| {
            DVec3::new(
                (i % side) as f64,
                ((i / side) % side) as f64,
                (i / (side * side)) as f64,
            )
        })
        .collect();
    let h = vec![2.5; x.len()];
    let ratio = |mut grid: CellList| {
        let list = grid
            .neighbors(&x, &ScalarSupport::new(&h).unwrap())
            .unwrap();
        assert!(grid.candidates() >= list.total_pairs() as u64);
        grid.candidates() as f64 / list.total_pairs() as f64
    };
    let whole = ratio(CellList::new().with_cell_fraction(1.0));
    let half = ratio(CellList::new());
    println!("candidates per neighbour: cells of r {whole:.2}, of r/2 {half:.2}");
    assert!((4.5..6.4).contains(&whole), "{whole}");
    assert!((2.5..3.7).contains(&half), "{half}");
}

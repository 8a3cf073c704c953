//! Crater measurement on synthetic particle beds with a known crater: a flat lattice with
//! a paraboloid bowl and a shallow spall annulus removed (docs/diagnostics.md §4).

use proptest::prelude::*;
use sph_diagnostics::{
    CraterOptions, EjectaCriterion, Geometry, ImpactError, ParticleView, crater, ejecta,
};

/// The removed region: a paraboloid bowl of depth `bowl_depth` and radius `bowl_radius`
/// inside a flat-bottomed spall annulus `spall_depth` deep out to `spall_radius` (all in
/// units of the spacing). Returns the floor height (≤ 0) at radius s.
#[derive(Clone, Copy, Debug)]
struct Shape {
    bowl_depth: f64,
    bowl_radius: f64,
    spall_depth: f64,
    spall_radius: f64,
}

/// The bed's crater in most tests: a bowl 8.3 deep and 10.4 wide in a spall zone 2.6
/// deep out to 17.3 spacings.
const STANDARD: Shape = Shape {
    bowl_depth: 8.3,
    bowl_radius: 10.4,
    spall_depth: 2.6,
    spall_radius: 17.3,
};

impl Shape {
    fn floor(&self, s: f64) -> f64 {
        if s >= self.spall_radius {
            return 0.0;
        }
        let bowl = self.bowl_depth * (1.0 - (s / self.bowl_radius).powi(2));
        -bowl.max(self.spall_depth)
    }
}

/// A bed of particles at spacing `dx` (horizontal) and `dz` (vertical), top layer at
/// z = 0 (the surface), 15 spacings deep, with `shape` removed. 3-D: a square lattice
/// out to ±`half` spacings; RZ: columns at r = (i + ½) dx.
fn bed(shape: Shape, geometry: Geometry, half: i32, dx: f64, dz: f64) -> Vec<[f64; 3]> {
    let columns: Vec<(f64, f64)> = match geometry {
        Geometry::ThreeD => (-half..=half)
            .flat_map(|i| (-half..=half).map(move |j| (i as f64 * dx, j as f64 * dx)))
            .collect(),
        Geometry::Axisymmetric => (0..half).map(|i| ((i as f64 + 0.5) * dx, 0.0)).collect(),
        Geometry::Plane => (-half..=half).map(|i| (i as f64 * dx, 0.0)).collect(),
        Geometry::Line => vec![(0.0, 0.0)],
    };
    let layers = (15.0 * dx / dz).round() as i32;
    let mut p = Vec::new();
    for (x, y) in columns {
        let floor = shape.floor(x.hypot(y) / dx) * dx;
        for k in 0..=layers {
            let z = -(k as f64) * dz;
            if z <= floor + 1e-12 * dx {
                p.push([x, y, z]);
            }
        }
    }
    p
}

fn view_arrays(p: &[[f64; 3]], body: u16) -> (Vec<[f64; 3]>, Vec<f64>, Vec<u16>) {
    (
        vec![[0.0; 3]; p.len()],
        vec![1e-6; p.len()],
        vec![body; p.len()],
    )
}

#[test]
fn three_d_bed_recovers_depth_diameter_and_bowl_within_one_bin() {
    let dx = 1e-3;
    let shape = STANDARD;
    let mut p = bed(shape, Geometry::ThreeD, 24, dx, dx);
    let (mut v, mut m, mut b) = view_arrays(&p, 1);
    // A raised rim one spacing high just outside the spall zone.
    for i in -24..=24i32 {
        for j in -24..=24i32 {
            let s = (i as f64).hypot(j as f64);
            if (17.3..19.3).contains(&s) {
                p.push([i as f64 * dx, j as f64 * dx, dx]);
                v.push([0.0; 3]);
                m.push(1e-6);
                b.push(1);
            }
        }
    }
    // Ejecta above the crater (target, rising) and a projectile remnant in the bowl:
    // neither is wall.
    p.push([0.0, 0.0, 2.0 * dx]);
    v.push([0.0, 0.0, 100.0]);
    m.push(1e-6);
    b.push(1);
    p.push([0.0, 0.0, -2.0 * dx]);
    v.push([0.0; 3]);
    m.push(1e-6);
    b.push(0);
    let view = ParticleView::new(&p, &v, &m, &b);
    let criterion = EjectaCriterion::new(&[1], 0.0);
    assert_eq!(ejecta(&view, &criterion).unwrap().count, 1);
    let c = crater(&view, &criterion, &CraterOptions::new(Geometry::ThreeD, dx)).unwrap();

    // Depth: the axis column's top is the first lattice layer below −8.3 dx.
    assert!((c.depth - 8.3 * dx).abs() <= dx, "depth {}", c.depth);
    assert!((c.depth - 9.0 * dx).abs() < 1e-12);
    // Diameter: 2 × 17.3 dx; the edge bin [17, 18) dx mixes floor and rim, so 34 dx.
    assert!(
        (c.diameter - 34.6 * dx).abs() <= dx,
        "diameter {}",
        c.diameter
    );
    assert!((c.diameter - 34.0 * dx).abs() < 1e-12);
    // Bowl: depth ≥ 4.5 dx out to s = 7.49 dx; the bin [7, 8) dx fails, so 14 dx
    // against the paraboloid's 2 × 10.4/√2 = 14.71 dx.
    assert!(
        (c.bowl_diameter - 14.71 * dx).abs() <= dx,
        "bowl {}",
        c.bowl_diameter
    );
    assert!((c.bowl_diameter - 14.0 * dx).abs() < 1e-12);
    assert!((c.rim_height - dx).abs() < 1e-15);
    assert!(c.profile.depth.iter().all(|d| !d.is_nan()));
}

#[test]
fn rz_bed_and_3d_bed_agree() {
    let dx = 5e-4;
    let shape = STANDARD;
    let p = bed(shape, Geometry::Axisymmetric, 30, dx, dx);
    let (v, m, b) = view_arrays(&p, 2);
    let view = ParticleView::new(&p, &v, &m, &b);
    let c = crater(
        &view,
        &EjectaCriterion::new(&[1, 2], 0.0),
        &CraterOptions::new(Geometry::Axisymmetric, dx),
    )
    .unwrap();
    assert!((c.depth - 9.0 * dx).abs() < 1e-12);
    assert!((c.diameter - 34.0 * dx).abs() < 1e-12);
    assert!(
        (c.bowl_diameter - 14.0 * dx).abs() < 1e-12,
        "bowl {}",
        c.bowl_diameter
    );
    assert_eq!(c.rim_height, 0.0);
}

/// In plane strain the same profile is a trench across x, read by |x|: its depth and
/// width as the 3-D bed's within a bin; in 1-D the one column's depth.
#[test]
fn plane_trench_and_line_column_are_recovered() {
    let dx = 5e-4;
    let shape = STANDARD;
    for geometry in [Geometry::Plane, Geometry::Line] {
        let p = bed(shape, geometry, 30, dx, dx);
        let (v, m, b) = view_arrays(&p, 1);
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = crater(
            &view,
            &EjectaCriterion::new(&[1], 0.0),
            &CraterOptions::new(geometry, dx),
        )
        .unwrap();
        assert!(
            (c.depth - 9.0 * dx).abs() < 1e-12,
            "{geometry:?} depth {}",
            c.depth
        );
        if geometry == Geometry::Plane {
            // The columns sit on the bins' lower edges: |x| = 17 dx is inside the spall
            // (17.3 dx), so the bin [17, 18) dx is removed whole and the width reads
            // 2 × 18 dx, against 34.6 dx (one bin on each side at most).
            assert!(
                (c.diameter - 36.0 * dx).abs() < 1e-12,
                "width {}",
                c.diameter
            );
            // Bowl (depth ≥ 4.5 dx): the column at |x| = 7 dx is 5 layers deep (floor
            // −4.54 dx), the one at 8 dx 4 layers, so the bin [7, 8) dx is bowl whole:
            // 16 dx against the paraboloid's 14.71 dx.
            assert!(
                (c.bowl_diameter - 16.0 * dx).abs() < 1e-12,
                "bowl {}",
                c.bowl_diameter
            );
        }
    }
}

#[test]
fn empty_radial_bins_from_coarse_columns_are_bridged() {
    // RZ columns 1.5 bins apart (variable resolution far from the axis): some bins are
    // empty, the crater edge is still found at the last column inside it.
    let dx = 1.0;
    let shape = Shape {
        bowl_depth: 6.0,
        bowl_radius: 6.0,
        spall_depth: 2.0,
        spall_radius: 9.0,
    };
    let mut p = Vec::new();
    for i in 0..12 {
        let r = 0.75 + 1.5 * i as f64;
        for k in 0..15 {
            let z = -(k as f64);
            if z <= shape.floor(r) {
                p.push([r, 0.0, z]);
            }
        }
    }
    let (v, m, b) = view_arrays(&p, 1);
    let view = ParticleView::new(&p, &v, &m, &b);
    let c = crater(
        &view,
        &EjectaCriterion::new(&[1], 0.0),
        &CraterOptions::new(Geometry::Axisymmetric, dx),
    )
    .unwrap();
    assert!(c.profile.depth.iter().any(|d| d.is_nan()));
    // Columns at 0.75, 2.25, …, 8.25 are inside r = 9; the one at 8.25 is in bin [8, 9).
    assert_eq!(c.diameter, 18.0);
    assert_eq!(c.depth, 6.0);
}

#[test]
fn an_untouched_bed_has_no_crater() {
    let dx = 1e-3;
    let flat = Shape {
        bowl_depth: 0.0,
        bowl_radius: 1.0,
        spall_depth: 0.0,
        spall_radius: 0.0,
    };
    let p = bed(flat, Geometry::ThreeD, 6, dx, dx);
    let (v, m, b) = view_arrays(&p, 1);
    let view = ParticleView::new(&p, &v, &m, &b);
    let c = crater(
        &view,
        &EjectaCriterion::new(&[1], 0.0),
        &CraterOptions::new(Geometry::ThreeD, dx),
    )
    .unwrap();
    assert_eq!((c.depth, c.diameter, c.bowl_diameter), (0.0, 0.0, 0.0));
    // With only projectile particles there is no wall: an error, not a panic.
    let (v, m, _) = view_arrays(&p, 1);
    let b0 = vec![0u16; p.len()];
    let view = ParticleView::new(&p, &v, &m, &b0);
    assert!(matches!(
        crater(
            &view,
            &EjectaCriterion::new(&[1], 0.0),
            &CraterOptions::new(Geometry::ThreeD, dx)
        ),
        Err(ImpactError::EmptySelection(_))
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any bowl-in-spall crater in an RZ bed (vertical spacing ¼ bin) is recovered:
    /// depth and crater radius within one bin; the bowl radius within two (its edge
    /// is where a sloping floor crosses a threshold that itself depends on the
    /// measured depth).
    #[test]
    fn rz_craters_are_recovered(
        spall_depth in 1.5f64..3.0,
        extra in 1.5f64..6.0,
        bowl_radius in 6.0f64..14.0,
        spall_gap in 2.0f64..8.0,
    ) {
        let shape = Shape {
            bowl_depth: 2.0 * spall_depth + extra,
            bowl_radius,
            spall_depth,
            spall_radius: bowl_radius + spall_gap,
        };
        let p = bed(shape, Geometry::Axisymmetric, 40, 1.0, 0.25);
        let (v, m, b) = view_arrays(&p, 1);
        let view = ParticleView::new(&p, &v, &m, &b);
        let c = crater(
            &view,
            &EjectaCriterion::new(&[1], 0.0),
            &CraterOptions::new(Geometry::Axisymmetric, 1.0),
        ).unwrap();
        prop_assert!((c.depth - shape.bowl_depth).abs() <= 1.0);
        prop_assert!((c.diameter / 2.0 - shape.spall_radius).abs() <= 1.0);
        let bowl_edge = bowl_radius * (1.0f64 - 0.5).sqrt();
        prop_assert!((c.bowl_diameter / 2.0 - bowl_edge).abs() <= 2.0,
            "bowl radius {} vs {}", c.bowl_diameter / 2.0, bowl_edge);
    }
}

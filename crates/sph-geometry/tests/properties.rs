//! Property tests: invariants of shapes, lattices and the variable-resolution placement
//! over random inputs.

use proptest::prelude::*;
use sph_core::glam::DVec3;
use sph_geometry::{
    Aabb, Cuboid, Cylinder, FibonacciPlacement, Shape, ShapeExt, Sphere, cubic_lattice,
    estimate_volume, hcp_lattice, shells,
};
use std::fmt;

/// A boxed shape that proptest can print (by its description).
struct Body(Box<dyn Shape<DVec3>>);

impl fmt::Debug for Body {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.describe())
    }
}

impl Shape<DVec3> for Body {
    fn contains(&self, p: DVec3) -> bool {
        self.0.contains(p)
    }
    fn bounds(&self) -> Option<Aabb<DVec3>> {
        self.0.bounds()
    }
    fn volume(&self) -> Option<f64> {
        self.0.volume()
    }
    fn describe(&self) -> String {
        self.0.describe()
    }
}

fn vec3(range: f64) -> impl Strategy<Value = DVec3> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = DVec3> {
    vec3(1.0)
        .prop_filter("non-zero", |v| v.length() > 0.1)
        .prop_map(|v| v.normalize())
}

/// A random bounded shape: ball, box or cylinder of size about 1–4.
fn shape() -> impl Strategy<Value = Body> {
    prop_oneof![
        (vec3(2.0), 0.5..2.0f64).prop_map(|(c, r)| Body(Box::new(Sphere::new(c, r).unwrap()))),
        (vec3(2.0), (0.5..2.0f64, 0.5..2.0f64, 0.5..2.0f64)).prop_map(|(c, (a, b, d))| {
            Body(Box::new(
                Cuboid::from_centre(c, DVec3::new(a, b, d)).unwrap(),
            ))
        }),
        (vec3(2.0), unit(), 0.5..2.0f64, 1.0..4.0f64)
            .prop_map(|(c, a, r, l)| Body(Box::new(Cylinder::new(c, a, r, l).unwrap()))),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every point a shape contains lies in its bounds.
    #[test]
    fn bounds_hold_the_shape(s in shape(), pts in prop::collection::vec(vec3(7.0), 200)) {
        let b = s.bounds().unwrap();
        for p in pts {
            if s.contains(p) {
                prop_assert!(b.contains(p), "{p} in {} but outside {b:?}", s.describe());
            }
        }
    }

    /// Midpoint quadrature agrees with the exact volume (boundary-layer error: 60
    /// samples per axis over bounds of aspect ≤ 4 stays well inside 3 %).
    #[test]
    fn estimated_volume_matches_exact(s in shape()) {
        let exact = s.volume().unwrap();
        let est = estimate_volume(&s, 60).unwrap();
        prop_assert!((est / exact - 1.0).abs() < 0.03, "{}: {est} vs {exact}", s.describe());
    }

    /// Boolean combinations follow their truth tables point by point.
    #[test]
    fn csg_truth_tables(a in shape(), b in shape(), pts in prop::collection::vec(vec3(5.0), 100)) {
        let (ia, ib): (Vec<bool>, Vec<bool>) =
            pts.iter().map(|&p| (a.contains(p), b.contains(p))).unzip();
        let u = (&a).union(&b);
        let i = (&a).intersect(&b);
        let d = (&a).subtract(&b);
        for (k, &p) in pts.iter().enumerate() {
            prop_assert_eq!(u.contains(p), ia[k] || ib[k]);
            prop_assert_eq!(i.contains(p), ia[k] && ib[k]);
            prop_assert_eq!(d.contains(p), ia[k] && !ib[k]);
        }
    }

    /// A cylinder's containment is invariant under moving the point with the cylinder.
    #[test]
    fn cylinder_is_rigid(axis in unit(), r in 0.2..2.0f64, l in 0.2..3.0f64,
                         t in 0.0..1.0f64, s in 0.0..1.2f64, phi in 0.0..std::f64::consts::TAU) {
        let c = Cylinder::new(DVec3::new(1.0, -2.0, 0.5), axis, r, l).unwrap();
        let (e1, e2) = axis.any_orthonormal_pair();
        let p = c.base() + axis * (t * l) + (e1 * phi.cos() + e2 * phi.sin()) * (s * r);
        // Points well away from the lateral surface are classified by s alone.
        if (s - 1.0).abs() > 1e-9 {
            prop_assert_eq!(c.contains(p), s < 1.0);
        }
    }

    /// Lattice sites all lie inside the shape, and masses are ρ × site volume.
    #[test]
    fn lattice_points_inside(s in shape(), dx in 0.15..0.4f64, rho in 0.5..5.0f64) {
        let cubic = cubic_lattice(&s, dx, rho).unwrap();
        prop_assert!(cubic.positions.iter().all(|&p| s.contains(p)));
        prop_assert!(cubic.masses.iter().all(|&m| (m - rho * dx.powi(3)).abs() < 1e-12 * m));
        let hcp = hcp_lattice(&s, dx, rho).unwrap();
        prop_assert!(hcp.positions.iter().all(|&p| s.contains(p)));
        let site = dx.powi(3) / 2f64.sqrt();
        prop_assert!(hcp.masses.iter().all(|&m| (m - rho * site).abs() < 1e-12 * m));
    }

    /// The variable-resolution placement keeps only inside points, on their layer
    /// spacings, with the exact total mass after normalisation and a small raw error.
    #[test]
    fn fibonacci_placement_invariants(
        s in shape(),
        frac in (0.0..1.0f64, 0.0..1.0f64, 0.0..1.0f64),
        a_res in 0.15..0.4f64,
        q in 1.0..1.1f64,
        rho in 0.5..5.0f64,
    ) {
        let b = s.bounds().unwrap();
        let origin = b.min + b.extent() * DVec3::new(frac.0, frac.1, frac.2);
        let place = FibonacciPlacement::new(origin, a_res, q, rho).unwrap();
        let (p, layers) = place.place_with_report(&s).unwrap();
        prop_assert!(p.positions.iter().all(|&x| s.contains(x)));
        prop_assert_eq!(p.positions.len(), p.masses.len());
        prop_assert_eq!(p.positions.len(), p.spacing.len());
        prop_assert!(p.masses.iter().all(|&m| m > 0.0 && m.is_finite()));
        let v = s.volume().unwrap();
        prop_assert!((p.total_mass() / (rho * v) - 1.0).abs() < 1e-10);
        // Raw error: quadrature plus volume lost where a ray has no particle, a surface
        // effect of order (spacing × area)/volume. Bodies resolved by at least six
        // spacings (V^(1/3)/A_res ≥ 6) stay within 3 %; coarser ones (a cylinder
        // 3.6 spacings across lost 3.7 %) only within 25 %. The 0.5 % acceptance
        // bounds for the study's bodies are in tests/acceptance.rs.
        let resolved = v.cbrt() / a_res >= 6.0;
        let bound = if resolved { 0.03 } else { 0.25 };
        prop_assert!(p.raw_mass_error.unwrap().abs() < bound, "raw {:?} (resolved: {resolved})", p.raw_mass_error);
        // Each particle sits on its layer's sphere with that layer's spacing.
        let mut i = 0;
        for l in &layers {
            prop_assert!(l.kept <= l.shell.count);
            for k in i..i + l.kept {
                let d = (p.positions[k] - origin).length();
                prop_assert!((d - l.shell.radius).abs() < 1e-12 * (1.0 + d));
                prop_assert_eq!(p.spacing[k], l.shell.spacing);
            }
            i += l.kept;
        }
        prop_assert_eq!(i, p.len());
    }

    /// Layers tile space: contiguous shells one spacing thick, counts by the formula.
    #[test]
    fn layers_tile_space(a in 0.01..1.0f64, q in 1.0..1.2f64, reach in 0.0..50.0f64) {
        let ls = shells(a, q, reach).unwrap();
        let mut inner = 0.0;
        for (k, l) in ls.iter().enumerate() {
            prop_assert_eq!(l.index, k);
            prop_assert_eq!(l.inner, inner);
            prop_assert!((l.outer - l.inner - l.spacing).abs() < 1e-12 * l.outer);
            prop_assert!(l.count >= 3);
            let n = (4.0 * std::f64::consts::PI * l.radius.powi(2) / l.spacing.powi(2)).floor();
            prop_assert_eq!(l.count, n as usize);
            inner = l.outer;
        }
        prop_assert!(ls.last().unwrap().inner <= reach && inner > reach);
    }
}

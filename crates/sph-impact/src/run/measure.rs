//! The impact diagnostics of one instant (docs/diagnostics.md): ejecta, β from the
//! ejecta and from the target, the crater.

use crate::run::arrays::Arrays;
use crate::scene::{DiagnosticSetup, GeometryKind};
use serde::Serialize;
use sph_diagnostics::{
    AxisDepth, AxisField, Crater, CraterOptions, CraterProfile, DensityCut, DiscKernel,
    EjectaCriterion, Geometry, ProjectileDebris, beta_from_ejecta, beta_from_target,
    crater_against, crater_profile, detached_ejecta, ejecta,
};

/// What the diagnostics need that does not change during a run.
pub(crate) struct Measurer {
    /// Target body ids.
    pub targets: Vec<u16>,
    pub setup: DiagnosticSetup,
    /// Projectile mass m_p (kg).
    pub projectile_mass: f64,
    /// Initial axial momentum of everything but the projectile (kg·m/s).
    pub initial_target_momentum_z: f64,
    /// 3-D or RZ (how the distance from the axis is measured).
    pub geometry: GeometryKind,
    /// How many mirror copies each particle's mass in the measured arrays stands for (4
    /// in a 3-D quarter model, else 1): the `copies` the arrays were made with
    /// (`Arrays::of`).
    pub copies: f64,
    /// The untouched target's crater profile at t = 0, which later profiles are read
    /// against ([`Measurer::calibrate`]); `None` before calibration.
    pub reference: Option<CraterProfile>,
    /// Reference density of the (first) target's material (kg/m³), for the rubble cut.
    pub target_density: f64,
    /// The axis depth against the t = 0 field ([`Measurer::calibrate`]); `None` before
    /// calibration or when inactive.
    pub axis: Option<AxisDepth>,
}

/// β and the ejecta at one instant.
#[derive(Clone, Copy, Debug, Default, Serialize)]
pub(crate) struct BetaMeasure {
    pub beta: f64,
    pub beta_target: f64,
    /// β as a ballistic pendulum sees it: the target's momentum with escaping projectile
    /// debris left out, 1 + (P_ej + P_esc)/P_imp (docs/diagnostics.md §3).
    pub beta_pendulum: f64,
    pub ejecta_mass: f64,
    pub ejecta_momentum_z: f64,
}

impl Measurer {
    /// True when there is a target and an impact speed, so β and the crater are defined.
    pub fn active(&self) -> bool {
        !self.targets.is_empty() && self.setup.impact_speed > 0.0 && self.projectile_mass > 0.0
    }

    pub fn criterion(&self) -> EjectaCriterion<'_> {
        EjectaCriterion::new(&self.targets, self.setup.surface_z)
            .with_tolerance(self.setup.ejecta_tolerance)
    }

    /// β (from the ejecta and from the target) and the ejecta sums; NaN when inactive.
    pub fn beta(&self, a: &Arrays) -> Result<BetaMeasure, sph_diagnostics::ImpactError> {
        if !self.active() {
            return Ok(BetaMeasure {
                beta: f64::NAN,
                beta_target: f64::NAN,
                beta_pendulum: f64::NAN,
                ..Default::default()
            });
        }
        let view = a.view();
        let c = self.criterion();
        let ej = ejecta(&view, &c)?;
        let u = self.setup.impact_speed;
        let from_target = |debris| {
            beta_from_target(
                &view,
                &c,
                self.projectile_mass,
                u,
                self.initial_target_momentum_z,
                debris,
            )
            .map(|b| b.beta)
        };
        Ok(BetaMeasure {
            beta: beta_from_ejecta(ej.momentum_z, self.projectile_mass, u)?,
            beta_target: from_target(ProjectileDebris::WithRemnant)?,
            beta_pendulum: from_target(ProjectileDebris::ExcludeEscaping)?,
            ejecta_mass: ej.mass,
            ejecta_momentum_z: ej.momentum_z,
        })
    }

    /// β from the ejecta that no target particle reaches any more (docs/diagnostics.md
    /// §3.1); NaN when inactive.
    pub fn beta_detached(&self, a: &Arrays) -> Result<f64, sph_diagnostics::ImpactError> {
        if !self.active() {
            return Ok(f64::NAN);
        }
        let free = detached_ejecta(&a.view(), &self.criterion(), &a.support)?;
        beta_from_ejecta(
            free.momentum_z,
            self.projectile_mass,
            self.setup.impact_speed,
        )
    }

    /// The crater options: the setup's bin and depth threshold, each particle covering
    /// its own spacing, the setup's spall damage.
    pub fn crater_options(&self) -> CraterOptions {
        let mut o = CraterOptions::new(self.diagnostic_geometry(), self.setup.crater_bin);
        o.depth_threshold = self.setup.crater_depth_threshold;
        o.footprint = true;
        // A quarter model's particle carries its four mirror copies' mass (`Arrays`).
        o.copies = self.copies;
        o.spall_damage = self.setup.spall_damage;
        o.density_cut = self.setup.rubble_density.map(|f| DensityCut {
            reference_density: self.target_density,
            min_fraction: f,
        });
        o
    }

    /// How the diagnostics measure the distance from the axis.
    fn diagnostic_geometry(&self) -> Geometry {
        match self.geometry {
            GeometryKind::ThreeD | GeometryKind::ThreeDQuarter => Geometry::ThreeD,
            GeometryKind::Rz => Geometry::Axisymmetric,
            GeometryKind::Plane => Geometry::Plane,
            GeometryKind::Line => Geometry::Line,
        }
    }

    /// The target's volume-fraction field about the axis now (averaged over the disc).
    fn axis_field(&self, a: &Arrays) -> Result<AxisField, sph_diagnostics::ImpactError> {
        AxisField::new(
            &a.view(),
            &self.criterion(),
            self.diagnostic_geometry(),
            DiscKernel::new(self.setup.axis_kernel_width, self.setup.axis_disc_radius)?,
        )
    }

    /// Keeps the untouched target's crater profile at t = 0 as the reference the later
    /// profiles are read against, bin by bin. A lattice's top layer sits half a spacing
    /// below the surface and the variable-resolution layers deeper where the particles
    /// are larger; against the reference an untouched bed reads depth 0 at every radius
    /// (docs/diagnostics.md §4.1). (One offset for all bins, their median depth, would
    /// read the tops of deeper layers far from the axis.) Keeps the t = 0 field on the axis as the axis depth's reference (§4.4).
    pub fn calibrate(&mut self, a: &Arrays) -> Result<(), sph_diagnostics::ImpactError> {
        self.axis = None;
        if self.active() {
            // A target that does not reach the axis (an offset or hollow body) has no
            // depth there: NaN, not a failed run.
            let field = self.axis_field(a)?;
            if !field.is_empty() {
                self.axis = Some(AxisDepth::new(field, self.setup.surface_z)?);
            }
        }
        // The profile alone, against the plane: the sizes and the spall are not needed.
        self.reference = if self.active() {
            Some(crater_profile(
                &a.view(),
                &self.criterion(),
                &self.crater_options(),
            )?)
        } else {
            None
        };
        Ok(())
    }

    /// The crater depth on the axis from the volume fraction (m); NaN when inactive or
    /// when the axis is empty down to the bottom of the target.
    pub fn axis_depth(&self, a: &Arrays) -> Result<f64, sph_diagnostics::ImpactError> {
        match &self.axis {
            Some(axis) => axis.depth(&self.axis_field(a)?),
            None => Ok(f64::NAN),
        }
    }

    /// The crater; `None` when inactive.
    pub fn crater(&self, a: &Arrays) -> Result<Option<Crater>, sph_diagnostics::ImpactError> {
        if !self.active() {
            return Ok(None);
        }
        crater_against(
            &a.view(),
            &self.criterion(),
            &self.crater_options(),
            self.reference.as_ref(),
        )
        .map(Some)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn measurer(rubble_density: Option<f64>) -> Measurer {
        Measurer {
            targets: vec![1],
            setup: DiagnosticSetup {
                projectile: 0,
                targets: vec![1],
                surface_z: 0.0,
                impact_speed: 1000.0,
                crater_bin: 1e-3,
                crater_depth_threshold: 1e-3,
                ejecta_tolerance: 0.0,
                ejecta_bin: 0.02,
                spall_damage: None,
                rubble_density,
                axis_kernel_width: 2.5e-3,
                axis_disc_radius: 2.5e-3,
            },
            projectile_mass: 1.0,
            initial_target_momentum_z: 0.0,
            geometry: GeometryKind::Rz,
            copies: 1.0,
            reference: None,
            target_density: 2876.0,
            axis: None,
        }
    }

    /// Target particles (body 1) at rest, undamaged, at `position` with `mass` and
    /// `density`.
    fn at_rest(position: Vec<[f64; 3]>, mass: Vec<f64>, density: Vec<f64>) -> Arrays {
        let n = position.len();
        Arrays {
            position,
            velocity: vec![[0.0; 3]; n],
            mass,
            body: vec![1; n],
            damage: vec![0.0; n],
            density,
            specific_energy: vec![0.0; n],
            support: vec![2.5e-3; n],
        }
    }

    /// A crater 3 mm in radius with its floor at z = −10.5 mm, and above the floor in
    /// each of its bins a dilated ring (0.3 ρ0) at z = −6 mm, below the surface and at
    /// rest, so not ejecta.
    fn crater_with_rubble(m: &Measurer) -> Crater {
        let (mut position, mut density) = (Vec::new(), Vec::new());
        for k in 0..40 {
            let r = (k as f64 + 0.5) * 1e-3;
            let z = if k < 3 { -10.5e-3 } else { -0.5e-3 };
            for z in [z, z - 1e-3] {
                position.push([r, 0.0, z]);
                density.push(2876.0);
            }
        }
        for r in [0.5e-3, 1.5e-3, 2.5e-3] {
            position.push([r, 0.0, -6.0e-3]);
            density.push(0.3 * 2876.0);
        }
        // Rings 1 mm square at the reference density (the rubble: dilated).
        let mass = position
            .iter()
            .map(|p| 2.0 * std::f64::consts::PI * p[0] * 1e-6 * 2876.0)
            .collect();
        m.crater(&at_rest(position, mass, density))
            .unwrap()
            .unwrap()
    }

    /// Two target particles and two projectile particles, one of each above the surface
    /// and rising; the projectile (1 kg at 1 km/s) brought P_imp = 1000 kg·m/s. All
    /// have support radius `h`: the rising target particle is 4 mm from the other one.
    fn target_and_debris_rising(h: f64) -> Arrays {
        Arrays {
            position: vec![
                [1e-3, 0.0, 2e-3],
                [1e-3, 0.0, -2e-3],
                [0.0, 0.0, 3e-3],
                [0.0, 0.0, -1e-3],
            ],
            velocity: vec![
                [0.0, 0.0, 300.0],
                [0.0, 0.0, -1100.0],
                [0.0, 0.0, 50.0],
                [0.0, 0.0, -150.0],
            ],
            mass: vec![1.0, 1.0, 0.4, 0.6],
            body: vec![1, 1, 0, 0],
            damage: vec![0.0; 4],
            density: vec![2876.0; 4],
            specific_energy: vec![0.0; 4],
            support: vec![h; 4],
        }
    }

    #[test]
    fn the_pendulum_counts_escaping_projectile_debris_and_the_ejecta_beta_does_not() {
        let b = measurer(None)
            .beta(&target_and_debris_rising(2.5e-3))
            .unwrap();
        // Target ejecta: 1 kg at 300 m/s.
        assert!((b.beta - 1.3).abs() < 1e-12, "{b:?}");
        // The remnant holds everything else: −1100 + 20 − 90 = −1170 kg·m/s.
        assert!((b.beta_target - 1.17).abs() < 1e-12, "{b:?}");
        // The pendulum leaves out the rising debris above the surface (0.4 kg at 50 m/s):
        // −(−1100 − 90)/1000.
        assert!((b.beta_pendulum - 1.19).abs() < 1e-12, "{b:?}");
    }

    #[test]
    fn the_detached_beta_counts_only_ejecta_out_of_the_targets_reach() {
        // The rising target particle is 4 mm from the one below the surface: out of
        // reach with h = 2.5 mm (all its momentum counts), within it with h = 5 mm (none).
        let m = measurer(None);
        let free = m.beta_detached(&target_and_debris_rising(2.5e-3)).unwrap();
        assert!((free - 1.3).abs() < 1e-12, "{free}");
        let held = m.beta_detached(&target_and_debris_rising(5e-3)).unwrap();
        assert_eq!(held, 1.0);
    }

    #[test]
    fn loose_rubble_does_not_fill_the_crater() {
        let cut = crater_with_rubble(&measurer(Some(0.5)));
        let kept = crater_with_rubble(&measurer(None));
        // With the cut the floor is the rock's; without it the rubble is the floor.
        assert!((cut.depth - 10.5e-3).abs() < 1e-12, "{}", cut.depth);
        assert!((kept.depth - 6.0e-3).abs() < 1e-12, "{}", kept.depth);
        assert!((cut.diameter - 6.0e-3).abs() < 1e-12, "{}", cut.diameter);
    }

    /// Rings of a uniform bed 1 mm apart from radius `r_min` out to 20 mm, 10 mm deep.
    fn bed(r_min: f64) -> Arrays {
        let (mut position, mut mass) = (Vec::new(), Vec::new());
        for i in 0..20 {
            let r = (i as f64 + 0.5) * 1e-3;
            if r < r_min {
                continue;
            }
            for k in 0..10 {
                position.push([r, 0.0, -(k as f64 + 0.5) * 1e-3]);
                mass.push(2.0 * std::f64::consts::PI * r * 1e-6 * 2876.0);
            }
        }
        let density = vec![2876.0; position.len()];
        at_rest(position, mass, density)
    }

    #[test]
    fn the_axis_depth_is_read_against_the_start_and_is_nan_off_the_axis() {
        let mut m = measurer(None);
        m.calibrate(&bed(0.0)).unwrap();
        // The untouched bed reads its own surface, within a tenth of its spacing.
        let d = m.axis_depth(&bed(0.0)).unwrap();
        assert!(d.abs() < 1e-4, "{d}");
        // A target that does not reach the disc's kernel (a hollow cylinder with a 5 mm
        // bore, R + H = 5 mm)
        // calibrates, and its axis depth is NaN rather than a failed run.
        let mut hollow = measurer(None);
        hollow.calibrate(&bed(5e-3)).unwrap();
        assert!(hollow.axis.is_none());
        assert!(hollow.axis_depth(&bed(5e-3)).unwrap().is_nan());
    }

    /// An RZ bed like a variable-resolution target: rings 0.5 mm apart out to 5 mm,
    /// 1 mm out to 10 mm and 2 mm out to 30 mm, 10 layers each, the top layer half a
    /// spacing down and every other layer shifted by half a spacing in r (so a bin
    /// between two top rings holds the top of the layer below). Rings with r < `bowl.0`
    /// and z > −`bowl.1` are left out.
    fn graded_bed(bowl: (f64, f64)) -> Arrays {
        let (mut position, mut mass) = (Vec::new(), Vec::new());
        for (from, to, d) in [
            (0.0, 5e-3, 0.5e-3),
            (5e-3, 10e-3, 1e-3),
            (10e-3, 30e-3, 2e-3),
        ] {
            for k in 0..10 {
                let z = -(k as f64 + 0.5) * d;
                let mut r = from + if k % 2 == 0 { 0.5 } else { 1.0 } * d;
                while r < to {
                    if !(r < bowl.0 && z > -bowl.1) {
                        position.push([r, 0.0, z]);
                        mass.push(2.0 * std::f64::consts::PI * r * d * d * 2876.0);
                    }
                    r += d;
                }
            }
        }
        let density = vec![2876.0; position.len()];
        at_rest(position, mass, density)
    }

    #[test]
    fn a_graded_bed_reads_no_crater_untouched_and_its_bowl_when_carved() {
        let mut m = measurer(None);
        m.setup.crater_bin = 0.5e-3;
        m.setup.crater_depth_threshold = 0.5e-3;
        let untouched = graded_bed((0.0, 0.0));
        // Against the plane the untouched bed reads its top layer's depth, half the
        // local spacing: 1 mm where the rings are 2 mm apart.
        let plain = m.crater(&untouched).unwrap().unwrap();
        let spread = plain.profile.depth.iter().fold(0.0f64, |a, d| a.max(*d));
        assert!(spread > 0.9e-3, "{spread}");
        m.calibrate(&untouched).unwrap();
        let c = m.crater(&untouched).unwrap().unwrap();
        assert!(c.profile.depth.iter().all(|d| d.abs() < 1e-15), "{c:?}");
        assert_eq!((c.depth, c.diameter), (0.0, 0.0));
        // A bowl 4 mm deep whose edge falls between the rings at r = 3.0 and 3.25 mm
        // (a ring straddling the edge would cover half a spacing of the bowl): its
        // floor is the layer at −4.25 mm, the untouched top −0.25 mm.
        let c = m.crater(&graded_bed((3.1e-3, 4e-3))).unwrap().unwrap();
        assert!((c.depth - 4.0e-3).abs() < 1e-12, "{}", c.depth);
        assert!((c.diameter - 6.0e-3).abs() < 1e-12, "{}", c.diameter);
    }

    #[test]
    fn the_depth_threshold_decides_whether_a_shallow_pit_is_crater() {
        let mut m = measurer(None);
        m.setup.crater_bin = 0.5e-3;
        let untouched = graded_bed((0.0, 0.0));
        // A pit 2 mm deep (floor at the layer −2.25 mm, top −0.25 mm) out to r = 3.1 mm.
        let pit = graded_bed((3.1e-3, 2e-3));
        let read = |m: &mut Measurer, threshold: f64| {
            m.setup.crater_depth_threshold = threshold;
            m.calibrate(&untouched).unwrap();
            m.crater(&pit).unwrap().unwrap()
        };
        let shallow = read(&mut m, 1.0e-3);
        assert!((shallow.depth - 2.0e-3).abs() < 1e-12, "{}", shallow.depth);
        assert!(
            (shallow.diameter - 6.0e-3).abs() < 1e-12,
            "{}",
            shallow.diameter
        );
        // Deeper than the pit: no crater, and its depth is that of the innermost bin.
        let strict = read(&mut m, 3.0e-3);
        assert_eq!(strict.diameter, 0.0);
        assert!((strict.depth - 2.0e-3).abs() < 1e-12, "{}", strict.depth);
    }
}

//! The scheme's choices that pass 2 makes for every pair, gathered so that the study's
//! own choices can be constants of the compiled loop.
//!
//! Pass 2 reads a dozen of the scheme's options per pair (the limiter, the Riemann solver,
//! the energy, density and momentum forms, …). Read from the scheme, each is a test per
//! pair and a value the loop keeps in a register or on the stack; as constants they fold
//! away. [`rates`](super::rates) therefore runs a loop compiled for
//! [`PairScheme::study`] (the choices of the paper's scheme, which every bundled scene
//! uses) when the scheme makes exactly those choices, and the loop that reads them
//! otherwise. Both loops do the same arithmetic in the same order, so a run's results do
//! not depend on which one it took (docs/performance.md, "The scheme's choices as
//! constants of the pair loop").

use crate::solver::config::{DensityForm, EnergyForm, MomentumForm, SchemeConfig};
use sph_damage::StressCoupling;
use sph_riemann::{
    InterfaceCoupling, Limiter, MonaghanViscosity, RiemannSolver, ViscositySoundSpeed,
    ViscositySwitch,
};

/// What pass 2 reads of the scheme per pair.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PairScheme {
    pub limiter: Limiter,
    pub riemann: RiemannSolver,
    pub coupling: InterfaceCoupling,
    pub energy: EnergyForm,
    pub density: DensityForm,
    pub momentum: MomentumForm,
    pub stress_coupling: StressCoupling,
    pub viscosity: MonaghanViscosity,
    pub unbonded_interfaces: bool,
    pub density_stabilization: f64,
    pub energy_diffusion: f64,
    pub gradient_correction: bool,
    pub momentum_correction: bool,
}

impl PairScheme {
    /// The choices of `scheme`, read at run time.
    #[inline(always)]
    pub fn of(scheme: &SchemeConfig) -> Self {
        PairScheme {
            limiter: scheme.limiter,
            riemann: scheme.riemann,
            coupling: scheme.coupling,
            energy: scheme.energy,
            density: scheme.density,
            momentum: scheme.momentum,
            stress_coupling: scheme.stress_coupling,
            viscosity: scheme.viscosity,
            unbonded_interfaces: scheme.unbonded_interfaces,
            density_stabilization: scheme.density_stabilization,
            energy_diffusion: scheme.energy_diffusion,
            gradient_correction: scheme.gradient_correction,
            momentum_correction: scheme.momentum_correction,
        }
    }

    /// The paper's scheme (`SchemeConfig::default`): van Leer reconstruction, the
    /// acoustic Riemann solver with the study's damage coupling, the compatible energy
    /// form, dρ/dt from the mass, the particles' pressures, each particle's own (1 − D),
    /// Monaghan's viscosity without switch or reconstruction on c_L, unbonded material
    /// interfaces, no gradient corrections, no density stabilisation or energy
    /// diffusion. Only the viscosity's α and β are taken from `scheme`: every choice is
    /// a constant wherever this is inlined.
    #[inline(always)]
    pub fn study(scheme: &SchemeConfig) -> Self {
        PairScheme {
            limiter: Limiter::VanLeer,
            riemann: RiemannSolver::Acoustic,
            coupling: InterfaceCoupling::Study,
            energy: EnergyForm::Compatible,
            density: DensityForm::Mass,
            momentum: MomentumForm::ParticlePressure,
            stress_coupling: StressCoupling::Particle,
            viscosity: MonaghanViscosity {
                alpha: scheme.viscosity.alpha,
                beta: scheme.viscosity.beta,
                switch: ViscositySwitch::None,
                reconstruct: false,
                sound_speed: ViscositySoundSpeed::Longitudinal,
            },
            unbonded_interfaces: true,
            density_stabilization: 0.0,
            energy_diffusion: 0.0,
            gradient_correction: false,
            momentum_correction: false,
        }
    }

    /// [`Self::study`] with `STUDY`, else [`Self::of`]: called where the choices are
    /// read, so that with `STUDY` they are constants there.
    #[inline(always)]
    pub fn pick<const STUDY: bool>(scheme: &SchemeConfig) -> Self {
        if STUDY {
            Self::study(scheme)
        } else {
            Self::of(scheme)
        }
    }

    /// Whether `scheme` makes the choices of [`Self::study`].
    pub fn is_study(scheme: &SchemeConfig) -> bool {
        Self::of(scheme) == Self::study(scheme)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_scheme_is_the_study_preset_and_any_other_choice_is_not() {
        let scheme = SchemeConfig::default();
        assert!(PairScheme::is_study(&scheme));
        // α and β are read from the scheme in both loops.
        let mut other = scheme.clone();
        other.viscosity.alpha = 0.5;
        assert!(PairScheme::is_study(&other));
        let changes: [fn(&mut SchemeConfig); 7] = [
            |s| s.limiter = Limiter::Minmod,
            |s| s.energy = EnergyForm::Study,
            |s| s.density = DensityForm::Volume,
            |s| s.stress_coupling = StressCoupling::PairMax,
            |s| s.viscosity.switch = ViscositySwitch::Balsara,
            |s| s.density_stabilization = 0.1,
            |s| s.momentum_correction = true,
        ];
        for change in changes {
            let mut s = scheme.clone();
            change(&mut s);
            assert!(!PairScheme::is_study(&s), "{s:?}");
        }
    }
}

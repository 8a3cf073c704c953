//! The smoothing length after a stage: scalar h from the density (h = n_target × the
//! particle's measure^(1/d), capped at h_max_factor × its initial support), or the ASPH
//! tensor advected with the velocity gradient and scaled to the same equivalent radius
//! (docs/scenes.md, `smoothing`).

use super::*;

impl<D: Dimension, K: Kernel, R: PairRule<D>> Simulation<D, K, R> {
    /// The scalar support of a particle of mass `m` at `x` and density `rho` > 0:
    /// n_target × its measure^(1/d), capped at h_max_factor × n_target × its initial
    /// spacing `s0` (the advancing pass, module `advance`, sets it; ASPH scales its
    /// tensor to it).
    #[inline]
    pub(super) fn scalar_support(&self, m: f64, x: D::Vector, rho: f64, s0: f64) -> f64 {
        let (n_target, cap) = (self.scheme.n_target, self.scheme.h_max_factor);
        let measure = self.kernel_measure(m, x, rho);
        // The exponent passes through `black_box`: as a constant ½ it lets LLVM turn
        // pow into sqrt in 2-D, which differs from glibc's pow in the last bit for about
        // one argument in a thousand (and then in every later bit of a run). It stays
        // pow, so results are those of earlier versions to the bit.
        let exponent = std::hint::black_box(1.0 / D::DIM as f64);
        (n_target * measure.powf(exponent)).min(cap * n_target * s0)
    }

    /// Advances the ASPH tensors of `y` (after its density) over a stage of length `dt`
    /// with `stage`'s rates, evaluated on `rate_state`; a no-op with a scalar support
    /// (set by the advancing pass).
    pub(super) fn update_asph(
        &self,
        y: &mut State<D>,
        stage: &Stage<D>,
        dt: f64,
        rate_state: &State<D>,
    ) {
        let SmoothingMode::Asph { max_aspect } = self.scheme.smoothing else {
            return;
        };
        let p = &mut y.particles;
        let grads = stage.grads.as_ref().expect("ASPH computes gradients");
        let h_src = &rate_state.h_tensor;
        let (m, rho, s0) = (&p.mass, &p.density, &y.spacing0);
        let new: Vec<(D::Tensor, f64)> = (0..p.len())
            .into_par_iter()
            .map(|i| {
                // The equivalent radius follows the density as in the scalar mode, with
                // the same cap: a particle expanding into vacuum would otherwise grow
                // its support without bound.
                let target = if rho[i] > 0.0 {
                    self.scalar_support(m[i], p.position[i], rho[i], s0[i])
                } else {
                    1.0 / h_src[i].sym_eigenvalues()[0]
                };
                asph_update(
                    &y.h_tensor[i],
                    &grads.each[i].velocity,
                    dt,
                    target,
                    max_aspect,
                )
            })
            .collect();
        for (i, (h, radius)) in new.into_iter().enumerate() {
            y.h_tensor[i] = h;
            p.smoothing_length[i] = radius;
        }
    }

    /// A particle's kernel measure at density `rho` (the length, area or volume per
    /// particle that h follows): m/ρ, in RZ the ring's (r, z) area
    /// (`axisymmetric::ring_area`).
    pub(super) fn kernel_measure(&self, m: f64, x: D::Vector, rho: f64) -> f64 {
        match self.scheme.geometry {
            Geometry::Cartesian => m / rho,
            Geometry::Axisymmetric => ring_area(m, radius(x), rho),
        }
    }
}

/// ASPH update of one H: advect the metric G = H² with L, take its square root, scale
/// it to the target equivalent radius and limit its aspect ratio.
pub(super) fn asph_update<T: Tensor>(
    h: &T,
    l: &T,
    dt: f64,
    target_radius: f64,
    max_aspect: f64,
) -> (T, f64) {
    let g = h.mul_tensor(h);
    let dg = (l.transpose().mul_tensor(&g) + g.mul_tensor(l)) * (-dt);
    let g_new = (g + dg).symmetric();
    let eig = g_new.sym_eigen();
    let n = T::Vector::DIM;
    let mut lam: Vec<f64> = (0..n).map(|k| eig.values[k].max(0.0).sqrt()).collect();
    // Limit the aspect: no semi-axis longer than max_aspect × the shortest.
    let lmax = lam.iter().cloned().fold(0.0, f64::max);
    if !(lmax > 0.0) {
        return (T::IDENTITY * (1.0 / target_radius), target_radius);
    }
    for l in lam.iter_mut() {
        *l = l.max(lmax / max_aspect);
    }
    // Scale to the target volume: Π λ_k = target^(−n).
    let prod: f64 = lam.iter().product();
    let scale = (target_radius.powi(-(n as i32)) / prod).powf(1.0 / n as f64);
    let v = eig.vectors;
    let h_new = T::from_fn(|a, b| {
        (0..n)
            .map(|k| v.component(a, k) * lam[k] * scale * v.component(b, k))
            .sum()
    });
    // V diag(λ) Vᵀ is symmetric in exact arithmetic; make it so in floating point.
    let h_new = h_new.symmetric();
    let radius = equivalent_radius(&h_new);
    (h_new, radius)
}

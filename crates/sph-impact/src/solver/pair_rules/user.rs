//! A pair rule of the user's own: an extra pair force, written in the user's crate and
//! compiled into the one pair loop of pass 2 (`Simulation::with_pair_rule`). The default,
//! [`NoPairRule`], is a type with nothing in it whose rule returns `None`, so a run
//! without a rule of its own compiles the call away.
//!
//! The force is added to the scheme's own pair force per unit mass of the partner before
//! anything reads it: the momentum and energy of the pair follow from it as from the
//! built-in terms (dv_i/dt gets m_j F_ij, dv_j/dt gets −m_i F_ij; the compatible energy
//! form books its work at the interface velocity), so a rule that is antisymmetric in
//! (i, j), F_ji = −F_ij, conserves momentum and energy to round-off. In RZ the masses are
//! per radian and the force is added as it is, without the ring weights r.

use sph_core::Dimension;

/// What a pair rule sees of the pair (i, j): r = x_i − x_j (j may be a boundary ghost).
#[derive(Clone, Copy, Debug)]
pub struct PairView<D: Dimension> {
    /// x_i − x_j (m).
    pub r: D::Vector,
    /// |r| (m), positive.
    pub dist: f64,
    /// r/|r|.
    pub r_hat: D::Vector,
    /// The pair's kernel gradient ∇_i W̄_ij (m⁻⁴ in 3-D).
    pub grad_w: D::Vector,
    /// v_i, v_j (m/s).
    pub velocity: (D::Vector, D::Vector),
    /// ρ_i, ρ_j (kg/m³).
    pub density: (f64, f64),
    /// P_i, P_j (Pa; the damaged pressures).
    pub pressure: (f64, f64),
    /// Material (body) ids of i and j.
    pub material: (u16, u16),
    /// Support radii h_i, h_j (m).
    pub support: (f64, f64),
}

/// An extra pair force (`Simulation::with_pair_rule`).
pub trait PairRule<D: Dimension>: Send + Sync {
    /// The force on i per unit mass of j (m s⁻² kg⁻¹), or `None` for no force. It must be
    /// antisymmetric, F(j, i) = −F(i, j), for momentum to be conserved.
    fn force(&self, pair: &PairView<D>) -> Option<D::Vector>;
}

/// No pair rule of the user's: the default.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoPairRule;

impl<D: Dimension> PairRule<D> for NoPairRule {
    #[inline(always)]
    fn force(&self, _pair: &PairView<D>) -> Option<D::Vector> {
        None
    }
}

//! Ejecta that no longer touch the target: the part of β that can no longer change
//! (docs/diagnostics.md §3.1).
//!
//! Ejecta (§2) are target material above the original surface moving up. Some of it is
//! still part of the target: a raised rim of unbroken rock that will stop and sink back,
//! or slow rubble pressed against the crater wall. Such material trades momentum with
//! the target through the pair forces, so β from all the ejecta can still fall (it does
//! at A_res 1 mm, docs/validation.md "β in time").
//!
//! Two particles interact only when |x_i − x_j| < max(h_i, h_j) (the solver's pair
//! criterion, h the support radius). A target particle above the surface is **attached**
//! when a chain of such pairs through target particles above the surface reaches a target
//! particle at or below it; the other ejecta are **detached**. No force from the target
//! reaches detached ejecta, and with no gravity their momentum stays as it is unless
//! they run into other material again. So β from the detached ejecta alone rises toward
//! β from all of them as the ejecta separate, and once the two are equal every
//! ejectum flies free and β has settled.
//!
//! **Method.** The target particles above the surface and those below it within reach
//! of it are put into a hash grid of cells as wide as the largest support among them;
//! a breadth-first search from the ones below marks the attached. Positions are the
//! scene's: an RZ ring is its point (r, 0, z), so rings connect in the (r, z) plane as
//! they interact; a quarter model's particle is nearer to a particle of its own quarter
//! than to that particle's mirror images, so the quarter alone decides.

use crate::ejecta::{Ejecta, EjectaCriterion};
use crate::error::{ImpactError, positive};
use crate::particles_view::ParticleView;
use std::collections::HashMap;

/// Mass, momentum and count of the ejecta of `view` that no target particle at or
/// below the surface reaches through a chain of interacting target particles (module
/// docs). `support` is each particle's support radius h (m, positive and finite).
pub fn detached_ejecta(
    view: &ParticleView,
    criterion: &EjectaCriterion,
    support: &[f64],
) -> Result<Ejecta, ImpactError> {
    view.validate()?;
    criterion.check()?;
    if support.len() != view.len() {
        return Err(ImpactError::LengthMismatch {
            field: "support",
            len: support.len(),
            expected: view.len(),
        });
    }
    for &h in support {
        positive("support", h)?;
    }
    let top = criterion.surface_z + criterion.tolerance;
    let is_target = |i: &usize| criterion.is_target(view.body[*i]);
    let z = |i: usize| view.position[i][2];
    let above: Vec<usize> = (0..view.len())
        .filter(is_target)
        .filter(|&i| z(i) > top)
        .collect();
    let Some(reach) = above.iter().map(|&i| support[i]).reduce(f64::max) else {
        return Ok(Ejecta::default());
    };
    // Below the surface, only particles that can reach a particle above it.
    let anchors: Vec<usize> = (0..view.len())
        .filter(is_target)
        .filter(|&i| z(i) <= top && z(i) > top - reach.max(support[i]))
        .collect();
    let cell = anchors.iter().map(|&i| support[i]).fold(reach, f64::max);
    let key = |i: usize| view.position[i].map(|x| (x / cell).floor() as i64);
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for &i in &above {
        grid.entry(key(i)).or_default().push(i);
    }
    let mut attached = vec![false; view.len()];
    let mut queue = anchors;
    while let Some(i) = queue.pop() {
        let c = key(i);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(cands) = grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) else {
                        continue;
                    };
                    for &j in cands {
                        if attached[j] {
                            continue;
                        }
                        let h = support[i].max(support[j]);
                        let d2: f64 = (0..3)
                            .map(|a| (view.position[i][a] - view.position[j][a]).powi(2))
                            .sum();
                        if d2 < h * h {
                            attached[j] = true;
                            queue.push(j);
                        }
                    }
                }
            }
        }
    }
    Ok(Ejecta::of(
        view,
        above
            .into_iter()
            .filter(|&i| !attached[i] && view.velocity[i][2] > 0.0),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ejecta::ejecta;

    /// A target slab (body 1) of cells 1 mm wide below z = 0 over |x| < 5 mm (a line in
    /// x, z: enough for a chain), plus `extra` particles above it; all supports 2.5 mm.
    fn scene(extra: &[([f64; 3], [f64; 3], u16)]) -> (Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<u16>) {
        let (mut x, mut v, mut b) = (Vec::new(), Vec::new(), Vec::new());
        for i in -5..5 {
            for k in 0..3 {
                x.push([(i as f64 + 0.5) * 1e-3, 0.0, -(k as f64 + 0.5) * 1e-3]);
                v.push([0.0; 3]);
                b.push(1);
            }
        }
        for &(p, u, body) in extra {
            x.push(p);
            v.push(u);
            b.push(body);
        }
        (x, v, b)
    }

    fn read(extra: &[([f64; 3], [f64; 3], u16)]) -> (Ejecta, Ejecta) {
        let (x, v, b) = scene(extra);
        let m = vec![1e-3; x.len()];
        let h = vec![2.5e-3; x.len()];
        let view = ParticleView::new(&x, &v, &m, &b);
        let c = EjectaCriterion::new(&[1], 0.0);
        (
            ejecta(&view, &c).unwrap(),
            detached_ejecta(&view, &c, &h).unwrap(),
        )
    }

    #[test]
    fn a_chain_to_the_surface_holds_ejecta_and_a_gap_frees_them() {
        // A column rising from the surface in steps of 2 mm (< h = 2.5 mm): every one
        // is ejecta, none is detached. The same column with a 3 mm gap above its second
        // particle: the three above the gap are detached.
        let up = [0.0, 0.0, 10.0];
        let column = |gap: f64| -> Vec<([f64; 3], [f64; 3], u16)> {
            (0..5)
                .map(|k| {
                    let z = 1.0e-3 + 2.0e-3 * k as f64 + if k >= 2 { gap } else { 0.0 };
                    ([0.0, 0.0, z], up, 1)
                })
                .collect()
        };
        let (all, free) = read(&column(0.0));
        assert_eq!(all.count, 5);
        assert_eq!(free.count, 0);
        assert_eq!(free.momentum_z, 0.0);
        let (all, free) = read(&column(1.0e-3));
        assert_eq!(all.count, 5);
        assert_eq!(free.count, 3);
        assert!((free.momentum_z - 3.0 * 1e-3 * 10.0).abs() < 1e-15);
    }

    #[test]
    fn falling_material_still_holds_a_chain_and_other_bodies_do_not() {
        // The particle linking the rising one to the surface falls (not ejecta) but
        // still carries the chain: the rising one stays attached. A projectile particle
        // in the same place carries no chain: the rising one is detached.
        let link = ([0.0, 0.0, 1.5e-3], [0.0, 0.0, -5.0], 1);
        let riser = ([0.0, 0.0, 3.5e-3], [0.0, 0.0, 10.0], 1);
        let (all, free) = read(&[link, riser]);
        assert_eq!((all.count, free.count), (1, 0));
        let projectile = ([0.0, 0.0, 1.5e-3], [0.0, 0.0, -5.0], 0);
        let (all, free) = read(&[projectile, riser]);
        assert_eq!((all.count, free.count), (1, 1));
    }

    #[test]
    fn the_larger_support_of_a_pair_decides() {
        // A particle 3 mm above the slab's nearest particle (the next is 3.16 mm away):
        // detached with h = 2.5 mm, attached when its own h is 4 mm.
        let (x, v, b) = scene(&[([0.5e-3, 0.0, 2.5e-3], [0.0, 0.0, 1.0], 1)]);
        let m = vec![1e-3; x.len()];
        let view = ParticleView::new(&x, &v, &m, &b);
        let c = EjectaCriterion::new(&[1], 0.0);
        let mut h = vec![2.5e-3; x.len()];
        assert_eq!(detached_ejecta(&view, &c, &h).unwrap().count, 1);
        *h.last_mut().unwrap() = 4e-3;
        assert_eq!(detached_ejecta(&view, &c, &h).unwrap().count, 0);
    }

    #[test]
    fn bad_supports_are_refused() {
        let (x, v, b) = scene(&[]);
        let m = vec![1e-3; x.len()];
        let view = ParticleView::new(&x, &v, &m, &b);
        let c = EjectaCriterion::new(&[1], 0.0);
        assert!(detached_ejecta(&view, &c, &[1e-3]).is_err());
        for bad in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
            let mut h = vec![1e-3; x.len()];
            h[3] = bad;
            assert!(detached_ejecta(&view, &c, &h).is_err(), "{bad}");
        }
    }
}

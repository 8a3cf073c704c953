//! Elastic–plastic planar impact (docs/verification.md, "Solid dynamics: elastic–plastic planar
//! impact"): aluminium (E = 70 GPa, ν = 0.3, ρ = 2700, linear elastic EOS P = Kμ, von Mises
//! Y = 0.29 GPa) plates colliding symmetrically at V = 400 m/s (±200 m/s) and V = 1000 m/s.
//! Exact two-wave structure: an elastic precursor at c_L = 5907.6 m/s with amplitude
//! σ_HEL = Y(1−ν)/(1−2ν) = (K + 4G/3)Y/(2G) = 0.5075 GPa, the same at every V, followed by the
//! plastic wave at c_B = √(K/ρ) = 4648 m/s (σ_xx = 2.618 GPa behind it at 400 m/s, 6.383 GPa at
//! 1000 m/s).
//!
//! Measured at t = 0.8 L/c_L (before the precursor reaches the free end): the precursor
//! amplitude as the median σ_xx between the two measured fronts (a quarter of the gap
//! away from each), the precursor front as the
//! half-HEL crossing (its speed taken relative to the material, which moves at −V/2), and
//! the plastic state behind the plastic front.

use super::column::{Planar, PlanarRun};
use super::elastic_bar::two_plates_set_up;
use super::outcome::{Outcome, Profile};
use super::setup::{last_crossing, median};
use crate::{SchemeConfig, SolverError};

const YIELD: f64 = 0.29e9;
/// Plate length: long enough (at 0.5 mm spacing) for the precursor to separate from the
/// smeared plastic front before it reaches the free end.
const LENGTH: f64 = 0.4;

/// Runs with `n` particles per plate at both impact speeds, in 1-D or as an RZ column
/// (the profile then on the axis).
pub(crate) fn run(
    n: usize,
    scheme: SchemeConfig,
    geometry: Planar,
) -> Result<Outcome, SolverError> {
    let mut out = Outcome {
        problem: match geometry {
            Planar::OneD => "hel-impact".into(),
            Planar::Rz { .. } => "hel-impact (rz)".into(),
        },
        ..Default::default()
    };
    let wall = std::time::Instant::now();
    let mut particles = 0;
    let mut crossings = None;
    for (label, v_impact, plastic_exact) in [("v400", 400.0, 2.618e9), ("v1000", 1000.0, 6.383e9)] {
        let (p, plates, c_l, dx) = two_plates_set_up(n, LENGTH, 0.5 * v_impact, YIELD, &scheme)?;
        let mut sim = PlanarRun::new(p, plates, scheme.clone(), dx, geometry)?;
        particles = sim.particles();
        let bulk = 70.0e9 / (3.0 * (1.0 - 0.6));
        let shear = 70.0e9 / 2.6;
        let hel = (bulk + 4.0 / 3.0 * shear) * YIELD / (2.0 * shear);
        let c_b = (bulk / 2700.0).sqrt();
        let t = 0.8 * LENGTH / c_l;
        sim.run_until(t, |_| {})?;
        crossings = sim.axis_crossings().map(|(end, mid)| {
            let (e0, m0) = crossings.unwrap_or((0, 0));
            (end + e0, mid + m0)
        });
        let prof = sim.profile();
        let (x, sxx) = (prof.x, prof.sigma);
        let right: Vec<usize> = (0..x.len()).filter(|&k| x[k] > 0.0).collect();
        let xr: Vec<f64> = right.iter().map(|&k| x[k]).collect();
        let compression: Vec<f64> = right.iter().map(|&k| -sxx[k]).collect();
        // Waves run at their speed relative to the material, which moves at −V/2.
        let drift = 0.5 * v_impact;
        // Plastic state: behind the plastic front, near the impact plane.
        let xp_guess = (c_b - drift) * t;
        let behind: Vec<f64> = (0..xr.len())
            .filter(|&k| xr[k] > 0.2 * xp_guess && xr[k] < 0.6 * xp_guess)
            .map(|k| compression[k])
            .collect();
        let plastic = median(behind);
        // The two fronts as measured: the elastic one at half the HEL, the plastic one
        // half-way between the HEL and the plastic plateau. The precursor amplitude is
        // the median between them, a quarter of the gap away from each.
        let front = last_crossing(&xr, &compression, 0.5 * hel).unwrap_or(f64::NAN);
        let plastic_front =
            last_crossing(&xr, &compression, 0.5 * (hel + plastic)).unwrap_or(f64::NAN);
        let gap = front - plastic_front;
        let zone: Vec<f64> = (0..xr.len())
            .filter(|&k| xr[k] > plastic_front + 0.25 * gap && xr[k] < front - 0.25 * gap)
            .map(|k| compression[k])
            .collect();
        let precursor = median(zone);
        out.set(&format!("{label}_precursor_stress"), precursor);
        out.set(
            &format!("{label}_precursor_error_relative"),
            precursor / hel - 1.0,
        );
        // Front speed relative to the material ahead of it (moving at −V/2).
        let speed = front / t + drift;
        out.set(&format!("{label}_precursor_front_speed"), speed);
        out.set(
            &format!("{label}_precursor_speed_error_relative"),
            speed / c_l - 1.0,
        );
        out.set(&format!("{label}_plastic_stress"), plastic);
        out.set(
            &format!("{label}_plastic_stress_error_relative"),
            plastic / plastic_exact - 1.0,
        );
        out.set("hel_exact", hel);
        if label == "v1000" {
            out.profile = Profile {
                columns: ["x", "sigma_xx"].map(String::from).to_vec(),
                rows: (0..x.len()).map(|k| vec![x[k], sxx[k]]).collect(),
            };
        }
    }
    out.set("resolution", n as f64);
    out.set("particles", particles as f64);
    // Both impact speeds together.
    out.set_axis_crossings(crossings);
    out.set("wall_time_s", wall.elapsed().as_secs_f64());
    Ok(out)
}

//! Scatter markers: the shape is rasterised once into a small coverage stamp, which is
//! then blended at every point. 10⁵ particles cost 10⁵ stamp copies of a few dozen
//! pixels each, with no per-point geometry.

use super::canvas::{Canvas, alpha8};
use super::color::Rgb;
use super::style::Marker;

/// Sub-samples per pixel side when anti-aliasing a stamp (4 × 4 = 16 levels).
const SUB: usize = 4;

/// Coverage (0..=255) of a marker centred on the centre of pixel (0, 0), over the
/// square −half..=half in both directions.
#[derive(Clone, Debug)]
pub(crate) struct Stamp {
    half: i64,
    cov: Vec<u8>,
}

/// Whether offset (dx, dy) from the centre lies in `marker` of radius r.
fn inside(marker: Marker, dx: f64, dy: f64, r: f64) -> bool {
    // Stroke half-thickness of the line-like markers.
    let t = (0.18 * r).max(0.5);
    match marker {
        Marker::Circle => dx * dx + dy * dy <= r * r,
        Marker::OpenCircle => {
            let d = (dx * dx + dy * dy).sqrt();
            d <= r && d >= r - 2.0 * t
        }
        // Squares and diamonds are scaled to the circle's area (side √π r), so that
        // markers of one size look equally heavy.
        Marker::Square => dx.abs().max(dy.abs()) <= 0.886 * r,
        Marker::Diamond => dx.abs() + dy.abs() <= 1.253 * r,
        Marker::Triangle => {
            // Apex (0, −r), base corners (±0.866 r, 0.5 r): equilateral, inscribed in
            // the circle of radius r.
            let h = 0.5 * r;
            dy <= h && dy >= -r && dx.abs() <= 0.866 * r * (dy + r) / (1.5 * r)
        }
        Marker::Plus => (dx.abs() <= t && dy.abs() <= r) || (dy.abs() <= t && dx.abs() <= r),
        Marker::Cross => {
            let (u, v) = (
                (dx + dy) * std::f64::consts::FRAC_1_SQRT_2,
                (dx - dy) * std::f64::consts::FRAC_1_SQRT_2,
            );
            (u.abs() <= t && v.abs() <= r) || (v.abs() <= t && u.abs() <= r)
        }
    }
}

impl Stamp {
    /// The stamp of `marker` with diameter `size` pixels.
    pub fn new(marker: Marker, size: f64, aa: bool) -> Self {
        let r = 0.5 * size;
        let half = (r + 1.0).ceil() as i64;
        let side = (2 * half + 1) as usize;
        let mut cov = vec![0u8; side * side];
        for j in 0..side {
            for i in 0..side {
                let (px, py) = (i as i64 - half, j as i64 - half);
                let c = if aa {
                    let mut n = 0;
                    for sj in 0..SUB {
                        for si in 0..SUB {
                            let dx = px as f64 + (si as f64 + 0.5) / SUB as f64 - 0.5;
                            let dy = py as f64 + (sj as f64 + 0.5) / SUB as f64 - 0.5;
                            n += inside(marker, dx, dy, r) as usize;
                        }
                    }
                    (n * 255 / (SUB * SUB)) as u8
                } else if inside(marker, px as f64, py as f64, r) {
                    255
                } else {
                    0
                };
                cov[j * side + i] = c;
            }
        }
        // A marker smaller than a pixel still marks its pixel.
        if cov.iter().all(|&c| c == 0) {
            cov[half as usize * side + half as usize] = 255;
        }
        Self { half, cov }
    }

    fn side(&self) -> i64 {
        2 * self.half + 1
    }
}

impl Canvas {
    /// Blends `stamp` in `color` at opacity `alpha` ∈ [0, 255] centred on the pixel that
    /// contains `p`.
    pub(crate) fn stamp(&mut self, stamp: &Stamp, p: [f64; 2], color: Rgb, alpha: u8) {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return;
        }
        let clip = self.clip();
        // Points far outside are dropped before the integer conversion.
        let (fx, fy) = (p[0].floor(), p[1].floor());
        let h = stamp.half as f64;
        if fx + h < clip.x0 as f64
            || fx - h >= clip.x1 as f64
            || fy + h < clip.y0 as f64
            || fy - h >= clip.y1 as f64
        {
            return;
        }
        let (cx, cy) = (fx as i64, fy as i64);
        let side = stamp.side();
        let x0 = cx - stamp.half;
        let y0 = cy - stamp.half;
        let whole = x0 >= clip.x0 && y0 >= clip.y0 && x0 + side <= clip.x1 && y0 + side <= clip.y1;
        for j in 0..side {
            for i in 0..side {
                let c = stamp.cov[(j * side + i) as usize];
                if c == 0 {
                    continue;
                }
                let a = if alpha == 255 {
                    c
                } else {
                    ((c as u32 * alpha as u32 + 127) / 255) as u8
                };
                let (x, y) = (x0 + i, y0 + j);
                if whole {
                    let k = self.offset(x, y);
                    self.blend_at(k, color, a);
                } else {
                    self.blend(x, y, color, a);
                }
            }
        }
    }

    /// Draws `marker` of diameter `size` pixels at each point (pixel coordinates) in one
    /// colour; points with a non-finite coordinate are not drawn.
    pub fn markers(
        &mut self,
        points: &[[f64; 2]],
        marker: Marker,
        size: f64,
        color: Rgb,
        alpha: f64,
    ) {
        if !(size > 0.0) {
            return;
        }
        let stamp = Stamp::new(marker, size, self.antialias());
        let a = alpha8(alpha);
        for &p in points {
            self.stamp(&stamp, p, color, a);
        }
    }
}

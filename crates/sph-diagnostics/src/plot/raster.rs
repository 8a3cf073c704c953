//! Thick, optionally dashed and anti-aliased lines.
//!
//! A stroke of width w is the set of points within w/2 of the path: a union of
//! capsules, one per segment, which gives round joins and caps. Each pixel's coverage
//! is estimated from the distance d of its centre to the segment as
//! clamp(w/2 + ½ − d, 0, 1) (a one-pixel linear ramp, the box-filter estimate for a
//! straight edge); without anti-aliasing a pixel is on when d ≤ w/2. Coverage of a
//! whole polyline is gathered in a mask with max() before blending, so joints and
//! overlapping dashes are not blended twice.

use super::canvas::{Canvas, Rect, alpha8};
use super::color::Rgb;

/// How a line is stroked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stroke {
    /// Width in pixels.
    pub width: f64,
    /// Colour.
    pub color: Rgb,
    /// Opacity in [0, 1].
    pub alpha: f64,
    /// Drawn and blank lengths in pixels, or `None` for solid. Patterns with a part
    /// shorter than [`MIN_DASH`] cannot be resolved on pixels and are drawn solid.
    pub dash: Option<(f64, f64)>,
}

impl Stroke {
    /// A solid, opaque stroke.
    pub fn solid(width: f64, color: Rgb) -> Self {
        Self {
            width,
            color,
            alpha: 1.0,
            dash: None,
        }
    }
}

/// Shortest dash or gap (pixels) drawn as such.
pub const MIN_DASH: f64 = 0.5;

/// Segments are rasterised in pieces no longer than this (pixels) so that each piece's
/// bounding box stays close to the capsule even for diagonal lines.
const PIECE: f64 = 16.0;

/// Coverage in 0..=255 of a rectangle of pixels.
struct Mask {
    rect: Rect,
    cov: Vec<u8>,
}

impl Mask {
    fn new(rect: Rect) -> Self {
        Self {
            rect,
            cov: vec![0; (rect.width() * rect.height()) as usize],
        }
    }

    /// Adds the capsule of half-width `hw` around segment a–b.
    fn capsule(&mut self, a: [f64; 2], b: [f64; 2], hw: f64, aa: bool) {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let n = (len / PIECE).ceil().max(1.0) as usize;
        for k in 0..n {
            let t0 = k as f64 / n as f64;
            let t1 = (k + 1) as f64 / n as f64;
            let p = lerp(a, b, t0);
            let q = lerp(a, b, t1);
            self.piece(p, q, hw, aa);
        }
    }

    fn piece(&mut self, p: [f64; 2], q: [f64; 2], hw: f64, aa: bool) {
        let reach = hw + 1.0;
        let x0 = ((p[0].min(q[0]) - reach).floor() as i64).max(self.rect.x0);
        let x1 = ((p[0].max(q[0]) + reach).ceil() as i64).min(self.rect.x1);
        let y0 = ((p[1].min(q[1]) - reach).floor() as i64).max(self.rect.y0);
        let y1 = ((p[1].max(q[1]) + reach).ceil() as i64).min(self.rect.y1);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        let l2 = dx * dx + dy * dy;
        let w = self.rect.width();
        for y in y0..y1 {
            let cy = y as f64 + 0.5;
            for x in x0..x1 {
                let cx = x as f64 + 0.5;
                // Distance from the pixel centre to the segment p–q.
                let t = if l2 > 0.0 {
                    (((cx - p[0]) * dx + (cy - p[1]) * dy) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let d = ((cx - p[0] - t * dx).powi(2) + (cy - p[1] - t * dy).powi(2)).sqrt();
                let c = if aa {
                    (hw + 0.5 - d).clamp(0.0, 1.0)
                } else if d <= hw {
                    1.0
                } else {
                    0.0
                };
                if c > 0.0 {
                    let i = ((y - self.rect.y0) * w + (x - self.rect.x0)) as usize;
                    let c8 = (c * 255.0).round() as u8;
                    if c8 > self.cov[i] {
                        self.cov[i] = c8;
                    }
                }
            }
        }
    }
}

fn lerp(a: [f64; 2], b: [f64; 2], t: f64) -> [f64; 2] {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

fn finite(p: [f64; 2]) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// Liang–Barsky clipping of the segment a + t(b − a), t ∈ [0, 1], to the box
/// [x0, x1] × [y0, y1]: the parameter interval inside, if any.
fn clip_segment(a: [f64; 2], b: [f64; 2], bx: [f64; 4]) -> Option<(f64, f64)> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a[0] - bx[0]),
        (dx, bx[1] - a[0]),
        (-dy, a[1] - bx[2]),
        (dy, bx[3] - a[1]),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    (t0 <= t1).then_some((t0, t1))
}

impl Canvas {
    /// Strokes the path through `points` (pixel coordinates). A point with a non-finite
    /// coordinate breaks the path: the segments on either side are not joined.
    pub fn polyline(&mut self, points: &[[f64; 2]], stroke: &Stroke) {
        let hw = 0.5 * stroke.width;
        if !(hw > 0.0) || points.len() < 2 {
            return;
        }
        let aa = self.antialias();
        let clip = self.clip();
        // Mask over the clip, shrunk to the bounding box of the finite points.
        let (mut bx0, mut bx1, mut by0, mut by1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &p in points.iter().filter(|p| finite(**p)) {
            bx0 = bx0.min(p[0]);
            bx1 = bx1.max(p[0]);
            by0 = by0.min(p[1]);
            by1 = by1.max(p[1]);
        }
        if bx0 > bx1 {
            return;
        }
        let reach = hw + 1.0;
        let rect = clip.intersect(&Rect::new(
            (bx0 - reach).floor().max(-1e9) as i64,
            (by0 - reach).floor().max(-1e9) as i64,
            (bx1 + reach).ceil().min(1e9) as i64,
            (by1 + reach).ceil().min(1e9) as i64,
        ));
        if rect.is_empty() {
            return;
        }
        let mut mask = Mask::new(rect);
        let clip_box = [
            rect.x0 as f64 - reach,
            rect.x1 as f64 + reach,
            rect.y0 as f64 - reach,
            rect.y1 as f64 + reach,
        ];
        // Dash phase: distance travelled along the current unbroken path.
        let mut travelled = 0.0;
        for seg in points.windows(2) {
            let (a, b) = (seg[0], seg[1]);
            if !finite(a) || !finite(b) {
                travelled = 0.0;
                continue;
            }
            let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
            if let Some((t0, t1)) = clip_segment(a, b, clip_box) {
                match stroke.dash {
                    Some((on, off)) if on >= MIN_DASH && off >= MIN_DASH => {
                        dashes(&mut mask, a, b, len, (t0, t1), travelled, on, off, hw, aa)
                    }
                    _ => mask.capsule(lerp(a, b, t0), lerp(a, b, t1), hw, aa),
                }
            }
            travelled += len;
        }
        let a = alpha8(stroke.alpha);
        let w = rect.width();
        for y in rect.y0..rect.y1 {
            for x in rect.x0..rect.x1 {
                let c = mask.cov[((y - rect.y0) * w + (x - rect.x0)) as usize];
                if c > 0 {
                    let i = self.offset(x, y);
                    let ac = ((c as u32 * a as u32 + 127) / 255) as u8;
                    self.blend_at(i, stroke.color, ac);
                }
            }
        }
    }

    /// Strokes the segment a–b.
    pub fn line(&mut self, a: [f64; 2], b: [f64; 2], stroke: &Stroke) {
        self.polyline(&[a, b], stroke);
    }

    /// Fills the disc of radius `r` around `c` (pixel coordinates).
    pub fn fill_circle(&mut self, c: [f64; 2], r: f64, color: Rgb) {
        // A zero-length stroke is a disc of radius width/2.
        self.polyline(&[c, c], &Stroke::solid(2.0 * r, color));
    }
}

/// Adds to the mask the drawn parts of the dash pattern (on, off) over the clipped
/// parameter range `t` of segment a–b, whose start lies `phase0` along the path.
fn dashes(
    mask: &mut Mask,
    a: [f64; 2],
    b: [f64; 2],
    len: f64,
    t: (f64, f64),
    phase0: f64,
    on: f64,
    off: f64,
    hw: f64,
    aa: bool,
) {
    if len <= 0.0 {
        return;
    }
    let period = on + off;
    // Walk only the visible part: start at the dash period containing t.0.
    let s_start = phase0 + t.0 * len;
    let s_end = phase0 + t.1 * len;
    let mut s = (s_start / period).floor() * period;
    while s < s_end {
        // The round caps reach hw beyond a dash's ends: pull the true ends (not those
        // cut by a vertex or the clip box) in by hw so that a dash inks `on` pixels.
        let d0 = if s >= s_start {
            s + hw.min(0.5 * on)
        } else {
            s_start
        };
        let d1 = if s + on <= s_end {
            s + on - hw.min(0.5 * on)
        } else {
            s_end
        };
        if d1 >= d0 {
            let p = lerp(a, b, (d0 - phase0) / len);
            let q = lerp(a, b, (d1 - phase0) / len);
            mask.capsule(p, q, hw, aa);
        }
        s += period;
    }
}

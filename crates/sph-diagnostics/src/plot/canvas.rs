//! The raster: an RGB pixel buffer with a clip rectangle and alpha blending.
//!
//! Pixel (i, j) covers [i, i+1) × [j, j+1) in canvas coordinates, so its centre is
//! (i + ½, j + ½); y grows downwards. Shapes are drawn by their coverage of pixel
//! centres (anti-aliased: a one-pixel ramp at the edge).

use super::color::Rgb;
use super::error::PlotError;

/// Largest accepted canvas side in pixels (an 8192² RGB canvas is 200 MB).
pub const MAX_SIDE: u32 = 8192;

/// A half-open pixel rectangle [x0, x1) × [y0, y1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    /// Left column (inclusive).
    pub x0: i64,
    /// Top row (inclusive).
    pub y0: i64,
    /// Right column (exclusive).
    pub x1: i64,
    /// Bottom row (exclusive).
    pub y1: i64,
}

impl Rect {
    /// The rectangle [x0, x1) × [y0, y1).
    pub const fn new(x0: i64, y0: i64, x1: i64, y1: i64) -> Self {
        Self { x0, y0, x1, y1 }
    }

    /// Width in pixels (0 when empty).
    pub fn width(&self) -> i64 {
        (self.x1 - self.x0).max(0)
    }

    /// Height in pixels (0 when empty).
    pub fn height(&self) -> i64 {
        (self.y1 - self.y0).max(0)
    }

    /// Whether it contains no pixel.
    pub fn is_empty(&self) -> bool {
        self.width() == 0 || self.height() == 0
    }

    /// The common part of two rectangles (possibly empty).
    pub fn intersect(&self, o: &Rect) -> Rect {
        Rect::new(
            self.x0.max(o.x0),
            self.y0.max(o.y0),
            self.x1.min(o.x1),
            self.y1.min(o.y1),
        )
    }

    /// Whether pixel (x, y) lies inside.
    pub fn contains(&self, x: i64, y: i64) -> bool {
        x >= self.x0 && x < self.x1 && y >= self.y0 && y < self.y1
    }
}

/// An RGB raster with 8 bits per channel.
#[derive(Clone, Debug)]
pub struct Canvas {
    width: u32,
    height: u32,
    data: Vec<u8>,
    clip: Rect,
    antialias: bool,
}

impl Canvas {
    /// A canvas filled with `background`; anti-aliasing on. Each side must be in
    /// 1..=[`MAX_SIDE`].
    pub fn new(width: u32, height: u32, background: Rgb) -> Result<Self, PlotError> {
        if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
            return Err(PlotError::BadSize {
                width,
                height,
                max: MAX_SIDE,
            });
        }
        let n = width as usize * height as usize;
        let mut data = Vec::with_capacity(3 * n);
        for _ in 0..n {
            data.extend_from_slice(&[background.r, background.g, background.b]);
        }
        Ok(Self {
            width,
            height,
            data,
            clip: Rect::new(0, 0, width as i64, height as i64),
            antialias: true,
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The pixel bytes, row by row from the top, R G B per pixel.
    pub fn data(&self) -> &[u8] {
        &self.data
    }

    /// The colour of pixel (x, y), `None` outside the canvas.
    pub fn pixel(&self, x: i64, y: i64) -> Option<Rgb> {
        if x < 0 || y < 0 || x >= self.width as i64 || y >= self.height as i64 {
            return None;
        }
        let i = 3 * (y as usize * self.width as usize + x as usize);
        Some(Rgb::new(self.data[i], self.data[i + 1], self.data[i + 2]))
    }

    /// Turns anti-aliasing of lines and markers on or off (text is always crisp).
    pub fn set_antialias(&mut self, on: bool) {
        self.antialias = on;
    }

    /// Whether lines and markers are anti-aliased.
    pub fn antialias(&self) -> bool {
        self.antialias
    }

    /// Restricts drawing to `clip` (intersected with the canvas); `None` lifts it.
    pub fn set_clip(&mut self, clip: Option<Rect>) {
        let full = Rect::new(0, 0, self.width as i64, self.height as i64);
        self.clip = clip.map_or(full, |c| c.intersect(&full));
    }

    /// The current clip rectangle.
    pub fn clip(&self) -> Rect {
        self.clip
    }

    /// Blends `c` over pixel (x, y) with opacity `a` ∈ [0, 255]; nothing outside the clip.
    #[inline]
    pub fn blend(&mut self, x: i64, y: i64, c: Rgb, a: u8) {
        if a == 0 || !self.clip.contains(x, y) {
            return;
        }
        let i = 3 * (y as usize * self.width as usize + x as usize);
        self.blend_at(i, c, a);
    }

    /// Blend at byte offset `i`, which the caller has checked against the clip.
    #[inline]
    pub(crate) fn blend_at(&mut self, i: usize, c: Rgb, a: u8) {
        if a == 255 {
            self.data[i] = c.r;
            self.data[i + 1] = c.g;
            self.data[i + 2] = c.b;
            return;
        }
        let a = a as u32;
        let mix = |src: u8, dst: u8| ((src as u32 * a + dst as u32 * (255 - a) + 127) / 255) as u8;
        self.data[i] = mix(c.r, self.data[i]);
        self.data[i + 1] = mix(c.g, self.data[i + 1]);
        self.data[i + 2] = mix(c.b, self.data[i + 2]);
    }

    /// Byte offset of pixel (x, y); the caller guarantees it is on the canvas.
    #[inline]
    pub(crate) fn offset(&self, x: i64, y: i64) -> usize {
        3 * (y as usize * self.width as usize + x as usize)
    }

    /// Fills the pixels of `r` (within the clip) with `c` at opacity `a` ∈ [0, 255].
    pub fn fill_rect(&mut self, r: Rect, c: Rgb, a: u8) {
        let r = r.intersect(&self.clip);
        for y in r.y0..r.y1 {
            for x in r.x0..r.x1 {
                let i = self.offset(x, y);
                self.blend_at(i, c, a);
            }
        }
    }

    /// Draws the outline of `r`, `t` pixels thick, inside `r`.
    pub fn stroke_rect(&mut self, r: Rect, t: i64, c: Rgb) {
        let t = t.max(1).min(r.width()).min(r.height());
        self.fill_rect(Rect::new(r.x0, r.y0, r.x1, r.y0 + t), c, 255);
        self.fill_rect(Rect::new(r.x0, r.y1 - t, r.x1, r.y1), c, 255);
        self.fill_rect(Rect::new(r.x0, r.y0 + t, r.x0 + t, r.y1 - t), c, 255);
        self.fill_rect(Rect::new(r.x1 - t, r.y0 + t, r.x1, r.y1 - t), c, 255);
    }
}

/// Opacity in [0, 1] → 8-bit alpha.
pub(crate) fn alpha8(a: f64) -> u8 {
    (a.clamp(0.0, 1.0) * 255.0).round() as u8
}

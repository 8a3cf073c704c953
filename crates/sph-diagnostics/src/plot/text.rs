//! Text from the built-in bitmap font, at integer scales, upright or rotated a quarter
//! turn counter-clockwise (y-axis labels, read bottom to top).

use super::canvas::Canvas;
use super::color::{BLACK, Rgb};
use super::font::{self, ADVANCE, CAP_HEIGHT, GLYPH_HEIGHT, GLYPH_WIDTH};

/// Horizontal anchor: which point of the text lies at the given x.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum HAlign {
    /// The left edge.
    #[default]
    Left,
    /// The middle.
    Center,
    /// The right edge.
    Right,
}

/// Vertical anchor: which height of the text lies at the given y.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum VAlign {
    /// Top of the capitals.
    #[default]
    Top,
    /// Middle of the capitals (centres numbers on a tick).
    Middle,
    /// The baseline.
    Baseline,
    /// Bottom of the descenders.
    Bottom,
}

/// How a piece of text is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TextStyle {
    /// Integer magnification of the 5×9 font (1 → 7 px capitals, 2 → 14 px, 3 → 21 px).
    /// Scale 0 draws nothing.
    pub scale: u32,
    /// Ink colour.
    pub color: Rgb,
    /// Horizontal anchor (along the reading direction).
    pub halign: HAlign,
    /// Vertical anchor (across the reading direction).
    pub valign: VAlign,
    /// Rotated a quarter turn counter-clockwise: reads bottom to top.
    pub vertical: bool,
}

impl TextStyle {
    /// Black text at `scale`, anchored at its top-left corner.
    pub fn new(scale: u32) -> Self {
        Self {
            scale,
            color: BLACK,
            halign: HAlign::Left,
            valign: VAlign::Top,
            vertical: false,
        }
    }

    /// Sets the anchors.
    pub fn anchor(mut self, halign: HAlign, valign: VAlign) -> Self {
        self.halign = halign;
        self.valign = valign;
        self
    }

    /// Sets the colour.
    pub fn color(mut self, color: Rgb) -> Self {
        self.color = color;
        self
    }

    /// Rotates the text to read bottom to top.
    pub fn vertical(mut self) -> Self {
        self.vertical = true;
        self
    }
}

impl Canvas {
    /// Draws `text` anchored at pixel (x, y). Characters missing from the font are drawn
    /// as hollow boxes. Text is not anti-aliased: the bitmap is exact at integer scales.
    pub fn text(&mut self, x: i64, y: i64, text: &str, style: &TextStyle) {
        let s = style.scale as i64;
        if s == 0 {
            return;
        }
        let width = font::text_width(text, style.scale) as i64;
        let ua = match style.halign {
            HAlign::Left => 0,
            HAlign::Center => width / 2,
            HAlign::Right => width,
        };
        let va = match style.valign {
            VAlign::Top => 0,
            VAlign::Middle => CAP_HEIGHT as i64 * s / 2,
            VAlign::Baseline => CAP_HEIGHT as i64 * s,
            VAlign::Bottom => GLYPH_HEIGHT as i64 * s,
        };
        for (k, ch) in text.chars().enumerate() {
            let g = font::glyph_or_box(ch);
            let u_char = k as i64 * ADVANCE as i64 * s;
            for row in 0..GLYPH_HEIGHT {
                for col in 0..GLYPH_WIDTH {
                    if !font::ink(g, col, row) {
                        continue;
                    }
                    // Text-local block: u along the reading direction, v downwards.
                    let u = u_char + col as i64 * s - ua;
                    let v = row as i64 * s - va;
                    for dv in 0..s {
                        for du in 0..s {
                            let (px, py) = if style.vertical {
                                // Quarter turn counter-clockwise: u → up, v → right.
                                (x + v + dv, y - (u + du) - 1)
                            } else {
                                (x + u + du, y + v + dv)
                            };
                            self.blend(px, py, style.color, 255);
                        }
                    }
                }
            }
        }
    }
}

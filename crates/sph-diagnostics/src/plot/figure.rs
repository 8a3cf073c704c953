//! A figure: an image of given size holding panels on a grid, an optional overall title,
//! rendered to a [`Canvas`] or straight to a PNG file.

use std::path::Path;

use super::axes::Axes;
use super::canvas::{Canvas, Rect};
use super::color::WHITE;
use super::error::PlotError;
use super::font;
use super::render;
use super::report::RenderReport;
use super::text::{HAlign, TextStyle, VAlign};

/// Largest text scale accepted (3 → 21 px capitals).
pub const MAX_TEXT_SCALE: u32 = 3;

/// One panel and its place: cell (row, col) of a rows × cols grid.
#[derive(Clone, Debug)]
struct Panel {
    row: usize,
    col: usize,
    rows: usize,
    cols: usize,
    axes: Axes,
}

/// An image made of panels.
#[derive(Clone, Debug)]
pub struct Figure {
    width: u32,
    height: u32,
    title: String,
    text_scale: u32,
    antialias: bool,
    panels: Vec<Panel>,
}

impl Figure {
    /// An empty figure of `width` × `height` pixels (checked when rendering), text at
    /// scale 2 (14 px capitals), anti-aliasing on.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            title: String::new(),
            text_scale: 2,
            antialias: true,
            panels: Vec::new(),
        }
    }

    /// Sets the overall title, drawn above all panels one text scale larger.
    pub fn title(&mut self, title: impl Into<String>) -> &mut Self {
        self.title = title.into();
        self
    }

    /// Sets the text scale, 1..=[`MAX_TEXT_SCALE`] (1 suits panels narrower than ~400 px).
    pub fn text_scale(&mut self, scale: u32) -> Result<&mut Self, PlotError> {
        if !(1..=MAX_TEXT_SCALE).contains(&scale) {
            return Err(PlotError::BadParameter {
                what: "text_scale",
                value: scale as f64,
                reason: "text scale must be 1, 2 or 3",
            });
        }
        self.text_scale = scale;
        Ok(self)
    }

    /// Turns anti-aliasing of lines and markers on (default) or off.
    pub fn antialias(&mut self, on: bool) -> &mut Self {
        self.antialias = on;
        self
    }

    /// The panel in cell (`row`, `col`) of a `rows` × `cols` grid, created empty on
    /// first use; the same arguments return the same panel.
    pub fn panel(
        &mut self,
        row: usize,
        col: usize,
        rows: usize,
        cols: usize,
    ) -> Result<&mut Axes, PlotError> {
        if row >= rows || col >= cols {
            return Err(PlotError::BadPanel {
                row,
                col,
                rows,
                cols,
            });
        }
        Ok(self.cell(row, col, rows, cols))
    }

    /// The single panel of a one-panel figure.
    pub fn axes(&mut self) -> &mut Axes {
        self.cell(0, 0, 1, 1)
    }

    fn cell(&mut self, row: usize, col: usize, rows: usize, cols: usize) -> &mut Axes {
        let found = self
            .panels
            .iter()
            .position(|p| (p.row, p.col, p.rows, p.cols) == (row, col, rows, cols));
        let k = match found {
            Some(k) => k,
            None => {
                self.panels.push(Panel {
                    row,
                    col,
                    rows,
                    cols,
                    axes: Axes::default(),
                });
                self.panels.len() - 1
            }
        };
        &mut self.panels[k].axes
    }

    /// Draws the figure.
    pub fn render(&self) -> Result<(Canvas, RenderReport), PlotError> {
        let mut canvas = Canvas::new(self.width, self.height, WHITE)?;
        canvas.set_antialias(self.antialias);
        let (w, h) = (self.width as i64, self.height as i64);
        let mut top = 0;
        if !self.title.is_empty() {
            // One text scale larger than the panels', smaller if it would not fit the
            // width (a long title was cut off at both edges).
            let fits = |s: u32| i64::from(font::text_width(&self.title, s)) + 20 <= w;
            let s = (1..=self.text_scale + 1)
                .rev()
                .find(|&s| fits(s))
                .unwrap_or(1);
            let style = TextStyle::new(s).anchor(HAlign::Center, VAlign::Top);
            canvas.text(w / 2, 10, &self.title, &style);
            canvas.text(w / 2 + 1, 10, &self.title, &style);
            top = 10 + font::text_height(s) as i64 + 4;
        }
        let mut report = RenderReport::default();
        for p in &self.panels {
            let (rows, cols) = (p.rows as i64, p.cols as i64);
            let (r, c) = (p.row as i64, p.col as i64);
            let area = Rect::new(
                c * w / cols,
                top + r * (h - top) / rows,
                (c + 1) * w / cols,
                top + (r + 1) * (h - top) / rows,
            );
            report.panels.push(render::panel(
                &mut canvas,
                &p.axes,
                area,
                self.text_scale,
                (p.row, p.col),
            )?);
        }
        Ok((canvas, report))
    }

    /// Renders and writes a PNG file; the report says which points were not drawn.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<RenderReport, PlotError> {
        let (canvas, report) = self.render()?;
        canvas.save_png(path)?;
        Ok(report)
    }
}

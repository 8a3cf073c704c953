//! Colours, the default series palette and continuous colour maps.

/// An 8-bit sRGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
}

impl Rgb {
    /// A colour from its three channels.
    pub const fn new(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b }
    }

    /// Straight interpolation `a + t (b − a)` per channel, `t` in [0, 1].
    pub fn lerp(a: Rgb, b: Rgb, t: f64) -> Rgb {
        let ch = |x: u8, y: u8| (x as f64 + t * (y as f64 - x as f64)).round() as u8;
        Rgb::new(ch(a.r, b.r), ch(a.g, b.g), ch(a.b, b.b))
    }
}

/// Black.
pub const BLACK: Rgb = Rgb::new(0, 0, 0);
/// White.
pub const WHITE: Rgb = Rgb::new(255, 255, 255);
/// Grey for secondary ink.
pub const GREY: Rgb = Rgb::new(128, 128, 128);
/// Light grey for grid lines.
pub const LIGHT_GREY: Rgb = Rgb::new(225, 225, 225);
/// Blue (first colour of the default palette).
pub const BLUE: Rgb = Rgb::new(31, 119, 180);
/// Orange.
pub const ORANGE: Rgb = Rgb::new(255, 127, 14);
/// Green.
pub const GREEN: Rgb = Rgb::new(44, 160, 44);
/// Red.
pub const RED: Rgb = Rgb::new(214, 39, 40);
/// Purple.
pub const PURPLE: Rgb = Rgb::new(148, 103, 189);
/// Brown.
pub const BROWN: Rgb = Rgb::new(140, 86, 75);

/// Series colours in order, for callers that colour series by index
/// (the widely used "category 10" hues; readable on white and distinct from each other).
pub const PALETTE: [Rgb; 6] = [BLUE, ORANGE, GREEN, RED, PURPLE, BROWN];

/// A continuous colour map from [0, 1] to colours.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Colormap {
    /// Perceptually uniform, dark blue-violet → green → yellow; readable in grey-scale
    /// print and by colour-blind readers (van der Walt & Smith 2015, matplotlib's
    /// default). The default, and the choice for damage D ∈ [0, 1].
    #[default]
    Viridis,
    /// Diverging blue → light grey → red, for signed quantities such as a velocity
    /// component (Moreland 2009, "Diverging color maps for scientific visualization").
    CoolWarm,
    /// Black → white.
    Greys,
}

/// Viridis at t = 0, 1/8, …, 1 (#440154, #472D7B, #3B528B, #2C728E, #21908C, #27AD81,
/// #5DC863, #AADC32, #FDE725: the published table at those positions). Linear
/// interpolation between these nine stops stays within a few 8-bit levels of the full
/// 256-entry table.
const VIRIDIS: [Rgb; 9] = [
    Rgb::new(68, 1, 84),
    Rgb::new(71, 45, 123),
    Rgb::new(59, 82, 139),
    Rgb::new(44, 114, 142),
    Rgb::new(33, 144, 140),
    Rgb::new(39, 173, 129),
    Rgb::new(93, 200, 99),
    Rgb::new(170, 220, 50),
    Rgb::new(253, 231, 37),
];

/// Moreland's cool-warm end points and a neutral midpoint (Moreland 2009, table 1).
const COOL_WARM: [Rgb; 3] = [
    Rgb::new(59, 76, 192),
    Rgb::new(221, 221, 221),
    Rgb::new(180, 4, 38),
];

const GREYS: [Rgb; 2] = [BLACK, WHITE];

impl Colormap {
    /// The colour at `t`. Values outside [0, 1] take the end colours: callers that
    /// map data count such values (see `SeriesReport::outside_color_range`). A NaN `t`
    /// gives the low end; plotted values are filtered for finiteness before this.
    pub fn at(self, t: f64) -> Rgb {
        let stops: &[Rgb] = match self {
            Colormap::Viridis => &VIRIDIS,
            Colormap::CoolWarm => &COOL_WARM,
            Colormap::Greys => &GREYS,
        };
        let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
        let pos = t * (stops.len() - 1) as f64;
        let i = (pos.floor() as usize).min(stops.len() - 2);
        Rgb::lerp(stops[i], stops[i + 1], pos - i as f64)
    }
}

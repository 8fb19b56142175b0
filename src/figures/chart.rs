//! The data of a figure: lines, axes, charts, pages, error maps, and the
//! helpers that choose axis ranges and steps. No drawing here.

use crate::paper::PAPER_F_STAR_MAX;

/// The colours of the curves (Okabe & Ito's palette, safe for colour
/// blindness), by [`Series::color`]; index 7 is black.
pub const PALETTE: [(u8, u8, u8); 8] = [
    (0, 114, 178),   // blue
    (213, 94, 0),    // vermillion
    (0, 158, 115),   // bluish green
    (204, 121, 167), // reddish purple
    (230, 159, 0),   // orange
    (86, 180, 233),  // sky blue
    (120, 120, 120), // grey
    (0, 0, 0),       // black
];

/// The palette index of black, for legend entries that explain a line style.
pub const BLACK_INDEX: usize = 7;

/// How a line is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// A continuous line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dashes, close together.
    Dotted,
    /// No line: the points are a polygon filled with a light tint of the
    /// colour (a range marked on the chart; drawn under the lines that
    /// follow it). Its legend sample is a tinted box.
    Shade,
    /// No line: a marker at each point (the series' markers' shape, a
    /// circle without), e.g. a load marked on a curve. Its legend sample
    /// is the marker alone.
    Points,
}

/// The shape of the markers along a line (filled, in the line's colour).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// ●
    Circle,
    /// ■
    Square,
    /// ▲
    Triangle,
    /// ◆
    Diamond,
    /// ▼
    TriangleDown,
}

/// Markers along a line, so that lines that run together stay apart: they
/// sit on a grid of [`Markers::PER_AXIS`] positions across the whole x axis,
/// shifted by `phase` of a grid step, so that lines with different phases
/// never put markers at the same x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Markers {
    /// The shape.
    pub shape: Shape,
    /// Shift of the grid, in grid steps, in [0, 1).
    pub phase: f64,
}

impl Markers {
    /// Marker positions across the width of the x axis.
    pub const PER_AXIS: usize = 12;
}

/// One line of a chart, in data units.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; `None` for no legend entry.
    pub label: Option<String>,
    /// The points (x, y); may be empty for a legend-only entry.
    pub points: Vec<(f64, f64)>,
    /// Index into [`PALETTE`].
    pub color: usize,
    /// Solid, dashed or dotted.
    pub style: LineStyle,
    /// Markers along the line (and on its legend entry), if any.
    pub markers: Option<Markers>,
}

impl Series {
    /// A solid line without markers.
    pub fn line(label: Option<String>, points: Vec<(f64, f64)>, color: usize) -> Series {
        Series {
            label,
            points,
            color,
            style: LineStyle::Solid,
            markers: None,
        }
    }
}

/// An axis of a chart (a plotting axis; [`crate::spline::Axis`] is a table's).
#[derive(Debug, Clone, PartialEq)]
pub struct ChartAxis {
    /// The axis title, with the paper's symbols.
    pub title: String,
    /// Logarithmic scale.
    pub log: bool,
    /// The range shown, in data units.
    pub range: (f64, f64),
    /// Labelled ticks in data units; `None`: decades for a log axis, round
    /// numbers for a linear one.
    pub ticks: Option<Vec<f64>>,
}

/// Where the legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Top left of the plotting area.
    UpperLeft,
    /// Top right.
    UpperRight,
    /// The corner (of the four) whose legend box covers the fewest of the
    /// lines' pixels: where the data is not.
    Clear,
}

/// A line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// The caption above the chart (`None` for a lower panel).
    pub title: Option<String>,
    /// Horizontal axis.
    pub x: ChartAxis,
    /// Vertical axis.
    pub y: ChartAxis,
    /// The lines, drawn in order.
    pub series: Vec<Series>,
    /// Where the legend goes.
    pub legend: Corner,
}

/// An image of one chart, or of a chart over a lower panel sharing its
/// horizontal axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Page {
    /// The main chart.
    pub top: Chart,
    /// An optional lower panel (2/5 of the height).
    pub bottom: Option<Chart>,
}

impl Page {
    /// A page of one chart.
    pub fn single(top: Chart) -> Page {
        Page { top, bottom: None }
    }
}

/// The table's relative error of μ over (ψ, F*) at one θ, against direct
/// integration, on a grid of cells equally spaced in ln ψ and ln F* over
/// the table's domain.
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorMap {
    /// The adhesion parameter of the map.
    pub theta: f64,
    /// Cell edges in ψ (`psi.len() − 1` rows).
    pub psi: Vec<f64>,
    /// Cell edges in F* (`f_star.len() − 1` columns).
    pub f_star: Vec<f64>,
    /// |μ_table/μ − 1| at each cell's centre, row by row (ψ major).
    pub rel: Vec<f64>,
    /// The tolerance the table promises.
    pub tolerance: f64,
}

impl ErrorMap {
    /// The largest error and the cell centre (ψ, F*) where it occurs.
    pub fn max(&self) -> (f64, f64, f64) {
        let cols = self.f_star.len() - 1;
        let (mut best, mut at) = (0.0, 0);
        for (i, &r) in self.rel.iter().enumerate() {
            if r > best {
                (best, at) = (r, i);
            }
        }
        let centre = |e: &[f64], k: usize| (e[k] * e[k + 1]).sqrt();
        (best, centre(&self.psi, at / cols), centre(&self.f_star, at % cols))
    }
}

/// `x` as the paper prints parameter values: 0.5, 2, 0.003, 0.0001.
pub(super) fn num(x: f64) -> String {
    format!("{x}")
}

/// The smallest and largest positive x and y over the series.
pub(super) fn extent(series: &[Series]) -> ((f64, f64), (f64, f64)) {
    let mut e = ((f64::INFINITY, 0.0_f64), (f64::INFINITY, 0.0_f64));
    for &(x, y) in series.iter().flat_map(|s| &s.points) {
        if x > 0.0 {
            e.0 = (e.0 .0.min(x), e.0 .1.max(x));
        }
        if y > 0.0 {
            e.1 = (e.1 .0.min(y), e.1 .1.max(y));
        }
    }
    e
}

/// A log range out to whole half-decades around `lo..hi`, leaving at
/// least 0.05 decades free at either end.
pub(super) fn log_range(lo: f64, hi: f64) -> (f64, f64) {
    let a = ((lo.log10() - 0.05) * 2.0).floor() / 2.0;
    let b = ((hi.log10() + 0.05) * 2.0).ceil() / 2.0;
    (10f64.powf(a), 10f64.powf(b))
}

/// A μ axis for `series`: logarithmic where μ spans more than a factor 10,
/// else linear from 0.
pub(super) fn mu_axis(series: &[Series]) -> ChartAxis {
    let (_, (lo, hi)) = extent(series);
    let log = hi / lo > 10.0;
    ChartAxis {
        title: "μ".into(),
        log,
        range: if log { log_range(lo, hi) } else { zero_to(hi) },
        ticks: None,
    }
}

/// A linear range from 0 to a round number above `hi`.
pub(super) fn zero_to(hi: f64) -> (f64, f64) {
    let step = nice_step(hi / 6.0);
    (0.0, ((hi * 1.04) / step).ceil() * step)
}

/// The F* axis of the paper's figures: logarithmic, up to 0.1.
pub(super) fn f_axis(series: &[Series]) -> ChartAxis {
    let lo = extent(series).0 .0;
    ChartAxis {
        title: "F*".into(),
        log: true,
        range: (log_range(lo, PAPER_F_STAR_MAX).0, PAPER_F_STAR_MAX),
        ticks: None,
    }
}

/// A round step near `x`: 1, 2, 2.5 or 5 times a power of ten.
pub(super) fn nice_step(x: f64) -> f64 {
    let p = 10f64.powf(x.log10().floor());
    let m = x / p;
    let k = if m <= 1.0 {
        1.0
    } else if m <= 2.0 {
        2.0
    } else if m <= 2.5 {
        2.5
    } else if m <= 5.0 {
        5.0
    } else {
        10.0
    };
    k * p
}

/// The superscript digits 0–9.
const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// 10 to the power `k`, with a superscript exponent: 10⁻³.
pub(super) fn pow10(k: i32) -> String {
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        s.push(SUPERSCRIPTS[c as usize - '0' as usize]);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decades_are_written_with_superscripts() {
        assert_eq!(pow10(-5), "10⁻⁵");
        assert_eq!(pow10(0), "10⁰");
        assert_eq!(pow10(12), "10¹²");
    }

    #[test]
    fn nice_steps_are_1_2_2_5_5_times_a_power_of_ten() {
        assert_eq!(nice_step(0.07), 0.1);
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(nice_step(1.5), 2.0);
        assert_eq!(nice_step(2.2), 2.5);
    }
}

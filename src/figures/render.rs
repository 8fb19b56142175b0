//! Drawing charts with plotters, to PNG (supersampled) or SVG.

use super::chart::{
    nice_step, num, pow10, Chart, ChartAxis, Corner, ErrorMap, LineStyle, Markers, Page, Shape, PALETTE,
};
use super::{size_at, FigureError, Format, BASE_SIZE, DEFAULT_SCALE};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

mod error_map;

/// DejaVu Sans (assets/DejaVuSans-LICENSE.txt), so that no system font is
/// needed at run time.
static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
/// The family name the charts ask for.
const FAMILY: &str = "sans-serif";

/// Registers the embedded font (once).
fn fonts() -> Result<(), String> {
    static DONE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *DONE.get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err("the embedded font could not be read".into())
    }
}

/// Something that draws itself on a drawing area of any backend, with
/// every length in pixels multiplied by `s`.
trait Render {
    fn render<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, s: u32) -> Result<(), String>;
}

/// PNGs are drawn this many times larger and averaged down: plotters does
/// not anti-alias lines, and thick polylines drawn at the final size look
/// jagged. At scale 3 the factor is 2 (a 6000 × 4500 canvas, 81 MB),
/// which the thicker lines need less.
fn supersample(scale: u32) -> u32 {
    if scale <= 2 {
        3
    } else {
        2
    }
}

/// Draws `what` into `path` at `scale`, PNG or SVG by its extension.
fn save(path: &Path, what: &impl Render, scale: u32) -> Result<(), FigureError> {
    let format = Format::from_path(path)?;
    let size = size_at(scale)?;
    let failed = |message: String| FigureError::Draw {
        path: path.display().to_string(),
        message,
    };
    // Drawn beside the output, then renamed over it, under a temporary
    // name that keeps the extension plotters' encoder reads.
    crate::io::replace_via(path, true, |tmp| {
        draw(tmp, format, size, what, scale).map_err(std::io::Error::other)
    })
    .map_err(|e| failed(e.to_string()))
}

/// Draws `what` into `path` (as `format`, at `size`).
fn draw(path: &Path, format: Format, size: (u32, u32), what: &impl Render, scale: u32) -> Result<(), String> {
    fonts().and_then(|()| match format {
        Format::Png => {
            let k = supersample(scale);
            let big = (size.0 * k, size.1 * k);
            let mut buf = vec![0u8; big.0 as usize * big.1 as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut buf, big).into_drawing_area();
                what.render(&root, scale * k)?;
                root.present().map_err(err)?;
            }
            let small = downsample(&buf, big, k);
            let mut png = BitMapBackend::new(path, size);
            png.blit_bitmap((0, 0), size, &small).map_err(err)?;
            png.present().map_err(err)
        }
        Format::Svg => {
            let root = SVGBackend::new(path, size).into_drawing_area();
            what.render(&root, scale)?;
            root.present().map_err(err)
        }
    })
}

/// Averages each `k`×`k` block of an RGB image of size `big`.
fn downsample(buf: &[u8], big: (u32, u32), k: u32) -> Vec<u8> {
    let (w, h) = ((big.0 / k) as usize, (big.1 / k) as usize);
    let (bw, k) = (big.0 as usize, k as usize);
    let n = (k * k) as u32;
    let mut out = vec![0u8; w * h * 3];
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0u32; 3];
            for dy in 0..k {
                let row = ((y * k + dy) * bw + x * k) * 3;
                for px in buf[row..row + 3 * k].chunks_exact(3) {
                    for (acc, &v) in sum.iter_mut().zip(px) {
                        *acc += u32::from(v);
                    }
                }
            }
            for (c, acc) in sum.iter().enumerate() {
                out[(y * w + x) * 3 + c] = ((acc + n / 2) / n) as u8;
            }
        }
    }
    out
}

impl Page {
    /// Draws the page into `path` ([`super::SIZE`] pixels; PNG or SVG by
    /// the extension).
    pub fn save(&self, path: &Path) -> Result<(), FigureError> {
        save(path, self, DEFAULT_SCALE)
    }

    /// Draws the page into `path` at `scale` ([`size_at`]).
    pub fn save_scaled(&self, path: &Path, scale: u32) -> Result<(), FigureError> {
        save(path, self, scale)
    }
}

impl ErrorMap {
    /// Draws the map and its colour bar into `path` ([`super::SIZE`]
    /// pixels; PNG or SVG by the extension).
    pub fn save(&self, path: &Path) -> Result<(), FigureError> {
        save(path, self, DEFAULT_SCALE)
    }

    /// Draws the map into `path` at `scale` ([`size_at`]).
    pub fn save_scaled(&self, path: &Path, scale: u32) -> Result<(), FigureError> {
        save(path, self, scale)
    }
}

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

fn rgb(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

// Sizes in pixels of an image at scale 1 (BASE_SIZE); every one is
// multiplied by the scale (and the supersampling).
const CAPTION_PX: u32 = 30;
const DESC_PX: u32 = 26;
const LABEL_PX: u32 = 22;
const LEGEND_PX: u32 = 22;
const LINE_PX: u32 = 3;
const X_AREA_PX: u32 = 75;
const Y_AREA_PX: u32 = 100;
const X_TICKS_ONLY_PX: u32 = 40;
const MARGIN_PX: u32 = 16;
const MARGIN_RIGHT_PX: u32 = 40;
const TICK_PX: u32 = 6;
const COLOUR_BAR_PX: u32 = 170;
/// Half the width of a line's marker.
const MARKER_PX: u32 = 7;
/// The white rim around a marker, which keeps it apart from lines.
const MARKER_RIM_PX: u32 = 2;
/// The radius of the ring around the error map's largest error.
const RING_PX: u32 = 12;
/// Dash and gap of a dashed line; of a dotted one.
const DASH_PX: (u32, u32) = (14, 9);
const DOT_PX: (u32, u32) = (3, 6);
/// The opacity of a shaded range ([`LineStyle::Shade`]) over the white page.
const SHADE_ALPHA: f64 = 0.08;

/// A tick label: a decade as 10ᵏ, a small or large number as m×10ᵏ,
/// others in plain decimals suited to the step.
fn tick_label(v: f64, step: f64) -> String {
    if v.abs() < step * 1e-6 {
        return "0".into();
    }
    let big = v.abs().max(step);
    if !(1e-2..1e4).contains(&big) {
        let k = v.abs().log10().floor() as i32;
        let m = v / 10f64.powi(k);
        let m = (m * 100.0).round() / 100.0;
        return format!("{}×{}", num(m).replace('-', "−"), pow10(k));
    }
    let decimals = (-(step.log10().floor()) as i32).max(0) as usize
        + usize::from((step / 10f64.powf(step.log10().floor()) - 2.5).abs() < 1e-9);
    format!("{v:.decimals$}").replace('-', "−")
}

impl ChartAxis {
    /// Data value → plotting coordinate (log10 on a log axis).
    fn to_plot(&self, v: f64) -> f64 {
        if self.log {
            v.log10()
        } else {
            v
        }
    }

    /// Plotting coordinate → data value.
    fn to_data(&self, u: f64) -> f64 {
        if self.log {
            10f64.powf(u)
        } else {
            u
        }
    }

    /// The labelled ticks and the light grid lines, in plotting coordinates,
    /// and the step used for labels.
    fn ticks(&self) -> (Vec<f64>, Vec<f64>, f64) {
        let (a, b) = (self.to_plot(self.range.0), self.to_plot(self.range.1));
        let eps = 1e-9 * (b - a);
        if let Some(t) = &self.ticks {
            let major: Vec<f64> = t.iter().map(|&v| self.to_plot(v)).collect();
            return (major, Vec::new(), 1.0);
        }
        if self.log {
            // Decades; on a short axis (under 2.5 decades) also 2× and 5×.
            let labelled: &[i32] = if b - a < 2.5 { &[1, 2, 5] } else { &[1] };
            let (mut major, mut minor) = (Vec::new(), Vec::new());
            for k in (a.floor() as i32)..=(b.ceil() as i32) {
                for m in 1..=9 {
                    let u = f64::from(k) + f64::from(m).log10();
                    if u > a - eps && u < b + eps {
                        if labelled.contains(&m) {
                            major.push(u);
                        } else {
                            minor.push(u);
                        }
                    }
                }
            }
            (major, minor, 1.0)
        } else {
            let step = nice_step((b - a) / 6.0);
            let first = (a / step - 1e-9).ceil() as i64;
            let last = (b / step + 1e-9).floor() as i64;
            let major = (first..=last).map(|i| i as f64 * step).collect();
            let fine = step / 5.0;
            let minor = (((a / fine) - 1e-9).ceil() as i64..=((b / fine) + 1e-9).floor() as i64)
                .filter(|i| i % 5 != 0)
                .map(|i| i as f64 * fine)
                .collect();
            (major, minor, step)
        }
    }

    /// The plotting coordinate with its ticks.
    fn coord(&self) -> Ticked {
        let (major, minor, _) = self.ticks();
        Ticked {
            inner: (self.to_plot(self.range.0)..self.to_plot(self.range.1)).into(),
            major,
            minor,
        }
    }

    /// The label of the tick at plotting coordinate `u`.
    fn label(&self, u: f64) -> String {
        if self.ticks.is_some() {
            return num((self.to_data(u) * 1e6).round() / 1e6);
        }
        if self.log {
            let k = u.round();
            if (u - k).abs() < 1e-6 {
                pow10(k as i32)
            } else {
                let k = u.floor();
                format!("{}×{}", 10f64.powf(u - k).round(), pow10(k as i32))
            }
        } else {
            tick_label(u, self.ticks().2)
        }
    }
}

/// A linear plotting coordinate (data are mapped through log10 for log
/// axes beforehand) with ticks and light grid lines chosen here, not by
/// plotters: decades and 2…9 subdivisions on log axes.
struct Ticked {
    inner: RangedCoordf64,
    major: Vec<f64>,
    minor: Vec<f64>,
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.major.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
}

type Plot<'a, DB> = ChartContext<'a, DB, Cartesian2d<Ticked, Ticked>>;

/// The chart's frame, mesh and labels on `area`.
fn frame<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: Option<&str>,
    x: &ChartAxis,
    y: &ChartAxis,
    grid: bool,
    y_area: u32,
    s: u32,
) -> Result<Plot<'a, DB>, String> {
    let font: TextStyle = (FAMILY, CAPTION_PX * s).into_font().into();
    // The caption is centred between the margins, and must not reach over
    // the vertical axis's tick labels on the left (the top one rises above
    // the plotting area; the axis title, further left, sits lower): as
    // much room on the right.
    let ticks = y_area.saturating_sub(DESC_PX * s) as i32;
    let room = area.dim_in_pixel().0 as i32 - 2 * ticks - ((MARGIN_PX + MARGIN_RIGHT_PX) * s) as i32;
    let lines = match title {
        Some(t) => wrap(t, room, |text| {
            area.estimate_text_size(text, &font).map_or(i32::MAX, |(w, _)| w as i32)
        }),
        None => Vec::new(),
    };
    // A title that fits is the builder's caption (as it always was); a
    // longer one is wrapped into lines drawn above the chart's area.
    let below_title;
    let on = if lines.len() > 1 {
        let mut a = area.margin(MARGIN_PX * s, 0, 0, 0);
        for line in &lines {
            a = a.titled(line, font.clone()).map_err(err)?;
        }
        below_title = a;
        &below_title
    } else {
        area
    };
    let mut builder = ChartBuilder::on(on);
    builder
        .margin(MARGIN_PX * s)
        .margin_right(MARGIN_RIGHT_PX * s)
        .x_label_area_size(if x.title.is_empty() { X_TICKS_ONLY_PX } else { X_AREA_PX } * s)
        .y_label_area_size(y_area);
    if lines.len() > 1 {
        builder.margin_top(0);
    } else if let Some(t) = title {
        builder.caption(t, font);
    }
    let mut chart = builder.build_cartesian_2d(x.coord(), y.coord()).map_err(err)?;
    let fx = |u: &f64| x.label(*u);
    let fy = |u: &f64| y.label(*u);
    let mut mesh = chart.configure_mesh();
    mesh.x_label_formatter(&fx)
        .y_label_formatter(&fy)
        .x_desc(x.title.as_str())
        .y_desc(y.title.as_str())
        .axis_desc_style((FAMILY, DESC_PX * s))
        .label_style((FAMILY, LABEL_PX * s))
        .axis_style(BLACK.stroke_width(s))
        .bold_line_style(BLACK.mix(0.16).stroke_width(s))
        .light_line_style(BLACK.mix(0.045).stroke_width(s))
        .set_all_tick_mark_size(TICK_PX * s);
    if !grid {
        mesh.disable_mesh();
    }
    mesh.draw().map_err(err)?;
    Ok(chart)
}

/// `text` in lines at most `room` pixels wide by `width` (a text's
/// width in pixels): broken after a comma where one fits, else between
/// words; a single word wider than `room` is shortened with "…". One
/// line when it all fits.
fn wrap(text: &str, room: i32, width: impl Fn(&str) -> i32) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    // Pieces that end after ", " (kept with the piece before), then words.
    let push = |piece: &str, lines: &mut Vec<String>, line: &mut String| {
        let joined = format!("{line}{piece}");
        if line.is_empty() || width(joined.trim_end()) <= room {
            *line = joined;
        } else {
            lines.push(line.trim_end().to_string());
            *line = piece.to_string();
        }
    };
    for chunk in text.split_inclusive(", ") {
        if width(chunk.trim_end()) <= room {
            push(chunk, &mut lines, &mut line);
            continue;
        }
        // Words, with "=" kept between its two sides (`ψ = 1` is one).
        let mut words: Vec<String> = Vec::new();
        for token in chunk.split_inclusive(' ') {
            match words.last_mut() {
                Some(last) if token.trim() == "=" || last.trim_end().ends_with(" =") || last.trim() == "=" => {
                    last.push_str(token)
                }
                _ => words.push(token.to_string()),
            }
        }
        for word in words {
            let mut word = word;
            if width(word.trim_end()) > room {
                let mut kept: String = word.trim_end().to_string();
                while !kept.is_empty() && width(&format!("{kept}…")) > room {
                    kept.pop();
                }
                word = format!("{kept}… ");
            }
            push(&word, &mut lines, &mut line);
        }
    }
    if !line.trim_end().is_empty() || lines.is_empty() {
        lines.push(line.trim_end().to_string());
    }
    lines
}

/// A box around the plotting area.
fn border<DB: DrawingBackend>(chart: &Plot<'_, DB>, s: u32) -> Result<(), String> {
    let area = chart.plotting_area();
    let (w, h) = area.dim_in_pixel();
    area.strip_coord_spec()
        .draw(&Rectangle::new(
            [(0, 0), (w as i32 - 1, h as i32 - 1)],
            BLACK.stroke_width(s),
        ))
        .map_err(err)
}

/// The width of the vertical axis's label area: room for the widest tick
/// label, the ticks and the axis title.
fn y_area<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, y: &ChartAxis, s: u32) -> Result<u32, String> {
    let font: TextStyle = (FAMILY, LABEL_PX * s).into_font().into();
    let mut widest = 0;
    for u in y.ticks().0 {
        widest = widest.max(area.estimate_text_size(&y.label(u), &font).map_err(err)?.0);
    }
    Ok((Y_AREA_PX * s).max(widest + (DESC_PX + TICK_PX + 34) * s))
}

/// The outline of `shape` of half-width `r` around the origin, in pixels
/// (a circle as a 24-gon). Triangles are a little larger, so that all
/// shapes look alike in weight.
fn outline(shape: Shape, r: i32) -> Vec<(i32, i32)> {
    let rf = f64::from(r);
    let t = rf * 1.3;
    let pts: Vec<(f64, f64)> = match shape {
        Shape::Circle => (0..24)
            .map(|k| {
                let a = std::f64::consts::TAU * f64::from(k) / 24.0;
                (rf * a.cos(), rf * a.sin())
            })
            .collect(),
        Shape::Square => vec![(-rf, -rf), (rf, -rf), (rf, rf), (-rf, rf)],
        Shape::Diamond => {
            let d = rf * 1.4;
            vec![(0.0, -d), (d, 0.0), (0.0, d), (-d, 0.0)]
        }
        Shape::Triangle => vec![(0.0, -t), (t * 1.15, t * 0.6), (-t * 1.15, t * 0.6)],
        Shape::TriangleDown => vec![(0.0, t), (t * 1.15, -t * 0.6), (-t * 1.15, -t * 0.6)],
    };
    pts.into_iter()
        .map(|(x, y)| (x.round() as i32, y.round() as i32))
        .collect()
}

/// A marker at the pixel `at` of `area`: `shape` filled in `colour` on a
/// white rim, which keeps it apart from the lines it sits on.
fn draw_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x, y): (i32, i32),
    shape: Shape,
    colour: RGBColor,
    s: u32,
) -> Result<(), String> {
    let r = (MARKER_PX * s) as i32;
    let at = |v: Vec<(i32, i32)>| v.into_iter().map(|(dx, dy)| (x + dx, y + dy)).collect::<Vec<_>>();
    area.draw(&Polygon::new(
        at(outline(shape, r + (MARKER_RIM_PX * s) as i32)),
        WHITE.filled(),
    ))
    .map_err(err)?;
    area.draw(&Polygon::new(at(outline(shape, r)), colour.filled()))
        .map_err(err)
}

/// The pixel of the data point `(u, v)` (plotting coordinates) in the
/// plotting area of `chart`, counted from its upper left corner.
fn pixel<DB: DrawingBackend>(chart: &Plot<'_, DB>, u: f64, v: f64) -> (i32, i32) {
    let plot = chart.plotting_area();
    let base = plot.get_base_pixel();
    let (a, b) = plot.map_coordinate(&(u, v));
    (a - base.0, b - base.1)
}

/// Where the markers of a line go, in plotting coordinates: the x of the
/// grid of [`Markers::PER_AXIS`] steps across the axis `x_range`, shifted by
/// the phase, that fall inside the line's extent; y interpolated linearly
/// between the line's points.
fn marker_positions(pts: &[(f64, f64)], m: Markers, x_range: (f64, f64)) -> Vec<(f64, f64)> {
    let mut pts = pts.to_vec();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (Some(first), Some(last)) = (pts.first(), pts.last()) else {
        return Vec::new();
    };
    let (lo, hi) = (first.0, last.0);
    let step = (x_range.1 - x_range.0) / Markers::PER_AXIS as f64;
    let mut out = Vec::new();
    for k in 0..=Markers::PER_AXIS {
        let u = x_range.0 + (k as f64 + m.phase + 0.5) * step;
        // Not within a quarter step of the frame, where a marker would
        // cross it.
        let from_frame = (u - x_range.0).min(x_range.1 - u) / step;
        if u < lo || u > hi || from_frame < 0.25 {
            continue;
        }
        let j = pts.partition_point(|p| p.0 < u).clamp(1, pts.len() - 1);
        let ((x0, y0), (x1, y1)) = (pts[j - 1], pts[j]);
        let t = if x1 > x0 { (u - x0) / (x1 - x0) } else { 0.0 };
        out.push((u, y0 + t * (y1 - y0)));
    }
    out
}

fn draw_chart<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, c: &Chart, y_area: u32, s: u32) -> Result<(), String> {
    let mut chart = frame(area, c.title.as_deref(), &c.x, &c.y, true, y_area, s)?;
    let si = s as i32;
    let x_range = (c.x.to_plot(c.x.range.0), c.x.to_plot(c.x.range.1));
    for line in &c.series {
        let colour = rgb(line.color);
        let style = colour.stroke_width(LINE_PX * s);
        let pts: Vec<(f64, f64)> = line
            .points
            .iter()
            .filter(|&&(x, y)| (!c.x.log || x > 0.0) && (!c.y.log || y > 0.0))
            .map(|&(x, y)| (c.x.to_plot(x), c.y.to_plot(y)))
            .collect();
        match line.style {
            LineStyle::Solid => chart.draw_series(LineSeries::new(pts.clone(), style)),
            LineStyle::Dashed => chart.draw_series(DashedLineSeries::new(
                pts.clone(),
                DASH_PX.0 as i32 * si,
                DASH_PX.1 as i32 * si,
                style,
            )),
            LineStyle::Dotted => chart.draw_series(DashedLineSeries::new(
                pts.clone(),
                DOT_PX.0 as i32 * si,
                DOT_PX.1 as i32 * si,
                style,
            )),
            LineStyle::Shade => chart.draw_series(std::iter::once(Polygon::new(
                pts.clone(),
                colour.mix(SHADE_ALPHA).filled(),
            ))),
            LineStyle::Points => {
                let area = chart.plotting_area().strip_coord_spec();
                let shape = line.markers.map_or(Shape::Circle, |m| m.shape);
                for &(u, v) in &pts {
                    draw_marker(&area, pixel(&chart, u, v), shape, colour, s)?;
                }
                continue;
            }
        }
        .map_err(err)?;
        if let Some(m) = line.markers {
            let area = chart.plotting_area().strip_coord_spec();
            for (u, v) in marker_positions(&pts, m, x_range) {
                draw_marker(&area, pixel(&chart, u, v), m.shape, colour, s)?;
            }
        }
    }
    border(&chart, s)?;
    legend(&chart, c, s)
}

/// The legend: a box in the chart's upper corner with, per labelled line,
/// a sample of its stroke and marker and its label. Drawn here rather than
/// by plotters so that the samples carry the markers.
fn legend<DB: DrawingBackend>(chart: &Plot<'_, DB>, c: &Chart, s: u32) -> Result<(), String> {
    let entries: Vec<_> = c.series.iter().filter(|l| l.label.is_some()).collect();
    if entries.is_empty() {
        return Ok(());
    }
    let si = s as i32;
    let area = chart.plotting_area().strip_coord_spec();
    let font: TextStyle = (FAMILY, LEGEND_PX * s).into_font().into();
    let font = font.pos(Pos::new(HPos::Left, VPos::Center));
    let (pad, sample, gap, row) = (10 * si, 40 * si, 10 * si, 31 * si);
    let mut text_w = 0;
    for l in &entries {
        let label = l.label.as_deref().unwrap_or_default();
        text_w = text_w.max(area.estimate_text_size(label, &font).map_err(err)?.0 as i32);
    }
    let w = pad + sample + gap + text_w + pad;
    let h = 2 * pad + row * entries.len() as i32 - (row - LEGEND_PX as i32 * si);
    let (aw, ah) = area.dim_in_pixel();
    let inset = 12 * si;
    let left = inset;
    let right = aw as i32 - w - inset;
    let (x, y) = match c.legend {
        Corner::UpperLeft => (left, inset),
        Corner::UpperRight => (right, inset),
        Corner::Clear => {
            let bottom = ah as i32 - h - inset;
            let lines = lines_in_pixels(chart, c);
            // The upper corners first, then the lower ones; ties keep the
            // earlier.
            [(right, inset), (left, inset), (right, bottom), (left, bottom)]
                .into_iter()
                .min_by_key(|&(x, y)| covered(&lines, (x, y), (w, h), si))
                .unwrap_or((right, inset))
        }
    };
    area.draw(&Rectangle::new([(x, y), (x + w, y + h)], WHITE.mix(0.92).filled()))
        .map_err(err)?;
    area.draw(&Rectangle::new(
        [(x, y), (x + w, y + h)],
        BLACK.mix(0.5).stroke_width(s),
    ))
    .map_err(err)?;
    for (k, l) in entries.iter().enumerate() {
        let cy = y + pad + LEGEND_PX as i32 * si / 2 + row * k as i32;
        let (x0, x1) = (x + pad, x + pad + sample);
        let colour = rgb(l.color);
        let style = colour.stroke_width(LINE_PX * s);
        let seg = vec![(x0, cy), (x1, cy)];
        match l.style {
            LineStyle::Solid => area.draw(&PathElement::new(seg, style)),
            LineStyle::Dashed => area.draw(&DashedPathElement::new(seg, 10 * si, 6 * si, style)),
            LineStyle::Dotted => area.draw(&DashedPathElement::new(
                seg,
                DOT_PX.0 as i32 * si,
                DOT_PX.1 as i32 * si,
                style,
            )),
            LineStyle::Shade => area.draw(&Rectangle::new(
                [(x0, cy - 8 * si), (x1, cy + 8 * si)],
                colour.mix(SHADE_ALPHA).filled(),
            )),
            LineStyle::Points => Ok(()),
        }
        .map_err(err)?;
        if let Some(m) = l.markers {
            draw_marker(&area, ((x0 + x1) / 2, cy), m.shape, colour, s)?;
        } else if l.style == LineStyle::Points {
            draw_marker(&area, ((x0 + x1) / 2, cy), Shape::Circle, colour, s)?;
        }
        let label = l.label.as_deref().unwrap_or_default();
        area.draw(&Text::new(label, (x1 + gap, cy), font.clone()))
            .map_err(err)?;
    }
    Ok(())
}

/// The lines of `c` (and where their markers go) in the pixels of the
/// plotting area of `chart`.
fn lines_in_pixels<DB: DrawingBackend>(chart: &Plot<'_, DB>, c: &Chart) -> Vec<Vec<(i32, i32)>> {
    c.series
        .iter()
        .map(|line| {
            line.points
                .iter()
                .filter(|&&(x, y)| (!c.x.log || x > 0.0) && (!c.y.log || y > 0.0))
                .map(|&(x, y)| pixel(chart, c.x.to_plot(x), c.y.to_plot(y)))
                .collect()
        })
        .collect()
}

/// How much of `lines` (pixel polylines) a box at `at` of `size` covers,
/// with a margin of the lines' and markers' half-width (`s` the scale):
/// the number of points, every pixel or so along each line, inside it.
fn covered(lines: &[Vec<(i32, i32)>], at: (i32, i32), size: (i32, i32), s: i32) -> usize {
    let pad = (MARKER_PX + MARKER_RIM_PX) as i32 * s;
    let (x0, y0, x1, y1) = (at.0 - pad, at.1 - pad, at.0 + size.0 + pad, at.1 + size.1 + pad);
    let inside = |x: f64, y: f64| x >= f64::from(x0) && x <= f64::from(x1) && y >= f64::from(y0) && y <= f64::from(y1);
    let mut n = 0;
    for line in lines {
        if let [only] = line[..] {
            n += usize::from(inside(f64::from(only.0), f64::from(only.1)));
        }
        for pair in line.windows(2) {
            let ((ax, ay), (bx, by)) = (pair[0], pair[1]);
            let (dx, dy) = (f64::from(bx - ax), f64::from(by - ay));
            // Steps of about a pixel; a segment far outside the image
            // (a point off the axis) counts at most 10000 steps.
            let steps = dx.abs().max(dy.abs()).clamp(1.0, 1e4) as usize;
            n += (0..=steps)
                .filter(|&k| {
                    let t = k as f64 / steps as f64;
                    inside(f64::from(ax) + t * dx, f64::from(ay) + t * dy)
                })
                .count();
        }
    }
    n
}

impl Render for Page {
    fn render<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, s: u32) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let mut width = y_area(root, &self.top.y, s)?;
        match &self.bottom {
            None => draw_chart(root, &self.top, width, s),
            Some(bottom) => {
                // The same label width in both panels keeps their F* axes aligned.
                width = width.max(y_area(root, &bottom.y, s)?);
                let (upper, lower) = root.split_vertically(BASE_SIZE.1 * 3 / 5 * s);
                draw_chart(&upper, &self.top, width, s)?;
                draw_chart(&lower, bottom, width, s)
            }
        }
    }
}

#[cfg(test)]
mod tests;

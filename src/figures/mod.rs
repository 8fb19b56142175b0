//! The paper's figures 3–6, a μ(F*) curve for any parameters, and a
//! table's error map, drawn with plotters to PNG or SVG (chosen by the
//! file's extension).
//!
//! Each figure is first computed as data ([`Page`], [`ErrorMap`]), then
//! drawn ([`Page::save`], [`ErrorMap::save`]). Curves follow the paper's
//! range (its section "Results"): [`H_SAMPLES`] separations equally spaced
//! over 0 ≤ h* ≤ 3, keeping the loads 0 < F* ≤ 0.1; where F*(h* = 0) > 0.1
//! the curve is closed exactly at F* = 0.1.
//!
//! ```no_run
//! use ke_friction::figures::Figure;
//! Figure::Fig5.page()?.save("fig5.png".as_ref())?;
//! # Ok::<(), ke_friction::figures::FigureError>(())
//! ```

use crate::{Contact, EvalError, Kind, LookupError, Model, ParamError, Params, Table};
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

/// Width and height of every image, in pixels (readable at 100%).
pub const SIZE: (u32, u32) = (1000, 750);
/// Separations sampled per curve over 0 ≤ h* ≤ 3.
pub const H_SAMPLES: usize = 200;
use crate::paper::PAPER_F_STAR_MAX;
/// θ of the paper's figures 3–5.
pub const PAPER_THETA: f64 = 0.003;

/// DejaVu Sans (assets/DejaVuSans-LICENSE.txt), so that no system font is
/// needed at run time.
static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
/// The family name the charts ask for.
const FAMILY: &str = "sans-serif";

/// A figure that cannot be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FigureError {
    /// The output file's extension is neither `.png` nor `.svg`.
    #[error("{path}: unknown image format {ext:?}: the name must end in .png or .svg")]
    Format {
        /// The output path.
        path: String,
        /// Its extension (empty if none).
        ext: String,
    },
    /// Invalid model parameters.
    #[error(transparent)]
    Params(#[from] ParamError),
    /// An evaluation failed.
    #[error(transparent)]
    Eval(#[from] EvalError),
    /// A query outside the table's domain.
    #[error(transparent)]
    Lookup(#[from] LookupError),
    /// The table was built for other model constants than those asked for.
    #[error("the table holds {table}, not {asked}")]
    TableMismatch {
        /// The table's constants.
        table: String,
        /// The requested ones.
        asked: String,
    },
    /// Nothing to draw: no load in the plotted range.
    #[error("nothing to draw: {0}")]
    Empty(String),
    /// The drawing or the writing of the file failed.
    #[error("cannot draw {path}: {message}")]
    Draw {
        /// The output path.
        path: String,
        /// What went wrong.
        message: String,
    },
}

/// An image format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// PNG bitmap.
    Png,
    /// SVG vector graphics.
    Svg,
}

impl Format {
    /// The format named by `path`'s extension (`.png` or `.svg`, any case).
    pub fn from_path(path: &Path) -> Result<Format, FigureError> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        match ext.as_str() {
            "png" => Ok(Format::Png),
            "svg" => Ok(Format::Svg),
            _ => Err(FigureError::Format {
                path: path.display().to_string(),
                ext,
            }),
        }
    }
}

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

/// One line of a chart, in data units.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text; `None` for no legend entry.
    pub label: Option<String>,
    /// The points (x, y); may be empty for a legend-only entry.
    pub points: Vec<(f64, f64)>,
    /// Index into [`PALETTE`].
    pub color: usize,
    /// Dashed instead of solid.
    pub dashed: bool,
}

/// An axis of a chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
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
    /// Bottom left.
    LowerLeft,
    /// Bottom right.
    LowerRight,
}

/// A line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// The caption above the chart (`None` for a lower panel).
    pub title: Option<String>,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
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

/// The paper's figures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Figure {
    /// Fs*/P* against F* for ψ = 0.5, 1, 2, 4, 8 at θ = 0.003.
    Fig3,
    /// Q* against F* (log–log), same ψ and θ.
    Fig4,
    /// μ against F* for ψ = 0.5, 1, 2 at θ = 0.003, with the CEB-type model.
    Fig5,
    /// μ against F* for ψ = 0.5 and 2 at θ = 1e-4, 1e-3, 3e-3.
    Fig6,
}

impl Figure {
    /// All four, in order.
    pub const ALL: [Figure; 4] = [Figure::Fig3, Figure::Fig4, Figure::Fig5, Figure::Fig6];

    /// `fig3` … `fig6`.
    pub fn name(self) -> &'static str {
        match self {
            Figure::Fig3 => "fig3",
            Figure::Fig4 => "fig4",
            Figure::Fig5 => "fig5",
            Figure::Fig6 => "fig6",
        }
    }

    /// The figure as data.
    pub fn page(self) -> Result<Page, FigureError> {
        Ok(Page {
            top: match self {
                Figure::Fig3 => fig3()?,
                Figure::Fig4 => fig4()?,
                Figure::Fig5 => fig5()?,
                Figure::Fig6 => fig6()?,
            },
            bottom: None,
        })
    }
}

/// Writes fig3.png … fig6.png into `dir` (which must exist); returns the
/// paths written.
pub fn save_all(dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let mut out = Vec::new();
    for fig in Figure::ALL {
        let path = dir.join(format!("{}.png", fig.name()));
        fig.page()?.save(&path)?;
        out.push(path);
    }
    Ok(out)
}

/// The contacts of a curve in the paper's range: [`H_SAMPLES`] separations
/// over 0 ≤ h* ≤ 3 with 0 < F* ≤ 0.1, ordered by decreasing F*; if F* > 0.1
/// at h* = 0, the contact at F* = 0.1 exactly comes first.
pub fn paper_sweep(model: &Model) -> Result<Vec<Contact>, FigureError> {
    let mut out = Vec::with_capacity(H_SAMPLES + 1);
    for (i, h) in crate::paper::h_points(H_SAMPLES).enumerate() {
        let c = model.at_h_star(h)?;
        if c.f_star > PAPER_F_STAR_MAX {
            continue;
        }
        if c.f_star <= 0.0 {
            break;
        }
        if out.is_empty() && i > 0 {
            out.push(model.at_f_star(PAPER_F_STAR_MAX)?);
        }
        out.push(c);
    }
    Ok(out)
}

fn model(psi: f64, theta: f64, kind: Kind) -> Result<Model, FigureError> {
    Ok(Model::new(Params::new(psi, theta).kind(kind))?)
}

/// `x` as the paper prints parameter values: 0.5, 2, 0.003, 0.0001.
fn num(x: f64) -> String {
    format!("{x}")
}

fn psi_label(psi: f64) -> String {
    format!("ψ = {}", num(psi))
}

/// The smallest and largest positive x and y over the series.
fn extent(series: &[Series]) -> ((f64, f64), (f64, f64)) {
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
fn log_range(lo: f64, hi: f64) -> (f64, f64) {
    let a = ((lo.log10() - 0.05) * 2.0).floor() / 2.0;
    let b = ((hi.log10() + 0.05) * 2.0).ceil() / 2.0;
    (10f64.powf(a), 10f64.powf(b))
}

/// A linear range from 0 to a round number above `hi`.
fn zero_to(hi: f64) -> (f64, f64) {
    let step = nice_step(hi / 6.0);
    (0.0, ((hi * 1.04) / step).ceil() * step)
}

/// The F* axis of the paper's figures: logarithmic, up to 0.1.
fn f_axis(series: &[Series]) -> Axis {
    let lo = extent(series).0 .0;
    Axis {
        title: "F*".into(),
        log: true,
        range: (log_range(lo, PAPER_F_STAR_MAX).0, PAPER_F_STAR_MAX),
        ticks: None,
    }
}

/// A chart against F* (log) with a linear y axis from zero, its legend
/// upper right.
fn linear_chart(title: &str, y_title: &str, series: Vec<Series>) -> Chart {
    let y = extent(&series).1;
    Chart {
        title: Some(title.into()),
        x: f_axis(&series),
        y: Axis {
            title: y_title.into(),
            log: false,
            range: zero_to(y.1),
            ticks: None,
        },
        series,
        legend: Corner::UpperRight,
    }
}

/// One curve `(F*, y)` per ψ = 0.5, 1, 2, 4, 8 at θ = 0.003 (Figs. 3 and 4).
fn psi_series(y: impl Fn(&Contact) -> f64) -> Result<Vec<Series>, FigureError> {
    let mut series = Vec::new();
    for (k, psi) in [0.5, 1.0, 2.0, 4.0, 8.0].into_iter().enumerate() {
        let m = model(psi, PAPER_THETA, Kind::KogutEtsion)?;
        series.push(Series {
            label: Some(psi_label(psi)),
            points: paper_sweep(&m)?.iter().map(|c| (c.f_star, y(c))).collect(),
            color: k,
            dashed: false,
        });
    }
    Ok(series)
}

/// Fig. 3: Fs*/P* against F*, ψ = 0.5, 1, 2, 4, 8, θ = 0.003.
fn fig3() -> Result<Chart, FigureError> {
    Ok(linear_chart(
        "Fig. 3: adhesion force ratio Fₛ*/P*, θ = 0.003",
        "Fₛ*/P*",
        psi_series(|c| c.fs_star / c.p_star)?,
    ))
}

/// Fig. 4: Q* against F*, log–log, ψ = 0.5, 1, 2, 4, 8, θ = 0.003.
fn fig4() -> Result<Chart, FigureError> {
    let series = psi_series(|c| c.q_star)?;
    let y = extent(&series).1;
    Ok(Chart {
        title: Some("Fig. 4: static friction force Q*, θ = 0.003".into()),
        x: f_axis(&series),
        y: Axis {
            title: "Q*".into(),
            log: true,
            range: log_range(y.0, y.1),
            ticks: None,
        },
        series,
        legend: Corner::UpperLeft,
    })
}

/// μ(F*) along the paper's sweep.
fn mu_points(model: &Model) -> Result<Vec<(f64, f64)>, FigureError> {
    Ok(paper_sweep(model)?
        .iter()
        .filter_map(|c| c.mu.map(|mu| (c.f_star, mu)))
        .collect())
}

/// Legend entries that explain line styles.
fn style_entry(label: &str, dashed: bool) -> Series {
    Series {
        label: Some(label.into()),
        points: Vec::new(),
        color: BLACK_INDEX,
        dashed,
    }
}

/// Fig. 5: μ against F*, ψ = 0.5, 1, 2, θ = 0.003; Kogut–Etsion solid,
/// CEB-type (MODEL.md §8) dashed.
fn fig5() -> Result<Chart, FigureError> {
    let mut series = Vec::new();
    for (k, psi) in [0.5, 1.0, 2.0].into_iter().enumerate() {
        for kind in [Kind::KogutEtsion, Kind::CebType] {
            let m = model(psi, PAPER_THETA, kind)?;
            series.push(Series {
                label: (kind == Kind::KogutEtsion).then(|| psi_label(psi)),
                points: mu_points(&m)?,
                color: k,
                dashed: kind == Kind::CebType,
            });
        }
    }
    series.push(style_entry("Kogut–Etsion", false));
    series.push(style_entry("CEB-type (approx.)", true));
    Ok(linear_chart(
        "Fig. 5: static friction coefficient μ, θ = 0.003",
        "μ",
        series,
    ))
}

/// Fig. 6: μ against F*, ψ = 0.5 (solid) and 2 (dashed), θ = 1e-4, 1e-3,
/// 3e-3 (colours).
fn fig6() -> Result<Chart, FigureError> {
    let mut series = Vec::new();
    for (j, psi) in [0.5, 2.0].into_iter().enumerate() {
        for (k, theta) in [1e-4, 1e-3, 3e-3].into_iter().enumerate() {
            let m = model(psi, theta, Kind::KogutEtsion)?;
            series.push(Series {
                label: (j == 0).then(|| format!("θ = {}", num(theta))),
                points: mu_points(&m)?,
                color: k,
                dashed: j == 1,
            });
        }
    }
    series.push(style_entry("ψ = 0.5", false));
    series.push(style_entry("ψ = 2", true));
    Ok(linear_chart(
        "Fig. 6: effect of the adhesion parameter θ on μ",
        "μ",
        series,
    ))
}

/// The model constants a table holds, or a curve asks for, in words.
fn constants(p: &Params) -> String {
    format!(
        "beta = {}, nu = {}, eps_star = {}, fit {:?}, model {:?}",
        p.beta, p.nu, p.eps_star, p.fit, p.kind
    )
}

/// μ against F* for `model` by direct integration over the paper's range;
/// with a table, its lookup overlaid (dashed) and, in a lower panel, the
/// relative difference μ_table/μ − 1 at the loads inside the table's domain.
pub fn curve(model: &Model, table: Option<&Table>) -> Result<Page, FigureError> {
    let params = *model.params();
    let name = match params.kind {
        Kind::KogutEtsion => "Kogut–Etsion",
        Kind::CebType => "CEB-type (approx.)",
    };
    let direct = mu_points(model)?;
    if direct.is_empty() {
        return Err(FigureError::Empty(format!(
            "F* is not positive anywhere on 0 <= h* <= 3 for psi = {}, theta = {}",
            params.psi, params.theta
        )));
    }
    let mut series = vec![Series {
        label: Some(format!("{name}, direct integration")),
        points: direct,
        color: 0,
        dashed: false,
    }];
    // The lower panel's y axis and curve (its x axis is the upper one's).
    let mut bottom = None;
    if let Some(table) = table {
        let d = table.domain();
        let held = d.params(params.psi, params.theta);
        if held != params {
            return Err(FigureError::TableMismatch {
                table: constants(&held),
                asked: constants(&params),
            });
        }
        // ψ and θ outside the domain are errors that name them.
        table.mu(params.psi, params.theta, d.f_star.0)?;
        let mut looked = Vec::new();
        let mut rel = Vec::new();
        for &(f, mu) in &series[0].points {
            if f >= d.f_star.0 && f <= d.f_star.1 {
                let t = table.mu(params.psi, params.theta, f)?;
                looked.push((f, t));
                rel.push((f, t / mu - 1.0));
            }
        }
        if rel.is_empty() {
            return Err(FigureError::Empty(format!(
                "no load of the curve lies in the table's range F* in [{:e}, {:e}]",
                d.f_star.0, d.f_star.1
            )));
        }
        series.push(Series {
            label: Some("table lookup".into()),
            points: looked,
            color: 1,
            dashed: true,
        });
        // Drawn in units of 10^k so that the tick labels stay short.
        let worst = rel.iter().map(|p| p.1.abs()).fold(0.0, f64::max).max(1e-15);
        let k = worst.log10().floor() as i32;
        let unit = 10f64.powi(k);
        let step = nice_step(worst / unit / 2.5);
        let span = (worst / unit / step).ceil() * step * 1.05;
        bottom = Some((
            Axis {
                title: format!("(μ_table/μ − 1)/{}", pow10(k)),
                log: false,
                range: (-span, span),
                ticks: None,
            },
            Series {
                label: None,
                points: rel.iter().map(|&(f, r)| (f, r / unit)).collect(),
                color: 1,
                dashed: false,
            },
        ));
    }
    let (_, (ylo, yhi)) = extent(&series);
    let y = if yhi / ylo > 10.0 {
        Axis {
            title: "μ".into(),
            log: true,
            range: log_range(ylo, yhi),
            ticks: None,
        }
    } else {
        Axis {
            title: "μ".into(),
            log: false,
            range: zero_to(yhi),
            ticks: None,
        }
    };
    let mut x = f_axis(&series);
    let bottom = bottom.map(|(y, curve)| Chart {
        title: None,
        x: x.clone(),
        y,
        series: vec![curve],
        legend: Corner::UpperRight,
    });
    if bottom.is_some() {
        // One axis title, under the lower panel.
        x.title.clear();
    }
    Ok(Page {
        top: Chart {
            title: Some(format!(
                "μ against F*: ψ = {}, θ = {} ({name})",
                num(params.psi),
                num(params.theta)
            )),
            x,
            y,
            series,
            legend: Corner::UpperRight,
        },
        bottom,
    })
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

/// The error map of `table` at `theta` with `rows` × `cols` cells.
pub fn table_error(table: &Table, theta: f64, rows: usize, cols: usize) -> Result<ErrorMap, FigureError> {
    let d = *table.domain();
    // θ outside the domain is an error that names it.
    table.mu(d.psi.0, theta, d.f_star.0)?;
    let edges = |(lo, hi): (f64, f64), n: usize| -> Vec<f64> {
        (0..=n).map(|i| lo * (hi / lo).powf(i as f64 / n as f64)).collect()
    };
    let psi = edges(d.psi, rows.max(1));
    let f_star = edges(d.f_star, cols.max(1));
    let mut rel = Vec::with_capacity(rows * cols);
    for r in 0..psi.len() - 1 {
        let p = (psi[r] * psi[r + 1]).sqrt();
        let model = Model::new(d.params(p, theta))?;
        for c in 0..f_star.len() - 1 {
            let f = (f_star[c] * f_star[c + 1]).sqrt();
            let guess = table.h_star(p, theta, f)?;
            let h = model.solve_h(f, guess)?;
            let exact = model.at_h_star(h)?;
            let mu = exact.mu.ok_or(EvalError::FStar(f))?;
            rel.push((table.mu(p, theta, f)? / mu - 1.0).abs());
        }
    }
    Ok(ErrorMap {
        theta,
        psi,
        f_star,
        rel,
        tolerance: table.info().tolerance,
    })
}

// ---------------------------------------------------------------------------
// Drawing.

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
/// jagged.
const SUPERSAMPLE: u32 = 3;

/// Draws `what` into `path`, PNG or SVG by its extension.
fn save(path: &Path, what: &impl Render) -> Result<(), FigureError> {
    let format = Format::from_path(path)?;
    let result = fonts().and_then(|()| match format {
        Format::Png => {
            let k = SUPERSAMPLE;
            let big = (SIZE.0 * k, SIZE.1 * k);
            let mut buf = vec![0u8; big.0 as usize * big.1 as usize * 3];
            {
                let root = BitMapBackend::with_buffer(&mut buf, big).into_drawing_area();
                what.render(&root, k)?;
                root.present().map_err(err)?;
            }
            let small = downsample(&buf, big, k);
            let mut png = BitMapBackend::new(path, SIZE);
            png.blit_bitmap((0, 0), SIZE, &small).map_err(err)?;
            png.present().map_err(err)
        }
        Format::Svg => {
            let root = SVGBackend::new(path, SIZE).into_drawing_area();
            what.render(&root, 1)?;
            root.present().map_err(err)
        }
    });
    result.map_err(|message| FigureError::Draw {
        path: path.display().to_string(),
        message,
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
    /// Draws the page into `path` ([`SIZE`] pixels; PNG or SVG by the
    /// extension).
    pub fn save(&self, path: &Path) -> Result<(), FigureError> {
        save(path, self)
    }
}

impl ErrorMap {
    /// Draws the map and its colour bar into `path` ([`SIZE`] pixels; PNG
    /// or SVG by the extension).
    pub fn save(&self, path: &Path) -> Result<(), FigureError> {
        save(path, self)
    }
}

fn err<E: std::fmt::Display>(e: E) -> String {
    e.to_string()
}

fn rgb(i: usize) -> RGBColor {
    let (r, g, b) = PALETTE[i % PALETTE.len()];
    RGBColor(r, g, b)
}

// Sizes in pixels of the final image.
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

/// A round step near `x`: 1, 2, 2.5 or 5 times a power of ten.
fn nice_step(x: f64) -> f64 {
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

const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// 10 to the power `k`, with a superscript exponent: 10⁻³.
fn pow10(k: i32) -> String {
    let mut s = String::from("10");
    if k < 0 {
        s.push('⁻');
    }
    for c in k.unsigned_abs().to_string().chars() {
        s.push(SUPERSCRIPTS[c as usize - '0' as usize]);
    }
    s
}

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

impl Axis {
    /// Data value → plotting coordinate.
    fn to(&self, v: f64) -> f64 {
        if self.log {
            v.log10()
        } else {
            v
        }
    }

    /// Plotting coordinate → data value.
    fn from(&self, u: f64) -> f64 {
        if self.log {
            10f64.powf(u)
        } else {
            u
        }
    }

    /// The labelled ticks and the light grid lines, in plotting coordinates,
    /// and the step used for labels.
    fn ticks(&self) -> (Vec<f64>, Vec<f64>, f64) {
        let (a, b) = (self.to(self.range.0), self.to(self.range.1));
        let eps = 1e-9 * (b - a);
        if let Some(t) = &self.ticks {
            let major: Vec<f64> = t.iter().map(|&v| self.to(v)).collect();
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
            inner: (self.to(self.range.0)..self.to(self.range.1)).into(),
            major,
            minor,
        }
    }

    /// The label of the tick at plotting coordinate `u`.
    fn label(&self, u: f64) -> String {
        if self.ticks.is_some() {
            return num((self.from(u) * 1e6).round() / 1e6);
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
    x: &Axis,
    y: &Axis,
    grid: bool,
    y_area: u32,
    s: u32,
) -> Result<Plot<'a, DB>, String> {
    let mut builder = ChartBuilder::on(area);
    builder
        .margin(MARGIN_PX * s)
        .margin_right(MARGIN_RIGHT_PX * s)
        .x_label_area_size(if x.title.is_empty() { X_TICKS_ONLY_PX } else { X_AREA_PX } * s)
        .y_label_area_size(y_area);
    if let Some(t) = title {
        builder.caption(t, (FAMILY, CAPTION_PX * s));
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
fn y_area<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, y: &Axis, s: u32) -> Result<u32, String> {
    let font: TextStyle = (FAMILY, LABEL_PX * s).into_font().into();
    let mut widest = 0;
    for u in y.ticks().0 {
        widest = widest.max(area.estimate_text_size(&y.label(u), &font).map_err(err)?.0);
    }
    Ok((Y_AREA_PX * s).max(widest + (DESC_PX + TICK_PX + 34) * s))
}

fn draw_chart<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, c: &Chart, y_area: u32, s: u32) -> Result<(), String> {
    let mut chart = frame(area, c.title.as_deref(), &c.x, &c.y, true, y_area, s)?;
    let si = s as i32;
    let mut labelled = false;
    for line in &c.series {
        let style = rgb(line.color).stroke_width(LINE_PX * s);
        let pts: Vec<(f64, f64)> = line
            .points
            .iter()
            .filter(|&&(x, y)| (!c.x.log || x > 0.0) && (!c.y.log || y > 0.0))
            .map(|&(x, y)| (c.x.to(x), c.y.to(y)))
            .collect();
        let anno = if line.dashed {
            chart
                .draw_series(DashedLineSeries::new(pts, 14 * si, 9 * si, style))
                .map_err(err)?
        } else {
            chart.draw_series(LineSeries::new(pts, style)).map_err(err)?
        };
        if let Some(label) = &line.label {
            labelled = true;
            let dashed = line.dashed;
            anno.label(label.as_str()).legend(move |(x, y)| {
                let pts = vec![(x - 4 * si, y), (x + 36 * si, y)];
                if dashed {
                    DashedPathElement::new(pts, 10 * si, 6 * si, style).into_dyn()
                } else {
                    PathElement::new(pts, style).into_dyn()
                }
            });
        }
    }
    border(&chart, s)?;
    if labelled {
        let font: TextStyle = (FAMILY, LEGEND_PX * s).into_font().into();
        let pad = 10 * s;
        let glyph = 50 * s;
        let mut text_w = 0;
        let labels = c.series.iter().filter_map(|l| l.label.as_deref());
        for label in labels.clone() {
            text_w = text_w.max(area.estimate_text_size(label, &font).map_err(err)?.0);
        }
        // The box's size as plotters lays it out (line height 1.25 em),
        // so that it can sit a little inside the frame.
        let lines = labels.count() as f64;
        let w = (text_w + glyph + 2 * pad) as i32;
        let h = ((lines - 1.0) * 1.25 * f64::from(LEGEND_PX * s) + f64::from(LEGEND_PX * s)) as i32 + 2 * pad as i32;
        let (aw, ah) = chart.plotting_area().dim_in_pixel();
        let inset = (12 * s) as i32;
        let (x, y) = match c.legend {
            Corner::UpperLeft => (inset, inset),
            Corner::UpperRight => (aw as i32 - w - inset, inset),
            Corner::LowerLeft => (inset, ah as i32 - h - inset),
            Corner::LowerRight => (aw as i32 - w - inset, ah as i32 - h - inset),
        };
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::Coordinate(x, y))
            .margin(pad)
            .legend_area_size(glyph)
            .label_font(font)
            .background_style(WHITE.mix(0.92))
            .border_style(BLACK.mix(0.5).stroke_width(s))
            .draw()
            .map_err(err)?;
    }
    Ok(())
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
                let (upper, lower) = root.split_vertically(SIZE.1 * 3 / 5 * s);
                draw_chart(&upper, &self.top, width, s)?;
                draw_chart(&lower, bottom, width, s)
            }
        }
    }
}

/// Viridis, sampled at five points and interpolated linearly.
fn viridis(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = t.clamp(0.0, 1.0) * 4.0;
    let i = (t.floor() as usize).min(3);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

impl ErrorMap {
    /// The colour scale's decades (log10 of the error): whole decades
    /// covering the errors and, not at the very top, the tolerance; at
    /// most 6 of them.
    fn scale(&self) -> (f64, f64) {
        let max = self.rel.iter().copied().fold(0.0, f64::max);
        let min = self
            .rel
            .iter()
            .copied()
            .filter(|&r| r > 0.0)
            .fold(f64::INFINITY, f64::min);
        let hi = (max.max(self.tolerance).log10() + 0.3).ceil();
        let lo = if min.is_finite() { min.log10().floor() } else { hi - 6.0 };
        (lo.max(hi - 6.0), hi)
    }
}

impl Render for ErrorMap {
    fn render<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, s: u32) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (main, bar) = root.split_horizontally((SIZE.0 - COLOUR_BAR_PX) * s);
        let (lo, hi) = self.scale();
        let colour = |r: f64| viridis((r.max(1e-300).log10() - lo) / (hi - lo));
        let (psi_lo, psi_hi) = (self.psi[0], self.psi[self.psi.len() - 1]);
        let x = Axis {
            title: "F*".into(),
            log: true,
            range: (self.f_star[0], self.f_star[self.f_star.len() - 1]),
            ticks: None,
        };
        let psi_ticks: Vec<f64> = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0]
            .into_iter()
            .filter(|&v| v >= psi_lo * (1.0 - 1e-9) && v <= psi_hi * (1.0 + 1e-9))
            .collect();
        let y = Axis {
            title: "ψ".into(),
            log: true,
            range: (psi_lo, psi_hi),
            ticks: (psi_ticks.len() >= 2).then_some(psi_ticks),
        };
        let (max, at_psi, at_f) = self.max();
        let title = format!(
            "Table error, θ = {} (max {} at ○)",
            num(self.theta),
            tick_label(max, max)
        );
        let width = y_area(&main, &y, s)?;
        let mut chart = frame(&main, Some(&title), &x, &y, false, width, s)?;
        let cols = self.f_star.len() - 1;
        chart
            .draw_series(self.rel.iter().enumerate().map(|(i, &r)| {
                let (row, col) = (i / cols, i % cols);
                Rectangle::new(
                    [
                        (x.to(self.f_star[col]), y.to(self.psi[row + 1])),
                        (x.to(self.f_star[col + 1]), y.to(self.psi[row])),
                    ],
                    colour(r).filled(),
                )
            }))
            .map_err(err)?;
        // The largest error, ringed.
        let ring = ShapeStyle::from(&WHITE).stroke_width(3 * s);
        chart
            .draw_series(std::iter::once(Circle::new((x.to(at_f), y.to(at_psi)), 12 * s, ring)))
            .map_err(err)?;
        border(&chart, s)?;

        // The colour bar: the same caption and x-label space as the map,
        // so that the two line up.
        let mut builder = ChartBuilder::on(&bar);
        builder
            .margin(MARGIN_PX * s)
            .margin_right(10 * s)
            .caption(" ", (FAMILY, CAPTION_PX * s))
            .x_label_area_size(X_AREA_PX * s)
            .y_label_area_size(0)
            .right_y_label_area_size(95 * s);
        let cb = Axis {
            title: "|μ_table/μ − 1|   (red: tolerance)".into(),
            log: true,
            range: (10f64.powf(lo), 10f64.powf(hi)),
            ticks: None,
        };
        let unit = Axis {
            title: String::new(),
            log: false,
            range: (0.0, 1.0),
            ticks: Some(vec![]),
        };
        let mut bar_chart = builder.build_cartesian_2d(unit.coord(), cb.coord()).map_err(err)?;
        let fy = |u: &f64| cb.label(*u);
        bar_chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_label_formatter(&fy)
            .y_desc(cb.title.as_str())
            .axis_desc_style((FAMILY, DESC_PX * s))
            .label_style((FAMILY, LABEL_PX * s))
            .axis_style(BLACK.stroke_width(s))
            .set_all_tick_mark_size(TICK_PX * s)
            .draw()
            .map_err(err)?;
        let steps = 120;
        bar_chart
            .draw_series((0..steps).map(|i| {
                let a = lo + (hi - lo) * i as f64 / steps as f64;
                let b = lo + (hi - lo) * (i + 1) as f64 / steps as f64;
                Rectangle::new([(0.0, b), (1.0, a)], viridis((i as f64 + 0.5) / steps as f64).filled())
            }))
            .map_err(err)?;
        // The tolerance the table promises, as a line across the bar.
        let t = self.tolerance.log10();
        if t >= lo && t <= hi {
            bar_chart
                .draw_series(LineSeries::new(vec![(0.0, t), (1.0, t)], RED.stroke_width(3 * s)))
                .map_err(err)?;
        }
        border(&bar_chart, s)?;
        Ok(())
    }
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
    fn tick_labels_suit_the_step() {
        assert_eq!(tick_label(0.5, 0.5), "0.5");
        assert_eq!(tick_label(0.25, 0.25), "0.25");
        assert_eq!(tick_label(2.0, 0.5), "2.0");
        assert_eq!(tick_label(1e-19, 0.5), "0");
        assert_eq!(tick_label(-2e-5, 1e-5), "−2×10⁻⁵");
        assert_eq!(tick_label(4.02e-5, 4.02e-5), "4.02×10⁻⁵");
    }

    #[test]
    fn nice_steps_are_1_2_2_5_5_times_a_power_of_ten() {
        assert_eq!(nice_step(0.07), 0.1);
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(nice_step(1.5), 2.0);
        assert_eq!(nice_step(2.2), 2.5);
    }

    #[test]
    fn format_follows_the_extension() {
        assert_eq!(Format::from_path("a.PNG".as_ref()), Ok(Format::Png));
        assert_eq!(Format::from_path("a/b.svg".as_ref()), Ok(Format::Svg));
        assert!(Format::from_path("a.jpg".as_ref()).is_err());
        assert!(Format::from_path("a".as_ref()).is_err());
    }

    #[test]
    fn the_paper_sweep_ends_at_f_star_0_1() {
        // ψ = 2: F*(h* = 0) = 0.13, so the curve starts at F* = 0.1 exactly.
        let m = Model::new(Params::new(2.0, 0.003)).unwrap();
        let s = paper_sweep(&m).unwrap();
        assert!((s[0].f_star - 0.1).abs() < 1e-12);
        assert!(s.windows(2).all(|w| w[1].f_star < w[0].f_star));
        assert!(s.len() > 180, "{} points", s.len());
    }
}

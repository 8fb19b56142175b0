//! A measured surface's height histogram with the densities fitted to it,
//! and μ(F*) for each fit (`kefric plot surface`).

use super::chart::{f_axis, mu_axis, num, Chart, ChartAxis, Corner, LineStyle, Markers, Page, Series};
use super::distributions::{DENSITY_Y, DISTRIBUTIONS_LOADS};
use super::paper::SHAPES;
use super::FigureError;
use crate::Model;

/// The load axis of [`surface_page`]'s μ panel: what is drawn along it
/// and over which range.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadAxis {
    /// The axis title: `"F*"`, `"F (N)"`, `"p (Pa)"`.
    pub title: String,
    /// The axis' value at F* = 1 (1 for F*, A_n·H for a force in N, H
    /// for a pressure in Pa): F* = value / `per_f_star`.
    pub per_f_star: f64,
    /// The range drawn (LO < HI, both > 0), in the axis' unit.
    pub range: (f64, f64),
    /// A load to mark on the μ curves (a single load asked for), in the
    /// axis' unit: a point on each curve, labelled with it.
    pub mark: Option<f64>,
}

impl LoadAxis {
    /// F* over `range`.
    pub fn f_star(range: (f64, f64)) -> LoadAxis {
        LoadAxis {
            title: "F*".into(),
            per_f_star: 1.0,
            range,
            mark: None,
        }
    }

    /// The loads the μ panel is drawn at, in the axis' unit:
    /// [`DISTRIBUTIONS_LOADS`] log-spaced over
    /// the range, ends included (the warnings of a plot count these).
    pub fn loads(&self) -> impl Iterator<Item = f64> + '_ {
        let (lo, hi) = self.range;
        let n = super::DISTRIBUTIONS_LOADS;
        (0..n).map(move |k| lo * (hi / lo).powf(k as f64 / (n - 1) as f64))
    }
}

/// Bins of the height histogram.
pub const SURFACE_BINS: usize = 80;

/// Two panels for one surface. Above, μ against F* (log F*, over
/// `loads`, default [`DISTRIBUTIONS_F_STAR`](super::DISTRIBUTIONS_F_STAR)) for each model of `fits` (label, model:
/// the same surface and materials with different height distributions;
/// loads where μ is undefined are left out). Below, on a log axis, the
/// histogram of `standardised` heights (height/σ of the detrended
/// surface; NaN skipped; `None` for a pair of surfaces, whose summed
/// heights are not a sample) in black steps, and each fit's standardised
/// density g(x) in its μ curve's colour. `title` names the surface (the
/// lower panel's title); `intervals` its sampling intervals, printed
/// beside ψ and β (the upper panel's title), on which they depend.
///
/// `loads` is the μ panel's x axis: F* (the default, 1e-5 to 0.1), or a
/// force in newtons or a pressure in pascals ([`LoadAxis`]); the axis
/// spans exactly its range.
pub fn surface_page(
    title: &str,
    intervals: &str,
    standardised: Option<&[f64]>,
    fits: &[(String, Model)],
    loads: Option<&LoadAxis>,
) -> Result<Page, FigureError> {
    let default = LoadAxis::f_star(super::DISTRIBUTIONS_F_STAR);
    let loads = loads.unwrap_or(&default);
    let (lo, hi) = loads.range;
    let mut mu_series = Vec::with_capacity(fits.len());
    let mut g_series = Vec::with_capacity(fits.len() + 1);
    // The x range: the heights' own, else ±5.
    let mut x_range = (-5.0f64, 5.0f64);
    if let Some(z) = standardised {
        let finite = z.iter().copied().filter(|v| v.is_finite());
        let (a, b) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        if a >= b || !a.is_finite() {
            return Err(FigureError::Empty(
                "the surface has no spread of heights to draw".into(),
            ));
        }
        let n = z.iter().filter(|v| v.is_finite()).count() as f64;
        let width = (b - a) / SURFACE_BINS as f64;
        let mut counts = vec![0usize; SURFACE_BINS];
        for v in z.iter().copied().filter(|v| v.is_finite()) {
            let i = (((v - a) / width) as usize).min(SURFACE_BINS - 1);
            counts[i] += 1;
        }
        let mut steps = Vec::with_capacity(2 * SURFACE_BINS);
        for (i, &c) in counts.iter().enumerate() {
            let g = c as f64 / (n * width);
            if c > 0 {
                let x0 = a + width * i as f64;
                steps.push((x0, g));
                steps.push((x0 + width, g));
            }
        }
        g_series.push(Series::line(Some("measured heights".into()), steps, super::BLACK_INDEX));
        let pad = 0.05 * (b - a);
        x_range = (a - pad, b + pad);
    }
    for (i, (label, model)) in fits.iter().enumerate() {
        let markers = Some(Markers {
            shape: SHAPES[i % SHAPES.len()],
            phase: i as f64 / fits.len().max(1) as f64,
        });
        let mut points = Vec::with_capacity(DISTRIBUTIONS_LOADS);
        for f in loads.loads() {
            if let Some(mu) = model.at_f_star(f / loads.per_f_star).ok().and_then(|c| c.mu) {
                if mu.is_finite() && mu > 0.0 {
                    points.push((f, mu));
                }
            }
        }
        mu_series.push(Series {
            markers,
            ..Series::line(Some(label.clone()), points, i)
        });
        let density = model.params().constants.distribution.density()?;
        let (s0, s1) = density.support();
        const STEPS: usize = 1000;
        let g: Vec<(f64, f64)> = (0..=STEPS)
            .map(|j| x_range.0 + (x_range.1 - x_range.0) * j as f64 / STEPS as f64)
            .filter(|&x| x > s0 && x < s1)
            .map(|x| (x, density.pdf(x)))
            .filter(|&(_, y)| y.is_finite() && y >= DENSITY_Y.0 && y <= DENSITY_Y.1)
            .collect();
        g_series.push(Series {
            style: LineStyle::Dashed,
            ..Series::line(None, g, i)
        });
    }
    if let Some(v) = loads.mark {
        // The load asked for: μ there on each curve, as points.
        let points: Vec<(f64, f64)> = fits
            .iter()
            .filter_map(|(_, model)| model.at_f_star(v / loads.per_f_star).ok().and_then(|c| c.mu))
            .filter(|mu| mu.is_finite() && *mu > 0.0)
            .map(|mu| (v, mu))
            .collect();
        if !points.is_empty() {
            mu_series.push(Series {
                style: LineStyle::Points,
                ..Series::line(
                    Some(format!("the load: {} = {}", loads.title, num(v))),
                    points,
                    super::BLACK_INDEX,
                )
            });
        }
    }
    if mu_series.iter().all(|s| s.points.is_empty()) {
        return Err(FigureError::Empty(format!(
            "mu is defined at no load in [{}, {}] for this surface and these materials",
            num(lo),
            num(hi)
        )));
    }
    let y = mu_axis(&mu_series);
    let mut x = f_axis(&mu_series);
    x.title.clone_from(&loads.title);
    x.range = (lo, hi);
    let p = fits.first().map(|(_, m)| m.params());
    Ok(Page {
        top: Chart {
            title: p.map(|p| {
                let r = |v: f64| crate::Shortest::rounded(v);
                format!(
                    "ψ = {}, θ = {}, β = {} {intervals}",
                    r(p.psi),
                    r(p.theta),
                    r(p.constants.beta)
                )
            }),
            x,
            y,
            series: mu_series,
            legend: Corner::Clear,
        },
        bottom: Some(Chart {
            title: Some(title.to_string()),
            x: ChartAxis {
                title: "height/σ (detrended, standardised)".into(),
                log: false,
                range: x_range,
                ticks: None,
            },
            y: ChartAxis {
                title: "density".into(),
                log: true,
                range: DENSITY_Y,
                ticks: None,
            },
            series: g_series,
            legend: Corner::Clear,
        }),
    })
}

/// A log axis over the positive data of `series` (title `title`).
pub(super) fn log_axis(title: &str, series: &[Series], x: bool) -> Result<ChartAxis, FigureError> {
    let ((x0, x1), (y0, y1)) = super::chart::extent(series);
    let (lo, hi) = if x { (x0, x1) } else { (y0, y1) };
    if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && hi >= lo) {
        return Err(FigureError::Empty(format!(
            "nothing positive to draw on the {title} axis"
        )));
    }
    let (lo, hi) = if hi > lo { (lo, hi) } else { (lo / 2.0, hi * 2.0) };
    Ok(ChartAxis {
        title: title.into(),
        log: true,
        range: super::chart::log_range(lo, hi),
        ticks: None,
    })
}

/// A vertical dotted line at `x` across `range`, labelled `label`.
pub(super) fn marker(label: &str, x: f64, range: (f64, f64), color: usize) -> Series {
    Series {
        style: LineStyle::Dotted,
        ..Series::line(Some(label.into()), vec![(x, range.0), (x, range.1)], color)
    }
}

#[cfg(feature = "topography")]
/// The power spectral densities of a surface (log–log): each of `spectra`
/// (a name — "along x", "along y", "area (radial)" — and its q, C), with
/// the filters' wavevectors 2π/λs and 2π/λc marked where given. `title`
/// names the surface.
pub fn psd_page(
    title: &str,
    spectra: &[(&str, &crate::topography::Psd)],
    lambda_s: Option<f64>,
    lambda_c: Option<f64>,
) -> Result<Page, FigureError> {
    let mut series: Vec<Series> = spectra
        .iter()
        .enumerate()
        .map(|(i, (name, p))| {
            let points =
                p.q.iter()
                    .zip(&p.c)
                    .filter(|(q, c)| **q > 0.0 && **c > 0.0)
                    .map(|(q, c)| (*q, *c))
                    .collect();
            Series::line(Some((*name).to_string()), points, i)
        })
        .collect();
    let x = log_axis("q (rad/m)", &series, true)?;
    let y = log_axis("C (m³; m⁴ for the area)", &series, false)?;
    let n = series.len();
    for (k, (name, lambda)) in [("2π/λs", lambda_s), ("2π/λc", lambda_c)].into_iter().enumerate() {
        if let Some(lambda) = lambda {
            series.push(marker(name, 2.0 * std::f64::consts::PI / lambda, y.range, n + k));
        }
    }
    Ok(Page::single(Chart {
        title: Some(format!("power spectral density: {title}")),
        x,
        y,
        series,
        legend: Corner::Clear,
    }))
}

/// One λs of a scan: μ (with a load), ψ (with materials) and β.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScanPoint {
    /// The S-filter's nesting index (m).
    pub lambda_s: f64,
    /// μ at the load, if any.
    pub mu: Option<f64>,
    /// ψ, if the materials are given.
    pub psi: Option<f64>,
    /// β.
    pub beta: f64,
}

/// μ (above; ψ when there is no load) and ψ, β (below) against λs on a
/// log axis, the instrument's reliability cut-off marked: the scales left
/// of it are distorted by the instrument.
pub fn scan_page(title: &str, points: &[ScanPoint], cutoff: Option<f64>) -> Result<Page, FigureError> {
    let line = |label: &str, f: &dyn Fn(&ScanPoint) -> Option<f64>, color: usize| Series {
        markers: Some(Markers {
            shape: SHAPES[color % SHAPES.len()],
            phase: 0.0,
        }),
        ..Series::line(
            Some(label.into()),
            points
                .iter()
                .filter_map(|p| f(p).filter(|v| v.is_finite() && *v > 0.0).map(|v| (p.lambda_s, v)))
                .collect(),
            color,
        )
    };
    let has_mu = points.iter().any(|p| p.mu.is_some());
    let mut top = vec![if has_mu {
        line("μ", &|p| p.mu, 0)
    } else {
        line("ψ", &|p| p.psi, 1)
    }];
    let mut bottom = vec![line("β", &|p| Some(p.beta), 2)];
    if points.iter().any(|p| p.psi.is_some()) {
        bottom.insert(0, line("ψ", &|p| p.psi, 1));
    }
    let x = log_axis("λs (m)", &top, true).or_else(|_| log_axis("λs (m)", &bottom, true))?;
    let y_top = log_axis(if has_mu { "μ" } else { "ψ" }, &top, false)?;
    let y_bottom = log_axis("ψ, β", &bottom, false)?;
    if let Some(cutoff) = cutoff {
        // The reliable range, λs at or above the cut-off, shaded under
        // the lines (first in the series), and the cut-off itself dotted.
        let shade = |label: Option<String>, (x1, y): ((f64, f64), (f64, f64))| Series {
            style: LineStyle::Shade,
            ..Series::line(
                label,
                vec![
                    (cutoff.max(x1.0), y.0),
                    (x1.1, y.0),
                    (x1.1, y.1),
                    (cutoff.max(x1.0), y.1),
                ],
                super::BLACK_INDEX,
            )
        };
        if cutoff < x.range.1 {
            top.insert(0, shade(Some("reliable: λs ≥ cut-off".into()), (x.range, y_top.range)));
            bottom.insert(0, shade(None, (x.range, y_bottom.range)));
        }
        top.push(marker("reliability cut-off", cutoff, y_top.range, super::BLACK_INDEX));
        bottom.push(Series {
            label: None,
            ..marker("", cutoff, y_bottom.range, super::BLACK_INDEX)
        });
    }
    Ok(Page {
        top: Chart {
            title: Some(format!("against the S-filter nesting index λs: {title}")),
            x: x.clone(),
            y: y_top,
            series: top,
            legend: Corner::Clear,
        },
        bottom: Some(Chart {
            title: None,
            x,
            y: y_bottom,
            series: bottom,
            legend: Corner::Clear,
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points() -> Vec<ScanPoint> {
        (0..8)
            .map(|k| {
                let lambda_s = 1e-6 * 2f64.powi(k);
                ScanPoint {
                    lambda_s,
                    mu: Some(1.0 + 0.1 * k as f64),
                    psi: Some(0.5 + 0.05 * k as f64),
                    beta: 0.05 + 0.01 * k as f64,
                }
            })
            .collect()
    }

    #[test]
    fn the_reliable_range_is_shaded_from_the_cutoff_to_the_right_end() {
        let page = scan_page("t", &points(), Some(8e-6)).unwrap();
        for chart in [&page.top, page.bottom.as_ref().unwrap()] {
            let shade = &chart.series[0];
            assert_eq!(shade.style, LineStyle::Shade);
            let xs: Vec<f64> = shade.points.iter().map(|p| p.0).collect();
            assert_eq!(xs.iter().cloned().fold(f64::INFINITY, f64::min), 8e-6);
            assert_eq!(xs.iter().cloned().fold(0.0, f64::max), chart.x.range.1);
            let ys: Vec<f64> = shade.points.iter().map(|p| p.1).collect();
            assert!(ys.contains(&chart.y.range.0) && ys.contains(&chart.y.range.1));
        }
        assert_eq!(page.top.series[0].label.as_deref(), Some("reliable: λs ≥ cut-off"));
        // Drawn as a filled polygon (SVG keeps the element).
        let path = std::env::temp_dir().join(format!("kef-scan-shade-{}.svg", std::process::id()));
        page.save(&path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        assert!(svg.contains("<polygon"), "no polygon in the SVG");
    }

    #[test]
    fn a_cutoff_beyond_the_scan_shades_nothing_and_none_marks_nothing() {
        let page = scan_page("t", &points(), Some(1.0)).unwrap();
        assert!(page.top.series.iter().all(|s| s.style != LineStyle::Shade));
        let page = scan_page("t", &points(), None).unwrap();
        assert!(page.top.series.iter().all(|s| s.style == LineStyle::Solid));
    }

    /// A load axis in newtons spans exactly the range given, and each point
    /// is the model's μ at F* = F/(A_n·H).
    #[test]
    fn the_load_axis_is_the_range_given_in_its_unit() {
        let model = Model::new(crate::Params::new(1.0, 0.001)).unwrap();
        // 1 cm² against 100 MPa: F* = F / 1e4 N.
        let axis = LoadAxis {
            title: "F (N)".into(),
            per_f_star: 1e4,
            range: (0.2, 300.0),
            mark: None,
        };
        let fits = [("gaussian".to_string(), model.clone())];
        let page = surface_page("t", "", None, &fits, Some(&axis)).unwrap();
        assert_eq!(page.top.x.title, "F (N)");
        assert_eq!(page.top.x.range, (0.2, 300.0));
        let points = &page.top.series[0].points;
        assert_eq!(points.len(), DISTRIBUTIONS_LOADS);
        assert!((points[0].0 / 0.2 - 1.0).abs() < 1e-12 && (points[points.len() - 1].0 / 300.0 - 1.0).abs() < 1e-12);
        for &(f, mu) in points {
            assert_eq!(mu, model.at_f_star(f / 1e4).unwrap().mu.unwrap(), "F = {f} N");
        }
    }

    /// A single load is marked: a point on each curve at μ there, in the
    /// axis' unit, labelled with the load; none without one.
    #[test]
    fn a_single_load_is_marked_on_each_curve() {
        let fits = [
            (
                "gaussian".to_string(),
                Model::new(crate::Params::new(1.0, 0.001)).unwrap(),
            ),
            ("psi 2".to_string(), Model::new(crate::Params::new(2.0, 0.001)).unwrap()),
        ];
        let axis = LoadAxis {
            title: "F (N)".into(),
            per_f_star: 1e4,
            range: (0.1, 1000.0),
            mark: Some(10.0),
        };
        let page = surface_page("t", "", None, &fits, Some(&axis)).unwrap();
        let mark = page.top.series.last().unwrap();
        assert_eq!(mark.style, LineStyle::Points);
        assert_eq!(mark.label.as_deref(), Some("the load: F (N) = 10"));
        assert_eq!(mark.points.len(), 2);
        for (&(f, mu), (_, model)) in mark.points.iter().zip(&fits) {
            assert_eq!((f, mu), (10.0, model.at_f_star(1e-3).unwrap().mu.unwrap()));
        }
        // Drawn: a marker's white rim and fill per point (SVG polygons).
        let path = std::env::temp_dir().join(format!("kef-surface-mark-{}.svg", std::process::id()));
        page.save(&path).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        let _ = std::fs::remove_file(&path);
        assert!(svg.contains("the load: F (N) = 10"), "no label");
        let unmarked = LoadAxis { mark: None, ..axis };
        let page = surface_page("t", "", None, &fits, Some(&unmarked)).unwrap();
        assert!(page.top.series.iter().all(|s| s.style != LineStyle::Points));
    }
}

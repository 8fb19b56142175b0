//! A measured surface's height histogram with the densities fitted to it,
//! and μ(F*) for each fit (`kefric plot surface`).

use super::chart::{f_axis, mu_axis, num, Chart, ChartAxis, Corner, LineStyle, Markers, Page, Series};
use super::distributions::{DENSITY_Y, DISTRIBUTIONS_F_STAR, DISTRIBUTIONS_LOADS};
use super::paper::SHAPES;
use super::FigureError;
use crate::Model;

/// Bins of the height histogram.
pub const SURFACE_BINS: usize = 80;

/// Two panels for one surface. Above, μ against F* (log F*, over
/// `f_star`, default 1e-5 to 0.1) for each model of `fits` (label, model:
/// the same surface and materials with different height distributions;
/// loads where μ is undefined are left out). Below, on a log axis, the
/// histogram of `standardised` heights (height/σ of the detrended
/// surface; NaN skipped; `None` for a pair of surfaces, whose summed
/// heights are not a sample) in black steps, and each fit's standardised
/// density g(x) in its μ curve's colour. `title` names the surface (the
/// lower panel's title); `intervals` its sampling intervals, printed
/// beside ψ and β (the upper panel's title), on which they depend.
pub fn surface_page(
    title: &str,
    intervals: &str,
    standardised: Option<&[f64]>,
    fits: &[(String, Model)],
    f_star: Option<(f64, f64)>,
) -> Result<Page, FigureError> {
    let (lo, hi) = f_star.unwrap_or(DISTRIBUTIONS_F_STAR);
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
        for k in 0..DISTRIBUTIONS_LOADS {
            let f = lo * (hi / lo).powf(k as f64 / (DISTRIBUTIONS_LOADS - 1) as f64);
            if let Some(mu) = model.at_f_star(f).ok().and_then(|c| c.mu) {
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
    if mu_series.iter().all(|s| s.points.is_empty()) {
        return Err(FigureError::Empty(format!(
            "mu is defined at no load in [{}, {}] for this surface and these materials",
            num(lo),
            num(hi)
        )));
    }
    let y = mu_axis(&mu_series);
    let mut x = f_axis(&mu_series);
    x.range.0 = x.range.0.min(lo);
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
            legend: Corner::UpperRight,
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
            legend: Corner::UpperRight,
        }),
    })
}

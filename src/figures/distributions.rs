//! μ(F*) for non-Gaussian asperity heights (MODEL.md §9), with the
//! standardised densities g(x) that produce it.

use super::chart::{f_axis, mu_axis, num, Chart, ChartAxis, Corner, Markers, Page, Series};
use super::paper::SHAPES;
use super::FigureError;
use crate::{Constants, HeightDistribution, Model};

/// The Pearson (Sk, K) of [`distributions_page`], drawn after the Gaussian:
/// peaked, skewed both ways, a bounded J-shaped one ((0.8, 2.5), type I)
/// and a negatively skewed peaked one.
pub const DISTRIBUTION_SET: [(f64, f64); 6] = [
    (0.0, 8.0),
    (0.0, 5.0),
    (-0.5, 3.375),
    (0.5, 3.375),
    (0.8, 2.5),
    (-0.8, 4.0),
];

/// Loads of the μ(F*) panel, spaced logarithmically over
/// [`DISTRIBUTIONS_F_STAR`].
pub const DISTRIBUTIONS_LOADS: usize = 60;
/// The F* range of the μ(F*) panel.
pub const DISTRIBUTIONS_F_STAR: (f64, f64) = crate::F_STAR_RANGE;
/// The x range of the density panel, in standard deviations.
pub const DENSITY_X: (f64, f64) = (-5.0, 8.0);
/// The g range of the density panel (logarithmic).
pub const DENSITY_Y: (f64, f64) = (1e-8, 1.0);

/// The Gaussian and the Pearson distributions of [`DISTRIBUTION_SET`],
/// each with its legend label ("Gaussian", "Sk = 0.5, K = 3.375").
pub fn distribution_set() -> Result<Vec<(String, HeightDistribution)>, FigureError> {
    let mut out = vec![("Gaussian".to_string(), HeightDistribution::GAUSSIAN)];
    for (sk, k) in DISTRIBUTION_SET {
        out.push((
            format!("Sk = {}, K = {}", num(sk), num(k)),
            HeightDistribution::pearson(sk, k)?,
        ));
    }
    Ok(out)
}

/// Two panels: above, μ against F* (log F*, 1e-5 to 0.1) at (`psi`,
/// `theta`) for the Gaussian and each Pearson (Sk, K) of
/// [`DISTRIBUTION_SET`] (loads where the model fails or μ is undefined are
/// left out); below, the standardised densities g(x) on a log axis, the
/// same colours, so that the upper tails that carry light loads show.
pub fn distributions_page(psi: f64, theta: f64) -> Result<Page, FigureError> {
    let set = distribution_set()?;
    let of = set.len();
    let mut mu_series = Vec::with_capacity(of);
    let mut g_series = Vec::with_capacity(of);
    let (lo, hi) = DISTRIBUTIONS_F_STAR;
    for (i, (label, d)) in set.into_iter().enumerate() {
        // The Gaussian in black, the others in the palette's first colours.
        let color = if i == 0 { super::BLACK_INDEX } else { i - 1 };
        let markers = Some(Markers {
            shape: SHAPES[i % SHAPES.len()],
            phase: i as f64 / of as f64,
        });
        let density = d.density()?;
        let model = Model::new(Constants::default().distribution(d).at(psi, theta)?)?;
        let mut points = Vec::with_capacity(DISTRIBUTIONS_LOADS);
        for k in 0..DISTRIBUTIONS_LOADS {
            let f = lo * (hi / lo).powf(k as f64 / (DISTRIBUTIONS_LOADS - 1) as f64);
            if let Ok(c) = model.at_f_star(f) {
                if let Some(mu) = c.mu.filter(|m| m.is_finite() && *m > 0.0) {
                    points.push((f, mu));
                }
            }
        }
        mu_series.push(Series {
            markers,
            ..Series::line(Some(label), points, color)
        });
        // g on a fine grid, where it lies inside the panel's range (an
        // interval for these unimodal densities).
        const STEPS: usize = 1300;
        let (a, b) = DENSITY_X;
        let (s0, s1) = density.support();
        let g: Vec<(f64, f64)> = (0..=STEPS)
            .map(|j| a + (b - a) * j as f64 / STEPS as f64)
            .filter(|&x| x > s0 && x < s1)
            .map(|x| (x, density.pdf(x)))
            .filter(|&(_, y)| y.is_finite() && y >= DENSITY_Y.0 && y <= DENSITY_Y.1)
            .collect();
        g_series.push(Series {
            markers,
            ..Series::line(None, g, color)
        });
    }
    if mu_series.iter().all(|s| s.points.is_empty()) {
        return Err(FigureError::Empty(format!(
            "mu is defined at no load in [{lo:e}, {hi:e}] for psi = {psi}, theta = {theta}"
        )));
    }
    let y = mu_axis(&mu_series);
    let mut x = f_axis(&mu_series);
    x.range.0 = x.range.0.min(lo);
    Ok(Page {
        top: Chart {
            title: Some(format!(
                "μ against F* for non-Gaussian heights (Pearson): ψ = {}, θ = {}",
                num(psi),
                num(theta)
            )),
            x,
            y,
            series: mu_series,
            legend: Corner::Clear,
        },
        bottom: Some(Chart {
            title: None,
            x: ChartAxis {
                title: "x = height/σ_s (standardised)".into(),
                log: false,
                range: DENSITY_X,
                ticks: None,
            },
            y: ChartAxis {
                title: "g(x)".into(),
                log: true,
                range: DENSITY_Y,
                ticks: None,
            },
            series: g_series,
            legend: Corner::Clear,
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_set_is_admissible_and_labelled() {
        let set = distribution_set().unwrap();
        assert_eq!(set.len(), 7);
        assert_eq!(set[0].0, "Gaussian");
        assert_eq!(set[4].0, "Sk = 0.5, K = 3.375");
    }
}

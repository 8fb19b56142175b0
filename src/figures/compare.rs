//! A table against the model: a μ(F*) curve by direct integration with
//! the lookup overlaid, and a table's error map.

use super::chart::{
    f_axis, mu_axis, nice_step, num, pow10, Chart, ChartAxis, Corner, ErrorMap, LineStyle, Page, Series,
};
use super::paper::mu_points;
use super::FigureError;
use crate::build::verify::direct_mu;
use crate::{Model, Params, Table};

/// The model constants a table holds, or a curve asks for, in words.
fn constants(p: &Params) -> String {
    format!(
        "beta = {}, nu = {}, eps_star = {}, fit {}, model {}",
        p.constants.beta, p.constants.nu, p.constants.eps_star, p.constants.fit, p.constants.kind
    )
}

/// μ against F* for `model` by direct integration over the paper's range
/// (or, with `f_star`, at 200 loads spaced logarithmically over it); with
/// a table, its lookup overlaid (dashed) and, in a lower panel, the
/// relative difference μ_table/μ − 1 at the loads inside the table's domain.
pub fn curve_page(model: &Model, table: Option<&Table>, f_star: Option<(f64, f64)>) -> Result<Page, FigureError> {
    let params = model.params().clone();
    let name = params.constants.kind.law().label;
    let direct = match f_star {
        None => mu_points(model)?,
        Some((lo, hi)) => {
            const LOADS: usize = 200;
            let mut points = Vec::with_capacity(LOADS);
            for i in 0..LOADS {
                let f = lo * (hi / lo).powf(i as f64 / (LOADS - 1) as f64);
                if let Some(mu) = model.at_f_star(f)?.mu {
                    points.push((f, mu));
                }
            }
            points
        }
    };
    if direct.is_empty() {
        return Err(FigureError::Empty(format!(
            "F* is not positive anywhere on 0 <= h* <= 3 for psi = {}, theta = {}",
            params.psi, params.theta
        )));
    }
    let mut series = vec![Series::line(Some(format!("{name}, direct integration")), direct, 0)];
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
            style: LineStyle::Dashed,
            ..Series::line(Some("table lookup".into()), looked, 1)
        });
        // Drawn in units of 10^k so that the tick labels stay short.
        let worst = rel.iter().map(|p| p.1.abs()).fold(0.0, f64::max).max(1e-15);
        let k = worst.log10().floor() as i32;
        let unit = 10f64.powi(k);
        let step = nice_step(worst / unit / 2.5);
        let span = (worst / unit / step).ceil() * step * 1.05;
        bottom = Some((
            ChartAxis {
                title: format!("(μ_table/μ − 1)/{}", pow10(k)),
                log: false,
                range: (-span, span),
                ticks: None,
            },
            Series::line(None, rel.iter().map(|&(f, r)| (f, r / unit)).collect(), 1),
        ));
    }
    let y = mu_axis(&series);
    let mut x = f_axis(&series);
    let bottom = bottom.map(|(y, curve)| Chart {
        title: None,
        x: x.clone(),
        y,
        series: vec![curve],
        legend: Corner::Clear,
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
            legend: Corner::Clear,
        },
        bottom,
    })
}

/// The error map of `table` at `theta` with `rows` × `cols` cells: this
/// machine's lookup ([`Table::mu`]) against direct integration
/// ([`direct_mu`], the builder's verification uses the same).
pub fn table_error(table: &Table, theta: f64, rows: usize, cols: usize) -> Result<ErrorMap, FigureError> {
    let d = table.domain().clone();
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
        for c in 0..f_star.len() - 1 {
            let f = (f_star[c] * f_star[c + 1]).sqrt();
            let exact = direct_mu(table, p, theta, f)?;
            rel.push((table.mu(p, theta, f)? / exact - 1.0).abs());
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

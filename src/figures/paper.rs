//! The paper's figures 3–6 as data.

use super::chart::{
    extent, f_axis, log_range, num, zero_to, Chart, ChartAxis, Corner, LineStyle, Markers, Page, Series, Shape,
    BLACK_INDEX,
};
use super::{FigureError, H_SAMPLES, PAPER_THETA};
use crate::paper::fits::h_points;
use crate::paper::PAPER_F_STAR_MAX;
use crate::{Contact, Model, ModelKind, Params};

/// The contacts of a curve in the paper's range: [`H_SAMPLES`] separations
/// over 0 ≤ h* ≤ 3 with 0 < F* ≤ 0.1, ordered by decreasing F*; if F* > 0.1
/// at h* = 0, the contact at F* = 0.1 exactly comes first.
pub fn paper_sweep(model: &Model) -> Result<Vec<Contact>, FigureError> {
    let mut out = Vec::with_capacity(H_SAMPLES + 1);
    for (i, h) in h_points(H_SAMPLES).enumerate() {
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

fn model(psi: f64, theta: f64, kind: ModelKind) -> Result<Model, FigureError> {
    Ok(Model::new(Params::new(psi, theta).kind(kind))?)
}

fn psi_label(psi: f64) -> String {
    format!("ψ = {}", num(psi))
}

/// The ψ of Figs. 3 and 4; Fig. 5 uses the first three. Each keeps its
/// colour and marker shape in every figure.
const PSIS: [f64; 5] = [0.5, 1.0, 2.0, 4.0, 8.0];
/// The marker shape of `PSIS[k]` (Figs. 3–5) and of the k-th θ (Fig. 6),
/// and the shapes other figures cycle through.
pub(super) const SHAPES: [Shape; 5] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::TriangleDown,
];

/// Markers of shape `k`, the `i`-th of `of` lines whose markers must not
/// sit at the same x.
fn markers(k: usize, i: usize, of: usize) -> Option<Markers> {
    Some(Markers {
        shape: SHAPES[k % SHAPES.len()],
        phase: i as f64 / of as f64,
    })
}

/// A chart against F* (log) with a linear y axis from zero, its legend
/// upper right.
fn linear_chart(title: &str, y_title: &str, series: Vec<Series>) -> Chart {
    let y = extent(&series).1;
    Chart {
        title: Some(title.into()),
        x: f_axis(&series),
        y: ChartAxis {
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
    for (k, psi) in PSIS.into_iter().enumerate() {
        let m = model(psi, PAPER_THETA, ModelKind::KogutEtsion)?;
        series.push(Series {
            markers: markers(k, k, PSIS.len()),
            ..Series::line(
                Some(psi_label(psi)),
                paper_sweep(&m)?.iter().map(|c| (c.f_star, y(c))).collect(),
                k,
            )
        });
    }
    Ok(series)
}

/// Fig. 3: Fs*/P* against F*, ψ = 0.5, 1, 2, 4, 8, θ = 0.003.
pub(super) fn fig3() -> Result<Chart, FigureError> {
    Ok(linear_chart(
        "Fig. 3: adhesion force ratio Fₛ*/P*, θ = 0.003",
        "Fₛ*/P*",
        psi_series(|c| c.fs_star / c.p_star)?,
    ))
}

/// Fig. 4: Q* against F*, log–log, ψ = 0.5, 1, 2, 4, 8, θ = 0.003.
pub(super) fn fig4() -> Result<Chart, FigureError> {
    let series = psi_series(|c| c.q_star)?;
    let y = extent(&series).1;
    Ok(Chart {
        title: Some("Fig. 4: static friction force Q*, θ = 0.003".into()),
        x: f_axis(&series),
        y: ChartAxis {
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
pub(super) fn mu_points(model: &Model) -> Result<Vec<(f64, f64)>, FigureError> {
    Ok(paper_sweep(model)?
        .iter()
        .filter_map(|c| c.mu.map(|mu| (c.f_star, mu)))
        .collect())
}

/// A legend entry that explains a line style (black, no points).
fn style_entry(label: &str, style: LineStyle) -> Series {
    Series {
        style,
        ..Series::line(Some(label.into()), Vec::new(), BLACK_INDEX)
    }
}

/// Fig. 5: μ against F*, ψ = 0.5, 1, 2, θ = 0.003; Kogut–Etsion solid,
/// CEB-type (MODEL.md §8) dashed; colour and marker shape by ψ. The upper
/// panel has the paper's linear μ axis; the lower one shows the same lines
/// on a logarithmic μ axis, where the CEB-type line of ψ = 2 (μ = 0.0013–0.022,
/// flat against zero above) is readable. The CEB-type line of ψ = 1 runs
/// along the Kogut–Etsion line of ψ = 2: their markers (■ and ▲) tell them
/// apart.
pub(super) fn fig5() -> Result<Page, FigureError> {
    let mut series = Vec::new();
    let psis = &PSIS[..3];
    for (k, &psi) in psis.iter().enumerate() {
        for (j, kind) in [ModelKind::KogutEtsion, ModelKind::CebType].into_iter().enumerate() {
            let m = model(psi, PAPER_THETA, kind)?;
            series.push(Series {
                label: (kind == ModelKind::KogutEtsion).then(|| psi_label(psi)),
                points: mu_points(&m)?,
                color: k,
                style: if j == 0 { LineStyle::Solid } else { LineStyle::Dashed },
                // Six lines, six phases: no two markers at the same F*.
                markers: markers(k, 2 * k + j, 2 * psis.len()),
            });
        }
    }
    let (_, (ylo, yhi)) = extent(&series);
    series.push(style_entry("Kogut–Etsion", LineStyle::Solid));
    series.push(style_entry("CEB-type (approx.)", LineStyle::Dashed));
    let mut top = linear_chart("Fig. 5: static friction coefficient μ, θ = 0.003", "μ", series);
    let mut bottom = Chart {
        title: None,
        x: top.x.clone(),
        y: ChartAxis {
            title: "μ (log scale)".into(),
            log: true,
            range: log_range(ylo, yhi),
            ticks: None,
        },
        series: top.series.iter().filter(|s| !s.points.is_empty()).cloned().collect(),
        legend: Corner::UpperRight,
    };
    for s in &mut bottom.series {
        s.label = None;
    }
    // One F* title, under the lower panel.
    top.x.title.clear();
    Ok(Page {
        top,
        bottom: Some(bottom),
    })
}

/// Fig. 6: μ against F*, ψ = 0.5 (solid) and 2 (dashed), θ = 1e-4, 1e-3,
/// 3e-3 (colour and marker shape). At ψ = 2 the three θ give the same μ
/// to within the line width (the paper's point: adhesion is negligible
/// there); their markers, staggered along F*, show all three.
pub(super) fn fig6() -> Result<Chart, FigureError> {
    let mut series = Vec::new();
    let thetas = [1e-4, 1e-3, 3e-3];
    for (j, psi) in [0.5, 2.0].into_iter().enumerate() {
        for (k, theta) in thetas.into_iter().enumerate() {
            let m = model(psi, theta, ModelKind::KogutEtsion)?;
            series.push(Series {
                label: (j == 0).then(|| format!("θ = {}", num(theta))),
                points: mu_points(&m)?,
                color: k,
                style: if j == 0 { LineStyle::Solid } else { LineStyle::Dashed },
                markers: markers(k, k, thetas.len()),
            });
        }
    }
    series.push(style_entry("ψ = 0.5", LineStyle::Solid));
    series.push(style_entry("ψ = 2 (the three θ coincide)", LineStyle::Dashed));
    Ok(linear_chart(
        "Fig. 6: effect of the adhesion parameter θ on μ",
        "μ",
        series,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

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

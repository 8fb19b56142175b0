//! Several measurements of one surface (a contact.engineering container,
//! or loose files): each measurement's reliable spectrum with the combined
//! one, and μ against λs with its spread across the measurements
//! (`kefric plot surface CONTAINER --psd`, `--scan`).

use super::chart::{Chart, ChartAxis, Corner, LineStyle, Markers, Page, Series};
use super::paper::SHAPES;
use super::surface::{log_axis, marker};
use super::{FigureError, BLACK_INDEX};
use crate::topography::container::{MeasurementPsd, ScanRow};
use crate::topography::Psd;
use std::f64::consts::PI;

/// The palette's colours a measurement may take (black is the combined
/// spectrum's).
const COLOURS: usize = BLACK_INDEX;

/// Bins a decade of a measurement's spectrum as drawn.
pub const DRAWN_PER_DECADE: f64 = 100.0;

/// The positive points of a spectrum.
fn points(p: &Psd) -> Vec<(f64, f64)> {
    p.q.iter()
        .zip(&p.c)
        .filter(|(q, c)| **q > 0.0 && **c > 0.0 && q.is_finite() && c.is_finite())
        .map(|(q, c)| (*q, *c))
        .collect()
}

/// A measurement's spectrum as drawn: its points averaged (q and C) in
/// bins of 1/[`DRAWN_PER_DECADE`] decade, so that a dense, noisy spectrum
/// (thousands of points swinging by decades from one to the next) draws as
/// a line rather than a solid block of spikes; where the spectrum is
/// sparser than the bins its points are kept as they are.
fn drawn(p: &Psd) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut bin = (i64::MIN, 0.0, 0.0, 0usize);
    for (q, c) in points(p) {
        let b = (q.log10() * DRAWN_PER_DECADE).floor() as i64;
        if b != bin.0 && bin.3 > 0 {
            out.push((bin.1 / bin.3 as f64, bin.2 / bin.3 as f64));
            bin = (b, 0.0, 0.0, 0);
        }
        bin.0 = b;
        bin.1 += q;
        bin.2 += c;
        bin.3 += 1;
    }
    if bin.3 > 0 {
        out.push((bin.1 / bin.3 as f64, bin.2 / bin.3 as f64));
    }
    out
}

/// Each measurement's reliable 1-D PSD (log–log; averaged in bins of
/// 1/[`DRAWN_PER_DECADE`] decade) in its own colour,
/// labelled `label` (its name and instrument), clipped to its reliable
/// range, its reliability cut-off (tip radius or resolution) dotted in its
/// colour where one is given; the combined spectrum on top in black with
/// markers. A measurement without a reliable spectrum keeps its legend
/// entry, saying so. The filters' wavevectors 2π/λs and 2π/λc are
/// marked where given. `title` names the surface.
pub fn container_psd_page(
    title: &str,
    measurements: &[(String, &MeasurementPsd)],
    combined: Option<&Psd>,
    lambda_s: Option<f64>,
    lambda_c: Option<f64>,
) -> Result<Page, FigureError> {
    let mut series: Vec<Series> = measurements
        .iter()
        .enumerate()
        .map(|(i, (label, m))| {
            let label = match &m.psd {
                Some(_) => label.clone(),
                None => format!("{label} (no reliable spectrum)"),
            };
            Series::line(Some(label), m.psd.as_ref().map(drawn).unwrap_or_default(), i % COLOURS)
        })
        .collect();
    if let Some(c) = combined {
        series.push(Series {
            markers: Some(Markers {
                shape: SHAPES[0],
                phase: 0.0,
            }),
            ..Series::line(Some("combined".into()), points(c), BLACK_INDEX)
        });
    }
    let x = log_axis("q (rad/m)", &series, true)?;
    let y = log_axis("C¹ᴰ (m³)", &series, false)?;
    for (i, (_, m)) in measurements.iter().enumerate() {
        if let Some(cutoff) = m.cutoff {
            let q = 2.0 * PI / cutoff;
            if q > x.range.0 && q < x.range.1 {
                let mut line = marker("", q, y.range, i % COLOURS);
                line.label = None;
                series.push(line);
            }
        }
    }
    for (name, lambda) in [("2π/λs", lambda_s), ("2π/λc", lambda_c)] {
        if let Some(lambda) = lambda {
            series.push(marker(name, 2.0 * PI / lambda, y.range, BLACK_INDEX));
        }
    }
    Ok(Page::single(Chart {
        title: Some(format!(
            "reliable power spectra and the combined one (dotted: reliability cut-offs): {title}"
        )),
        x,
        y,
        series,
        legend: Corner::Clear,
    }))
}

/// μ against λs from a scan of the combined spectrum (above: μ with a
/// load, else ψ; the spread of μ across the measurements taken alone
/// shaded between its min and max where two or more overlap a band), and
/// below the measurements each λs rests on: measurement k's line at
/// height k + 1 (named in the upper legend) through the λs whose band it overlaps, in its colour, over
/// its reliable range shaded. `names[k]` labels measurement k, `reliable[k]`
/// its reliable wavelengths (λ_min, λ_max). Rows without a μ are left out
/// of the upper panel.
pub fn container_scan_page(
    title: &str,
    names: &[String],
    reliable: &[Option<(f64, f64)>],
    rows: &[ScanRow],
) -> Result<Page, FigureError> {
    let mu = |r: &ScanRow| r.result.as_ref().ok().and_then(|a| a.frictions.first()).map(|f| f.mu);
    let has_mu = rows.iter().any(|r| mu(r).is_some_and(|v| v.is_finite() && v > 0.0));
    let value = |r: &ScanRow| {
        if has_mu {
            mu(r)
        } else {
            r.result.as_ref().ok().map(|a| a.model.psi)
        }
    };
    let line: Vec<(f64, f64)> = rows
        .iter()
        .filter_map(|r| {
            value(r)
                .filter(|v| v.is_finite() && *v > 0.0)
                .map(|v| (r.band.lambda_s, v))
        })
        .collect();
    let symbol = if has_mu { "μ" } else { "ψ" };
    let mut top = vec![Series {
        markers: Some(Markers {
            shape: SHAPES[0],
            phase: 0.0,
        }),
        ..Series::line(Some(format!("{symbol} (combined spectrum)")), line, 0)
    }];
    // The spread: one shaded polygon a run of consecutive rows with one.
    let mut bands: Vec<Vec<(f64, f64, f64)>> = vec![Vec::new()];
    for r in rows {
        match r.spread.as_ref().and_then(|s| s.first()).filter(|_| has_mu) {
            Some(&(lo, hi)) if lo > 0.0 && hi >= lo && hi.is_finite() => {
                if let Some(b) = bands.last_mut() {
                    b.push((r.band.lambda_s, lo, hi));
                }
            }
            _ => {
                if bands.last().is_some_and(|b| !b.is_empty()) {
                    bands.push(Vec::new());
                }
            }
        }
    }
    bands.retain(|b| b.len() >= 2);
    let mut first = true;
    for b in &bands {
        let mut polygon: Vec<(f64, f64)> = b.iter().map(|&(x, lo, _)| (x, lo)).collect();
        polygon.extend(b.iter().rev().map(|&(x, _, hi)| (x, hi)));
        let label = first.then(|| "μ of each measurement alone (min to max)".to_string());
        first = false;
        top.insert(
            0,
            Series {
                style: LineStyle::Shade,
                ..Series::line(label, polygon, 0)
            },
        );
    }
    if top.iter().all(|s| s.points.is_empty()) {
        return Err(FigureError::Empty(format!("{symbol} is defined at no λs of the scan")));
    }
    let x = log_axis("λs (m)", &top, true)?;
    let y_top = log_axis(symbol, &top, false)?;
    // Below: the measurements each row rests on.
    let n = names.len();
    let mut bottom = Vec::with_capacity(2 * n);
    for (k, name) in names.iter().enumerate() {
        let level = (k + 1) as f64;
        if let Some((lo, hi)) = reliable.get(k).copied().flatten() {
            let (lo, hi) = (lo.max(x.range.0), hi.min(x.range.1));
            if lo < hi {
                bottom.push(Series {
                    style: LineStyle::Shade,
                    ..Series::line(
                        None,
                        vec![
                            (lo, level - 0.3),
                            (hi, level - 0.3),
                            (hi, level + 0.3),
                            (lo, level + 0.3),
                        ],
                        k % COLOURS,
                    )
                });
            }
        }
        let on: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.measurements.contains(&k))
            .map(|r| (r.band.lambda_s, level))
            .collect();
        let markers = Some(Markers {
            shape: SHAPES[(k + 1) % SHAPES.len()],
            phase: k as f64 / n.max(1) as f64,
        });
        bottom.push(Series {
            markers,
            ..Series::line(None, on, k % COLOURS)
        });
        // Named in the upper legend (the lower panel has no room for one).
        top.push(Series {
            markers,
            ..Series::line(Some(format!("below: {name}")), Vec::new(), k % COLOURS)
        });
    }
    Ok(Page {
        top: Chart {
            title: Some(format!("{symbol} against λs, λc fixed: {title}")),
            x: x.clone(),
            y: y_top,
            series: top,
            legend: Corner::Clear,
        },
        bottom: Some(Chart {
            title: Some("the measurements each λs rests on (shaded: each one's reliable range)".into()),
            x,
            y: ChartAxis {
                title: "measurement".into(),
                log: false,
                range: (0.5, n as f64 + 0.5),
                ticks: Some((1..=n).map(|k| k as f64).collect()),
            },
            series: bottom,
            legend: Corner::Clear,
        }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dense spectrum draws as bin averages of 1/100 decade; a sparse
    /// one as it is.
    #[test]
    fn dense_spectra_are_drawn_as_bin_averages() {
        let q: Vec<f64> = (1..=1000).map(|k| k as f64 * 1e6).collect();
        let c: Vec<f64> = q
            .iter()
            .enumerate()
            .map(|(k, q)| q.powi(-3) * if k % 2 == 0 { 1e3 } else { 1.0 })
            .collect();
        let p = Psd { q, c };
        let d = drawn(&p);
        // q from 1e6 to 1e9: 3 decades, at most 301 bins.
        assert!(d.len() <= 301 && d.len() > 150, "{}", d.len());
        // The first point alone in its bin, as it is; from 1e8 on, bins of
        // several points mix the two alternating levels (C·q³ = 1000 and 1).
        assert_eq!(d[0], (p.q[0], p.c[0]));
        let upper: Vec<f64> = d
            .iter()
            .filter(|(q, _)| *q > 1.1e8 && *q < 9.9e8)
            .map(|(q, c)| c * q.powi(3))
            .collect();
        assert!(upper.len() > 50);
        assert!(upper.iter().all(|v| *v > 100.0 && *v < 900.0), "{upper:?}");
        let sparse = Psd {
            q: vec![0.0, 1e3, 1e5, 1e7],
            c: vec![1.0, 2.0, 3.0, 4.0],
        };
        assert_eq!(drawn(&sparse), vec![(1e3, 2.0), (1e5, 3.0), (1e7, 4.0)]);
    }

    /// A measurement without a reliable spectrum keeps its legend entry;
    /// the cut-off of one with a tip radius is marked at 2π/cutoff; the
    /// combined curve is last but for the markers, in black.
    #[test]
    fn psd_page_names_every_measurement() {
        let p = Psd {
            q: (0..50).map(|k| 1e6 * 1.1f64.powi(k)).collect(),
            c: (0..50).map(|k| 1e-20 * 1.1f64.powi(-3 * k)).collect(),
        };
        let with = MeasurementPsd {
            psd: Some(p.clone()),
            cutoff: Some(1e-6),
            reason: None,
        };
        let without = MeasurementPsd {
            psd: None,
            cutoff: None,
            reason: Some("no reliable data".into()),
        };
        let page = container_psd_page(
            "t",
            &[("a".into(), &with), ("b".into(), &without)],
            Some(&p),
            None,
            None,
        )
        .unwrap();
        let labels: Vec<Option<&str>> = page.top.series.iter().map(|s| s.label.as_deref()).collect();
        assert_eq!(
            labels,
            vec![Some("a"), Some("b (no reliable spectrum)"), Some("combined"), None]
        );
        assert_eq!(page.top.series[2].color, BLACK_INDEX);
        let cut = &page.top.series[3];
        assert_eq!(cut.style, LineStyle::Dotted);
        assert!((cut.points[0].0 - 2.0 * PI / 1e-6).abs() < 1e-3);
        let page = container_psd_page("t", &[("a".into(), &with)], Some(&p), Some(2e-6), Some(1e-5)).unwrap();
        let marked: Vec<&str> = page.top.series.iter().filter_map(|s| s.label.as_deref()).collect();
        assert_eq!(marked, vec!["a", "combined", "2π/λs", "2π/λc"]);
    }
}

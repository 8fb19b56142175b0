//! μ from the whole band of a container's measurements (docs/MODEL.md,
//! the multi-measurement section): the spectral moments of the combined
//! spectrum between 2π/λc and 2π/λs, the roughness from them, the height
//! distribution from the measurement(s) that resolve λc, then the model
//! and the friction at each load as for one surface; and the scan over λs
//! with each row's spread across the measurements that cover its band.

use std::f64::consts::PI;

use super::{
    combined_psd, measurement_psd, roughness_from_moments, spectral_moments, Heights, Measurement, MeasurementPsd,
    Moments, Roughness,
};
use crate::topography::{EvaluateError, StatsOptions, Surface, SurfaceModel};
use crate::{Classify, ErrorKind, Friction, Load, Model, Params, Shortest, Warning};

/// The band of scales μ is computed over (metres): λs the shortest
/// wavelength, λc the longest.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Band {
    /// The short cut-off λs (m).
    pub lambda_s: f64,
    /// The long cut-off λc (m).
    pub lambda_c: f64,
}

/// The scales each measurement resolves reliably and their union.
#[derive(Debug, Clone, PartialEq)]
pub struct Resolved {
    /// Each measurement's reliable wavelengths (λ_min, λ_max) in metres,
    /// 2π over its reliable spectrum's largest and smallest nonzero q;
    /// `None` where it has no reliable spectrum.
    pub ranges: Vec<Option<(f64, f64)>>,
}

impl Resolved {
    /// The reliable ranges of `spectra` (see [`Resolved::ranges`]).
    pub fn of(spectra: &[MeasurementPsd]) -> Resolved {
        let ranges = spectra
            .iter()
            .map(|s| {
                let psd = s.psd.as_ref()?;
                let q_min = psd.q.iter().copied().filter(|&q| q > 0.0).fold(f64::INFINITY, f64::min);
                let q_max = psd.q.iter().copied().fold(0.0, f64::max);
                (q_min.is_finite() && q_max > q_min).then(|| (2.0 * PI / q_max, 2.0 * PI / q_min))
            })
            .collect();
        Resolved { ranges }
    }

    /// The default band: λc the largest scale any measurement resolves, λs
    /// the smallest reliable scale of any. `None` if none has a reliable
    /// spectrum.
    pub fn default_band(&self) -> Option<Band> {
        let lambda_s = self.ranges.iter().flatten().map(|r| r.0).fold(f64::INFINITY, f64::min);
        let lambda_c = self.ranges.iter().flatten().map(|r| r.1).fold(0.0, f64::max);
        (lambda_s.is_finite() && lambda_c > lambda_s).then_some(Band { lambda_s, lambda_c })
    }

    /// The measurements (indices) whose reliable q-range overlaps
    /// [2π/λc, 2π/λs].
    pub fn overlapping(&self, band: Band) -> Vec<usize> {
        self.ranges
            .iter()
            .enumerate()
            .filter_map(|(i, r)| r.filter(|r| r.0 < band.lambda_c && r.1 > band.lambda_s).map(|_| i))
            .collect()
    }

    /// The measurements (indices) that resolve λc: whose reliable range
    /// reaches it (to 10⁻⁹ relative).
    pub fn covering(&self, lambda_c: f64) -> Vec<usize> {
        self.ranges
            .iter()
            .enumerate()
            .filter_map(|(i, r)| r.filter(|r| r.1 >= lambda_c * (1.0 - 1e-9)).map(|_| i))
            .collect()
    }
}

/// Why a container has no μ over a band.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum AnalysisError {
    /// No measurement has a reliable spectrum.
    #[error("no measurement has a reliable spectrum")]
    NoSpectrum,
    /// The band is not a band: λs ≥ λc, not positive, or holding fewer
    /// than two points of the spectrum.
    #[error("band: {0}")]
    Band(String),
    /// The moments make no roughness (α out of range, a zero moment).
    #[error(
        "band {}..{} m: its spectral moments make no roughness (m0, m2, m4 > 0 and α in range needed)",
        Shortest(*lambda_s),
        Shortest(*lambda_c)
    )]
    Roughness {
        /// λs (m).
        lambda_s: f64,
        /// λc (m).
        lambda_c: f64,
    },
    /// No measurement with uniformly sampled heights resolves λc, so there
    /// is no height distribution.
    #[error("no measurement with uniformly sampled heights resolves the long cut-off {0} m (the height distribution comes from one that does)")]
    NoHeights(f64),
    /// The heights' statistics of the covering measurement failed.
    #[error("measurement {name}: {reason}")]
    Stats {
        /// The measurement's name.
        name: String,
        /// Why.
        reason: String,
    },
    /// A step of the model failed (distribution, inputs, model, a load).
    #[error(transparent)]
    Evaluate(EvaluateError),
}

impl Classify for AnalysisError {
    fn kind(&self) -> ErrorKind {
        match self {
            AnalysisError::Evaluate(e) => e.kind(),
            _ => ErrorKind::Domain,
        }
    }
}

/// A warning's record: its kind and its message.
#[derive(serde::Serialize)]
struct WarningRecord {
    kind: &'static str,
    message: String,
}

/// Serialises warnings as `{kind, message}` records.
pub(super) fn warning_records<S: serde::Serializer>(warnings: &[Warning], s: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeSeq;
    let mut seq = s.serialize_seq(Some(warnings.len()))?;
    for w in warnings {
        seq.serialize_element(&WarningRecord {
            kind: w.kind().name(),
            message: w.to_string(),
        })?;
    }
    seq.end()
}

/// μ from the whole band ([`container_analysis`]).
#[derive(Debug, Clone, serde::Serialize)]
pub struct ContainerAnalysis {
    /// The band integrated over.
    pub band: Band,
    /// The spectral moments of the combined spectrum over the band.
    pub moments: Moments,
    /// σ, α, η, R, β from the moments.
    pub roughness: Roughness,
    /// The measurement (index) whose detrended heights give the height
    /// distribution: the one with the most points among those resolving λc.
    pub heights_from: usize,
    /// The measurements (indices) whose reliable range overlaps the band.
    pub measurements: Vec<usize>,
    /// The model's inputs.
    pub model: Params,
    /// The friction at each load, in the loads' order.
    pub frictions: Vec<Friction>,
    /// The validity domain's warnings and each friction's (the contact's,
    /// too few asperities, the height tail's).
    #[serde(serialize_with = "warning_records")]
    pub warnings: Vec<Warning>,
}

/// The measurement's heights as a single surface (statistics with the
/// default options), for the height distribution.
fn heights_surface(m: &Measurement) -> Result<Surface, AnalysisError> {
    let Heights::Uniform(t) = &m.heights else {
        return Err(AnalysisError::Stats {
            name: m.name.clone(),
            reason: "nonuniform profile".into(),
        });
    };
    Surface::new(t.clone(), StatsOptions::default()).map_err(|e| AnalysisError::Stats {
        name: m.name.clone(),
        reason: e.to_string(),
    })
}

/// The surface whose heights give the distribution: among the measurements
/// resolving λc with uniform heights, the one with the most points.
fn covering_surface(
    measurements: &[Measurement],
    resolved: &Resolved,
    lambda_c: f64,
) -> Result<(usize, Surface), AnalysisError> {
    let best = resolved
        .covering(lambda_c)
        .into_iter()
        .filter(|&i| matches!(measurements[i].heights, Heights::Uniform(_)))
        .max_by_key(|&i| {
            let (nx, ny) = measurements[i].grid();
            nx * ny
        })
        .ok_or(AnalysisError::NoHeights(lambda_c))?;
    Ok((best, heights_surface(&measurements[best])?))
}

/// μ from moments: roughness, then the model's inputs with the heights of
/// `heights` and the friction at each load with its warnings.
fn mu_of_moments(
    moments: Moments,
    band: Band,
    heights: &Surface,
    how: &SurfaceModel,
    loads: &[Load],
) -> Result<(Roughness, Params, Vec<Friction>, Vec<Warning>), AnalysisError> {
    let roughness = roughness_from_moments(&moments).ok_or(AnalysisError::Roughness {
        lambda_s: band.lambda_s,
        lambda_c: band.lambda_c,
    })?;
    let distribution = heights
        .distribution(how.family)
        .map_err(|e| AnalysisError::Evaluate(EvaluateError::Distribution(e)))?;
    let physical = how
        .materials
        .with_roughness(roughness.sigma, roughness.radius, roughness.eta);
    let params = Params::from_physical(&physical)
        .map_err(|e| AnalysisError::Evaluate(EvaluateError::Params(e)))?
        .distribution(distribution)
        .fit(how.fit)
        .kind(how.kind);
    let mut warnings: Vec<Warning> = Warning::of_params(&params).collect();
    let mut frictions = Vec::with_capacity(loads.len());
    if !loads.is_empty() {
        let model = Model::new(params.clone()).map_err(|e| AnalysisError::Evaluate(EvaluateError::Model(e)))?;
        for load in loads {
            let f = load
                .friction(&model, &physical)
                .map_err(|e| AnalysisError::Evaluate(EvaluateError::Load(e)))?;
            warnings.extend(f.warnings(&model, &physical));
            warnings.extend(heights.tail_warning(f.contact.h_star));
            frictions.push(f);
        }
    }
    Ok((roughness, params, frictions, warnings))
}

/// μ from the whole band of a container surface's `measurements`
/// (their reliable spectra `spectra`, [`measurement_psd`]): the moments
/// m0, m2, m4 of the combined spectrum ([`combined_psd`], `per_decade`
/// points a decade) between 2π/λc and 2π/λs ([`spectral_moments`]; `band`
/// `None`: [`Resolved::default_band`]), σ, α, η, R, β from them
/// ([`roughness_from_moments`]), the height distribution of `how.family`
/// (default: [`Surface::default_family`]) from the detrended heights of
/// the measurement resolving λc with the most points, then
/// [`Params::from_physical`] and the friction at each of `loads`.
pub fn container_analysis(
    measurements: &[Measurement],
    spectra: &[MeasurementPsd],
    band: Option<Band>,
    per_decade: u32,
    how: &SurfaceModel,
    loads: &[Load],
) -> Result<ContainerAnalysis, AnalysisError> {
    let resolved = Resolved::of(spectra);
    let band = match band {
        Some(b) => b,
        None => resolved.default_band().ok_or(AnalysisError::NoSpectrum)?,
    };
    let combined = combined_psd(spectra, per_decade).ok_or(AnalysisError::NoSpectrum)?;
    analyse(measurements, &resolved, &combined.psd, band, how, loads)
}

fn analyse(
    measurements: &[Measurement],
    resolved: &Resolved,
    combined: &crate::topography::Psd,
    band: Band,
    how: &SurfaceModel,
    loads: &[Load],
) -> Result<ContainerAnalysis, AnalysisError> {
    let moments = band_moments(combined, band)?;
    let (heights_from, heights) = covering_surface(measurements, resolved, band.lambda_c)?;
    let (roughness, model, frictions, warnings) = mu_of_moments(moments, band, &heights, how, loads)?;
    Ok(ContainerAnalysis {
        band,
        moments,
        roughness,
        heights_from,
        measurements: resolved.overlapping(band),
        model,
        frictions,
        warnings,
    })
}

fn band_moments(psd: &crate::topography::Psd, band: Band) -> Result<Moments, AnalysisError> {
    if !(band.lambda_s > 0.0 && band.lambda_c > band.lambda_s && band.lambda_c.is_finite()) {
        return Err(AnalysisError::Band(format!(
            "λs {} m and λc {} m: need 0 < λs < λc, finite",
            Shortest(band.lambda_s),
            Shortest(band.lambda_c)
        )));
    }
    spectral_moments(psd, band.lambda_s, band.lambda_c).ok_or_else(|| {
        AnalysisError::Band(format!(
            "λs {} m to λc {} m holds fewer than two points of the spectrum",
            Shortest(band.lambda_s),
            Shortest(band.lambda_c)
        ))
    })
}

/// One row of [`container_scan`]: μ over [λs, λc] and its spread.
#[derive(Debug, Clone, serde::Serialize)]
pub struct ScanRow {
    /// The band of this row.
    pub band: Band,
    /// The measurements (indices) whose reliable q-range overlaps the band.
    pub measurements: Vec<usize>,
    /// μ from the combined spectrum, or why there is none.
    #[serde(serialize_with = "result_record")]
    pub result: Result<ContainerAnalysis, AnalysisError>,
    /// Where two or more measurements overlap the band: each load's
    /// (min, max) μ over the measurements taken alone (each one's own
    /// spectrum over the band, the same heights); `None` otherwise or
    /// where fewer than two of them give a μ. A measurement that resolves
    /// only a small part of the band has a small σ alone and may put the
    /// contact far below the mean plane, where μ is 0: the spread says how
    /// much μ depends on which instrument is believed, not a statistical
    /// error.
    pub spread: Option<Vec<(f64, f64)>>,
}

fn result_record<S: serde::Serializer>(r: &Result<ContainerAnalysis, AnalysisError>, s: S) -> Result<S::Ok, S::Error> {
    use serde::Serialize;
    match r {
        Ok(a) => a.serialize(s),
        Err(e) => {
            use serde::ser::SerializeMap;
            let mut map = s.serialize_map(Some(1))?;
            map.serialize_entry("error", &e.to_string())?;
            map.end()
        }
    }
}

/// The scan over λs, log-spaced at `per_decade` a decade (at least 1) from
/// the smallest reliable scale of any measurement up to λc (the band's,
/// default [`Resolved::default_band`]), λc fixed: each row μ from the
/// combined spectrum ([`container_analysis`]) with the measurements it
/// rests on, and the spread across them where two or more overlap.
/// The row count is bounded by the decades spanned × `per_decade`
/// (`per_decade` at most 1000).
pub fn container_scan(
    measurements: &[Measurement],
    spectra: &[MeasurementPsd],
    lambda_c: Option<f64>,
    per_decade: u32,
    how: &SurfaceModel,
    loads: &[Load],
) -> Result<Vec<ScanRow>, AnalysisError> {
    let per = per_decade.clamp(1, 1000);
    let resolved = Resolved::of(spectra);
    let default = resolved.default_band().ok_or(AnalysisError::NoSpectrum)?;
    let lambda_c = lambda_c.unwrap_or(default.lambda_c);
    if !(lambda_c > default.lambda_s && lambda_c.is_finite()) {
        return Err(AnalysisError::Band(format!(
            "λc {} m: must be finite and above the smallest reliable scale {} m",
            Shortest(lambda_c),
            Shortest(default.lambda_s)
        )));
    }
    let combined = combined_psd(spectra, super::COMBINED_POINTS_PER_DECADE).ok_or(AnalysisError::NoSpectrum)?;
    let decades = (lambda_c / default.lambda_s).log10();
    let steps = (decades * f64::from(per)).ceil().max(1.0) as usize;
    // Covering heights are the same for every row (λc is fixed).
    let heights = covering_surface(measurements, &resolved, lambda_c);
    let mut rows = Vec::with_capacity(steps);
    for k in 0..steps {
        let lambda_s = default.lambda_s * 10f64.powf(k as f64 / f64::from(per));
        let band = Band { lambda_s, lambda_c };
        let over = resolved.overlapping(band);
        let (result, spread) = match &heights {
            Err(e) => (Err(e.clone()), None),
            Ok((heights_from, surface)) => {
                let result = band_moments(&combined.psd, band).and_then(|moments| {
                    let (roughness, model, frictions, warnings) = mu_of_moments(moments, band, surface, how, loads)?;
                    Ok(ContainerAnalysis {
                        band,
                        moments,
                        roughness,
                        heights_from: *heights_from,
                        measurements: over.clone(),
                        model,
                        frictions,
                        warnings,
                    })
                });
                (result, spread(spectra, &over, band, surface, how, loads))
            }
        };
        rows.push(ScanRow {
            band,
            measurements: over,
            result,
            spread,
        });
    }
    Ok(rows)
}

/// Each load's (min, max) μ over the measurements `over` taken alone.
fn spread(
    spectra: &[MeasurementPsd],
    over: &[usize],
    band: Band,
    heights: &Surface,
    how: &SurfaceModel,
    loads: &[Load],
) -> Option<Vec<(f64, f64)>> {
    if over.len() < 2 || loads.is_empty() {
        return None;
    }
    let each: Vec<Vec<f64>> = over
        .iter()
        .filter_map(|&i| {
            let psd = spectra[i].psd.as_ref()?;
            let moments = band_moments(psd, band).ok()?;
            let (_, _, frictions, _) = mu_of_moments(moments, band, heights, how, loads).ok()?;
            Some(frictions.iter().map(|f| f.mu).collect())
        })
        .collect();
    if each.len() < 2 {
        return None;
    }
    Some(
        (0..loads.len())
            .map(|j| {
                each.iter()
                    .map(|mus| mus[j])
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), mu| {
                        (lo.min(mu), hi.max(mu))
                    })
            })
            .collect(),
    )
}

/// The reliable spectra of `measurements` ([`measurement_psd`]), in
/// parallel with the `parallel` feature.
pub fn measurement_spectra(measurements: &[Measurement]) -> Vec<MeasurementPsd> {
    super::each(measurements, measurement_psd)
}

//! The combined 1-D power spectrum of a container's measurements, as
//! SurfaceTopography's container `power_spectrum(unit='m',
//! nb_points_per_decade=10)` computes it (`Container/Averaging.py`
//! `log_average` with `Support/Regression.py` `resample`), checked by
//! `tools/container_check.py`; and the spectral moments of a band of it.

use std::f64::consts::PI;

use super::{Heights, Measurement};
use crate::topography::{psd_profile_x, tip_reliability_cutoff, Psd, PsdError, Topography, Window, TIP_SAFETY_FACTOR};

/// Log-spaced bins per decade of the combined spectrum
/// (SurfaceTopography's `nb_points_per_decade` default).
pub const COMBINED_POINTS_PER_DECADE: u32 = 10;
/// Decades the bin edges reach beyond whole decades (SurfaceTopography's
/// `dectol`).
const DECADE_TOLERANCE: f64 = 0.01;
/// Grid points per smallest spacing of a nonuniform profile interpolated
/// onto a uniform grid (SurfaceTopography's `nb_interpolate`).
const NB_INTERPOLATE: usize = 5;
/// The most points a nonuniform profile is interpolated onto.
const MAX_INTERPOLATED: usize = 1 << 26;

/// A measurement's reliable 1-D spectrum along x.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasurementPsd {
    /// q from 0 (rad/m) and C (m³), the wavevectors below the reliability
    /// cut-off; `None` if the measurement has no reliable data (or its
    /// spectrum cannot be taken: missing points).
    pub psd: Option<Psd>,
    /// The short reliability cut-off (metres) from the tip radius or the
    /// resolution, if any: wavelengths below it are left out.
    pub cutoff: Option<f64>,
    /// Why there is no spectrum, if there is none.
    pub reason: Option<String>,
}

/// The combined spectrum: bins where at least one measurement has data.
#[derive(Debug, Clone, PartialEq)]
pub struct CombinedPsd {
    /// Wavevectors (rad/m) and the averaged 1-D PSD (m³).
    pub psd: Psd,
    /// The measurements (indices) that contribute to each bin.
    pub contributors: Vec<Vec<usize>>,
}

/// A measurement's reliable 1-D PSD along x, as SurfaceTopography's
/// `power_spectrum_from_profile(reliable=True, resampling_method=None)`:
/// the Hann window unless periodic; wavevectors below 2π/λ with λ the
/// larger of two pixels and the tip-radius (or resolution) cut-off. A
/// nonuniform profile is first interpolated linearly onto a grid of 5
/// points per smallest spacing and its spectrum cut at 2π/(mean spacing).
pub fn measurement_psd(m: &Measurement) -> MeasurementPsd {
    let none = |cutoff, reason: String| MeasurementPsd {
        psd: None,
        cutoff,
        reason: Some(reason),
    };
    let (t, mean_step) = match &m.heights {
        Heights::Uniform(t) => (t.clone(), None),
        Heights::Nonuniform { x, z } => match interpolate(x, z) {
            Ok(t) => (t, Some((x[x.len() - 1] - x[0]) / (x.len() - 1) as f64)),
            Err(e) => return none(None, e),
        },
    };
    let cutoff = match (m.tip_radius, m.resolution) {
        (Some(r), _) => match tip_reliability_cutoff(&t, r, TIP_SAFETY_FACTOR) {
            Ok(c) => c,
            Err(e) => return none(None, e.to_string()),
        },
        (None, Some(r)) => Some(r),
        (None, None) => None,
    };
    let window = if m.is_periodic && mean_step.is_none() {
        Window::None
    } else {
        Window::Hann
    };
    let psd = match psd_profile_x(&t, window) {
        Ok(p) => p,
        Err(e @ PsdError::MissingPoints { .. }) => return none(cutoff, e.to_string()),
        Err(e) => return none(cutoff, e.to_string()),
    };
    let pixels = 2.0 * t.nx() as f64 * t.dx() / t.nx() as f64;
    let lambda = cutoff.map_or(pixels, |c| c.max(pixels));
    let mut q_max = 2.0 * PI / lambda;
    if let Some(step) = mean_step {
        q_max = q_max.min(2.0 * PI / step);
    }
    let keep = psd.q.iter().take_while(|&&q| q < q_max).count();
    if keep <= 1 {
        return none(cutoff, "no reliable data: the cut-off is longer than the scan".into());
    }
    MeasurementPsd {
        psd: Some(Psd {
            q: psd.q[..keep].to_vec(),
            c: psd.c[..keep].to_vec(),
        }),
        cutoff,
        reason: None,
    }
}

/// A nonuniform profile linearly interpolated onto a uniform grid of
/// `5·⌊L/min Δx⌋` points spanning L (SurfaceTopography's `to_uniform`).
fn interpolate(x: &[f64], z: &[f64]) -> Result<Topography, String> {
    let n = x.len();
    let length = x[n - 1] - x[0];
    let min_step = x.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
    let cells = (length / min_step).floor();
    if !(cells.is_finite() && cells * NB_INTERPOLATE as f64 <= MAX_INTERPOLATED as f64) {
        return Err(format!(
            "a nonuniform profile's smallest spacing ({min_step:e} m) makes over {MAX_INTERPOLATED} points"
        ));
    }
    let points = NB_INTERPOLATE * cells as usize;
    if points < 2 {
        return Err("a nonuniform profile of fewer than 2 grid points".into());
    }
    let pixel = length / (points - 1) as f64;
    let heights = interp_grid(x, z, pixel, points);
    Topography::profile(heights, pixel).map_err(|e| e.to_string())
}

/// The profile (x increasing) linearly interpolated at `x[0] + i·pixel`,
/// i < `points`, as numpy's `interp` (clamped at the ends).
pub(super) fn interp_grid(x: &[f64], z: &[f64], pixel: f64, points: usize) -> Vec<f64> {
    let n = x.len();
    let mut heights = Vec::with_capacity(points);
    let mut s = 0;
    for i in 0..points {
        let p = i as f64 * pixel + x[0];
        while s + 2 < n && x[s + 1] < p {
            s += 1;
        }
        let h = if p <= x[0] {
            z[0]
        } else if p >= x[n - 1] {
            z[n - 1]
        } else {
            let (x1, x2) = (x[s], x[s + 1]);
            let slope = (z[s + 1] - z[s]) / (x2 - x1);
            slope * (p - x1) + z[s]
        };
        heights.push(h);
    }
    heights
}

/// Bin-averages (x, y) onto SurfaceTopography's log grid from 10^lo to
/// 10^hi decades: `(hi − lo)·per + 1` edges equally spaced in log10 from
/// lo − 0.01 to hi + 0.01; a point on an edge belongs to the bin below.
/// Each bin: the mean x and mean y of its points, `None` if empty.
fn resample(x: &[f64], y: &[f64], lo: i32, hi: i32, per: u32) -> Vec<Option<(f64, f64)>> {
    let start = (10f64.powf(f64::from(lo))).log10() - DECADE_TOLERANCE;
    let stop = (10f64.powf(f64::from(hi))).log10() + DECADE_TOLERANCE;
    let edges_n = (hi - lo) as usize * per as usize + 1;
    let step = (stop - start) / (edges_n - 1) as f64;
    let edges: Vec<f64> = (0..edges_n)
        .map(|i| {
            let e = if i == edges_n - 1 {
                stop
            } else {
                i as f64 * step + start
            };
            10f64.powf(e)
        })
        .collect();
    let bins = edges_n - 1;
    let mut sx = vec![0.0; bins];
    let mut sy = vec![0.0; bins];
    let mut count = vec![0usize; bins];
    for (&xv, &yv) in x.iter().zip(y) {
        // searchsorted(side='left'): the first edge >= x.
        let idx = edges.partition_point(|&e| e < xv);
        if idx == 0 || idx > bins {
            continue;
        }
        sx[idx - 1] += xv;
        sy[idx - 1] += yv;
        count[idx - 1] += 1;
    }
    (0..bins)
        .map(|b| (count[b] > 0).then(|| (sx[b] / count[b] as f64, sy[b] / count[b] as f64)))
        .collect()
}

/// The combined 1-D PSD of `spectra` (one per measurement, from
/// [`measurement_psd`]), as SurfaceTopography's `log_average`: each
/// measurement's spectrum (q > 0) bin-averaged onto log bins covering its
/// whole decades, `per_decade` a decade; bins aligned across
/// measurements; in each bin the plain mean over the measurements with
/// data there (of q and of C). `None` if no measurement has data.
pub fn combined_psd(spectra: &[MeasurementPsd], per_decade: u32) -> Option<CombinedPsd> {
    use std::collections::BTreeMap;
    let per = per_decade.max(1);
    let mut bins: BTreeMap<i64, Vec<(f64, f64, usize)>> = BTreeMap::new();
    for (i, s) in spectra.iter().enumerate() {
        let Some(psd) = &s.psd else { continue };
        let lower = psd.q.iter().copied().filter(|&q| q > 0.0).fold(f64::INFINITY, f64::min);
        let upper = psd.q.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if !lower.is_finite() || upper <= 0.0 {
            continue;
        }
        let lo = lower.log10().floor() as i32;
        let hi = upper.log10().ceil() as i32;
        if lo >= hi {
            // SurfaceTopography: NoReliableDataError (min >= max).
            continue;
        }
        for (j, bin) in resample(&psd.q, &psd.c, lo, hi, per).into_iter().enumerate() {
            if let Some((q, c)) = bin {
                bins.entry(i64::from(lo) * i64::from(per) + j as i64)
                    .or_default()
                    .push((q, c, i));
            }
        }
    }
    if bins.is_empty() {
        return None;
    }
    let mut out = CombinedPsd {
        psd: Psd {
            q: Vec::new(),
            c: Vec::new(),
        },
        contributors: Vec::new(),
    };
    for vals in bins.values() {
        let valid: Vec<&(f64, f64, usize)> = vals.iter().filter(|v| v.0.is_finite() && v.1.is_finite()).collect();
        if valid.is_empty() {
            continue;
        }
        let n = valid.len() as f64;
        out.psd.q.push(valid.iter().map(|v| v.0).sum::<f64>() / n);
        out.psd.c.push(valid.iter().map(|v| v.1).sum::<f64>() / n);
        out.contributors.push(valid.iter().map(|v| v.2).collect());
    }
    Some(out)
}

/// The spectral moments of a band of a 1-D PSD (see [`spectral_moments`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Moments {
    /// m0: the mean square height (m²).
    pub m0: f64,
    /// m2: the mean square slope along a direction.
    pub m2: f64,
    /// m4: the mean square curvature along a direction (1/m²).
    pub m4: f64,
    /// The band's wavevectors actually integrated over (rad/m).
    pub q_range: (f64, f64),
}

/// The spectral moments m_n = (1/π)∫ qⁿ C¹ᴰ(q) dq, n = 0, 2, 4, of the 1-D
/// PSD `psd` between q = 2π/λc and 2π/λs (trapezoids between the
/// spectrum's points within the band, on a log-log linear interpolation of
/// C to the band's ends where they fall between points). For an isotropic
/// surface these profile moments are the areal directional moments of
/// MODEL.md §10 (Nayak 1971): m0 the height variance, m2 the slope
/// variance and m4 the curvature variance along any direction. `None` if
/// the band holds fewer than two points of the spectrum or is empty.
pub fn spectral_moments(psd: &Psd, lambda_s: f64, lambda_c: f64) -> Option<Moments> {
    if !(lambda_s > 0.0 && lambda_c > lambda_s && lambda_c.is_finite()) {
        return None;
    }
    let (q_lo, q_hi) = (2.0 * PI / lambda_c, 2.0 * PI / lambda_s);
    let pts: Vec<(f64, f64)> = psd
        .q
        .iter()
        .zip(&psd.c)
        .filter(|(q, c)| **q > 0.0 && c.is_finite() && **c > 0.0)
        .map(|(q, c)| (*q, *c))
        .collect();
    // Log-log interpolation of C at q within the spectrum.
    let at = |q: f64| -> Option<f64> {
        let k = pts.partition_point(|p| p.0 < q);
        if k == 0 || k >= pts.len() {
            return None;
        }
        let (a, b) = (pts[k - 1], pts[k]);
        let t = (q / a.0).ln() / (b.0 / a.0).ln();
        Some((a.1.ln() + t * (b.1 / a.1).ln()).exp())
    };
    let mut band: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0 >= q_lo && p.0 <= q_hi).collect();
    if let Some(c) = at(q_lo).filter(|_| band.first().is_none_or(|p| p.0 > q_lo)) {
        band.insert(0, (q_lo, c));
    }
    if let Some(c) = at(q_hi).filter(|_| band.last().is_none_or(|p| p.0 < q_hi)) {
        band.push((q_hi, c));
    }
    if band.len() < 2 {
        return None;
    }
    let mut m = [0.0; 3];
    for w in band.windows(2) {
        let ((q1, c1), (q2, c2)) = (w[0], w[1]);
        for (k, n) in [0, 2, 4].into_iter().enumerate() {
            m[k] += 0.5 * (q2 - q1) * (q1.powi(n) * c1 + q2.powi(n) * c2) / PI;
        }
    }
    Some(Moments {
        m0: m[0],
        m2: m[1],
        m4: m[2],
        q_range: (band[0].0, band[band.len() - 1].0),
    })
}

/// The model's roughness inputs from the spectral moments (MODEL.md §10):
/// σ = √m0, the bandwidth α = m0·m4/m2², the summit density η, the summit
/// radius R and β = σ·η·R, by the same functions the single-measurement
/// statistics use.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Roughness {
    /// rms height σ (m).
    pub sigma: f64,
    /// Nayak's bandwidth parameter α.
    pub alpha: f64,
    /// Summit density η (1/m²).
    pub eta: f64,
    /// Summit radius R (m).
    pub radius: f64,
    /// β = σ_s·η·R of the model, from α (MODEL.md §10).
    pub beta: f64,
}

/// [`Roughness`] from `moments`; `None` where a moment is not positive
/// and finite or α is not admissible (≤ 1.5).
pub fn roughness_from_moments(moments: &Moments) -> Option<Roughness> {
    let Moments { m0, m2, m4, .. } = *moments;
    if !([m0, m2, m4].iter().all(|v| v.is_finite() && *v > 0.0)) {
        return None;
    }
    let alpha = m0 * m4 / (m2 * m2);
    if !(crate::gw::ALPHA_ADMISSIBLE.contains(alpha) && alpha.is_finite()) {
        return None;
    }
    Some(Roughness {
        sigma: m0.sqrt(),
        alpha,
        eta: crate::gw::summit_density(m2, m4),
        radius: crate::gw::summit_radius(m4),
        beta: crate::gw::beta_of_alpha(alpha),
    })
}

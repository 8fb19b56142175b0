//! The combined scale-dependent statistics of a container's measurements:
//! the mean square slope (order 1) and curvature (order 2) along x at
//! stencil lengths on a grid aligned to whole decades, each measurement's
//! over its reliable bandwidth and their mean where several have a value,
//! as SurfaceTopography's `Container/ScaleDependentStatistics.py`
//! (`scale_dependent_statistical_property(lambda x, y=None: np.mean(x*x),
//! n, unit='m', nb_points_per_decade)`) computes them, nonuniform line
//! scans included; checked by `tools/container_check.py`.

use std::collections::BTreeMap;

use super::spectrum::interp_grid;
use super::{Heights, Measurement};
use crate::topography::scale::{probe_cutoff, scale_dependent_x};
use crate::topography::{tip_reliability_cutoff, TIP_SAFETY_FACTOR};

/// Fewest derivative values a statistic is taken over
/// (SurfaceTopography's `threshold`); fewer give NaN.
const THRESHOLD: usize = 4;

/// One measurement's scale-dependent mean square slope or curvature along
/// x on the container's aligned grid ([`measurement_scale_dependent`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MeasurementScale {
    /// The short reliability cut-off (metres) from the tip radius or the
    /// resolution, if any (for a nonuniform profile, from its own
    /// interpolated derivatives, as SurfaceTopography's
    /// `scanning_probe_reliability_cutoff` of a nonuniform line scan).
    pub cutoff: Option<f64>,
    /// Each value's index on the grid aligned to whole decades:
    /// `decade · per_decade + k` for the length `10^(decade + k/per_decade)`.
    pub grid_index: Vec<i64>,
    /// Stencil lengths (metres), increasing.
    pub distance: Vec<f64>,
    /// The mean square derivative at each (slope: 1; curvature: 1/m²); NaN
    /// where fewer than 4 derivative values are kept.
    pub mean_square: Vec<f64>,
}

/// The combined scale-dependent mean square slope (order 1) or curvature
/// (order 2) of a container's measurements.
#[derive(Debug, Clone, PartialEq)]
pub struct CombinedScale {
    /// Each length's index on the grid aligned to whole decades (see
    /// [`MeasurementScale::grid_index`]).
    pub grid_index: Vec<i64>,
    /// Stencil lengths (metres), increasing: the first contributing
    /// measurement's (as SurfaceTopography reports them).
    pub distance: Vec<f64>,
    /// The mean square derivative along x at each (slope: 1; curvature:
    /// 1/m²): the mean over the measurements with a value there (NaN where
    /// every one has NaN).
    pub mean_square: Vec<f64>,
    /// The measurements (indices) behind each value.
    pub contributors: Vec<Vec<usize>>,
}

/// SurfaceTopography's `bandwidth()`: the mean pixel size and the mean
/// physical size (uniform), the mean spacing and the length (nonuniform).
fn bandwidth(m: &Measurement) -> (f64, f64) {
    match &m.heights {
        Heights::Uniform(t) => match t.dy() {
            None => (t.dx(), t.nx() as f64 * t.dx()),
            Some(dy) => ((t.dx() + dy) / 2.0, (t.nx() as f64 * t.dx() + t.ny() as f64 * dy) / 2.0),
        },
        Heights::Nonuniform { x, .. } => {
            let n = x.len();
            let mean = x.windows(2).map(|w| w[1] - w[0]).sum::<f64>() / (n - 1) as f64;
            (mean, x[n - 1] - x[0])
        }
    }
}

/// The derivative of order `n` (1 or 2) of a nonuniform profile at stencil
/// length `d`, as SurfaceTopography's nonuniform `derivative(n,
/// distance=d)`: the scale factor `k = ⌈d/l⌉` (l the mean spacing), the
/// profile interpolated linearly onto a grid of spacing `d/(k·n)` from its
/// first point (`⌊L/spacing⌋ + 1` points), then the uniform stencil of `k`
/// steps on the points whose stencil lies in the data: upwind
/// `[h(x + d) − h(x)]/d`, central `[h(x − d/2) − 2h(x) + h(x + d/2)]/(d/2)²`.
/// Each value is handed to `each`; returns how many. Nothing (0) if the
/// grid would exceed 4 points per data point (a length below the scale
/// factor's range, which the callers do not ask for).
fn nonuniform_derivative(x: &[f64], z: &[f64], lower: f64, n: usize, d: f64, mut each: impl FnMut(f64)) -> usize {
    let length = x[x.len() - 1] - x[0];
    let k = (d / lower).ceil();
    if !(k.is_finite() && k >= 1.0) {
        return 0;
    }
    let pixel = d / k / n as f64;
    let points = (length / pixel).floor() + 1.0;
    if !(points.is_finite() && points <= 4.0 * x.len() as f64 + 4.0) {
        return 0;
    }
    let (k, points) = (k as usize, points as usize);
    let h = interp_grid(x, z, pixel, points);
    let step = k as f64 * pixel;
    match n {
        1 => {
            let kept = points.saturating_sub(k);
            for i in 0..kept {
                each((-h[i] + h[i + k]) / step);
            }
            kept
        }
        _ => {
            if points <= 2 * k {
                return 0;
            }
            for i in k..points - k {
                each((h[i - k] - 2.0 * h[i] + h[i + k]) / (step * step));
            }
            points - 2 * k
        }
    }
}

/// The reliability cut-off of a measurement (see [`MeasurementScale::cutoff`]).
fn cutoff(m: &Measurement) -> Option<f64> {
    match (m.tip_radius, m.resolution, &m.heights) {
        (Some(r), _, Heights::Uniform(t)) => tip_reliability_cutoff(t, r, TIP_SAFETY_FACTOR).ok().flatten(),
        (Some(r), _, Heights::Nonuniform { x, z }) => {
            let (lower, upper) = bandwidth(m);
            probe_cutoff(lower, upper, r, TIP_SAFETY_FACTOR, |d| {
                let mut min = f64::INFINITY;
                let count = nonuniform_derivative(x, z, lower, 2, d, |v| min = min.min(v));
                (count > 0).then_some(min)
            })
            .ok()
            .flatten()
        }
        (None, r, _) => r,
    }
}

/// One measurement's scale-dependent mean square slope (`order` 1) or
/// curvature (`order` 2) along x, as SurfaceTopography's container does
/// for each of its topographies: with λ_low its bandwidth's lower bound
/// (mean pixel size, or mean spacing of a nonuniform profile), or its
/// reliability cut-off if larger, and L its size, the lengths
/// 10^(k/per_decade) over the whole decades from ⌊log₁₀ λ_low⌋ to
/// ⌈log₁₀ L⌉ that lie strictly between `order`·λ_low and L; at each the
/// mean square of the derivative (uniform: [`crate::topography::ScaleRow`];
/// nonuniform: interpolated onto a grid at that length, see
/// SurfaceTopography's nonuniform `derivative(distance=...)`). Empty if
/// nothing lies in its band.
pub fn measurement_scale_dependent(m: &Measurement, order: u32, per_decade: u32) -> MeasurementScale {
    let per = per_decade.max(1);
    let order = order.clamp(1, 2);
    let n = f64::from(order);
    let (pixel, size) = bandwidth(m);
    let cutoff = cutoff(m);
    let mut out = MeasurementScale {
        cutoff,
        grid_index: Vec::new(),
        distance: Vec::new(),
        mean_square: Vec::new(),
    };
    let lower = cutoff.map_or(pixel, |c| c.max(pixel));
    if !(lower < size && lower > 0.0) {
        return out;
    }
    let lo = lower.log10().floor() as i32;
    let hi = size.log10().ceil() as i32;
    let count = (hi - lo) as usize * per as usize + 1;
    let step = f64::from(hi - lo) / (count - 1) as f64;
    for k in 0..count {
        let e = if k == count - 1 {
            f64::from(hi)
        } else {
            k as f64 * step + f64::from(lo)
        };
        let d = 10f64.powf(e);
        if d > n * lower && d < size {
            out.grid_index.push(i64::from(lo) * i64::from(per) + k as i64);
            out.distance.push(d);
        }
    }
    match &m.heights {
        Heights::Uniform(t) => match scale_dependent_x(t, &out.distance, order == 2) {
            Ok(rms) => out.mean_square = rms.iter().map(|r| r * r).collect(),
            Err(_) => {
                out.grid_index.clear();
                out.distance.clear();
            }
        },
        Heights::Nonuniform { x, z } => {
            out.mean_square = out
                .distance
                .iter()
                .map(|&d| {
                    let mut sum = 0.0;
                    let kept = nonuniform_derivative(x, z, pixel, order as usize, d, |v| sum += v * v);
                    if kept < THRESHOLD {
                        f64::NAN
                    } else {
                        sum / kept as f64
                    }
                })
                .collect();
        }
    }
    out
}

/// The measurements' values combined: at each grid length, the mean over
/// the measurements with a value that is not NaN (`np.nanmean`).
pub fn combine_scale_dependent(each: &[MeasurementScale]) -> Option<CombinedScale> {
    let mut bins: BTreeMap<i64, Vec<(f64, f64, usize)>> = BTreeMap::new();
    for (i, s) in each.iter().enumerate() {
        for ((key, d), v) in s.grid_index.iter().zip(&s.distance).zip(&s.mean_square) {
            bins.entry(*key).or_default().push((*d, *v, i));
        }
    }
    if bins.is_empty() {
        return None;
    }
    let mut out = CombinedScale {
        grid_index: bins.keys().copied().collect(),
        distance: Vec::with_capacity(bins.len()),
        mean_square: Vec::with_capacity(bins.len()),
        contributors: Vec::with_capacity(bins.len()),
    };
    for vals in bins.values() {
        let valid: Vec<&(f64, f64, usize)> = vals.iter().filter(|v| !v.1.is_nan()).collect();
        out.distance.push(vals[0].0);
        out.mean_square.push(if valid.is_empty() {
            f64::NAN
        } else {
            valid.iter().map(|v| v.1).sum::<f64>() / valid.len() as f64
        });
        out.contributors.push(valid.iter().map(|v| v.2).collect());
    }
    Some(out)
}

/// The combined scale-dependent mean square slope (`order` 1) or curvature
/// (`order` 2) along x of `measurements`, as SurfaceTopography's container
/// `scale_dependent_statistical_property(lambda x, y=None: np.mean(x*x),
/// n=order, unit='m', nb_points_per_decade=per_decade)`: each
/// measurement's ([`measurement_scale_dependent`]), then their mean at each
/// length ([`combine_scale_dependent`]). `None` if nothing contributes.
pub fn combined_scale_dependent(measurements: &[Measurement], order: u32, per_decade: u32) -> Option<CombinedScale> {
    let each = super::each(measurements, |m| measurement_scale_dependent(m, order, per_decade));
    combine_scale_dependent(&each)
}

/// Each measurement's scale-dependent mean square slope and curvature
/// ([`measurement_scale_dependent`], orders 1 and 2), in parallel with the
/// `parallel` feature.
pub fn measurement_scales(measurements: &[Measurement], per_decade: u32) -> Vec<[MeasurementScale; 2]> {
    super::each(measurements, |m| {
        [
            measurement_scale_dependent(m, 1, per_decade),
            measurement_scale_dependent(m, 2, per_decade),
        ]
    })
}

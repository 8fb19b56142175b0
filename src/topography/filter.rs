//! ISO 16610 Gaussian filters of profiles (ISO 16610-21) and maps
//! (ISO 16610-61): the mean line / mean surface `G_λ[z]`, the S-filter and
//! the L-filter (roughness z − `G_λc[z]`).
//!
//! Weighting function s(x) = exp(−π (x/(αλ))²)/(αλ) with
//! α = √(ln 2/π) (50 % amplitude transmission at the cut-off wavelength
//! λ), separable for maps (s(x)·s(y)), truncated at |x| ≤ λ (and
//! |y| ≤ λ). The discrete weights are w_k = s(kΔ) for |k| ≤ ⌊λ/Δ⌋ (Δ = dx
//! along x, dy along y).
//!
//! The filter is a normalised convolution over the points that exist: at
//! each point, Σ w·z over the valid neighbours divided by Σ w over the
//! same neighbours. One rule handles the ends of the scan (the end-effect
//! correction) and the missing points; a missing point stays missing.
//! Numerator and denominator are separable convolutions: along x (each
//! row), then along y (each column); the denominator convolves the
//! validity indicator (and is a product of two one-dimensional sums when
//! no point is missing).

use super::Topography;
use crate::ErrorKind;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use std::sync::Arc;

/// α = √(ln 2/π): the Gaussian's 50 % transmission at λ.
const ALPHA: f64 = 0.469_718_639_349_825_7;

/// λ/Δ within this of an integer counts as that integer, so that a
/// cut-off given as a decimal multiple of Δ (λ = 25·dx) keeps its end
/// weights |k|·Δ = λ whatever the rounding of λ/Δ.
const INTEGER_SLACK: f64 = 1e-9;

/// Columns gathered at once for the y pass (whole cache lines of each
/// row).
const COLUMN_BLOCK: usize = 16;

/// Outputs summed at once by the direct convolution (in registers).
const LANES: usize = 8;

/// What a filter refuses.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum FilterError {
    /// The cut-off is not finite and > 0.
    #[error(
        "the cut-off wavelength lambda = {lambda:e} m is out of range: the cut-off must be > 0 and finite (metres)"
    )]
    Cutoff {
        /// The cut-off given (metres).
        lambda: f64,
    },
    /// The cut-off is shorter than two sampling intervals.
    #[error(
        "the cut-off wavelength lambda = {lambda:e} m is out of range: must be at least 2·max(dx, dy) = {min:e} m"
    )]
    TooShort {
        /// The cut-off given (metres).
        lambda: f64,
        /// 2·max(dx, dy), or 2·dx for a profile (metres).
        min: f64,
    },
    /// The cut-off is longer than the scan.
    #[error("the cut-off wavelength lambda = {lambda:e} m is out of range: must be at most the scan size, {}", sizes(*.size_x, *.size_y))]
    TooLong {
        /// The cut-off given (metres).
        lambda: f64,
        /// nx·dx (metres).
        size_x: f64,
        /// ny·dy (metres); `None` for a profile.
        size_y: Option<f64>,
    },
}

fn sizes(size_x: f64, size_y: Option<f64>) -> String {
    match size_y {
        Some(size_y) => format!("min(nx·dx = {size_x:e} m, ny·dy = {size_y:e} m)"),
        None => format!("nx·dx = {size_x:e} m"),
    }
}

/// What kind of failure this is (see [`ErrorKind`]): `Argument` for a
/// cut-off that is not a number (NaN, ∞), `Domain` for one out of range.
impl crate::Classify for FilterError {
    fn kind(&self) -> ErrorKind {
        match self {
            FilterError::Cutoff { lambda }
            | FilterError::TooShort { lambda, .. }
            | FilterError::TooLong { lambda, .. } => ErrorKind::of_value(*lambda),
        }
    }
}

/// How the filters convolve: both ways give the same result (to ~1e-12
/// of the height range); they differ only in speed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum Convolution {
    /// The cheaper of the two for each direction, by an estimate of their
    /// costs (what [`gaussian_lowpass`] does).
    #[default]
    Auto,
    /// Direct summation over the 2⌊λ/Δ⌋ + 1 weights.
    Direct,
    /// FFT convolution (zero-padded, so no wrap-around).
    Fft,
}

/// `G_λ[z]`: the Gaussian low-pass (mean line / mean surface) of `t` at
/// cut-off `lambda` (metres). Missing points stay missing; the others are
/// the normalised convolution over the valid points within λ.
pub fn gaussian_lowpass(t: &Topography, lambda: f64) -> Result<Topography, FilterError> {
    gaussian_lowpass_using(t, lambda, Convolution::Auto)
}

/// [`gaussian_lowpass`] with the convolution chosen by the caller (for
/// tests and timing; the result is the same to rounding).
pub fn gaussian_lowpass_using(t: &Topography, lambda: f64, method: Convolution) -> Result<Topography, FilterError> {
    let Filtered {
        offset,
        scale,
        residual: mut heights,
    } = filtered(t, None, lambda, method)?;
    for h in &mut heights {
        // NaN (missing) stays NaN.
        *h = offset + scale * *h;
    }
    Ok(like(t, heights))
}

/// The S-filter (ISO 16610-21/-61): removes the wavelengths shorter than
/// `lambda_s` (metres); the same as [`gaussian_lowpass`].
pub fn s_filter(t: &Topography, lambda_s: f64) -> Result<Topography, FilterError> {
    gaussian_lowpass(t, lambda_s)
}

/// The L-filter: the roughness z − `G_λc[z]` (metres), the wavelengths
/// longer than `lambda_c` removed. Missing points stay missing.
pub fn l_filter(t: &Topography, lambda_c: f64) -> Result<Topography, FilterError> {
    l_filter_of(t, None, lambda_c)
}

/// The L-filter of `t` less `trend` (the F-operation's plane), the
/// detrended heights never held: computed row by row where they are
/// needed. Holds one map-sized buffer besides `t` (two with missing
/// points), the result's.
pub(crate) fn l_filter_of(t: &Topography, trend: Option<&Trend>, lambda_c: f64) -> Result<Topography, FilterError> {
    let Filtered {
        offset,
        scale,
        residual: mut heights,
    } = filtered(t, trend, lambda_c, Convolution::Auto)?;
    let mut buffer = Vec::new();
    for (j, (z, r)) in t
        .heights()
        .chunks_exact(t.nx())
        .zip(heights.chunks_exact_mut(t.nx()))
        .enumerate()
    {
        let z = source_row(trend, j, z, &mut buffer);
        for (&z, r) in z.iter().zip(r) {
            // NaN (missing) stays NaN.
            *r = if r.is_nan() {
                f64::NAN
            } else {
                (z - offset) - scale * *r
            };
        }
    }
    Ok(like(t, heights))
}

/// A fitted plane (or line, or mean) taken off heights row by row:
/// `(z − z0) − (rows[j] + columns[i])` at column i of row j (NaN stays
/// NaN), the F-operation of [`Topography::detrended`] without a
/// map-sized copy.
#[derive(Debug, Clone)]
pub(crate) struct Trend {
    /// The first valid height (taken off first, for precision).
    pub(crate) z0: f64,
    /// The plane's value less its x term, per row.
    pub(crate) rows: Vec<f64>,
    /// The plane's x term, per column.
    pub(crate) columns: Vec<f64>,
}

impl Trend {
    /// Row `j`'s heights `z` less the trend, in `buffer`.
    pub(crate) fn row<'a>(&self, j: usize, z: &[f64], buffer: &'a mut Vec<f64>) -> &'a [f64] {
        let p = self.rows[j];
        buffer.clear();
        buffer.extend(z.iter().zip(&self.columns).map(|(&z, &l)| (z - self.z0) - (p + l)));
        buffer
    }
}

/// Row `j` of the filter's input: the heights `z`, less `trend` if any.
#[inline]
fn source_row<'a>(trend: Option<&Trend>, j: usize, z: &'a [f64], buffer: &'a mut Vec<f64>) -> &'a [f64] {
    match trend {
        Some(trend) => trend.row(j, z, buffer),
        None => z,
    }
}

fn like(t: &Topography, heights: Vec<f64>) -> Topography {
    // The same grid; the heights are finite or NaN (a weighted mean of
    // finite heights, kept in range by the offset and scale of
    // `filtered`).
    Topography {
        heights: std::sync::Arc::new(heights),
        nx: t.nx(),
        ny: t.ny(),
        dx: t.dx(),
        dy: t.dy(),
        metadata: t.metadata().clone(),
    }
}

/// `G_λ[z]` = offset + scale·residual (NaN where missing).
struct Filtered {
    offset: f64,
    scale: f64,
    residual: Vec<f64>,
}

fn check(t: &Topography, lambda: f64) -> Result<(), FilterError> {
    if !(lambda.is_finite() && lambda > 0.0) {
        return Err(FilterError::Cutoff { lambda });
    }
    let min = 2.0 * t.dx().max(t.dy().unwrap_or(0.0));
    if lambda < min {
        return Err(FilterError::TooShort { lambda, min });
    }
    let size_x = t.nx() as f64 * t.dx();
    let size_y = t.dy().map(|dy| t.ny() as f64 * dy);
    if lambda > size_x.min(size_y.unwrap_or(f64::INFINITY)) {
        return Err(FilterError::TooLong { lambda, size_x, size_y });
    }
    Ok(())
}

/// The filter of `t`'s heights less `trend` (if any), the input read row
/// by row: the one map-sized buffer is the result's (and, with missing
/// points, the denominator's).
fn filtered(t: &Topography, trend: Option<&Trend>, lambda: f64, method: Convolution) -> Result<Filtered, FilterError> {
    check(t, lambda)?;
    let (nx, ny) = (t.nx(), t.ny());
    let z = t.heights();
    let mut buffer = Vec::new();
    // Filter (z − offset)/scale: the offset (mid-range) makes a constant
    // surface exactly constant and keeps FFT rounding relative to the
    // roughness, not to the mean height; the power-of-two scale (exact)
    // keeps every sum far from overflow and underflow.
    // One pass for the range and the missing points (comparisons with
    // NaN are false: missing points drop out by themselves).
    let (mut lo, mut hi, mut missing) = (f64::INFINITY, f64::NEG_INFINITY, false);
    for (j, row) in z.chunks_exact(nx).enumerate() {
        for &h in source_row(trend, j, row, &mut buffer) {
            lo = if h < lo { h } else { lo };
            hi = if h > hi { h } else { hi };
            missing |= h.is_nan();
        }
    }
    if lo > hi {
        // Every point missing.
        return Ok(Filtered {
            offset: 0.0,
            scale: 1.0,
            residual: vec![f64::NAN; z.len()],
        });
    }
    let offset = lo / 2.0 + hi / 2.0;
    let spread = (hi / 2.0 - lo / 2.0).max(f64::MIN_POSITIVE);
    // 2^-1022..=2^1023: the scale and its reciprocal are finite and exact.
    let scale = 2f64.powi((spread.log2().ceil() as i32).clamp(-1022, 1023));
    let inverse = 1.0 / scale;

    let mut num: Vec<f64> = Vec::with_capacity(z.len());
    for (j, row) in z.chunks_exact(nx).enumerate() {
        num.extend(source_row(trend, j, row, &mut buffer).iter().map(|&h| {
            if h.is_nan() {
                0.0
            } else {
                (h - offset) * inverse
            }
        }));
    }
    drop(buffer);
    let mut den: Vec<f64> = if missing {
        z.iter().map(|h| if h.is_nan() { 0.0 } else { 1.0 }).collect()
    } else {
        Vec::new()
    };

    let mut along_x = LineFilter::new(nx, weights(lambda, t.dx()), method, false);
    for row in num.chunks_exact_mut(nx) {
        along_x.apply_in_place(row);
    }
    for row in den.chunks_exact_mut(nx) {
        along_x.apply_in_place(row);
    }
    let mut den_x = vec![1.0; nx];
    if !missing {
        along_x.apply_in_place(&mut den_x);
    }
    let mut den_y = vec![1.0; ny];
    if let Some(dy) = t.dy() {
        let mut along_y = LineFilter::new(ny, weights(lambda, dy), method, true);
        columns(&mut num, nx, ny, &mut along_y);
        columns(&mut den, nx, ny, &mut along_y);
        if !missing {
            along_y.apply_in_place(&mut den_y);
        }
    }

    let residual = if missing {
        // In place: a point is missing in the input less the trend iff
        // it is in the heights (the trend is finite).
        for (n, (h, d)) in num.iter_mut().zip(z.iter().zip(&den)) {
            *n = if h.is_nan() { f64::NAN } else { *n / d };
        }
        num
    } else {
        for d in &mut den_x {
            *d = 1.0 / *d;
        }
        for (row, dy) in num.chunks_exact_mut(nx).zip(&den_y) {
            let dy = 1.0 / dy;
            for (n, dx) in row.iter_mut().zip(&den_x) {
                *n *= dx * dy;
            }
        }
        num
    };
    Ok(Filtered {
        offset,
        scale,
        residual,
    })
}

/// w_k ∝ s(kΔ) for k = 0..=⌊λ/Δ⌋ (the 1/(αλ) factor cancels in the
/// normalised convolution and is left out: w_0 = 1).
fn weights(lambda: f64, delta: f64) -> Vec<f64> {
    let ratio = lambda / delta;
    let reach = (ratio + INTEGER_SLACK * ratio.max(1.0)).floor() as usize;
    let width = ALPHA * ratio;
    (0..=reach)
        .map(|k| {
            let u = k as f64 / width;
            (-std::f64::consts::PI * u * u).exp()
        })
        .collect()
}

/// The y pass, in place.
fn columns(data: &mut [f64], nx: usize, ny: usize, filter: &mut LineFilter) {
    if data.is_empty() {
        return;
    }
    if let LineFilter::Direct { w, .. } = filter {
        return columns_direct(data, nx, ny, w);
    }
    // Blocks of columns gathered into lines, convolved, and put back.
    let mut lines = vec![0.0; COLUMN_BLOCK * ny];
    for i0 in (0..nx).step_by(COLUMN_BLOCK) {
        let b = COLUMN_BLOCK.min(nx - i0);
        for (j, row) in data.chunks_exact(nx).enumerate() {
            for (c, &v) in row[i0..i0 + b].iter().enumerate() {
                lines[c * ny + j] = v;
            }
        }
        for line in lines.chunks_exact_mut(ny).take(b) {
            filter.apply_in_place(line);
        }
        for (j, row) in data.chunks_exact_mut(nx).enumerate() {
            for (c, v) in row[i0..i0 + b].iter_mut().enumerate() {
                *v = lines[c * ny + j];
            }
        }
    }
}

/// The direct y pass without gathering columns: each row becomes
/// w_0·row_j + Σ_k w_k (row_{j−k} + row_{j+k}) (rows outside the map are
/// zero), over strips of columns narrow enough for the 2K + 1 rows of a
/// strip to stay in cache. The rows above j are already overwritten: their originals
/// are kept in a ring of K + 1 rows.
fn columns_direct(data: &mut [f64], nx: usize, ny: usize, w: &[f64]) {
    let reach = w.len() - 1;
    // About 256 KiB of rows per strip, 64 to 512 columns.
    let strip = (32 * 1024 / (2 * reach + 1)).clamp(64, 512);
    let ring_len = reach + 1;
    let mut ring = vec![0.0; ring_len * strip];
    let mut acc = vec![0.0; strip];
    for i0 in (0..nx).step_by(strip) {
        let b = strip.min(nx - i0);
        for j in 0..ny {
            let at = j * nx + i0;
            let slot = (j % ring_len) * strip;
            ring[slot..slot + b].copy_from_slice(&data[at..at + b]);
            let acc = &mut acc[..b];
            for (a, &c) in acc.iter_mut().zip(&ring[slot..slot + b]) {
                *a = w[0] * c;
            }
            for (k, &wk) in w.iter().enumerate().skip(1) {
                let above = (j >= k).then(|| ((j - k) % ring_len) * strip);
                let below = (j + k < ny).then(|| (j + k) * nx + i0);
                match (above, below) {
                    (Some(u), Some(d)) => {
                        for ((a, &x), &y) in acc.iter_mut().zip(&ring[u..u + b]).zip(&data[d..d + b]) {
                            *a += wk * (x + y);
                        }
                    }
                    (Some(u), None) => {
                        for (a, &x) in acc.iter_mut().zip(&ring[u..u + b]) {
                            *a += wk * x;
                        }
                    }
                    (None, Some(d)) => {
                        for (a, &y) in acc.iter_mut().zip(&data[d..d + b]) {
                            *a += wk * y;
                        }
                    }
                    (None, None) => {}
                }
            }
            data[at..at + b].copy_from_slice(acc);
        }
    }
}

/// A zero-padded convolution of lines of `n` points with the symmetric
/// weights w_0..w_K: out(i) = Σ w_|k|·x(i + k) over |k| ≤ K, 0 ≤ i + k < n.
enum LineFilter {
    Direct {
        w: Vec<f64>,
        padded: Vec<f64>,
    },
    Fft {
        n: usize,
        forward: Arc<dyn RealToComplex<f64>>,
        inverse: Arc<dyn ComplexToReal<f64>>,
        /// The kernel's spectrum (real: the kernel is symmetric), with the
        /// inverse transform's 1/len.
        gain: Vec<f64>,
        buffer: Vec<f64>,
        spectrum: Vec<Complex<f64>>,
        scratch: Vec<Complex<f64>>,
    },
}

impl LineFilter {
    /// `column`: lines along y (gathered for an FFT).
    fn new(n: usize, mut w: Vec<f64>, method: Convolution, column: bool) -> LineFilter {
        // Weights at |k| ≥ n never meet a point of the line.
        w.truncate(n);
        let reach = w.len() - 1;
        let len = fft_len(n + reach);
        let use_fft = match method {
            Convolution::Direct => false,
            Convolution::Fft => true,
            Convolution::Auto => fft_cost(n, len, column) < direct_cost(n, reach),
        };
        if !use_fft {
            return LineFilter::Direct {
                w,
                padded: vec![0.0; n + 2 * reach],
            };
        }
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(len);
        let inverse = planner.plan_fft_inverse(len);
        let mut kernel = forward.make_input_vec();
        kernel[0] = w[0];
        for (k, &wk) in w.iter().enumerate().skip(1) {
            kernel[k] = wk;
            kernel[len - k] = wk;
        }
        let mut spectrum = forward.make_output_vec();
        let mut scratch = forward.make_scratch_vec();
        if inverse.get_scratch_len() > scratch.len() {
            scratch.resize(inverse.get_scratch_len(), Complex::default());
        }
        forward
            .process_with_scratch(&mut kernel, &mut spectrum, &mut scratch)
            .expect("buffer lengths from the plan");
        let gain = spectrum.iter().map(|c| c.re / len as f64).collect();
        LineFilter::Fft {
            n,
            forward,
            inverse,
            gain,
            buffer: kernel,
            spectrum,
            scratch,
        }
    }

    fn apply_in_place(&mut self, line: &mut [f64]) {
        match self {
            LineFilter::Direct { w, padded } => {
                let reach = w.len() - 1;
                let n = line.len();
                padded[reach..reach + n].copy_from_slice(line);
                // Blocks of LANES outputs held in registers across the
                // weights (symmetric: one multiply per pair of points).
                let blocks = n / LANES;
                for b in 0..blocks {
                    let i = b * LANES;
                    let centre: &[f64; LANES] = padded[reach + i..reach + i + LANES].try_into().unwrap();
                    let mut acc = centre.map(|c| w[0] * c);
                    for (k, &wk) in w.iter().enumerate().skip(1) {
                        let left: &[f64; LANES] = padded[reach + i - k..reach + i - k + LANES].try_into().unwrap();
                        let right: &[f64; LANES] = padded[reach + i + k..reach + i + k + LANES].try_into().unwrap();
                        for l in 0..LANES {
                            acc[l] += wk * (left[l] + right[l]);
                        }
                    }
                    line[i..i + LANES].copy_from_slice(&acc);
                }
                for i in blocks * LANES..n {
                    let mut acc = w[0] * padded[reach + i];
                    for (k, &wk) in w.iter().enumerate().skip(1) {
                        acc += wk * (padded[reach + i - k] + padded[reach + i + k]);
                    }
                    line[i] = acc;
                }
            }
            LineFilter::Fft {
                n,
                forward,
                inverse,
                gain,
                buffer,
                spectrum,
                scratch,
            } => {
                debug_assert_eq!(line.len(), *n);
                buffer[..*n].copy_from_slice(line);
                buffer[*n..].fill(0.0);
                forward
                    .process_with_scratch(buffer, spectrum, scratch)
                    .expect("buffer lengths from the plan");
                for (s, g) in spectrum.iter_mut().zip(gain.iter()) {
                    *s *= *g;
                }
                inverse
                    .process_with_scratch(spectrum, buffer, scratch)
                    .expect("buffer lengths from the plan");
                line.copy_from_slice(&buffer[..*n]);
            }
        }
    }
}

// Why two ways: direct summation costs ~(K + 1)·n multiply-adds per line
// (the weights are symmetric) and vectorises well, so it wins for short
// kernels (the S-filter, λs a few Δ); FFT convolution costs
// ~len·log2(len) per line whatever K is (len ≥ n + K), so it wins for
// long ones (the L-filter, λc a sizeable part of the scan, K in the
// hundreds). Along y the FFT also pays for gathering the columns into
// lines (the direct sum runs over whole rows). The constants are the
// measured time per unit of each (ns, one core, x86-64 without AVX,
// 4096 × 4096, `examples/filter_speed.rs`); only their ratios matter,
// and near the crossover the two cost about the same anyway.
const DIRECT_NS: f64 = 0.4;
const FFT_NS: f64 = 0.55;
const GATHER_NS: f64 = 5.0;

fn direct_cost(n: usize, reach: usize) -> f64 {
    DIRECT_NS * (reach + 1) as f64 * n as f64
}

fn fft_cost(n: usize, len: usize, column: bool) -> f64 {
    FFT_NS * len as f64 * (len as f64).log2() + if column { GATHER_NS * n as f64 } else { 0.0 }
}

/// The smallest even 2^a·3^b·5^c ≥ `min` (a fast FFT length).
fn fft_len(min: usize) -> usize {
    let mut best = usize::MAX;
    let mut p2 = 2usize;
    loop {
        let mut p3 = p2;
        loop {
            let mut p5 = p3;
            while p5 < min {
                p5 *= 5;
            }
            best = best.min(p5);
            if p3 >= min {
                break;
            }
            p3 *= 3;
        }
        if p2 >= min {
            break;
        }
        p2 *= 2;
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn alpha_is_sqrt_ln2_over_pi() {
        assert!((ALPHA - (std::f64::consts::LN_2 / std::f64::consts::PI).sqrt()).abs() < 1e-16);
    }

    #[test]
    fn fft_lengths_are_smooth_and_minimal() {
        for (min, len) in [(1, 2), (2, 2), (3, 4), (7, 8), (11, 12), (4121, 4320), (4915, 5000)] {
            assert_eq!(fft_len(min), len, "min {min}");
        }
    }

    #[test]
    fn weights_reach_lambda_over_delta() {
        assert_eq!(weights(25e-6, 1e-6).len(), 26);
        assert_eq!(weights(2.5e-6, 1e-6).len(), 3);
        let w = weights(1.0, 0.1);
        assert_eq!(w.len(), 11);
        // At |x| = λ: exp(−π/α²) = exp(−π²/ln 2).
        let end = (-std::f64::consts::PI.powi(2) / std::f64::consts::LN_2).exp();
        assert!((w[10] / end - 1.0).abs() < 1e-13);
    }
}
